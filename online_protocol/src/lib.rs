//! The requests, responses and status codes of Rivet's online protocol (`docs/protocol.md`,
//! version 3) with their encoding, written once for both sides: the runtime decodes
//! [`Request`]s and encodes [`Response`]s and [`Refusal`]s, the client does the opposite.
//!
//! Everything here is plain data and pure functions: no I/O, no threads. Decoding never
//! panics, whatever the bytes; a [`DecodeError`] says what was wrong at which byte.
//!
//! - [`framing`]: the function code, the version and every size of the framing.
//! - [`Service`] and [`Status`]: the numbers of the services and of the statuses.
//! - [`Place`]: where a variable is on the target.
//! - [`Request`] and [`Response`]: one variant per service, with `encode` and `decode`; the
//!   debugging services of version 3 (§6) as [`DebugRequest`] and [`DebugResponse`].
//! - [`ModbusDeviceReport`] and [`modbus_devices_page`]: the `MODBUS_DEVICES` answer and the
//!   page of it the runtime sends.

mod answers;
mod debug_request;
mod debug_response;
mod debug_types;
mod error;
pub mod framing;
mod modbus_devices;
mod online_change;
mod place;
mod reader;
mod request;
mod response;
mod service;
mod status;
mod writer;

#[cfg(test)]
mod arb;
#[cfg(test)]
mod debug_arb;

pub use answers::{
    Enumeration, Fault, Identity, Resolved, Snapshot, TargetState, TaskInfo, TraceSample,
    TraceState, TraceStatus, Value,
};
pub use debug_request::DebugRequest;
pub use debug_response::{
    BreakpointInfo, DebugResponse, HaltReason, HaltState, SessionState, StackFrame, TaskDebugState,
    TaskHalt,
};
pub use debug_types::{
    BreakpointSpec, DebugOptions, DebugStatus, FlowCycle, FlowEntry, FrameRange, HitMode, HitRule,
    StepKind,
};
pub use error::DecodeError;
pub use framing::*;
pub use modbus_devices::{ModbusDeviceReport, ModbusDeviceState, modbus_devices_page};
pub use online_change::{ChangeApplied, ChangeCheck, ChangeDetailEntry, MAX_DETAIL_KIND};
pub use place::Place;
pub use reader::Reader;
pub use request::{Request, ResetKind, TraceConfig, TriggerKind};
pub use response::{Answer, Response};
pub use service::Service;
pub use status::{Refusal, Status};
pub use writer::cut;

/// A SHA-256 hash: of a whole image in `DOWNLOAD_BEGIN`, of its identity in `IDENTIFY`.
pub type Hash = [u8; 32];
