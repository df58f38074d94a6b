//! `<T>_TO_STRING` and `STRING_TO_<T>`: values as CODESYS writes them and literals read back.
//!
//! [`to_text`] writes:
//! - `BOOL` as `TRUE` or `FALSE`;
//! - integers and bit strings in decimal (`INT_TO_STRING(-5)` is `'-5'`, `BYTE_TO_STRING(255)` is
//!   `'255'`, as CODESYS does; the Delta manual's hexadecimal form for bit strings is not used);
//! - reals with the fewest digits that read back to the same value, without a trailing `.0`,
//!   switching to an exponent (`1.5E+20`) below 10⁻⁵ and from 10¹⁵ on, and `NaN`, `INF`, `-INF`;
//! - `TIME` as `T#1d2h3m4s5ms` without zero parts (`T#0ms` for zero, `T#-1s` below zero) and
//!   `LTIME` as `LTIME#…` down to `us` and `ns`;
//! - `DATE` as `D#2024-01-31`, `TOD` as `TOD#12:30:00` (with `.001` when there are milliseconds,
//!   modulo a day like the Delta display of `TOD#17:2:47.295`), `DT` as `DT#2024-01-31-12:30:00`
//!   and the long forms as `LDATE#…`, `LTOD#…`, `LDT#…` with up to nine fraction digits;
//! - `CHAR` and `WCHAR` as the character itself (a byte is read as Latin-1).
//!
//! [`from_text`] reads what [`to_text`] writes and IEC literals: typed ones (`'INT#-5'`,
//! `'WORD#16#FF'`, `'T#5s'`, `'REAL#1.5'`), based integers (`'16#FF'`, `'2#1010'`), underscores
//! between digits, and surrounding blanks.
//! Like CODESYS it reads the literal at the start and ignores what follows (`'34abc'` is 34) and
//! keeps the low bits of an integer that does not fit (`STRING_TO_BYTE('500')` is 244).
//! Text that starts with no literal gives 0 (Delta's controller keeps the previous value instead;
//! a pure function has none to keep).
//! A literal of another type is converted as [`convert`] converts (`STRING_TO_DWORD('T#5m')` is
//! 300000); `STRING_TO_BOOL` is `TRUE` only for `'TRUE'` in any case or a nonzero typed literal.

use super::convert::{DAY_NS, convert, rescale_ns, time_ns};
use super::time::{DateTimeParts, ns_from_parts, parts_from_ns};
use super::{int_value, raw_from_i128, raw_from_real, real_value};
use program_image::Elementary::{self, *};
use std::fmt::Write as _;

/// The text `<from>_TO_STRING` gives for the raw value `raw`.
pub fn to_text(raw: u64, from: Elementary) -> String {
    match from {
        Bool => if raw & 0xFF != 0 { "TRUE" } else { "FALSE" }.to_string(),
        Real | Lreal => real_text(real_value(raw, from), from),
        Time => duration_text("T#", time_ns(raw, from), 1_000_000),
        Ltime => duration_text("LTIME#", time_ns(raw, from), 1),
        Date => format!("D#{}", date_text(time_ns(raw, from))),
        Ldate => format!("LDATE#{}", date_text(time_ns(raw, from))),
        TimeOfDay => format!("TOD#{}", clock_text(time_ns(raw, from), 3)),
        LtimeOfDay => format!("LTOD#{}", clock_text(time_ns(raw, from), 9)),
        DateAndTime => format!("DT#{}", date_time_text(time_ns(raw, from), 0)),
        LdateAndTime => format!("LDT#{}", date_time_text(time_ns(raw, from), 9)),
        Char => char::from(raw as u8).to_string(),
        Wchar => char::from_u32((raw & 0xFFFF) as u32)
            .unwrap_or(char::REPLACEMENT_CHARACTER)
            .to_string(),
        _ => int_value(raw, from).to_string(),
    }
}

/// [`to_text`] as the single-byte characters of a `STRING`: Latin-1, with `?` for a character
/// beyond it (only a `WCHAR` can produce one).
pub fn to_text_bytes(raw: u64, from: Elementary) -> Vec<u8> {
    to_text(raw, from)
        .chars()
        .map(|c| u8::try_from(c).unwrap_or(b'?'))
        .collect()
}

