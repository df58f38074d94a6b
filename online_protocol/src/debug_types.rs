//! The small typed fields of the debugging services (`docs/protocol.md` §6): hit rules, step
//! kinds, session options, frame ranges and flow entries.

/// When a breakpoint's hit halts the task (`hit_mode`), CODESYS's four choices.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum HitMode {
    /// Every hit halts.
    Always = 0,
    /// The hit whose count equals the target halts.
    Equal = 1,
    /// Every hit whose count is a multiple of the target halts.
    Multiple = 2,
    /// Every hit whose count is at least the target halts.
    AtLeast = 3,
}

impl HitMode {
    /// Every mode, in the order of their numbers.
    pub const ALL: [HitMode; 4] = [
        HitMode::Always,
        HitMode::Equal,
        HitMode::Multiple,
        HitMode::AtLeast,
    ];
}

/// A breakpoint's hit rule: the mode and its target count.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct HitRule {
    /// When a hit halts.
    pub mode: HitMode,
    /// The count the mode compares with; at least 1 for every mode but [`HitMode::Always`].
    pub target: u32,
}

impl HitRule {
    /// Every hit halts.
    pub const ALWAYS: HitRule = HitRule {
        mode: HitMode::Always,
        target: 0,
    };

    /// Whether the hit numbered `count` (1 for the first) halts the task.
    pub fn halts_at(self, count: u32) -> bool {
        match self.mode {
            HitMode::Always => true,
            HitMode::Equal => count == self.target,
            HitMode::Multiple => self.target != 0 && count.is_multiple_of(self.target),
            HitMode::AtLeast => count >= self.target,
        }
    }
}

/// What a `STEP` steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum StepKind {
    /// To the next statement start, in any POU.
    Into = 0,
    /// To the next statement start with at most as many frames as now.
    Over = 1,
    /// To the next statement start with fewer frames than now.
    Out = 2,
}

impl StepKind {
    /// Every kind, in the order of their numbers.
    pub const ALL: [StepKind; 3] = [StepKind::Into, StepKind::Over, StepKind::Out];
}

/// The options of a debug session (`DEBUG_ATTACH`'s and `HALT_STATE`'s `options` byte).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct DebugOptions {
    /// Bit 0: any halt (breakpoint or step) halts every task ("halt all").
    pub halt_all_on_halt: bool,
}

impl DebugOptions {
    /// The options' byte on the wire.
    pub fn bits(self) -> u8 {
        u8::from(self.halt_all_on_halt)
    }

    /// The options of `bits`, if it sets no bit version 3 does not know.
    pub fn from_bits(bits: u8) -> Option<Self> {
        (bits <= 1).then_some(Self {
            halt_all_on_halt: bits == 1,
        })
    }
}

/// What `IDENTIFY`'s `debug` byte says about debugging on the target (version 3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct DebugStatus {
    /// Bit 0: a debug session exists.
    pub session: bool,
    /// Bit 1: at least one task is halted.
    pub halted: bool,
    /// Bit 2: the session lingers without a connection.
    pub lingering: bool,
    /// Bit 3: debugging is switched off on this runtime (`--debug off`).
    pub switched_off: bool,
}

impl DebugStatus {
    /// The byte on the wire.
    pub fn bits(self) -> u8 {
        u8::from(self.session)
            | u8::from(self.halted) << 1
            | u8::from(self.lingering) << 2
            | u8::from(self.switched_off) << 3
    }

    /// The status of `bits`; bits a later version may add are ignored, as they only inform.
    pub fn from_bits(bits: u8) -> Self {
        Self {
            session: bits & 1 != 0,
            halted: bits & 2 != 0,
            lingering: bits & 4 != 0,
            switched_off: bits & 8 != 0,
        }
    }
}

/// Which cycle's flow bitmap `FLOW_READ` reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum FlowCycle {
    /// The last complete cycle.
    LastComplete = 0,
    /// The current cycle so far (what a halted task has done).
    Current = 1,
}

impl FlowCycle {
    /// Every choice, in the order of their numbers.
    pub const ALL: [FlowCycle; 2] = [FlowCycle::LastComplete, FlowCycle::Current];
}

/// Bytes of a frame: an offset from the frame's start and a size (`FRAME_READ`, `FRAME_WRITE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FrameRange {
    /// Bytes from the frame's start (or the stack's, with [`crate::WHOLE_STACK`]).
    pub offset: u32,
    /// How many bytes.
    pub size: u16,
}

/// A POU whose statements `FLOW_CONFIGURE` records, on one instance or every one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FlowEntry {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// The instance as a pointer value (`docs/program-image.md` §5.2); 0 for every instance.
    pub instance: u64,
}

/// A breakpoint as `BREAK_SET` sets it: a statement start with its filters.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BreakpointSpec {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// The instruction index where the statement starts.
    pub instruction: u32,
    /// The instance it halts on as a pointer value; 0 for any.
    pub instance: u64,
    /// The task it halts; [`crate::ALL_TASKS`] for any.
    pub task: u8,
    /// When a hit halts.
    pub hit: HitRule,
    /// The compiled condition: a postcard-encoded `program_image::BreakCondition`, empty for
    /// none; at most [`crate::MAX_CONDITION_BYTES`] fit the frame.
    pub condition: Vec<u8>,
}
