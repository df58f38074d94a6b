//! Where a variable is on the target, as the protocol sends it (`docs/protocol.md` §3,
//! "Places, monitor, write, force").

use crate::framing::NO_BIT;

/// A place: `region:u8`, `offset:u32`, `bit:u8` (0xFF for none) and `size:u16`.
///
/// A bit place (a located BOOL) has a size of 1 and its value is one byte, 0 or 1. The
/// fields are not checked here: the runtime checks a place against its memory and answers
/// status 5 for a bad one.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Place {
    /// 0 data, 1 `%I`, 2 `%Q`, 3 `%M`.
    pub region: u8,
    /// The byte offset in the region.
    pub offset: u32,
    /// The bit of a located BOOL (0 to 7 when valid), `None` for a whole value; on the wire
    /// `None` is [`NO_BIT`], so `Some(NO_BIT)` cannot be sent.
    pub bit: Option<u8>,
    /// The size of the value in bytes.
    pub size: u16,
}

impl Place {
    /// Appends the place's 8 bytes.
    pub fn encode(&self, out: &mut Vec<u8>) {
        out.push(self.region);
        out.extend_from_slice(&self.offset.to_le_bytes());
        out.push(self.bit.unwrap_or(NO_BIT));
        out.extend_from_slice(&self.size.to_le_bytes());
    }

    /// Whether the place is a single bit.
    pub fn is_bit(&self) -> bool {
        self.bit.is_some()
    }

    /// The bytes its value takes in an answer (`READ`, `FORCES`, a trace sample): one for a
    /// bit, else its size.
    pub fn value_bytes(&self) -> usize {
        if self.is_bit() {
            1
        } else {
            usize::from(self.size)
        }
    }
}
