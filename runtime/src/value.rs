//! Values of variables named by path (`Main.fb.ET`, `Main.a[3].x`), read from an engine's
//! memory and shown as IEC literals or JSON.

use std::fmt;

use program_image::{Elementary as E, ProgramImage, Region, TypeDef, TypeId};

use crate::engine::Engine;

/// A value read from memory.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// BOOL.
    Bool(bool),
    /// Any integer, bit string, enumeration or CHAR, with its type.
    Int(i128, E),
    /// REAL or LREAL.
    Real(f64, E),
    /// A time, date or time of day, as raw units of its type.
    Time(i64, E),
    /// STRING or WSTRING.
    Text(String),
    /// An enumeration value: its name when it has one, and its number.
    Enum(Option<String>, i64),
    /// A pointer or reference value.
    Pointer(u64),
    /// A structure or instance: its members in order.
    Struct(Vec<(String, Value)>),
    /// An array: its elements in order.
    Array(Vec<Value>),
}

/// Why a path does not name a value.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum PathError {
    /// No variable has this path.
    #[error("unknown variable '{0}'")]
    Unknown(String),
    /// A member that the type does not have.
    #[error("'{path}' has no member '{member}'")]
    NoMember {
        /// The path up to the member.
        path: String,
        /// The member asked for.
        member: String,
    },
    /// An index on something that is not an array, or out of its bounds.
    #[error("'{0}': index out of bounds or not an array")]
    BadIndex(String),
    /// The path is not written as `a.b[1].c`.
    #[error("'{0}' is not a variable path")]
    Syntax(String),
}

/// A resolved place: where the value is and its type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Place {
    /// The region.
    pub region: Region,
    /// Byte offset in it.
    pub offset: u64,
    /// For a located BOOL, its bit.
    pub bit: Option<u8>,
    /// Its type.
    pub ty: TypeId,
}

/// One step of a path: a name and the indices after it.
struct Step {
    name: String,
    indices: Vec<i64>,
}

fn parse_path(path: &str) -> Result<Vec<Step>, PathError> {
    let error = || PathError::Syntax(path.to_owned());
    let mut steps = Vec::new();
    for part in path.split('.') {
        let (name, mut rest) = match part.find('[') {
            Some(at) => (&part[..at], &part[at..]),
            None => (part, ""),
        };
        if name.trim().is_empty() {
            return Err(error());
        }
        let mut indices = Vec::new();
        while let Some(inner) = rest.strip_prefix('[') {
            let close = inner.find(']').ok_or_else(error)?;
            for index in inner[..close].split(',') {
                indices.push(index.trim().parse::<i64>().map_err(|_| error())?);
            }
            rest = &inner[close + 1..];
        }
        if !rest.trim().is_empty() {
            return Err(error());
        }
        steps.push(Step {
            name: name.trim().to_owned(),
            indices,
        });
    }
    Ok(steps)
}

/// Where the variable `path` is in `image`.
pub fn resolve(image: &ProgramImage, path: &str) -> Result<Place, PathError> {
    let steps = parse_path(path)?;
    // The longest prefix of names that is a symbol; the rest are members and indices.
    for taken in (1..=steps.len()).rev() {
        let name: Vec<&str> = steps[..taken].iter().map(|s| s.name.as_str()).collect();
        let name = name.join(".");
        if steps[..taken - 1].iter().any(|s| !s.indices.is_empty()) {
            continue;
        }
        let Some(symbol) = image
            .symbols
            .iter()
            .find(|s| s.path.eq_ignore_ascii_case(&name))
        else {
            continue;
        };
        let mut place = Place {
            region: symbol.region,
            offset: u64::from(symbol.offset),
            bit: symbol.bit,
            ty: symbol.ty,
        };
        let mut walked = name;
        place = index(image, place, &steps[taken - 1].indices, &walked)?;
        for step in &steps[taken..] {
            let Some(TypeDef::Struct { members, .. }) = image.types.get(place.ty as usize) else {
                return Err(PathError::NoMember {
                    path: walked,
                    member: step.name.clone(),
                });
            };
            let Some(member) = members
                .iter()
                .find(|m| m.name.eq_ignore_ascii_case(&step.name))
            else {
                return Err(PathError::NoMember {
                    path: walked,
                    member: step.name.clone(),
                });
            };
            walked = format!("{walked}.{}", member.name);
            place = match member.located {
                Some(located) => Place {
                    region: located.region,
                    offset: located.bit_offset / 8,
                    bit: (located.size_bits == 1).then_some((located.bit_offset % 8) as u8),
                    ty: member.ty,
                },
                None => Place {
                    offset: place.offset + u64::from(member.offset),
                    ty: member.ty,
                    ..place
                },
            };
            place = index(image, place, &step.indices, &walked)?;
        }
        return Ok(place);
    }
    Err(PathError::Unknown(path.to_owned()))
}

