use super::super::layout::object_toml;
use crate::{Object, Pou};

/// The canonical text of the POU read from `text`, checked to read back equal.
#[track_caller]
fn canonical(text: &str) -> String {
    let pou: Pou = toml::from_str(text).unwrap();
    let saved = object_toml(&Object::Pou(pou.clone())).unwrap();
    let again: Pou = toml::from_str(&saved).unwrap();
    assert_eq!(again, pou, "{saved}");
    saved
}

#[test]
fn an_ld_network_is_saved_as_an_indented_tree_one_element_a_line() {
    // The same body written compactly, one network a line.
    let compact = r#"kind = "program"
body = { language = "ld", network = [{ title = "Start", label = "Start", rung = [{ type = "operand", id = 1, text = "start" }, { type = "parallel", id = 2, branch = [{ rung = [{ type = "operand", id = 3, text = "b" }] }, { rung = [{ type = "operand", id = 4, text = "c", negated = true }] }] }, { type = "block", id = 5, type_name = "TON", instance = "t", input = [{ pin = "IN" }, { pin = "PT", source = [{ type = "operand", id = 6, text = "T#1s" }] }], output = [{ pin = "Q" }, { pin = "ET", assign = "elapsed" }] }], output = [{ type = "coil", id = 7, variable = "q", kind = "set" }, { type = "branch", id = 8, rung = [{ type = "operand", id = 9, text = "e" }], output = [{ type = "return", id = 10 }] }] }, { label = "Done" }] }
"#;
    let expected = r#"kind = "program"

[body]
language = "ld"

[[body.network]]
title = "Start"
label = "Start"
rung = [
    { type = "operand", id = 1, text = "start" },
    { type = "parallel", id = 2, branch = [
        { rung = [{ type = "operand", id = 3, text = "b" }] },
        { rung = [{ type = "operand", id = 4, text = "c", negated = true }] },
    ] },
    { type = "block", id = 5, type_name = "TON", instance = "t", input = [
        { pin = "IN" },
        { pin = "PT", source = [{ type = "operand", id = 6, text = "T#1s" }] },
    ], output = [{ pin = "Q" }, { pin = "ET", assign = "elapsed" }] },
]
output = [
    { type = "coil", id = 7, variable = "q", kind = "set" },
    { type = "branch", id = 8, rung = [
        { type = "operand", id = 9, text = "e" },
    ], output = [{ type = "return", id = 10 }] },
]

[[body.network]]
label = "Done"
"#;
    assert_eq!(canonical(compact), expected);
    assert_eq!(canonical(expected), expected);
}

#[test]
fn short_lists_inside_an_element_stay_on_its_line() {
    let text = r#"kind = "function_block"

[body]
language = "fbd"

[[body.network]]
rung = [
    { type = "operand", id = 1, text = "x" },
    { type = "block", id = 2, type_name = "ADD", input = [{ pin = "IN1" }, { pin = "IN2" }] },
]
"#;
    assert_eq!(canonical(text), text);
}

#[test]
fn texts_with_line_breaks_and_quotes_read_back_equal() {
    let text = r#"kind = "program"
body = { language = "ld", network = [{ comment = "two\nlines", rung = [{ type = "operand", id = 1, text = "a\n'b' \"c\"\\" }, { type = "operand", id = 2, text = "x" }] }] }
"#;
    let saved = canonical(text);
    assert!(saved.contains("rung = [\n"), "{saved}");
}

/// The `toml` examples of section 4.1 of `docs/project-format.md`, without their comments.
fn documented_networks() -> Vec<String> {
    let document = include_str!("../../../docs/project-format.md");
    let start = document
        .find("### 4.1 LD and FBD networks")
        .expect("section 4.1");
    let section = &document[start..];
    let end = section[4..]
        .find("\n### ")
        .map_or(section.len(), |end| end + 4);
    section[..end]
        .split("```toml\n")
        .skip(1)
        .filter_map(|block| block.split("```").next())
        .map(|block| {
            block
                .lines()
                .map(|line| match line.find("  # ") {
                    Some(comment) => line[..comment].trim_end(),
                    None => line,
                })
                .fold(String::new(), |text, line| text + line + "\n")
        })
        .collect()
}

