//! What the studio shows of a runtime Modbus device while logged in (`docs/modbus-master.md`
//! §9.2, §6.11): its state as one of four lights, the state and the last error in words, and
//! the master's counters, decided here from the runtime's report so the device tree, the
//! device editor and the status line only draw them.

use online::{ModbusDeviceReport, ModbusDeviceState, TargetState};
use project_model::ModbusDevice;

use super::i18n::{Language, ModbusOnlineText};
use super::online::Online;
use super::online::modbus_reports::ModbusReportsProblem;
use super::theme::StudioColors;
use crate::modbus_devices_cli::error_code_name;

/// The light a runtime device's node shows: what a PLC engineer wants to see at a glance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum DeviceLight {
    /// The last round had no failure.
    Communicating,
    /// The device answers with errors, does not answer, or its serial port failed.
    Failing,
    /// Nothing reaches the program: the runtime's master is off, or the program is not running
    /// (the master may still poll the device, and its counters say so).
    Off,
    /// No round has ended yet, or the runtime has not reported the device yet.
    Waiting,
}

/// A runtime device's online state in words, for the tree's tooltip and the editor's Online
/// part. Made each frame from the last report; not kept.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct DeviceOnline {
    /// The light of the device's node.
    pub light: DeviceLight,
    /// The state in words: "Not answering".
    pub state: String,
    /// The last error and the counters, each a label and its value, in the order shown.
    pub rows: Vec<(String, String)>,
}

impl DeviceLight {
    /// The theme's colour of the light.
    pub(crate) fn color(self, colors: &StudioColors) -> egui::Color32 {
        match self {
            Self::Communicating => colors.device_communicating,
            Self::Failing => colors.device_failing,
            Self::Off => colors.device_off,
            Self::Waiting => colors.device_waiting,
        }
    }
}

/// What the studio shows of `device` now: `None` for a studio device (no I/O task), and when
/// not logged in to a target that runs the project's program with runtime devices.
pub(crate) fn device_online(
    online: &Online,
    device: &ModbusDevice,
    language: Language,
) -> Option<DeviceOnline> {
    if !device.is_runtime_device() || !online.is_online() || online.runtime_device_count() == 0 {
        return None;
    }
    Some(describe(
        online.modbus_device_report(&device.name),
        online.modbus_reports_answered(),
        online.modbus_reports_problem(),
        online.target_state(),
        language,
    ))
}

/// A device's online state from its last `report` (`None`: the runtime has not reported it;
/// `answered` when it has reported other devices), the last question's `problem` and the
/// target's `program` state.
pub(crate) fn describe(
    report: Option<&ModbusDeviceReport>,
    answered: bool,
    problem: Option<&ModbusReportsProblem>,
    program: Option<TargetState>,
    language: Language,
) -> DeviceOnline {
    let word = |text: ModbusOnlineText| text.get(language).to_owned();
    let Some(report) = report else {
        let state = match problem {
            Some(ModbusReportsProblem::NotReported) => word(ModbusOnlineText::NotReported),
            Some(ModbusReportsProblem::Refused(reason)) => {
                ModbusOnlineText::Refused.fill(language, &[("reason", reason)])
            }
            // Reports came, but without this device: the target runs a build from before the
            // device got its I/O task.
            None if answered => word(ModbusOnlineText::NotInProgram),
            None => word(ModbusOnlineText::NoReportYet),
        };
        return DeviceOnline {
            light: DeviceLight::Waiting,
            state,
            rows: Vec::new(),
        };
    };
    let running = matches!(program, Some(TargetState::Running | TargetState::Faulted));
    let (light, state) = match report.state {
        ModbusDeviceState::Off => (DeviceLight::Off, ModbusOnlineText::MasterOff),
        // A stopped program copies nothing in or out, whatever the master last did.
        _ if !running => (DeviceLight::Off, ModbusOnlineText::ProgramNotRunning),
        ModbusDeviceState::Starting => (DeviceLight::Waiting, ModbusOnlineText::NotYetConnected),
        ModbusDeviceState::Communicating => {
            (DeviceLight::Communicating, ModbusOnlineText::Communicating)
        }
        ModbusDeviceState::AnsweringWithErrors => {
            (DeviceLight::Failing, ModbusOnlineText::AnsweringWithErrors)
        }
        ModbusDeviceState::NotAnswering => (DeviceLight::Failing, ModbusOnlineText::NotAnswering),
        ModbusDeviceState::SerialPortError => {
            (DeviceLight::Failing, ModbusOnlineText::SerialPortError)
        }
    };
    DeviceOnline {
        light,
        state: word(state),
        rows: counter_rows(report, language),
    }
}

