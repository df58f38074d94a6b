//! The Rivet soft PLC.
//!
//! It loads a program image, runs its tasks cyclically with priorities and a watchdog, owns the
//! memory areas `%I`, `%Q` and `%M`, keeps retain and persistent data, runs motion through the
//! `motion` crate and serves Modbus TCP with Rivet's online services.
//! It is both the simulator embedded in the studio and the `rivet-runtime` target binary.
//!
//! Built so far:
//! - [`areas`]: the located areas `%I`, `%Q` and `%M` as bytes in the CODESYS layout, shared by
//!   the engine and the Modbus server behind one mutex.
//! - [`modbus`]: the Modbus TCP server that maps the standard function codes onto the located
//!   areas (the default map is `docs/modbus-map.md`) and leaves a hook for the online services.

pub mod areas;
pub mod modbus;
