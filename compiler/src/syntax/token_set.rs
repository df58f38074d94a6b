//! Sets of token kinds, for lookahead and error recovery.

use super::SyntaxKind;

/// A set of kinds as a bit set.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TokenSet([u64; 4]);

impl TokenSet {
    /// The empty set.
    pub const EMPTY: Self = Self([0; 4]);

    /// A set of the given kinds.
    pub const fn new(kinds: &[SyntaxKind]) -> Self {
        let mut bits = [0u64; 4];
        let mut index = 0;
        while index < kinds.len() {
            let kind = kinds[index] as usize;
            bits[kind / 64] |= 1 << (kind % 64);
            index += 1;
        }
        Self(bits)
    }

    /// The union of two sets.
    pub const fn union(self, other: Self) -> Self {
        Self([
            self.0[0] | other.0[0],
            self.0[1] | other.0[1],
            self.0[2] | other.0[2],
            self.0[3] | other.0[3],
        ])
    }

    /// Whether `kind` is in the set.
    pub const fn contains(self, kind: SyntaxKind) -> bool {
        let kind = kind as usize;
        kind / 64 < 4 && self.0[kind / 64] & (1 << (kind % 64)) != 0
    }
}
