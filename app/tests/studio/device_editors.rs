//! The device editors in the studio: each node's settings edited in place, bad values refused
//! with their reason and the project unchanged, and every change one undo step.

use app::studio::{Language, Settings, StudioApp, TreeNode};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{Dialect, ModbusDataType, ModbusTable, Project};

use crate::support::{example_copy, studio};

fn project<'h>(harness: &'h Harness<'_, StudioApp>) -> &'h Project {
    &harness.state().session().unwrap().project
}

fn undo_label(harness: &Harness<'_, StudioApp>) -> Option<String> {
    let session = harness.state().session().unwrap();
    session.history.undo_label().map(str::to_owned)
}

/// Opens the document of `node` as a double-click in the device tree does.
fn open(harness: &mut Harness<'_, StudioApp>, node: TreeNode) {
    harness.state_mut().open(node);
    harness.run();
}

/// Types `text` into the text field labelled `label` over its old text and presses Enter,
/// scrolling the field into view first as a user would (a channel table is wide).
fn enter_text(harness: &mut Harness<'_, StudioApp>, label: &str, text: &str) {
    let role = egui::accesskit::Role::TextInput;
    harness.get_by_role_and_label(role, label).scroll_to_me();
    harness.run();
    harness.get_by_role_and_label(role, label).click();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.key_press(Key::Backspace);
    harness.get_by_role_and_label(role, label).type_text(text);
    harness.run();
    harness.key_press(Key::Enter);
    harness.run();
}

/// Undoes the last change with Ctrl+Z, with the focus out of any field.
fn undo(harness: &mut Harness<'_, StudioApp>) {
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
}

/// The studio on `project` with its interface in Simplified Chinese.
fn chinese_studio(project: &std::path::Path) -> Harness<'static, StudioApp> {
    let settings = Settings {
        language: Language::SimplifiedChinese,
        ..Settings::default()
    };
    let app = StudioApp::new(settings, Some(project.to_owned()));
    Harness::builder()
        .with_size([1400.0, 900.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app)
}

#[track_caller]
fn assert_refused(harness: &Harness<'_, StudioApp>, reason: &str) {
    assert!(
        harness.query_by_label_contains(reason).is_some(),
        "no refusal saying '{reason}'"
    );
}

#[test]
fn the_controller_editor_sets_the_port_refuses_port_0_and_undoes() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::Controller);
    assert!(harness.query_by_label_contains("Password of").is_none());

    enter_text(&mut harness, "Port of PLC", "5021");
    assert_eq!(project(&harness).controller.port, 5021);
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set port of PLC to 5021")
    );

    enter_text(&mut harness, "Port of PLC", "0");
    assert_refused(&harness, "port 0 cannot be used");
    assert_eq!(project(&harness).controller.port, 5021);
    enter_text(&mut harness, "Host of PLC", "");
    assert_refused(&harness, "the host is empty");
    assert_eq!(project(&harness).controller.host, "127.0.0.1");

    harness.key_press(Key::Escape);
    undo(&mut harness);
    assert_eq!(project(&harness).controller.port, 5020);

    // The Modbus map override: on, one range added, a range past 65535 refused.
    harness.get_by_label("Own Modbus map of PLC").click();
    harness.run();
    assert!(project(&harness).controller.modbus_map.is_some());
    harness.get_by_label("Add range").click();
    harness.run();
    let map = project(&harness).controller.modbus_map.clone().unwrap();
    assert_eq!(map.ranges.len(), 1);
    enter_text(&mut harness, "Start of row 1", "65535");
    enter_text(&mut harness, "Count of row 1", "2");
    assert_refused(&harness, "passes address 65535");
    assert_eq!(
        project(&harness)
            .controller
            .modbus_map
            .as_ref()
            .unwrap()
            .ranges[0]
            .count,
        1
    );
}

/// Builds the project as F11 does and returns the codes of the build's findings.
fn build_codes(harness: &mut Harness<'_, StudioApp>) -> Vec<String> {
    let revision = harness.state().session().unwrap().history.revision();
    harness.state_mut().build();
    crate::support::wait_until(harness, "the build", |app| {
        !app.is_building() && app.last_build().is_some_and(|b| b.revision == revision)
    });
    let outcome = harness.state().last_build().unwrap();
    outcome.messages.iter().map(|m| m.code.clone()).collect()
}

