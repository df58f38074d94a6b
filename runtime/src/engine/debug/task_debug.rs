//! What the debugger keeps of one task: its shadow call stack, the step it was given and
//! where it is halted.

use std::time::Instant;

/// One frame of a task's call stack as the debugger sees it (`STACK`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StackFrame {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// For the innermost frame where the task is; for the others the call instruction.
    pub instruction: u32,
    /// The absolute offset in the engine's memory of the instance the frame runs on.
    pub instance: usize,
    /// The absolute offset in the engine's memory of the frame's start.
    pub frame: usize,
    /// The frame's size in bytes, the POU's `frame_size`.
    pub frame_bytes: u32,
}

/// The kinds of `STEP`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepKind {
    /// Halt at the next statement start in any POU.
    Into,
    /// Halt at the next statement start with at most as many frames as now.
    Over,
    /// Halt at the next statement start with fewer frames than now.
    Out,
}

/// Where a task that goes on is to halt next, besides breakpoints.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pending {
    /// Nowhere: it runs until a breakpoint.
    Nothing,
    /// At the next statement start with at most this many frames (into is `usize::MAX`).
    Within(usize),
    /// At the next statement start with fewer than this many frames.
    Below(usize),
    /// At the first statement of the next program it starts (step out of, or over the end
    /// of, a program's body).
    NextProgram,
    /// At this statement start (POU and instruction), any instance.
    RunTo(u32, u32),
    /// At the next statement start (`HALT`).
    Halt,
}

/// Why a task halted (`reason` of `HALT_STATE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HaltReason {
    /// A breakpoint hit (0), with its id.
    Breakpoint(u16),
    /// A step ended (1).
    Step,
    /// Run to cursor reached its statement (2).
    RunTo,
    /// `HALT` (3).
    Halt,
    /// A breakpoint's condition faulted (4), with the breakpoint's id.
    ConditionFaulted(u16),
}

impl HaltReason {
    /// Its number on the wire.
    pub fn code(self) -> u8 {
        match self {
            Self::Breakpoint(_) => 0,
            Self::Step => 1,
            Self::RunTo => 2,
            Self::Halt => 3,
            Self::ConditionFaulted(_) => 4,
        }
    }

    /// The breakpoint's id, 0xFFFF when the reason is no breakpoint.
    pub fn breakpoint(self) -> u16 {
        match self {
            Self::Breakpoint(id) | Self::ConditionFaulted(id) => id,
            _ => 0xFFFF,
        }
    }
}

/// Where and why a task is halted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Halt {
    /// Why.
    pub reason: HaltReason,
    /// The POU it is halted in.
    pub pou: u32,
    /// The statement start it is halted at (not run yet).
    pub instruction: u32,
    /// Its frames, 1 for a program's body.
    pub depth: u16,
    /// The task's count of finished cycles before this one.
    pub cycle: u64,
    /// When it halted.
    pub since: Instant,
}

/// The debugger's view of one task.
#[derive(Clone, Debug)]
pub struct TaskDebug {
    /// Its call stack while it is in a cycle run with the debugger, outermost first.
    pub(crate) stack: Vec<StackFrame>,
    /// Where it is to halt next.
    pub(crate) pending: Pending,
    /// Where it is halted, when it is.
    pub(crate) halt: Option<Halt>,
    /// Set when a task that went on has not halted since (`HALT_STATE` state 4).
    pub(crate) stepping: bool,
    /// The task's count of finished cycles before the one in progress.
    pub(crate) cycle: u64,
}

impl TaskDebug {
    pub(crate) fn new() -> Self {
        Self {
            stack: Vec::new(),
            pending: Pending::Nothing,
            halt: None,
            stepping: false,
            cycle: 0,
        }
    }

    /// Its call stack, innermost first, while it is in a cycle.
    pub fn stack(&self) -> impl Iterator<Item = &StackFrame> {
        self.stack.iter().rev()
    }

    /// Where it is halted, when it is.
    pub fn halt(&self) -> Option<&Halt> {
        self.halt.as_ref()
    }

    /// Whether it went on after a step, run to cursor or continue and has not halted since.
    pub fn stepping(&self) -> bool {
        self.stepping
    }

    /// Whether it is in a cycle run with the debugger (halted, waiting or running).
    pub fn in_cycle(&self) -> bool {
        !self.stack.is_empty()
    }
}
