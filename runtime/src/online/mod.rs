//! Rivet's online services (`docs/protocol.md`, version 1) over Modbus function code 0x64:
//! identity, login, download, run control, monitor, write, force, trace, statistics and faults.
//!
//! - [`codec`]: requests parsed from bytes and responses built, without panics.
//! - [`OnlineServices`]: the services on a [`crate::scheduler::Scheduler`], as the
//!   [`crate::modbus::CustomFunctions`] hook of the Modbus server.
//! - [`Forces`] and [`Trace`]: the force table and the trace recorder, which the scheduler's
//!   thread applies and feeds around every cycle.

pub mod codec;
mod download;
mod forces;
mod place;
mod services;
mod trace;

pub use download::{CHUNK_BYTES, TRANSFER_TIMEOUT, Transfer};
pub use forces::Forces;
pub use place::{Memory, NO_BIT, WirePlace};
pub use services::{OnlineServices, WRONG_PASSWORD_DELAY};
pub use trace::{MAX_TRACE_BYTES, Sample, Trace, TraceState};
