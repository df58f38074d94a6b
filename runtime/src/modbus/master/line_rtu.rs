//! A serial line's task on the master's thread (`docs/modbus-master.md` §6.9): every RTU device
//! of one port, polled in turn (the round of the device due longest runs whole, then the line
//! looks again), with the inter-frame silence before each request, unasked input dropped after
//! a timeout or an invalid answer, and the port reopened with back-off when it fails.

use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, Instant};

use program_image::modbus_master::{Parity, SerialPortDef};
use tokio::sync::{Notify, mpsc};
use tokio_modbus::Slave;
use tokio_modbus::client::Context;
use tokio_modbus::slave::SlaveContext;

use super::backoff::Backoff;
use super::device_round::DeviceRound;
use super::due::{Due, RoundKind};
use super::line_port::{LineActivity, LinePort, StreamSlot};
use super::round::{Answer, call_checked};
use super::status::{Outcome, error_codes};
use crate::serial::{SerialOpenError, SerialSettings, StopBits, open_port};
use tokio_serial::SerialStream;

/// A device of the line: its rounds and its schedule.
pub struct LineDevice {
    /// Its rounds.
    pub round: DeviceRound,
    /// When they are due.
    pub due: Due,
}

/// One serial port and the devices on it.
pub struct RtuLine {
    /// The port, with this machine's device file.
    port: SerialPortDef,
    /// The devices' rounds, in the project's order.
    devices: Vec<DeviceRound>,
    /// The devices' schedules, handed to their tasks when the line runs.
    dues: Vec<Due>,
}

/// The open port: tokio-modbus's client over it, and what it notes of the line.
struct OpenPort {
    /// tokio-modbus's RTU client over the port.
    context: Context,
    /// What the transport notes of the line.
    activity: Arc<LineActivity>,
    /// Where the transport leaves the stream when the client is dropped.
    returned: StreamSlot<SerialStream>,
}

impl OpenPort {
    /// tokio-modbus's client over `stream`.
    fn attach(stream: SerialStream, activity: Arc<LineActivity>) -> Self {
        let returned = StreamSlot::default();
        let transport = LinePort::new(stream, Arc::clone(&activity), Arc::clone(&returned));
        Self {
            context: tokio_modbus::client::rtu::attach_slave(transport, Slave(0)),
            activity,
            returned,
        }
    }

    /// A new client over the same open port. After a frame its decoder could not read,
    /// tokio-modbus's framing stays failed and would report every later call as a broken
    /// pipe; the port itself is fine (`docs/modbus-master.md` §4.2: an invalid response is
    /// handled as a timeout). `None` if the stream did not come back.
    fn renewed(self) -> Option<Self> {
        let Self {
            context,
            activity,
            returned,
        } = self;
        // Dropping the client drops its transport, which leaves the stream in the slot.
        drop(context);
        let stream = returned
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .take()?;
        Some(Self::attach(stream, activity))
    }
}

impl RtuLine {
    /// The line of `port` with `devices`, in the project's order.
    pub fn new(port: SerialPortDef, devices: Vec<LineDevice>) -> Self {
        let (devices, dues) = devices
            .into_iter()
            .map(|device| (device.round, device.due))
            .unzip();
        Self {
            port,
            devices,
            dues,
        }
    }

    /// Runs the line until the master's runtime is dropped.
    pub async fn run(mut self) {
        // Each device's schedule runs in a task of its own and reports when its round is due,
        // then waits until the line has run it.
        let (due_sender, mut due_receiver) = mpsc::unbounded_channel();
        let mut ran = Vec::new();
        for (index, mut due) in std::mem::take(&mut self.dues).into_iter().enumerate() {
            let sender = due_sender.clone();
            let done = Arc::new(Notify::new());
            ran.push(Arc::clone(&done));
            tokio::spawn(async move {
                loop {
                    let kind = due.wait().await;
                    if sender.send((Instant::now(), index, kind)).is_err() {
                        return;
                    }
                    done.notified().await;
                }
            });
        }
        drop(due_sender);
        let mut waiting: Vec<(Instant, usize, RoundKind)> = Vec::new();
        let mut port: Option<OpenPort> = None;
        let mut backoff = Backoff::default();
        loop {
            if waiting.is_empty() {
                match due_receiver.recv().await {
                    Some(due) => waiting.push(due),
                    None => return,
                }
            }
            while let Ok(due) = due_receiver.try_recv() {
                waiting.push(due);
            }
            // The device due longest first; ties by the project's order.
            let Some(next) = (0..waiting.len()).min_by_key(|&at| (waiting[at].0, waiting[at].1))
            else {
                continue;
            };
            let (_, index, kind) = waiting.remove(next);
            self.run_round(index, kind, &mut port, &mut backoff).await;
            if let Some(done) = ran.get(index) {
                done.notify_one();
            }
        }
    }