/// [`to_text`] as the UTF-16 code units of a `WSTRING`.
pub fn to_wtext(raw: u64, from: Elementary) -> Vec<u16> {
    match from {
        // A lone surrogate is still one code unit of a `WSTRING`, so it is kept as it is.
        Wchar => vec![(raw & 0xFFFF) as u16],
        _ => to_text(raw, from).encode_utf16().collect(),
    }
}

/// The raw value `STRING_TO_<to>` gives for `text` (the characters of a `STRING`, without its
/// terminator); 0 when no literal starts the text.
pub fn from_text(text: &[u8], to: Elementary) -> u64 {
    if matches!(to, Char | Wchar) {
        // A character conversion takes the first character as it is, blanks included.
        return text.first().map_or(0, |&c| u64::from(c));
    }
    let text = text.trim_ascii();
    if to == Bool && text.eq_ignore_ascii_case(b"TRUE") {
        return 1;
    }
    match parse_literal(text, to) {
        Some(literal) => literal.to_raw(to),
        None => 0,
    }
}

/// [`from_text`] for the code units of a `WSTRING`; units beyond Latin-1 cannot be part of a
/// literal and stand for a character that ends it.
pub fn from_wtext(units: &[u16], to: Elementary) -> u64 {
    if to == Wchar {
        return units.first().map_or(0, |&unit| u64::from(unit));
    }
    let bytes: Vec<u8> = units
        .iter()
        .map(|&unit| u8::try_from(unit).unwrap_or(0xFF))
        .collect();
    from_text(&bytes, to)
}

/// A literal read from text, before it is stored in the target type.
enum Literal {
    /// An integer (typed or not), exact in its low 128 bits.
    Integer(i128),
    /// A real.
    Real(f64),
    /// `TRUE` or `FALSE` from a `BOOL#` literal.
    Bool(bool),
    /// Nanoseconds held by a time or date literal of the given type.
    Time(i128, Elementary),
}

impl Literal {
    fn to_raw(&self, to: Elementary) -> u64 {
        match *self {
            Literal::Integer(value) if to.is_real() => raw_from_real(value as f64, to),
            Literal::Integer(value) => raw_from_i128(value, to),
            Literal::Real(value) => raw_from_real(value, to),
            Literal::Bool(value) => convert(u64::from(value), Bool, to),
            Literal::Time(ns, ty) => {
                if super::convert::time_unit_ns(to).is_some() {
                    rescale_ns(ns, ty, to)
                } else {
                    convert(rescale_ns(ns, ty, ty), ty, to)
                }
            }
        }
    }
}

fn parse_literal(text: &[u8], to: Elementary) -> Option<Literal> {
    let hash = text.iter().position(|&c| c == b'#');
    if let Some(hash) = hash {
        let prefix = &text[..hash];
        if !prefix.is_empty() && prefix.iter().all(|c| c.is_ascii_alphabetic() || *c == b'_') {
            return parse_typed(prefix, &text[hash + 1..], to);
        }
    }
    match to {
        Real | Lreal => parse_real(text, to),
        Bool => None,
        _ => parse_integer(text).map(Literal::Integer),
    }
}

fn parse_typed(prefix: &[u8], rest: &[u8], to: Elementary) -> Option<Literal> {
    let name = prefix.to_ascii_uppercase();
    let time_type = match name.as_slice() {
        b"T" | b"TIME" => Some(Time),
        b"LT" | b"LTIME" => Some(Ltime),
        b"D" | b"DATE" => Some(Date),
        b"LD" | b"LDATE" => Some(Ldate),
        b"TOD" | b"TIME_OF_DAY" => Some(TimeOfDay),
        b"LTOD" | b"LTIME_OF_DAY" => Some(LtimeOfDay),
        b"DT" | b"DATE_AND_TIME" => Some(DateAndTime),
        b"LDT" | b"LDATE_AND_TIME" => Some(LdateAndTime),
        _ => None,
    };
    if let Some(ty) = time_type {
        let ns = match ty {
            Time | Ltime => parse_duration(rest)?,
            Date | Ldate => parse_date(rest)?.0,
            TimeOfDay | LtimeOfDay => parse_clock(rest)?.0,
            _ => parse_date_time(rest)?,
        };
        return Some(Literal::Time(ns, ty));
    }
    let ty = Elementary::ALL
        .into_iter()
        .find(|ty| ty.name().as_bytes() == name.as_slice())?;
    match ty {
        Bool => {
            if rest.eq_ignore_ascii_case(b"TRUE") {
                Some(Literal::Bool(true))
            } else if rest.eq_ignore_ascii_case(b"FALSE") {
                Some(Literal::Bool(false))
            } else {
                parse_integer(rest).map(|value| Literal::Bool(value != 0))
            }
        }
        Real | Lreal => parse_real(rest, if to.is_real() { to } else { ty }),
        _ => parse_integer(rest).map(Literal::Integer),
    }
}

