//! A differing byte named by the variable that holds it: the symbol covering it, then members
//! and elements through the type table, down to an elementary value, a string or a pointer.

use program_image::{ProgramImage, Region, TypeDef, TypeId};

use crate::value;

/// A byte named, with each engine's value there.
pub(super) struct Named {
    /// The path down to the innermost member or element, `None` where no symbol covers it.
    pub path: Option<String>,
    /// The first engine's value.
    pub first: String,
    /// The second engine's value.
    pub second: String,
}

/// How deep structures and arrays are followed, as `value` shows them.
const MAX_DEPTH: usize = 32;

/// Names byte `offset` of `region`, which differs between `first` and `second` (the two
/// engines' bytes of the region), with both values.
pub(super) fn name(
    image: &ProgramImage,
    region: Region,
    offset: usize,
    first: &[u8],
    second: &[u8],
) -> Named {
    let byte_text = |bytes: &[u8]| match bytes.get(offset) {
        Some(byte) => format!("byte 16#{byte:02X}"),
        None => "no byte".to_owned(),
    };
    let Some((path, leaf)) = walk(image, region, offset, first, second) else {
        return Named {
            path: None,
            first: byte_text(first),
            second: byte_text(second),
        };
    };
    let (first, second) = match leaf {
        Some(leaf) => (
            leaf_text(image, &leaf, offset, first),
            leaf_text(image, &leaf, offset, second),
        ),
        // Padding inside a structure, or past the last element: only the byte tells.
        None => (byte_text(first), byte_text(second)),
    };
    Named {
        path: Some(path),
        first,
        second,
    }
}

/// The value the walk ends at: a type that has no members or elements, where it starts in the
/// region, and for a located BOOL its bit.
struct Leaf {
    ty: TypeId,
    start: usize,
    bit: Option<u8>,
}

/// The symbol covering `offset`, then its members and elements down to a [`Leaf`]; the leaf
/// is `None` when the byte is in padding.
fn walk(
    image: &ProgramImage,
    region: Region,
    offset: usize,
    first: &[u8],
    second: &[u8],
) -> Option<(String, Option<Leaf>)> {
    let size_of = |ty: TypeId| {
        image
            .types
            .get(ty as usize)
            .map_or(0, |def| def.size_bytes(&image.types))
    };
    let differing_bits =
        first.get(offset).copied().unwrap_or(0) ^ second.get(offset).copied().unwrap_or(0);
    // Several symbols may cover a byte (a program and its variables, `%IW0` and `%IX0.3`):
    // the smallest is the most precise, and of the bits of a byte the one that differs.
    let symbol = image
        .symbols
        .iter()
        .filter(|symbol| symbol.region == region)
        .filter(|symbol| {
            let start = symbol.offset as usize;
            let size = if symbol.bit.is_some() {
                1
            } else {
                size_of(symbol.ty)
            };
            start <= offset && (offset - start) < usize::try_from(size).unwrap_or(usize::MAX)
        })
        .filter(|symbol| {
            symbol
                .bit
                .is_none_or(|bit| differing_bits >> (bit & 7) & 1 != 0)
        })
        .min_by_key(|symbol| {
            let size = if symbol.bit.is_some() {
                0
            } else {
                size_of(symbol.ty)
            };
            (size, std::cmp::Reverse(symbol.path.len()))
        })?;
    let mut path = symbol.path.clone();
    let mut ty = symbol.ty;
    let mut start = symbol.offset as usize;
    if symbol.bit.is_some() {
        let leaf = Leaf {
            ty,
            start,
            bit: symbol.bit,
        };
        return Some((path, Some(leaf)));
    }
    for _ in 0..MAX_DEPTH {
        let within = (offset - start) as u64;
        match image.types.get(ty as usize) {
            Some(TypeDef::Struct { members, .. }) => {
                // A located member lives in another region, not in the structure's bytes.
                let Some(member) = members.iter().find(|member| {
                    member.located.is_none()
                        && u64::from(member.offset) <= within
                        && within < u64::from(member.offset) + size_of(member.ty)
                }) else {
                    return Some((format!("{path} (padding)"), None));
                };
                path = format!("{path}.{}", member.name);
                ty = member.ty;
                start += member.offset as usize;
            }
            Some(TypeDef::Array { element, dims }) => {
                let element_size = size_of(*element);
                if element_size == 0 {
                    return Some((path, None));
                }
                let mut linear = within / element_size;
                let mut indices = Vec::with_capacity(dims.len());
                // The last dimension varies fastest (the first is outermost).
                for &(low, high) in dims.iter().rev() {
                    let count = high.abs_diff(low).saturating_add(1);
                    indices.push(i128::from(low) + i128::from(linear % count));
                    linear /= count;
                }
                if linear != 0 {
                    return Some((format!("{path} (past its elements)"), None));
                }
                indices.reverse();
                let indices: Vec<String> = indices.iter().map(i128::to_string).collect();
                path = format!("{path}[{}]", indices.join(", "));
                start += usize::try_from(within / element_size * element_size).unwrap_or(0);
                ty = *element;
            }
            _ => {
                return Some((
                    path,
                    Some(Leaf {
                        ty,
                        start,
                        bit: None,
                    }),
                ));
            }
        }
    }
    Some((path, None))
}

