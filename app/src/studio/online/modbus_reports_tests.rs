//! The Modbus devices' question and its answers, on an [`Online`] put in each login state by
//! hand (no target is reached: these decide what is asked, kept and shown).

use std::sync::Arc;

use online::{DebugStatus, Identity, ModbusDeviceState, TargetState};
use program_image::ProgramImage;
use program_image::modbus_master::{DeviceDef, Link, MasterSection, Schedule, WordOrder};

use super::*;

/// The hash of the project's program in these tests.
const OURS: [u8; 32] = [1; 32];
/// The hash of another program on the target.
const OTHER: [u8; 32] = [2; 32];

fn device(name: &str) -> DeviceDef {
    DeviceDef {
        name: name.to_owned(),
        link: Link::Tcp {
            host: "127.0.0.1".to_owned(),
            port: 502,
        },
        unit_id: 1,
        timeout_ms: 100,
        task: 0,
        schedule: Schedule::Interval { interval_ms: 100 },
        word_order: WordOrder::HighFirst,
        max_read_gap: 0,
        status: None,
        channels: Vec::new(),
    }
}

/// A report of `name` as the runtime sends it (the caller cuts the name as the runtime does).
fn report(name: &str) -> ModbusDeviceReport {
    ModbusDeviceReport {
        name: name.to_owned(),
        state: ModbusDeviceState::Communicating,
        last_error: 0,
        last_exception: 0,
        consecutive_errors: 0,
        requests: 10,
        errors: 0,
        rounds: 5,
        overruns: 0,
        last_response_us: 300,
        since_last_error_ms: None,
        detail: String::new(),
    }
}

/// Logged in (phase Online) with a program whose image has `devices`, to a target that runs
/// the program whose hash is `on_target`.
fn logged_in(devices: &[&str], on_target: [u8; 32]) -> Online {
    let mut online = Online::new();
    let program = ProgramImage {
        modbus_master: Some(MasterSection {
            serial_ports: Vec::new(),
            devices: devices.iter().map(|name| device(name)).collect(),
        }),
        ..ProgramImage::default()
    };
    online.image = Some(super::super::BuiltImage {
        bytes: Arc::new(Vec::new()),
        hash: OURS,
        tasks: Vec::new(),
        program: Arc::new(program),
        project: Arc::new(project_model::Project::default()),
    });
    online.target_identity = Some(Identity {
        protocol: 3,
        runtime_version: "test".to_owned(),
        state: TargetState::Running,
        image_hash: Some(on_target),
        project: String::new(),
        password_required: false,
        debug: DebugStatus::default(),
    });
    online.phase = Phase::Online;
    online
}

fn reports(reports: Vec<ModbusDeviceReport>) -> ModbusDevicesAnswer {
    ModbusDevicesAnswer::Reports {
        reports,
        state: TargetState::Running,
    }
}

#[test]
fn after_a_login_without_change_nothing_of_the_other_program_is_matched_or_counted() {
    let mut online = logged_in(&["Drive"], OTHER);
    assert_eq!(online.runtime_device_count(), 0);
    // The other program's answer (its own device of the same name) is dropped.
    online.modbus_devices_answered(reports(vec![report("Drive")]));
    assert!(online.modbus_device_report("Drive").is_none());
    assert!(!online.modbus_reports_answered());
    online.modbus_devices_answered(ModbusDevicesAnswer::NotReported);
    assert_eq!(online.modbus_reports_problem(), None);
    // Reports taken in while the project's program ran are not shown once another runs.
    let mut online = logged_in(&["Drive"], OURS);
    assert_eq!(online.runtime_device_count(), 1);
    online.modbus_devices_answered(reports(vec![report("Drive")]));
    assert!(online.modbus_device_report("Drive").is_some());
    if let Some(identity) = &mut online.target_identity {
        identity.image_hash = Some(OTHER);
    }
    assert!(online.modbus_device_report("Drive").is_none());
    assert!(!online.modbus_reports_answered());
    assert_eq!(online.runtime_device_count(), 0);
}