#[test]
fn the_documented_networks_are_canonical() {
    let examples = documented_networks();
    assert_eq!(examples.len(), 2);
    for example in examples {
        let text = format!("kind = \"program\"\n\n[body]\nlanguage = \"ld\"\n\n{example}");
        assert_eq!(canonical(&text), text);
    }
}

#[test]
fn an_sfc_chart_is_saved_as_an_indented_tree_one_node_a_line() {
    // The same chart written compactly, on one line.
    let compact = r#"kind = "program"
body = { language = "sfc", chart = { node = [{ type = "step", id = 1, name = "Init" }, { type = "alternative", id = 2, branch = [{ node = [{ type = "transition", id = 3, condition = "xStart" }] }, { node = [{ type = "transition", id = 4, condition = "xAbort", priority = 1 }, { type = "jump", id = 5, target = "Init" }] }] }, { type = "step", id = 6, name = "Fill", max_time = "T#10s", action = [{ action = "Valve", qualifier = "N" }, { action = "Horn", qualifier = "L", duration = "T#2s", indicator = "xHorn" }] }, { type = "transition", id = 7, condition = "Fill.t > T#3s" }, { type = "parallel", id = 8, branch = [{ node = [{ type = "step", id = 9, name = "Left" }] }, { node = [{ type = "macro", id = 10, name = "Right", node = [{ type = "step", id = 11, name = "R1" }, { type = "transition", id = 12, condition = "b" }, { type = "step", id = 13, name = "R2" }] }] }] }, { type = "transition", id = 14, condition = "TRUE" }, { type = "jump", id = 15, target = "Init" }] } }
"#;
    // The example of section 4.3 of the format's documentation.
    let document = include_str!("../../../docs/project-format.md");
    let section = document
        .find("### 4.3 SFC charts")
        .map(|start| &document[start..])
        .expect("section 4.3");
    let example = section
        .split("```toml\n")
        .nth(1)
        .and_then(|block| block.split("```").next())
        .expect("an example");
    let expected = format!("kind = \"program\"\n\n{example}");
    assert_eq!(canonical(compact), expected);
    assert_eq!(canonical(&expected), expected);
}

#[test]
fn a_project_with_a_branching_sfc_chart_loads_saves_and_loads_back_unchanged() {
    use std::collections::BTreeSet;

    use crate::{Folder, Node, Project, load_project, save_project};

    let text = r#"kind = "program"
body = { language = "sfc", chart = { node = [{ type = "step", id = 1, name = "Init", action = [{ action = "Lamp", qualifier = "SD", duration = "T#1s" }] }, { type = "alternative", id = 2, branch = [{ node = [{ type = "transition", id = 3, condition = "a" }] }, { node = [{ type = "transition", id = 4, condition = "b", comment = "two\nlines" }, { type = "jump", id = 5, target = "Init" }] }] }, { type = "parallel", id = 6, branch = [{ node = [{ type = "step", id = 7, name = "L" }] }, { node = [{ type = "step", id = 8, name = "R" }] }] }, { type = "transition", id = 9, condition = "c" }, { type = "jump", id = 10, target = "Init" }] } }
"#;
    let mut pou: Pou = toml::from_str(text).unwrap();
    pou.name = "Seq".into();
    let project = Project {
        application: Folder {
            name: String::new(),
            children: vec![Node::Object(Object::Pou(pou))],
        },
        ..Project::default()
    };
    let dir = tempfile::tempdir().unwrap();
    let first = save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
    let loaded = load_project(dir.path()).unwrap();
    assert_eq!(loaded.project, project);
    let second = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(second.written.is_empty(), "rewrote {:?}", second.written);
    assert_eq!(loaded.files, first.files);
}

