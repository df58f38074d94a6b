//! The pure functions of the standard library: conversions, text, bit shifts, strings, dates and
//! numeric functions with CODESYS-defined edges.
//!
//! Values cross this API as raw bits: a `u64` holding the value's little-endian memory bytes,
//! zero-extended.
//! So an `INT` −1 is `0xFFFF`, a `REAL` is `f32::to_bits` widened to `u64`, and `TRUE` is 1.
//! Every function here is total: it never panics and never allocates more than its inputs bound.
//! The helpers below are the one place where raw bits become numbers and back.

pub mod bits;
pub mod convert;
pub mod numeric;
pub mod string;
pub mod text;
pub mod time;

use program_image::Elementary;

/// The number of value bits of `ty`: one for `BOOL`, eight times its size otherwise.
pub fn width_bits(ty: Elementary) -> u32 {
    match ty {
        Elementary::Bool => 1,
        _ => ty.size_bytes() * 8,
    }
}

/// The mask of the bits a value of `ty` occupies in its raw form.
pub fn mask(ty: Elementary) -> u64 {
    let width = width_bits(ty);
    if width >= 64 {
        u64::MAX
    } else {
        (1u64 << width) - 1
    }
}

/// The value of an integer-like `raw` of type `ty` (integers, bit strings, time and date types,
/// `CHAR`, `WCHAR`) as an `i64`: sign-extended for signed types, zero-extended otherwise.
///
/// A `ULINT` or `LWORD` above `i64::MAX` comes back as its two's-complement bits; use
/// [`int_value`] where the full range matters.
/// `BOOL` gives 0 or 1 (any nonzero byte counts as `TRUE`).
pub fn sign_extend(raw: u64, ty: Elementary) -> i64 {
    int_value(raw, ty) as i64
}

/// The exact value of an integer-like `raw` of type `ty`, wide enough for every type
/// (`ULINT` included); `REAL` and `LREAL` give their bit pattern read as unsigned.
pub fn int_value(raw: u64, ty: Elementary) -> i128 {
    if ty == Elementary::Bool {
        return i128::from(raw & 0xFF != 0);
    }
    let width = width_bits(ty);
    let bits = raw & mask(ty);
    if ty.is_signed() && width < 64 {
        // Shifting the sign bit to the top and back copies it into the upper bits.
        let shift = 64 - width;
        i128::from(((bits << shift) as i64) >> shift)
    } else if ty.is_signed() {
        i128::from(bits as i64)
    } else {
        i128::from(bits)
    }
}

/// The raw bits of the integer `value` stored in a `ty`: the low bits are kept, as CODESYS does
/// when a value does not fit (`INT_TO_SINT(4223)` is 127).
/// For `BOOL` any nonzero value is `TRUE`.
pub fn raw_from_i64(value: i64, ty: Elementary) -> u64 {
    raw_from_i128(i128::from(value), ty)
}

/// [`raw_from_i64`] for values beyond the `i64` range (a `ULINT` above `i64::MAX`).
pub fn raw_from_i128(value: i128, ty: Elementary) -> u64 {
    if ty == Elementary::Bool {
        return u64::from(value != 0);
    }
    (value as u64) & mask(ty)
}

/// The value of a `REAL` or `LREAL` raw as `f64` (a `REAL` widens exactly).
/// Any other type gives its integer value as `f64`, so callers may pass any numeric type.
pub fn real_value(raw: u64, ty: Elementary) -> f64 {
    match ty {
        Elementary::Real => f64::from(f32::from_bits(raw as u32)),
        Elementary::Lreal => f64::from_bits(raw),
        _ => int_value(raw, ty) as f64,
    }
}

/// The raw bits of the real `value` stored in a `REAL` (rounded to `f32`) or an `LREAL`.
/// For any other type the value is converted as [`convert::convert`] converts an `LREAL`.
pub fn raw_from_real(value: f64, ty: Elementary) -> u64 {
    match ty {
        Elementary::Real => u64::from((value as f32).to_bits()),
        Elementary::Lreal => value.to_bits(),
        _ => convert::convert(value.to_bits(), Elementary::Lreal, ty),
    }
}

/// The raw bits of a `BOOL`.
pub fn raw_from_bool(value: bool) -> u64 {
    u64::from(value)
}

/// Whether `raw` of type `ty` is nonzero, which is what every `*_TO_BOOL` returns.
///
/// For reals this is `x <> 0.0`, so `-0.0` is `FALSE` and NaN is `TRUE` (NaN compares unequal
/// to zero, as it does in the C code CODESYS generates).
pub fn is_true(raw: u64, ty: Elementary) -> bool {
    match ty {
        Elementary::Real | Elementary::Lreal => real_value(raw, ty) != 0.0,
        Elementary::Bool => raw & 0xFF != 0,
        _ => raw & mask(ty) != 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Elementary::*;

    #[test]
    fn signed_values_are_sign_extended_from_their_width() {
        assert_eq!(sign_extend(0xFFFF, Int), -1);
        assert_eq!(sign_extend(0xFFFF, Uint), 65535);
        assert_eq!(sign_extend(0x80, Sint), -128);
        assert_eq!(sign_extend(0xFFFF_FFFF, Time), -1);
        assert_eq!(sign_extend(u64::MAX, Lint), -1);
        assert_eq!(int_value(u64::MAX, Ulint), i128::from(u64::MAX));
    }

    #[test]
    fn stored_integers_keep_their_low_bits() {
        assert_eq!(raw_from_i64(-1, Int), 0xFFFF);
        assert_eq!(raw_from_i64(4223, Sint), 0x7F);
        assert_eq!(raw_from_i64(2, Bool), 1);
        assert_eq!(raw_from_real(1.5, Real), u64::from(1.5f32.to_bits()));
        assert_eq!(real_value(u64::from(1.5f32.to_bits()), Real), 1.5);
    }

    #[test]
    fn nan_is_true_and_negative_zero_is_false() {
        assert!(is_true(f64::NAN.to_bits(), Lreal));
        assert!(!is_true((-0.0f64).to_bits(), Lreal));
        assert!(!is_true(0x100, Byte));
    }
}
