//! A breakpoint's compiled condition (`docs/protocol.md` §6.2, "Conditions"): code that runs
//! at the breakpoint's statement with the bases of its POU, reads what the POU sees and
//! writes only a scratch area after the POU's frame, so it can neither change the program
//! nor run long.

use serde::{Deserialize, Serialize};

use crate::ProgramImage;
use crate::code::{Instr, Operand, StdFunction};
use crate::image::Pou;

/// A compiled breakpoint condition, postcard-encoded in `BREAK_SET` as the image's sections
/// are. Its temporaries, constants and result live in a scratch area of `scratch_bytes` right
/// after the POU's frame (frame offsets `frame_size ..`), which `init` fills before each run.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BreakCondition {
    /// The bytes of the scratch area.
    pub scratch_bytes: u32,
    /// The scratch area's first bytes, written before each run (at most `scratch_bytes`); the
    /// bytes after them hold whatever the stack held, so only temporaries live there.
    pub init: Vec<u8>,
    /// The instructions: only those [`BreakCondition::allows`] allows, jumping only forward.
    pub code: Vec<Instr>,
    /// The frame offset of the BOOL result, inside the scratch area.
    pub result: u32,
}

/// Why a condition is refused; the runtime answers `BREAK_SET` with status 2 and this text.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ConditionError {
    /// The bytes are not a postcard-encoded [`BreakCondition`].
    #[error("the condition does not decode: {0}")]
    Malformed(String),
    /// The breakpoint's POU does not exist.
    #[error("the condition is for POU {0}, which the image does not have")]
    UnknownPou(u32),
    /// The scratch area, its initial bytes or the result do not fit.
    #[error("the condition's scratch area is wrong: {0}")]
    Scratch(String),
    /// An instruction the verifier refuses.
    #[error("instruction {instruction} of the condition: {reason}")]
    Refused {
        /// Its index in the condition's code.
        instruction: usize,
        /// Why.
        reason: String,
    },
}

impl BreakCondition {
    /// The condition as `BREAK_SET` carries it.
    pub fn encode(&self) -> Vec<u8> {
        // Serialising plain data to a vector cannot fail; an empty encoding would be refused
        // when decoded, so a failure here could never set a condition.
        postcard::to_allocvec(self).unwrap_or_default()
    }

    /// The condition in `bytes`, which it must use exactly.
    pub fn decode(bytes: &[u8]) -> Result<Self, ConditionError> {
        match postcard::take_from_bytes::<Self>(bytes) {
            Ok((condition, [])) => Ok(condition),
            Ok((_, rest)) => Err(ConditionError::Malformed(format!(
                "{} bytes left over",
                rest.len()
            ))),
            Err(error) => Err(ConditionError::Malformed(error.to_string())),
        }
    }

    /// Whether a condition may use `instr`: instructions 0–15, 20, 22, 23, 25, 26, 28 and 29
    /// of `docs/program-image.md` §7.1 (no calls of POUs or blocks, no `Store` or
    /// `StoreElement`, no `Return`, no `Native`).
    pub fn allows(instr: &Instr) -> bool {
        !matches!(
            instr,
            Instr::Store { .. }
                | Instr::StoreElement { .. }
                | Instr::CallFunction { .. }
                | Instr::CallBlock { .. }
                | Instr::CallStdBlock { .. }
                | Instr::Return
                | Instr::CallVirtual { .. }
                | Instr::Native { .. }
        )
    }
}

