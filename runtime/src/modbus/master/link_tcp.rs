//! A Modbus TCP device's task on the master's thread (`docs/modbus-master.md` §6.7): its own
//! connection, its rounds as they fall due, and the reconnection with back-off.

use std::time::{Duration, Instant};

use program_image::modbus_master::{DeviceDef, Link};
use tokio_modbus::Slave;
use tokio_modbus::client::Context;

use super::backoff::Backoff;
use super::connect_error::ConnectError;
use super::device_round::DeviceRound;
use super::due::Due;
use super::round::{Answer, call_checked};
use super::status::{Outcome, error_codes};

/// The shortest time a connection attempt is given, whatever the response timeout.
const MIN_CONNECT_TIMEOUT: Duration = Duration::from_millis(1000);

/// One TCP device: its rounds and its schedule.
pub struct TcpDevice {
    /// Its rounds.
    round: DeviceRound,
    /// When they are due.
    due: Due,
    /// `host:port`, naming the device in failures.
    peer: String,
}

impl TcpDevice {
    /// The task of the device `round` serves, due as `due` says.
    pub fn new(round: DeviceRound, due: Due) -> Self {
        let peer = match &round.device.link {
            Link::Tcp { host, port } => format!("{host}:{port}"),
            Link::Rtu { .. } => String::new(),
        };
        Self { round, due, peer }
    }

    /// Runs rounds until the master's runtime is dropped.
    pub async fn run(mut self) {
        let mut connection: Option<Context> = None;
        let mut backoff = Backoff::default();
        loop {
            let mut kind = self.due.wait().await;
            let requests = self.round.begin(kind);
            for (position, &request) in requests.iter().enumerate() {
                if !self.round.may_send(request) {
                    continue;
                }
                if connection.is_none() {
                    if !backoff.may_try(Instant::now()) {
                        // Waiting for the back-off: the round counts as failed, not sent.
                        self.round.not_sent(
                            &requests[position..],
                            error_codes::TCP_COMMUNICATION_ERROR,
                            "",
                        );
                        kind = kind.without_overruns();
                        break;
                    }
                    self.round.connecting();
                    match connect(&self.round.device, &self.peer).await {
                        Ok(context) => connection = Some(context),
                        Err(detail) => {
                            // The wait counts from the attempt's end: an attempt may take a
                            // second, which would eat the first waits whole.
                            backoff.failed(Instant::now());
                            kind = kind.without_overruns();
                            self.round.not_sent(
                                &requests[position..],
                                error_codes::TCP_COMMUNICATION_ERROR,
                                &detail.to_string(),
                            );
                            break;
                        }
                    }
                }
                let Some(context) = connection.as_mut() else {
                    break;
                };
                let started = Instant::now();
                let answer = call_checked(
                    context,
                    &self.round.requests[request],
                    &self.round.device,
                    &self.round.exchange.layout,
                    self.round.values_for(request),
                    &self.peer,
                    None,
                )
                .await;
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
                self.round.apply(request, answer, took);
                if close {
                    // A late answer would be taken for the next request's: a new connection.
                    connection = None;
                }
                if let Some(code) = unanswered {
                    self.round.not_sent(&requests[position + 1..], code, "");
                    break;
                }
            }
            self.round.end(kind);
        }
    }
}

/// Opens the device's connection with `TCP_NODELAY` within `max(timeout_ms, 1000)` ms, or
/// says why it could not.
async fn connect(device: &DeviceDef, peer: &str) -> Result<Context, ConnectError> {
    let Link::Tcp { host, port } = &device.link else {
        return Err(ConnectError::NotTcp {
            device: device.name.clone(),
        });
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
            Err(ConnectError::Refused {
                peer: peer.to_owned(),
            })
        }
        Ok(Err(source)) => Err(ConnectError::Failed {
            peer: peer.to_owned(),
            source,
        }),
        Err(_) => Err(ConnectError::TimedOut {
            peer: peer.to_owned(),
            limit_ms: limit.as_millis(),
        }),
    }
}
