//! Task intervals: IEC duration literals (`T#100ms`) and the ISO 8601 durations CODESYS writes
//! (`PT0.2S`).

/// The interval written `text` in microseconds, rounded to the nearest one; `None` when it is not
/// a duration, is zero, or does not fit Rivet's `u32` of microseconds (about 71 minutes).
pub fn parse_interval_us(text: &str) -> Option<u32> {
    let text = text.trim();
    let upper = text.to_ascii_uppercase();
    let nanoseconds = if let Some(rest) = upper.strip_prefix("PT") {
        iso_nanoseconds(rest, true)?
    } else if let Some(rest) = upper.strip_prefix('P') {
        iso_nanoseconds(rest, false)?
    } else {
        let rest = ["TIME#", "T#", "LTIME#", "LT#"]
            .iter()
            .find_map(|prefix| upper.strip_prefix(prefix))?;
        iec_nanoseconds(rest)?
    };
    let microseconds = (nanoseconds + 500.0) / 1000.0;
    if microseconds < 1.0 || microseconds > f64::from(u32::MAX) {
        return None;
    }
    // In range and not below one: the conversion neither saturates nor truncates a whole part.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    Some(microseconds.floor() as u32)
}

/// The nanoseconds of an IEC duration without its prefix: numbers each followed by a unit
/// (`D`, `H`, `M`, `S`, `MS`, `US`, `NS`), `_` allowed between digits.
fn iec_nanoseconds(text: &str) -> Option<f64> {
    let text: String = text.chars().filter(|c| *c != '_').collect();
    let mut rest = text.as_str();
    let mut total = 0.0;
    if rest.is_empty() {
        return None;
    }
    while !rest.is_empty() {
        let number_end = rest
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .unwrap_or(rest.len());
        let number: f64 = rest.get(..number_end)?.parse().ok()?;
        rest = rest.get(number_end..)?;
        let (unit_ns, length) = if rest.starts_with("MS") {
            (1e6, 2)
        } else if rest.starts_with("US") {
            (1e3, 2)
        } else if rest.starts_with("NS") {
            (1.0, 2)
        } else if rest.starts_with('D') {
            (86_400e9, 1)
        } else if rest.starts_with('H') {
            (3_600e9, 1)
        } else if rest.starts_with('M') {
            (60e9, 1)
        } else if rest.starts_with('S') {
            (1e9, 1)
        } else {
            return None;
        };
        total += number * unit_ns;
        rest = rest.get(length..)?;
    }
    Some(total)
}

/// The nanoseconds of an ISO 8601 duration after its `P` (`in_time` when the `T` was there too):
/// `nD` before `T`, then `nH`, `nM`, `nS`.
fn iso_nanoseconds(text: &str, in_time: bool) -> Option<f64> {
    let (date, time) = if in_time {
        ("", text)
    } else {
        match text.split_once('T') {
            Some((date, time)) => (date, time),
            None => (text, ""),
        }
    };
    if date.is_empty() && time.is_empty() {
        return None;
    }
    let mut total = 0.0;
    for (part, units) in [
        (date, &[('D', 86_400e9)][..]),
        (time, &[('H', 3_600e9), ('M', 60e9), ('S', 1e9)][..]),
    ] {
        let mut rest = part;
        let mut next_unit = 0;
        while !rest.is_empty() {
            let number_end = rest.find(|c: char| !(c.is_ascii_digit() || c == '.'))?;
            let number: f64 = rest.get(..number_end)?.parse().ok()?;
            let unit = rest.get(number_end..)?.chars().next()?;
            let position = units
                .iter()
                .skip(next_unit)
                .position(|(letter, _)| *letter == unit)?;
            let (_, unit_ns) = units.get(next_unit + position)?;
            next_unit += position + 1;
            total += number * unit_ns;
            rest = rest.get(number_end + 1..)?;
        }
    }
    Some(total)
}

#[cfg(test)]
mod tests {
    use super::parse_interval_us;

    #[test]
    fn iec_durations_are_read() {
        assert_eq!(parse_interval_us("T#100ms"), Some(100_000));
        assert_eq!(parse_interval_us("t#20MS"), Some(20_000));
        assert_eq!(parse_interval_us("TIME#1s500ms"), Some(1_500_000));
        assert_eq!(parse_interval_us("T#1m"), Some(60_000_000));
        assert_eq!(parse_interval_us("T#2.5ms"), Some(2_500));
        assert_eq!(parse_interval_us("T#250us"), Some(250));
        assert_eq!(parse_interval_us("T#1_000ms"), Some(1_000_000));
    }

    #[test]
    fn iso_durations_are_read() {
        assert_eq!(parse_interval_us("PT0.2S"), Some(200_000));
        assert_eq!(parse_interval_us("PT1M30S"), Some(90_000_000));
        assert_eq!(parse_interval_us("pt0.001s"), Some(1_000));
        assert_eq!(parse_interval_us("P0DT0H1M"), Some(60_000_000));
        // 26 hours: beyond the 71 minutes of a u32 of microseconds.
        assert_eq!(parse_interval_us("P1DT2H"), None);
    }

    #[test]
    fn what_is_not_a_usable_duration_is_refused() {
        for text in [
            "", "100", "T#", "T#10x", "PT", "PTS", "PT1S2M", "T#0ms", "T#100d", "PT0S", "ms",
        ] {
            assert_eq!(parse_interval_us(text), None, "{text}");
        }
    }
}
