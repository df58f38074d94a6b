//! The `MODBUS_DEVICES` service (`docs/modbus-master.md` §9.1): the state and counters of the
//! devices the runtime's Modbus master polls, page by page.

use online_protocol::{ModbusDeviceReport, ModbusDeviceState, Response, modbus_devices_page};

use super::OnlineServices;
use crate::modbus::master::{DeviceSnapshot, DeviceState};

impl OnlineServices {
    /// The page of devices from the `from`-th on, in the image's order; `total` 0 without a
    /// program or without runtime devices.
    pub(super) fn modbus_devices(&self, from: u8) -> Response {
        let reports: Vec<ModbusDeviceReport> = self
            .scheduler
            .modbus_devices()
            .iter()
            .map(report_of)
            .collect();
        modbus_devices_page(&reports, from)
    }
}

/// A device's snapshot as the protocol reports it: the same state and counters the program's
/// status variable holds.
fn report_of(snapshot: &DeviceSnapshot) -> ModbusDeviceReport {
    ModbusDeviceReport {
        name: snapshot.name.clone(),
        state: state_of(snapshot.state),
        last_error: snapshot.last_error,
        last_exception: snapshot.last_exception,
        consecutive_errors: snapshot.consecutive_errors,
        requests: snapshot.requests,
        errors: snapshot.errors,
        rounds: snapshot.rounds,
        overruns: snapshot.overruns,
        last_response_us: snapshot.last_response_us,
        since_last_error_ms: (snapshot.since_last_error_ms != u32::MAX)
            .then_some(snapshot.since_last_error_ms),
        detail: snapshot.detail.clone(),
    }
}

/// The protocol's state for the master's: the two enumerations have the same six states.
fn state_of(state: DeviceState) -> ModbusDeviceState {
    match state {
        DeviceState::Starting => ModbusDeviceState::Starting,
        DeviceState::Communicating => ModbusDeviceState::Communicating,
        DeviceState::AnsweringWithErrors => ModbusDeviceState::AnsweringWithErrors,
        DeviceState::NotAnswering => ModbusDeviceState::NotAnswering,
        DeviceState::SerialPortError => ModbusDeviceState::SerialPortError,
        DeviceState::Off => ModbusDeviceState::Off,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn snapshot(state: DeviceState, since_last_error_ms: u32) -> DeviceSnapshot {
        DeviceSnapshot {
            name: "BeltDrive".to_owned(),
            state,
            last_error: 0xA1,
            last_exception: 2,
            consecutive_errors: 3,
            requests: 40,
            errors: 5,
            rounds: 20,
            overruns: 1,
            connection_attempts: 2,
            last_response_us: 850,
            since_last_error_ms,
            detail: "no answer from 127.0.0.1:5502 within 100 ms".to_owned(),
        }
    }

    #[test]
    fn a_snapshot_is_reported_with_its_counters_and_state() {
        let report = report_of(&snapshot(DeviceState::NotAnswering, 1500));
        assert_eq!(report.name, "BeltDrive");
        assert_eq!(report.state, ModbusDeviceState::NotAnswering);
        assert_eq!(
            (report.last_error, report.last_exception),
            (0xA1, 2),
            "the MB_ErrorCodes value and the exception pass unchanged"
        );
        assert_eq!(
            (
                report.consecutive_errors,
                report.requests,
                report.errors,
                report.rounds,
                report.overruns,
                report.last_response_us
            ),
            (3, 40, 5, 20, 1, 850)
        );
        assert_eq!(report.since_last_error_ms, Some(1500));
        assert_eq!(report.detail, "no answer from 127.0.0.1:5502 within 100 ms");
    }

    #[test]
    fn no_failure_yet_is_reported_as_none_and_every_state_keeps_its_number() {
        assert_eq!(
            report_of(&snapshot(DeviceState::Starting, u32::MAX)).since_last_error_ms,
            None
        );
        for state in [
            DeviceState::Starting,
            DeviceState::Communicating,
            DeviceState::AnsweringWithErrors,
            DeviceState::NotAnswering,
            DeviceState::SerialPortError,
            DeviceState::Off,
        ] {
            assert_eq!(state_of(state) as u8, state as u8, "{state:?}");
        }
    }
}
