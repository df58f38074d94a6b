//! A device's counters and state (`docs/modbus-master.md` §3.1, §4.2, §9.1): what the status
//! variable shows, what `MODBUS_DEVICES` will report, and the one line on standard error when
//! the state changes.

use std::time::{Duration, Instant};

use online_protocol::ModbusDeviceReport;
use program_image::Elementary;

/// The name of the status structure, found by name in the image's type table.
pub const STATUS_TYPE_NAME: &str = "MODBUS_DEVICE_STATUS";
/// The size of `MODBUS_DEVICE_STATUS` in bytes.
pub const STATUS_BYTES: usize = 32;
/// The members of `MODBUS_DEVICE_STATUS`: name, offset and type (§3.1).
pub const STATUS_MEMBERS: [(&str, u32, Elementary); 10] = [
    ("xConnected", 0, Elementary::Bool),
    ("xError", 1, Elementary::Bool),
    ("eLastError", 2, Elementary::Usint),
    ("byLastException", 3, Elementary::Byte),
    ("udiConsecutiveErrors", 4, Elementary::Udint),
    ("udiRequests", 8, Elementary::Udint),
    ("udiErrors", 12, Elementary::Udint),
    ("udiRounds", 16, Elementary::Udint),
    ("udiOverruns", 20, Elementary::Udint),
    ("ltLastResponseTime", 24, Elementary::Ltime),
];

/// The values of `MB_ErrorCodes` (§3.1): CODESYS's names and numbers, and Rivet's own.
pub mod error_codes {
    /// No error.
    pub const RESPONSE_SUCCESS: u8 = 0x00;
    /// No (complete) response within the timeout.
    pub const RESPONSE_TIMEOUT: u8 = 0xA1;
    /// Reserved: a bad CRC ends as a timeout in version 1 (§6.6).
    pub const RESPONSE_CRC_FAIL: u8 = 0xA2;
    /// The response names another unit id.
    pub const RESPONSE_WRONG_SLAVE: u8 = 0xA3;
    /// The response answers another function.
    pub const RESPONSE_WRONG_FUNCTIONCODE: u8 = 0xA4;
    /// No connection: refused, reset, closed, unreachable, connect timeout.
    pub const TCP_COMMUNICATION_ERROR: u8 = 0xA5;
    /// A response whose count, address or values do not match the request.
    pub const RESPONSE_INVALID_DATA: u8 = 0xA6;
    /// A response that is not a Modbus PDU.
    pub const RESPONSE_INVALID_PROTOCOL: u8 = 0xA7;
    /// An MBAP header with a wrong protocol id or length.
    pub const RESPONSE_INVALID_HEADER: u8 = 0xA8;
    /// The serial port cannot be opened, or failed.
    pub const SERIAL_PORT_ERROR: u8 = 0xC0;
    /// No round has ended since the master started.
    pub const NOT_YET_POLLED: u8 = 0xC1;
}

/// A device's state as `MODBUS_DEVICES` reports it (§9.1): the protocol's enumeration, so the
/// master's states and the reported ones cannot drift apart.
pub use online_protocol::ModbusDeviceState as DeviceState;

/// How one request ended, as far as the counters care.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Answered with what was asked.
    Success,
    /// Answered with an exception code (1 to 255).
    Exception(u8),
    /// Answered, but not with a valid answer to the request (an `MB_ErrorCodes` value).
    Invalid(u8),
    /// Not answered: a timeout, no connection or a port error (an `MB_ErrorCodes` value);
    /// the rest of the round is not sent.
    Unanswered(u8),
}