/// The last error, the last exception and the counters of `report`, each a label and a value.
pub(crate) fn counter_rows(
    report: &ModbusDeviceReport,
    language: Language,
) -> Vec<(String, String)> {
    let word = |text: ModbusOnlineText| text.get(language).to_owned();
    let mut last_error = error_in_words(report.last_error, language);
    if !report.detail.is_empty() {
        // The runtime's own words name what failed ("connection refused by 127.0.0.1:5502").
        last_error = format!("{last_error}: {}", report.detail);
    }
    if let (Some(age_ms), true) = (report.since_last_error_ms, report.last_error != 0) {
        last_error = ModbusOnlineText::LastErrorAgo.fill(
            language,
            &[("error", &last_error), ("age", &duration_words(age_ms))],
        );
    }
    let last_exception = match report.last_exception {
        0 => word(ModbusOnlineText::NoException),
        code => format!("{code} ({})", error_code_name(code)),
    };
    vec![
        (word(ModbusOnlineText::LastError), last_error),
        (word(ModbusOnlineText::LastException), last_exception),
        (word(ModbusOnlineText::Rounds), report.rounds.to_string()),
        (
            word(ModbusOnlineText::Requests),
            report.requests.to_string(),
        ),
        (word(ModbusOnlineText::Errors), report.errors.to_string()),
        (
            word(ModbusOnlineText::ConsecutiveErrors),
            report.consecutive_errors.to_string(),
        ),
        (
            word(ModbusOnlineText::Overruns),
            report.overruns.to_string(),
        ),
        (
            word(ModbusOnlineText::LastResponse),
            response_time_words(report.last_response_us),
        ),
    ]
}

/// An `MB_ErrorCodes` value in the words of `language`, followed by its name in the library
/// ("No answer within the timeout (RESPONSE_TIMEOUT)") so it matches what the program's
/// `eLastError` shows; a value the library does not name shows its number.
pub(crate) fn error_in_words(code: u8, language: Language) -> String {
    let words = match code {
        0x00 => ModbusOnlineText::ResponseSuccess,
        0x01 => ModbusOnlineText::IllegalFunction,
        0x02 => ModbusOnlineText::IllegalDataAddress,
        0x03 => ModbusOnlineText::IllegalDataValue,
        0x04 => ModbusOnlineText::SlaveDeviceFailure,
        0x05 => ModbusOnlineText::Acknowledge,
        0x06 => ModbusOnlineText::SlaveDeviceBusy,
        0x07 => ModbusOnlineText::NegativeAcknowledge,
        0x08 => ModbusOnlineText::MemoryParityError,
        0x0A => ModbusOnlineText::GatewayPathUnavailable,
        0x0B => ModbusOnlineText::GatewayDeviceFailedToRespond,
        0xA1 => ModbusOnlineText::ResponseTimeout,
        0xA2 => ModbusOnlineText::ResponseCrcFail,
        0xA3 => ModbusOnlineText::ResponseWrongSlave,
        0xA4 => ModbusOnlineText::ResponseWrongFunctionCode,
        0xA5 => ModbusOnlineText::TcpCommunicationError,
        0xA6 => ModbusOnlineText::ResponseInvalidData,
        0xA7 => ModbusOnlineText::ResponseInvalidProtocol,
        0xA8 => ModbusOnlineText::ResponseInvalidHeader,
        0xC0 => ModbusOnlineText::SerialPortFailed,
        0xC1 => ModbusOnlineText::NotYetPolled,
        _ => {
            let number = format!("16#{code:02X}");
            return ModbusOnlineText::ErrorCodeUnknown.fill(language, &[("code", &number)]);
        }
    };
    format!("{} ({})", words.get(language), error_code_name(code))
}

/// The status line's words while logged in to the simulator whose master polls `count`
/// devices (`docs/modbus-master.md` §6.11); `None` without runtime devices.
pub(crate) fn polling_status(count: usize, language: Language) -> Option<String> {
    let text = match count {
        0 => return None,
        1 => ModbusOnlineText::PollingOne,
        _ => ModbusOnlineText::PollingMany,
    };
    Some(text.fill(language, &[("count", &count.to_string())]))
}