#[test]
fn a_cfc_chart_is_saved_one_element_and_one_wire_a_line() {
    // The example of docs/project-format.md §4.2, with a box long enough to pass 100 columns.
    let expected = r#"kind = "program"

[body]
language = "cfc"

[body.chart]
element = [
    { id = 1, x = 2, y = 4, kind = { type = "input", expression = "rSetpoint" } },
    { id = 2, x = 10, y = 4, order = 0, kind = { type = "box", type_name = "SUB", input = [{ name = "IN1" }, { name = "IN2", negated = true }], output = [{ name = "OUT" }] } },
    { id = 3, x = 18, y = 4, order = 1, kind = { type = "output", expression = "rError" } },
]
wire = [
    { from = { element = 1 }, to = { element = 2, pin = "IN1" } },
    { from = { element = 2, pin = "OUT" }, to = { element = 3 }, points = [{ x = 15, y = 6 }] },
]
"#;
    let compact = r#"kind = "program"
body = { language = "cfc", chart = { element = [{ id = 1, x = 2, y = 4, kind = { type = "input", expression = "rSetpoint" } }, { id = 2, x = 10, y = 4, order = 0, kind = { type = "box", type_name = "SUB", input = [{ name = "IN1" }, { name = "IN2", negated = true }], output = [{ name = "OUT" }] } }, { id = 3, x = 18, y = 4, order = 1, kind = { type = "output", expression = "rError" } }], wire = [{ from = { element = 1 }, to = { element = 2, pin = "IN1" } }, { from = { element = 2, pin = "OUT" }, to = { element = 3 }, points = [{ x = 15, y = 6 }] }] } }
"#;
    assert_eq!(canonical(compact), expected);
    assert_eq!(canonical(expected), expected);
}

#[test]
fn il_bodies_are_saved_in_il_files_beside_the_pou_and_load_back_unchanged() {
    use std::collections::BTreeSet;
    use std::path::PathBuf;

    use crate::{Body, Folder, Node, PouAction, Project, load_project, save_project};

    let text = "kind = \"function_block\"\nbody = { language = \"il\" }\n";
    let mut pou: Pou = toml::from_str(text).unwrap();
    pou.name = "Counter".into();
    pou.body = Body::Il {
        text: "LD Reset\nJMPC ResetCnt\n(* count *)\nLD Cnt\nADD 1\n".into(),
    };
    pou.actions.push(PouAction {
        name: "Clear".into(),
        body: Body::Il {
            text: "LD 0\nST Cnt\n".into(),
        },
    });
    let project = Project {
        application: Folder {
            name: String::new(),
            children: vec![Node::Object(Object::Pou(pou))],
        },
        ..Project::default()
    };
    let dir = tempfile::tempdir().unwrap();
    let first = save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
    let il_files: Vec<&PathBuf> = first
        .files
        .iter()
        .filter(|file| file.extension().is_some_and(|ext| ext == "il"))
        .collect();
    assert_eq!(il_files.len(), 2, "{:?}", first.files);
    let body = std::fs::read_to_string(dir.path().join("application/Counter.il")).unwrap();
    assert_eq!(
        body,
        "LD Reset\nJMPC ResetCnt\n(* count *)\nLD Cnt\nADD 1\n"
    );
    let loaded = load_project(dir.path()).unwrap();
    assert_eq!(loaded.project, project);
    let second = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(second.written.is_empty(), "rewrote {:?}", second.written);
}

