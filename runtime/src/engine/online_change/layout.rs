//! Matching the running program's variables with the new program's, by path and type: which
//! bytes are copied where, which pointers are moved, and what is added, removed or
//! reinitialised (`docs/protocol.md` §7).

use std::collections::{HashMap, HashSet};

use program_image::{ProgramImage, Region, SymbolFlags, TypeDef, TypeId};

use super::super::carry::same_type;
use super::{ChangeDetail, DetailKind};

/// Bytes of the old data region copied unchanged to the new one.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Segment {
    /// Where the bytes are in the old data region.
    pub old: usize,
    /// Where they go in the new one.
    pub new: usize,
    /// How many bytes.
    pub length: usize,
}

/// What a pointer-like variable holds besides its address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SlotKind {
    /// `POINTER TO`, `REFERENCE TO` or a `VAR_IN_OUT`: 8 bytes.
    Pointer,
    /// An interface value: the instance's address, then its function block's POU index.
    Interface,
    /// An open array's descriptor: the address, then `rank` pairs of bounds, copied as they are.
    OpenArray {
        /// The number of dimensions.
        rank: usize,
    },
}

/// A pointer-like variable kept by path: its address is moved at the switch.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct PointerSlot {
    /// Its offset in the old data region.
    pub old: usize,
    /// Its offset in the new one.
    pub new: usize,
    /// What it holds besides the address.
    pub kind: SlotKind,
    /// Its path, for the details.
    pub path: String,
}

/// What the walk over the two programs' variables found.
#[derive(Debug, Default)]
pub(super) struct Matching {
    /// The bytes copied, sorted by their old offset, adjacent ones joined.
    pub segments: Vec<Segment>,
    /// The pointer-like variables kept.
    pub slots: Vec<PointerSlot>,
    /// The starts of structures and instances of the same name carried member by member
    /// (their type changed): old offset to new, sorted by the old. A pointer to such an
    /// instance (an interface value, a reference) and the motion blocks kept for it follow
    /// it there.
    pub anchors: Vec<(usize, usize)>,
    /// Variables added, removed and reinitialised.
    pub details: Vec<ChangeDetail>,
    /// Variables whose values are carried (a whole variable of the same type counts once).
    pub carried: u32,
    /// Of those, the ones that lie in a RETAIN or PERSISTENT range of the new program.
    pub retained: u32,
}

/// How deep types may nest before the walk gives up on a variable (and reinitialises it);
/// the verifier refuses cycles, so this only bounds hostile but verified tables.
const MAX_DEPTH: u32 = 32;

/// Matches every variable of `new`'s data region with `old`'s by path and type.
pub(super) fn match_variables(old: &ProgramImage, new: &ProgramImage) -> Matching {
    let mut walk = Walk {
        old,
        new,
        found: Matching::default(),
    };
    let old_roots = roots(old);
    let new_roots = roots(new);
    // Paths compare without case, as IEC 61131-3 names do.
    let by_path = |image: &'_ ProgramImage, roots: &[usize]| -> HashMap<String, usize> {
        roots
            .iter()
            .map(|&index| (image.symbols[index].path.to_ascii_lowercase(), index))
            .collect()
    };
    let (old_by_path, new_by_path) = (by_path(old, &old_roots), by_path(new, &new_roots));
    for &index in &new_roots {
        let symbol = &new.symbols[index];
        let previous = old_by_path
            .get(&symbol.path.to_ascii_lowercase())
            .map(|&i| &old.symbols[i]);
        match previous {
            Some(previous) if !symbol.flags.has(SymbolFlags::CONSTANT) => walk.variable(
                previous.ty,
                previous.offset as usize,
                symbol.ty,
                symbol.offset as usize,
                &symbol.path,
                0,
            ),
            Some(_) => {}
            None => walk.note(DetailKind::VariableAdded, &symbol.path),
        }
    }
    for &index in &old_roots {
        let symbol = &old.symbols[index];
        if !new_by_path.contains_key(&symbol.path.to_ascii_lowercase()) {
            walk.note(DetailKind::VariableRemoved, &symbol.path);
        }
    }
    let mut found = walk.found;
    found.segments = merged(found.segments);
    found.anchors.sort_unstable();
    found
}

/// The data-region symbols no other symbol contains: globals and program instances (the
/// members inside them are reached through the type table).
fn roots(image: &ProgramImage) -> Vec<usize> {
    let paths: HashSet<String> = image
        .symbols
        .iter()
        .filter(|s| s.region == Region::Data)
        .map(|s| s.path.to_ascii_lowercase())
        .collect();
    image
        .symbols
        .iter()
        .enumerate()
        .filter(|(_, s)| s.region == Region::Data)
        .filter(|(_, s)| {
            let lower = s.path.to_ascii_lowercase();
            let mut parent = lower.as_str();
            while let Some((head, _)) = parent.rsplit_once('.') {
                if paths.contains(head) {
                    return false;
                }
                parent = head;
            }
            true
        })
        .map(|(index, _)| index)
        .collect()
}

/// Sorts segments by their old offset and joins those that follow each other in both regions.
fn merged(mut segments: Vec<Segment>) -> Vec<Segment> {
    segments.sort_by_key(|s| s.old);
    let mut joined: Vec<Segment> = Vec::with_capacity(segments.len());
    for segment in segments {
        match joined.last_mut() {
            Some(last)
                if last.old + last.length == segment.old
                    && last.new + last.length == segment.new =>
            {
                last.length += segment.length;
            }
            _ => joined.push(segment),
        }
    }
    joined
}

struct Walk<'a> {
    old: &'a ProgramImage,
    new: &'a ProgramImage,
    found: Matching,
}

