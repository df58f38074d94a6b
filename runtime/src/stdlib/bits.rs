//! `SHL`, `SHR`, `ROL` and `ROR`, sized by the type of the operand.
//!
//! The width is the operand type's (LC1200 §5.3: `ROR(BYTE#16#45, 2)` is `16#51`, the same bits
//! as a `WORD` give `16#4011`).
//! Shifts work on the bit pattern for every type: `SHR` fills with zeros on signed types too,
//! as IEC defines it for `ANY_BIT`, so `SHR(INT#-16, 2)` is `16#3FFC`.
//! A shift by the width or more gives 0 (Delta 8.11); a rotation counts modulo the width.
//! The count is taken as unsigned, so a negative count converted to `u64` is a large count.

use super::{mask, width_bits};
use program_image::Elementary;

/// `SHL(raw, n)`: `raw` shifted left by `n` bits within the width of `ty`.
pub fn shl(raw: u64, n: u64, ty: Elementary) -> u64 {
    if n >= u64::from(width_bits(ty)) {
        return 0;
    }
    (raw << n) & mask(ty)
}

/// `SHR(raw, n)`: `raw` shifted right by `n` bits within the width of `ty`, filling with zeros.
pub fn shr(raw: u64, n: u64, ty: Elementary) -> u64 {
    if n >= u64::from(width_bits(ty)) {
        return 0;
    }
    (raw & mask(ty)) >> n
}

/// `ROL(raw, n)`: `raw` rotated left by `n` modulo the width of `ty`.
pub fn rol(raw: u64, n: u64, ty: Elementary) -> u64 {
    let width = u64::from(width_bits(ty));
    let n = n % width;
    let bits = raw & mask(ty);
    if n == 0 {
        return bits;
    }
    ((bits << n) | (bits >> (width - n))) & mask(ty)
}

/// `ROR(raw, n)`: `raw` rotated right by `n` modulo the width of `ty`.
pub fn ror(raw: u64, n: u64, ty: Elementary) -> u64 {
    let width = u64::from(width_bits(ty));
    rol(raw, width - n % width, ty)
}

#[cfg(test)]
mod tests {
    use super::*;
    use Elementary::*;

    #[test]
    fn shifts_by_the_width_or_more_give_zero() {
        assert_eq!(shl(0xFF, 8, Byte), 0);
        assert_eq!(shr(0xFF, 8, Byte), 0);
        assert_eq!(shl(1, 63, Lword), 1 << 63);
        assert_eq!(shl(1, u64::MAX, Lword), 0);
    }

    #[test]
    fn rotations_count_modulo_the_width() {
        assert_eq!(rol(0x45, 10, Byte), rol(0x45, 2, Byte));
        assert_eq!(ror(0x8000_0000_0000_0001, 1, Lword), 0xC000_0000_0000_0000);
        assert_eq!(rol(0x45, 8, Byte), 0x45);
    }

    #[test]
    fn shr_fills_signed_types_with_zeros() {
        assert_eq!(shr(0xFFF0, 2, Int), 0x3FFC);
    }

    #[test]
    fn bool_is_one_bit_wide() {
        assert_eq!(rol(1, 5, Bool), 1);
        assert_eq!(shl(1, 1, Bool), 0);
    }
}
