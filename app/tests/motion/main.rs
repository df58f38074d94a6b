//! The motion kernel driven from Structured Text through `rivet simulate`: the worked examples
//! of the PLCopen motion digest (`plcopen`) and of the Omron and Delta digests (`vendors`), on
//! the example project's `MotionTask` (2 ms), one test binary with shared helpers (`support`);
//! each run is made with the default engine and with the interpreter, whose outputs must match.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

mod plcopen;
mod support;
mod vendors;
