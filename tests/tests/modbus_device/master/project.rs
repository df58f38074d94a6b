//! A project with runtime devices, built by the compiler (`docs/modbus-master.md` §3, §5) and
//! loaded by the runtime's scheduler: the paths the compiler writes are the ones the runtime
//! resolves, for every kind of variable a channel binds.

use std::sync::{Arc, Mutex};

use program_image::modbus_master::Link;
use project_model::{
    ChannelDirection, ModbusBinding, ModbusDataType, ModbusDevice, ModbusTable, Task, TaskKind,
};
use runtime::areas::LocatedAreas;
use runtime::scheduler::{Scheduler, SchedulerOptions};

use super::read_int;

/// Globals and a program with a variable of each kind a channel binds: a global, a program's
/// variable, a structure's member, an array from 1, a WORD, a located %MW word, and a status of
/// the Modbus library's type, which the project does not declare.
const SOURCE: &str = "
TYPE ST_Recipe :
STRUCT
    iSpeed : INT;
    rTemperature : REAL;
END_STRUCT
END_TYPE
VAR_GLOBAL
    iSetpoint : INT := 3;
    stRecipe : ST_Recipe;
    aiZones : ARRAY[1..4] OF INT;
    wRaw : WORD;
    wLocated AT %MW4 : WORD;
    stDrive : MODBUS_DEVICE_STATUS;
END_VAR
PROGRAM Main
VAR
    iOut : INT := 11;
END_VAR
iOut := iSetpoint + stRecipe.iSpeed + aiZones[1] + WORD_TO_INT(wRaw) + WORD_TO_INT(wLocated);
IF stDrive.xError THEN
    iOut := 0;
END_IF
END_PROGRAM
";

/// A channel of `count` `data_type` values at `address` of the holding registers.
fn channel(
    variable: &str,
    address: u16,
    data_type: ModbusDataType,
    count: u16,
    direction: ChannelDirection,
) -> ModbusBinding {
    ModbusBinding {
        count,
        direction,
        ..ModbusBinding::new(variable, ModbusTable::HoldingRegister, address, data_type)
    }
}

#[test]
fn a_compiled_project_with_devices_loads_into_the_scheduler() {
    use ChannelDirection::{Read, Write};
    let mut project = compiler::SourceProject::new(SOURCE).project;
    project.tasks = vec![Task {
        name: "MainTask".into(),
        kind: TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority: 1,
        watchdog: None,
        programs: vec!["Main".into()],
    }];
    project.modbus_devices = vec![ModbusDevice {
        task: Some("MainTask".into()),
        poll_interval_ms: Some(50),
        status: Some("stDrive".into()),
        bindings: vec![
            channel("iSetpoint", 0, ModbusDataType::Int16, 1, Read),
            channel("Main.iOut", 1, ModbusDataType::Int16, 1, Write),
            channel("GVL.stRecipe.iSpeed", 2, ModbusDataType::Int16, 1, Read),
            channel("GVL.aiZones", 3, ModbusDataType::Int16, 4, Read),
            channel("GVL.wRaw", 7, ModbusDataType::Uint16, 1, Read),
            channel("GVL.wLocated", 8, ModbusDataType::Uint16, 1, Read),
        ],
        // A port nothing listens on: the master, which polls from the load on, is refused
        // there; the test looks only at what the load resolved and never starts the program.
        ..ModbusDevice::tcp("Drive", "127.0.0.1", 1)
    }];
    let modbus_findings: Vec<String> = compiler::sema::check_project(&project)
        .into_iter()
        .filter(|finding| {
            let id = finding.diagnostic.code.id();
            ("E0140"..="E0145").contains(&id) || matches!(id, "W0015" | "W0016")
        })
        .map(|finding| finding.diagnostic.message)
        .collect();
    assert_eq!(modbus_findings, Vec::<String>::new());
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(error) => panic!("the project does not build: {error:?}"),
    };
    let section = image.modbus_master.clone().unwrap();
    assert!(matches!(section.devices[0].link, Link::Tcp { port: 1, .. }));
    assert_eq!(section.devices[0].status.as_deref(), Some("GVL.stDrive"));

    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    // The runtime resolves every path and the status type at load, refusing the image otherwise.
    if let Err(error) = scheduler.load(image) {
        panic!("the runtime refuses the compiled image: {error}");
    }
    assert_eq!(read_int(&scheduler, "Main.iOut"), 11);
    assert_eq!(read_int(&scheduler, "GVL.iSetpoint"), 3);
    assert_eq!(scheduler.modbus_devices().len(), 1);
}
