//! Values of literals: integers in any base, reals, durations, dates and times of day.
//!
//! The checker reports a malformed or out-of-range literal with these messages, and code
//! generation stores the values they return.

/// Why a literal's text is not a value: each variant names the literal as written.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LiteralError {
    /// `7#1`: the part before `#` is no base.
    #[error("'{base}#' is not a base; use 2#, 8# or 16#")]
    UnknownBase {
        /// The base as written.
        base: String,
    },
    /// `16#`: no digits.
    #[error("'{text}' has no digits")]
    NoDigits {
        /// The literal.
        text: String,
    },
    /// `2#102`: a digit the base does not have.
    #[error("{}", bad_digit(text, *.base))]
    BadDigit {
        /// The literal.
        text: String,
        /// Its base: 2, 8, 10 or 16.
        base: u32,
    },
    /// A real literal that is no number.
    #[error("'{text}' is not a number")]
    NotANumber {
        /// The literal.
        text: String,
    },
    /// `T#`: a duration without a value.
    #[error("'{text}' has no value; write for example T#2s")]
    NoValue {
        /// The literal.
        text: String,
    },
    /// `T#5`: the last number has no unit.
    #[error("'{text}': the number at the end has no unit (d, h, m, s, ms, us, ns)")]
    NoUnit {
        /// The literal.
        text: String,
    },
    /// `T#ms`: a unit without a number before it.
    #[error("'{text}': expected a number before '{rest}'")]
    NoNumber {
        /// The literal.
        text: String,
        /// What follows where the number is missing.
        rest: String,
    },
    /// `T#1.2.3s`: a number that is not one.
    #[error("'{text}': '{number}' is not a number")]
    BadNumber {
        /// The literal.
        text: String,
        /// The number as written.
        number: String,
    },
    /// `T#5x`: a unit that is not one.
    #[error("'{text}': unknown unit at '{rest}'; use d, h, m, s, ms, us or ns")]
    UnknownUnit {
        /// The literal.
        text: String,
        /// What follows the number.
        rest: String,
    },
    /// A date not written `D#YYYY-MM-DD`.
    #[error("'{text}' is not a date; write D#YYYY-MM-DD")]
    NotADate {
        /// The literal.
        text: String,
    },
    /// `D#2023-02-29`: a date the calendar does not have.
    #[error("'{text}' is not a valid calendar date")]
    NoSuchDate {
        /// The literal.
        text: String,
    },
    /// A time of day not written `TOD#HH:MM:SS.fff`, or out of range.
    #[error("'{text}' is not a time of day; write TOD#HH:MM:SS.fff")]
    NotATimeOfDay {
        /// The literal.
        text: String,
    },
    /// A date and time not written `DT#YYYY-MM-DD-HH:MM:SS`.
    #[error("'{text}' is not a date and time; write DT#YYYY-MM-DD-HH:MM:SS")]
    NotADateAndTime {
        /// The literal.
        text: String,
    },
    /// A typed literal without its `#`.
    #[error("'{text}' has no '#'")]
    NoHash {
        /// The literal.
        text: String,
    },
}

/// The message on a digit the base does not have: which digits the base allows.
fn bad_digit(text: &str, base: u32) -> String {
    match base {
        2 => format!("'{text}' may hold only the digits 0 and 1"),
        8 => format!("'{text}' may hold only the digits 0 to 7"),
        16 => format!("'{text}' may hold only the digits 0 to 9 and A to F"),
        _ => format!("'{text}' is not a decimal number"),
    }
}

/// Parses an integer literal: `123`, `1_000`, `16#FF`, `2#1010_1010`, `8#777`.
pub fn parse_integer(text: &str) -> Result<u128, LiteralError> {
    let (base, digits) = match text.split_once('#') {
        Some((base, digits)) => {
            let base = match base {
                "2" => 2,
                "8" => 8,
                "16" => 16,
                other => {
                    return Err(LiteralError::UnknownBase {
                        base: other.to_owned(),
                    });
                }
            };
            (base, digits)
        }
        None => (10, text),
    };
    let digits: String = digits.chars().filter(|c| *c != '_').collect();
    if digits.is_empty() {
        return Err(LiteralError::NoDigits {
            text: text.to_owned(),
        });
    }
    u128::from_str_radix(&digits, base).map_err(|_| LiteralError::BadDigit {
        text: text.to_owned(),
        base,
    })
}

/// Parses a real literal: `1.5`, `1.5E-3`, `1_000.0`.
pub fn parse_real(text: &str) -> Result<f64, LiteralError> {
    let cleaned: String = text.chars().filter(|c| *c != '_').collect();
    cleaned
        .parse::<f64>()
        .map_err(|_| LiteralError::NotANumber {
            text: text.to_owned(),
        })
}

