//! Independent Modbus clients shared by the runtime's integration tests: mbpoll and pymodbus
//! are system packages that `scripts/test.sh` installs, and without them the tests that use them
//! fail and say so. `pymodbus_client.py` beside this file is the script `modbus_server.rs` runs.
//!
//! The lookups are the workspace tests' own (`tests/src/peers.rs`), compiled in here too, so
//! both crates find the peers the same way; only running them off the async workers is added.

// Each test binary uses a part of the shared helpers, and the rest would be dead code in it.
#[allow(dead_code)]
#[path = "../../../tests/src/peers.rs"]
mod shared;

#[allow(unused_imports)]
pub use shared::{PymodbusServer, SocatPair, python_with_pymodbus, required_program};

/// Runs a program to its end off the async workers and returns its standard output, or fails
/// with everything it said.
pub async fn run(program: String, args: Vec<String>) -> String {
    tokio::task::spawn_blocking(move || shared::run(&program, &args))
        .await
        .unwrap()
}