    /// Runs one round of device `index` on the line.
    async fn run_round(
        &mut self,
        index: usize,
        mut kind: RoundKind,
        port: &mut Option<OpenPort>,
        backoff: &mut Backoff,
    ) {
        let silence = Duration::from_micros(u64::from(self.port.silent_interval_us()));
        let path = self.port.device.clone();
        let Some(round) = self.devices.get_mut(index) else {
            return;
        };
        let requests = round.begin(kind);
        for (position, &request) in requests.iter().enumerate() {
            if !round.may_send(request) {
                continue;
            }
            if port.is_none() {
                if !backoff.may_try(Instant::now()) {
                    round.not_sent(&requests[position..], error_codes::SERIAL_PORT_ERROR, "");
                    kind = kind.without_overruns();
                    break;
                }
                match open(&self.port) {
                    Ok(opened) => *port = Some(opened),
                    Err(detail) => {
                        backoff.failed(Instant::now());
                        kind = kind.without_overruns();
                        round.not_sent(
                            &requests[position..],
                            error_codes::SERIAL_PORT_ERROR,
                            &detail.to_string(),
                        );
                        break;
                    }
                }
            }
            let Some(open) = port.as_mut() else {
                break;
            };
            open.context.set_slave(Slave(round.device.unit_id));
            // The silence before a request counts from the last byte either way, or from a
            // timeout; what arrived meanwhile unasked is dropped.
            tokio::time::sleep_until((open.activity.last_byte() + silence).into()).await;
            open.activity.discard_input();
            let started = Instant::now();
            let answer = call_checked(
                &mut open.context,
                &round.requests[request],
                &round.device,
                &round.exchange.layout,
                round.values_for(request),
                &format!("unit {} on {path}", round.device.unit_id),
                Some(self.port.baud_rate),
            )
            .await;
            let took = started.elapsed();
            match answer {
                Answer::Failed {
                    outcome: Outcome::Unanswered(error_codes::TCP_COMMUNICATION_ERROR),
                    detail,
                    ..
                } => {
                    // End of file or an I/O error: the port is gone; every device of the
                    // line fails until it opens again.
                    *port = None;
                    backoff.failed(Instant::now());
                    let detail = format!("the serial port {path} failed ({detail})");
                    let failed = Answer::Failed {
                        outcome: Outcome::Unanswered(error_codes::SERIAL_PORT_ERROR),
                        detail,
                        close: true,
                    };
                    round.apply(request, failed, took);
                    round.not_sent(
                        &requests[position + 1..],
                        error_codes::SERIAL_PORT_ERROR,
                        "",
                    );
                    break;
                }
                Answer::Failed {
                    outcome: Outcome::Unanswered(code),
                    ..
                } => {
                    // A timeout: the silence counts from now, and the line goes on with the
                    // next device.
                    open.activity.touch();
                    round.apply(request, answer, took);
                    round.not_sent(&requests[position + 1..], code, "");
                    break;
                }
                Answer::Failed {
                    outcome: Outcome::Invalid(_),
                    ..
                } => {
                    // That request fails; the silence counts from now, what arrives meanwhile
                    // is dropped before the next request, and the next goes to a new client
                    // on the same port (a frame tokio-modbus could not decode leaves its
                    // client failed).
                    open.activity.touch();
                    round.apply(request, answer, took);
                    *port = port.take().and_then(OpenPort::renewed);
                }
                _ => {
                    backoff.succeeded();
                    round.apply(request, answer, took);
                }
            }
        }
        round.end(kind);
    }
}

/// Opens the line's port with its settings, or says why it cannot (naming the port's path).
fn open(port: &SerialPortDef) -> Result<OpenPort, SerialOpenError> {
    let settings = SerialSettings {
        baud_rate: port.baud_rate,
        data_bits: port.data_bits,
        parity: match port.parity {
            Parity::None => crate::serial::Parity::None,
            Parity::Odd => crate::serial::Parity::Odd,
            Parity::Even => crate::serial::Parity::Even,
        },
        stop_bits: if port.stop_bits == 2 {
            StopBits::Two
        } else {
            StopBits::One
        },
    };
    let stream = open_port(Path::new(&port.device), &settings)?;
    Ok(OpenPort::attach(stream, LineActivity::new()))
}
