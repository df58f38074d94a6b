//! Workspace integration tests for Rivet.
//!
//! The tests live in `tests/tests/`: the architecture rules checked against `cargo metadata`,
//! project round trips, and, as the product grows, compile → run → Modbus checks over loopback.