/// An integer at the start of `text`: an optional sign, then decimal digits or a base
/// (`2#`, `8#`, `16#`) and its digits, with single underscores between digits.
/// The value wraps in 128 bits, which keeps every low bit a target can hold.
fn parse_integer(text: &[u8]) -> Option<i128> {
    let (negative, text) = split_sign(text);
    let (decimal, used) = digits(text, 10);
    let decimal = decimal?;
    let value = match text.get(used) {
        Some(b'#') if matches!(decimal, 2 | 8 | 16) => {
            digits(&text[used + 1..], decimal as u32).0?
        }
        _ => decimal,
    };
    let value = value as i128;
    Some(if negative {
        value.wrapping_neg()
    } else {
        value
    })
}

/// The value of the digits in `radix` at the start of `text` and the bytes they take, or `None`
/// if there are none.
fn digits(text: &[u8], radix: u32) -> (Option<u128>, usize) {
    let mut value: Option<u128> = None;
    let mut used = 0;
    while let Some(&c) = text.get(used) {
        if c == b'_'
            && value.is_some()
            && text
                .get(used + 1)
                .is_some_and(|c| char::from(*c).is_digit(radix))
        {
            used += 1;
            continue;
        }
        let Some(digit) = char::from(c).to_digit(radix) else {
            break;
        };
        value = Some(
            value
                .unwrap_or(0)
                .wrapping_mul(u128::from(radix))
                .wrapping_add(u128::from(digit)),
        );
        used += 1;
    }
    (value, used)
}

fn split_sign(text: &[u8]) -> (bool, &[u8]) {
    match text.first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    }
}

/// A real at the start of `text`, read as `ty` (an `f32` is read directly, not through `f64`).
fn parse_real(text: &[u8], ty: Elementary) -> Option<Literal> {
    let (negative, unsigned) = split_sign(text);
    for (word, value) in [
        (&b"NAN"[..], f64::NAN),
        (b"INFINITY", f64::INFINITY),
        (b"INF", f64::INFINITY),
    ] {
        if unsigned.len() >= word.len() && unsigned[..word.len()].eq_ignore_ascii_case(word) {
            return Some(Literal::Real(if negative { -value } else { value }));
        }
    }
    // A based integer (`16#FF`) is a valid real constant too.
    if let (Some(_), used) = digits(unsigned, 10)
        && unsigned.get(used) == Some(&b'#')
    {
        return parse_integer(text).map(|value| Literal::Real(value as f64));
    }
    let mut number = String::new();
    if negative {
        number.push('-');
    }
    let (integral, used) = digits(unsigned, 10);
    integral?;
    push_digits(&mut number, &unsigned[..used]);
    let mut rest = &unsigned[used..];
    if rest.first() == Some(&b'.') {
        let (fraction, used) = digits(&rest[1..], 10);
        if fraction.is_some() {
            number.push('.');
            push_digits(&mut number, &rest[1..1 + used]);
            rest = &rest[1 + used..];
        }
    }
    if let Some(b'e' | b'E') = rest.first() {
        let (negative_exponent, exponent_text) = split_sign(&rest[1..]);
        let (exponent, used) = digits(exponent_text, 10);
        if exponent.is_some() {
            number.push('e');
            if negative_exponent {
                number.push('-');
            }
            push_digits(&mut number, &exponent_text[..used]);
        }
    }
    let value = if ty == Real {
        number.parse::<f32>().ok().map(f64::from)
    } else {
        number.parse::<f64>().ok()
    };
    value.map(Literal::Real)
}

