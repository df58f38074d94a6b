//! `<T1>_TO_<T2>` and `TRUNC` for every pair of elementary types.
//!
//! The rules, with where they come from:
//! - To `BOOL`: nonzero is `TRUE` (LC1200 §5.3.9); for reals NaN is `TRUE` (see [`super::is_true`]).
//! - From `BOOL`: 0 or 1 in the target's unit, so `BOOL_TO_TIME(TRUE)` is `T#1ms` and
//!   `BOOL_TO_DT(TRUE)` is one second past 1970 (LC1200 §5.3.9).
//! - Between integers, bit strings, `CHAR` and `WCHAR`: the value is widened by its own
//!   signedness (`SINT#-1` becomes `INT#-1`, as in IEC and CODESYS; the Delta manual's tables
//!   that zero-extend signed types are taken as a documentation error) and narrowed by keeping the
//!   low bits (`INT_TO_SINT(4223)` is 127).
//! - Reals to everything else: rounded half away from zero (`REAL_TO_INT(-1.5)` is −2, Delta:
//!   −2.6 → −3), then stored like an integer, so out-of-range values wrap
//!   (LC1200: "CODESYS ignores the upper bytes"; Delta: `REAL_TO_USINT(-2.4)` is 254).
//!   NaN, the infinities and magnitudes of 2¹²⁷ or more have no low bits to keep and give 0.
//! - Integers to reals: the nearest real.
//! - Time and date types to integers and back: the stored count in the type's own unit
//!   (`TIME_TO_DWORD(T#5m)` is 300000, `DATE_TO_INT(D#1970-01-15)` is 29952).
//! - Between time and date types: the value is rescaled between units (`TIME_TO_LTIME` multiplies
//!   by 10⁶); a date-and-time converted to a date keeps the day (`DT_TO_DATE`), and any date type
//!   converted to a time of day keeps the time since midnight (`DT_TO_TOD`).
//!   Rescaling down truncates toward zero for durations and floors for points in time.

use super::{int_value, is_true, raw_from_i128, raw_from_real, real_value};
use program_image::Elementary::{self, *};

/// The raw result of `<from>_TO_<to>` applied to the raw value `raw`.
pub fn convert(raw: u64, from: Elementary, to: Elementary) -> u64 {
    if to == Bool {
        return u64::from(is_true(raw, from));
    }
    match (from.is_real(), to.is_real()) {
        (true, true) => raw_from_real(real_value(raw, from), to),
        (true, false) => raw_from_i128(real_to_integer(real_value(raw, from).round()), to),
        (false, true) => {
            let value = int_value(raw, from);
            // Converting straight to `f32` avoids rounding twice through `f64`.
            match to {
                Real => u64::from((value as f32).to_bits()),
                _ => (value as f64).to_bits(),
            }
        }
        (false, false) => match (time_unit_ns(from), time_unit_ns(to)) {
            (Some(_), Some(_)) if from != to => time_to_time(raw, from, to),
            _ => raw_from_i128(int_value(raw, from), to),
        },
    }
}

/// `TRUNC`: the real `raw` of type `from_real` with its fraction dropped (toward zero), stored in
/// `to_int` by the same wrapping rule as [`convert`] (`TRUNC(-1.4)` is −1).
/// A `from_real` that is not a real is converted as by [`convert`].
pub fn trunc(raw: u64, from_real: Elementary, to_int: Elementary) -> u64 {
    if !from_real.is_real() {
        return convert(raw, from_real, to_int);
    }
    let x = real_value(raw, from_real).trunc();
    if to_int.is_real() {
        return raw_from_real(x, to_int);
    }
    if to_int == Bool {
        return u64::from(x != 0.0 || x.is_nan());
    }
    raw_from_i128(real_to_integer(x), to_int)
}

/// The nanoseconds one count of a time or date type stands for, or `None` for other types.
pub fn time_unit_ns(ty: Elementary) -> Option<i128> {
    match ty {
        Time | TimeOfDay => Some(1_000_000),
        Date | DateAndTime => Some(1_000_000_000),
        Ltime | Ldate | LtimeOfDay | LdateAndTime => Some(1),
        _ => None,
    }
}

/// One day in nanoseconds.
pub(crate) const DAY_NS: i128 = 86_400 * 1_000_000_000;

/// The value of a time or date raw in nanoseconds (since midnight, since 1970 or as a duration).
/// Other types give their integer value.
pub fn time_ns(raw: u64, ty: Elementary) -> i128 {
    int_value(raw, ty) * time_unit_ns(ty).unwrap_or(1)
}

