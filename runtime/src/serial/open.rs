//! Opening a serial port by its path with a line's settings.

use std::path::{Path, PathBuf};

use tokio_serial::{SerialPortBuilder, SerialStream};

use crate::serial::settings::{Parity, SerialSettings, SerialSettingsError, StopBits};

/// Why a serial port could not be opened; names the port's path.
#[derive(Debug, thiserror::Error)]
pub enum SerialOpenError {
    /// The settings cannot run a Modbus RTU line.
    #[error("cannot open {path}: {source}", path = .path.display())]
    Settings {
        /// The port's path.
        path: PathBuf,
        /// What is wrong with the settings.
        source: SerialSettingsError,
    },
    /// The operating system refused to open or configure the port (it does not exist, another
    /// program holds it, or it does not take a setting).
    #[error("cannot open {path}: {source}", path = .path.display())]
    Port {
        /// The port's path.
        path: PathBuf,
        /// The serial library's error, with the operating system's reason.
        source: tokio_serial::Error,
    },
}

/// Opens the serial port at `path` with `settings`: raw mode, no flow control, modem lines
/// ignored (`CLOCAL`), and exclusive access (`TIOCEXCL` and a `flock`), so that no second
/// program talks on the same line.
///
/// Must be called within a tokio runtime, which then drives the stream.
pub fn open_port(path: &Path, settings: &SerialSettings) -> Result<SerialStream, SerialOpenError> {
    settings
        .check()
        .map_err(|source| SerialOpenError::Settings {
            path: path.to_owned(),
            source,
        })?;
    SerialStream::open(&builder(path, settings)).map_err(|source| SerialOpenError::Port {
        path: path.to_owned(),
        source,
    })
}

/// The serial library's description of the port: what the termios will be asked for.
fn builder(path: &Path, settings: &SerialSettings) -> SerialPortBuilder {
    let parity = match settings.parity {
        Parity::None => tokio_serial::Parity::None,
        Parity::Even => tokio_serial::Parity::Even,
        Parity::Odd => tokio_serial::Parity::Odd,
    };
    let stop_bits = match settings.stop_bits {
        StopBits::One => tokio_serial::StopBits::One,
        StopBits::Two => tokio_serial::StopBits::Two,
    };
    // `check` has let only 8 data bits through.
    tokio_serial::new(path.to_string_lossy(), settings.baud_rate)
        .data_bits(tokio_serial::DataBits::Eight)
        .parity(parity)
        .stop_bits(stop_bits)
        .flow_control(tokio_serial::FlowControl::None)
        .exclusive(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_port_is_asked_for_the_settings_parity_stop_bits_and_exclusive_access() {
        let path = Path::new("/dev/ttyUSB7");
        let asked = builder(path, &"9600-8O2".parse().unwrap());
        let expected = tokio_serial::new("/dev/ttyUSB7", 9600)
            .data_bits(tokio_serial::DataBits::Eight)
            .parity(tokio_serial::Parity::Odd)
            .stop_bits(tokio_serial::StopBits::Two)
            .flow_control(tokio_serial::FlowControl::None)
            .exclusive(true);
        assert_eq!(asked, expected);
        let even = builder(path, &SerialSettings::STANDARD);
        assert_ne!(even, expected);
        assert_eq!(
            even,
            tokio_serial::new("/dev/ttyUSB7", 19200)
                .parity(tokio_serial::Parity::Even)
                .stop_bits(tokio_serial::StopBits::One)
                .flow_control(tokio_serial::FlowControl::None)
        );
    }

    #[tokio::test]
    async fn a_missing_port_and_bad_settings_are_refused_naming_the_path() {
        let missing = Path::new("/nonexistent/rivet-port");
        let error = open_port(missing, &SerialSettings::STANDARD).unwrap_err();
        assert!(matches!(error, SerialOpenError::Port { .. }), "{error:?}");
        assert!(
            error
                .to_string()
                .starts_with("cannot open /nonexistent/rivet-port: ")
        );
        let seven = SerialSettings {
            data_bits: 7,
            ..SerialSettings::STANDARD
        };
        let error = open_port(missing, &seven).unwrap_err();
        assert_eq!(
            error.to_string(),
            "cannot open /nonexistent/rivet-port: 7 data bits cannot carry Modbus RTU: expected 8"
        );
    }
}
