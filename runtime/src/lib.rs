//! The Rivet soft PLC.
//!
//! It loads a program image, runs its tasks cyclically with priorities and a watchdog, owns the
//! memory areas `%I`, `%Q` and `%M`, keeps retain and persistent data, runs motion through the
//! `motion` crate and serves Modbus TCP with Rivet's online services.
//! It is both the simulator embedded in the studio and the `rivet-runtime` target binary.
//! Its standard library's pure functions (conversions, strings, dates) live in [`stdlib`].

pub mod stdlib;
