//! The answers of online change (`docs/protocol.md` §7, version 3): the check's verdict and
//! counts, the details the user reads, and what the switch did.

use crate::error::DecodeError;
use crate::reader::Reader;
use crate::writer::{first, put_str8};

/// `ONLINE_CHANGE_CHECK`'s answer: whether the change is possible, why not, and its counts.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ChangeCheck {
    /// Whether the change can be applied.
    pub possible: bool,
    /// Why not (`docs/protocol.md` §7's table), 0 when possible.
    pub reason: u8,
    /// POUs whose code changed.
    pub pous_changed: u16,
    /// POUs added.
    pub pous_added: u16,
    /// POUs removed.
    pub pous_removed: u16,
    /// Variables whose values are carried over.
    pub carried: u32,
    /// Variables added.
    pub added: u32,
    /// Variables removed.
    pub removed: u32,
    /// Variables reinitialised because their type changed.
    pub reinitialised: u32,
    /// Pointers moved to their target's new place.
    pub pointers_moved: u32,
    /// Pointers that will be set to 0.
    pub pointers_cleared: u32,
    /// Forces that will be released.
    pub forces_released: u16,
    /// How many details `ONLINE_CHANGE_DETAILS` lists.
    pub details: u16,
    /// Why not, in words, with the first difference found; empty when possible.
    pub why: String,
}

/// One detail of `ONLINE_CHANGE_DETAILS`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChangeDetailEntry {
    /// 0 POU changed, 1 POU added, 2 POU removed, 3 variable added, 4 variable removed,
    /// 5 variable reinitialised, 6 pointer cleared, 7 force released, 8 trace removed,
    /// 9 motion block instance dropped.
    pub kind: u8,
    /// The POU's name or the variable's path.
    pub name: String,
}

/// `ONLINE_CHANGE_APPLY`'s answer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChangeApplied {
    /// Cycles run by all tasks before the switch.
    pub cycles: u64,
    /// Variables whose values were carried over.
    pub carried: u32,
    /// Whether RETAIN or PERSISTENT values were carried over.
    pub retained: bool,
    /// How long no task could start, in microseconds.
    pub switch_us: u32,
}

/// The largest detail kind.
pub const MAX_DETAIL_KIND: u8 = 9;

impl ChangeCheck {
    pub(crate) fn encode(&self, out: &mut Vec<u8>) {
        out.push(u8::from(self.possible));
        out.push(self.reason);
        for count in [self.pous_changed, self.pous_added, self.pous_removed] {
            out.extend_from_slice(&count.to_le_bytes());
        }
        for count in [
            self.carried,
            self.added,
            self.removed,
            self.reinitialised,
            self.pointers_moved,
            self.pointers_cleared,
        ] {
            out.extend_from_slice(&count.to_le_bytes());
        }
        out.extend_from_slice(&self.forces_released.to_le_bytes());
        out.extend_from_slice(&self.details.to_le_bytes());
        put_str8(out, &self.why);
    }

    pub(crate) fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(Self {
            possible: r.flag("possible")?,
            reason: r.u8("reason")?,
            pous_changed: r.u16("POUs changed")?,
            pous_added: r.u16("POUs added")?,
            pous_removed: r.u16("POUs removed")?,
            carried: r.u32("carried")?,
            added: r.u32("added")?,
            removed: r.u32("removed")?,
            reinitialised: r.u32("reinitialised")?,
            pointers_moved: r.u32("pointers moved")?,
            pointers_cleared: r.u32("pointers cleared")?,
            forces_released: r.u16("forces released")?,
            details: r.u16("details")?,
            why: r.str8("why")?,
        })
    }
}

impl ChangeDetailEntry {
    /// The bytes this detail takes in a response.
    pub fn wire_bytes(&self) -> usize {
        2 + self.name.len().min(crate::framing::MAX_STR8_BYTES)
    }
}

/// Appends `total:u16`, `count:u8` and the details.
pub(crate) fn put_details(out: &mut Vec<u8>, total: u16, details: &[ChangeDetailEntry]) {
    out.extend_from_slice(&total.to_le_bytes());
    let details = first(details);
    out.push(details.len() as u8);
    for detail in details {
        out.push(detail.kind);
        put_str8(out, &detail.name);
    }
}

/// Reads what [`put_details`] wrote.
pub(crate) fn details(r: &mut Reader<'_>) -> Result<(u16, Vec<ChangeDetailEntry>), DecodeError> {
    let total = r.u16("total")?;
    let count = r.u8("count")?;
    let mut details = Vec::with_capacity(usize::from(count));
    for _ in 0..count {
        let kinds: Vec<u8> = (0..=MAX_DETAIL_KIND).collect();
        details.push(ChangeDetailEntry {
            kind: r.choice("detail kind", &kinds, "0 to 9")?,
            name: r.str8("name")?,
        });
    }
    Ok((total, details))
}

impl ChangeApplied {
    pub(crate) fn encode(&self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.cycles.to_le_bytes());
        out.extend_from_slice(&self.carried.to_le_bytes());
        out.push(u8::from(self.retained));
        out.extend_from_slice(&self.switch_us.to_le_bytes());
    }

    pub(crate) fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(Self {
            cycles: r.u64("cycles")?,
            carried: r.u32("carried")?,
            retained: r.flag("retained")?,
            switch_us: r.u32("switch time")?,
        })
    }
}
