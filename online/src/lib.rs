//! The client side of Rivet's online services: connect, identify, download with progress,
//! run control, monitoring, write and force, trace upload, and polling of generic Modbus TCP
//! devices.
//!
//! It knows nothing of any UI. Today it holds an async [`Client`] with one method per service
//! of `docs/protocol.md` (whose requests and responses `online_protocol` encodes and decodes),
//! [`OnlineError`], which says for every failure what happened and what to do, and a
//! [`session`] that runs a client on a background task: commands in, events and value
//! snapshots out, reconnecting when the target comes back; and [`device`], which polls a
//! third-party Modbus TCP device's coils and registers as typed values.

mod client;
mod debug_client;
pub mod device;
mod error;
#[cfg(test)]
mod fake_target;
pub mod session;

pub use client::{Client, REQUEST_TIMEOUT, Sample, TraceConfig, Trigger};
pub use debug_client::{Attached, FlowBitmap};
// The debugging services' types (`docs/protocol.md` §6), so callers need not depend on the
// protocol crate.
pub use error::OnlineError;
pub use online_protocol::{
    ALL_TASKS, BreakpointInfo, BreakpointSpec, DebugOptions, DebugStatus, FlowCycle, FlowEntry,
    FrameRange, HaltReason, HaltState, HitMode, HitRule, MAX_CONDITION_BYTES, MAX_FLOW_ENTRIES,
    MAX_LINGER_S, SessionState, StackFrame, StepKind, TaskDebugState, TaskHalt,
};
pub use online_protocol::{
    ChangeApplied, ChangeCheck, ChangeDetailEntry, Enumeration, Fault, Identity,
    ModbusDeviceReport, ModbusDeviceState, Place, ResetKind as Reset, Resolved, Snapshot,
    TargetState, TaskInfo, TraceState, TraceStatus, Value,
};
// The string and enumeration type tags of a resolved variable, so callers tell strings from elementary values
// without writing the protocol's numbers by hand or depending on the protocol crate.
pub use online_protocol::{TYPE_ENUM, TYPE_STRING, TYPE_WSTRING};
// A device's name as `MODBUS_DEVICES` carries it (cut at a character boundary to its limit), so
// the studio matches a report to its device exactly as the runtime cut the name.
pub use online_protocol::{MAX_MODBUS_DEVICE_NAME_BYTES, cut};
