//! One request of a round through tokio-modbus's `Client::call`, with the checks of
//! `docs/modbus-master.md` §6.6, and the bookkeeping of a round's results (§6.3).
//!
//! The convenience readers of tokio-modbus are never called: they `debug_assert!` the count of
//! a response, so a misbehaving device would panic a debug build. Every count, echo, unit id
//! and function code is checked here instead.

use std::borrow::Cow;
use std::io;
use std::time::Duration;

use program_image::ModbusTable;
use program_image::modbus_master::{
    CodecError, DeviceDef, Direction, OnError, PlannedRequest, bits_to_values, registers_to_values,
    table_holds_bits, values_to_bits, values_to_registers,
};
use tokio_modbus::client::{Client, Context};
use tokio_modbus::{ProtocolError, Request, Response};

use super::exchange::{InputImage, ValueLayout};
use super::status::{DeviceStatus, Outcome, error_codes};

/// What one request gave.
#[derive(Debug)]
pub enum Answer {
    /// Registers read.
    Registers(Vec<u16>),
    /// Coils or discrete inputs read, exactly as many as asked.
    Bits(Vec<bool>),
    /// A write acknowledged with the right echo.
    Written,
    /// A failure, counted with its outcome; `close` when the connection may be out of step.
    Failed {
        /// How it counts.
        outcome: Outcome,
        /// In words, for the state line and `MODBUS_DEVICES`.
        detail: String,
        /// Whether the connection is to be closed (a timeout or an invalid answer).
        close: bool,
    },
}

/// Bits a byte takes on a serial line: start, 8 data, parity or a second stop bit, stop (the
/// Modbus RTU character of 11 bits, whatever the port's framing, as the silence is counted).
const RTU_BITS_PER_BYTE: u64 = 11;

/// Sends `request` (a write takes its coils or registers from `values`, laid out by `layout`)
/// and checks the answer; `peer` names the device in failures. On a serial line at
/// `rtu_baud_rate`, the time the request takes to send is added to the timeout, which counts
/// from its last byte (`docs/modbus-master.md` §2.1, §6.9).
pub async fn call_checked(
    context: &mut Context,
    request: &PlannedRequest,
    device: &DeviceDef,
    layout: &ValueLayout,
    values: &[u8],
    peer: &str,
    rtu_baud_rate: Option<u32>,
) -> Answer {
    let start = request.start;
    let quantity = request.quantity;
    let modbus_request = match build(request, device, layout, values) {
        Ok(built) => built,
        Err(problem) => {
            return Answer::Failed {
                outcome: Outcome::Invalid(error_codes::RESPONSE_INVALID_DATA),
                detail: problem.to_string(),
                close: false,
            };
        }
    };
    let timeout = Duration::from_millis(u64::from(device.timeout_ms))
        + rtu_baud_rate.map_or(Duration::ZERO, |baud_rate| {
            rtu_send_time(rtu_frame_bytes(&modbus_request), baud_rate)
        });
    let sent = modbus_request.clone();
    let result = match tokio::time::timeout(timeout, context.call(modbus_request)).await {
        Ok(result) => result,
        Err(_) => {
            return Answer::Failed {
                outcome: Outcome::Unanswered(error_codes::RESPONSE_TIMEOUT),
                detail: format!("no answer from {peer} within {} ms", device.timeout_ms),
                close: true,
            };
        }
    };
    let invalid = |code: u8, detail: String| Answer::Failed {
        outcome: Outcome::Invalid(code),
        detail,
        close: true,
    };
    let response = match result {
        Ok(Ok(response)) => response,
        Ok(Err(exception)) => {
            let code = u8::from(exception);
            return Answer::Failed {
                outcome: Outcome::Exception(code),
                detail: format!("{peer} answered exception {code} ({exception})"),
                close: false,
            };
        }
        Err(tokio_modbus::Error::Protocol(ProtocolError::HeaderMismatch { message, .. })) => {
            let code = if unit_ids_differ(&message) {
                error_codes::RESPONSE_WRONG_SLAVE
            } else {
                error_codes::RESPONSE_INVALID_HEADER
            };
            return invalid(code, format!("{peer} answered another request: {message}"));
        }
        Err(tokio_modbus::Error::Protocol(ProtocolError::FunctionCodeMismatch { .. })) => {
            return invalid(
                error_codes::RESPONSE_WRONG_FUNCTIONCODE,
                format!("{peer} answered another function code"),
            );
        }
        Err(tokio_modbus::Error::Transport(error)) => return transport_failure(&error, peer),
    };
    check(&sent, response, start, quantity).unwrap_or_else(|(code, problem)| {
        invalid(code, format!("{peer} gave an invalid answer: {problem}"))
    })
}

