//! Values typed on the command line, as IEC literals, turned into the bytes of the variable's
//! type: `TRUE`, `42`, `16#FF`, `-1.5`, `T#1s500ms`, `D#2024-01-31`, `'text'`.

use compiler::literal::{self, LiteralError};
use online::{TYPE_STRING, TYPE_WSTRING};
use program_image::Elementary as E;

/// Why a typed value is not one of its variable's type; the command line prints the English
/// message, the studio translates each variant.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ValueError {
    /// A string value without quotes.
    #[error("'{0}' is not a string; write it in quotes, such as 'abc'")]
    NotAString(String),
    /// A string longer than the variable holds.
    #[error("'{text}' is longer than the {length} characters the string holds")]
    TooLong {
        /// The string without its quotes.
        text: String,
        /// How many characters the variable holds.
        length: u16,
    },
    /// The variable is neither elementary nor a string.
    #[error("only elementary values and strings can be written")]
    NotWritable,
    /// The text is no value of the type.
    #[error("'{text}' is not a value of {ty}")]
    NotAValue {
        /// The value as typed.
        text: String,
        /// The type's IEC name.
        ty: &'static str,
    },
    /// The text is a malformed literal of the type.
    #[error("'{text}' is not a value of {ty}: {error}")]
    BadLiteral {
        /// The value as typed.
        text: String,
        /// The type's IEC name.
        ty: &'static str,
        /// What is wrong with the literal.
        error: LiteralError,
    },
    /// The value is outside the type's range.
    #[error("{text} is outside the range of {ty}")]
    OutOfRange {
        /// The value as typed.
        text: String,
        /// The type's IEC name.
        ty: &'static str,
    },
}

/// The bytes of `text` as a value of the type with tag `tag` (strings: [`TYPE_STRING`] and
/// [`TYPE_WSTRING`], with `length` characters), or why it is not one.
pub fn parse(text: &str, tag: u8, length: u16) -> Result<Vec<u8>, ValueError> {
    if tag == TYPE_STRING || tag == TYPE_WSTRING {
        let inner = text
            .strip_prefix(['\'', '"'])
            .and_then(|t| t.strip_suffix(['\'', '"']))
            .ok_or_else(|| ValueError::NotAString(text.to_owned()))?;
        if inner.chars().count() > usize::from(length) {
            return Err(ValueError::TooLong {
                text: inner.to_owned(),
                length,
            });
        }
        let wide = tag == TYPE_WSTRING;
        let mut bytes: Vec<u8> = if wide {
            inner.encode_utf16().flat_map(u16::to_le_bytes).collect()
        } else {
            inner
                .chars()
                .map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?'))
                .collect()
        };
        let size = if wide {
            2 * (usize::from(length) + 1)
        } else {
            usize::from(length) + 1
        };
        bytes.resize(size, 0);
        return Ok(bytes);
    }
    let ty = E::from_tag(tag).ok_or(ValueError::NotWritable)?;
    // A typed literal (`INT#5`, `TIME#5s`) is accepted when its prefix is the type's.
    let body = match text.split_once('#') {
        Some((prefix, rest))
            if prefix.eq_ignore_ascii_case(ty.name())
                && !matches!(
                    prefix.to_ascii_uppercase().as_str(),
                    "T" | "D" | "TOD" | "DT"
                ) =>
        {
            rest
        }
        _ => text,
    };
    let wrong = || ValueError::NotAValue {
        text: text.to_owned(),
        ty: ty.name(),
    };
    let bad = |error| ValueError::BadLiteral {
        text: text.to_owned(),
        ty: ty.name(),
        error,
    };
    let size = ty.size_bytes() as usize;
    let raw: u64 = match ty {
        E::Bool => match body.to_ascii_uppercase().as_str() {
            "TRUE" | "1" => 1,
            "FALSE" | "0" => 0,
            _ => return Err(wrong()),
        },
        E::Real => u64::from((literal::parse_real(body).map_err(|_| wrong())? as f32).to_bits()),
        E::Lreal => literal::parse_real(body).map_err(|_| wrong())?.to_bits(),
        E::Time | E::Ltime => {
            let ns = literal::parse_duration(body).map_err(bad)?;
            let value = if ty == E::Time { ns / 1_000_000 } else { ns };
            in_range(value, ty).ok_or_else(wrong)?
        }
        E::Date | E::Ldate => {
            let days = i128::from(literal::parse_date(body).map_err(bad)?);
            in_range(
                if ty == E::Date {
                    days * 86_400
                } else {
                    days * 86_400_000_000_000
                },
                ty,
            )
            .ok_or_else(wrong)?
        }
        E::TimeOfDay | E::LtimeOfDay => {
            let ns = literal::parse_time_of_day(body).map_err(bad)?;
            in_range(
                if ty == E::TimeOfDay {
                    ns / 1_000_000
                } else {
                    ns
                },
                ty,
            )
            .ok_or_else(wrong)?
        }
        E::DateAndTime | E::LdateAndTime => {
            let ns = literal::parse_date_and_time(body).map_err(bad)?;
            in_range(
                if ty == E::DateAndTime {
                    ns / 1_000_000_000
                } else {
                    ns
                },
                ty,
            )
            .ok_or_else(wrong)?
        }
        _ => {
            let (negative, digits) = match body.strip_prefix('-') {
                Some(rest) => (true, rest),
                None => (false, body.strip_prefix('+').unwrap_or(body)),
            };
            let magnitude = literal::parse_integer(digits).map_err(bad)?;
            let value = i128::try_from(magnitude).map_err(|_| wrong())?;
            let value = if negative { -value } else { value };
            in_range(value, ty).ok_or_else(|| ValueError::OutOfRange {
                text: text.to_owned(),
                ty: ty.name(),
            })?
        }
    };
    Ok(raw.to_le_bytes()[..size].to_vec())
}

