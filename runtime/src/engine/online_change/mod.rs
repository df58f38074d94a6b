//! Online change (`docs/protocol.md` §7, `docs/debugging.md` §6): whether a new image can take
//! over from the running one between two cycles, what the user is shown beforehand, and the
//! plan that carries the values over at the switch.
//!
//! The plan is worked out away from the scheduler's thread ([`OnlineChangePlan::new`]); the
//! switch ([`OnlineChangePlan::apply`]) only copies bytes, moves pointers and hands the motion
//! kernel over, so it holds the tasks for a small part of an interval.

mod layout;
mod verdict;

use std::collections::HashMap;

use program_image::{DebugInfo, ProgramImage, Region};

use super::Engine;
use layout::{Matching, PointerSlot, Segment, SlotKind};

pub use verdict::ChangeRefusal;

/// What a detail of the check is about, with its number on the wire (`kind` of
/// `ONLINE_CHANGE_DETAILS`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum DetailKind {
    /// A POU whose code changed.
    PouChanged = 0,
    /// A POU added.
    PouAdded = 1,
    /// A POU removed.
    PouRemoved = 2,
    /// A variable added: it starts from its initial value.
    VariableAdded = 3,
    /// A variable removed.
    VariableRemoved = 4,
    /// A variable whose type changed: it starts from its initial value.
    VariableReinitialised = 5,
    /// A pointer whose target is gone or changed type: it is set to 0.
    PointerCleared = 6,
    /// A force on a variable that is gone or changed type: it is released.
    ForceReleased = 7,
    /// The trace, one of whose variables is gone or changed type: it is removed.
    TraceRemoved = 8,
    /// A motion block instance that is gone while its axis may move.
    MotionBlockDropped = 9,
}

/// One thing the user reads before applying a change: a POU's name or a variable's path.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChangeDetail {
    /// What it is about.
    pub kind: DetailKind,
    /// The POU's name or the variable's path.
    pub name: String,
}

/// The counts of the check, as `ONLINE_CHANGE_CHECK` sends them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChangeSummary {
    /// POUs whose code changed.
    pub pous_changed: u32,
    /// POUs added.
    pub pous_added: u32,
    /// POUs removed.
    pub pous_removed: u32,
    /// Variables whose values are carried over (a whole variable of the same type once).
    pub carried: u32,
    /// Of those, how many are RETAIN or PERSISTENT in the new program.
    pub retained: u32,
    /// Variables added.
    pub added: u32,
    /// Variables removed.
    pub removed: u32,
    /// Variables reinitialised because their type changed.
    pub reinitialised: u32,
    /// Pointers that will be moved to their target's new place (as the memory is now).
    pub pointers_moved: u32,
    /// Pointers that will be set to 0 (as the memory is now).
    pub pointers_cleared: u32,
}

/// What the switch did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AppliedChange {
    /// Variables whose values were carried over.
    pub carried: u32,
    /// Of those, how many are RETAIN or PERSISTENT in the new program.
    pub retained: u32,
    /// Pointers moved to their target's new place.
    pub pointers_moved: u32,
    /// Pointers set to 0.
    pub pointers_cleared: u32,
    /// Motion block instances dropped because their instance is gone.
    pub motion_blocks_dropped: u32,
}

/// The verdict, the details and the copy plan of an online change from one image to another.
#[derive(Clone, Debug)]
pub struct OnlineChangePlan {
    refusal: Option<(ChangeRefusal, String)>,
    summary: ChangeSummary,
    details: Vec<ChangeDetail>,
    segments: Vec<Segment>,
    slots: Vec<PointerSlot>,
    anchors: Vec<(usize, usize)>,
    /// For each POU index of the old image, the index of the POU of the same name in the new
    /// one (the class of an interface value).
    classes: Vec<Option<u32>>,
}

/// What becomes of a pointer's value at the switch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PointerFate {
    /// Null, or into a located area (the areas do not move): kept as it is.
    Kept(u64),
    /// Into the data region, where its target keeps its path and type: moved there.
    Moved(u64),
    /// Its target is gone or changed type, or it points into a stack or the constants: 0.
    Cleared,
}

const REGION_SHIFT: u32 = 56;
const OFFSET_MASK: u64 = (1 << REGION_SHIFT) - 1;
const POINTER_NULL: u64 = 0;
const POINTER_DATA: u64 = 1;
const POINTER_INPUT: u64 = 3;
const POINTER_MEMORY: u64 = 5;

