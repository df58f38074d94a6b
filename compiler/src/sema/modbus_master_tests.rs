//! The build's findings about runtime Modbus devices, one project per code, checked whole.

use project_model::{
    ChannelDirection, ChannelTrigger, ModbusBinding, ModbusDataType, ModbusDevice, ModbusLink,
    ModbusSchedule, ModbusTable, Project, SerialPort, Task, TaskKind,
};

use crate::SourceProject;
use crate::sema::check_project;

/// The program and globals every test starts from: `GVL` with inputs, an output, flags and a
/// status; `Main` reads `iIn` into `iOut`.
const SOURCE: &str = "\
VAR_GLOBAL
    iIn : INT;
    iOut : INT;
    aiTemps : ARRAY[0..3] OF INT;
    xError : BOOL;
    xSend : BOOL;
    stDrive : MODBUS_DEVICE_STATUS;
    wRaw : WORD;
END_VAR
VAR_GLOBAL CONSTANT
    iLimit : INT := 100;
END_VAR
PROGRAM Main
VAR
    iLocal : INT;
    iUnused : INT;
END_VAR
VAR_TEMP
    iScratch : INT;
END_VAR
iScratch := 1;
GVL.iOut := GVL.iIn * 2 + iLocal + iScratch;
IF GVL.stDrive.xError THEN
    GVL.iOut := 0;
END_IF
END_PROGRAM
";

/// `SOURCE` as a project with a 10 ms `MainTask` calling `Main` and `devices`.
fn project(devices: Vec<ModbusDevice>) -> Project {
    project_from(SOURCE, devices)
}

/// `source` as a project with a 10 ms `MainTask` calling `Main` and `devices`.
fn project_from(source: &str, devices: Vec<ModbusDevice>) -> Project {
    let mut project = SourceProject::new(source).project;
    project.tasks = vec![Task {
        name: "MainTask".into(),
        kind: TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority: 1,
        watchdog: None,
        programs: vec!["Main".into()],
    }];
    project.modbus_devices = devices;
    project
}

/// A TCP device on 127.0.0.1 mastered in `MainTask` every 10 ms, with `bindings`.
fn device(name: &str, bindings: Vec<ModbusBinding>) -> ModbusDevice {
    ModbusDevice {
        task: Some("MainTask".into()),
        poll_interval_ms: Some(10),
        bindings,
        ..ModbusDevice::tcp(name, "127.0.0.1", 5502)
    }
}

/// A channel reading `data_type` values at `address` of the input registers into `variable`.
fn read(variable: &str, address: u16, data_type: ModbusDataType) -> ModbusBinding {
    ModbusBinding::new(variable, ModbusTable::InputRegister, address, data_type)
}

/// A channel writing one INT from `variable` to holding register `address`.
fn write(variable: &str, address: u16) -> ModbusBinding {
    ModbusBinding {
        direction: ChannelDirection::Write,
        ..ModbusBinding::new(
            variable,
            ModbusTable::HoldingRegister,
            address,
            ModbusDataType::Int16,
        )
    }
}

/// Every finding of `project` with a code of issue 19, and every W0001 and W0002, as
/// `CODE declaration: message`.
fn findings(project: &Project) -> Vec<String> {
    check_project(project)
        .into_iter()
        .filter(|finding| {
            let id = finding.diagnostic.code.id();
            ("E0140"..="E0145").contains(&id) || matches!(id, "W0001" | "W0002" | "W0015" | "W0016")
        })
        .map(|finding| {
            if !finding.diagnostic.code.id().starts_with("W000") {
                assert_eq!(
                    finding.file.to_str(),
                    Some(project_model::MANIFEST_FILE_NAME)
                );
            }
            format!(
                "{} {}: {}",
                finding.diagnostic.code.id(),
                finding.declaration.unwrap_or_default(),
                finding.diagnostic.message
            )
        })
        .collect()
}

