//! Workspace integration tests for Rivet.
//!
//! The tests live in `tests/tests/`: the architecture rules checked against `cargo metadata`,
//! project round trips, and compile → run → Modbus checks over loopback. [`peers`] finds the
//! independent Modbus clients those checks use, and socat's virtual serial cables;
//! [`fault_proxy`] stands between a Modbus master and a slave to play network faults.

pub mod fault_proxy;
pub mod peers;
