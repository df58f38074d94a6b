//! Carrying RETAIN and PERSISTENT values from one program to the next: a variable that keeps
//! its path and its type keeps its value, whatever else changed in the program.

use program_image::{ProgramImage, Region, SymbolFlags, TypeDef, TypeId};

use super::Engine;

/// Copies into `new` the value of every RETAIN or PERSISTENT variable of `new` that `old` has
/// too, under the same path, retained, and of the same type; returns how many were copied.
pub fn carry_retained(old: &Engine, new: &mut Engine) -> usize {
    let (old_image, new_image) = (old.image(), new.image());
    let retained =
        |flags: SymbolFlags| flags.has(SymbolFlags::RETAIN) || flags.has(SymbolFlags::PERSISTENT);
    let mut copies = Vec::new();
    for symbol in new_image
        .symbols
        .iter()
        .filter(|s| retained(s.flags) && s.region == Region::Data)
    {
        let Some(previous) = old_image.symbols.iter().find(|s| {
            s.region == Region::Data
                && retained(s.flags)
                && s.path.eq_ignore_ascii_case(&symbol.path)
        }) else {
            continue;
        };
        if !same_type(old_image, previous.ty, new_image, symbol.ty, 0) {
            continue;
        }
        let size = new_image
            .types
            .get(symbol.ty as usize)
            .map_or(0, |t| t.size_bytes(&new_image.types)) as usize;
        let from = previous.offset as usize;
        if let Some(bytes) = old.region(Region::Data).get(from..from + size) {
            copies.push((symbol.offset as usize, bytes.to_vec()));
        }
    }
    let data = new.region_mut(Region::Data);
    let mut carried = 0;
    for (at, bytes) in copies {
        if let Some(place) = data.get_mut(at..at + bytes.len()) {
            place.copy_from_slice(&bytes);
            carried += 1;
        }
    }
    carried
}

/// Whether two types of two images lay out the same values. Pointers never match: their
/// values are addresses of the old program.
pub(super) fn same_type(
    a_image: &ProgramImage,
    a: TypeId,
    b_image: &ProgramImage,
    b: TypeId,
    depth: u32,
) -> bool {
    if depth > 32 {
        return false;
    }
    let (Some(x), Some(y)) = (a_image.types.get(a as usize), b_image.types.get(b as usize)) else {
        return false;
    };
    match (x, y) {
        (TypeDef::Elementary(p), TypeDef::Elementary(q)) => p == q,
        (TypeDef::String { length: p }, TypeDef::String { length: q })
        | (TypeDef::WString { length: p }, TypeDef::WString { length: q }) => p == q,
        (
            TypeDef::Array {
                element: p,
                dims: pd,
            },
            TypeDef::Array {
                element: q,
                dims: qd,
            },
        ) => pd == qd && same_type(a_image, *p, b_image, *q, depth + 1),
        (TypeDef::Enum { base: p, .. }, TypeDef::Enum { base: q, .. }) => p == q,
        (
            TypeDef::Struct {
                size: ps,
                members: pm,
                ..
            },
            TypeDef::Struct {
                size: qs,
                members: qm,
                ..
            },
        ) => {
            ps == qs
                && pm.len() == qm.len()
                && pm.iter().zip(qm).all(|(m, n)| {
                    m.name.eq_ignore_ascii_case(&n.name)
                        && m.offset == n.offset
                        && m.located == n.located
                        && same_type(a_image, m.ty, b_image, n.ty, depth + 1)
                })
        }
        _ => false,
    }
}