/// The device of the clean project: reads `iIn`, writes `iOut`, fills the status and an error
/// flag, and sends `wRaw` on a rising edge of `xSend`.
fn clean_device() -> ModbusDevice {
    let mut device = device(
        "BeltDrive",
        vec![
            read("GVL.iIn", 0, ModbusDataType::Int16),
            write("GVL.iOut", 10),
            ModbusBinding {
                error_flag: Some("GVL.xError".into()),
                ..read("GVL.aiTemps", 1, ModbusDataType::Int16)
            },
            ModbusBinding {
                trigger: ChannelTrigger::RisingEdge,
                trigger_variable: Some("GVL.xSend".into()),
                ..write("GVL.wRaw", 11)
            },
            read("Main.iLocal", 20, ModbusDataType::Int16),
        ],
    );
    device.bindings[2].count = 4;
    device.bindings[3].data_type = ModbusDataType::Uint16;
    device.status = Some("GVL.stDrive".into());
    device
}

#[test]
fn a_runtime_device_bound_to_fitting_variables_has_no_finding_and_fills_its_variables() {
    // Main.iLocal is read and never written by the program, but the runtime fills it: no
    // W0002; iUnused is still never used.
    assert_eq!(
        findings(&project(vec![clean_device()])),
        ["W0001 iUnused: 'iUnused' is declared but never used"]
    );
    let mut studio = clean_device();
    studio.task = None;
    assert_eq!(
        findings(&project(vec![studio])),
        [
            "W0002 iLocal: 'iLocal' is read but never written, so it always holds its default value",
            "W0001 iUnused: 'iUnused' is declared but never used",
        ]
    );
}

#[test]
fn a_studio_device_is_not_checked_by_the_build() {
    let mut studio = device("Meter", vec![read("GVL.iMissing", 0, ModbusDataType::Real)]);
    studio.task = None;
    studio.bindings[0].direction = ChannelDirection::Write;
    assert_eq!(
        findings(&project(vec![studio])),
        [
            "W0002 iLocal: 'iLocal' is read but never written, so it always holds its default value",
            "W0001 iUnused: 'iUnused' is declared but never used",
        ]
    );
}

/// The findings of one device with `bindings` and `status`, without the W0001/W0002 of `SOURCE`.
fn device_findings(bindings: Vec<ModbusBinding>, status: Option<&str>) -> Vec<String> {
    let mut device = device("BeltDrive", bindings);
    device.status = status.map(str::to_owned);
    findings(&project(vec![device]))
        .into_iter()
        .filter(|finding| !finding.starts_with("W000"))
        .collect()
}

#[test]
fn e0140_names_paths_the_runtime_cannot_copy() {
    assert_eq!(
        device_findings(
            vec![
                read("GVL.iMissing", 0, ModbusDataType::Int16),
                read("Main.iScratch", 1, ModbusDataType::Int16),
                read("GVL.iLimit", 2, ModbusDataType::Int16),
                // A write channel only reads its variable, so a CONSTANT is fine.
                write("GVL.iLimit", 3),
                read("", 4, ModbusDataType::Int16),
            ],
            Some("Main.iNothing"),
        ),
        [
            "E0140 BeltDrive: Modbus device 'BeltDrive', status (Main.iNothing): the status variable 'Main.iNothing' names no variable of the project: write the path of a global or program variable, such as GVL_IO.rSpeed",
            "E0140 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iMissing): the variable 'GVL.iMissing' names no variable of the project: write the path of a global or program variable, such as GVL_IO.rSpeed",
            "E0140 BeltDrive: Modbus device 'BeltDrive', channel 2 (Main.iScratch): the variable 'Main.iScratch' is a VAR_TEMP, which has no place between cycles: bind a global variable or a program's VAR, VAR_INPUT or VAR_OUTPUT",
            "E0140 BeltDrive: Modbus device 'BeltDrive', channel 3 (GVL.iLimit): the variable 'GVL.iLimit' is a CONSTANT, which the runtime cannot write: remove CONSTANT or bind another variable",
            "E0140 BeltDrive: Modbus device 'BeltDrive', channel 5 (): the variable '' names no variable of the project: write the path of a global or program variable, such as GVL_IO.rSpeed",
        ]
    );
}

