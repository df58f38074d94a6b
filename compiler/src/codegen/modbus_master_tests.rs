//! Section 14 as the build writes it, compared with one written by hand from
//! `docs/modbus-master.md` §5.1.

use program_image::Elementary as IE;
use program_image::ModbusTable as ImageTable;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, MasterSection, OnError, Parity, Schedule,
    SerialPortDef, Trigger, WordOrder,
};
use project_model::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDataType,
    ModbusDevice, ModbusLink, ModbusSchedule, ModbusTable, Project, SerialPort, Task, TaskKind,
};

use crate::{SourceProject, compile_project};

/// Two tasks, globals of every kind a channel binds, and a program that uses them.
const SOURCE: &str = "\
VAR_GLOBAL
    iIn : INT;
    aiTemps : ARRAY[0..7] OF INT;
    xError : BOOL;
    xSend : BOOL;
    stHeater : MODBUS_DEVICE_STATUS;
    arSetpoints : ARRAY[1..2] OF REAL;
    xPump : BOOL;
END_VAR
PROGRAM Main
VAR
    iOut : INT;
END_VAR
iOut := iIn * 2 + aiTemps[0];
arSetpoints[1] := INT_TO_REAL(iOut);
xPump := NOT xError AND NOT stHeater.xError;
END_PROGRAM
PROGRAM Slow
xSend := NOT xSend;
END_PROGRAM
";

/// A task calling `program`.
fn task(name: &str, interval_us: u32, program: &str) -> Task {
    Task {
        name: name.into(),
        kind: TaskKind::Cyclic { interval_us },
        priority: 1,
        watchdog: None,
        programs: vec![program.into()],
    }
}

/// Two runtime devices (TCP polled every 20 ms, RTU after every cycle) with channels of every
/// kind (reads, a default and a single write, an array, an edge-triggered write, an error flag
/// and a status), and a studio device between them.
fn two_device_project() -> Project {
    let mut project = SourceProject::new(SOURCE).project;
    project.tasks = vec![
        task("SlowTask", 100_000, "Slow"),
        task("MainTask", 10_000, "Main"),
    ];
    let mut unused = SerialPort::new("Spare", "/dev/ttyS0");
    unused.baud_rate = 9600;
    let mut line = SerialPort::new("RS485", "/dev/ttyUSB0");
    line.parity = project_model::Parity::None;
    line.stop_bits = 2;
    line.inter_frame_delay_us = 5000;
    project.serial_ports = vec![unused, line];

    // A TCP device polled every 20 ms, reading into unqualified and array globals and a
    // program's variable, writing with the default code.
    let mut drive = ModbusDevice {
        task: Some("maintask".into()),
        poll_interval_ms: Some(20),
        max_read_gap: 4,
        word_order: project_model::WordOrder::LowFirst,
        ..ModbusDevice::tcp("BeltDrive", "127.0.0.1", 5502)
    };
    let mut temps = ModbusBinding::new(
        "GVL.aiTemps",
        ModbusTable::InputRegister,
        10,
        ModbusDataType::Int16,
    );
    temps.count = 8;
    temps.on_error = ChannelErrorAction::SetToZero;
    temps.error_flag = Some("xError".into());
    let mut out = ModbusBinding::new(
        "Main.iOut",
        ModbusTable::HoldingRegister,
        0,
        ModbusDataType::Int16,
    );
    out.direction = ChannelDirection::Write;
    drive.bindings = vec![
        ModbusBinding::new(
            "iIn",
            ModbusTable::HoldingRegister,
            1,
            ModbusDataType::Int16,
        ),
        temps,
        out,
    ];
    // A studio device stays out of the section.
    let studio = ModbusDevice::tcp("Meter", "127.0.0.1", 5503);
    // An RTU device polled after every cycle, with a status, a single-coil write and a REAL
    // array sent on an edge.
    let mut pump = ModbusBinding::new("GVL.xPump", ModbusTable::Coil, 3, ModbusDataType::Bool);
    pump.direction = ChannelDirection::Write;
    pump.function_code = Some(5);
    let mut setpoints = ModbusBinding::new(
        "GVL.arSetpoints",
        ModbusTable::HoldingRegister,
        100,
        ModbusDataType::Real,
    );
    setpoints.count = 2;
    setpoints.direction = ChannelDirection::Write;
    setpoints.trigger = ChannelTrigger::RisingEdge;
    setpoints.trigger_variable = Some("xSend".into());
    let heater = ModbusDevice {
        link: ModbusLink::Rtu {
            serial_port: "rs485".into(),
        },
        unit_id: 3,
        timeout_ms: 200,
        poll_interval_ms: None,
        task: Some("SlowTask".into()),
        schedule: ModbusSchedule::EveryCycle,
        status: Some("GVL.stHeater".into()),
        bindings: vec![pump, setpoints],
        ..ModbusDevice::tcp("Heater", "", 0)
    };
    project.modbus_devices = vec![drive, studio, heater];

    project
}