impl OnlineChangePlan {
    /// Compares the running image `old` (whose data region holds `old_data` now, for the
    /// pointers' fates) with the new image `new`.
    pub fn new(old: &ProgramImage, old_data: &[u8], new: &ProgramImage) -> Self {
        let refusal = verdict::refusal(old, new);
        let Matching {
            segments,
            slots,
            anchors,
            details: variable_details,
            carried,
            retained,
        } = layout::match_variables(old, new);
        let mut details = pou_details(old, new);
        details.extend(variable_details);
        let classes = old
            .pous
            .iter()
            .map(|pou| {
                new.pous
                    .iter()
                    .position(|p| p.name.eq_ignore_ascii_case(&pou.name))
                    .map(|index| index as u32)
            })
            .collect();
        let mut plan = Self {
            refusal,
            summary: ChangeSummary {
                carried,
                retained,
                ..ChangeSummary::default()
            },
            details,
            segments,
            slots,
            anchors,
            classes,
        };
        let mut cleared = Vec::new();
        for slot in &plan.slots {
            match plan.fate(read_u64(old_data, slot.old)) {
                PointerFate::Moved(_) => plan.summary.pointers_moved += 1,
                PointerFate::Cleared => cleared.push(ChangeDetail {
                    kind: DetailKind::PointerCleared,
                    name: slot.path.clone(),
                }),
                PointerFate::Kept(_) => {}
            }
        }
        plan.summary.pointers_cleared = cleared.len() as u32;
        plan.details.extend(cleared);
        plan.details.sort_by_key(|detail| detail.kind);
        let count = |kind| plan.details.iter().filter(|d| d.kind == kind).count() as u32;
        plan.summary.pous_changed = count(DetailKind::PouChanged);
        plan.summary.pous_added = count(DetailKind::PouAdded);
        plan.summary.pous_removed = count(DetailKind::PouRemoved);
        plan.summary.added = count(DetailKind::VariableAdded);
        plan.summary.removed = count(DetailKind::VariableRemoved);
        plan.summary.reinitialised = count(DetailKind::VariableReinitialised);
        plan
    }

    /// Why the change is impossible, in words with the first difference found; `None` when
    /// it is possible.
    pub fn refusal(&self) -> Option<(ChangeRefusal, &str)> {
        self.refusal
            .as_ref()
            .map(|(reason, why)| (*reason, why.as_str()))
    }

    /// The counts the user is shown.
    pub fn summary(&self) -> ChangeSummary {
        self.summary
    }

    /// What the user reads before applying, in the order of [`DetailKind`].
    pub fn details(&self) -> &[ChangeDetail] {
        &self.details
    }

    /// Adds a detail found outside the programs (a force, the trace, a motion block).
    pub fn add_detail(&mut self, kind: DetailKind, name: String) {
        self.details.push(ChangeDetail { kind, name });
        self.details.sort_by_key(|detail| detail.kind);
    }

    /// Where the `length` bytes at `offset` of the old data region are in the new one, when
    /// they all belong to one variable that is carried whole (a force or a trace place
    /// follows its variable that way); `None` when it is gone or changed type.
    pub fn moved_range(&self, offset: usize, length: usize) -> Option<usize> {
        let at = self.segments.partition_point(|s| s.old <= offset);
        let segment = self.segments.get(at.checked_sub(1)?)?;
        (offset + length <= segment.old + segment.length)
            .then(|| segment.new + (offset - segment.old))
    }

    /// Where the data byte at `offset` of the old program is in the new one: inside a
    /// variable carried whole, or the start of a structure or instance carried member by
    /// member (what a pointer to it, or a motion block kept for it, follows).
    pub fn moved_byte(&self, offset: usize) -> Option<usize> {
        self.moved_range(offset, 1).or_else(|| {
            self.anchors
                .binary_search_by_key(&offset, |&(old, _)| old)
                .ok()
                .map(|index| self.anchors[index].1)
        })
    }