#[test]
fn e0140_refuses_a_static_variable_reached_through_an_instance_or_a_derived_block() {
    let source = format!(
        "FUNCTION_BLOCK FB_Base\nVAR_STAT\n    iShared : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION_BLOCK FB_Derived EXTENDS FB_Base\nEND_FUNCTION_BLOCK\n{}",
        SOURCE.replace("iUnused : INT;", "iUnused : INT;\n    fbX : FB_Derived;")
    );
    let device = device(
        "BeltDrive",
        vec![
            read("Main.fbX.iShared", 0, ModbusDataType::Int16),
            read("FB_Derived.iShared", 1, ModbusDataType::Int16),
            read("FB_Base.iShared", 2, ModbusDataType::Int16),
        ],
    );
    let found: Vec<String> = findings(&project_from(&source, vec![device]))
        .into_iter()
        .filter(|finding| finding.starts_with("E0140"))
        .collect();
    assert_eq!(
        found,
        [
            "E0140 BeltDrive: Modbus device 'BeltDrive', channel 1 (Main.fbX.iShared): the variable 'Main.fbX.iShared' names a VAR_STAT, which all instances share under the name of the function block declaring it: bind 'FB_Base.iShared' instead",
            "E0140 BeltDrive: Modbus device 'BeltDrive', channel 2 (FB_Derived.iShared): the variable 'FB_Derived.iShared' names a VAR_STAT, which all instances share under the name of the function block declaring it: bind 'FB_Base.iShared' instead",
        ]
    );
}

#[test]
fn e0141_refuses_several_values_at_a_bit_address() {
    let source = SOURCE.replace(
        "wRaw : WORD;",
        "wRaw : WORD;\n    axBits AT %IX0.0 : ARRAY[0..7] OF BOOL;\n    xOne AT %IX1.0 : BOOL;",
    );
    let coils = |variable: &str, address: u16, count: u16| ModbusBinding {
        count,
        ..ModbusBinding::new(variable, ModbusTable::Coil, address, ModbusDataType::Bool)
    };
    let device = device(
        "BeltDrive",
        vec![coils("GVL.axBits", 0, 8), coils("GVL.xOne", 8, 1)],
    );
    let found: Vec<String> = findings(&project_from(&source, vec![device]))
        .into_iter()
        .filter(|finding| finding.starts_with("E0141"))
        .collect();
    assert_eq!(
        found,
        [
            "E0141 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.axBits): the variable 'GVL.axBits' is located at the bit address %IX0.0, where the runtime copies one bit, but the channel holds 8 values: remove the AT address, or bind a variable of its own to each bit"
        ]
    );
}

#[test]
fn e0141_says_which_declaration_fits_the_data_type_and_count() {
    let mut temps = read("GVL.aiTemps", 0, ModbusDataType::Int16);
    temps.count = 8;
    assert_eq!(
        device_findings(
            vec![
                temps,
                read("GVL.iIn", 10, ModbusDataType::Real),
                read("GVL.wRaw", 12, ModbusDataType::Uint16),
                read("GVL.aiTemps", 20, ModbusDataType::Int16),
            ],
            None,
        ),
        [
            "E0141 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.aiTemps): the channel reads 8 int16 values, but the variable is declared as ARRAY[0..3] OF INT: declare it as ARRAY[0..7] OF INT",
            "E0141 BeltDrive: Modbus device 'BeltDrive', channel 2 (GVL.iIn): the channel reads one real value, but the variable is declared as INT: declare it as REAL",
            "E0141 BeltDrive: Modbus device 'BeltDrive', channel 4 (GVL.aiTemps): the channel reads one int16 value, but the variable is declared as ARRAY[0..3] OF INT: declare it as INT",
            "E0142 BeltDrive: Modbus device 'BeltDrive', channel 4 (GVL.aiTemps): the variable 'GVL.aiTemps' is also filled by Modbus device 'BeltDrive', channel 1 (GVL.aiTemps): bind each channel, status and error flag to a variable of its own",
        ]
    );
}

