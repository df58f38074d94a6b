//! A fast hasher for the native blocks' small maps (member names, instance addresses), looked up
//! hundreds of times per cycle: the standard SipHash, built to resist hash flooding by untrusted
//! keys, costs more than the rest of a lookup, and these keys come from the loaded image.

use std::hash::{BuildHasherDefault, Hasher};

/// A multiply-and-rotate hasher over words (the scheme of rustc's FxHasher).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct FastHasher {
    hash: u64,
}

/// The multiplier: an odd constant with well-spread bits.
const SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl FastHasher {
    fn add(&mut self, word: u64) {
        self.hash = (self.hash.rotate_left(5) ^ word).wrapping_mul(SEED);
    }
}

impl Hasher for FastHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for chunk in &mut chunks {
            let mut word = [0u8; 8];
            word.copy_from_slice(chunk);
            self.add(u64::from_le_bytes(word));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut word = [0u8; 8];
            word[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(word));
        }
    }

    fn write_u8(&mut self, value: u8) {
        self.add(u64::from(value));
    }

    fn write_usize(&mut self, value: usize) {
        self.add(value as u64);
    }

    fn finish(&self) -> u64 {
        self.hash
    }
}

/// Builds [`FastHasher`]s for `HashMap`.
pub(super) type FastBuild = BuildHasherDefault<FastHasher>;

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use super::*;

    #[test]
    fn maps_with_the_fast_hasher_find_what_they_hold() {
        let mut map: HashMap<String, u32, FastBuild> = HashMap::default();
        for (index, name) in ["Execute", "Position", "Velocity", "Busy", "Done", "ErrorID"]
            .iter()
            .enumerate()
        {
            map.insert((*name).to_owned(), index as u32);
        }
        assert_eq!(map.get("Velocity"), Some(&2));
        assert_eq!(map.get("ErrorID"), Some(&5));
        assert_eq!(map.get("velocity"), None);
    }
}
