//! What the studio shows of a runtime Modbus device while logged in (`docs/modbus-master.md`
//! §9.2, §6.11): its state as one of four lights, the state and the last error in words, and
//! the master's counters, decided here from the runtime's report so the device tree, the
//! device editor and the status line only draw them.

use online::{ModbusDeviceReport, ModbusDeviceState, TargetState, TaskInfo};
use project_model::{ModbusDevice, same_identifier};

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
    /// Nothing reaches the program: the runtime's master is off, or the program or the
    /// device's I/O task is not running (the master may still poll the device, and its
    /// counters say so).
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
    let io_task = device.task.as_deref().unwrap_or_default();
    Some(describe(
        online.modbus_device_report(&device.name),
        online.modbus_reports_answered(),
        online.modbus_reports_problem(),
        io_task_runs(online.target_state(), online.tasks(), io_task),
        language,
    ))
}

/// Whether the I/O task named `io_task` runs, so that values are exchanged with its devices:
/// the target's program runs (`state`, refreshed with each `MODBUS_DEVICES` answer) and the
/// last task statistics do not say a fault stopped that task.
pub(crate) fn io_task_runs(state: Option<TargetState>, tasks: &[TaskInfo], io_task: &str) -> bool {
    let program_runs = matches!(state, Some(TargetState::Running | TargetState::Faulted));
    let task_faulted = tasks
        .iter()
        .any(|task| task.faulted && same_identifier(&task.name, io_task));
    program_runs && !task_faulted
}

/// A device's online state from its last `report` (`None`: the runtime has not reported it;
/// `answered` when it has reported other devices), the last question's `problem` and whether
/// its I/O task runs (`task_runs`).
pub(crate) fn describe(
    report: Option<&ModbusDeviceReport>,
    answered: bool,
    problem: Option<&ModbusReportsProblem>,
    task_runs: bool,
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
    // The runtime reports the master's view only: it polls on while the program is stopped
    // (state 5 means the master itself is off), so whether values reach the program is decided
    // here.
    let (light, state) = match report.state {
        ModbusDeviceState::Off => (DeviceLight::Off, ModbusOnlineText::MasterOff),
        // A stopped program or I/O task copies nothing in or out, whatever the master last did.
        _ if !task_runs => (DeviceLight::Off, ModbusOnlineText::ProgramNotRunning),
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
        last_error = ModbusOnlineText::ErrorDetail.fill(
            language,
            &[("error", &last_error), ("detail", &report.detail)],
        );
    }
    if let (Some(age_ms), true) = (report.since_last_error_ms, report.last_error != 0) {
        last_error = ModbusOnlineText::LastErrorAgo.fill(
            language,
            &[
                ("error", &last_error),
                ("age", &duration_words(age_ms, language)),
            ],
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
            response_time_words(report.last_response_us, language),
        ),
    ]
}

/// An `MB_ErrorCodes` value in the words of `language`, followed by its name in the library
/// ("No answer within the timeout (RESPONSE_TIMEOUT)") so it matches what the program's
/// `eLastError` shows; a value the library does not name shows its number.
pub(crate) fn error_in_words(code: u8, language: Language) -> String {
    match error_words(code) {
        Some(words) => format!("{} ({})", words.get(language), error_code_name(code)),
        None => {
            let number = format!("16#{code:02X}");
            ModbusOnlineText::ErrorCodeUnknown.fill(language, &[("code", &number)])
        }
    }
}

/// The words of an `MB_ErrorCodes` value the library names; `None` for any other value.
fn error_words(code: u8) -> Option<ModbusOnlineText> {
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
        _ => return None,
    };
    Some(words)
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

/// A response time as engineers read it: `850 µs`, `12.3 ms`; "None yet" for 0, which the
/// runtime keeps until the device's first answer (an answer takes at least a microsecond).
fn response_time_words(time_us: u32, language: Language) -> String {
    match time_us {
        0 => ModbusOnlineText::NoResponseYet.get(language).to_owned(),
        // Units of the metric system read the same in both languages.
        1..1000 => format!("{time_us} µs"),
        _ => format!("{:.1} ms", f64::from(time_us) / 1000.0),
    }
}