/// The bytes of `request`'s RTU frame: unit id, function code, its data, CRC.
pub fn rtu_frame_bytes(request: &Request<'_>) -> usize {
    let data = match request {
        Request::WriteMultipleCoils(_, coils) => 5 + coils.len().div_ceil(8),
        Request::WriteMultipleRegisters(_, words) => 5 + 2 * words.len(),
        // Reads, and writes of one coil or register: an address and a count or a value.
        _ => 4,
    };
    1 + 1 + data + 2
}

/// How long `bytes` take to send at `baud_rate`, in whole microseconds rounded up.
pub fn rtu_send_time(bytes: usize, baud_rate: u32) -> Duration {
    let bits = bytes as u64 * RTU_BITS_PER_BYTE;
    let micros = (bits * 1_000_000).div_ceil(u64::from(baud_rate.max(1)));
    Duration::from_micros(micros)
}

/// Why a write's request could not be built from the program's bytes; the section was verified
/// at load, so either means an inconsistent image, said in the device's status detail.
#[derive(Debug, thiserror::Error)]
enum BuildError {
    /// A channel's values fall outside the request serving it.
    #[error("a channel beyond its request")]
    ChannelBeyondRequest,
    /// A channel's values could not be converted into coils or registers.
    #[error(transparent)]
    Codec(#[from] CodecError),
}

/// The Modbus request for `request`, with a write's values converted from the program's bytes.
fn build(
    request: &PlannedRequest,
    device: &DeviceDef,
    layout: &ValueLayout,
    values: &[u8],
) -> Result<Request<'static>, BuildError> {
    let (start, quantity) = (request.start, request.quantity);
    if request.direction == Direction::Read {
        return Ok(match request.table {
            ModbusTable::Coils => Request::ReadCoils(start, quantity),
            ModbusTable::DiscreteInputs => Request::ReadDiscreteInputs(start, quantity),
            ModbusTable::HoldingRegisters => Request::ReadHoldingRegisters(start, quantity),
            ModbusTable::InputRegisters => Request::ReadInputRegisters(start, quantity),
        });
    }
    if table_holds_bits(request.table) {
        let mut bits = vec![false; usize::from(quantity)];
        for served in &request.channels {
            let channel = &device.channels[served.channel];
            let at = usize::from(served.offset);
            let span = channel.span() as usize;
            let target = bits
                .get_mut(at..at + span)
                .ok_or(BuildError::ChannelBeyondRequest)?;
            values_to_bits(layout.slice(values, served.channel), target)?;
        }
        return Ok(match request.function_code {
            5 => Request::WriteSingleCoil(start, bits.first().copied().unwrap_or(false)),
            _ => Request::WriteMultipleCoils(start, Cow::Owned(bits)),
        });
    }
    let mut words = vec![0u16; usize::from(quantity)];
    for served in &request.channels {
        let channel = &device.channels[served.channel];
        let at = usize::from(served.offset);
        let span = channel.span() as usize;
        let target = words
            .get_mut(at..at + span)
            .ok_or(BuildError::ChannelBeyondRequest)?;
        values_to_registers(
            layout.slice(values, served.channel),
            channel.value_type,
            device.word_order,
            target,
        )?;
    }
    Ok(match request.function_code {
        6 => Request::WriteSingleRegister(start, words.first().copied().unwrap_or(0)),
        _ => Request::WriteMultipleRegisters(start, Cow::Owned(words)),
    })
}