#[test]
fn the_section_holds_the_runtime_devices_with_indices_codes_and_tags_resolved() {
    let project = two_device_project();
    let image = compile_project(&project).unwrap();
    let channel = |variable: &str, table, address, value_type, function_code| ChannelDef {
        variable: variable.to_owned(),
        table,
        address,
        value_type,
        count: 1,
        direction: Direction::Read,
        function_code,
        trigger: Trigger::Cyclic,
        on_error: OnError::KeepLastValue,
        error_flag: None,
    };
    let expected = MasterSection {
        serial_ports: vec![SerialPortDef {
            name: "RS485".into(),
            device: "/dev/ttyUSB0".into(),
            baud_rate: 19200,
            parity: Parity::None,
            data_bits: 8,
            stop_bits: 2,
            inter_frame_delay_us: 5000,
        }],
        devices: vec![
            DeviceDef {
                name: "BeltDrive".into(),
                link: Link::Tcp {
                    host: "127.0.0.1".into(),
                    port: 5502,
                },
                unit_id: 1,
                timeout_ms: 500,
                task: 1,
                schedule: Schedule::Interval { interval_ms: 20 },
                word_order: WordOrder::LowFirst,
                max_read_gap: 4,
                status: None,
                channels: vec![
                    // An unqualified global is written as the runtime finds it.
                    channel("GVL.iIn", ImageTable::HoldingRegisters, 1, IE::Int, 3),
                    ChannelDef {
                        count: 8,
                        on_error: OnError::SetToZero,
                        error_flag: Some("GVL.xError".into()),
                        ..channel("GVL.aiTemps", ImageTable::InputRegisters, 10, IE::Int, 4)
                    },
                    ChannelDef {
                        direction: Direction::Write,
                        ..channel("Main.iOut", ImageTable::HoldingRegisters, 0, IE::Int, 16)
                    },
                ],
            },
            DeviceDef {
                name: "Heater".into(),
                link: Link::Rtu { serial_port: 0 },
                unit_id: 3,
                timeout_ms: 200,
                task: 0,
                schedule: Schedule::EveryCycle,
                word_order: WordOrder::HighFirst,
                max_read_gap: 0,
                status: Some("GVL.stHeater".into()),
                channels: vec![
                    ChannelDef {
                        direction: Direction::Write,
                        ..channel("GVL.xPump", ImageTable::Coils, 3, IE::Bool, 5)
                    },
                    ChannelDef {
                        count: 2,
                        direction: Direction::Write,
                        trigger: Trigger::RisingEdge {
                            variable: "GVL.xSend".into(),
                        },
                        ..channel(
                            "GVL.arSetpoints",
                            ImageTable::HoldingRegisters,
                            100,
                            IE::Real,
                            16,
                        )
                    },
                ],
            },
        ],
    };
    assert_eq!(image.modbus_master, Some(expected));
    // The section survives the container and the load-time verification.
    let decoded = program_image::ProgramImage::decode(&image.encode()).unwrap();
    assert_eq!(decoded.modbus_master, image.modbus_master);
}

#[test]
fn the_example_project_builds_without_a_modbus_finding_or_section() {
    let project = project_model::load_project(&assets::example_project_dir())
        .unwrap()
        .project;
    // Its BeltDrive at 192.168.1.50 stays a studio device: a task would send traffic there.
    assert!(
        project
            .modbus_devices
            .iter()
            .all(|device| device.task.is_none())
    );
    let modbus_findings: Vec<String> = crate::sema::check_project(&project)
        .into_iter()
        .filter(|finding| {
            let id = finding.diagnostic.code.id();
            ("E0140"..="E0145").contains(&id) || matches!(id, "W0015" | "W0016")
        })
        .map(|finding| finding.diagnostic.message)
        .collect();
    assert_eq!(modbus_findings, Vec::<String>::new());
    let image = compile_project(&project).unwrap();
    assert_eq!(image.modbus_master, None);
}

#[test]
fn bit_channels_without_a_function_code_get_the_defaults_1_2_and_15() {
    let mut project = SourceProject::new(SOURCE).project;
    project.tasks = vec![task("MainTask", 10_000, "Main")];
    let bit = |variable: &str, table, address| {
        ModbusBinding::new(variable, table, address, ModbusDataType::Bool)
    };
    let mut send = bit("GVL.xSend", ModbusTable::Coil, 8);
    send.direction = ChannelDirection::Write;
    project.modbus_devices = vec![ModbusDevice {
        task: Some("MainTask".into()),
        poll_interval_ms: Some(10),
        bindings: vec![
            bit("GVL.xPump", ModbusTable::Coil, 0),
            bit("GVL.xError", ModbusTable::DiscreteInput, 0),
            send,
        ],
        ..ModbusDevice::tcp("Valves", "127.0.0.1", 5502)
    }];
    let image = compile_project(&project).unwrap();
    let codes: Vec<(String, u8)> = image
        .modbus_master
        .iter()
        .flat_map(|section| &section.devices)
        .flat_map(|device| &device.channels)
        .map(|channel| (channel.variable.clone(), channel.function_code))
        .collect();
    assert_eq!(
        codes,
        [
            ("GVL.xPump".to_owned(), 1),
            ("GVL.xError".to_owned(), 2),
            ("GVL.xSend".to_owned(), 15),
        ]
    );
}

#[test]
fn the_editor_defines_and_counts_each_device_as_the_build_does() {
    let project = two_device_project();
    let image = compile_project(&project).unwrap();
    let built = image.modbus_master.unwrap().devices;
    let runtime_devices: Vec<&ModbusDevice> = project
        .modbus_devices
        .iter()
        .filter(|device| device.is_runtime_device())
        .collect();
    assert_eq!(runtime_devices.len(), built.len());
    for (device, built) in runtime_devices.into_iter().zip(&built) {
        assert_eq!(&crate::ide::modbus_device_def(&project, device), built);
        assert_eq!(
            crate::ide::modbus_round_requests(&project, device),
            program_image::modbus_master::plan(built).len(),
            "{}",
            device.name
        );
    }
}
