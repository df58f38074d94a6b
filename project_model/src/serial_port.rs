//! The controller's serial ports, on which Modbus RTU devices are polled.

use serde::{Deserialize, Serialize};

use crate::{Project, same_identifier};

/// A serial port of the controller (`[[serial_port]]` in the manifest): the device file and the
/// line settings its Modbus RTU devices share (`docs/modbus-master.md` §2.3).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct SerialPort {
    /// The port's name, which devices name in their `serial_port`, such as `RS485`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The device file on the target, such as `/dev/ttyUSB0`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub device: String,
    /// The line's speed in bits per second.
    pub baud_rate: u32,
    /// The parity bit of every character.
    pub parity: Parity,
    /// Data bits per character (Modbus RTU sends 8).
    pub data_bits: u8,
    /// Stop bits per character, 1 or 2.
    pub stop_bits: u8,
    /// The silence kept before each request, in microseconds; 0 means the standard's 3.5
    /// character times.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub inter_frame_delay_us: u32,
}

/// The parity of a serial line.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum Parity {
    /// No parity bit.
    None,
    /// Even parity, the Modbus serial line standard's default.
    #[default]
    Even,
    /// Odd parity.
    Odd,
}

impl SerialPort {
    /// The baud rates a port may use, in the order editors offer them.
    pub const BAUD_RATES: [u32; 9] = [1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400];

    /// The longest inter-frame delay, in microseconds (1 s).
    pub const MAX_INTER_FRAME_DELAY_US: u32 = 1_000_000;

    /// A port named `name` on `device` with the Modbus serial line standard's settings: 19200
    /// baud, 8 data bits, even parity, one stop bit, and the standard's inter-frame delay.
    pub fn new(name: impl Into<String>, device: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            device: device.into(),
            baud_rate: 19200,
            parity: Parity::Even,
            data_bits: 8,
            stop_bits: 1,
            inter_frame_delay_us: 0,
        }
    }
}

impl Parity {
    /// Every parity, in the order editors offer them.
    pub const ALL: [Self; 3] = [Self::None, Self::Even, Self::Odd];
}

impl Project {
    /// The names of the Modbus devices on the serial port named `name` (compared as
    /// identifiers, without regard to case), in the project's order: the devices a rename
    /// carries along and that keep the port from being deleted.
    pub fn devices_on_serial_port(&self, name: &str) -> Vec<&str> {
        self.modbus_devices
            .iter()
            .filter(|device| {
                device
                    .serial_port()
                    .is_some_and(|port| same_identifier(port, name))
            })
            .map(|device| device.name.as_str())
            .collect()
    }
}

/// Whether the inter-frame delay is the default, which the manifest leaves out.
fn is_zero(value: &u32) -> bool {
    *value == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_port_reads_every_key_and_leaves_the_default_delay_out_when_written() {
        let text = "name = \"RS485\"\ndevice = \"/dev/ttyUSB0\"\nbaud_rate = 19200\n\
                    parity = \"even\"\ndata_bits = 8\nstop_bits = 1\n";
        let port: SerialPort = toml::from_str(text).unwrap();
        assert_eq!(port, SerialPort::new("RS485", "/dev/ttyUSB0"));
        assert_eq!(toml::to_string(&port).unwrap(), text);
        let delayed: SerialPort =
            toml::from_str(&format!("{text}inter_frame_delay_us = 5000\n")).unwrap();
        assert_eq!(delayed.inter_frame_delay_us, 5000);
    }

    #[test]
    fn the_devices_on_a_port_are_found_without_regard_to_case() {
        let mut project = Project::default();
        project
            .serial_ports
            .push(SerialPort::new("RS485", "/dev/ttyUSB0"));
        let mut drive = crate::ModbusDevice::tcp("Drive", "127.0.0.1", 502);
        drive.link = crate::ModbusLink::Rtu {
            serial_port: "rs485".into(),
        };
        let mut meter = drive.clone();
        meter.name = "Meter".into();
        let panel = crate::ModbusDevice::tcp("Panel", "127.0.0.1", 502);
        project.modbus_devices = vec![drive, panel, meter];
        assert_eq!(
            project.devices_on_serial_port("RS485"),
            vec!["Drive", "Meter"]
        );
        assert!(project.devices_on_serial_port("RS232").is_empty());
    }

    #[test]
    fn an_unknown_parity_is_refused_naming_the_three() {
        let text = "name = \"A\"\ndevice = \"d\"\nbaud_rate = 9600\nparity = \"mark\"\n\
                    data_bits = 8\nstop_bits = 1\n";
        let error = toml::from_str::<SerialPort>(text).unwrap_err().to_string();
        assert!(error.contains("none") && error.contains("odd"), "{error}");
    }
}