/// A time since an event in the unit that fits, in the words of `language`: `350 ms`,
/// `4.2 s`, `12 min`, `2 h` ("4.2 秒", "12 分钟", "2 小时").
fn duration_words(time_ms: u32, language: Language) -> String {
    const MINUTE_MS: u32 = 60_000;
    const HOUR_MS: u32 = 60 * MINUTE_MS;
    // Each unit is used up to twice the next one, so a value never reads as 1 of a coarse unit.
    let (unit, value) = match time_ms {
        0..1000 => (ModbusOnlineText::Milliseconds, time_ms.to_string()),
        1000..120_000 => (
            ModbusOnlineText::Seconds,
            format!("{:.1}", f64::from(time_ms) / 1000.0),
        ),
        120_000..7_200_000 => (ModbusOnlineText::Minutes, (time_ms / MINUTE_MS).to_string()),
        _ => (ModbusOnlineText::Hours, (time_ms / HOUR_MS).to_string()),
    };
    unit.fill(language, &[("value", &value)])
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

    /// The device's I/O task runs.
    const RUNNING: bool = true;

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
    fn a_stopped_io_task_shows_its_devices_off_whatever_the_master_reports() {
        let report = communicating();
        let stopped = describe(Some(&report), true, None, false, Language::English);
        assert_eq!(stopped.light, DeviceLight::Off);
        assert_eq!(
            stopped.state,
            "Stopped: the program is not running, so no I/O data is exchanged"
        );
        assert_eq!(
            describe(
                Some(&report),
                true,
                None,
                false,
                Language::SimplifiedChinese
            )
            .state,
            "停止：程序未运行，不交换 I/O 数据"
        );
        // The master being off says so, whatever the program does.
        let off = ModbusDeviceReport {
            state: ModbusDeviceState::Off,
            ..report
        };
        let off = describe(Some(&off), true, None, false, Language::English);
        assert_eq!(off.state, "Disabled: the runtime's Modbus master is off");
    }

    fn task(name: &str, faulted: bool) -> TaskInfo {
        TaskInfo {
            name: name.to_owned(),
            cycles: 10,
            last_ns: 0,
            min_ns: 0,
            max_ns: 0,
            average_ns: 0,
            jitter_max_ns: 0,
            faulted,
        }
    }

    #[test]
    fn an_io_task_runs_while_the_program_runs_and_no_fault_stopped_it() {
        let tasks = [task("MainTask", false), task("FastTask", true)];
        let running = Some(TargetState::Running);
        assert!(io_task_runs(running, &tasks, "MainTask"));
        assert!(io_task_runs(Some(TargetState::Faulted), &tasks, "maintask"));
        // The device's own task was stopped by a fault.
        assert!(!io_task_runs(
            Some(TargetState::Faulted),
            &tasks,
            "FastTask"
        ));
        for state in [
            None,
            Some(TargetState::Stopped),
            Some(TargetState::NoProgram),
        ] {
            assert!(!io_task_runs(state, &tasks, "MainTask"), "{state:?}");
        }
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
        // The detail and the age joined with the language's own punctuation and units.
        assert_eq!(
            shown.rows[0].1,
            "响应超时 (RESPONSE_TIMEOUT)：no answer within 100 ms，1.5 秒前"
        );
        assert_eq!(shown.rows[6].0, "轮询超限次数");
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
            // The translated words alone, without the library's distinct name after them.
            let words: std::collections::HashSet<&str> = named
                .iter()
                .filter_map(|&code| error_words(code))
                .map(|words| words.get(language))
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
        assert_eq!(
            old.state,
            "This runtime version does not report the Modbus devices' states"
        );
        let refused = describe(
            None,
            false,
            Some(&ModbusReportsProblem::Refused("busy".into())),
            RUNNING,
            Language::SimplifiedChinese,
        );
        assert_eq!(refused.state, "运行时拒绝报告 Modbus 设备状态：busy");
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
    fn times_read_in_the_unit_that_fits_in_each_language() {
        let english = Language::English;
        let chinese = Language::SimplifiedChinese;
        assert_eq!(response_time_words(999, english), "999 µs");
        assert_eq!(response_time_words(12_345, english), "12.3 ms");
        assert_eq!(duration_words(350, english), "350 ms");
        assert_eq!(duration_words(4_200, english), "4.2 s");
        assert_eq!(duration_words(720_000, english), "12 min");
        assert_eq!(duration_words(5_400_000, english), "90 min");
        assert_eq!(duration_words(43_200_000, english), "12 h");
        assert_eq!(duration_words(350, chinese), "350 毫秒");
        assert_eq!(duration_words(1_500, chinese), "1.5 秒");
        assert_eq!(duration_words(720_000, chinese), "12 分钟");
        assert_eq!(duration_words(7_200_000, chinese), "2 小时");
    }

    #[test]
    fn a_device_never_answered_has_no_response_time_yet() {
        let never = ModbusDeviceReport {
            last_response_us: 0,
            ..timed_out()
        };
        let shown = describe(Some(&never), true, None, RUNNING, Language::English);
        assert_eq!(
            shown.rows[7],
            ("Last response time".into(), "None yet".into())
        );
        let shown = describe(
            Some(&never),
            true,
            None,
            RUNNING,
            Language::SimplifiedChinese,
        );
        assert_eq!(shown.rows[7].1, "尚无应答");
        assert_eq!(response_time_words(1, Language::English), "1 µs");
    }
}
