//! The optional `debug` section (`docs/program-image.md` §3, section 13): per POU the hash of
//! its source and the variables of its frame, for the debugger's frame view and for online
//! change to tell changed POUs from moved ones. The runtime never needs it.

use serde::{Deserialize, Serialize};

use crate::encoding::ImageError;
use crate::types::TypeId;
use crate::{ProgramImage, TypeDef};

/// The `debug` section: one entry per POU, in the order of the `code` section.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct DebugInfo {
    /// The POUs' entries, index for index with [`ProgramImage::pous`].
    pub pous: Vec<PouDebug>,
}

/// What the debugger knows of one POU beyond its code.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct PouDebug {
    /// SHA-256 of the POU's declaration and body text as the compiler read them.
    pub source_hash: [u8; 32],
    /// The variables that live in its frame, in the order of their offsets (parameters, the
    /// result, then the others, as `docs/program-image.md` §7 lays a frame out).
    pub frame: Vec<FrameVariable>,
}

/// A variable in a POU's frame: a function's or method's parameter, result or local, or a
/// body's VAR_TEMP.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct FrameVariable {
    /// The declared name.
    pub name: String,
    /// Its type; for [`FrameVariableKind::InOut`] the pointee's, as the frame holds a pointer.
    pub ty: TypeId,
    /// Bytes from the frame's start.
    pub offset: u32,
    /// Which section declared it.
    pub kind: FrameVariableKind,
}

/// Which section declared a frame variable, in the order of their numbers on the wire.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FrameVariableKind {
    /// `VAR_INPUT`.
    Input,
    /// `VAR_OUTPUT`.
    Output,
    /// `VAR_IN_OUT`: the frame holds a pointer to the caller's variable.
    InOut,
    /// The function's or method's result.
    Result,
    /// `VAR`.
    Var,
    /// `VAR_TEMP`.
    Temp,
}

/// The `source_hash` of a POU whose source is `parts` (its declarations and its body, as the
/// compiler read them): SHA-256 over each part's byte length (u64, little-endian) and bytes,
/// so that moving text from one part to the next changes the hash.
pub fn source_hash(parts: &[&str]) -> [u8; 32] {
    use sha2::{Digest, Sha256};
    let mut hasher = Sha256::new();
    for part in parts {
        hasher.update((part.len() as u64).to_le_bytes());
        hasher.update(part.as_bytes());
    }
    hasher.finalize().into()
}

impl FrameVariable {
    /// The bytes it takes in the frame: a pointer for an in-out, else its type's size.
    pub fn size_bytes(&self, types: &[TypeDef]) -> u64 {
        match self.kind {
            FrameVariableKind::InOut => 8,
            _ => types
                .get(self.ty as usize)
                .map_or(0, |ty| ty.size_bytes(types)),
        }
    }
}

impl ProgramImage {
    /// The debug section has one entry per POU, and every frame variable has a type and lies
    /// inside its POU's frame.
    pub(crate) fn verify_debug(&self) -> Result<(), ImageError> {
        let Some(debug) = &self.debug else {
            return Ok(());
        };
        if debug.pous.len() != self.pous.len() {
            return Err(ImageError::Invalid(format!(
                "debug has {} POUs, the code {}",
                debug.pous.len(),
                self.pous.len()
            )));
        }
        for (pou, entry) in self.pous.iter().zip(&debug.pous) {
            for variable in &entry.frame {
                if variable.ty as usize >= self.types.len() {
                    return Err(ImageError::Invalid(format!(
                        "debug: variable '{}' of POU '{}' has no type",
                        variable.name, pou.name
                    )));
                }
                let end = u64::from(variable.offset) + variable.size_bytes(&self.types);
                if end > u64::from(pou.frame_size) {
                    return Err(ImageError::Invalid(format!(
                        "debug: variable '{}' of POU '{}' lies outside its frame of {} bytes",
                        variable.name, pou.name, pou.frame_size
                    )));
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_source_hash_changes_with_the_text_and_with_where_it_is_split() {
        let hash = source_hash(&["VAR x : INT; END_VAR", "x := 1;"]);
        assert_eq!(hash, source_hash(&["VAR x : INT; END_VAR", "x := 1;"]));
        assert_ne!(hash, source_hash(&["VAR x : INT; END_VAR", "x := 2;"]));
        assert_ne!(hash, source_hash(&["VAR x : INT; END_VAR x", " := 1;"]));
        assert_ne!(hash, [0; 32]);
    }

    #[test]
    fn an_in_out_takes_a_pointer_in_the_frame_whatever_its_pointee() {
        let types = [TypeDef::String { length: 80 }];
        let mut variable = FrameVariable {
            name: "s".to_owned(),
            ty: 0,
            offset: 0,
            kind: FrameVariableKind::InOut,
        };
        assert_eq!(variable.size_bytes(&types), 8);
        variable.kind = FrameVariableKind::Var;
        assert_eq!(variable.size_bytes(&types), 81);
    }
}