fn push_digits(number: &mut String, digits: &[u8]) {
    number.extend(
        digits
            .iter()
            .filter(|&&c| c != b'_')
            .map(|&c| char::from(c)),
    );
}

/// The nanoseconds of a duration such as `1d2h3m4s5ms`, `-1.5s` or `1_000ms`.
fn parse_duration(text: &[u8]) -> Option<i128> {
    const UNITS: [(&[u8], i128); 7] = [
        (b"ms", 1_000_000),
        (b"us", 1_000),
        (b"ns", 1),
        (b"d", DAY_NS),
        (b"h", 3_600_000_000_000),
        (b"m", 60_000_000_000),
        (b"s", 1_000_000_000),
    ];
    let (negative, mut rest) = split_sign(text);
    let mut total: i128 = 0;
    let mut any = false;
    loop {
        let (whole, used) = digits(rest, 10);
        let Some(whole) = whole else { break };
        let mut after = &rest[used..];
        let mut fraction: &[u8] = &[];
        if after.first() == Some(&b'.') {
            let (_, used) = digits(&after[1..], 10);
            fraction = &after[1..1 + used];
            after = &after[1 + used..];
        }
        let Some(&(unit_name, unit_ns)) = UNITS.iter().find(|(name, _)| {
            after.len() >= name.len() && after[..name.len()].eq_ignore_ascii_case(name)
        }) else {
            break;
        };
        let whole = i128::try_from(whole).unwrap_or(i128::MAX);
        total = total.saturating_add(whole.saturating_mul(unit_ns));
        total = total.saturating_add(fraction_of(fraction, unit_ns));
        any = true;
        rest = &after[unit_name.len()..];
        if rest.first() == Some(&b'_') {
            rest = &rest[1..];
        }
    }
    any.then_some(if negative { -total } else { total })
}

/// The nanoseconds that the decimal fraction digits `fraction` of `unit_ns` stand for, truncated.
fn fraction_of(fraction: &[u8], unit_ns: i128) -> i128 {
    let mut value: i128 = 0;
    let mut scale: i128 = 1;
    // Eighteen digits resolve a nanosecond of a day; more add nothing but overflow risk.
    for &c in fraction.iter().filter(|&&c| c != b'_').take(18) {
        value = value * 10 + i128::from(c - b'0');
        scale *= 10;
    }
    value * unit_ns / scale
}

/// `yyyy-mm-dd` at the start of `text`: the nanoseconds since 1970 and the rest of the text.
fn parse_date(text: &[u8]) -> Option<(i128, &[u8])> {
    let (year, rest) = number_then(text, Some(b'-'))?;
    let (month, rest) = number_then(rest, Some(b'-'))?;
    let (day, used) = digits(rest, 10);
    let parts = DateTimeParts {
        year: i64::try_from(year).ok()?,
        month: u32::try_from(month).ok()?,
        day: u32::try_from(day?).ok()?,
        hour: 0,
        minute: 0,
        second: 0,
        nanosecond: 0,
    };
    Some((ns_from_parts(&parts)?, &rest[used..]))
}

/// `hh:mm[:ss[.fff…]]` at the start of `text`: the nanoseconds since midnight and the rest.
fn parse_clock(text: &[u8]) -> Option<(i128, &[u8])> {
    let (hour, rest) = number_then(text, Some(b':'))?;
    let (minute, used) = digits(rest, 10);
    let mut rest = &rest[used..];
    let mut second = 0;
    let mut nanos = 0;
    if rest.first() == Some(&b':') {
        let (value, used) = digits(&rest[1..], 10);
        second = value?;
        rest = &rest[1 + used..];
        if rest.first() == Some(&b'.') {
            let (_, used) = digits(&rest[1..], 10);
            nanos = fraction_of(&rest[1..1 + used], 1_000_000_000);
            rest = &rest[1 + used..];
        }
    }
    let (hour, minute) = (hour, minute?);
    if hour >= 24 || minute >= 60 || second >= 60 {
        return None;
    }
    let seconds = (hour * 3600 + minute * 60 + second) as i128;
    Some((seconds * 1_000_000_000 + nanos, rest))
}