#[test]
fn the_dialect_is_chosen_beside_the_controller_rebuilds_by_its_rules_saves_and_undoes() {
    // A REAL stored into an INT: a warning in CODESYS, an error in IEC 61131-3.
    let dir = example_copy(|path| {
        let main = path.join("application/Main.st");
        let mut text = std::fs::read_to_string(&main).unwrap();
        text.push_str("\nGVL_IO.iBeltSpeedSetpoint := GVL_Machine.stRecipe.rBeltSpeed;\n");
        std::fs::write(&main, text).unwrap();
    });
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::Controller);
    let codes = build_codes(&mut harness);
    assert!(codes.contains(&"W0014".to_owned()), "{codes:?}");
    assert!(!codes.iter().any(|c| c.starts_with('E')), "{codes:?}");

    harness.get_by_label("Language rules of PLC").click();
    harness.run();
    harness.get_by_label("IEC 61131-3 only").click();
    harness.run();
    assert_eq!(project(&harness).dialect, Dialect::IecStrict);
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set language rules of PLC to IEC 61131-3 only")
    );
    let codes = build_codes(&mut harness);
    assert!(codes.contains(&"E0104".to_owned()), "{codes:?}");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::S);
    harness.step();
    harness.step();
    let saved = project_model::load_project(dir.path()).unwrap().project;
    assert_eq!(saved.dialect, Dialect::IecStrict);

    undo(&mut harness);
    assert_eq!(project(&harness).dialect, Dialect::Codesys);
    let codes = build_codes(&mut harness);
    assert!(!codes.iter().any(|c| c.starts_with('E')), "{codes:?}");
}

#[test]
fn the_io_area_editor_moves_an_area_refuses_an_overlap_naming_the_other_and_undoes() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::IoArea("AO_2".into()));

    enter_text(&mut harness, "Start byte of AO_2", "1");
    assert_refused(&harness, "byte %QB1 overlaps the I/O area 'DO_16'");
    let area = |harness: &Harness<'_, StudioApp>| project(harness).io_areas[2].clone();
    assert_eq!(area(&harness).start_byte, 2);

    enter_text(&mut harness, "Start byte of AO_2", "8");
    assert_eq!(area(&harness).start_byte, 8);
    enter_text(&mut harness, "Size of AO_2", "0");
    assert_refused(&harness, "at least 1 byte");
    assert_eq!(area(&harness).size_bytes, 4);

    harness.key_press(Key::Escape);
    undo(&mut harness);
    assert_eq!(area(&harness).start_byte, 2);
}

#[test]
fn the_modbus_device_editor_edits_settings_and_channels_and_refuses_what_does_not_fit() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();

    enter_text(&mut harness, "Poll interval of BeltDrive", "250");
    assert_eq!(drive(&harness).poll_interval_ms, Some(250));
    enter_text(&mut harness, "Timeout of BeltDrive", "0");
    assert_refused(&harness, "the timeout is at least 1 ms");
    enter_text(&mut harness, "Unit id of BeltDrive", "300");
    assert_refused(&harness, "'300' is not a whole number from 0 to 255");
    assert_eq!(drive(&harness).timeout_ms, 500);
    assert_eq!(drive(&harness).unit_id, 1);

    // A channel's variable must exist and have the channel's type.
    enter_text(&mut harness, "Variable of row 1", "GVL_Machine.rMissing");
    assert_refused(&harness, "there is no variable 'GVL_Machine.rMissing'");
    enter_text(
        &mut harness,
        "Variable of row 1",
        "GVL_Machine.iPackagesInBatch",
    );
    assert_refused(&harness, "is declared as INT, but the channel reads REAL");
    assert_eq!(
        drive(&harness).bindings[0].variable,
        "GVL_Machine.rBeltSpeedActual"
    );

    // A channel added by naming its variable gets its type and a free address.
    harness.key_press(Key::Escape);
    enter_text(
        &mut harness,
        "Add channel for variable",
        "GVL_Machine.udiTotalPackages",
    );
    let added = drive(&harness).bindings[2].clone();
    assert_eq!(added.variable, "GVL_Machine.udiTotalPackages");
    assert_eq!(added.table, ModbusTable::HoldingRegister);
    assert_eq!(added.data_type, ModbusDataType::Uint32);
    enter_text(&mut harness, "Address of row 3", "4");
    assert_eq!(drive(&harness).bindings[2].address, 4);
    enter_text(&mut harness, "Address of row 1", "1");
    assert!(harness.query_by_label_contains("overlaps").is_none());

    harness.get_by_label("Delete of row 2").click();
    harness.run();
    assert_eq!(drive(&harness).bindings.len(), 2);
    undo(&mut harness);
    assert_eq!(drive(&harness).bindings.len(), 3);
    undo(&mut harness);
    undo(&mut harness);
    undo(&mut harness);
    undo(&mut harness);
    assert_eq!(drive(&harness).bindings.len(), 2);
    assert_eq!(drive(&harness).poll_interval_ms, Some(100));
}

