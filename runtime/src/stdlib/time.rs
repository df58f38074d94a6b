//! Date and time functions: `CONCAT_*`, `SPLIT_*`, `DAY_OF_WEEK` and the arithmetic of durations,
//! times of day and dates, over the proleptic Gregorian calendar.
//!
//! The arithmetic is written once over nanoseconds and serves every IEC name:
//!
//! | IEC / CODESYS | here |
//! |---|---|
//! | `ADD_TIME`, `ADD_LTIME`, `ADD_TOD_TIME`, `ADD_DT_TIME`, `ADD_LDT_LTIME`… | [`add_duration`] |
//! | `SUB_TIME`, `SUB_TOD_TIME`, `SUB_DT_TIME`… | [`sub_duration`] |
//! | `SUB_DATE_DATE`, `SUB_TOD_TOD`, `SUB_DT_DT`, `SUB_LDT_LDT`… | [`difference`] |
//! | `MUL_TIME`, `MUL_LTIME` | [`mul_duration_int`], [`mul_duration_real`] |
//! | `DIV_TIME`, `DIV_LTIME` | [`div_duration_int`], [`div_duration_real`] |
//! | `DT_TO_DATE`, `DT_TO_TOD`… | [`super::convert::convert`] |
//!
//! Results keep the low bits of their type like every integer result, so a sum past
//! `DT#2106-02-07-06:28:15` wraps.
//! A `TOD` plus a `TIME` is not reduced modulo a day, as in CODESYS, which adds the counts;
//! `TOD_TO_STRING` shows such a value modulo a day.
//! Invalid calendar inputs to `CONCAT_*` (month 13, February 30, hour 24…) give 0, the 1970 epoch.

use super::convert::{DAY_NS, raw_from_time_ns, time_ns, time_unit_ns};
use super::{int_value, raw_from_i64, raw_from_i128};
use program_image::Elementary;

/// A calendar date and time of day, as `SPLIT_DT` gives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DateTimeParts {
    /// The year, such as 2024 (negative before year 1).
    pub year: i64,
    /// The month, 1 to 12.
    pub month: u32,
    /// The day of the month, 1 to 31.
    pub day: u32,
    /// The hour, 0 to 23.
    pub hour: u32,
    /// The minute, 0 to 59.
    pub minute: u32,
    /// The second, 0 to 59.
    pub second: u32,
    /// The nanoseconds within the second (a multiple of 10⁶ for the 32-bit types).
    pub nanosecond: u32,
}

impl DateTimeParts {
    /// The milliseconds within the second, which is what `SPLIT_DT` and `SPLIT_TOD` return.
    pub fn millisecond(&self) -> u32 {
        self.nanosecond / 1_000_000
    }
}

/// The days since 1970-01-01 of a proleptic Gregorian date; `month` and `day` are not checked.
pub fn days_from_civil(year: i64, month: u32, day: u32) -> i64 {
    // Howard Hinnant's algorithm: count in 400-year eras that start on 1 March, so that the leap
    // day falls at the end of the counted year.
    let year = if month <= 2 { year - 1 } else { year };
    let era = year.div_euclid(400);
    let year_of_era = year - era * 400;
    let month = i64::from(month);
    let day_of_year =
        (153 * (if month > 2 { month - 3 } else { month + 9 }) + 2) / 5 + i64::from(day) - 1;
    let day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
    era * 146_097 + day_of_era - 719_468
}

