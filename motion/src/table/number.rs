//! How numbers and names are written into the exported files (`docs/cam-formats.md` §1.2).

use super::TableError;

/// The shortest plain decimal that reads back as the same value, with `.` as the decimal
/// point and no exponent; a negative zero is written as `0` so files never show `-0`.
pub(crate) fn plain(value: f64) -> String {
    if value == 0.0 {
        return "0".to_owned();
    }
    // Rust's `Display` for f64 is the shortest round-trip decimal and never uses an exponent.
    format!("{value}")
}

/// A number as a Structured Text `LREAL`/`REAL` literal: like [`plain`], but always with a
/// decimal point so the initialiser never relies on integer-to-real conversion.
pub(crate) fn st_real(value: f64) -> String {
    let text = plain(value);
    if text.contains('.') {
        text
    } else {
        format!("{text}.0")
    }
}

/// `value` rounded to `digits` significant decimal digits, as the nearest f64.
pub(crate) fn round_significant(value: f64, digits: usize) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    // Formatting in scientific notation rounds the decimal digits correctly, which repeated
    // multiplication by powers of ten would not.
    let text = format!("{:.*e}", digits.saturating_sub(1), value);
    text.parse().unwrap_or(value)
}

/// Checks that `name` can be the name of a variable or type in IEC 61131-3 Structured Text.
pub(crate) fn check_identifier(name: &str) -> Result<(), TableError> {
    let mut chars = name.chars();
    let starts_well = chars
        .next()
        .is_some_and(|first| first.is_ascii_alphabetic() || first == '_');
    let rest_well = name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    let underscores_well = !name.contains("__") && !name.ends_with('_');
    if starts_well && rest_well && underscores_well {
        Ok(())
    } else {
        Err(TableError::InvalidIdentifier {
            name: name.to_owned(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_numbers_are_shortest_decimals_without_exponent_or_negative_zero() {
        assert_eq!(plain(90.0), "90");
        assert_eq!(plain(18.6328125), "18.6328125");
        assert_eq!(plain(-0.5), "-0.5");
        assert_eq!(plain(-0.0), "0");
        assert_eq!(plain(1e-7), "0.0000001");
        assert_eq!(plain(0.1), "0.1");
    }

    #[test]
    fn structured_text_reals_always_have_a_decimal_point() {
        assert_eq!(st_real(90.0), "90.0");
        assert_eq!(st_real(-0.0), "0.0");
        assert_eq!(st_real(0.52734375), "0.52734375");
    }

    #[test]
    fn rounding_keeps_seven_significant_digits() {
        assert_eq!(round_significant(18.6328125, 7), 18.63281);
        assert_eq!(round_significant(161.3671875, 7), 161.3672);
        assert_eq!(round_significant(0.000123456789, 7), 0.0001234568);
        assert_eq!(round_significant(0.0, 7), 0.0);
    }

    #[test]
    fn identifiers_follow_iec_rules() {
        assert!(check_identifier("Cam_Table1").is_ok());
        assert!(check_identifier("_x").is_ok());
        for bad in ["", "1cam", "cam table", "cam__table", "cam_", "Kurve_ä"] {
            assert_eq!(
                check_identifier(bad),
                Err(TableError::InvalidIdentifier {
                    name: bad.to_owned()
                }),
                "{bad}"
            );
        }
    }
}
