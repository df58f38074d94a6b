//! Runtime faults: what stops a task, and where it happened.

use std::fmt;

/// Why a task stopped.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FaultKind {
    /// An integer division or `MOD` by zero.
    #[error("division by zero")]
    DivisionByZero,
    /// An array index outside the declared bounds.
    #[error("array index {index} is outside {low}..{high}")]
    IndexOutOfBounds {
        /// The index used.
        index: i64,
        /// The lowest index.
        low: i64,
        /// The highest index.
        high: i64,
    },
    /// Dereferencing a null pointer or reference.
    #[error("null pointer dereferenced")]
    NullPointer,
    /// A pointer that points nowhere valid (outside its region, or into a returned frame).
    #[error("invalid pointer {0:#018x}")]
    BadPointer(u64),
    /// Calls nested deeper than the task's stack allows (recursion).
    #[error("stack exhausted: calls nested too deeply")]
    StackOverflow,
    /// The task ran longer than its watchdog allows.
    #[error("watchdog: the cycle ran longer than {limit_us} µs")]
    Watchdog {
        /// The limit that was exceeded, in microseconds.
        limit_us: u64,
    },
    /// A memory access outside the engine's memory; verification should make this impossible.
    #[error("memory access outside the program's memory")]
    Memory,
    /// A halted cycle was abandoned (`STOP`, `RESET` or a download while a task was halted):
    /// not a fault, the rest of the cycle just does not run.
    #[error("the halted cycle was abandoned")]
    Abandoned,
    /// The engine itself failed (a bug in the runtime, caught so that the process goes on).
    #[error("internal error of the runtime: {0}")]
    Internal(String),
}

/// A fault with the place it happened.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FaultRecord {
    /// The task that stopped.
    pub task: String,
    /// What happened.
    pub kind: FaultKind,
    /// The POU whose code faulted.
    pub pou: String,
    /// The source file, when the image has a line table.
    pub file: Option<String>,
    /// The 1-based source line, when the image has a line table.
    pub line: Option<u32>,
    /// The instruction index in the POU.
    pub instruction: u32,
    /// The task's cycle count when it happened.
    pub cycle: u64,
}

impl fmt::Display for FaultRecord {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "task '{}' stopped: {} in {}",
            self.task, self.kind, self.pou
        )?;
        match (&self.file, self.line) {
            (Some(file), Some(line)) => write!(f, " ({file}:{line})"),
            _ => write!(f, " (instruction {})", self.instruction),
        }
    }
}
