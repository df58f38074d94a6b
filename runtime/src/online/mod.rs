//! Rivet's online services (`docs/protocol.md`, version 3) over Modbus function code 0x64:
//! identity, login, download, run control, monitor, write, force, trace, statistics and faults.
//!
//! - The requests and responses themselves, with their encoding, are `online_protocol`'s:
//!   this module decodes requests and encodes responses only through it.
//! - [`OnlineServices`]: the services on a [`crate::scheduler::Scheduler`], as the
//!   [`crate::modbus::CustomFunctions`] hook of the Modbus server.
//! - [`WRONG_PASSWORD_DELAY`] and its neighbours: how long a client address waits after a
//!   wrong password, whichever of its connections sent it.
//! - [`read_password`]: a password from a file or [`PASSWORD_VARIABLE`], for the binaries.
//! - [`Forces`] and [`Trace`]: the force table and the trace recorder, which the scheduler's
//!   thread applies and feeds around every cycle.

mod debug;
mod debug_reads;
mod download;
mod forces;
mod password;
mod place;
mod services;
mod trace;
mod wrong_passwords;

pub use debug::{Debugging, MAX_LINGER_S};
pub use download::{CHECKED_TRANSFER_TIMEOUT, TRANSFER_TIMEOUT, Transfer};
pub use forces::Forces;
pub use password::{PASSWORD_VARIABLE, PasswordError, read_password};
pub use place::{Memory, PlaceAccess};
pub use services::OnlineServices;
pub use trace::{MAX_TRACE_BYTES, Sample, Trace, TraceState};
pub use wrong_passwords::{FORGET_ONE_AFTER, LONGEST_WAIT, MAX_ADDRESSES, WRONG_PASSWORD_DELAY};
