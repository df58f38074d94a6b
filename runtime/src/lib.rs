//! The Rivet soft PLC.
//!
//! It loads a program image, runs its tasks cyclically with priorities and a watchdog, owns the
//! memory areas `%I`, `%Q` and `%M`, keeps retain and persistent data, runs motion through the
//! `motion` crate and serves Modbus TCP with Rivet's online services.
//! It is both the simulator embedded in the studio and the `rivet-runtime` target binary.
//!
//! - [`engine`]: the execution engine ([`engine::Engine`]: an image's memory and code, one task
//!   cycle at a time, faults with POU and source line).
//! - [`stdlib`]: the standard library's pure functions (conversions, strings, dates).
//! - [`value`]: values of symbols read and written by path, as IEC literals.
//! - [`simulation`]: N cycles on a simulated clock, as `rivet simulate` runs them.
//! - [`differential`]: one image under two engines, compared after every cycle
//!   (`docs/native-engine.md` §11.1).
//! - [`areas`]: the located areas `%I`, `%Q` and `%M` as bytes in the CODESYS layout, shared by
//!   the engine and the Modbus server behind one mutex.
//! - [`scheduler`]: the real-time scheduler that runs an engine's tasks on their own thread,
//!   with priorities, statistics and the watchdog, behind a handle.
//! - [`retain`]: RETAIN and PERSISTENT variables saved in the data directory.
//! - [`modbus`]: the Modbus TCP server that maps the standard function codes onto the located
//!   areas (the default map is `docs/modbus-map.md`) and leaves a hook for the online services.
//! - [`serial`]: serial ports for Modbus RTU: line settings, their timing, opening a port.
//! - [`online`]: the online services of `docs/protocol.md` (identity, download, run control,
//!   monitor, write, force, trace, statistics, faults) on that hook.

pub mod areas;
pub mod differential;
pub mod engine;
pub mod modbus;
pub mod online;
pub mod retain;
pub mod scheduler;
pub mod serial;
pub mod simulation;
pub mod stdlib;
pub mod value;

#[cfg(test)]
mod test_images;
