//! What one device's rounds move on the master's thread, whatever its link: its plan, the
//! outputs taken from the scheduler, the results built request by request, and the publishing
//! at the round's end (`docs/modbus-master.md` §6.3).

use std::sync::{Arc, Mutex, PoisonError};
use std::time::Duration;

use program_image::modbus_master::{DeviceDef, Direction, PlannedRequest, Trigger, plan};

use super::StateLines;
use super::due::RoundKind;
use super::exchange::{DeviceExchange, InputImage};
use super::round::{Answer, RoundResults};
use super::status::DeviceStatus;

/// One device's round state.
pub struct DeviceRound {
    /// The device.
    pub device: DeviceDef,
    /// Its requests in round order.
    pub requests: Vec<PlannedRequest>,
    /// The exchange with the scheduler.
    pub exchange: Arc<DeviceExchange>,
    /// The counters and state the online service reads, replaced at each round's end.
    shared_status: Arc<Mutex<DeviceStatus>>,
    /// The round being built, request by request.
    results: RoundResults,
    /// The write channels' values of the newest cycle end, taken at the round's start.
    outputs: Vec<u8>,
    /// The values latched with the pending edges, taken at the round's start.
    edge_values: Vec<u8>,
    /// Per trigger, whether its group is pending in this round.
    pending: Vec<bool>,
    /// Where a change of state is written, if anywhere.
    state_lines: Option<StateLines>,
}

impl DeviceRound {
    /// The rounds of `device`, publishing through `exchange` and `shared_status`.
    pub fn new(
        device: DeviceDef,
        exchange: Arc<DeviceExchange>,
        shared_status: Arc<Mutex<DeviceStatus>>,
        state_lines: Option<StateLines>,
    ) -> Self {
        let layout = &exchange.layout;
        Self {
            requests: plan(&device),
            results: RoundResults {
                image: InputImage::empty(layout),
                status: DeviceStatus::new(&device.name, false),
            },
            outputs: vec![0; layout.total],
            edge_values: vec![0; layout.total],
            pending: vec![false; layout.triggers.len()],
            device,
            exchange,
            shared_status,
            state_lines,
        }
    }

    /// Takes the newest outputs and pending edges, and gives the indices of the requests of a
    /// round of `kind`: cyclic ones in a full round, pending edges' ones always; writes only
    /// once the I/O task ended a cycle and while the program runs.
    pub fn begin(&mut self, kind: RoundKind) -> Vec<usize> {
        let published =
            self.exchange
                .take_outputs(&mut self.outputs, &mut self.edge_values, &mut self.pending);
        let may_write = published && self.exchange.running();
        let layout = &self.exchange.layout;
        self.requests
            .iter()
            .enumerate()
            .filter(|(_, request)| {
                let wanted = match &request.trigger {
                    Trigger::Cyclic => matches!(kind, RoundKind::Full { .. }),
                    Trigger::RisingEdge { variable } => layout
                        .triggers
                        .iter()
                        .position(|known| known.eq_ignore_ascii_case(variable))
                        .is_some_and(|index| self.pending[index]),
                };
                wanted && (request.direction == Direction::Read || may_write)
            })
            .map(|(index, _)| index)
            .collect()
    }

    /// Whether request `request` may be sent now: a write only while the program runs, looked
    /// at before each request, so that a round begun before a stop sends no write after it.
    pub fn may_send(&self, request: usize) -> bool {
        self.requests
            .get(request)
            .is_some_and(|planned| planned.direction == Direction::Read || self.exchange.running())
    }

    /// The values a write request takes its coils or registers from.
    pub fn values_for(&self, request: usize) -> &[u8] {
        match self.requests.get(request).map(|request| &request.trigger) {
            Some(Trigger::RisingEdge { .. }) => &self.edge_values,
            _ => &self.outputs,
        }
    }

    /// Counts request `request`'s answer and applies it to its channels.
    pub fn apply(&mut self, request: usize, answer: Answer, took: Duration) {
        if let Some(planned) = self.requests.get(request) {
            self.results
                .apply(&self.device, &self.exchange.layout, planned, answer, took);
        }
    }

    /// Counts a connection attempt about to be made (`DeviceStatus::connection_attempts`, read
    /// through `Scheduler::modbus_connection_attempts`).
    pub fn connecting(&mut self) {
        let status = &mut self.results.status;
        status.connection_attempts = status.connection_attempts.wrapping_add(1);
    }

    /// Fails the requests `requests` of the round, not sent, with `code`.
    pub fn not_sent(&mut self, requests: &[usize], code: u8, detail: &str) {
        let planned: Vec<&PlannedRequest> = requests
            .iter()
            .filter_map(|index| self.requests.get(*index))
            .collect();
        self.results
            .not_sent(&self.device, &self.exchange.layout, &planned, code, detail);
    }

    /// Ends the round: counts it, publishes it to the scheduler and the online service, and
    /// hands on the state line if the state changed.
    pub fn end(&mut self, kind: RoundKind) {
        let overruns = match kind {
            RoundKind::Full { overruns } => overruns,
            RoundKind::EdgesOnly => 0,
        };
        let line = self.results.end(overruns);
        if let (Some(line), Some(lines)) = (line, &self.state_lines) {
            lines(&line);
        }
        self.exchange.publish_round(&self.results.image);
        *self
            .shared_status
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = self.results.status.clone();
    }
}