impl Walk<'_> {
    /// Matches the variable at `old_at` of type `old_ty` with the one at `new_at` of `new_ty`,
    /// both named `path`.
    fn variable(
        &mut self,
        old_ty: TypeId,
        old_at: usize,
        new_ty: TypeId,
        new_at: usize,
        path: &str,
        depth: u32,
    ) {
        let (Some(before), Some(after)) = (
            self.old.types.get(old_ty as usize),
            self.new.types.get(new_ty as usize),
        ) else {
            return self.note(DetailKind::VariableReinitialised, path);
        };
        if depth > MAX_DEPTH {
            return self.note(DetailKind::VariableReinitialised, path);
        }
        if same_type(self.old, old_ty, self.new, new_ty, 0) {
            let length = after.size_bytes(&self.new.types) as usize;
            self.found.segments.push(Segment {
                old: old_at,
                new: new_at,
                length,
            });
            self.found.carried += 1;
            if self.retained(new_at, length) {
                self.found.retained += 1;
            }
            return;
        }
        match (before, after) {
            (
                TypeDef::Struct {
                    members: old_members,
                    name: old_name,
                    ..
                },
                TypeDef::Struct { members, name, .. },
            ) => {
                if old_name.eq_ignore_ascii_case(name) {
                    self.found.anchors.push((old_at, new_at));
                }
                for member in members {
                    if member.located.is_some() {
                        continue;
                    }
                    let member_path = format!("{path}.{}", member.name);
                    let previous = old_members
                        .iter()
                        .find(|m| m.located.is_none() && m.name.eq_ignore_ascii_case(&member.name));
                    match previous {
                        None => self.note(DetailKind::VariableAdded, &member_path),
                        Some(_) if SymbolFlags(member.flags).has(SymbolFlags::CONSTANT) => {}
                        Some(previous) => self.variable(
                            previous.ty,
                            old_at + previous.offset as usize,
                            member.ty,
                            new_at + member.offset as usize,
                            &member_path,
                            depth + 1,
                        ),
                    }
                }
                for previous in old_members {
                    if previous.located.is_none()
                        && !members.iter().any(|m| {
                            m.located.is_none() && m.name.eq_ignore_ascii_case(&previous.name)
                        })
                    {
                        self.note(
                            DetailKind::VariableRemoved,
                            &format!("{path}.{}", previous.name),
                        );
                    }
                }
            }
            (
                TypeDef::Array {
                    element: old_element,
                    dims: old_dims,
                },
                TypeDef::Array { element, dims },
            ) if old_dims == dims => {
                let old_size =
                    self.old
                        .types
                        .get(*old_element as usize)
                        .map_or(0, |t| t.size_bytes(&self.old.types)) as usize;
                let new_size =
                    self.new
                        .types
                        .get(*element as usize)
                        .map_or(0, |t| t.size_bytes(&self.new.types)) as usize;
                let count = dims.iter().fold(1usize, |count, (low, high)| {
                    count.saturating_mul((high - low + 1).max(0) as usize)
                });
                for index in 0..count {
                    self.variable(
                        *old_element,
                        old_at + index * old_size,
                        *element,
                        new_at + index * new_size,
                        &format!("{path}[{}]", subscripts(dims, index)),
                        depth + 1,
                    );
                }
            }
            (
                TypeDef::Pointer {
                    reference: old_reference,
                    ..
                },
                TypeDef::Pointer { reference, .. },
            ) if old_reference == reference => self.slot(old_at, new_at, SlotKind::Pointer, path),
            (TypeDef::Interface { name: old_name }, TypeDef::Interface { name })
                if old_name.eq_ignore_ascii_case(name) =>
            {
                self.slot(old_at, new_at, SlotKind::Interface, path);
            }
            (
                TypeDef::OpenArray {
                    element: old_element,
                    rank: old_rank,
                },
                TypeDef::OpenArray { element, rank },
            ) if old_rank == rank && same_type(self.old, *old_element, self.new, *element, 0) => {
                let rank = *rank as usize;
                self.slot(old_at, new_at, SlotKind::OpenArray { rank }, path);
            }
            _ => self.note(DetailKind::VariableReinitialised, path),
        }
    }

    fn slot(&mut self, old: usize, new: usize, kind: SlotKind, path: &str) {
        self.found.slots.push(PointerSlot {
            old,
            new,
            kind,
            path: path.to_owned(),
        });
        self.found.carried += 1;
    }

    /// Lists a detail, except about the names the compiler generates (they contain `__`,
    /// which no user name may), which say nothing to the user.
    fn note(&mut self, kind: DetailKind, path: &str) {
        if !path.contains("__") {
            self.found.details.push(ChangeDetail {
                kind,
                name: path.to_owned(),
            });
        }
    }

    /// Whether bytes `at..at + length` of the new data region are RETAIN or PERSISTENT.
    fn retained(&self, at: usize, length: usize) -> bool {
        let retain = &self.new.retain;
        retain
            .retain
            .iter()
            .chain(&retain.persistent)
            .any(|&(offset, size)| {
                let (offset, size) = (offset as usize, size as usize);
                at < offset + size && offset < at + length
            })
    }
}

/// The subscripts of the `index`-th element (first dimension outermost) as "2, 3".
fn subscripts(dims: &[(i64, i64)], mut index: usize) -> String {
    let mut parts = vec![0i64; dims.len()];
    for (part, (low, high)) in parts.iter_mut().zip(dims).rev() {
        let extent = (high - low + 1).max(1) as usize;
        *part = low + (index % extent) as i64;
        index /= extent;
    }
    parts
        .iter()
        .map(i64::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}
