//! The content of nodes the user adds: empty objects and list entries with sensible settings.

use project_model::{
    Axis, AxisKind, AxisLimits, AxisScaling, CamTable, DataType, GlobalVarList, IoArea,
    IoDirection, ModbusDevice, Object, Pou, PouKind, Project, SerialPort, SoftwareLimits, Task,
    TaskKind, TraceConfig, TypeDefinition, WatchList,
};

use super::body_language::BodyLanguage;
use crate::studio::i18n::Text;

/// The kinds of application objects the tree can add without asking anything but a name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NewObject {
    /// A global variable list.
    Gvl,
    /// A structure data type.
    Structure,
    /// A watch list.
    WatchList,
    /// A trace of the first task.
    Trace,
    /// A cam table as CODESYS creates one (three Poly5 segments over 0 to 360).
    Cam,
}

impl NewObject {
    /// The default name a new object of this kind starts from.
    pub fn base_name(self) -> &'static str {
        match self {
            Self::Gvl => "GVL",
            Self::Structure => "DUT",
            Self::WatchList => "Watch",
            Self::Trace => "Trace",
            Self::Cam => "CAM",
        }
    }

    /// What the kind is called in undo labels.
    pub fn description(self) -> Text {
        match self {
            Self::Gvl => Text::NounGvl,
            Self::Structure => Text::NounDataType,
            Self::WatchList => Text::NounWatchList,
            Self::Trace => Text::TraceWord,
            Self::Cam => Text::NounCamTable,
        }
    }

    /// An empty object of this kind named `name`.
    pub fn build(self, project: &Project, name: String) -> Object {
        match self {
            Self::Gvl => Object::Gvl(GlobalVarList {
                name,
                ..GlobalVarList::default()
            }),
            Self::Structure => Object::DataType(DataType {
                name,
                comment: String::new(),
                definition: TypeDefinition::Struct {
                    extends: None,
                    members: Vec::new(),
                },
            }),
            Self::WatchList => Object::WatchList(WatchList {
                name,
                entries: Vec::new(),
            }),
            Self::Trace => Object::Trace(TraceConfig {
                name,
                task: first_task(project),
                every_n_cycles: 1,
                record_count: 1000,
                trigger: None,
                variables: Vec::new(),
            }),
            Self::Cam => Object::CamTable(CamTable::codesys_default(name)),
        }
    }
}

/// A POU with an empty body in `language`.
pub fn new_pou(
    name: String,
    kind: PouKind,
    return_type: Option<String>,
    language: BodyLanguage,
) -> Pou {
    Pou {
        name,
        kind,
        return_type: if kind == PouKind::Function {
            return_type
        } else {
            None
        },
        extends: None,
        implements: Vec::new(),
        comment: String::new(),
        variables: Vec::new(),
        body: language.empty_body(),
        methods: Vec::new(),
        properties: Vec::new(),
        actions: Vec::new(),
        transitions: Vec::new(),
    }
}

/// What a POU kind is called in menus and undo labels.
pub fn pou_kind_description(kind: PouKind) -> Text {
    match kind {
        PouKind::Program => Text::NounProgram,
        PouKind::FunctionBlock => Text::NounFunctionBlock,
        PouKind::Function => Text::NounFunction,
        PouKind::Interface => Text::NounInterface,
    }
}

/// A cyclic task of 10 ms without programs, as CODESYS adds one.
pub fn new_task(name: String) -> Task {
    Task {
        name,
        kind: TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority: 1,
        watchdog: None,
        programs: Vec::new(),
    }
}

/// Two bytes of inputs just after the last input area, so the new area overlaps nothing.
pub fn new_io_area(project: &Project, name: String) -> IoArea {
    let start_byte = project
        .io_areas
        .iter()
        .filter(|area| area.direction == IoDirection::Input)
        .map(|area| area.start_byte.saturating_add(area.size_bytes))
        .max()
        .unwrap_or(0);
    IoArea {
        name,
        direction: IoDirection::Input,
        start_byte,
        size_bytes: 2,
        comment: String::new(),
    }
}

/// A serial port on the first USB serial adapter with the Modbus serial line standard's
/// settings (19200 baud, 8 data bits, even parity, one stop bit).
pub fn new_serial_port(name: String) -> SerialPort {
    SerialPort::new(name, "/dev/ttyUSB0")
}

/// A Modbus TCP device on the standard port without bindings.
pub fn new_modbus_device(name: String) -> ModbusDevice {
    ModbusDevice::tcp(name, "192.168.1.10", 502)
}

/// A linear virtual axis in millimetres, updated by the first task.
pub fn new_axis(project: &Project, name: String) -> Axis {
    Axis {
        name,
        kind: AxisKind::Virtual,
        task: first_task(project),
        unit: "mm".to_owned(),
        modulo_period: None,
        software_limits: SoftwareLimits::default(),
        limits: AxisLimits {
            velocity: 1000.0,
            acceleration: 10_000.0,
            deceleration: 10_000.0,
            jerk: 100_000.0,
        },
        scaling: AxisScaling::default(),
    }
}

fn first_task(project: &Project) -> String {
    project
        .tasks
        .first()
        .map(|task| task.name.clone())
        .unwrap_or_default()
}