/// The raw `ty` holding `ns` nanoseconds: durations truncate toward zero, points in time
/// (dates, times of day) floor, and the count keeps its low bits.
pub fn raw_from_time_ns(ns: i128, ty: Elementary) -> u64 {
    let unit = time_unit_ns(ty).unwrap_or(1);
    let count = if is_duration(ty) {
        ns / unit
    } else {
        ns.div_euclid(unit)
    };
    raw_from_i128(count, ty)
}

/// `TIME` and `LTIME`, the types that measure a span rather than a point.
fn is_duration(ty: Elementary) -> bool {
    matches!(ty, Time | Ltime)
}

fn is_calendar(ty: Elementary) -> bool {
    matches!(ty, Date | Ldate | DateAndTime | LdateAndTime)
}

fn time_to_time(raw: u64, from: Elementary, to: Elementary) -> u64 {
    rescale_ns(time_ns(raw, from), from, to)
}

/// The raw `to` for `ns` nanoseconds held by a time or date type `from`, by the rules of
/// [`convert`] (a date keeps the day of a date-and-time, a time of day the time since midnight).
pub(crate) fn rescale_ns(ns: i128, from: Elementary, to: Elementary) -> u64 {
    let ns = match to {
        Date | Ldate if is_calendar(from) => ns - ns.rem_euclid(DAY_NS),
        TimeOfDay | LtimeOfDay if is_calendar(from) => ns.rem_euclid(DAY_NS),
        _ => ns,
    };
    raw_from_time_ns(ns, to)
}

/// An integral real as an exact integer, or 0 where there is none to give (NaN, infinite, or
/// too large for `i128`, whose low 64 bits would all be zero anyway above 2¹¹⁶).
fn real_to_integer(x: f64) -> i128 {
    // 2^127 is exactly representable, and every integral f64 below it fits an i128.
    const LIMIT: f64 = 170_141_183_460_469_231_731_687_303_715_884_105_728.0;
    if x.is_finite() && x.abs() < LIMIT {
        x as i128
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stdlib::{raw_from_i64, sign_extend};

    fn real(x: f32) -> u64 {
        u64::from(x.to_bits())
    }

    #[test]
    fn reals_round_half_away_from_zero() {
        assert_eq!(sign_extend(convert(real(2.5), Real, Int), Int), 3);
        assert_eq!(sign_extend(convert(real(-2.5), Real, Int), Int), -3);
        assert_eq!(sign_extend(convert(real(0.49), Real, Int), Int), 0);
    }

    #[test]
    fn out_of_range_reals_wrap_and_nan_gives_zero() {
        assert_eq!(convert(real(-2.4), Real, Usint), 254);
        assert_eq!(convert(real(70000.0), Real, Int), 70000 & 0xFFFF);
        assert_eq!(convert(f64::NAN.to_bits(), Lreal, Dint), 0);
        assert_eq!(convert(f64::INFINITY.to_bits(), Lreal, Lint), 0);
        assert_eq!(convert(1e300f64.to_bits(), Lreal, Ulint), 0);
        assert_eq!(
            convert(1e19f64.to_bits(), Lreal, Ulint),
            10_000_000_000_000_000_000
        );
    }

    #[test]
    fn signed_values_widen_with_their_sign() {
        assert_eq!(convert(0x80, Sint, Int), 0xFF80);
        assert_eq!(convert(0x80, Usint, Int), 0x80);
        assert_eq!(convert(0xFFFF, Int, Ulint), u64::MAX);
    }

    #[test]
    fn time_types_rescale_between_units() {
        assert_eq!(convert(1500, Time, Ltime), 1_500_000_000);
        assert_eq!(
            convert(raw_from_i64(-1_500_000_001, Ltime), Ltime, Time),
            raw_from_i64(-1500, Time)
        );
        let dt = 1_227_905u64; // DT#1970-01-15-05:05:05
        assert_eq!(convert(dt, DateAndTime, Date), 14 * 86_400);
        assert_eq!(convert(dt, DateAndTime, TimeOfDay), 18_305_000);
        assert_eq!(convert(dt, DateAndTime, LtimeOfDay), 18_305_000_000_000);
        assert_eq!(
            convert(dt, DateAndTime, LdateAndTime),
            1_227_905_000_000_000
        );
    }

    #[test]
    fn trunc_drops_the_fraction() {
        assert_eq!(sign_extend(trunc(real(-5.6), Real, Lint), Lint), -5);
        assert_eq!(trunc(real(1.9), Real, Dint), 1);
    }
}
