//! One breakpoint of the debug session (`docs/protocol.md` §6.2, "Breakpoints"): a statement
//! start with its instance and task filters, its hit count and mode, and its condition
//! lowered to the engine's own form.

use std::sync::Arc;

use crate::engine::lower::Op;

/// When a hit halts the task, CODESYS's four choices (`hit_mode` on the wire).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HitMode {
    /// Every hit halts (0).
    Always,
    /// The hit whose count equals the target halts (1).
    Equal,
    /// Every hit whose count is a multiple of the target halts (2).
    Multiple,
    /// Every hit from the target's on halts (3).
    AtLeast,
}

impl HitMode {
    /// The mode numbered `code` on the wire.
    pub fn from_code(code: u8) -> Option<Self> {
        Some(match code {
            0 => Self::Always,
            1 => Self::Equal,
            2 => Self::Multiple,
            3 => Self::AtLeast,
            _ => return None,
        })
    }

    /// Its number on the wire.
    pub fn code(self) -> u8 {
        match self {
            Self::Always => 0,
            Self::Equal => 1,
            Self::Multiple => 2,
            Self::AtLeast => 3,
        }
    }

    /// Whether the hit numbered `hits` (1 for the first) halts with `target`.
    pub fn halts(self, hits: u32, target: u32) -> bool {
        match self {
            Self::Always => true,
            Self::Equal => hits == target,
            Self::Multiple => target > 0 && hits.is_multiple_of(target),
            Self::AtLeast => hits >= target,
        }
    }
}

/// What a client asks for in `BREAK_SET`, before the runtime checks it.
#[derive(Clone, Debug, PartialEq)]
pub struct BreakpointSpec {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// The statement start's instruction index in that POU.
    pub instruction: u32,
    /// The instance as a pointer value (`docs/program-image.md` §5.2); 0 for any.
    pub instance: u64,
    /// The only task that halts there; `None` for any.
    pub task: Option<u8>,
    /// When a hit halts.
    pub hit_mode: HitMode,
    /// The count the mode compares with; at least 1 unless the mode is [`HitMode::Always`].
    pub hit_target: u32,
    /// The compiled condition, postcard-encoded (`program_image::BreakCondition`); empty
    /// for none.
    pub condition: Vec<u8>,
}

/// A condition ready to run: its instructions lowered, its scratch area's size and contents.
pub(crate) struct LoweredCondition {
    pub(crate) ops: Vec<Op>,
    pub(crate) scratch_bytes: usize,
    pub(crate) init: Vec<u8>,
    pub(crate) result: usize,
}

/// A breakpoint as the session holds it.
#[derive(Clone)]
pub struct Breakpoint {
    /// Its id, given by the runtime, never 0xFFFF.
    pub id: u16,
    /// What was asked for (the condition's bytes as they came).
    pub spec: BreakpointSpec,
    /// Hits since it was set.
    pub hits: u32,
    /// The condition, shared so a copy of the breakpoint copies no code; lent out of the
    /// breakpoint while it runs.
    pub(crate) condition: Option<Arc<LoweredCondition>>,
}

impl std::fmt::Debug for Breakpoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Breakpoint")
            .field("id", &self.id)
            .field("spec", &self.spec)
            .field("hits", &self.hits)
            .finish()
    }
}

impl Breakpoint {
    /// Whether it has a condition.
    pub fn conditional(&self) -> bool {
        self.condition.is_some()
    }

    /// Whether task `task` running on the instance whose pointer value is `instance` reaches
    /// it (before its condition).
    pub(crate) fn accepts(&self, task: usize, instance: u64) -> bool {
        self.spec.task.is_none_or(|only| usize::from(only) == task)
            && (self.spec.instance == 0 || self.spec.instance == instance)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_four_hit_modes_halt_on_the_hits_codesys_names() {
        let halting = |mode: HitMode, target| -> Vec<u32> {
            (1..=7).filter(|&hits| mode.halts(hits, target)).collect()
        };
        assert_eq!(halting(HitMode::Always, 0), vec![1, 2, 3, 4, 5, 6, 7]);
        assert_eq!(halting(HitMode::Equal, 3), vec![3]);
        assert_eq!(halting(HitMode::Multiple, 3), vec![3, 6]);
        assert_eq!(halting(HitMode::AtLeast, 5), vec![5, 6, 7]);
        for code in 0..4 {
            assert_eq!(HitMode::from_code(code).map(HitMode::code), Some(code));
        }
        assert_eq!(HitMode::from_code(4), None);
    }
}