#[test]
fn serial_ports_and_runtime_devices_are_saved_in_canonical_order_and_load_back_equal() {
    use std::collections::BTreeSet;

    use crate::{
        ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDataType,
        ModbusDevice, ModbusLink, ModbusSchedule, ModbusTable, Parity, Project, SerialPort,
        WordOrder, load_project, save_project,
    };

    let mut temperatures = ModbusBinding::new(
        "GVL_Io.aiTemperatures",
        ModbusTable::InputRegister,
        0,
        ModbusDataType::Int16,
    );
    temperatures.count = 8;
    temperatures.on_error = ChannelErrorAction::SetToZero;
    temperatures.error_flag = Some("GVL_Io.xTempError".into());
    let mut setpoint = ModbusBinding::new(
        "GVL_Io.iSetpoint",
        ModbusTable::HoldingRegister,
        10,
        ModbusDataType::Int16,
    );
    setpoint.direction = ChannelDirection::Write;
    setpoint.function_code = Some(6);
    setpoint.trigger = ChannelTrigger::RisingEdge;
    setpoint.trigger_variable = Some("GVL_Io.xSend".into());
    setpoint.comment = "Sent on a rising edge".into();
    let project = Project {
        serial_ports: vec![SerialPort {
            parity: Parity::None,
            stop_bits: 2,
            inter_frame_delay_us: 5000,
            ..SerialPort::new("RS485", "/dev/ttyUSB0")
        }],
        modbus_devices: vec![
            ModbusDevice {
                name: "BeltDrive".into(),
                link: ModbusLink::Tcp {
                    host: "127.0.0.1".into(),
                    port: 5502,
                },
                unit_id: 1,
                word_order: WordOrder::HighFirst,
                poll_interval_ms: Some(10),
                timeout_ms: 100,
                task: Some("MainTask".into()),
                schedule: ModbusSchedule::Interval,
                max_read_gap: 4,
                status: Some("GVL_Io.stBeltDrive".into()),
                bindings: Vec::new(),
            },
            ModbusDevice {
                name: "TempController".into(),
                link: ModbusLink::Rtu {
                    serial_port: "RS485".into(),
                },
                unit_id: 3,
                word_order: WordOrder::LowFirst,
                poll_interval_ms: None,
                timeout_ms: 200,
                task: Some("MainTask".into()),
                schedule: ModbusSchedule::EveryCycle,
                max_read_gap: 0,
                status: None,
                bindings: vec![temperatures, setpoint],
            },
        ],
        ..Project::default()
    };
    let dir = tempfile::tempdir().unwrap();
    let first = save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
    let manifest = std::fs::read_to_string(dir.path().join("rivet.toml")).unwrap();
    let devices = &manifest[manifest.find("[[serial_port]]").unwrap()..];
    assert_eq!(
        devices,
        r#"[[serial_port]]
name = "RS485"
device = "/dev/ttyUSB0"
baud_rate = 19200
parity = "none"
data_bits = 8
stop_bits = 2
inter_frame_delay_us = 5000

[[modbus_device]]
name = "BeltDrive"
host = "127.0.0.1"
port = 5502
unit_id = 1
word_order = "high_first"
poll_interval_ms = 10
timeout_ms = 100
task = "MainTask"
max_read_gap = 4
status = "GVL_Io.stBeltDrive"

[[modbus_device]]
name = "TempController"
serial_port = "RS485"
unit_id = 3
word_order = "low_first"
timeout_ms = 200
task = "MainTask"
schedule = "every_cycle"

[[modbus_device.binding]]
variable = "GVL_Io.aiTemperatures"
table = "input_register"
address = 0
data_type = "int16"
count = 8
on_error = "set_to_zero"
error_flag = "GVL_Io.xTempError"

[[modbus_device.binding]]
variable = "GVL_Io.iSetpoint"
table = "holding_register"
address = 10
data_type = "int16"
direction = "write"
function_code = 6
trigger = "rising_edge"
trigger_variable = "GVL_Io.xSend"
comment = "Sent on a rising edge"
"#
    );
    let loaded = load_project(dir.path()).unwrap();
    assert_eq!(loaded.project, project);
    let second = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(
        second.written.is_empty(),
        "{:?} after {:?}",
        second.written,
        first.written
    );
}

#[test]
fn a_studio_device_leaves_every_new_key_out() {
    use crate::{ModbusBinding, ModbusDataType, ModbusDevice, ModbusLink, ModbusTable};

    let text = r#"name = "BeltDrive"
host = "192.168.1.50"
port = 502
unit_id = 1
word_order = "high_first"
poll_interval_ms = 100
timeout_ms = 500

[[binding]]
variable = "GVL_Machine.rBeltSpeedActual"
table = "input_register"
address = 0
data_type = "real"
"#;
    let device: ModbusDevice = toml::from_str(text).unwrap();
    assert_eq!(
        device.link,
        ModbusLink::Tcp {
            host: "192.168.1.50".into(),
            port: 502
        }
    );
    assert!(!device.is_runtime_device());
    assert_eq!(
        device.bindings,
        [ModbusBinding::new(
            "GVL_Machine.rBeltSpeedActual",
            ModbusTable::InputRegister,
            0,
            ModbusDataType::Real
        )]
    );
    assert_eq!(super::to_canonical_toml(&device).unwrap(), text);
}
