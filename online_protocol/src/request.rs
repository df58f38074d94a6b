//! The requests of the protocol, one variant per service, with their encoding
//! (`docs/protocol.md` §3).

use crate::Hash;
use crate::debug_request::DebugRequest;
use crate::error::DecodeError;
use crate::framing::MAX_PRETRIGGER_PERCENT;
use crate::place::Place;
use crate::reader::Reader;
use crate::service::Service;
use crate::writer::{put_place, put_places, put_str8, put_values};

/// How `RESET` resets the program's memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum ResetKind {
    /// Everything but RETAIN and PERSISTENT.
    Warm = 0,
    /// Everything but PERSISTENT.
    Cold = 1,
    /// Everything, and the forces are released.
    Origin = 2,
}

impl ResetKind {
    /// Every kind, in the order of their numbers.
    pub const ALL: [ResetKind; 3] = [ResetKind::Warm, ResetKind::Cold, ResetKind::Origin];
}

/// The trace trigger of a `TRACE_CONFIGURE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum TriggerKind {
    /// No trigger: record until the samples are complete.
    None = 0,
    /// The trigger place goes from FALSE to TRUE.
    Rising = 1,
    /// The trigger place goes from TRUE to FALSE.
    Falling = 2,
    /// The trigger place is TRUE.
    WhileTrue = 3,
}

impl TriggerKind {
    /// Every trigger, in the order of their numbers.
    pub const ALL: [TriggerKind; 4] = [
        TriggerKind::None,
        TriggerKind::Rising,
        TriggerKind::Falling,
        TriggerKind::WhileTrue,
    ];
}

/// A `TRACE_CONFIGURE` request without its token.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceConfig {
    /// The task index.
    pub task: u8,
    /// Sample every n-th cycle, at least 1.
    pub every: u16,
    /// How many samples to keep, at least 1.
    pub samples: u32,
    /// Percent of the samples kept before the trigger, 0 to 100.
    pub pretrigger: u8,
    /// The trigger.
    pub trigger: TriggerKind,
    /// The place the trigger looks at (sent, and ignored, without a trigger).
    pub trigger_place: Place,
    /// The places sampled (at most [`crate::TRACE_CONFIGURE_PLACES`] fit one frame).
    pub places: Vec<Place>,
}

/// A request: the service and its payload. A changing service carries the token of `LOGIN`
/// first (0 when the runtime has no password).
#[derive(Clone, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // The fields are the protocol's, documented in docs/protocol.md §3.
pub enum Request {
    Identify {
        protocol: u16,
    },
    Login {
        password: String,
    },
    Logout,
    DownloadBegin {
        token: u128,
        size: u32,
        hash: Hash,
    },
    DownloadChunk {
        token: u128,
        transfer: u16,
        offset: u32,
        bytes: Vec<u8>,
    },
    DownloadCommit {
        token: u128,
        transfer: u16,
        start: bool,
    },
    DownloadAbort {
        token: u128,
        transfer: u16,
    },
    OnlineChangeCheck {
        token: u128,
        transfer: u16,
    },
    OnlineChangeDetails {
        token: u128,
        transfer: u16,
        from: u16,
    },
    OnlineChangeApply {
        token: u128,
        transfer: u16,
    },
    Start {
        token: u128,
    },
    Stop {
        token: u128,
    },
    Reset {
        token: u128,
        kind: ResetKind,
    },
    Resolve {
        path: String,
    },
    Enumeration {
        path: String,
        from: u16,
    },
    Read {
        places: Vec<Place>,
    },
    Write {
        token: u128,
        values: Vec<(Place, Vec<u8>)>,
    },
    Force {
        token: u128,
        values: Vec<(Place, Vec<u8>)>,
    },
    Unforce {
        token: u128,
        places: Vec<Place>,
    },
    Forces {
        from: u16,
    },
    TraceConfigure {
        token: u128,
        config: TraceConfig,
    },
    TraceArm {
        token: u128,
    },
    TraceStatus,
    TraceUpload {
        from: u32,
    },
    TraceAdd {
        token: u128,
        places: Vec<Place>,
    },
    Tasks,
    Faults {
        from: u16,
    },
    ModbusDevices {
        from: u8,
    },
    /// A debugging service (version 3, §6).
    Debug(DebugRequest),
}

