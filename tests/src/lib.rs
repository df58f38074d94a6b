//! Workspace integration tests for Rivet.
//!
//! The tests live in `tests/tests/`: the architecture rules checked against `cargo metadata`,
//! project round trips, and compile → run → Modbus checks over loopback. [`peers`] finds the
//! independent Modbus clients those checks use.

pub mod peers;