/// The proleptic Gregorian `(year, month, day)` of a count of days since 1970-01-01.
pub fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let days = days + 719_468;
    let era = days.div_euclid(146_097);
    let day_of_era = days - era * 146_097;
    let year_of_era =
        (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let month_from_march = (5 * day_of_year + 2) / 153;
    let day = (day_of_year - (153 * month_from_march + 2) / 5 + 1) as u32;
    let month = if month_from_march < 10 {
        month_from_march + 3
    } else {
        month_from_march - 9
    } as u32;
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

/// The number of days of `month` in `year`, or 0 for a month outside 1 to 12.
pub fn days_in_month(year: i64, month: u32) -> u32 {
    match month {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        2 if year % 4 == 0 && (year % 100 != 0 || year % 400 == 0) => 29,
        2 => 28,
        _ => 0,
    }
}

/// The parts of a date or time raw of type `ty` (any time or date type; durations and times of
/// day count from 1970-01-01 midnight, so their date parts are those of the epoch and later days).
pub fn split(raw: u64, ty: Elementary) -> DateTimeParts {
    parts_from_ns(time_ns(raw, ty))
}

/// The parts of a count of nanoseconds since 1970-01-01 00:00.
pub fn parts_from_ns(ns: i128) -> DateTimeParts {
    let days = ns.div_euclid(DAY_NS);
    let in_day = ns.rem_euclid(DAY_NS);
    let (year, month, day) = civil_from_days(days as i64);
    let seconds = (in_day / 1_000_000_000) as u32;
    DateTimeParts {
        year,
        month,
        day,
        hour: seconds / 3600,
        minute: seconds / 60 % 60,
        second: seconds % 60,
        nanosecond: (in_day % 1_000_000_000) as u32,
    }
}

/// The nanoseconds since 1970-01-01 00:00 of valid calendar parts, or `None` if a part is out
/// of range.
pub fn ns_from_parts(parts: &DateTimeParts) -> Option<i128> {
    let valid = (1..=days_in_month(parts.year, parts.month)).contains(&parts.day)
        && parts.hour < 24
        && parts.minute < 60
        && parts.second < 60
        && parts.nanosecond < 1_000_000_000;
    if !valid || parts.year.unsigned_abs() > 1_000_000_000 {
        return None;
    }
    let days = i128::from(days_from_civil(parts.year, parts.month, parts.day));
    let seconds = i128::from(parts.hour * 3600 + parts.minute * 60 + parts.second);
    Some(days * DAY_NS + seconds * 1_000_000_000 + i128::from(parts.nanosecond))
}

/// `CONCAT_DATE(year, month, day)` as a raw `ty` (`DATE` or `LDATE`); 0 if the date is invalid.
pub fn concat_date(year: i64, month: i64, day: i64, ty: Elementary) -> u64 {
    concat_dt(year, month, day, 0, 0, 0, 0, ty)
}

/// `CONCAT_TOD(hour, minute, second, millisecond)` as a raw `ty` (`TOD` or `LTOD`); 0 if a part
/// is out of range.
pub fn concat_tod(hour: i64, minute: i64, second: i64, millisecond: i64, ty: Elementary) -> u64 {
    concat_dt(1970, 1, 1, hour, minute, second, millisecond, ty)
}

/// `CONCAT_DT(year, month, day, hour, minute, second, millisecond)` as a raw `ty` (`DT`, whose
/// resolution drops the milliseconds, or `LDT`); 0 if a part is out of range.
#[allow(clippy::too_many_arguments)] // The IEC function has these seven inputs.
pub fn concat_dt(
    year: i64,
    month: i64,
    day: i64,
    hour: i64,
    minute: i64,
    second: i64,
    millisecond: i64,
    ty: Elementary,
) -> u64 {
    let part = |value: i64| u32::try_from(value).unwrap_or(u32::MAX);
    if !(0..1000).contains(&millisecond) {
        return 0;
    }
    let parts = DateTimeParts {
        year,
        month: part(month),
        day: part(day),
        hour: part(hour),
        minute: part(minute),
        second: part(second),
        nanosecond: part(millisecond) * 1_000_000,
    };
    ns_from_parts(&parts).map_or(0, |ns| raw_from_time_ns(ns, ty))
}

/// `CONCAT_DATE_TOD(date, tod)` (and `CONCAT_LDATE_LTOD`): the day of `date` at the time of day
/// `tod`, as a raw `to` (`DT` or `LDT`).
pub fn concat_date_tod(
    date: u64,
    date_ty: Elementary,
    tod: u64,
    tod_ty: Elementary,
    to: Elementary,
) -> u64 {
    let day = time_ns(date, date_ty).div_euclid(DAY_NS) * DAY_NS;
    raw_from_time_ns(day + time_ns(tod, tod_ty), to)
}

/// `DAY_OF_WEEK(date)`: 0 for Sunday to 6 for Saturday (IEC 61131-3 3rd edition), for any date
/// type.
pub fn day_of_week(raw: u64, ty: Elementary) -> u64 {
    let days = time_ns(raw, ty).div_euclid(DAY_NS);
    // 1970-01-01 was a Thursday.
    (days + 4).rem_euclid(7) as u64
}

/// `ADD`: the point in time or duration `a` of type `a_ty` moved by the duration `d` of type
/// `d_ty`, as an `a_ty` (`TIME + TIME`, `TOD + TIME`, `DT + TIME`, `LDT + LTIME`…).
pub fn add_duration(a: u64, a_ty: Elementary, d: u64, d_ty: Elementary) -> u64 {
    raw_from_time_ns(time_ns(a, a_ty) + time_ns(d, d_ty), a_ty)
}

/// `SUB`: the point in time or duration `a` moved back by the duration `d`, as an `a_ty`.
pub fn sub_duration(a: u64, a_ty: Elementary, d: u64, d_ty: Elementary) -> u64 {
    raw_from_time_ns(time_ns(a, a_ty) - time_ns(d, d_ty), a_ty)
}

/// `SUB` of two values of the same time or date type `ty`: the duration `a − b` as a `to`
/// (`TIME` or `LTIME`), so `SUB(DATE#2016-10-1, DATE#2016-9-1)` is `TIME#30d`.
pub fn difference(a: u64, b: u64, ty: Elementary, to: Elementary) -> u64 {
    raw_from_time_ns(time_ns(a, ty) - time_ns(b, ty), to)
}

/// `MUL_TIME(t, k)` with an integer factor: the count times `k`, wrapping.
pub fn mul_duration_int(t: u64, ty: Elementary, k: i64) -> u64 {
    raw_from_i128(int_value(t, ty).wrapping_mul(i128::from(k)), ty)
}

/// `MUL_TIME(t, k)` with a real factor: the product rounded half away from zero to the type's
/// unit, stored like a real converted to an integer (NaN gives 0).
pub fn mul_duration_real(t: u64, ty: Elementary, k: f64) -> u64 {
    let product = int_value(t, ty) as f64 * k;
    super::raw_from_real(product, Elementary::Lint) & super::mask(ty)
}

/// `DIV_TIME(t, k)` with an integer divisor: the count divided by `k`, truncated toward zero;
/// division by zero gives 0 (Delta 8.9: `DIV` by 0 outputs 0).
pub fn div_duration_int(t: u64, ty: Elementary, k: i64) -> u64 {
    if k == 0 {
        return 0;
    }
    raw_from_i128(int_value(t, ty) / i128::from(k), ty)
}

/// `DIV_TIME(t, k)` with a real divisor: the quotient rounded half away from zero; division by
/// zero gives 0.
pub fn div_duration_real(t: u64, ty: Elementary, k: f64) -> u64 {
    if k == 0.0 {
        return 0;
    }
    mul_duration_real(t, ty, 1.0 / k)
}

/// The count of `ty` that stands for `ns` nanoseconds, truncated toward zero, as a raw value;
/// a helper for engines that hold times as plain numbers.
pub fn raw_from_ns(ns: i64, ty: Elementary) -> u64 {
    match time_unit_ns(ty) {
        Some(unit) => raw_from_i128(i128::from(ns) / unit, ty),
        None => raw_from_i64(ns, ty),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use Elementary::*;

    #[test]
    fn civil_dates_round_trip_over_centuries() {
        for days in (-800_000..800_000).step_by(97) {
            let (year, month, day) = civil_from_days(days);
            assert_eq!(days_from_civil(year, month, day), days);
        }
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(days_from_civil(2000, 3, 1), 11_017);
        assert_eq!(civil_from_days(days_from_civil(2024, 2, 29)), (2024, 2, 29));
    }

    #[test]
    fn invalid_dates_give_the_epoch() {
        assert_eq!(concat_date(2023, 2, 29, Date), 0);
        assert_eq!(concat_date(2024, 13, 1, Date), 0);
        assert_eq!(concat_tod(24, 0, 0, 0, TimeOfDay), 0);
        assert_eq!(concat_tod(1, 2, 3, 1000, TimeOfDay), 0);
        assert_eq!(
            concat_date(2024, 2, 29, Date),
            days_from_civil(2024, 2, 29) as u64 * 86_400
        );
    }

    #[test]
    fn splitting_gives_back_the_parts() {
        let dt = concat_dt(2024, 1, 31, 12, 30, 5, 0, DateAndTime);
        let parts = split(dt, DateAndTime);
        assert_eq!((parts.year, parts.month, parts.day), (2024, 1, 31));
        assert_eq!(
            (parts.hour, parts.minute, parts.second, parts.millisecond()),
            (12, 30, 5, 0)
        );
        let tod = concat_tod(23, 59, 59, 999, TimeOfDay);
        assert_eq!(tod, 86_399_999);
        assert_eq!(split(tod, TimeOfDay).millisecond(), 999);
    }

    #[test]
    fn day_of_week_counts_from_sunday() {
        assert_eq!(day_of_week(0, Date), 4);
        assert_eq!(day_of_week(concat_date(2024, 1, 28, Date), Date), 0);
    }

    #[test]
    fn durations_multiply_and_divide_without_panicking() {
        assert_eq!(mul_duration_int(1500, Time, 3), 4500);
        assert_eq!(div_duration_int(1500, Time, 0), 0);
        assert_eq!(div_duration_int(0x8000_0000, Time, -1), 0x8000_0000);
        assert_eq!(mul_duration_real(1000, Time, 1.5), 1500);
        assert_eq!(div_duration_real(1000, Time, 0.0), 0);
        assert_eq!(mul_duration_real(1000, Time, f64::NAN), 0);
    }
}