#[test]
fn the_answer_sets_the_target_state_and_ends_the_question_in_flight() {
    let mut online = logged_in(&["Drive"], OURS);
    online.target_state = Some(TargetState::Running);
    online.modbus_reports.in_flight = true;
    online.modbus_devices_answered(ModbusDevicesAnswer::Reports {
        reports: vec![report("Drive")],
        state: TargetState::Stopped,
    });
    assert!(!online.modbus_reports.in_flight);
    assert_eq!(online.target_state(), Some(TargetState::Stopped));
    // Even a dropped answer ends the question.
    let mut other = logged_in(&["Drive"], OTHER);
    other.modbus_reports.in_flight = true;
    other.modbus_devices_answered(ModbusDevicesAnswer::NotReported);
    assert!(!other.modbus_reports.in_flight);
}

#[test]
fn a_long_or_chinese_name_finds_its_report_by_place_and_by_the_name_as_cut() {
    // 40 bytes, of which the runtime sends the first 32.
    let long = "Conveyor_Line_3_Infeed_Servo_Drive_Axis1";
    assert_eq!(long.len(), 40);
    let long_sent = "Conveyor_Line_3_Infeed_Servo_Dri";
    // Twelve characters of three bytes: ten of them fit 32 bytes.
    let chinese = "输送线三号进料伺服驱动器";
    let chinese_sent = "输送线三号进料伺服驱";
    let mut online = logged_in(&["Meter", long, chinese], OURS);
    online.modbus_devices_answered(reports(vec![
        report("Meter"),
        report(long_sent),
        report(chinese_sent),
    ]));
    assert_eq!(
        online.modbus_device_report(long).map(|r| r.name.as_str()),
        Some(long_sent)
    );
    assert_eq!(
        online
            .modbus_device_report(chinese)
            .map(|r| r.name.as_str()),
        Some(chinese_sent)
    );
    // Names are found as the project finds them, without case.
    assert_eq!(
        online
            .modbus_device_report("METER")
            .map(|r| r.name.as_str()),
        Some("Meter")
    );
    // A report at the place of another name (the target's list is not the image's) is not
    // taken for the device.
    online.modbus_devices_answered(reports(vec![report("Scale"), report(long_sent)]));
    assert!(online.modbus_device_report("Meter").is_none());
    assert!(online.modbus_device_report(chinese).is_none());
}

/// Every condition met: the question is due.
fn due() -> ModbusQuestion {
    ModbusQuestion {
        online: true,
        runs_project: true,
        has_runtime_devices: true,
        in_flight: false,
        not_reported: false,
        interval_passed: true,
    }
}

#[test]
fn the_question_is_due_only_when_every_condition_holds() {
    assert!(due().is_due());
    let not_due = [
        ModbusQuestion {
            online: false,
            ..due()
        },
        ModbusQuestion {
            runs_project: false,
            ..due()
        },
        ModbusQuestion {
            has_runtime_devices: false,
            ..due()
        },
        ModbusQuestion {
            in_flight: true,
            ..due()
        },
        ModbusQuestion {
            not_reported: true,
            ..due()
        },
        ModbusQuestion {
            interval_passed: false,
            ..due()
        },
    ];
    for question in not_due {
        assert!(!question.is_due(), "{question:?}");
    }
}

#[test]
fn an_older_runtime_is_not_asked_again_before_the_next_login() {
    let mut online = logged_in(&["Drive"], OURS);
    online.modbus_devices_answered(ModbusDevicesAnswer::NotReported);
    let later = Instant::now() + Duration::from_secs(5);
    online.modbus_reports.last_asked = Some(Instant::now());
    online.ask_modbus_devices_when_due(later);
    // Not asked: the last question's time did not move.
    assert!(
        online
            .modbus_reports
            .last_asked
            .is_some_and(|asked| asked < later)
    );
    online.forget_modbus_reports();
    online.ask_modbus_devices_when_due(later);
    assert_eq!(online.modbus_reports.last_asked, Some(later));
    // Without a session the question cannot be sent, and no message says so.
    assert!(!online.modbus_reports.in_flight);
    assert!(online.take_messages().is_empty());
}
