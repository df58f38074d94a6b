//! Direct addresses (`%IX0.3`, `%QW4`, `%MD10`, `%I*`): their syntax, size and place in the
//! memory areas, with CODESYS's layout where `%MWn` covers bytes `2n` and `2n+1`.

/// A memory area.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Area {
    /// `%I`, inputs.
    Input,
    /// `%Q`, outputs.
    Output,
    /// `%M`, markers.
    Memory,
}

/// A parsed direct address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Address {
    /// The area.
    pub(crate) area: Area,
    /// The size in bits: 1 for `X`, 8, 16, 32 or 64.
    pub(crate) size_bits: u32,
    /// The first bit covered, counted from the start of the area.
    pub(crate) first_bit: u64,
}

impl Address {
    /// The bits covered, end exclusive.
    pub(crate) fn bits(&self) -> std::ops::Range<u64> {
        self.first_bit..self.first_bit + u64::from(self.size_bits)
    }
}

/// Why a text is not a direct address; each variant names the text as written.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AddressError {
    /// `IX0.0`: no `%`.
    #[error("'{text}' is not a direct address: it must start with '%'")]
    NoPercent {
        /// The address.
        text: String,
    },
    /// `%ZX0.0`: no area letter.
    #[error("'{text}' names no memory area: write %I (inputs), %Q (outputs) or %M (markers)")]
    NoArea {
        /// The address.
        text: String,
    },
    /// `%IK3`: no size letter.
    #[error(
        "'{text}' has no valid size: write X (bit), B (byte), W (word), D (double word) or L (long word)"
    )]
    NoSize {
        /// The address.
        text: String,
    },
    /// `%IWx`: a part that is no number.
    #[error("'{text}' is not a valid address: '{part}' is not a number")]
    NotANumber {
        /// The address.
        text: String,
        /// The part.
        part: String,
    },
    /// `%IX0.8`: a bit past the byte.
    #[error("'{text}' names bit {bit}, but a byte has bits 0 to 7")]
    NoSuchBit {
        /// The address.
        text: String,
        /// The bit named.
        bit: u64,
    },
}

/// Parses `text`; `Ok(None)` for an address left to the I/O mapping (`%I*`), `Err` with what is
/// wrong otherwise.
pub(crate) fn parse_address(text: &str) -> Result<Option<Address>, AddressError> {
    let upper = text.to_ascii_uppercase();
    let Some(rest) = upper.strip_prefix('%') else {
        return Err(AddressError::NoPercent {
            text: text.to_owned(),
        });
    };
    let mut chars = rest.chars();
    let area = match chars.next() {
        Some('I') => Area::Input,
        Some('Q') => Area::Output,
        Some('M') => Area::Memory,
        _ => {
            return Err(AddressError::NoArea {
                text: text.to_owned(),
            });
        }
    };
    let rest = chars.as_str();
    if rest == "*" {
        return Ok(None);
    }
    let (size_bits, numbers) = match rest.chars().next() {
        Some('X') => (1, &rest[1..]),
        Some('B') => (8, &rest[1..]),
        Some('W') => (16, &rest[1..]),
        Some('D') => (32, &rest[1..]),
        Some('L') => (64, &rest[1..]),
        Some(c) if c.is_ascii_digit() => (1, rest),
        _ => {
            return Err(AddressError::NoSize {
                text: text.to_owned(),
            });
        }
    };
    let parts: Vec<&str> = numbers.split('.').collect();
    let mut values = Vec::new();
    for part in &parts {
        match part.parse::<u64>() {
            Ok(value) => values.push(value),
            Err(_) => {
                return Err(AddressError::NotANumber {
                    text: text.to_owned(),
                    part: (*part).to_owned(),
                });
            }
        }
    }
    let first_bit = match (size_bits, values.as_slice()) {
        (1, [byte, bit]) => {
            if *bit > 7 {
                return Err(AddressError::NoSuchBit {
                    text: text.to_owned(),
                    bit: *bit,
                });
            }
            byte * 8 + bit
        }
        // IEC's single-level bit address, `%QX75`: bit 75 of the area.
        (1, [bit]) => *bit,
        (_, [index]) => index * u64::from(size_bits),
        // Hierarchical addresses (`%IW2.5.7`) are valid IEC but their layout belongs to the
        // I/O configuration, so they take part in no overlap check.
        _ => return Ok(None),
    };
    Ok(Some(Address {
        area,
        size_bits,
        first_bit,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses_follow_the_codesys_layout() {
        let word = parse_address("%MW1").unwrap().unwrap();
        assert_eq!(word.bits(), 16..32);
        let bit = parse_address("%IX2.3").unwrap().unwrap();
        assert_eq!(
            (bit.area, bit.first_bit, bit.size_bits),
            (Area::Input, 19, 1)
        );
        assert_eq!(parse_address("%QD2").unwrap().unwrap().bits(), 64..96);
        assert_eq!(parse_address("%I*"), Ok(None));
        assert_eq!(parse_address("%Q*"), Ok(None));
        assert!(
            parse_address("%IX0.8")
                .unwrap_err()
                .to_string()
                .contains("bits 0 to 7")
        );
        assert_eq!(parse_address("%QX75").unwrap().unwrap().first_bit, 75);
        assert_eq!(parse_address("%IW1.2.3"), Ok(None));
        assert!(parse_address("%ZW1").is_err());
        assert!(parse_address("%IWx").is_err());
    }
}
