//! The online display of the devices the simulator's Modbus master polls
//! (`docs/modbus-master.md` §9.2, §6.11): the device tree's icon and tooltip, the device
//! editor's Online part and the status line, from the simulator's own `MODBUS_DEVICES` reports.

use std::sync::{Arc, Mutex};

use app::studio::{StudioApp, TreeNode};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use online::{ModbusDeviceState, TargetState};
use runtime::areas::LocatedAreas;

use crate::support::{example_copy, login_with_download, replace_in, studio, wait_until};

/// A port on loopback that nobody listens on: bound, then let go.
fn closed_port() -> u16 {
    let listener = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    listener.local_addr().unwrap().port()
}

/// Whether the runtime reports `device` in `state`.
fn reported(app: &StudioApp, device: &str, state: ModbusDeviceState) -> bool {
    app.online()
        .modbus_device_report(device)
        .is_some_and(|report| report.state == state)
}

/// Steps the studio until a widget labelled with `text` shows (a tooltip waits for the pointer
/// to rest), failing after a few seconds of frames.
#[track_caller]
fn step_until_shown(harness: &mut Harness<'_, StudioApp>, text: &str) {
    for _ in 0..200 {
        if harness.query_by_label_contains(text).is_some() {
            return;
        }
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    panic!(
        "nothing labelled '{text}' showed; rounds shown: {}; {:?}",
        harness.query_by_label("Rounds").is_some(),
        harness.state().online().modbus_device_report("Meter")
    );
}

#[test]
fn runtime_devices_show_their_state_in_the_tree_the_editor_and_the_status_line() {
    let drive = crate::devices::drive(Arc::new(Mutex::new(LocatedAreas::new(16, 64, 8192))));
    let nobody = closed_port();
    // The example's belt drive on the loopback server, mastered by the runtime in MainTask, a
    // meter at a port nobody listens on, and a scale the studio would poll itself (no task).
    let project = example_copy(|dir| {
        replace_in(
            dir,
            "rivet.toml",
            "host = \"192.168.1.50\"\nport = 502",
            &format!("host = \"127.0.0.1\"\nport = {drive}"),
        );
        replace_in(
            dir,
            "rivet.toml",
            "timeout_ms = 500\n",
            "timeout_ms = 500\ntask = \"MainTask\"\n",
        );
        let manifest = dir.join("rivet.toml");
        let mut text = std::fs::read_to_string(&manifest).unwrap();
        text.push_str(&format!(
            "\n[[modbus_device]]\nname = \"Meter\"\nhost = \"127.0.0.1\"\nport = {nobody}\n\
             unit_id = 1\nword_order = \"high_first\"\npoll_interval_ms = 100\n\
             timeout_ms = 100\ntask = \"MainTask\"\n\n[[modbus_device.binding]]\n\
             variable = \"GVL_Machine.xAcknowledge\"\ntable = \"discrete_input\"\naddress = 0\n\
             data_type = \"bool\"\n\n[[modbus_device]]\nname = \"Scale\"\nhost = \"127.0.0.1\"\n\
             port = {nobody}\nunit_id = 1\nword_order = \"high_first\"\npoll_interval_ms = 100\n\
             timeout_ms = 100\n"
        ));
        std::fs::write(&manifest, text).unwrap();
    });
    let mut harness = studio(project.path());
    harness.key_press(Key::F11);
    wait_until(&mut harness, "the build", |app| app.last_build().is_some());
    let build = harness.state().last_build().unwrap();
    assert_eq!(build.counts().0, 0, "{:?}", build.messages);

    // Offline, a runtime device's node shows nothing new.
    assert!(harness.query_by_label_contains("BeltDrive: ").is_none());

    // Logged in with the program stopped, nothing is copied: both devices are off.
    login_with_download(&mut harness);
    assert_eq!(
        harness.state().online().target_state(),
        Some(TargetState::Stopped)
    );
    wait_until(&mut harness, "the first reports", |app| {
        app.online().modbus_device_report("Meter").is_some()
    });
    harness.step();
    assert!(
        harness
            .query_by_label(
                "BeltDrive: Stopped: the program is not running, so no I/O data is exchanged"
            )
            .is_some()
    );
    assert!(
        harness
            .query_by_label("Simulator: polling 2 Modbus devices")
            .is_some()
    );

    // Running, the drive communicates and the meter does not answer.
    harness.key_press(Key::F5);
    // The node shows the report together with the program's state, which the studio learns
    // with the next answer after the start: both must have arrived.
    wait_until(&mut harness, "the drive communicating", |app| {
        reported(app, "BeltDrive", ModbusDeviceState::Communicating)
            && reported(app, "Meter", ModbusDeviceState::NotAnswering)
            && app.online().target_state() == Some(TargetState::Running)
    });
    step_until_shown(&mut harness, "BeltDrive: Communicating");
    // A studio device shows nothing new.
    assert!(harness.query_by_label_contains("Scale: ").is_none());

    // The meter's tooltip gives its last error in words and its counters.
    harness.get_by_label("Meter: Not answering").scroll_to_me();
    harness.step();
    harness.step();
    // The pointer rests on the icon; it is placed again once the tree stopped scrolling.
    for _ in 0..3 {
        harness.get_by_label("Meter: Not answering").hover();
        harness.step();
    }
    step_until_shown(
        &mut harness,
        "No TCP connection to the device (TCP_COMMUNICATION_ERROR)",
    );
    assert!(harness.query_by_label("Consecutive errors").is_some());
    assert!(harness.query_by_label("Last response time").is_some());
    // The meter never answered: no response time yet, rather than 0 µs.
    assert!(harness.query_by_label("None yet").is_some());
    assert!(harness.query_by_label("0 µs").is_none());

    // The drive's editor has the read-only Online part with its state and counters.
    harness
        .state_mut()
        .open(TreeNode::ModbusDevice("BeltDrive".into()));
    harness.step();
    harness.step();
    // Its heading beside the Online menu's.
    assert_eq!(harness.query_all_by_label("Online").count(), 2);
    assert!(harness.query_by_label("State").is_some());
    assert!(harness.query_by_label("Communicating").is_some());
    assert!(
        harness
            .query_by_label("No error (RESPONSE_SUCCESS)")
            .is_some()
    );
    // The counters, also in the meter's tooltip still open under the pointer.
    assert_eq!(harness.query_all_by_label("Rounds").count(), 2);

    // Logged out, the icons, the Online part and the status line are gone.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F8);
    wait_until(&mut harness, "the logout", |app| {
        !app.online().is_logged_in()
    });
    harness.step();
    assert!(harness.query_by_label_contains("BeltDrive: ").is_none());
    assert!(harness.query_by_label("Communicating").is_none());
    assert!(
        harness
            .query_by_label_contains("Simulator: polling")
            .is_none()
    );
}
