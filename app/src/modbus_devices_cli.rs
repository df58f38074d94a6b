//! `rivet devices`: the Modbus devices a runtime masters, one line each, as the runtime's
//! `MODBUS_DEVICES` service reports them (`docs/modbus-master.md` §9.1).

use online::{ModbusDeviceReport, ModbusDeviceState};

/// The names and values of `MB_ErrorCodes` (`compiler/src/library/modbus.st`, §3.1), so a
/// last error reads as the name the program's `eLastError` shows.
const ERROR_CODE_NAMES: [(u8, &str); 21] = [
    (0x00, "RESPONSE_SUCCESS"),
    (0x01, "ILLEGAL_FUNCTION"),
    (0x02, "ILLEGAL_DATA_ADDRESS"),
    (0x03, "ILLEGAL_DATA_VALUE"),
    (0x04, "SLAVE_DEVICE_FAILURE"),
    (0x05, "ACKNOWLEDGE"),
    (0x06, "SLAVE_DEVICE_BUSY"),
    (0x07, "NEGATIVE_ACKNOWLEDGE"),
    (0x08, "MEMORY_PARITY_ERROR"),
    (0x0A, "GATEWAY_PATH_UNAVAILABLE"),
    (0x0B, "GATEWAY_DEVICE_FAILED_TO_RESPOND"),
    (0xA1, "RESPONSE_TIMEOUT"),
    (0xA2, "RESPONSE_CRC_FAIL"),
    (0xA3, "RESPONSE_WRONG_SLAVE"),
    (0xA4, "RESPONSE_WRONG_FUNCTIONCODE"),
    (0xA5, "TCP_COMMUNICATION_ERROR"),
    (0xA6, "RESPONSE_INVALID_DATA"),
    (0xA7, "RESPONSE_INVALID_PROTOCOL"),
    (0xA8, "RESPONSE_INVALID_HEADER"),
    (0xC0, "SERIAL_PORT_ERROR"),
    (0xC1, "NOT_YET_POLLED"),
];

/// The `MB_ErrorCodes` name of `code`, or `16#XX` for a value the library does not name (a
/// newer runtime's), so nothing is hidden.
pub fn error_code_name(code: u8) -> String {
    ERROR_CODE_NAMES
        .iter()
        .find(|(value, _)| *value == code)
        .map_or_else(|| format!("16#{code:02X}"), |(_, name)| (*name).to_owned())
}

/// A device's state in words, as the CLI prints it.
pub fn state_in_words(state: ModbusDeviceState) -> &'static str {
    match state {
        ModbusDeviceState::Starting => "starting",
        ModbusDeviceState::Communicating => "communicating",
        ModbusDeviceState::AnsweringWithErrors => "answering with errors",
        ModbusDeviceState::NotAnswering => "not answering",
        ModbusDeviceState::SerialPortError => "serial port error",
        ModbusDeviceState::Off => "off",
    }
}

/// One device's line of `rivet devices`: name, state, last error and exception, the counters,
/// and the last failure in words when there is one.
pub fn device_line(device: &ModbusDeviceReport) -> String {
    let since = device
        .since_last_error_ms
        .map_or_else(String::new, |ms| format!(", last error {ms} ms ago"));
    let detail = if device.detail.is_empty() {
        String::new()
    } else {
        format!(": {}", device.detail)
    };
    format!(
        "device '{}': {}, last error {}, last exception {}, {} consecutive errors, {} requests, \
         {} errors, {} rounds, {} overruns, last response {} µs{since}{detail}",
        device.name,
        state_in_words(device.state),
        error_code_name(device.last_error),
        device.last_exception,
        device.consecutive_errors,
        device.requests,
        device.errors,
        device.rounds,
        device.overruns,
        device.last_response_us,
    )
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

    use super::*;

    /// A device that timed out 35 ms ago.
    fn timed_out() -> ModbusDeviceReport {
        ModbusDeviceReport {
            name: "BeltDrive".to_owned(),
            state: ModbusDeviceState::NotAnswering,
            last_error: 0xA1,
            last_exception: 0,
            consecutive_errors: 4,
            requests: 100,
            errors: 4,
            rounds: 50,
            overruns: 1,
            last_response_us: 1200,
            since_last_error_ms: Some(35),
            detail: "no answer within 100 ms".to_owned(),
        }
    }

    #[test]
    fn a_line_names_the_state_the_error_and_every_counter() {
        assert_eq!(
            device_line(&timed_out()),
            "device 'BeltDrive': not answering, last error RESPONSE_TIMEOUT, last exception 0, \
             4 consecutive errors, 100 requests, 4 errors, 50 rounds, 1 overruns, last response \
             1200 µs, last error 35 ms ago: no answer within 100 ms"
        );
    }

    #[test]
    fn a_device_without_a_failure_has_no_age_and_no_detail() {
        let device = ModbusDeviceReport {
            state: ModbusDeviceState::Communicating,
            last_error: 0,
            since_last_error_ms: None,
            detail: String::new(),
            ..timed_out()
        };
        let line = device_line(&device);
        assert!(
            line.ends_with("last response 1200 µs") && line.contains("communicating"),
            "{line}"
        );
        assert!(line.contains("last error RESPONSE_SUCCESS"), "{line}");
    }

    #[test]
    fn an_error_code_the_library_does_not_name_shows_its_number() {
        assert_eq!(error_code_name(0x42), "16#42");
        assert_eq!(error_code_name(0xC0), "SERIAL_PORT_ERROR");
    }

    #[test]
    fn the_names_are_the_modbus_library_s_own() {
        // Every `NAME := 16#XX` of the library's MB_ErrorCodes, read from its text.
        let library = include_str!("../../compiler/src/library/modbus.st");
        let enumeration = library
            .split("TYPE MB_ErrorCodes")
            .nth(1)
            .and_then(|rest| rest.split("END_TYPE").next())
            .unwrap();
        let declared: Vec<(u8, String)> = enumeration
            .lines()
            .filter_map(|line| {
                let (name, value) = line.split_once(":=")?;
                let hex = value.trim().trim_start_matches("16#");
                let hex: String = hex.chars().take_while(char::is_ascii_hexdigit).collect();
                Some((
                    u8::from_str_radix(&hex, 16).unwrap(),
                    name.trim().to_owned(),
                ))
            })
            .collect();
        let ours: Vec<(u8, String)> = ERROR_CODE_NAMES
            .iter()
            .map(|(value, name)| (*value, (*name).to_owned()))
            .collect();
        assert_eq!(ours, declared);
    }
}