impl Request {
    /// The request's service.
    pub fn service(&self) -> Service {
        use Request::*;
        match self {
            Identify { .. } => Service::Identify,
            Login { .. } => Service::Login,
            Logout => Service::Logout,
            DownloadBegin { .. } => Service::DownloadBegin,
            DownloadChunk { .. } => Service::DownloadChunk,
            DownloadCommit { .. } => Service::DownloadCommit,
            DownloadAbort { .. } => Service::DownloadAbort,
            OnlineChangeCheck { .. } => Service::OnlineChangeCheck,
            OnlineChangeDetails { .. } => Service::OnlineChangeDetails,
            OnlineChangeApply { .. } => Service::OnlineChangeApply,
            Start { .. } => Service::Start,
            Stop { .. } => Service::Stop,
            Reset { .. } => Service::Reset,
            Resolve { .. } => Service::Resolve,
            Enumeration { .. } => Service::Enumeration,
            Read { .. } => Service::Read,
            Write { .. } => Service::Write,
            Force { .. } => Service::Force,
            Unforce { .. } => Service::Unforce,
            Forces { .. } => Service::Forces,
            TraceConfigure { .. } => Service::TraceConfigure,
            TraceArm { .. } => Service::TraceArm,
            TraceStatus => Service::TraceStatus,
            TraceUpload { .. } => Service::TraceUpload,
            TraceAdd { .. } => Service::TraceAdd,
            Tasks => Service::Tasks,
            Faults { .. } => Service::Faults,
            ModbusDevices { .. } => Service::ModbusDevices,
            Debug(request) => request.service(),
        }
    }

    /// The token of a service that changes the target, `None` for a read-only one.
    pub fn token(&self) -> Option<u128> {
        use Request::*;
        match self {
            DownloadBegin { token, .. }
            | DownloadChunk { token, .. }
            | DownloadCommit { token, .. }
            | DownloadAbort { token, .. }
            | OnlineChangeCheck { token, .. }
            | OnlineChangeDetails { token, .. }
            | OnlineChangeApply { token, .. }
            | Start { token }
            | Stop { token }
            | Reset { token, .. }
            | Write { token, .. }
            | Force { token, .. }
            | Unforce { token, .. }
            | TraceConfigure { token, .. }
            | TraceAdd { token, .. }
            | TraceArm { token } => Some(*token),
            Debug(request) => request.token(),
            Identify { .. }
            | Login { .. }
            | Logout
            | Resolve { .. }
            | Enumeration { .. }
            | Read { .. }
            | Forces { .. }
            | TraceStatus
            | TraceUpload { .. }
            | Tasks
            | Faults { .. }
            | ModbusDevices { .. } => None,
        }
    }

    /// The request's bytes after the function code: the service and its payload. Texts and
    /// lists longer than their one-byte length allows are cut; whether the frame fits a PDU is
    /// for the sender to check.
    pub fn encode(&self) -> Vec<u8> {
        use Request::*;
        let mut out = vec![self.service().number()];
        if let Some(token) = self.token() {
            out.extend_from_slice(&token.to_le_bytes());
        }
        match self {
            Identify { protocol } => out.extend_from_slice(&protocol.to_le_bytes()),
            Login { password } => put_str8(&mut out, password),
            Logout => {}
            DownloadBegin { size, hash, .. } => {
                out.extend_from_slice(&size.to_le_bytes());
                out.extend_from_slice(hash);
            }
            DownloadChunk {
                transfer,
                offset,
                bytes,
                ..
            } => {
                out.extend_from_slice(&transfer.to_le_bytes());
                out.extend_from_slice(&offset.to_le_bytes());
                out.extend_from_slice(bytes);
            }
            DownloadCommit {
                transfer, start, ..
            } => {
                out.extend_from_slice(&transfer.to_le_bytes());
                out.push(u8::from(*start));
            }
            DownloadAbort { transfer, .. }
            | OnlineChangeCheck { transfer, .. }
            | OnlineChangeApply { transfer, .. } => out.extend_from_slice(&transfer.to_le_bytes()),
            OnlineChangeDetails { transfer, from, .. } => {
                out.extend_from_slice(&transfer.to_le_bytes());
                out.extend_from_slice(&from.to_le_bytes());
            }
            Start { .. } | Stop { .. } | TraceArm { .. } | TraceStatus | Tasks => {}
            Reset { kind, .. } => out.push(*kind as u8),
            Resolve { path } => put_str8(&mut out, path),
            Enumeration { path, from } => {
                put_str8(&mut out, path);
                out.extend_from_slice(&from.to_le_bytes());
            }
            Read { places } | Unforce { places, .. } | TraceAdd { places, .. } => {
                put_places(&mut out, places);
            }
            Write { values, .. } | Force { values, .. } => put_values(&mut out, values),
            Forces { from } | Faults { from } => out.extend_from_slice(&from.to_le_bytes()),
            ModbusDevices { from } => out.push(*from),
            TraceConfigure { config, .. } => {
                out.push(config.task);
                out.extend_from_slice(&config.every.to_le_bytes());
                out.extend_from_slice(&config.samples.to_le_bytes());
                out.push(config.pretrigger);
                out.push(config.trigger as u8);
                put_place(&mut out, &config.trigger_place);
                put_places(&mut out, &config.places);
            }
            TraceUpload { from } => out.extend_from_slice(&from.to_le_bytes()),
            Debug(request) => request.encode_fields(&mut out),
        }
        out
    }