#[test]
fn e0142_finds_two_devices_filling_one_variable_or_a_part_of_it() {
    let first = device(
        "BeltDrive",
        vec![ModbusBinding {
            error_flag: Some("GVL.xError".into()),
            ..read("GVL.iIn", 0, ModbusDataType::Int16)
        }],
    );
    let mut second = device(
        "Meter",
        vec![ModbusBinding::new(
            "GVL.stDrive.xError",
            ModbusTable::DiscreteInput,
            0,
            ModbusDataType::Bool,
        )],
    );
    second.bindings.push(ModbusBinding {
        error_flag: Some("gvl.xerror".into()),
        ..read("iIn", 1, ModbusDataType::Int16)
    });
    second.status = Some("GVL.stDrive".into());
    let found: Vec<String> = findings(&project(vec![first, second]))
        .into_iter()
        .filter(|finding| !finding.starts_with("W000"))
        .collect();
    assert_eq!(
        found,
        [
            "E0142 Meter: Modbus device 'Meter', channel 1 (GVL.stDrive.xError): the variable 'GVL.stDrive.xError' is also filled by Modbus device 'Meter', status (GVL.stDrive), as its status: bind each channel, status and error flag to a variable of its own",
            "E0142 Meter: Modbus device 'Meter', channel 2 (iIn): the variable 'iIn' is also filled by Modbus device 'BeltDrive', channel 1 (GVL.iIn): bind each channel, status and error flag to a variable of its own",
            "E0142 Meter: Modbus device 'Meter', channel 2 (iIn): the error flag 'gvl.xerror' is also filled by Modbus device 'BeltDrive', channel 1 (GVL.iIn), as its error flag: bind each channel, status and error flag to a variable of its own",
        ]
    );
}

#[test]
fn e0143_and_e0144_report_a_project_past_the_runtime_s_limits() {
    let mut devices: Vec<ModbusDevice> = (0..256u16)
        .map(|number| ModbusDevice {
            poll_interval_ms: Some(10),
            task: Some("MainTask".into()),
            ..ModbusDevice::tcp(format!("Tcp{number}"), "127.0.0.1", 5000 + number)
        })
        .collect();
    devices[0].bindings = (0..1025u16)
        .map(|address| {
            ModbusBinding::new(
                "GVL.xError",
                ModbusTable::DiscreteInput,
                address,
                ModbusDataType::Bool,
            )
        })
        .collect();
    let mut project = project(Vec::new());
    for number in 0..33 {
        let port = format!("Port{number}");
        project
            .serial_ports
            .push(SerialPort::new(&port, format!("/dev/ttyS{number}")));
        devices.push(ModbusDevice {
            link: ModbusLink::Rtu { serial_port: port },
            ..device(&format!("Rtu{number}"), Vec::new())
        });
    }
    project.modbus_devices = devices;
    let found: Vec<String> = findings(&project)
        .into_iter()
        .filter(|finding| finding.contains("at most") || finding.contains("the most"))
        .collect();
    assert_eq!(
        found,
        [
            "E0143 Port32: serial port 'Port32': the project's runtime devices name more than 32 serial ports, the most the runtime masters: let devices share ports, or move some to the Studio",
            "E0143 Tcp255: Modbus device 'Tcp255': the project has 289 devices with an I/O task, but the runtime masters at most 255: this and the later ones are too many; master some in the Studio (no task)",
            "E0144 Tcp0: Modbus device 'Tcp0': it has 1025 channels, but the runtime masters at most 1024 per device: merge neighbouring channels into longer ones, or split the device",
        ]
    );
}