/// A device's counters since the master started; the status variable and `MODBUS_DEVICES`
/// show them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceStatus {
    /// The device's name.
    pub name: String,
    /// Its state now.
    pub state: DeviceState,
    /// The device answered its last request.
    pub connected: bool,
    /// A request of the last round failed.
    pub error: bool,
    /// The last failure's `MB_ErrorCodes` value (`NOT_YET_POLLED` before the first round).
    pub last_error: u8,
    /// The last exception code the device sent, 0 if none.
    pub last_exception: u8,
    /// Requests failed since the last that succeeded.
    pub consecutive_errors: u32,
    /// Requests sent.
    pub requests: u32,
    /// Requests failed, and requests not sent for want of a connection.
    pub errors: u32,
    /// Rounds ended.
    pub rounds: u32,
    /// Round starts dropped because the previous round still ran.
    pub overruns: u32,
    /// Connection attempts made (TCP; 0 on a serial line), failed or not: the back-off of
    /// §6.8 keeps them few while a device refuses. Not on the status variable nor the wire.
    pub connection_attempts: u32,
    /// How long the last answered request took.
    pub last_response: Duration,
    /// When the last failure happened.
    pub last_error_at: Option<Instant>,
    /// The last failure in words ("connection refused by 127.0.0.1:5502").
    pub detail: String,
    /// Whether a failure happened in the round now running.
    round_failed: bool,
    /// The worst failure of the round now running, as a state.
    round_state: DeviceState,
}

impl DeviceStatus {
    /// A device's status before its first round; `off` when the master does not run.
    pub fn new(name: &str, off: bool) -> Self {
        Self {
            name: name.to_owned(),
            state: if off {
                DeviceState::Off
            } else {
                DeviceState::Starting
            },
            connected: false,
            error: false,
            last_error: error_codes::NOT_YET_POLLED,
            last_exception: 0,
            consecutive_errors: 0,
            requests: 0,
            errors: 0,
            rounds: 0,
            overruns: 0,
            connection_attempts: 0,
            last_response: Duration::ZERO,
            last_error_at: None,
            detail: String::new(),
            round_failed: false,
            round_state: DeviceState::Communicating,
        }
    }

    /// Counts one request sent and how it ended; `detail` says a failure in words.
    pub fn request(&mut self, outcome: Outcome, took: Duration, detail: &str) {
        self.requests = self.requests.wrapping_add(1);
        match outcome {
            Outcome::Success => {
                self.connected = true;
                self.consecutive_errors = 0;
                self.last_response = took;
            }
            Outcome::Exception(code) => {
                self.connected = true;
                self.last_response = took;
                self.last_exception = code;
                self.fail(code, DeviceState::AnsweringWithErrors, detail);
            }
            Outcome::Invalid(code) => {
                self.connected = true;
                self.fail(code, DeviceState::AnsweringWithErrors, detail);
            }
            Outcome::Unanswered(code) => {
                self.connected = false;
                let state = if code == error_codes::SERIAL_PORT_ERROR {
                    DeviceState::SerialPortError
                } else {
                    DeviceState::NotAnswering
                };
                self.fail(code, state, detail);
            }
        }
    }

    /// Counts `count` requests of the round not sent, failed with `code` (§6.3, §6.8).
    pub fn not_sent(&mut self, count: u32, code: u8, detail: &str) {
        if count == 0 {
            return;
        }
        self.connected = false;
        self.errors = self.errors.wrapping_add(count);
        self.consecutive_errors = self.consecutive_errors.wrapping_add(count);
        self.last_error = code;
        self.last_error_at = Some(Instant::now());
        self.round_failed = true;
        self.round_state = if code == error_codes::SERIAL_PORT_ERROR {
            DeviceState::SerialPortError
        } else {
            DeviceState::NotAnswering
        };
        if !detail.is_empty() {
            self.detail = detail.to_owned();
        }
    }

    fn fail(&mut self, code: u8, state: DeviceState, detail: &str) {
        self.errors = self.errors.wrapping_add(1);
        self.consecutive_errors = self.consecutive_errors.wrapping_add(1);
        self.last_error = code;
        self.last_error_at = Some(Instant::now());
        self.round_failed = true;
        // The worst of the round wins: not answering over answering with errors.
        if self.round_state != DeviceState::NotAnswering
            && self.round_state != DeviceState::SerialPortError
        {
            self.round_state = state;
        }
        if !detail.is_empty() {
            self.detail = detail.to_owned();
        }
    }