/// The raw bits of an integer value of `ty`, if it is in the type's range.
fn in_range(value: i128, ty: E) -> Option<u64> {
    let bits = ty.size_bytes() * 8;
    let (low, high) = if ty.is_signed() {
        (-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1)
    } else {
        (0, (1i128 << bits) - 1)
    };
    (low..=high).contains(&value).then(|| {
        value as u64
            & if bits == 64 {
                u64::MAX
            } else {
                (1u64 << bits) - 1
            }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_become_the_bytes_of_their_type() {
        assert_eq!(parse("TRUE", E::Bool.tag(), 0), Ok(vec![1]));
        assert_eq!(parse("-2", E::Int.tag(), 0), Ok(vec![0xFE, 0xFF]));
        assert_eq!(parse("16#FF", E::Byte.tag(), 0), Ok(vec![0xFF]));
        assert_eq!(parse("INT#7", E::Int.tag(), 0), Ok(vec![7, 0]));
        assert_eq!(
            parse("T#1s500ms", E::Time.tag(), 0),
            Ok(1500i32.to_le_bytes().to_vec())
        );
        assert_eq!(
            parse("1.5", E::Real.tag(), 0),
            Ok(1.5f32.to_le_bytes().to_vec())
        );
        assert_eq!(parse("'ab'", 0x20, 3), Ok(vec![b'a', b'b', 0, 0]));
    }

    #[test]
    fn values_of_the_wrong_type_are_refused_with_the_reason() {
        assert_eq!(
            parse("300", E::Sint.tag(), 0).map_err(|error| error.to_string()),
            Err("300 is outside the range of SINT".to_owned())
        );
        assert!(
            parse("abc", E::Int.tag(), 0)
                .unwrap_err()
                .to_string()
                .contains("'abc' is not a value of INT")
        );
        assert!(parse("maybe", E::Bool.tag(), 0).is_err());
        assert!(
            parse("'too long'", 0x20, 3)
                .unwrap_err()
                .to_string()
                .contains("longer than the 3 characters")
        );
        assert!(
            parse("abc", 0x20, 3)
                .unwrap_err()
                .to_string()
                .contains("in quotes")
        );
    }
}