#[test]
fn e0143_reports_the_task_the_editor_s_device_problems_and_the_serial_ports() {
    let mut tcp = device("BeltDrive", Vec::new());
    tcp.task = Some("FastTask".into());
    tcp.timeout_ms = 0;
    let rtu = |name: &str, port: &str| ModbusDevice {
        link: ModbusLink::Rtu {
            serial_port: port.into(),
        },
        schedule: ModbusSchedule::EveryCycle,
        poll_interval_ms: None,
        ..device(name, Vec::new())
    };
    let mut project = project(vec![
        tcp,
        rtu("Heater", "RS485"),
        rtu("Scale", "RS232"),
        rtu("Pump", "Missing"),
    ]);
    let mut rs485 = SerialPort::new("RS485", "/dev/ttyUSB0");
    rs485.data_bits = 7;
    let rs232 = SerialPort::new("RS232", "/dev/ttyUSB0");
    // A port no runtime device names is not opened, so it is not checked.
    let unused = SerialPort::new("Spare", "");
    project.serial_ports = vec![rs485, rs232, unused];
    assert_eq!(
        findings(&project)
            .into_iter()
            .filter(|finding| !finding.starts_with("W000"))
            .collect::<Vec<_>>(),
        [
            "E0143 RS485: serial port 'RS485': 7 data bits cannot be used: enter 8 (Modbus RTU sends 8 data bits)",
            "E0143 RS232: serial port 'RS232': its device file '/dev/ttyUSB0' is also the device file of serial port 'RS485': two ports cannot share one device file",
            "E0143 BeltDrive: Modbus device 'BeltDrive': there is no task named 'FastTask' to copy the device's values: choose one of the project's tasks",
            "E0143 BeltDrive: Modbus device 'BeltDrive': the timeout is at least 1 ms",
            "E0143 Pump: Modbus device 'Pump': there is no serial port named 'Missing': add it under the controller or choose another",
        ]
    );
}

#[test]
fn e0144_reports_the_editor_s_channel_problems_once_each() {
    let mut coil = ModbusBinding::new("GVL.xSend", ModbusTable::Coil, 0, ModbusDataType::Bool);
    coil.on_error = project_model::ChannelErrorAction::SetToZero;
    coil.direction = ChannelDirection::Write;
    assert_eq!(
        device_findings(
            vec![
                ModbusBinding {
                    direction: ChannelDirection::Write,
                    ..read("GVL.iOut", 0, ModbusDataType::Int16)
                },
                ModbusBinding {
                    function_code: Some(3),
                    ..write("GVL.iOut", 1)
                },
                coil,
            ],
            None,
        ),
        [
            "E0144 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iOut): the channel writes to the input register table, which is read-only: only coils and holding registers can be written",
            "E0144 BeltDrive: Modbus device 'BeltDrive', channel 2 (GVL.iOut): function code 3 cannot write the holding register table; use 5 or 15 for coils, 6 or 16 for holding registers",
            "E0144 BeltDrive: Modbus device 'BeltDrive', channel 3 (GVL.xSend): the channel writes, so 'on error' does not apply: it chooses what a read channel's variable holds",
        ]
    );
}

#[test]
fn e0145_wants_the_status_structure_and_bool_flags() {
    assert_eq!(
        device_findings(
            vec![ModbusBinding {
                error_flag: Some("GVL.iOut".into()),
                trigger: ChannelTrigger::RisingEdge,
                trigger_variable: Some("GVL.wRaw".into()),
                ..write("GVL.iIn", 0)
            }],
            Some("GVL.iOut"),
        ),
        [
            "E0145 BeltDrive: Modbus device 'BeltDrive', status (GVL.iOut): the status variable is declared as INT: declare it as MODBUS_DEVICE_STATUS",
            "E0145 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iIn): the error flag 'GVL.iOut' is declared as INT: declare it as BOOL",
            "E0145 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iIn): the trigger variable 'GVL.wRaw' is declared as WORD: declare it as BOOL",
            "E0142 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iIn): the error flag 'GVL.iOut' is also filled by Modbus device 'BeltDrive', status (GVL.iOut), as its status: bind each channel, status and error flag to a variable of its own",
            "W0015 BeltDrive: Modbus device 'BeltDrive', status (GVL.iOut): the program also writes the status variable 'GVL.iOut', but the next cycle's copy from the device overwrites what it wrote: leave it to the runtime, or bind another variable",
            "W0015 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iIn): the program also writes the error flag 'GVL.iOut', but the next cycle's copy from the device overwrites what it wrote: leave it to the runtime, or bind another variable",
        ]
    );
}