    /// Ends a round: counts it, sets the error and the state, and returns the line for standard
    /// error when the state changed.
    pub fn end_round(&mut self, overruns: u32) -> Option<String> {
        self.rounds = self.rounds.wrapping_add(1);
        self.overruns = self.overruns.wrapping_add(overruns);
        self.error = self.round_failed;
        if self.last_error == error_codes::NOT_YET_POLLED {
            self.last_error = error_codes::RESPONSE_SUCCESS;
        }
        let state = if self.round_failed {
            self.round_state
        } else {
            DeviceState::Communicating
        };
        self.round_failed = false;
        self.round_state = DeviceState::Communicating;
        let before = std::mem::replace(&mut self.state, state);
        (before != state).then(|| self.state_line(before))
    }

    /// The line the runtime writes on its standard error for a change of state.
    fn state_line(&self, before: DeviceState) -> String {
        let what = match self.state {
            DeviceState::Communicating if before == DeviceState::Starting => {
                "communicating".to_owned()
            }
            DeviceState::Communicating => "answering again".to_owned(),
            DeviceState::AnsweringWithErrors => format!("answering with errors: {}", self.detail),
            DeviceState::NotAnswering => format!("{}; reconnecting", self.detail),
            DeviceState::SerialPortError => format!("{}; reopening the port", self.detail),
            DeviceState::Starting | DeviceState::Off => return String::new(),
        };
        format!("rivet-runtime: Modbus device '{}': {what}", self.name)
    }

    /// The status variable's bytes, by the offsets of §3.1 (little-endian, as the program's
    /// memory holds them).
    pub fn encode(&self) -> [u8; STATUS_BYTES] {
        let mut bytes = [0u8; STATUS_BYTES];
        bytes[0] = u8::from(self.connected);
        bytes[1] = u8::from(self.error);
        bytes[2] = self.last_error;
        bytes[3] = self.last_exception;
        bytes[4..8].copy_from_slice(&self.consecutive_errors.to_le_bytes());
        bytes[8..12].copy_from_slice(&self.requests.to_le_bytes());
        bytes[12..16].copy_from_slice(&self.errors.to_le_bytes());
        bytes[16..20].copy_from_slice(&self.rounds.to_le_bytes());
        bytes[20..24].copy_from_slice(&self.overruns.to_le_bytes());
        let nanoseconds = i64::try_from(self.last_response.as_nanos()).unwrap_or(i64::MAX);
        bytes[24..32].copy_from_slice(&nanoseconds.to_le_bytes());
        bytes
    }

    /// A copy for readers outside the master, as the online service `MODBUS_DEVICES` reports
    /// it: the same state and counters the program's status variable holds.
    pub fn snapshot(&self) -> ModbusDeviceReport {
        ModbusDeviceReport {
            name: self.name.clone(),
            state: self.state,
            last_error: self.last_error,
            last_exception: self.last_exception,
            consecutive_errors: self.consecutive_errors,
            requests: self.requests,
            errors: self.errors,
            rounds: self.rounds,
            overruns: self.overruns,
            last_response_us: u32::try_from(self.last_response.as_micros()).unwrap_or(u32::MAX),
            since_last_error_ms: self
                .last_error_at
                .map(|at| since_last_error_ms(at.elapsed())),
            detail: self.detail.clone(),
        }
    }
}

/// `since_last_error_ms` of a failure `elapsed` ago: whole milliseconds, held at
/// `u32::MAX - 1` (49 days), since `u32::MAX` on the wire means no failure yet.
pub fn since_last_error_ms(elapsed: Duration) -> u32 {
    u32::try_from(elapsed.as_millis())
        .unwrap_or(u32::MAX)
        .min(u32::MAX - 1)
}

#[cfg(test)]
#[path = "status_tests.rs"]
mod tests;