/// Opens the combo box labelled `combo` and chooses `option`, the last widget so labelled (the
/// popup is drawn after the tree, which may show the same name).
fn choose(harness: &mut Harness<'_, StudioApp>, combo: &str, option: &str) {
    harness.get_by_label(combo).scroll_to_me();
    harness.run();
    harness.get_by_label(combo).click();
    harness.run();
    let chosen = harness.get_all_by_label(option).last().unwrap();
    chosen.click();
    harness.run();
}

#[test]
fn the_master_settings_show_once_a_task_is_chosen_with_the_requests_of_a_round() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();
    assert!(harness.query_by_label("Schedule of BeltDrive").is_none());
    assert!(harness.query_by_label("Direction of row 1").is_none());

    choose(&mut harness, "I/O task of BeltDrive", "MainTask");
    assert_eq!(drive(&harness).task.as_deref(), Some("MainTask"));
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set I/O task of BeltDrive to MainTask")
    );
    assert!(harness.query_by_label("Schedule of BeltDrive").is_some());
    assert!(
        harness
            .query_by_label("Status variable of BeltDrive")
            .is_some()
    );
    assert!(harness.query_by_label("Error flag of row 2").is_some());
    // An input register and a discrete input: two tables, two requests.
    assert!(harness.query_by_label("2 requests per round").is_some());

    choose(
        &mut harness,
        "Schedule of BeltDrive",
        "Every cycle of the task",
    );
    assert_eq!(
        drive(&harness).schedule,
        project_model::ModbusSchedule::EveryCycle
    );
    enter_text(
        &mut harness,
        "Error flag of row 1",
        "GVL_Machine.xDriveReady",
    );
    assert_eq!(
        drive(&harness).bindings[0].error_flag.as_deref(),
        Some("GVL_Machine.xDriveReady")
    );
    enter_text(
        &mut harness,
        "Trigger variable of row 1",
        "GVL_Machine.xDriveReady",
    );
    assert_eq!(
        drive(&harness).bindings[0].trigger,
        project_model::ChannelTrigger::RisingEdge
    );

    // The poll interval is kept by every other edit, and emptied only where it may be.
    enter_text(&mut harness, "Poll interval of BeltDrive", "");
    assert_refused(&harness, "the poll interval is missing");
    assert_eq!(drive(&harness).poll_interval_ms, Some(100));
    harness.key_press(Key::Escape);
    undo(&mut harness);
    undo(&mut harness);
    undo(&mut harness);
    undo(&mut harness);
    assert_eq!(drive(&harness).task, None);
    assert!(harness.query_by_label("Schedule of BeltDrive").is_none());
}