#[test]
fn a_project_s_own_status_type_must_have_the_library_s_members() {
    let source = format!(
        "TYPE MODBUS_DEVICE_STATUS :\nSTRUCT\n    xConnected : BOOL;\nEND_STRUCT\nEND_TYPE\n{SOURCE}"
    );
    let mut device = device("BeltDrive", Vec::new());
    device.status = Some("GVL.stDrive".into());
    let found: Vec<String> = findings(&project_from(&source, vec![device]))
        .into_iter()
        .filter(|finding| finding.starts_with("E0145"))
        .collect();
    assert_eq!(
        found,
        [
            "E0145 BeltDrive: Modbus device 'BeltDrive', status (GVL.stDrive): the project declares its own MODBUS_DEVICE_STATUS, whose members differ from the Modbus library's, which the runtime writes: remove the project's declaration or give it the library's members"
        ]
    );
}

/// The E0145 findings of a device whose status is `GVL.stDrive`, with `declarations` before
/// `SOURCE`.
fn status_findings(declarations: &str) -> Vec<String> {
    let source = format!("{declarations}\n{SOURCE}");
    let mut device = device("BeltDrive", Vec::new());
    device.status = Some("GVL.stDrive".into());
    findings(&project_from(&source, vec![device]))
        .into_iter()
        .filter(|finding| finding.starts_with("E0145"))
        .collect()
}

#[test]
fn a_project_s_own_error_codes_must_keep_the_status_layout() {
    assert_eq!(
        status_findings("TYPE MB_ErrorCodes : (A, B); END_TYPE"),
        [
            "E0145 BeltDrive: Modbus device 'BeltDrive', status (GVL.stDrive): the project's MB_ErrorCodes has the base type INT (the default), which makes the member eLastError another size than the runtime writes: the project's MB_ErrorCodes must have the base type USINT"
        ]
    );
    assert_eq!(
        status_findings("TYPE MB_ErrorCodes : (A, B) UDINT; END_TYPE"),
        [
            "E0145 BeltDrive: Modbus device 'BeltDrive', status (GVL.stDrive): the project's MB_ErrorCodes has the base type UDINT, which makes the member eLastError another size than the runtime writes: the project's MB_ErrorCodes must have the base type USINT"
        ]
    );
    // A one-byte base keeps eLastError at its offset, as the runtime reads it.
    assert_eq!(
        status_findings("TYPE MB_ErrorCodes : (A, B) SINT; END_TYPE"),
        Vec::<String>::new()
    );
}

#[test]
fn a_project_s_own_status_type_must_keep_each_member_s_size() {
    let declaration = "TYPE MODBUS_DEVICE_STATUS :\nSTRUCT\n    xConnected : BOOL;\n    xError : BOOL;\n    eLastError : MB_ErrorCodes;\n    byLastException : BYTE;\n    udiConsecutiveErrors : UDINT;\n    udiRequests : UDINT;\n    udiErrors : UDINT;\n    udiRounds : UINT;\n    udiOverruns : UDINT;\n    ltLastResponseTime : LTIME;\nEND_STRUCT\nEND_TYPE";
    assert_eq!(
        status_findings(declaration),
        [
            "E0145 BeltDrive: Modbus device 'BeltDrive', status (GVL.stDrive): the project's MODBUS_DEVICE_STATUS declares the member udiRounds as UINT, which the runtime cannot write: declare it as UDINT"
        ]
    );
    assert_eq!(
        status_findings(&declaration.replace("udiRounds : UINT", "udiRounds : UDINT")),
        Vec::<String>::new()
    );
}