/// Checks that `response` answers `sent` (§6.6): its kind, its count, a write's echo.
fn check(
    sent: &Request<'_>,
    response: Response,
    start: u16,
    quantity: u16,
) -> Result<Answer, (u8, String)> {
    let count = usize::from(quantity);
    let echo = |address: u16, echoed: u16, expected: u16| {
        if address == start && echoed == expected {
            Ok(Answer::Written)
        } else {
            Err((
                error_codes::RESPONSE_INVALID_DATA,
                format!("the write echoes {address}/{echoed}, expected {start}/{expected}"),
            ))
        }
    };
    match (sent, response) {
        (Request::ReadCoils(..), Response::ReadCoils(mut bits))
        | (Request::ReadDiscreteInputs(..), Response::ReadDiscreteInputs(mut bits)) => {
            // tokio-modbus unpacks whole bytes: a right answer has ceil(count / 8) of them.
            if bits.len() != count.div_ceil(8) * 8 {
                return Err((
                    error_codes::RESPONSE_INVALID_DATA,
                    format!("{} bits for {count} asked", bits.len()),
                ));
            }
            bits.truncate(count);
            Ok(Answer::Bits(bits))
        }
        (Request::ReadHoldingRegisters(..), Response::ReadHoldingRegisters(words))
        | (Request::ReadInputRegisters(..), Response::ReadInputRegisters(words)) => {
            if words.len() != count {
                return Err((
                    error_codes::RESPONSE_INVALID_DATA,
                    format!("{} registers for {count} asked", words.len()),
                ));
            }
            Ok(Answer::Registers(words))
        }
        (Request::WriteSingleCoil(_, coil), Response::WriteSingleCoil(address, echoed)) => {
            echo(address, u16::from(echoed), u16::from(*coil))
        }
        (Request::WriteSingleRegister(_, word), Response::WriteSingleRegister(address, echoed)) => {
            echo(address, echoed, *word)
        }
        (Request::WriteMultipleCoils(..), Response::WriteMultipleCoils(address, echoed))
        | (
            Request::WriteMultipleRegisters(..),
            Response::WriteMultipleRegisters(address, echoed),
        ) => echo(address, echoed, quantity),
        _ => Err((
            error_codes::RESPONSE_WRONG_FUNCTIONCODE,
            "the answer is of another function".to_owned(),
        )),
    }
}

/// A failure of the transport: a malformed frame (the stream is out of step) or a lost
/// connection.
fn transport_failure(error: &io::Error, peer: &str) -> Answer {
    if error.kind() == io::ErrorKind::InvalidData {
        let text = error.to_string();
        let code =
            if text.starts_with("Invalid data length") || text.starts_with("Invalid protocol") {
                error_codes::RESPONSE_INVALID_HEADER
            } else {
                error_codes::RESPONSE_INVALID_PROTOCOL
            };
        return Answer::Failed {
            outcome: Outcome::Invalid(code),
            detail: format!("{peer} sent a malformed frame: {text}"),
            close: true,
        };
    }
    Answer::Failed {
        outcome: Outcome::Unanswered(error_codes::TCP_COMMUNICATION_ERROR),
        detail: format!("connection to {peer} lost: {error}"),
        close: true,
    }
}