#[test]
fn a_refused_master_setting_shows_its_reason_and_changes_nothing() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();
    let before = drive(&harness);

    // RTU in a project without serial ports.
    choose(
        &mut harness,
        "Link of BeltDrive",
        "Modbus RTU (serial port)",
    );
    assert_refused(&harness, "add a serial port under the controller first");
    assert_eq!(drive(&harness), before);

    // An input register cannot be written.
    choose(&mut harness, "I/O task of BeltDrive", "MainTask");
    choose(&mut harness, "Direction of row 1", "Write");
    assert_refused(&harness, "which is read-only");
    assert_eq!(drive(&harness).bindings, before.bindings);
    enter_text(
        &mut harness,
        "Error flag of row 2",
        "GVL_Machine.rBeltSpeedActual",
    );
    assert_refused(&harness, "declare it as BOOL");
    assert_eq!(drive(&harness).bindings, before.bindings);
}

/// The example with an array of two REALs in `GVL_Machine`, for a channel of two values.
fn example_with_speed_array() -> tempfile::TempDir {
    example_copy(|dir| {
        let gvl = dir.join("application/GVL_Machine.gvl.toml");
        let mut text = std::fs::read_to_string(&gvl).unwrap();
        text.push_str(
            "\n[[variable]]\nname = \"arSpeeds\"\nsection = \"VAR_GLOBAL\"\ntype = \"ARRAY[0..1] OF REAL\"\n",
        );
        std::fs::write(&gvl, text).unwrap();
    })
}

#[test]
fn a_runtime_channel_s_variable_is_checked_with_its_count_while_editing() {
    let dir = example_with_speed_array();
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();
    choose(&mut harness, "I/O task of BeltDrive", "MainTask");

    // The array does not fit a channel of one value: refused beside the field.
    enter_text(&mut harness, "Variable of row 1", "GVL_Machine.arSpeeds");
    assert_refused(
        &harness,
        "'GVL_Machine.arSpeeds': the channel reads one real value, but the variable is declared as ARRAY[0..1] OF REAL: declare it as REAL",
    );
    assert_eq!(
        drive(&harness).bindings[0].variable,
        "GVL_Machine.rBeltSpeedActual"
    );
    harness.key_press(Key::Escape);
    harness.run();

    // A count the variable does not fit is taken, and the row says what to declare.
    enter_text(&mut harness, "Count of row 1", "2");
    assert_eq!(drive(&harness).bindings[0].count, 2);
    assert_refused(
        &harness,
        "the channel reads 2 real values, but the variable is declared as REAL: declare it as ARRAY[0..1] OF REAL",
    );
    enter_text(&mut harness, "Variable of row 1", "GVL_Machine.arSpeeds");
    assert_eq!(drive(&harness).bindings[0].variable, "GVL_Machine.arSpeeds");
    assert!(
        harness
            .query_by_label_contains("the channel reads 2 real values")
            .is_none()
    );
}

#[test]
fn a_channel_s_misfit_is_said_in_chinese_when_chosen() {
    let dir = example_with_speed_array();
    let mut harness = chinese_studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    choose(&mut harness, "BeltDrive 的I/O 任务", "MainTask");
    enter_text(&mut harness, "第 1 行的变量", "GVL_Machine.arSpeeds");
    assert_refused(
        &harness,
        "'GVL_Machine.arSpeeds'：通道读取 1 个 real 值，但变量声明为 ARRAY[0..1] OF REAL：请将其声明为 REAL",
    );
    assert!(
        harness
            .query_by_label_contains("the channel reads")
            .is_none()
    );
}