#[test]
fn w0015_finds_the_program_writing_a_read_channel_s_whole_variable() {
    assert_eq!(
        device_findings(
            vec![
                read("GVL.iOut", 0, ModbusDataType::Int16),
                // The program only reads iIn.
                read("GVL.iIn", 1, ModbusDataType::Int16),
            ],
            None,
        ),
        [
            "W0015 BeltDrive: Modbus device 'BeltDrive', channel 1 (GVL.iOut): the program also writes the variable 'GVL.iOut', but the next cycle's copy from the device overwrites what it wrote: write another variable, or make the channel a write channel",
        ]
    );
}

#[test]
fn w0016_finds_a_device_polled_faster_than_its_task_copies() {
    let mut fast = device("BeltDrive", Vec::new());
    fast.poll_interval_ms = Some(5);
    let mut every_cycle = device("Meter", Vec::new());
    every_cycle.poll_interval_ms = Some(1);
    every_cycle.schedule = ModbusSchedule::EveryCycle;
    assert_eq!(
        findings(&project(vec![fast, every_cycle]))
            .into_iter()
            .filter(|finding| !finding.starts_with("W000"))
            .collect::<Vec<_>>(),
        [
            "W0016 BeltDrive: Modbus device 'BeltDrive': polled every 5 ms, but its task 'MainTask' copies its values every 10 ms: set poll_interval_ms to 10 or more, or schedule = \"every_cycle\"",
        ]
    );
}

#[test]
fn the_device_editor_refuses_a_channel_s_variable_with_the_build_s_reason() {
    let source = format!(
        "FUNCTION_BLOCK FB_Base\nVAR_STAT\n    iShared : INT;\nEND_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION F_Twice : INT\nVAR_INPUT\n    iValue : INT;\nEND_VAR\nF_Twice := iValue * 2;\nEND_FUNCTION\n{}",
        SOURCE
            .replace("iUnused : INT;", "iUnused : INT;\n    fbX : FB_Base;")
            .replace(
                "wRaw : WORD;",
                "wRaw : WORD;\n    axBits AT %IX0.0 : ARRAY[0..7] OF BOOL;"
            )
    );
    let bindings = vec![
        read("Main.iScratch", 0, ModbusDataType::Int16),
        read("Main.fbX.iShared", 1, ModbusDataType::Int16),
        read("GVL.iLimit", 2, ModbusDataType::Int16),
        read("F_Twice.iValue", 3, ModbusDataType::Int16),
        ModbusBinding {
            count: 8,
            ..ModbusBinding::new("GVL.axBits", ModbusTable::Coil, 0, ModbusDataType::Bool)
        },
        read("GVL.rNothing", 4, ModbusDataType::Real),
    ];
    let project = project_from(&source, vec![device("BeltDrive", bindings.clone())]);
    let editor: Vec<Option<String>> = bindings
        .iter()
        .map(|binding| {
            crate::ide::check_channel_binding(&project, binding)
                .err()
                .map(|error| error.to_string())
        })
        .collect();
    // Each refusal is the build's finding about the channel, after its prefix; only a
    // variable that is not there is worded for the field (the build names the field).
    let mut build: Vec<Option<String>> = vec![None; bindings.len()];
    for finding in findings(&project) {
        for (row, binding) in bindings.iter().enumerate() {
            let prefix = format!(
                "BeltDrive: Modbus device 'BeltDrive', channel {} ({}): ",
                row + 1,
                binding.variable
            );
            if let Some((_, message)) = finding.split_once(&prefix) {
                build[row] = Some(message.to_owned());
            }
        }
    }
    assert_eq!(editor[..5], build[..5]);
    assert!(editor.iter().all(Option::is_some), "{editor:?}");
    assert_eq!(
        editor[3].as_deref(),
        Some(
            "the variable 'F_Twice.iValue' is a variable of a function, which has no place between calls: bind a global variable or a program's VAR, VAR_INPUT or VAR_OUTPUT"
        )
    );
    assert_eq!(
        editor[5].as_deref(),
        Some(
            "there is no variable 'GVL.rNothing': write the path of a global or program variable, such as GVL_IO.rSpeed"
        )
    );
}