/// `yyyy-mm-dd-hh:mm[:ss[.fff…]]`: the nanoseconds since 1970.
fn parse_date_time(text: &[u8]) -> Option<i128> {
    let (date, rest) = parse_date(text)?;
    let rest = rest.strip_prefix(b"-")?;
    let (clock, _) = parse_clock(rest)?;
    Some(date + clock)
}

/// A decimal number followed by `separator`, and the text after the separator.
fn number_then(text: &[u8], separator: Option<u8>) -> Option<(u128, &[u8])> {
    let (value, used) = digits(text, 10);
    let value = value?;
    match separator {
        Some(separator) if text.get(used) == Some(&separator) => Some((value, &text[used + 1..])),
        Some(_) => None,
        None => Some((value, &text[used..])),
    }
}

fn real_text(value: f64, ty: Elementary) -> String {
    if value.is_nan() {
        return "NaN".to_string();
    }
    if value.is_infinite() {
        return if value < 0.0 { "-INF" } else { "INF" }.to_string();
    }
    if value == 0.0 {
        return if value.is_sign_negative() { "-0" } else { "0" }.to_string();
    }
    // `{:e}` gives the shortest digits that read back to the same value of the type.
    let scientific = if ty == Real {
        format!("{:e}", value as f32)
    } else {
        format!("{value:e}")
    };
    let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let (sign, mantissa) = match mantissa.strip_prefix('-') {
        Some(rest) => ("-", rest),
        None => ("", mantissa),
    };
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    if (-5..15).contains(&exponent) {
        let point = exponent + 1;
        let text = if point <= 0 {
            format!("0.{}{digits}", "0".repeat(point.unsigned_abs() as usize))
        } else if point as usize >= digits.len() {
            format!("{digits}{}", "0".repeat(point as usize - digits.len()))
        } else {
            format!(
                "{}.{}",
                &digits[..point as usize],
                &digits[point as usize..]
            )
        };
        format!("{sign}{text}")
    } else {
        let exponent_sign = if exponent < 0 { '-' } else { '+' };
        format!(
            "{sign}{mantissa}E{exponent_sign}{}",
            exponent.unsigned_abs()
        )
    }
}

fn duration_text(prefix: &str, ns: i128, smallest_ns: i128) -> String {
    const UNITS: [(&str, i128); 7] = [
        ("d", DAY_NS),
        ("h", 3_600_000_000_000),
        ("m", 60_000_000_000),
        ("s", 1_000_000_000),
        ("ms", 1_000_000),
        ("us", 1_000),
        ("ns", 1),
    ];
    let mut text = String::from(prefix);
    if ns < 0 {
        text.push('-');
    }
    let mut rest = ns.unsigned_abs();
    let mut any = false;
    for (name, unit) in UNITS.into_iter().filter(|(_, unit)| *unit >= smallest_ns) {
        let unit = unit as u128;
        let count = rest / unit;
        rest %= unit;
        if count > 0 {
            let _ = write!(text, "{count}{name}");
            any = true;
        }
    }
    if !any {
        text.push_str(if smallest_ns == 1 { "0ns" } else { "0ms" });
    }
    text
}

fn date_text(ns: i128) -> String {
    let parts = parts_from_ns(ns);
    format!("{:04}-{:02}-{:02}", parts.year, parts.month, parts.day)
}

/// `hh:mm:ss` of the time of day of `ns` (modulo a day), with up to `fraction_digits` digits
/// of the second in groups of three when they are not zero.
fn clock_text(ns: i128, fraction_digits: u32) -> String {
    let parts = parts_from_ns(ns.rem_euclid(DAY_NS));
    let mut text = format!("{:02}:{:02}:{:02}", parts.hour, parts.minute, parts.second);
    let fraction = parts.nanosecond / 10u32.pow(9 - fraction_digits);
    if fraction != 0 {
        let mut digits = format!("{fraction:0width$}", width = fraction_digits as usize);
        while digits.len() > 3 && digits.ends_with("000") {
            digits.truncate(digits.len() - 3);
        }
        text.push('.');
        text.push_str(&digits);
    }
    text
}