#[test]
fn a_rising_edge_waits_for_its_trigger_variable_which_then_sets_both_in_one_step() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();
    choose(&mut harness, "I/O task of BeltDrive", "MainTask");
    let hint = "Name the BOOL variable whose rising edge sends the channel";
    assert!(harness.query_by_label_contains(hint).is_none());

    // The choice is shown and waits: nothing is refused and the model is unchanged.
    choose(&mut harness, "Trigger of row 1", "Rising edge");
    assert!(harness.query_by_label_contains(hint).is_some());
    assert!(
        harness
            .query_by_label_contains("has no trigger variable")
            .is_none()
    );
    assert_eq!(
        drive(&harness).bindings[0].trigger,
        project_model::ChannelTrigger::Cyclic
    );

    // A variable that is no BOOL is refused and the choice keeps waiting.
    enter_text(
        &mut harness,
        "Trigger variable of row 1",
        "GVL_Machine.rBeltSpeedActual",
    );
    assert_refused(&harness, "declare it as BOOL");
    assert!(harness.query_by_label_contains(hint).is_some());
    harness.key_press(Key::Escape);
    harness.run();

    enter_text(
        &mut harness,
        "Trigger variable of row 1",
        "GVL_Machine.xDriveReady",
    );
    let channel = drive(&harness).bindings[0].clone();
    assert_eq!(channel.trigger, project_model::ChannelTrigger::RisingEdge);
    assert_eq!(
        channel.trigger_variable.as_deref(),
        Some("GVL_Machine.xDriveReady")
    );
    assert!(harness.query_by_label_contains(hint).is_none());
    undo(&mut harness);
    let channel = drive(&harness).bindings[0].clone();
    assert_eq!(channel.trigger, project_model::ChannelTrigger::Cyclic);
    assert_eq!(channel.trigger_variable, None);
}

#[test]
fn the_waiting_rising_edge_asks_for_its_variable_in_chinese() {
    let dir = example_copy(|_| {});
    let mut harness = chinese_studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    choose(&mut harness, "BeltDrive 的I/O 任务", "MainTask");
    choose(&mut harness, "第 1 行的触发", "上升沿");
    assert!(
        harness
            .query_by_label_contains("请填写 BOOL 触发变量：其上升沿时发送本通道")
            .is_some()
    );
    assert!(harness.query_by_label_contains("Name the BOOL").is_none());
}

#[test]
fn a_serial_port_added_in_the_tree_is_edited_and_an_rtu_device_put_on_it() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    harness.get_by_label("Serial ports").click_secondary();
    harness.run();
    harness.get_by_label("Add serial port").click();
    harness.run();
    let ports = |harness: &Harness<'_, StudioApp>| project(harness).serial_ports.clone();
    assert_eq!(ports(&harness).len(), 1);
    let name = ports(&harness)[0].name.clone();
    // Selected in the tree, the port's settings show in the Properties pane as the manifest
    // names them, like the other device nodes'.
    harness.get_by_label(&format!("{name} *")).click();
    harness.run();
    assert_eq!(
        harness.state().selection(),
        Some(&TreeNode::SerialPort(name.clone()))
    );
    assert!(harness.query_by_label("baud_rate").is_some());
    assert!(harness.query_by_label("stop_bits").is_some());
    assert!(
        harness
            .query_by_label_contains("0 = 3.5 characters (2006 µs)")
            .is_some()
    );

    choose(&mut harness, &format!("Baud rate of {name}"), "9600");
    assert_eq!(ports(&harness)[0].baud_rate, 9600);
    assert_eq!(
        undo_label(&harness),
        Some(format!("Set baud rate of {name} to 9600"))
    );
    assert!(
        harness
            .query_by_label_contains("0 = 3.5 characters (4011 µs)")
            .is_some()
    );
    enter_text(&mut harness, &format!("Device file of {name}"), "");
    assert_refused(&harness, "the device file is empty");
    assert_eq!(ports(&harness)[0].device, "/dev/ttyUSB0");
    harness.key_press(Key::Escape);
    undo(&mut harness);
    assert_eq!(ports(&harness)[0].baud_rate, 19200);

    // A device with a task moves onto the port, and follows the port's new name.
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    choose(&mut harness, "I/O task of BeltDrive", "MainTask");
    choose(
        &mut harness,
        "Link of BeltDrive",
        "Modbus RTU (serial port)",
    );
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();
    assert_eq!(drive(&harness).serial_port(), Some(name.as_str()));
    assert!(harness.query_by_label("Serial port of BeltDrive").is_some());
    assert!(harness.query_by_label("Host of BeltDrive").is_none());
    // Polled every cycle, the RTU device may have no poll interval, and the undo label says so.
    choose(
        &mut harness,
        "Schedule of BeltDrive",
        "Every cycle of the task",
    );
    enter_text(&mut harness, "Poll interval of BeltDrive", "");
    assert_eq!(drive(&harness).poll_interval_ms, None);
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set poll interval of BeltDrive to none")
    );
    // The port's row is marked as changed since the last save.
    let row = format!("{name} *");
    harness.get_by_label(&row).scroll_to_me();
    harness.run();
    harness.get_by_label(&row).click_secondary();
    harness.run();
    harness.get_by_label("Rename").click();
    harness.run();
    harness.get_by_label("Name").click();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.get_by_label("Name").type_text("RS485");
    harness.run();
    harness.get_by_label("OK").click();
    harness.run();
    assert_eq!(ports(&harness)[0].name, "RS485");
    assert_eq!(drive(&harness).serial_port(), Some("RS485"));
    undo(&mut harness);
    assert_eq!(ports(&harness)[0].name, name);
    assert_eq!(drive(&harness).serial_port(), Some(name.as_str()));

    // Back on TCP (which needs a poll interval), the device has the host and port it had
    // before it went onto the port.
    enter_text(&mut harness, "Poll interval of BeltDrive", "100");
    choose(&mut harness, "Link of BeltDrive", "Modbus TCP");
    assert_eq!(
        drive(&harness).link,
        project_model::ModbusLink::Tcp {
            host: "192.168.1.50".into(),
            port: 502
        }
    );
}

