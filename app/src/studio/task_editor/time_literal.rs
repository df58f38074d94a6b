//! Task times typed as IEC durations (`T#10ms`, `T#1.5s`) or as plain microseconds.

use compiler::literal::{LiteralError, parse_duration};

use crate::studio::error_texts::literal_error_text;
use crate::studio::i18n::{Language, RefusalText};

/// Why a typed task time is refused.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TimeRefusal {
    /// Nothing was typed.
    Empty,
    /// A plain number of microseconds too long to read.
    TooLong(String),
    /// The duration literal is malformed.
    Literal(LiteralError),
    /// The duration has a fraction of a microsecond.
    NotWholeMicroseconds(String),
    /// The time is zero or negative.
    NotPositive,
    /// The time is longer than a task time can be.
    BeyondRange(String),
}

impl TimeRefusal {
    /// The refusal as the user reads it, in `language`.
    pub fn text(&self, language: Language) -> String {
        match self {
            Self::Empty => RefusalText::TimeEmpty.get(language).to_owned(),
            Self::TooLong(text) => RefusalText::TimeTooLong.fill(language, &[("text", text)]),
            Self::Literal(error) => literal_error_text(error, language),
            Self::NotWholeMicroseconds(text) => {
                RefusalText::TimeNotWholeMicros.fill(language, &[("text", text)])
            }
            Self::NotPositive => RefusalText::TimeNotPositive.get(language).to_owned(),
            Self::BeyondRange(text) => RefusalText::TimeTooLongAtMost.fill(
                language,
                &[("text", text), ("max", &format_time_us(u32::MAX))],
            ),
        }
    }
}

impl From<LiteralError> for TimeRefusal {
    fn from(error: LiteralError) -> Self {
        Self::Literal(error)
    }
}

/// Parses a task time into microseconds: an IEC duration (`T#10ms`, `TIME#2s`, or `10ms`
/// without the prefix) or a plain number of microseconds (`10000`). Zero, negative times,
/// fractions of a microsecond and times beyond the model's range are refused with the reason.
pub fn parse_time_us(text: &str) -> Result<u32, TimeRefusal> {
    let text = text.trim();
    if text.is_empty() {
        return Err(TimeRefusal::Empty);
    }
    let micros: i128 = if text.chars().all(|c| c.is_ascii_digit() || c == '_') {
        text.replace('_', "")
            .parse()
            .map_err(|_| TimeRefusal::TooLong(text.to_owned()))?
    } else {
        let literal = if text.contains('#') {
            text.to_owned()
        } else {
            format!("T#{text}")
        };
        let nanos = parse_duration(&literal)?;
        if nanos % 1000 != 0 {
            return Err(TimeRefusal::NotWholeMicroseconds(text.to_owned()));
        }
        nanos / 1000
    };
    if micros <= 0 {
        return Err(TimeRefusal::NotPositive);
    }
    u32::try_from(micros).map_err(|_| TimeRefusal::BeyondRange(text.to_owned()))
}

/// A time in microseconds as the shortest IEC duration literal: `T#10ms`, `T#2s`, `T#250us`.
pub fn format_time_us(micros: u32) -> String {
    if micros.is_multiple_of(1_000_000) {
        format!("T#{}s", micros / 1_000_000)
    } else if micros.is_multiple_of(1000) {
        format!("T#{}ms", micros / 1000)
    } else {
        format!("T#{micros}us")
    }
}

/// What a time means, for the eye: `10 ms`, `2.5 ms`, `250 µs`, with the frequency of a cycle
/// that long.
pub fn describe_time_us(micros: u32) -> String {
    let length = if micros >= 1000 {
        format!("{} ms", f64::from(micros) / 1000.0)
    } else {
        format!("{micros} µs")
    };
    let hertz = 1_000_000.0 / f64::from(micros.max(1));
    if hertz >= 1.0 {
        format!("{length} ({} Hz)", (hertz * 100.0).round() / 100.0)
    } else {
        length
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_and_plain_microseconds_are_read() {
        assert_eq!(parse_time_us("T#10ms"), Ok(10_000));
        assert_eq!(parse_time_us("t#1.5s"), Ok(1_500_000));
        assert_eq!(parse_time_us("2ms"), Ok(2000));
        assert_eq!(parse_time_us(" 500 "), Ok(500));
        assert_eq!(parse_time_us("TIME#250us"), Ok(250));
    }

    #[test]
    fn zero_fractions_and_garbage_are_refused_with_a_reason() {
        assert!(
            parse_time_us("0").is_err_and(|e| e.text(Language::English).contains("longer than 0"))
        );
        assert!(
            parse_time_us("T#0ms")
                .is_err_and(|e| e.text(Language::English).contains("longer than 0"))
        );
        assert!(
            parse_time_us("T#1500ns")
                .is_err_and(|e| e.text(Language::English).contains("microseconds"))
        );
        assert!(
            parse_time_us("T#2h").is_err_and(|e| e.text(Language::English).contains("too long"))
        );
        assert!(parse_time_us("fast").is_err());
        assert!(parse_time_us("").is_err());
    }

    #[test]
    fn a_malformed_duration_is_refused_in_each_language() {
        let refusal = parse_time_us("T#5x").unwrap_err();
        assert!(matches!(refusal, TimeRefusal::Literal(_)));
        assert!(refusal.text(Language::English).contains("unknown unit"));
        assert!(
            refusal
                .text(Language::SimplifiedChinese)
                .contains("单位未知")
        );
    }

    #[test]
    fn times_print_as_the_shortest_literal_and_read_back() {
        for micros in [1, 250, 1000, 2500, 10_000, 1_000_000, 90_000_000] {
            assert_eq!(parse_time_us(&format_time_us(micros)), Ok(micros));
        }
        assert_eq!(format_time_us(10_000), "T#10ms");
        assert_eq!(describe_time_us(10_000), "10 ms (100 Hz)");
        assert_eq!(describe_time_us(2500), "2.5 ms (400 Hz)");
    }
}