impl ProgramImage {
    /// Checks `condition` for a breakpoint in POU `pou` as the runtime must before setting it:
    /// the code passes the image's verifier in the POU's scope with the frame grown by the
    /// scratch area, uses only the allowed instructions, jumps only forward, writes only its
    /// scratch area, and its result is a byte of that area.
    pub fn verify_condition(
        &self,
        pou: u32,
        condition: &BreakCondition,
    ) -> Result<(), ConditionError> {
        let owner = self
            .pous
            .get(pou as usize)
            .ok_or(ConditionError::UnknownPou(pou))?;
        let scratch_start = u64::from(owner.frame_size);
        let scratch_end = scratch_start + u64::from(condition.scratch_bytes);
        if scratch_end > u64::from(self.layout.stack_size) {
            return Err(ConditionError::Scratch(format!(
                "{} bytes after a frame of {} do not fit the stack of {}",
                condition.scratch_bytes, owner.frame_size, self.layout.stack_size
            )));
        }
        if condition.init.len() as u64 > u64::from(condition.scratch_bytes) {
            return Err(ConditionError::Scratch(format!(
                "{} initial bytes for {} bytes",
                condition.init.len(),
                condition.scratch_bytes
            )));
        }
        let result = u64::from(condition.result);
        if result < scratch_start || result + 1 > scratch_end {
            return Err(ConditionError::Scratch(format!(
                "the result at frame offset {result} is outside {scratch_start}..{scratch_end}"
            )));
        }
        for (instruction, instr) in condition.code.iter().enumerate() {
            let refuse = |reason: String| ConditionError::Refused {
                instruction,
                reason,
            };
            if !BreakCondition::allows(instr) {
                return Err(refuse(format!(
                    "{} is not allowed in a condition (no calls, no stores through pointers, no return)",
                    instr_name(instr)
                )));
            }
            if let Some(target) = jump_target(instr)
                && target as usize <= instruction
            {
                return Err(refuse(format!(
                    "jumps back to {target}: a condition jumps only forward"
                )));
            }
            if let Some((dst, size)) = written(instr) {
                let inside = match dst {
                    Operand::Frame(offset) => {
                        u64::from(offset) >= scratch_start
                            && u64::from(offset) + size <= scratch_end
                    }
                    _ => false,
                };
                if !inside {
                    return Err(refuse(format!(
                        "writes {dst:?} ({size} bytes) outside its scratch area (frame offsets {scratch_start}..{scratch_end})"
                    )));
                }
            }
        }
        // The operands, jump targets and kinds of argument are checked as the POU's own code
        // is, in its scope with the frame grown by the scratch area.
        let scope = Pou {
            frame_size: scratch_end as u32,
            frame_init: Vec::new(),
            code: condition.code.clone(),
            lines: Vec::new(),
            ..owner.clone()
        };
        self.verify_code(&scope).map_err(|error| {
            let (instruction, reason) = error.into_instruction_reason();
            ConditionError::Refused {
                instruction,
                reason,
            }
        })
    }
}

/// The target of a jump instruction.
fn jump_target(instr: &Instr) -> Option<u32> {
    match instr {
        Instr::Jump { target } | Instr::JumpIf { target, .. } | Instr::JumpIfNot { target, .. } => {
            Some(*target)
        }
        _ => None,
    }
}

/// The operand an allowed instruction writes and how many bytes.
fn written(instr: &Instr) -> Option<(Operand, u64)> {
    let size = |bytes: u32| u64::from(bytes);
    Some(match instr {
        Instr::Move { ty, dst, .. }
        | Instr::Unary { ty, dst, .. }
        | Instr::Binary { ty, dst, .. } => (*dst, size(ty.size_bytes())),
        Instr::SetBit { ty, dst, .. } => (*dst, size(ty.size_bytes())),
        Instr::Copy {
            size: bytes, dst, ..
        } => (*dst, size(*bytes)),
        Instr::Compare { dst, .. } | Instr::GetBit { dst, .. } => (*dst, 1),
        Instr::Convert { to, dst, .. } | Instr::Trunc { to, dst, .. } => {
            (*dst, size(to.size_bytes()))
        }
        Instr::Address { dst, .. }
        | Instr::Element { dst, .. }
        | Instr::Offset { dst, .. }
        | Instr::OpenElement { dst, .. }
        | Instr::Now { dst } => (*dst, 8),
        Instr::Clock { long, dst } => (*dst, if *long { 8 } else { 4 }),
        Instr::Load {
            size: bytes, dst, ..
        } => (*dst, size(*bytes)),
        Instr::CallStdFunction {
            function,
            wide,
            dst,
            ..
        } => {
            // An integer result is a DINT; a string's is its capacity and terminator, of the
            // other width for a recoded string.
            let unit = if *wide { 2 } else { 1 };
            let bytes = match (dst.1, function) {
                (0, _) => 4,
                (capacity, StdFunction::Recode) => (u64::from(capacity) + 1) * (3 - unit),
                (capacity, _) => (u64::from(capacity) + 1) * unit,
            };
            (dst.0, bytes)
        }
        Instr::ToText {
            wide,
            dst,
            capacity,
            ..
        } => (*dst, (u64::from(*capacity) + 1) * if *wide { 2 } else { 1 }),
        Instr::FromText { to, dst, .. } => (*dst, size(to.size_bytes())),
        Instr::LoadElement { ty, dst, .. } => (*dst, size(ty.size_bytes())),
        _ => return None,
    })
}

/// The instruction's name as `docs/program-image.md` §7.1 spells it.
fn instr_name(instr: &Instr) -> &'static str {
    match instr {
        Instr::Store { .. } => "Store",
        Instr::StoreElement { .. } => "StoreElement",
        Instr::CallFunction { .. } => "CallFunction",
        Instr::CallBlock { .. } => "CallBlock",
        Instr::CallStdBlock { .. } => "CallStdBlock",
        Instr::Return => "Return",
        Instr::CallVirtual { .. } => "CallVirtual",
        Instr::Native { .. } => "Native",
        _ => "this instruction",
    }
}

#[cfg(test)]
#[path = "condition_tests.rs"]
mod tests;