#[test]
fn the_axis_editor_sets_limits_with_units_refuses_a_period_of_0_and_undoes() {
    let dir = example_copy(|_| {});
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::Axis("Knife".into()));
    assert!(harness.query_by_label("deg/s³").is_some());
    let knife = |harness: &Harness<'_, StudioApp>| project(harness).axes[1].clone();

    enter_text(&mut harness, "Velocity of Knife", "2000");
    assert_eq!(knife(&harness).limits.velocity, 2000.0);
    assert_eq!(
        undo_label(&harness).as_deref(),
        Some("Set velocity of Knife to 2000")
    );
    enter_text(&mut harness, "Modulo period of Knife", "0");
    assert_refused(
        &harness,
        "the modulo period is 0; it must be greater than 0",
    );
    enter_text(&mut harness, "Jerk of Knife", "fast");
    assert_refused(&harness, "'fast' is not a number");
    assert_eq!(knife(&harness).modulo_period, Some(360.0));

    // Software limits with the minimum above the maximum are refused when switched on.
    enter_text(&mut harness, "Negative limit of Knife", "10");
    harness.key_press(Key::Escape);
    harness.get_by_label("Software limits of Knife").click();
    harness.run();
    assert_refused(&harness, "must be below the positive limit");
    assert!(!knife(&harness).software_limits.enabled);

    undo(&mut harness);
    undo(&mut harness);
    assert_eq!(knife(&harness).limits.velocity, 1440.0);
    assert_eq!(knife(&harness).software_limits.min, 0.0);
}

#[test]
fn the_device_editors_speak_chinese_when_chosen() {
    let dir = example_copy(|_| {});
    let mut harness = chinese_studio(dir.path());
    open(&mut harness, TreeNode::Axis("Knife".into()));
    assert!(harness.query_by_label("Knife 的速度").is_some());
    assert!(harness.query_by_label("Velocity of Knife").is_none());
    enter_text(&mut harness, "Knife 的加加速度", "快");
    assert_refused(&harness, "'快' 不是数字");
    assert_eq!(project(&harness).axes[1].limits.jerk, 144_000.0);
}

#[test]
fn a_value_refused_in_chinese_gives_its_reason_in_chinese() {
    let dir = example_copy(|_| {});
    let mut harness = chinese_studio(dir.path());
    open(&mut harness, TreeNode::Controller);
    let port = project(&harness).controller.port;
    enter_text(&mut harness, "PLC 的端口", "0");
    assert_refused(&harness, "不能使用端口 0：请输入 1 到 65535 之间的端口");
    assert!(
        harness
            .query_by_label_contains("port 0 cannot be used")
            .is_none()
    );
    assert_eq!(project(&harness).controller.port, port);

    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    let variable = project(&harness).modbus_devices[0].bindings[0]
        .variable
        .clone();
    enter_text(&mut harness, "第 1 行的变量", "GVL_Machine.rMissing");
    assert_refused(&harness, "没有变量 'GVL_Machine.rMissing'");
    assert!(
        harness
            .query_by_label_contains("there is no variable")
            .is_none()
    );
    assert_eq!(
        project(&harness).modbus_devices[0].bindings[0].variable,
        variable
    );
}

