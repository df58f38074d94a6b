//! Numeric functions whose edges CODESYS or the Delta manual define: `DIV` and `MOD` on integers,
//! `EXPT`, `FLOOR`, `FRACTION` and Delta's `MODREAL`, `MODTURNS` and `MODABS`.
//!
//! `MIN`, `MAX`, `LIMIT`, `SEL` and `MUX` are one comparison each and are left to the engine.

use super::{int_value, raw_from_i128};
use program_image::Elementary;

/// `DIV(a, b)` on the integer type `ty`: the quotient truncated toward zero, wrapping
/// (`DIV(INT#-32768, -1)` is −32768); division by zero gives 0 (Delta 8.9).
pub fn div(a: u64, b: u64, ty: Elementary) -> u64 {
    let divisor = int_value(b, ty);
    if divisor == 0 {
        return 0;
    }
    raw_from_i128(int_value(a, ty) / divisor, ty)
}

/// `MOD(a, b)` on the integer type `ty`: the remainder with the sign of the dividend
/// (`MOD(-7, 2)` is −1, as `a − (a / b)·b` gives it); modulo zero gives 0 (Delta 8.9).
pub fn modulo(a: u64, b: u64, ty: Elementary) -> u64 {
    let divisor = int_value(b, ty);
    if divisor == 0 {
        return 0;
    }
    raw_from_i128(int_value(a, ty) % divisor, ty)
}

/// `EXPT(base, exponent)` on integers: the power, wrapping like multiplication.
///
/// A negative exponent gives the truncated real result: 1 for a base of 1, ±1 for a base of −1,
/// 0 otherwise, and 0 for a base of 0 (where the real result would be infinite).
pub fn expt_int(base: i64, exponent: i64) -> i64 {
    if exponent < 0 {
        return match base {
            1 => 1,
            -1 if exponent % 2 == 0 => 1,
            -1 => -1,
            _ => 0,
        };
    }
    let mut result: i64 = 1;
    let mut square = base;
    let mut remaining = exponent as u64;
    // Square-and-multiply stays fast for any exponent; wrapping keeps the low bits, as an
    // overflowing multiplication does.
    while remaining > 0 {
        if remaining & 1 == 1 {
            result = result.wrapping_mul(square);
        }
        square = square.wrapping_mul(square);
        remaining >>= 1;
    }
    result
}

/// `EXPT(base, exponent)` on reals (`EXPT(-10, 2)` is 100): `powf`, whose edge cases are C's
/// `pow`: a negative base with a non-integral exponent gives NaN, 0 to a negative power gives
/// infinity, anything to the power 0 gives 1.
pub fn expt_real(base: f64, exponent: f64) -> f64 {
    base.powf(exponent)
}

/// Delta's `FLOOR`: the largest integer not above `x`, as an `i64` (`FLOOR(-10.2)` is −11);
/// NaN gives 0 and values beyond the `LINT` range saturate.
pub fn floor(x: f64) -> i64 {
    x.floor() as i64
}

/// Delta's `FRACTION`: the fractional part with the sign of `x` (`FRACTION(-5.6)` is −0.6).
pub fn fraction(x: f64) -> f64 {
    x.fract()
}

/// Delta's `MODREAL(a, b)`: the real remainder with the sign of `a` (`MODREAL(10.5, 2.5)` is 0.5);
/// a divisor of 0 gives 0, as `MOD` does.
pub fn modreal(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        return 0.0;
    }
    a % b
}

/// Delta's `MODTURNS(a, b)`: the whole number of times `b` fits in `a`, truncated toward zero
/// (`MODTURNS(800.23, 360)` is 2); a divisor of 0 gives 0.
pub fn modturns(a: f64, b: f64) -> i64 {
    if b == 0.0 {
        return 0;
    }
    (a / b).trunc() as i64
}

/// Delta's `MODABS(a, b)`: the remainder in `0..|b|` (`MODABS(-400.23, 360)` is 319.77);
/// a divisor of 0 gives 0.
pub fn modabs(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        return 0.0;
    }
    a.rem_euclid(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stdlib::{raw_from_i64, sign_extend};
    use Elementary::*;

    #[test]
    fn mod_takes_the_sign_of_the_dividend() {
        let m = |a, b| sign_extend(modulo(raw_from_i64(a, Int), raw_from_i64(b, Int), Int), Int);
        assert_eq!(m(-7, 2), -1);
        assert_eq!(m(7, -2), 1);
        assert_eq!(m(7, 0), 0);
        assert_eq!(m(-32768, -1), 0);
    }

    #[test]
    fn division_by_zero_gives_zero() {
        assert_eq!(div(10, 0, Uint), 0);
        assert_eq!(div(u64::MAX, 3, Ulint), u64::MAX / 3);
    }

    #[test]
    fn integer_powers_wrap_and_negative_exponents_truncate() {
        assert_eq!(expt_int(2, 63), i64::MIN);
        assert_eq!(expt_int(2, 64), 0);
        assert_eq!(expt_int(3, 5), 243);
        assert_eq!(expt_int(-3, 3), -27);
        assert_eq!(expt_int(2, -1), 0);
        assert_eq!(expt_int(-1, -3), -1);
        assert_eq!(expt_int(0, 0), 1);
    }

    #[test]
    fn real_edges_are_defined() {
        assert!(expt_real(-8.0, 1.0 / 3.0).is_nan());
        assert_eq!(floor(f64::NAN), 0);
        assert_eq!(modreal(1.0, 0.0), 0.0);
        assert_eq!(modturns(1.0, 0.0), 0);
        assert_eq!(modabs(1.0, 0.0), 0.0);
    }
}

/// Binary-coded decimal: each decimal digit of `raw` (unsigned) in one nibble, lowest digit in
/// the lowest nibble; digits beyond 16 are dropped with the bits that would hold them.
pub fn to_bcd(raw: u64) -> u64 {
    let mut value = raw;
    let mut bcd = 0u64;
    for nibble in 0..16 {
        bcd |= (value % 10) << (4 * nibble);
        value /= 10;
        if value == 0 {
            break;
        }
    }
    bcd
}

/// The value of a binary-coded decimal; a nibble above 9 counts as 9, as the digit it
/// cannot be.
pub fn from_bcd(raw: u64) -> u64 {
    (0..16).rev().fold(0u64, |value, nibble| {
        value * 10 + ((raw >> (4 * nibble)) & 0xF).min(9)
    })
}

#[cfg(test)]
mod bcd_tests {
    use super::*;

    #[test]
    fn bcd_round_trips_decimal_digits() {
        assert_eq!(to_bcd(1234), 0x1234);
        assert_eq!(from_bcd(0x1234), 1234);
        assert_eq!(to_bcd(0), 0);
        assert_eq!(from_bcd(0x9A), 99);
    }
}