fn date_time_text(ns: i128, fraction_digits: u32) -> String {
    let day = ns - ns.rem_euclid(DAY_NS);
    let clock = if fraction_digits == 0 {
        clock_text(ns.rem_euclid(DAY_NS) / 1_000_000_000 * 1_000_000_000, 3)
    } else {
        clock_text(ns, fraction_digits)
    };
    format!("{}-{clock}", date_text(day))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stdlib::raw_from_i64;

    #[track_caller]
    fn check_text(raw: u64, ty: Elementary, expected: &str) {
        assert_eq!(to_text(raw, ty), expected);
        assert_eq!(
            from_text(expected.as_bytes(), ty),
            raw,
            "reading {expected:?} back"
        );
    }

    #[test]
    fn durations_are_written_without_zero_parts() {
        check_text(1500, Time, "T#1s500ms");
        check_text(0, Time, "T#0ms");
        check_text(raw_from_i64(-1000, Time), Time, "T#-1s");
        check_text(90_061_001, Time, "T#1d1h1m1s1ms");
        check_text(1_000_001, Ltime, "LTIME#1ms1ns");
        check_text(0, Ltime, "LTIME#0ns");
    }

    #[test]
    fn reals_are_written_with_the_fewest_digits() {
        let real = |x: f32| u64::from(x.to_bits());
        check_text(real(1.234), Real, "1.234");
        check_text(real(2.0), Real, "2");
        check_text(real(-0.5), Real, "-0.5");
        check_text(real(1.5e20), Real, "1.5E+20");
        check_text(real(1e-7), Real, "1E-7");
        check_text(real(0.1), Real, "0.1");
        check_text(0.1f64.to_bits(), Lreal, "0.1");
        check_text(real(f32::INFINITY), Real, "INF");
        assert_eq!(to_text(f64::NAN.to_bits(), Lreal), "NaN");
        assert!(f64::from_bits(from_text(b"nan", Lreal)).is_nan());
    }

    #[test]
    fn literals_are_read_with_their_type_and_base() {
        assert_eq!(from_text(b"16#FF", Byte), 255);
        assert_eq!(from_text(b"WORD#16#FF_FF", Word), 0xFFFF);
        assert_eq!(from_text(b"2#1010", Int), 10);
        assert_eq!(from_text(b"INT#-5", Int), 0xFFFB);
        assert_eq!(from_text(b"  42  ", Dint), 42);
        assert_eq!(from_text(b"T#5s", Dword), 5000);
        assert_eq!(from_text(b"T#1.5s", Time), 1500);
        assert_eq!(from_text(b"LTIME#1us", Time), 0);
        assert_eq!(from_text(b"REAL#1.5", Int), 2);
        assert_eq!(from_text(b"BOOL#1", Bool), 1);
        assert_eq!(from_text(b"true", Bool), 1);
        assert_eq!(from_text(b"1", Bool), 0);
        assert_eq!(from_text(b"M123", Sint), 0);
        assert_eq!(from_text(b"", Lreal), 0);
        assert_eq!(from_text(b"A", Char), 65);
    }

    #[test]
    fn dates_and_times_of_day_are_written_as_literals() {
        check_text(1_706_659_200, Date, "D#2024-01-31");
        check_text(45_000_000, TimeOfDay, "TOD#12:30:00");
        check_text(1, TimeOfDay, "TOD#00:00:00.001");
        check_text(1_706_704_200, DateAndTime, "DT#2024-01-31-12:30:00");
        check_text(45_000_000_001_000, LtimeOfDay, "LTOD#12:30:00.000001");
        check_text(
            1_706_704_200_500_000_000,
            LdateAndTime,
            "LDT#2024-01-31-12:30:00.500",
        );
        assert_eq!(to_text(86_400_000, TimeOfDay), "TOD#00:00:00");
        assert_eq!(from_text(b"D#1970-1-1", Date), 0);
        assert_eq!(from_text(b"TOD#0:0:0", TimeOfDay), 0);
        assert_eq!(from_text(b"D#2023-02-29", Date), 0);
        assert_eq!(from_text(b"TOD#24:00:00", TimeOfDay), 0);
    }
}