/// The example with two serial ports and BeltDrive polled in the main task on the second.
fn example_with_two_ports() -> tempfile::TempDir {
    example_copy(|dir| {
        let manifest = dir.join("rivet.toml");
        let text = std::fs::read_to_string(&manifest).unwrap();
        let ports = "[[serial_port]]\nname = \"Line1\"\ndevice = \"/dev/ttyS0\"\n\
                     baud_rate = 19200\nparity = \"even\"\ndata_bits = 8\nstop_bits = 1\n\
                     inter_frame_delay_us = 0\n\n[[serial_port]]\nname = \"Line2\"\n\
                     device = \"/dev/ttyUSB0\"\nbaud_rate = 19200\nparity = \"even\"\n\
                     data_bits = 8\nstop_bits = 1\ninter_frame_delay_us = 0\n\n";
        let text = text
            .replacen(
                "[[modbus_device]]\n",
                &format!("{ports}[[modbus_device]]\n"),
                1,
            )
            .replacen(
                "host = \"192.168.1.50\"\nport = 502\n",
                "serial_port = \"Line2\"\ntask = \"MainTask\"\n",
                1,
            );
        std::fs::write(&manifest, text).unwrap();
    })
}

/// Renames the tree row `row` to `name` through its context menu's Rename dialog.
fn rename_in_tree(harness: &mut Harness<'_, StudioApp>, row: &str, name: &str) {
    crate::tree::menu(harness, row, "Rename");
    crate::tree::set_text(harness, "Name", name);
    harness.get_by_label("OK").click();
    harness.run();
}

#[test]
fn a_port_renamed_while_its_device_is_on_tcp_is_the_one_the_device_returns_to() {
    let dir = example_with_two_ports();
    let mut harness = studio(dir.path());
    let drive = |harness: &Harness<'_, StudioApp>| project(harness).modbus_devices[0].clone();
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    assert_eq!(drive(&harness).serial_port(), Some("Line2"));
    choose(&mut harness, "Link of BeltDrive", "Modbus TCP");
    assert_eq!(drive(&harness).serial_port(), None);

    rename_in_tree(&mut harness, "Line2", "Bus2");
    assert_eq!(project(&harness).serial_ports[1].name, "Bus2");
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    choose(
        &mut harness,
        "Link of BeltDrive",
        "Modbus RTU (serial port)",
    );
    // Not the first port, which stands in only for a port that is gone.
    assert_eq!(drive(&harness).serial_port(), Some("Bus2"));
}

#[test]
fn a_new_device_reusing_a_deleted_device_s_name_remembers_nothing_of_it() {
    let dir = example_with_two_ports();
    let mut harness = studio(dir.path());
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    assert_eq!(
        project(&harness).modbus_devices[0].serial_port(),
        Some("Line2")
    );
    // On TCP, the editor remembers the port it was on; the row is marked as changed.
    choose(&mut harness, "Link of BeltDrive", "Modbus TCP");
    crate::tree::menu(&mut harness, "BeltDrive *", "Delete");
    assert!(project(&harness).modbus_devices.is_empty());

    crate::tree::menu(&mut harness, "Modbus devices *", "Add Modbus device");
    let added = project(&harness).modbus_devices[0].name.clone();
    rename_in_tree(&mut harness, &format!("{added} *"), "BeltDrive");
    open(&mut harness, TreeNode::ModbusDevice("BeltDrive".into()));
    choose(&mut harness, "I/O task of BeltDrive", "MainTask");
    choose(
        &mut harness,
        "Link of BeltDrive",
        "Modbus RTU (serial port)",
    );
    // The deleted device's port is not remembered for the new one: it takes the first port.
    assert_eq!(
        project(&harness).modbus_devices[0].serial_port(),
        Some("Line1")
    );
}
