//! The typed answers that responses carry: what a target says about itself, its variables,
//! its tasks, its faults and its trace.

use crate::Hash;
use crate::framing::SAMPLE_HEADER_BYTES;
use crate::place::Place;

/// What the target says about itself (`IDENTIFY`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Identity {
    /// The protocol version it speaks.
    pub protocol: u16,
    /// Its runtime version.
    pub runtime_version: String,
    /// Its state.
    pub state: TargetState,
    /// The identity hash of its program, `None` without one (zeros on the wire).
    pub image_hash: Option<Hash>,
    /// The project name of its program.
    pub project: String,
    /// Whether changing services need a password.
    pub password_required: bool,
    /// What the target says about debugging (the `debug` byte version 3 appends).
    pub debug: crate::DebugStatus,
}

/// The state of a target, numbered as `IDENTIFY` and run control send it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum TargetState {
    /// No program loaded.
    NoProgram = 0,
    /// A program, not running.
    Stopped = 1,
    /// Running.
    Running = 2,
    /// Running, with at least one task stopped by a fault.
    Faulted = 3,
}

impl TargetState {
    /// Every state, in the order of their numbers.
    pub const ALL: [TargetState; 4] = [
        TargetState::NoProgram,
        TargetState::Stopped,
        TargetState::Running,
        TargetState::Faulted,
    ];

    /// The state in words.
    pub fn describe(self) -> &'static str {
        match self {
            Self::NoProgram => "no program",
            Self::Stopped => "stopped",
            Self::Running => "running",
            Self::Faulted => "running with a faulted task",
        }
    }
}

/// A variable resolved on the target (`RESOLVE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Resolved {
    /// Where it is.
    pub place: Place,
    /// Its elementary type tag (`docs/program-image.md` §4), [`crate::TYPE_STRING`],
    /// [`crate::TYPE_WSTRING`] or [`crate::TYPE_OTHER`].
    pub type_tag: u8,
    /// The characters of a string, else 0.
    pub length: u16,
}

/// An enumeration type's values (`ENUMERATION`, gathered over as many requests as it needs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Enumeration {
    /// The elementary tag of the integer type its values are stored as.
    pub base: u8,
    /// The values' names and numbers in declaration order.
    pub values: Vec<(String, i64)>,
}

impl Enumeration {
    /// The name of the value `number`, if the type has one (a variable can hold a number that
    /// names no value, for example after a write of a plain integer).
    pub fn name_of(&self, number: i64) -> Option<&str> {
        self.values
            .iter()
            .find(|(_, value)| *value == number)
            .map(|(name, _)| name.as_str())
    }
}

/// A place's bytes and whether it is forced.
pub type Value = (Vec<u8>, bool);

/// A consistent snapshot of some places (`READ`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Snapshot {
    /// Cycles run so far (all tasks) when it was taken.
    pub cycle: u64,
    /// Each place's bytes, and whether it is forced.
    pub values: Vec<Value>,
}

/// Statistics of one task (`TASKS`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TaskInfo {
    /// The task's name.
    pub name: String,
    /// Cycles run.
    pub cycles: u64,
    /// The last cycle's time.
    pub last_ns: u64,
    /// The shortest cycle.
    pub min_ns: u64,
    /// The longest cycle.
    pub max_ns: u64,
    /// The average cycle.
    pub average_ns: u64,
    /// The largest start jitter.
    pub jitter_max_ns: u64,
    /// Whether a fault stopped it.
    pub faulted: bool,
}

impl TaskInfo {
    /// The bytes of its entry in a `TASKS` answer: the name, six counters and the flag.
    pub fn wire_bytes(&self) -> usize {
        1 + self.name.len() + 6 * 8 + 1
    }
}

/// A fault the target recorded (`FAULTS`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fault {
    /// The task it stopped.
    pub task: String,
    /// What happened.
    pub kind: String,
    /// The POU.
    pub pou: String,
    /// The source file, empty when unknown.
    pub file: String,
    /// The line, 0 when unknown.
    pub line: u32,
    /// The task's cycle count.
    pub cycle: u64,
}

impl Fault {
    /// The bytes of its entry in a `FAULTS` answer: four texts, the line and the cycle.
    pub fn wire_bytes(&self) -> usize {
        4 + self.task.len() + self.kind.len() + self.pou.len() + self.file.len() + 4 + 8
    }
}

/// What the trace recorder is doing, numbered as `TRACE_STATUS` sends it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum TraceState {
    /// Nothing configured.
    Unconfigured = 0,
    /// Configured, not armed.
    Configured = 1,
    /// Armed: recording, before the trigger.
    Armed = 2,
    /// Triggered: recording the part after the trigger.
    Triggered = 3,
    /// Every sample is recorded.
    Complete = 4,
}

impl TraceState {
    /// Every state, in the order of their numbers.
    pub const ALL: [TraceState; 5] = [
        TraceState::Unconfigured,
        TraceState::Configured,
        TraceState::Armed,
        TraceState::Triggered,
        TraceState::Complete,
    ];
}

/// Where a trace is (`TRACE_STATUS`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TraceStatus {
    /// What the recorder is doing.
    pub state: TraceState,
    /// Samples recorded so far.
    pub recorded: u32,
    /// The index of the sample at the trigger, if it came ([`crate::NO_TRIGGER_SAMPLE`] on
    /// the wire when not).
    pub trigger_sample: Option<u32>,
}

/// One sample of a trace as `TRACE_UPLOAD` carries it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceSample {
    /// The task's cycle count after the sampled cycle.
    pub cycle: u64,
    /// The task clock at the start of the sampled cycle, in nanoseconds.
    pub time_ns: u64,
    /// The values of the configured places, in order, one after the other.
    pub values: Vec<u8>,
}

impl TraceSample {
    /// The bytes of the sample in a `TRACE_UPLOAD` answer.
    pub fn wire_bytes(&self) -> usize {
        SAMPLE_HEADER_BYTES + self.values.len()
    }
}