/// Parses a duration literal (`T#1h2m3s4ms`, `TIME#-5s`, `T#1.5s`, `LTIME#1d2us44ns`) into
/// nanoseconds.
pub fn parse_duration(text: &str) -> Result<i128, LiteralError> {
    let body = after_hash(text)?;
    let (negative, body) = match body.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, body.strip_prefix('+').unwrap_or(body)),
    };
    let body = body.replace('_', "");
    if body.is_empty() {
        return Err(LiteralError::NoValue {
            text: text.to_owned(),
        });
    }
    let lower = body.to_ascii_lowercase();
    // Exact integer arithmetic: an LTIME of 1000 days must keep its nanoseconds.
    let mut total_ns: i128 = 0;
    let mut rest = lower.as_str();
    while !rest.is_empty() {
        let number_len = rest
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .ok_or_else(|| LiteralError::NoUnit {
                text: text.to_owned(),
            })?;
        if number_len == 0 {
            return Err(LiteralError::NoNumber {
                text: text.to_owned(),
                rest: rest.to_owned(),
            });
        }
        let number = &rest[..number_len];
        let (whole, fraction) = number.split_once('.').unwrap_or((number, ""));
        let bad_number = || LiteralError::BadNumber {
            text: text.to_owned(),
            number: number.to_owned(),
        };
        let whole: i128 = if whole.is_empty() {
            0
        } else {
            whole.parse().map_err(|_| bad_number())?
        };
        if fraction.contains('.') || fraction.len() > 18 {
            return Err(bad_number());
        }
        rest = &rest[number_len..];
        let (unit_ns, unit_len): (i128, usize) = if rest.starts_with("ms") {
            (1_000_000, 2)
        } else if rest.starts_with("us") {
            (1_000, 2)
        } else if rest.starts_with("ns") {
            (1, 2)
        } else if rest.starts_with('d') {
            (86_400_000_000_000, 1)
        } else if rest.starts_with('h') {
            (3_600_000_000_000, 1)
        } else if rest.starts_with('m') {
            (60_000_000_000, 1)
        } else if rest.starts_with('s') {
            (1_000_000_000, 1)
        } else {
            return Err(LiteralError::UnknownUnit {
                text: text.to_owned(),
                rest: rest.to_owned(),
            });
        };
        let scale = 10i128.pow(fraction.len() as u32);
        let fraction: i128 = if fraction.is_empty() {
            0
        } else {
            fraction.parse().map_err(|_| bad_number())?
        };
        // Fractions below a nanosecond are rounded half away from zero.
        total_ns += whole * unit_ns + (fraction * unit_ns + scale / 2) / scale;
        rest = &rest[unit_len..];
    }
    Ok(if negative { -total_ns } else { total_ns })
}

/// Parses a date literal (`D#2024-01-31`, `DATE#1970-1-1`) into days since 1970-01-01.
pub fn parse_date(text: &str) -> Result<i64, LiteralError> {
    let body = after_hash(text)?;
    let (year, month, day) = ymd(body).ok_or_else(|| LiteralError::NotADate {
        text: text.to_owned(),
    })?;
    days_from_civil(year, month, day).ok_or_else(|| LiteralError::NoSuchDate {
        text: text.to_owned(),
    })
}

/// Parses a time-of-day literal (`TOD#12:30:00.5`, `TIME_OF_DAY#0:0:0`) into nanoseconds since
/// midnight.
pub fn parse_time_of_day(text: &str) -> Result<i128, LiteralError> {
    let body = after_hash(text)?;
    hms(body).ok_or_else(|| LiteralError::NotATimeOfDay {
        text: text.to_owned(),
    })
}

/// Parses a date-and-time literal (`DT#1998-02-13-14:20`, `DT#2024-01-31-12:00:00.5`) into
/// nanoseconds since 1970-01-01 00:00.
pub fn parse_date_and_time(text: &str) -> Result<i128, LiteralError> {
    let body = after_hash(text)?;
    let message = || LiteralError::NotADateAndTime {
        text: text.to_owned(),
    };
    // The date has two dashes; the third separates the time.
    let mut dashes = body.match_indices('-').map(|(index, _)| index);
    let split = dashes.nth(2).ok_or_else(message)?;
    let (year, month, day) = ymd(&body[..split]).ok_or_else(message)?;
    let days = days_from_civil(year, month, day).ok_or_else(|| LiteralError::NoSuchDate {
        text: text.to_owned(),
    })?;
    let time = hms(&body[split + 1..]).ok_or_else(message)?;
    Ok(i128::from(days) * 86_400_000_000_000 + time)
}

fn after_hash(text: &str) -> Result<&str, LiteralError> {
    text.split_once('#')
        .map(|(_, body)| body)
        .ok_or_else(|| LiteralError::NoHash {
            text: text.to_owned(),
        })
}

