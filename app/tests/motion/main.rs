//! The motion kernel driven from Structured Text through `rivet simulate`: the worked examples
//! of the PLCopen motion digest (`plcopen`) and of the Omron and Delta digests (`vendors`), on
//! the example project's `MotionTask` (2 ms), one test binary with shared helpers (`support`);
//! each run is made through `rivet simulate` with the default engine and in-process under the
//! interpreter and the native engine, compared cycle by cycle (`runtime::differential::run_both`).

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

mod plcopen;
mod support;
mod vendors;
