//! A Modbus TCP device's task on the master's thread (`docs/modbus-master.md` §6.7): its own
//! connection, its rounds as they fall due, and the reconnection with back-off.

use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};

use program_image::modbus_master::{DeviceDef, Direction, PlannedRequest, Trigger, plan};
use tokio_modbus::Slave;
use tokio_modbus::client::Context;

use super::StateLines;
use super::backoff::Backoff;
use super::due::{Due, RoundKind};
use super::exchange::{DeviceExchange, InputImage};
use super::round::{Answer, RoundResults, call_checked};
use super::status::{DeviceStatus, Outcome, error_codes};

/// The shortest time a connection attempt is given, whatever the response timeout.
const MIN_CONNECT_TIMEOUT: Duration = Duration::from_millis(1000);

/// One TCP device: its definition, its plan, and what the round moves.
pub struct TcpDevice {
    device: DeviceDef,
    requests: Vec<PlannedRequest>,
    exchange: Arc<DeviceExchange>,
    /// The counters as the online service reads them, replaced after each round.
    shared_status: Arc<Mutex<DeviceStatus>>,
    results: RoundResults,
    outputs: Vec<u8>,
    edge_values: Vec<u8>,
    pending: Vec<bool>,
    due: Due,
    peer: String,
    state_lines: Option<StateLines>,
}

impl TcpDevice {
    /// The task of `device`, whose I/O task cycles every `idle_interval` when the program
    /// stops (for an every-cycle device).
    pub fn new(
        device: DeviceDef,
        exchange: Arc<DeviceExchange>,
        shared_status: Arc<Mutex<DeviceStatus>>,
        idle_interval: Duration,
        state_lines: Option<StateLines>,
    ) -> Self {
        let layout = &exchange.layout;
        let peer = match &device.link {
            program_image::modbus_master::Link::Tcp { host, port } => format!("{host}:{port}"),
            program_image::modbus_master::Link::Rtu { .. } => String::new(),
        };
        Self {
            requests: plan(&device),
            results: RoundResults {
                image: InputImage::empty(layout),
                status: DeviceStatus::new(&device.name, false),
            },
            outputs: vec![0; layout.total],
            edge_values: vec![0; layout.total],
            pending: vec![false; layout.triggers.len()],
            due: Due::new(device.schedule, Arc::clone(&exchange), idle_interval),
            device,
            exchange,
            shared_status,
            peer,
            state_lines,
        }
    }

    /// Runs rounds until the master's runtime is dropped.
    pub async fn run(mut self) {
        let mut connection: Option<Context> = None;
        let mut backoff = Backoff::default();
        loop {
            let kind = self.due.wait().await;
            let published = self.exchange.take_outputs(
                &mut self.outputs,
                &mut self.edge_values,
                &mut self.pending,
            );
            // Nothing is written before the I/O task ended a cycle, nor while the program is
            // stopped.
            let may_write = published && self.exchange.running();
            let layout = &self.exchange.layout;
            let round: Vec<&PlannedRequest> = self
                .requests
                .iter()
                .filter(|request| {
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
                .collect();
            for (index, request) in round.iter().enumerate() {
                if connection.is_none() {
                    let now = Instant::now();
                    if !backoff.may_try(now) {
                        self.results.not_sent(
                            &self.device,
                            layout,
                            &round[index..],
                            error_codes::TCP_COMMUNICATION_ERROR,
                            "",
                        );
                        break;
                    }
                    match connect(&self.device, &self.peer).await {
                        Ok(context) => connection = Some(context),
                        Err(detail) => {
                            backoff.failed(now);
                            self.results.not_sent(
                                &self.device,
                                layout,
                                &round[index..],
                                error_codes::TCP_COMMUNICATION_ERROR,
                                &detail,
                            );
                            break;
                        }
                    }
                }
                let Some(context) = connection.as_mut() else {
                    break;
                };
                let values = match request.trigger {
                    Trigger::Cyclic => &self.outputs,
                    Trigger::RisingEdge { .. } => &self.edge_values,
                };
                let started = Instant::now();
                let answer =
                    call_checked(context, request, &self.device, layout, values, &self.peer).await;
                let took = started.elapsed();
                let (close, unanswered) = match &answer {
                    Answer::Failed {
                        outcome: Outcome::Unanswered(code),
                        close,
                        ..
                    } => (*close, Some(*code)),
                    Answer::Failed { close, .. } => (*close, None),
                    _ => {
                        backoff.succeeded();
                        (false, None)
                    }
                };
                self.results
                    .apply(&self.device, layout, request, answer, took);
                if close {
                    // A late answer would be taken for the next request's: a new connection.
                    connection = None;
                }
                if let Some(code) = unanswered {
                    self.results
                        .not_sent(&self.device, layout, &round[index + 1..], code, "");
                    break;
                }
            }
            let overruns = match kind {
                RoundKind::Full { overruns } => overruns,
                RoundKind::EdgesOnly => 0,
            };
            if let (Some(line), Some(lines)) = (self.results.end(overruns), &self.state_lines) {
                lines(&line);
            }
            self.exchange.publish_round(&self.results.image);
            *self
                .shared_status
                .lock()
                .unwrap_or_else(PoisonError::into_inner) = self.results.status.clone();
        }
    }
}

/// Opens the device's connection with `TCP_NODELAY` within `max(timeout_ms, 1000)` ms, or
/// says in words why it could not.
async fn connect(device: &DeviceDef, peer: &str) -> Result<Context, String> {
    let program_image::modbus_master::Link::Tcp { host, port } = &device.link else {
        return Err(format!("'{}' is not a TCP device", device.name));
    };
    let limit = Duration::from_millis(u64::from(device.timeout_ms)).max(MIN_CONNECT_TIMEOUT);
    let attempt = async {
        let stream = tokio::net::TcpStream::connect((host.as_str(), *port)).await?;
        stream.set_nodelay(true)?;
        Ok::<_, std::io::Error>(stream)
    };
    match tokio::time::timeout(limit, attempt).await {
        Ok(Ok(stream)) => Ok(tokio_modbus::client::tcp::attach_slave(
            stream,
            Slave(device.unit_id),
        )),
        Ok(Err(error)) if error.kind() == std::io::ErrorKind::ConnectionRefused => {
            Err(format!("connection refused by {peer}"))
        }
        Ok(Err(error)) => Err(format!("cannot connect to {peer}: {error}")),
        Err(_) => Err(format!(
            "cannot connect to {peer} within {} ms",
            limit.as_millis()
        )),
    }
}