fn index(
    image: &ProgramImage,
    place: Place,
    indices: &[i64],
    path: &str,
) -> Result<Place, PathError> {
    if indices.is_empty() {
        return Ok(place);
    }
    let Some(TypeDef::Array { element, dims }) = image.types.get(place.ty as usize) else {
        return Err(PathError::BadIndex(path.to_owned()));
    };
    if dims.len() != indices.len() {
        return Err(PathError::BadIndex(path.to_owned()));
    }
    let mut linear = 0u64;
    for (&(low, high), &i) in dims.iter().zip(indices) {
        if i < low || i > high {
            return Err(PathError::BadIndex(path.to_owned()));
        }
        // Bounds of a hostile image may be extreme: the arithmetic saturates rather than panics.
        let count = high.abs_diff(low).saturating_add(1);
        linear = linear.saturating_mul(count).saturating_add(i.abs_diff(low));
    }
    let size = image
        .types
        .get(*element as usize)
        .map_or(0, |t| t.size_bytes(&image.types));
    Ok(Place {
        offset: place.offset.saturating_add(linear.saturating_mul(size)),
        ty: *element,
        ..place
    })
}

/// Reads the value of the variable `path`.
pub fn read(engine: &Engine, path: &str) -> Result<Value, PathError> {
    let image = engine.image();
    let place = resolve(image, path)?;
    Ok(read_place(engine, place))
}

/// Reads the value at a resolved place.
pub fn read_place(engine: &Engine, place: Place) -> Value {
    let image = engine.image();
    let bytes = engine.region(place.region);
    value_at(image, bytes, place.offset as usize, place.bit, place.ty, 0)
}

/// Decodes the bytes of a value of type `ty` of `image`, as read from a target: enumerations
/// by name, structures and arrays by member. Missing bytes read as zero.
pub fn decode(image: &ProgramImage, ty: TypeId, bytes: &[u8]) -> Value {
    value_at(image, bytes, 0, None, ty, 0)
}

fn raw_at(bytes: &[u8], offset: usize, size: usize) -> u64 {
    let mut raw = [0u8; 8];
    if let Some(source) = bytes.get(offset..offset + size) {
        raw[..size].copy_from_slice(source);
    }
    u64::from_le_bytes(raw)
}

fn value_at(
    image: &ProgramImage,
    bytes: &[u8],
    offset: usize,
    bit: Option<u8>,
    ty: TypeId,
    depth: u32,
) -> Value {
    let Some(def) = image.types.get(ty as usize) else {
        return Value::Struct(Vec::new());
    };
    match def {
        TypeDef::Elementary(e) => {
            if let Some(bit) = bit {
                return Value::Bool(raw_at(bytes, offset, 1) >> bit & 1 != 0);
            }
            elementary(raw_at(bytes, offset, e.size_bytes() as usize), *e)
        }
        TypeDef::String { length } => {
            let end = (offset + *length as usize + 1).min(bytes.len());
            let chars = bytes.get(offset..end).unwrap_or_default();
            let text = chars
                .iter()
                .take_while(|&&c| c != 0)
                .map(|&c| char::from(c))
                .collect();
            Value::Text(text)
        }
        TypeDef::WString { length } => {
            let units: Vec<u16> = (0..=*length as usize)
                .map(|i| raw_at(bytes, offset + 2 * i, 2) as u16)
                .take_while(|&u| u != 0)
                .collect();
            Value::Text(String::from_utf16_lossy(&units))
        }
        TypeDef::Enum { base, values, .. } => {
            let raw = raw_at(bytes, offset, base.size_bytes() as usize);
            let number = match elementary(raw, *base) {
                Value::Int(v, _) => v as i64,
                _ => 0,
            };
            let name = values
                .iter()
                .find(|(_, v)| *v == number)
                .map(|(n, _)| n.clone());
            Value::Enum(name, number)
        }
        TypeDef::Pointer { .. } => Value::Pointer(raw_at(bytes, offset, 8)),
        TypeDef::Struct { members, .. } if depth < 32 => Value::Struct(
            members
                .iter()
                .filter(|m| !m.name.starts_with('_'))
                .map(|m| {
                    let value = value_at(
                        image,
                        bytes,
                        offset + m.offset as usize,
                        None,
                        m.ty,
                        depth + 1,
                    );
                    (m.name.clone(), value)
                })
                .collect(),
        ),
        TypeDef::Array { element, dims } if depth < 32 => {
            let count: u64 = dims
                .iter()
                .map(|(l, h)| h.abs_diff(*l).saturating_add(1))
                .fold(1u64, u64::saturating_mul);
            let size = image
                .types
                .get(*element as usize)
                .map_or(0, |t| t.size_bytes(&image.types));
            // Large arrays are shown by their first elements only.
            let shown = count.min(1000);
            Value::Array(
                (0..shown)
                    .map(|i| {
                        value_at(
                            image,
                            bytes,
                            offset.saturating_add(
                                usize::try_from(i.saturating_mul(size)).unwrap_or(usize::MAX),
                            ),
                            None,
                            *element,
                            depth + 1,
                        )
                    })
                    .collect(),
            )
        }
        _ => Value::Struct(Vec::new()),
    }
}