/// A leaf's value as an IEC literal, followed by what shows the difference even when the
/// literals look alike: the raw bits of an elementary value (two NaNs), or the differing byte
/// of a longer value (a string's bytes past its end).
fn leaf_text(image: &ProgramImage, leaf: &Leaf, offset: usize, bytes: &[u8]) -> String {
    let rest = bytes.get(leaf.start..).unwrap_or_default();
    if let Some(bit) = leaf.bit {
        let set = rest.first().is_some_and(|byte| byte >> (bit & 7) & 1 != 0);
        return if set { "TRUE" } else { "FALSE" }.to_owned();
    }
    let literal = value::decode(image, leaf.ty, rest);
    match image.types.get(leaf.ty as usize) {
        Some(TypeDef::Elementary(elementary)) => {
            let size = elementary.size_bytes() as usize;
            let raw: String = rest
                .iter()
                .take(size)
                .rev()
                .map(|byte| format!("{byte:02X}"))
                .collect();
            format!("{literal} (16#{raw})")
        }
        _ => {
            let byte = bytes.get(offset).copied().unwrap_or(0);
            format!("{literal}, byte {} = 16#{byte:02X}", offset - leaf.start)
        }
    }
}

#[cfg(test)]
mod tests {
    use program_image::{Elementary, Symbol, SymbolFlags};

    use super::*;

    /// `Main.r` (REAL at 0) and `Main.s` (STRING(7) at 4) in the data region.
    fn image() -> ProgramImage {
        let symbol = |path: &str, ty: u32, offset: u32| Symbol {
            path: path.to_owned(),
            ty,
            region: Region::Data,
            offset,
            bit: None,
            flags: SymbolFlags(0),
        };
        ProgramImage {
            types: vec![
                TypeDef::Elementary(Elementary::Real),
                TypeDef::String { length: 7 },
            ],
            symbols: vec![symbol("Main.r", 0, 0), symbol("Main.s", 1, 4)],
            ..ProgramImage::default()
        }
    }

    #[test]
    fn two_nans_that_differ_in_their_payload_show_their_bits() {
        let mut first = vec![0; 12];
        let mut second = first.clone();
        first[..4].copy_from_slice(&0x7FC0_0001_u32.to_le_bytes());
        second[..4].copy_from_slice(&0x7FC0_0002_u32.to_le_bytes());
        let named = name(&image(), Region::Data, 0, &first, &second);
        assert_eq!(named.path.as_deref(), Some("Main.r"));
        assert_eq!(named.first, "NaN (16#7FC00001)");
        assert_eq!(named.second, "NaN (16#7FC00002)");
    }

    #[test]
    fn a_string_that_differs_past_its_end_shows_the_differing_byte() {
        let mut first = vec![0; 12];
        first[4..7].copy_from_slice(b"abc");
        let mut second = first.clone();
        second[9] = b'x';
        let named = name(&image(), Region::Data, 9, &first, &second);
        assert_eq!(named.path.as_deref(), Some("Main.s"));
        assert_eq!(named.first, "'abc', byte 5 = 16#00");
        assert_eq!(named.second, "'abc', byte 5 = 16#78");
    }
}