/// A response time as engineers read it: `850 µs`, `12.3 ms`.
fn response_time_words(time_us: u32) -> String {
    if time_us < 1000 {
        format!("{time_us} µs")
    } else {
        format!("{:.1} ms", f64::from(time_us) / 1000.0)
    }
}

/// A time since an event: `350 ms`, `4.2 s`, `12 min`.
fn duration_words(time_ms: u32) -> String {
    match time_ms {
        0..1000 => format!("{time_ms} ms"),
        1000..120_000 => format!("{:.1} s", f64::from(time_ms) / 1000.0),
        _ => format!("{} min", time_ms / 60_000),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A device that timed out 1.5 s ago and is still not answering.
    fn timed_out() -> ModbusDeviceReport {
        ModbusDeviceReport {
            name: "Drive".to_owned(),
            state: ModbusDeviceState::NotAnswering,
            last_error: 0xA1,
            last_exception: 0,
            consecutive_errors: 4,
            requests: 100,
            errors: 4,
            rounds: 50,
            overruns: 1,
            last_response_us: 1250,
            since_last_error_ms: Some(1500),
            detail: "no answer within 100 ms".to_owned(),
        }
    }

    fn communicating() -> ModbusDeviceReport {
        ModbusDeviceReport {
            state: ModbusDeviceState::Communicating,
            last_error: 0,
            consecutive_errors: 0,
            since_last_error_ms: None,
            detail: String::new(),
            last_response_us: 420,
            ..timed_out()
        }
    }

    const RUNNING: Option<TargetState> = Some(TargetState::Running);

    #[test]
    fn each_report_state_gets_its_light_while_the_program_runs() {
        let light = |state| {
            let report = ModbusDeviceReport {
                state,
                ..timed_out()
            };
            describe(Some(&report), true, None, RUNNING, Language::English).light
        };
        assert_eq!(
            light(ModbusDeviceState::Communicating),
            DeviceLight::Communicating
        );
        assert_eq!(light(ModbusDeviceState::Starting), DeviceLight::Waiting);
        assert_eq!(
            light(ModbusDeviceState::AnsweringWithErrors),
            DeviceLight::Failing
        );
        assert_eq!(light(ModbusDeviceState::NotAnswering), DeviceLight::Failing);
        assert_eq!(
            light(ModbusDeviceState::SerialPortError),
            DeviceLight::Failing
        );
        assert_eq!(light(ModbusDeviceState::Off), DeviceLight::Off);
    }

    #[test]
    fn a_stopped_program_shows_its_devices_off_and_a_faulted_one_does_not() {
        let report = communicating();
        let stopped = describe(
            Some(&report),
            true,
            None,
            Some(TargetState::Stopped),
            Language::English,
        );
        assert_eq!(stopped.light, DeviceLight::Off);
        assert_eq!(
            stopped.state,
            "Off: the program is not running, so no values are copied"
        );
        let faulted = describe(
            Some(&report),
            true,
            None,
            Some(TargetState::Faulted),
            Language::English,
        );
        assert_eq!(faulted.light, DeviceLight::Communicating);
        // The master being off says so, whatever the program does.
        let off = ModbusDeviceReport {
            state: ModbusDeviceState::Off,
            ..report
        };
        let off = describe(
            Some(&off),
            true,
            None,
            Some(TargetState::Stopped),
            Language::English,
        );
        assert_eq!(off.state, "Off: the runtime's Modbus master is off");
    }

    #[test]
    fn the_rows_name_the_last_error_in_words_with_its_detail_and_age_and_every_counter() {
        let shown = describe(Some(&timed_out()), true, None, RUNNING, Language::English);
        assert_eq!(shown.state, "Not answering");
        let rows: Vec<(&str, &str)> = shown
            .rows
            .iter()
            .map(|(label, value)| (label.as_str(), value.as_str()))
            .collect();
        assert_eq!(
            rows,
            [
                (
                    "Last error",
                    "No answer within the timeout (RESPONSE_TIMEOUT): no answer within 100 ms, \
                     1.5 s ago"
                ),
                ("Last exception code", "0 (none)"),
                ("Rounds", "50"),
                ("Requests", "100"),
                ("Errors", "4"),
                ("Consecutive errors", "4"),
                ("Overruns", "1"),
                ("Last response time", "1.2 ms"),
            ]
        );
    }

    #[test]
    fn a_device_without_failures_says_no_error_and_an_exception_is_named() {
        let shown = describe(
            Some(&communicating()),
            true,
            None,
            RUNNING,
            Language::English,
        );
        assert_eq!(shown.rows[0].1, "No error (RESPONSE_SUCCESS)");
        assert_eq!(shown.rows[7].1, "420 µs");
        let exception = ModbusDeviceReport {
            state: ModbusDeviceState::AnsweringWithErrors,
            last_error: 2,
            last_exception: 2,
            since_last_error_ms: Some(20),
            detail: String::new(),
            ..timed_out()
        };
        let shown = describe(Some(&exception), true, None, RUNNING, Language::English);
        assert_eq!(
            shown.rows[0].1,
            "The device has no such address (ILLEGAL_DATA_ADDRESS), 20 ms ago"
        );
        assert_eq!(shown.rows[1].1, "2 (ILLEGAL_DATA_ADDRESS)");
    }

    #[test]
    fn the_words_are_chinese_when_chosen() {
        let shown = describe(
            Some(&timed_out()),
            true,
            None,
            RUNNING,
            Language::SimplifiedChinese,
        );
        assert_eq!(shown.state, "无应答");
        assert_eq!(shown.rows[0].0, "最近错误");
        assert!(
            shown.rows[0].1.starts_with("响应超时 (RESPONSE_TIMEOUT)"),
            "{}",
            shown.rows[0].1
        );
        assert_eq!(
            error_in_words(0xA5, Language::SimplifiedChinese),
            "与设备的 TCP 连接失败 (TCP_COMMUNICATION_ERROR)"
        );
    }

    #[test]
    fn every_named_error_code_has_words_of_its_own_and_an_unknown_one_its_number() {
        let named = [
            0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x0A, 0x0B, 0xA1, 0xA2, 0xA3,
            0xA4, 0xA5, 0xA6, 0xA7, 0xA8, 0xC0, 0xC1,
        ];
        for language in [Language::English, Language::SimplifiedChinese] {
            let words: std::collections::HashSet<String> = named
                .iter()
                .map(|&code| error_in_words(code, language))
                .collect();
            assert_eq!(words.len(), named.len(), "{language:?}");
            for code in named {
                assert!(
                    !error_in_words(code, language).contains("16#"),
                    "{code:#04x} has no name"
                );
            }
        }
        assert_eq!(error_in_words(0x42, Language::English), "Error code 16#42");
        assert_eq!(
            error_in_words(0x42, Language::SimplifiedChinese),
            "错误代码 16#42"
        );
    }

    #[test]
    fn a_device_not_reported_waits_and_says_why() {
        let shown = describe(None, false, None, RUNNING, Language::English);
        assert_eq!(shown.light, DeviceLight::Waiting);
        assert_eq!(
            shown.state,
            "Not yet connected: no report from the runtime yet"
        );
        assert!(shown.rows.is_empty());
        let older_build = describe(None, true, None, RUNNING, Language::English);
        assert_eq!(
            older_build.state,
            "Not in the program on the target: build and download to poll it"
        );
        let old = describe(
            None,
            false,
            Some(&ModbusReportsProblem::NotReported),
            RUNNING,
            Language::English,
        );
        assert_eq!(old.state, "This runtime does not report its Modbus devices");
        let refused = describe(
            None,
            false,
            Some(&ModbusReportsProblem::Refused("busy".into())),
            RUNNING,
            Language::SimplifiedChinese,
        );
        assert_eq!(refused.state, "运行时未报告其 Modbus 设备：busy");
    }

    #[test]
    fn the_status_line_counts_devices_in_the_singular_and_the_plural() {
        assert_eq!(polling_status(0, Language::English), None);
        assert_eq!(
            polling_status(1, Language::English).as_deref(),
            Some("Simulator: polling 1 Modbus device")
        );
        assert_eq!(
            polling_status(2, Language::English).as_deref(),
            Some("Simulator: polling 2 Modbus devices")
        );
        assert_eq!(
            polling_status(2, Language::SimplifiedChinese).as_deref(),
            Some("仿真器：正在轮询 2 个 Modbus 设备")
        );
    }

    #[test]
    fn times_read_in_the_unit_that_fits() {
        assert_eq!(response_time_words(999), "999 µs");
        assert_eq!(response_time_words(12_345), "12.3 ms");
        assert_eq!(duration_words(350), "350 ms");
        assert_eq!(duration_words(4_200), "4.2 s");
        assert_eq!(duration_words(720_000), "12 min");
    }
}