fn ymd(text: &str) -> Option<(i64, u32, u32)> {
    let mut parts = text.split('-');
    let year = parts.next()?.parse().ok()?;
    let month = parts.next()?.parse().ok()?;
    let day = parts.next()?.parse().ok()?;
    parts.next().is_none().then_some((year, month, day))
}

/// `HH:MM[:SS[.fff]]` into nanoseconds, checking the ranges.
fn hms(text: &str) -> Option<i128> {
    let mut parts = text.split(':');
    let hours: i128 = parts.next()?.parse().ok()?;
    let minutes: i128 = parts.next()?.parse().ok()?;
    let seconds: f64 = match parts.next() {
        Some(seconds) => seconds.parse().ok()?,
        None => 0.0,
    };
    if parts.next().is_some()
        || !(0..24).contains(&hours)
        || !(0..60).contains(&minutes)
        || !(0.0..60.0).contains(&seconds)
    {
        return None;
    }
    Some((hours * 3600 + minutes * 60) * 1_000_000_000 + (seconds * 1e9).round() as i128)
}

/// Days since 1970-01-01 of a proleptic Gregorian date, or `None` for an impossible date.
fn days_from_civil(year: i64, month: u32, day: u32) -> Option<i64> {
    let leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    let month_days = [
        31,
        if leap { 29 } else { 28 },
        31,
        30,
        31,
        30,
        31,
        31,
        30,
        31,
        30,
        31,
    ];
    if !(1..=12).contains(&month) || day == 0 || day > month_days[(month - 1) as usize] {
        return None;
    }
    // Howard Hinnant's days_from_civil algorithm.
    let y = if month <= 2 { year - 1 } else { year };
    let era = y.div_euclid(400);
    let year_of_era = y - era * 400;
    let m = i64::from(month);
    let day_of_year = (153 * (if m > 2 { m - 3 } else { m + 9 }) + 2) / 5 + i64::from(day) - 1;
    let day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
    Some(era * 146_097 + day_of_era - 719_468)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers_in_every_base() {
        assert_eq!(parse_integer("1_000"), Ok(1000));
        assert_eq!(parse_integer("16#FF"), Ok(255));
        assert_eq!(parse_integer("2#1010_1010"), Ok(0b1010_1010));
        assert_eq!(parse_integer("8#777"), Ok(0o777));
        assert!(
            parse_integer("2#102")
                .unwrap_err()
                .to_string()
                .contains("0 and 1")
        );
        assert!(
            parse_integer("7#1")
                .unwrap_err()
                .to_string()
                .contains("not a base")
        );
        assert!(parse_integer("16#").is_err());
    }

    #[test]
    fn durations_from_the_lc1200_table() {
        let ms = 1_000_000;
        assert_eq!(parse_duration("T#12ms"), Ok(12 * ms));
        assert_eq!(parse_duration("T#5m"), Ok(300_000 * ms));
        assert_eq!(
            parse_duration("T#1h2m3s4ms"),
            Ok(((3600 + 120 + 3) * 1000 + 4) * ms)
        );
        assert_eq!(parse_duration("TIME#-1.5s"), Ok(-1500 * ms));
        assert_eq!(parse_duration("T#49d17h2m47s295ms"), Ok(4_294_967_295 * ms));
        assert_eq!(
            parse_duration("LTIME#1000d15h23m12s34ms2us44ns"),
            Ok(((((1000 * 24 + 15) * 60 + 23) * 60 + 12) * 1000 + 34) * ms + 2_044)
        );
        assert!(
            parse_duration("T#5x")
                .unwrap_err()
                .to_string()
                .contains("unknown unit")
        );
        assert!(
            parse_duration("T#5")
                .unwrap_err()
                .to_string()
                .contains("no unit")
        );
    }

    #[test]
    fn dates_and_times_of_day() {
        assert_eq!(parse_date("D#1970-01-01"), Ok(0));
        assert_eq!(parse_date("D#1970-1-15"), Ok(14));
        assert_eq!(parse_date("D#2106-2-7"), Ok(49_710));
        assert!(parse_date("D#2023-02-29").is_err());
        assert_eq!(parse_time_of_day("TOD#00:00:00.012"), Ok(12_000_000));
        assert_eq!(
            parse_time_of_day("TOD#23:59:59.999"),
            Ok(86_399_999_000_000)
        );
        assert!(parse_time_of_day("TOD#24:00:00").is_err());
        assert_eq!(
            parse_date_and_time("DT#1970-01-01-00:00:01"),
            Ok(1_000_000_000)
        );
        assert_eq!(
            parse_date_and_time("DT#2106-2-7-6:28:15"),
            Ok(4_294_967_295 * 1_000_000_000)
        );
    }
}
