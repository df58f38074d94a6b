//! A serial line's settings, written as `19200-8E1`, and the character timing they imply.

use std::fmt;
use std::str::FromStr;
use std::time::Duration;

/// The baud rates a Rivet serial port may run at (`docs/modbus-master.md` §2.3).
pub const BAUD_RATES: [u32; 9] = [1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];

/// The settings of one serial line; checked by [`SerialSettings::check`], which parsing and
/// opening a port run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SerialSettings {
    /// Bits per second, one of [`BAUD_RATES`].
    pub baud_rate: u32,
    /// Data bits per character; Modbus RTU sends 8, and 7 (Modbus ASCII's) is refused rather
    /// than silently changed.
    pub data_bits: u8,
    /// The parity bit, if any.
    pub parity: Parity,
    /// Stop bits per character.
    pub stop_bits: StopBits,
}

/// The parity bit of each character.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parity {
    /// No parity bit (`N`).
    None,
    /// Even parity (`E`), the Modbus serial line standard's default.
    Even,
    /// Odd parity (`O`).
    Odd,
}

/// The stop bits of each character.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopBits {
    /// One stop bit.
    One,
    /// Two stop bits, which the standard asks for when there is no parity.
    Two,
}

/// Settings that a serial line cannot run with, or a text that is not settings.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SerialSettingsError {
    /// The text is not of the form `BAUD-DPS`.
    #[error(
        "{0:?} is not a serial line format: expected BAUD-DPS with D the data bits (8), P the \
         parity (N, E or O) and S the stop bits (1 or 2), such as 19200-8E1"
    )]
    Format(String),
    /// The baud rate is not one of [`BAUD_RATES`].
    #[error(
        "baud rate {0} is not supported: expected one of 1200, 2400, 4800, 9600, 19200, 38400, \
         57600, 115200 or 230400"
    )]
    BaudRate(u32),
    /// The data bits are not 8.
    #[error("{0} data bits cannot carry Modbus RTU: expected 8")]
    DataBits(u8),
}

impl SerialSettings {
    /// The Modbus serial line standard's default: 19200 baud, 8 data bits, even parity, one
    /// stop bit (`19200-8E1`).
    pub const STANDARD: SerialSettings = SerialSettings {
        baud_rate: 19200,
        data_bits: 8,
        parity: Parity::Even,
        stop_bits: StopBits::One,
    };

    /// Whether a Modbus RTU line can run with these settings: a listed baud rate and 8 data
    /// bits.
    pub fn check(&self) -> Result<(), SerialSettingsError> {
        if !BAUD_RATES.contains(&self.baud_rate) {
            return Err(SerialSettingsError::BaudRate(self.baud_rate));
        }
        if self.data_bits != 8 {
            return Err(SerialSettingsError::DataBits(self.data_bits));
        }
        Ok(())
    }

    /// The silence of 3.5 characters that ends a frame and comes before each frame sent
    /// (see [`silence_us`]).
    pub fn silence(&self) -> Duration {
        Duration::from_micros(silence_us(self.baud_rate))
    }
}

impl Default for SerialSettings {
    /// [`SerialSettings::STANDARD`].
    fn default() -> Self {
        Self::STANDARD
    }
}

/// The standard's 3.5 character times at `baud_rate`, in microseconds: 38.5 bit times rounded
/// up up to 19200 baud (4011 µs at 9600, 2006 µs at 19200) and 1750 µs above
/// (`docs/modbus-master.md` §2.3). The master and the slave share the image's computation, so a
/// line's two ends never disagree on it.
pub fn silence_us(baud_rate: u32) -> u64 {
    u64::from(program_image::modbus_master::silent_interval_us(baud_rate))
}

impl FromStr for SerialSettings {
    type Err = SerialSettingsError;

    /// Reads `BAUD-DPS` (`19200-8E1`, `9600-8N2`): the baud rate, the data bits, the parity
    /// letter (`N`, `E` or `O`, either case) and the stop bits, then checks them.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let format = || SerialSettingsError::Format(text.to_owned());
        let (baud_rate, character) = text.split_once('-').ok_or_else(format)?;
        let baud_rate: u32 = baud_rate.parse().map_err(|_| format())?;
        let [data_bits, parity, stop_bits] = character.as_bytes() else {
            return Err(format());
        };
        let data_bits = match data_bits {
            b'5'..=b'9' => data_bits - b'0',
            _ => return Err(format()),
        };
        let parity = match parity.to_ascii_uppercase() {
            b'N' => Parity::None,
            b'E' => Parity::Even,
            b'O' => Parity::Odd,
            _ => return Err(format()),
        };
        let stop_bits = match stop_bits {
            b'1' => StopBits::One,
            b'2' => StopBits::Two,
            _ => return Err(format()),
        };
        let settings = SerialSettings {
            baud_rate,
            data_bits,
            parity,
            stop_bits,
        };
        settings.check()?;
        Ok(settings)
    }
}

impl fmt::Display for SerialSettings {
    /// Writes the settings as [`FromStr`] reads them: `19200-8E1`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parity = match self.parity {
            Parity::None => 'N',
            Parity::Even => 'E',
            Parity::Odd => 'O',
        };
        let stop_bits = match self.stop_bits {
            StopBits::One => 1,
            StopBits::Two => 2,
        };
        write!(
            f,
            "{}-{}{parity}{stop_bits}",
            self.baud_rate, self.data_bits
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_standard_format_and_its_variants_parse_and_print_back() {
        for text in ["19200-8E1", "9600-8N2", "115200-8O1", "1200-8N1"] {
            let settings: SerialSettings = text.parse().unwrap();
            assert_eq!(settings.to_string(), text);
        }
        assert_eq!("19200-8E1".parse(), Ok(SerialSettings::STANDARD));
        assert_eq!(
            "9600-8n2".parse(),
            Ok(SerialSettings {
                baud_rate: 9600,
                data_bits: 8,
                parity: Parity::None,
                stop_bits: StopBits::Two,
            })
        );
    }

    #[test]
    fn a_malformed_format_is_refused_with_the_text_and_the_expected_form() {
        for text in [
            "",
            "19200",
            "19200-8E",
            "19200-8X1",
            "19200-8E3",
            "fast-8E1",
            "19200-8E1x",
        ] {
            let error = text.parse::<SerialSettings>().unwrap_err();
            assert_eq!(error, SerialSettingsError::Format(text.to_owned()));
            assert!(error.to_string().contains("such as 19200-8E1"), "{error}");
        }
    }

    #[test]
    fn an_unlisted_baud_rate_and_seven_data_bits_are_refused_by_name() {
        assert_eq!(
            "14400-8N1".parse::<SerialSettings>(),
            Err(SerialSettingsError::BaudRate(14400))
        );
        assert_eq!(
            "9600-7E1".parse::<SerialSettings>(),
            Err(SerialSettingsError::DataBits(7))
        );
        assert_eq!(
            SerialSettingsError::DataBits(7).to_string(),
            "7 data bits cannot carry Modbus RTU: expected 8"
        );
    }

    #[test]
    fn the_silence_is_three_and_a_half_characters_up_to_19200_baud_then_1750_us() {
        assert_eq!(silence_us(9600), 4011);
        assert_eq!(silence_us(19200), 2006);
        assert_eq!(silence_us(1200), 32084);
        for fast in [38400, 57600, 115200, 230400] {
            assert_eq!(silence_us(fast), 1750);
        }
        assert_eq!(
            SerialSettings::STANDARD.silence(),
            Duration::from_micros(2006)
        );
    }
}
