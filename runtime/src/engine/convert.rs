//! Conversions between elementary types on raw values, with the rules of IEC 61131-3 and
//! CODESYS: integers narrow by keeping their low bits, reals round to the nearest integer
//! (halves away from zero, so `REAL_TO_INT(-1.5) = -2`), anything non-zero is TRUE, and the
//! time types convert through their units (TIME milliseconds, LTIME nanoseconds).

use program_image::Elementary::{self, *};

/// A value on its way between two types.
#[derive(Clone, Copy)]
enum Value {
    Int(i128),
    Float(f64),
}

/// `raw` (zero-extended little-endian bytes of a `from`) converted to a `to`.
pub(crate) fn convert(raw: u64, from: Elementary, to: Elementary) -> u64 {
    let value = read(raw, from);
    let value = rescale(value, from, to);
    write(value, to)
}

/// `TRUNC`: a real to an integer, toward zero.
pub(crate) fn trunc(raw: u64, from: Elementary, to: Elementary) -> u64 {
    match read(raw, from) {
        Value::Float(f) => write(Value::Float(f.trunc()), to),
        other => write(other, to),
    }
}

fn read(raw: u64, ty: Elementary) -> Value {
    match ty {
        Real => Value::Float(f64::from(f32::from_bits(raw as u32))),
        Lreal => Value::Float(f64::from_bits(raw)),
        _ if ty.is_signed() => {
            let bits = ty.size_bytes() * 8;
            let shift = 64 - bits;
            Value::Int(i128::from(((raw << shift) as i64) >> shift))
        }
        _ => Value::Int(i128::from(raw)),
    }
}

/// The unit of a time type in nanoseconds, or 1 for other types.
fn unit_ns(ty: Elementary) -> Option<i128> {
    match ty {
        Time | TimeOfDay => Some(1_000_000),
        Date | DateAndTime => Some(1_000_000_000),
        Ltime | Ldate | LtimeOfDay | LdateAndTime => Some(1),
        _ => None,
    }
}

fn rescale(value: Value, from: Elementary, to: Elementary) -> Value {
    match (unit_ns(from), unit_ns(to), value) {
        (Some(a), Some(b), Value::Int(v)) => {
            let ns = v.saturating_mul(a);
            // DT to TOD keeps the time of day, DT to DATE the day.
            let ns = match (from, to) {
                (DateAndTime | LdateAndTime, TimeOfDay | LtimeOfDay) => {
                    ns.rem_euclid(86_400_000_000_000)
                }
                (DateAndTime | LdateAndTime, Date | Ldate) => {
                    ns - ns.rem_euclid(86_400_000_000_000)
                }
                _ => ns,
            };
            Value::Int(ns.div_euclid(b))
        }
        _ => value,
    }
}

fn write(value: Value, to: Elementary) -> u64 {
    match to {
        Real => u64::from(
            match value {
                Value::Int(v) => v as f32,
                Value::Float(f) => f as f32,
            }
            .to_bits(),
        ),
        Lreal => match value {
            Value::Int(v) => v as f64,
            Value::Float(f) => f,
        }
        .to_bits(),
        Bool => u64::from(match value {
            Value::Int(v) => v != 0,
            Value::Float(f) => f != 0.0,
        }),
        _ => {
            let integer = match value {
                Value::Int(v) => v,
                // Rounded half away from zero; NaN gives 0 and infinities saturate.
                Value::Float(f) => f.round() as i128,
            };
            let bits = to.size_bytes() * 8;
            let mask = if bits == 64 {
                u64::MAX
            } else {
                (1u64 << bits) - 1
            };
            (integer as u64) & mask
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[track_caller]
    fn check(raw: u64, from: Elementary, to: Elementary, expected: u64) {
        assert_eq!(convert(raw, from, to), expected, "{from:?} -> {to:?}");
    }

    #[test]
    fn the_lc1200_conversion_vectors_hold() {
        check(
            u64::from((-1.5f32).to_bits()),
            Real,
            Int,
            u64::from((-2i16) as u16),
        );
        check(u64::from(1.5f32.to_bits()), Real, Int, 2);
        check(4223, Int, Sint, 127);
        check(300, Int, Bool, 1);
        check(1500, Time, Ltime, 1_500_000_000);
        check(86_400 + 3600, DateAndTime, TimeOfDay, 3_600_000);
        check(86_400 + 3600, DateAndTime, Date, 86_400);
    }

    #[test]
    fn trunc_goes_toward_zero() {
        assert_eq!(
            trunc(u64::from((-1.7f32).to_bits()), Real, Dint),
            u64::from((-1i32) as u32)
        );
    }
}