    /// Carries `old`'s values into `new` by the plan: copies the bytes of the variables that
    /// kept their path and type, moves pointers by their current values, and hands `old`'s
    /// motion kernel (axes, motion and the blocks' commands) to `new`. `new` must have been
    /// loaded from the image the plan was made for, and `old` from the running one; the
    /// located areas are the caller's (they do not move). `old` is left without its motion
    /// kernel; it is borrowed, not taken, so the caller can drop it where freeing its code
    /// holds no task.
    pub fn apply(&self, old: &mut Engine, new: &mut Engine) -> AppliedChange {
        let old_data = old.region(Region::Data);
        let mut applied = AppliedChange {
            carried: self.summary.carried,
            retained: self.summary.retained,
            ..AppliedChange::default()
        };
        let mut writes: Vec<(usize, [u8; 8])> = Vec::new();
        let mut cleared: Vec<(usize, usize)> = Vec::new();
        for slot in &self.slots {
            let fate = self.fate(read_u64(old_data, slot.old));
            let class = match slot.kind {
                SlotKind::Interface => {
                    let old_class = read_u64(old_data, slot.old + 8) as u32;
                    self.classes.get(old_class as usize).copied().flatten()
                }
                _ => None,
            };
            let value = match (fate, slot.kind) {
                (PointerFate::Cleared, _) => None,
                (PointerFate::Kept(POINTER_NULL), SlotKind::Interface) => Some(0),
                (_, SlotKind::Interface) if class.is_none() => None,
                (PointerFate::Kept(value) | PointerFate::Moved(value), _) => Some(value),
            };
            let length = match slot.kind {
                SlotKind::Pointer => 8,
                SlotKind::Interface => 16,
                SlotKind::OpenArray { rank } => 8 + 16 * rank,
            };
            match value {
                Some(value) => {
                    if matches!(fate, PointerFate::Moved(_)) {
                        applied.pointers_moved += 1;
                    }
                    writes.push((slot.new, value.to_le_bytes()));
                    match slot.kind {
                        SlotKind::Interface => {
                            let class = u64::from(class.unwrap_or(0));
                            writes.push((slot.new + 8, class.to_le_bytes()));
                        }
                        SlotKind::OpenArray { rank } => {
                            // The bounds are copied as they are, 8 bytes at a time.
                            for part in 0..2 * rank {
                                let at = 8 + 8 * part;
                                let bound = read_u64(old_data, slot.old + at);
                                writes.push((slot.new + at, bound.to_le_bytes()));
                            }
                        }
                        SlotKind::Pointer => {}
                    }
                }
                None => {
                    applied.pointers_cleared += 1;
                    cleared.push((slot.new, length));
                }
            }
        }
        let data = new.region_mut(Region::Data);
        for segment in &self.segments {
            if let (Some(from), Some(to)) = (
                old_data.get(segment.old..segment.old + segment.length),
                data.get_mut(segment.new..segment.new + segment.length),
            ) {
                to.copy_from_slice(from);
            }
        }
        for (at, bytes) in &writes {
            if let Some(place) = data.get_mut(*at..*at + bytes.len()) {
                place.copy_from_slice(bytes);
            }
        }
        for (at, length) in cleared {
            if let Some(place) = data.get_mut(at..at + length) {
                place.fill(0);
            }
        }
        let (old_base, new_base) = (old.regions.data, new.regions.data);
        let dropped = new.motion.carry_from(&mut old.motion, |instance| {
            let offset = instance.checked_sub(old_base)?;
            self.moved_byte(offset).map(|at| at + new_base)
        });
        applied.motion_blocks_dropped = dropped as u32;
        applied
    }

    /// What becomes of a pointer holding `value` at the switch.
    fn fate(&self, value: u64) -> PointerFate {
        let region = value >> REGION_SHIFT;
        let offset = value & OFFSET_MASK;
        match region {
            POINTER_NULL => PointerFate::Kept(value),
            POINTER_DATA => match self.moved_byte(offset as usize) {
                Some(at) => PointerFate::Moved(POINTER_DATA << REGION_SHIFT | at as u64),
                None => PointerFate::Cleared,
            },
            POINTER_INPUT..=POINTER_MEMORY => PointerFate::Kept(value),
            _ => PointerFate::Cleared,
        }
    }
}

/// The POUs changed, added and removed, by name. When both images carry a `debug` section, a
/// POU counts as changed when its source hash differs: adding a global moves the addresses in
/// nearly every POU's code, and the user is to read the POUs they edited, not those whose
/// code was generated again around moved variables (which are replaced all the same). Without
/// both sections a POU counts as changed when its instructions or its frame differ.
fn pou_details(old: &ProgramImage, new: &ProgramImage) -> Vec<ChangeDetail> {
    let by_name = |image: &ProgramImage| -> HashMap<String, usize> {
        image
            .pous
            .iter()
            .enumerate()
            .map(|(index, pou)| (pou.name.to_ascii_lowercase(), index))
            .collect()
    };
    let (old_names, new_names) = (by_name(old), by_name(new));
    let hashes = match (&old.debug, &new.debug) {
        (Some(before), Some(after)) => Some((before, after)),
        _ => None,
    };
    let mut details = Vec::new();
    for (index, pou) in new.pous.iter().enumerate() {
        let detail = |kind| ChangeDetail {
            kind,
            name: pou.name.clone(),
        };
        let Some(&old_index) = old_names.get(&pou.name.to_ascii_lowercase()) else {
            details.push(detail(DetailKind::PouAdded));
            continue;
        };
        let before = &old.pous[old_index];
        let changed = match hashes {
            Some((before_debug, after_debug)) => {
                let hash = |debug: &DebugInfo, at: usize| debug.pous.get(at).map(|p| p.source_hash);
                hash(before_debug, old_index) != hash(after_debug, index)
            }
            None => {
                before.code != pou.code
                    || before.frame_size != pou.frame_size
                    || before.frame_init != pou.frame_init
            }
        };
        if changed {
            details.push(detail(DetailKind::PouChanged));
        }
    }
    for pou in &old.pous {
        if !new_names.contains_key(&pou.name.to_ascii_lowercase()) {
            details.push(ChangeDetail {
                kind: DetailKind::PouRemoved,
                name: pou.name.clone(),
            });
        }
    }
    details
}

/// The little-endian `u64` at `at`, 0 where `bytes` ends before.
fn read_u64(bytes: &[u8], at: usize) -> u64 {
    bytes
        .get(at..at + 8)
        .and_then(|b| b.try_into().ok())
        .map_or(0, u64::from_le_bytes)
}

#[cfg(test)]
mod tests;