    /// The request in `frame`, the bytes after the function code (service and payload).
    ///
    /// A frame too short for its service, with bytes left over, or with a field out of range
    /// is an error; [`DecodeError::status`] is the status the runtime answers with.
    pub fn decode(frame: &[u8]) -> Result<Self, DecodeError> {
        let mut r = Reader::new(frame);
        if frame.is_empty() {
            return Err(DecodeError::Empty);
        }
        let number = r.u8("service")?;
        let service = Service::from_number(number).ok_or(DecodeError::UnknownService(number))?;
        let request = match service {
            Service::Identify => Request::Identify {
                protocol: r.u16("protocol")?,
            },
            Service::Login => Request::Login {
                password: r.str8("password")?,
            },
            Service::Logout => Request::Logout,
            Service::DownloadBegin => Request::DownloadBegin {
                token: r.u128("token")?,
                size: r.u32("size")?,
                hash: r.hash("hash")?,
            },
            Service::DownloadChunk => Request::DownloadChunk {
                token: r.u128("token")?,
                transfer: r.u16("transfer")?,
                offset: r.u32("offset")?,
                bytes: r.rest().to_vec(),
            },
            Service::DownloadCommit => Request::DownloadCommit {
                token: r.u128("token")?,
                transfer: r.u16("transfer")?,
                start: r.flag("start")?,
            },
            Service::DownloadAbort => Request::DownloadAbort {
                token: r.u128("token")?,
                transfer: r.u16("transfer")?,
            },
            Service::OnlineChangeCheck => Request::OnlineChangeCheck {
                token: r.u128("token")?,
                transfer: r.u16("transfer")?,
            },
            Service::OnlineChangeDetails => Request::OnlineChangeDetails {
                token: r.u128("token")?,
                transfer: r.u16("transfer")?,
                from: r.u16("from")?,
            },
            Service::OnlineChangeApply => Request::OnlineChangeApply {
                token: r.u128("token")?,
                transfer: r.u16("transfer")?,
            },
            Service::Start => Request::Start {
                token: r.u128("token")?,
            },
            Service::Stop => Request::Stop {
                token: r.u128("token")?,
            },
            Service::Reset => Request::Reset {
                token: r.u128("token")?,
                kind: r.choice("reset kind", &ResetKind::ALL, "0 to 2")?,
            },
            Service::Resolve => Request::Resolve {
                path: r.str8("path")?,
            },
            Service::Enumeration => Request::Enumeration {
                path: r.str8("path")?,
                from: r.u16("from")?,
            },
            Service::Read => Request::Read {
                places: r.places()?,
            },
            Service::Write => Request::Write {
                token: r.u128("token")?,
                values: r.values()?,
            },
            Service::Force => Request::Force {
                token: r.u128("token")?,
                values: r.values()?,
            },
            Service::Unforce => Request::Unforce {
                token: r.u128("token")?,
                places: r.places()?,
            },
            Service::Forces => Request::Forces {
                from: r.u16("from")?,
            },
            Service::TraceConfigure => Request::TraceConfigure {
                token: r.u128("token")?,
                config: trace_config(&mut r)?,
            },
            Service::TraceArm => Request::TraceArm {
                token: r.u128("token")?,
            },
            Service::TraceStatus => Request::TraceStatus,
            Service::TraceUpload => Request::TraceUpload {
                from: r.u32("from")?,
            },
            Service::TraceAdd => Request::TraceAdd {
                token: r.u128("token")?,
                places: r.places()?,
            },
            Service::Tasks => Request::Tasks,
            Service::Faults => Request::Faults {
                from: r.u16("from")?,
            },
            Service::ModbusDevices => Request::ModbusDevices {
                from: r.u8("from")?,
            },
            debug => match DebugRequest::decode_fields(debug, &mut r)? {
                Some(request) => Request::Debug(request),
                None => return Err(DecodeError::UnknownService(number)),
            },
        };
        r.finish()?;
        Ok(request)
    }
}

/// The fields of `TRACE_CONFIGURE` after the token. The ranges of `every`, `samples` and
/// `pretrigger` are checked after the places are read, so that a cut frame is "too short".
fn trace_config(r: &mut Reader<'_>) -> Result<TraceConfig, DecodeError> {
    let task = r.u8("task")?;
    let every_at = r.position();
    let every = r.u16("every")?;
    let samples_at = r.position();
    let samples = r.u32("samples")?;
    let pretrigger_at = r.position();
    let pretrigger = r.u8("pretrigger")?;
    let trigger = r.choice("trigger", &TriggerKind::ALL, "0 to 3")?;
    let trigger_place = r.place("trigger place")?;
    let places = r.places()?;
    let out_of_range = |field, at, value: u64, expected| DecodeError::OutOfRange {
        field,
        at,
        value,
        expected,
    };
    if every == 0 {
        return Err(out_of_range("every", every_at, 0, "at least 1"));
    }
    if samples == 0 {
        return Err(out_of_range("samples", samples_at, 0, "at least 1"));
    }
    if pretrigger > MAX_PRETRIGGER_PERCENT {
        return Err(out_of_range(
            "pretrigger",
            pretrigger_at,
            u64::from(pretrigger),
            "at most 100",
        ));
    }
    Ok(TraceConfig {
        task,
        every,
        samples,
        pretrigger,
        trigger,
        trigger_place,
        places,
    })
}

#[cfg(test)]
#[path = "request_tests.rs"]
mod tests;
