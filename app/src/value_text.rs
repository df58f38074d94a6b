//! Values read from a target as text and numbers: what the command line prints and what the
//! studio's watch, force and trace views show.

use online::{Enumeration, Place, Resolved, TYPE_STRING, TYPE_WSTRING};
use program_image::Elementary;

/// The first eight bytes of a value, little-endian, as the raw bits of an elementary value
/// (missing bytes read as zero).
fn raw_of(bytes: &[u8]) -> u64 {
    let mut raw = [0u8; 8];
    let n = bytes.len().min(8);
    raw[..n].copy_from_slice(&bytes[..n]);
    u64::from_le_bytes(raw)
}

/// A value's bytes as an IEC literal.
pub fn show(resolved: &Resolved, bytes: &[u8]) -> String {
    let raw = raw_of(bytes);
    if resolved.place.bit.is_some() {
        return if raw & 1 != 0 {
            "TRUE".to_owned()
        } else {
            "FALSE".to_owned()
        };
    }
    match resolved.type_tag {
        TYPE_STRING => format!(
            "'{}'",
            bytes
                .iter()
                .take_while(|&&b| b != 0)
                .map(|&b| char::from(b))
                .collect::<String>()
        ),
        TYPE_WSTRING => {
            let units: Vec<u16> = bytes
                .chunks_exact(2)
                .map(|c| u16::from_le_bytes([c[0], c[1]]))
                .take_while(|&u| u != 0)
                .collect();
            format!("\"{}\"", String::from_utf16_lossy(&units))
        }
        tag => match Elementary::from_tag(tag) {
            Some(ty) => runtime::value::elementary(raw, ty).to_string(),
            None => format!("16#{}", hex(bytes)),
        },
    }
}

/// A value's bytes as text, an enumeration's by the name of its value (`enumeration` is the
/// variable's type when it is one, from `online::Client::enumeration`).
pub fn show_typed(resolved: &Resolved, enumeration: Option<&Enumeration>, bytes: &[u8]) -> String {
    match enumeration {
        Some(enumeration) => show_enumeration(enumeration, bytes),
        None => show(resolved, bytes),
    }
}

/// The bytes of an enumeration's value as its name, or as its number when no value of the type
/// has that number (a plain integer written to it) or the base type is unknown.
pub fn show_enumeration(enumeration: &Enumeration, bytes: &[u8]) -> String {
    let number = match Elementary::from_tag(enumeration.base)
        .map(|ty| runtime::value::elementary(raw_of(bytes), ty))
    {
        Some(runtime::value::Value::Int(number, _)) => number as i64,
        _ => return format!("16#{}", hex(bytes)),
    };
    match enumeration.name_of(number) {
        Some(name) => name.to_owned(),
        None => number.to_string(),
    }
}

/// Where a place is, in words, for places no path is known for.
pub fn describe_place(place: &Place) -> String {
    let region = match place.region {
        0 => "data",
        1 => "%I",
        2 => "%Q",
        _ => "%M",
    };
    match place.bit {
        Some(bit) => format!("{region} byte {} bit {bit}", place.offset),
        None => format!("{region} byte {} ({} bytes)", place.offset, place.size),
    }
}

/// Bytes as lowercase hexadecimal digits.
pub fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// A value's bytes as a number for plotting: BOOL as 0 or 1, integers, reals, times in their
/// raw units; `None` for strings and anything that is not a number.
pub fn numeric(resolved: &Resolved, bytes: &[u8]) -> Option<f64> {
    let raw = raw_of(bytes);
    if resolved.place.bit.is_some() {
        return Some(f64::from(u8::from(raw & 1 != 0)));
    }
    let ty = Elementary::from_tag(resolved.type_tag)?;
    match runtime::value::elementary(raw, ty) {
        runtime::value::Value::Bool(b) => Some(f64::from(u8::from(b))),
        runtime::value::Value::Int(v, _) => Some(v as f64),
        runtime::value::Value::Real(v, _) => Some(v),
        runtime::value::Value::Time(v, _) => Some(v as f64),
        runtime::value::Value::Enum(_, v) => Some(v as f64),
        _ => None,
    }
}

/// The bytes of an elementary value as its IEC literal.
pub fn describe_elementary(ty: Elementary, bytes: &[u8]) -> String {
    runtime::value::elementary(raw_of(bytes), ty).to_string()
}

/// Whether the value is a BOOL (drawn as steps, toggled rather than typed).
pub fn is_bool(resolved: &Resolved) -> bool {
    resolved.place.bit.is_some() || resolved.type_tag == Elementary::Bool as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    fn resolved(type_tag: u8, size: u16, bit: Option<u8>) -> Resolved {
        Resolved {
            place: Place {
                region: 0,
                offset: 0,
                bit,
                size,
            },
            type_tag,
            length: 0,
        }
    }

    #[test]
    fn numbers_and_booleans_are_shown_as_literals_and_plotted_as_numbers() {
        let int = resolved(Elementary::Int as u8, 2, None);
        assert_eq!(show(&int, &(-5i16).to_le_bytes()), "-5");
        assert_eq!(numeric(&int, &(-5i16).to_le_bytes()), Some(-5.0));
        let real = resolved(Elementary::Real as u8, 4, None);
        assert_eq!(numeric(&real, &1.5f32.to_le_bytes()), Some(1.5));
        let bit = resolved(Elementary::Bool as u8, 1, Some(3));
        assert_eq!(show(&bit, &[1]), "TRUE");
        assert_eq!(numeric(&bit, &[0]), Some(0.0));
        assert!(is_bool(&bit));
        let text = resolved(0x20, 4, None);
        assert_eq!(show(&text, b"ab\0\0"), "'ab'");
        assert_eq!(numeric(&text, b"ab\0\0"), None);
    }

    #[test]
    fn an_enumeration_is_shown_by_the_name_of_its_value_or_else_its_number() {
        let colour = Enumeration {
            base: Elementary::Int as u8,
            values: vec![
                ("RED".to_owned(), 0),
                ("GREEN".to_owned(), 1),
                ("BLUE".to_owned(), -7),
            ],
        };
        assert_eq!(show_enumeration(&colour, &1i16.to_le_bytes()), "GREEN");
        assert_eq!(show_enumeration(&colour, &(-7i16).to_le_bytes()), "BLUE");
        assert_eq!(show_enumeration(&colour, &5i16.to_le_bytes()), "5");
        let resolved = resolved(online::TYPE_ENUM, 2, None);
        assert_eq!(
            show_typed(&resolved, Some(&colour), &0i16.to_le_bytes()),
            "RED"
        );
        assert_eq!(show_typed(&resolved, None, &0i16.to_le_bytes()), "16#0000");
    }
}
