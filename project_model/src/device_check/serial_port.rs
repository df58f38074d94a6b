//! Checks of a serial port: its name, device file and line settings.

use super::{DeviceProblem, name_problems, others};
use crate::SerialPort;

/// Every problem of `port` as the serial port at `index` of `ports` (`None` for a new one): its
/// name, device file, baud rate, data and stop bits and inter-frame delay. Data bits of 7 pass
/// here and are reported by the build, since Modbus RTU sends 8 (`docs/modbus-master.md` §2.3).
pub fn serial_port_problems(
    ports: &[SerialPort],
    index: Option<usize>,
    port: &SerialPort,
) -> Vec<DeviceProblem> {
    let mut problems = name_problems(
        "serial port",
        &port.name,
        others(ports, index).map(|(_, other)| other.name.as_str()),
    );
    if port.device.trim().is_empty() {
        problems.push(DeviceProblem::EmptyDevice);
    }
    if !SerialPort::BAUD_RATES.contains(&port.baud_rate) {
        problems.push(DeviceProblem::UnsupportedBaudRate(port.baud_rate));
    }
    if !matches!(port.data_bits, 7 | 8) {
        problems.push(DeviceProblem::UnsupportedDataBits(port.data_bits));
    }
    if !matches!(port.stop_bits, 1 | 2) {
        problems.push(DeviceProblem::UnsupportedStopBits(port.stop_bits));
    }
    if port.inter_frame_delay_us > SerialPort::MAX_INTER_FRAME_DELAY_US {
        problems.push(DeviceProblem::InterFrameDelayTooLong(
            port.inter_frame_delay_us,
        ));
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_standard_port_and_its_limits_pass() {
        let mut port = SerialPort::new("RS485", "/dev/ttyUSB0");
        assert!(serial_port_problems(&[], None, &port).is_empty());
        port.data_bits = 7;
        port.stop_bits = 2;
        port.baud_rate = 230400;
        port.inter_frame_delay_us = 1_000_000;
        assert!(serial_port_problems(&[], None, &port).is_empty());
    }

    #[test]
    fn every_setting_out_of_range_is_named() {
        let mut port = SerialPort::new("RS485", " ");
        port.baud_rate = 14400;
        port.data_bits = 6;
        port.stop_bits = 0;
        port.inter_frame_delay_us = 1_000_001;
        assert_eq!(
            serial_port_problems(&[], None, &port),
            [
                DeviceProblem::EmptyDevice,
                DeviceProblem::UnsupportedBaudRate(14400),
                DeviceProblem::UnsupportedDataBits(6),
                DeviceProblem::UnsupportedStopBits(0),
                DeviceProblem::InterFrameDelayTooLong(1_000_001),
            ]
        );
        assert_eq!(
            DeviceProblem::UnsupportedBaudRate(14400).to_string(),
            "14400 baud is not offered: choose 1200, 2400, 4800, 9600, 19200, 38400, 57600, \
             115200 or 230400"
        );
    }

    #[test]
    fn a_second_port_of_the_same_name_is_refused_without_regard_to_case() {
        let ports = [SerialPort::new("RS485", "/dev/ttyS0")];
        let other = SerialPort::new("rs485", "/dev/ttyS1");
        assert_eq!(
            serial_port_problems(&ports, None, &other),
            [DeviceProblem::DuplicateName {
                kind: "serial port",
                name: "rs485".into()
            }]
        );
        assert!(serial_port_problems(&ports, Some(0), &ports[0]).is_empty());
    }
}
