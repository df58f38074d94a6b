//! The PLCopen v1.0 rules that are not local to one element (`docs/plcopen-xml.md` §1.3).

/// A v1.0 task interval (`HH:MM:SS.ffffff`) as an IEC duration literal (`T#100ms`); `None` when
/// it is not of that form. A v2.01 interval in a v1.0 file (`T#…`) is kept as written.
pub(super) fn interval_v10(written: &str) -> Option<String> {
    let written = written.trim();
    if written.to_ascii_uppercase().starts_with("T#") || written.starts_with("PT") {
        return Some(written.to_owned());
    }
    let mut parts = written.split(':');
    let hours: u64 = parts.next()?.parse().ok()?;
    let minutes: u64 = parts.next()?.parse().ok()?;
    let seconds_text = parts.next()?;
    if parts.next().is_some() {
        return None;
    }
    let (whole, fraction) = seconds_text.split_once('.').unwrap_or((seconds_text, ""));
    let seconds: u64 = whole.parse().ok()?;
    if fraction.len() > 6 || !fraction.bytes().all(|byte| byte.is_ascii_digit()) {
        return None;
    }
    let fraction_us: u64 = format!("{fraction:0<6}").parse().ok()?;
    let total_us = ((hours * 60 + minutes) * 60 + seconds) * 1_000_000 + fraction_us;
    let mut literal = String::from("T#");
    let units = [
        (3_600_000_000, "h"),
        (60_000_000, "m"),
        (1_000_000, "s"),
        (1_000, "ms"),
        (1, "us"),
    ];
    let mut rest = total_us;
    for (unit_us, unit) in units {
        let count = rest / unit_us;
        rest %= unit_us;
        if count > 0 {
            literal.push_str(&format!("{count}{unit}"));
        }
    }
    if total_us == 0 {
        literal.push_str("0ms");
    }
    Some(literal)
}

#[cfg(test)]
mod tests {
    use super::interval_v10;

    #[test]
    fn v10_intervals_become_duration_literals() {
        assert_eq!(interval_v10("00:00:00.100000").as_deref(), Some("T#100ms"));
        assert_eq!(interval_v10("01:02:03.5").as_deref(), Some("T#1h2m3s500ms"));
        assert_eq!(interval_v10("00:00:00").as_deref(), Some("T#0ms"));
        assert_eq!(interval_v10("T#20ms").as_deref(), Some("T#20ms"));
        assert_eq!(interval_v10("soon"), None);
        assert_eq!(interval_v10("00:00:00.1234567"), None);
    }
}