/// The value of raw bits of an elementary type.
pub fn elementary(raw: u64, ty: E) -> Value {
    let signed = |bits: u32| -> i64 {
        let shift = 64 - bits;
        ((raw << shift) as i64) >> shift
    };
    match ty {
        E::Bool => Value::Bool(raw & 1 != 0),
        E::Real => Value::Real(f64::from(f32::from_bits(raw as u32)), ty),
        E::Lreal => Value::Real(f64::from_bits(raw), ty),
        E::Time | E::Ltime | E::Ldate | E::LtimeOfDay | E::LdateAndTime => {
            Value::Time(signed(ty.size_bytes() * 8), ty)
        }
        E::Date | E::TimeOfDay | E::DateAndTime => Value::Time(raw as i64, ty),
        _ if ty.is_signed() => Value::Int(i128::from(signed(ty.size_bytes() * 8)), ty),
        _ => Value::Int(i128::from(raw), ty),
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Bool(b) => write!(f, "{}", if *b { "TRUE" } else { "FALSE" }),
            Self::Int(v, _) => write!(f, "{v}"),
            // A REAL prints with the digits an f32 holds (1.234, not 1.2339999675750732).
            Self::Real(v, E::Real) => write!(f, "{}", *v as f32),
            Self::Real(v, _) => write!(f, "{v}"),
            Self::Time(v, ty) => write!(f, "{}", time_literal(*v, *ty)),
            Self::Text(text) => write!(f, "'{}'", text.replace('\'', "$'")),
            Self::Enum(Some(name), _) => write!(f, "{name}"),
            Self::Enum(None, number) => write!(f, "{number}"),
            Self::Pointer(p) => write!(f, "16#{p:X}"),
            Self::Struct(members) => {
                write!(f, "(")?;
                for (i, (name, value)) in members.iter().enumerate() {
                    if i > 0 {
                        write!(f, ", ")?;
                    }
                    write!(f, "{name} := {value}")?;
                }
                write!(f, ")")
            }
            Self::Array(items) => {
                write!(f, "[")?;
                for (i, value) in items.iter().enumerate() {
                    if i > 0 {
                        write!(f, ", ")?;
                    }
                    write!(f, "{value}")?;
                }
                write!(f, "]")
            }
        }
    }
}

impl Value {
    /// The value as JSON: numbers and booleans as such, times, dates and strings as their IEC
    /// literal text, structures as objects and arrays as lists.
    pub fn to_json(&self) -> String {
        match self {
            Self::Bool(b) => b.to_string(),
            Self::Int(v, _) => v.to_string(),
            Self::Real(v, ty) if v.is_finite() => match ty {
                E::Real => format!("{}", *v as f32),
                _ => format!("{v}"),
            },
            Self::Enum(_, number) => number.to_string(),
            Self::Struct(members) => {
                let inner: Vec<String> = members
                    .iter()
                    .map(|(name, value)| format!("{}: {}", json_string(name), value.to_json()))
                    .collect();
                format!("{{{}}}", inner.join(", "))
            }
            Self::Array(items) => {
                let inner: Vec<String> = items.iter().map(Value::to_json).collect();
                format!("[{}]", inner.join(", "))
            }
            Self::Text(text) => json_string(text),
            other => json_string(&other.to_string()),
        }
    }
}

/// A JSON string literal.
pub fn json_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A time, date or time of day as an IEC literal: `T#1s500ms`, `D#2024-01-31`.
pub fn time_literal(value: i64, ty: E) -> String {
    crate::stdlib::text::to_text(value as u64 & crate::stdlib::mask(ty), ty)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn times_and_dates_print_as_iec_literals() {
        assert_eq!(time_literal(1500, E::Time), "T#1s500ms");
        assert_eq!(time_literal(0, E::Time), "T#0ms");
        assert_eq!(time_literal(19_753 * 86_400, E::Date), "D#2024-01-31");
        assert_eq!(time_literal(45_000_000, E::TimeOfDay), "TOD#12:30:00");
    }

    #[test]
    fn paths_parse_names_and_indices() {
        let steps = parse_path("Main.a[3, -1].x").unwrap();
        assert_eq!(steps.len(), 3);
        assert_eq!(steps[1].indices, [3, -1]);
        assert!(parse_path("Main..x").is_err());
        assert!(parse_path("Main.a[x]").is_err());
    }
}
