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

pub mod engine;
pub mod simulation;
pub mod stdlib;
pub mod value;