/// Whether tokio-modbus's header mismatch message names two different unit ids (`unit_id`
/// in a TCP header, `slave_id` in an RTU one); otherwise the transaction ids differ.
fn unit_ids_differ(message: &str) -> bool {
    let ids: Vec<&str> = ["unit_id: ", "slave_id: "]
        .iter()
        .flat_map(|key| message.match_indices(key))
        .map(|(at, key)| {
            let rest = &message[at + key.len()..];
            let end = rest
                .find(|c: char| !c.is_ascii_digit())
                .unwrap_or(rest.len());
            &rest[..end]
        })
        .collect();
    ids.len() == 2 && ids[0] != ids[1]
}

/// What a round delivers, built request by request on the master's thread.
#[derive(Debug)]
pub struct RoundResults {
    /// The image published at the round's end; its values stay from round to round, so a
    /// `keep_last_value` channel keeps them.
    pub image: InputImage,
    /// The counters and state.
    pub status: DeviceStatus,
}

impl RoundResults {
    /// Applies one answer to the channels of `request`, and counts it.
    pub fn apply(
        &mut self,
        device: &DeviceDef,
        layout: &ValueLayout,
        request: &PlannedRequest,
        answer: Answer,
        took: Duration,
    ) {
        match answer {
            Answer::Registers(words) => {
                for served in &request.channels {
                    let channel = &device.channels[served.channel];
                    let at = usize::from(served.offset);
                    let span = channel.span() as usize;
                    let target = layout.slice_mut(&mut self.image.values, served.channel);
                    let ok = words.get(at..at + span).is_some_and(|source| {
                        registers_to_values(source, channel.value_type, device.word_order, target)
                            .is_ok()
                    });
                    self.served(served.channel, ok);
                }
                self.status.request(Outcome::Success, took, "");
            }
            Answer::Bits(bits) => {
                for served in &request.channels {
                    let at = usize::from(served.offset);
                    let span = device.channels[served.channel].span() as usize;
                    let target = layout.slice_mut(&mut self.image.values, served.channel);
                    let ok = bits
                        .get(at..at + span)
                        .is_some_and(|source| bits_to_values(source, target).is_ok());
                    self.served(served.channel, ok);
                }
                self.status.request(Outcome::Success, took, "");
            }
            Answer::Written => {
                for served in &request.channels {
                    self.image.failed[served.channel] = false;
                }
                self.status.request(Outcome::Success, took, "");
            }
            Answer::Failed {
                outcome, detail, ..
            } => {
                self.fail_channels(device, layout, request);
                self.status.request(outcome, took, &detail);
            }
        }
    }

    /// Marks the channels of a request not sent as failed and counts it (§6.3).
    pub fn not_sent(
        &mut self,
        device: &DeviceDef,
        layout: &ValueLayout,
        requests: &[&PlannedRequest],
        code: u8,
        detail: &str,
    ) {
        for request in requests {
            self.fail_channels(device, layout, request);
        }
        self.status.not_sent(
            u32::try_from(requests.len()).unwrap_or(u32::MAX),
            code,
            detail,
        );
    }

    /// A channel served: delivered when its values converted, else failed.
    fn served(&mut self, channel: usize, ok: bool) {
        self.image.failed[channel] = !ok;
        self.image.deliver[channel] |= ok;
    }

    fn fail_channels(
        &mut self,
        device: &DeviceDef,
        layout: &ValueLayout,
        request: &PlannedRequest,
    ) {
        for served in &request.channels {
            self.image.failed[served.channel] = true;
            let channel = &device.channels[served.channel];
            if channel.direction == Direction::Read && channel.on_error == OnError::SetToZero {
                layout
                    .slice_mut(&mut self.image.values, served.channel)
                    .fill(0);
                self.image.deliver[served.channel] = true;
            }
        }
    }

    /// Ends the round: counts it, and gives the state line to write, if the state changed.
    pub fn end(&mut self, overruns: u32) -> Option<String> {
        let line = self.status.end_round(overruns);
        self.image.round += 1;
        self.image.status = self.status.encode();
        line
    }
}

#[cfg(test)]
#[path = "round_tests.rs"]
mod tests;
