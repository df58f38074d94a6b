//! A project's Modbus device as the image's `DeviceDef` (`docs/modbus-master.md` §5.1): the one
//! conversion that both the build's section 14 and the studio's "N requests per round"
//! (`ide::modbus_device_def`) use, so the count the editor shows is the count the runtime sends.
//!
//! Task and serial port names become indices, function codes are resolved from the table and
//! direction, data types become elementary tags, and variable paths are written as the runtime
//! finds them among the image's symbols. What does not resolve is returned beside a definition
//! that holds a stand-in for it: the build refuses it, the editor counts requests regardless,
//! since the plan depends on none of the stand-ins.

use std::fmt;

use program_image::Elementary as IE;
use program_image::ModbusTable as ImageTable;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, OnError, Schedule, Trigger, WordOrder,
};
use project_model::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDataType,
    ModbusDevice, ModbusLink, ModbusSchedule, ModbusTable, Project, SerialPort, same_identifier,
};

use crate::ide::variable_type::bound_path;
use crate::sema::scope::Globals;

/// A setting of a device that names nothing the image has; the definition holds 0 (an index)
/// or [`Schedule::EveryCycle`] in its place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Unresolved {
    /// The device's task is not among the image's tasks.
    Task(String),
    /// The device's serial port is not among the section's ports.
    SerialPort(String),
    /// The device is polled on an interval but has none.
    PollInterval,
}

impl fmt::Display for Unresolved {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Task(name) => write!(f, "there is no task named '{name}'"),
            Self::SerialPort(name) => write!(f, "there is no serial port named '{name}'"),
            Self::PollInterval => f.write_str("the poll interval is missing"),
        }
    }
}

/// The serial ports section 14 holds: those a runtime device of `project` names, in manifest
/// order. A device's `Link::Rtu` is its port's index among these.
pub(crate) fn runtime_serial_ports(project: &Project) -> Vec<&SerialPort> {
    project
        .serial_ports
        .iter()
        .filter(|port| {
            project.modbus_devices.iter().any(|device| {
                device.is_runtime_device()
                    && device
                        .serial_port()
                        .is_some_and(|name| same_identifier(name, &port.name))
            })
        })
        .collect()
}

/// A variable path as the runtime finds it among the image's symbols (`GVL.iIn` for an
/// unqualified `iIn`); a path that does not resolve is kept as written, trimmed, since the
/// checker has reported it.
pub(crate) fn canonical_path(project: &Project, globals: &Globals<'_>, path: &str) -> String {
    bound_path(project, globals, path)
        .map(|bound| bound.canonical)
        .unwrap_or_else(|_| path.trim().to_owned())
}

/// `device` as the image defines it, with `tasks` the image's task names in order, `ports` the
/// section's serial ports ([`runtime_serial_ports`]) and `path` writing variable paths; with
/// the first setting that does not resolve, if any.
pub(crate) fn device_def(
    device: &ModbusDevice,
    tasks: &[&str],
    ports: &[&SerialPort],
    path: &impl Fn(&str) -> String,
) -> (DeviceDef, Option<Unresolved>) {
    let mut unresolved = None;
    let task_name = device.task.as_deref().unwrap_or_default();
    let task = index_of(tasks.iter().copied(), task_name).unwrap_or_else(|| {
        unresolved.get_or_insert(Unresolved::Task(task_name.to_owned()));
        0
    });
    let link = match &device.link {
        ModbusLink::Tcp { host, port } => Link::Tcp {
            host: host.trim().to_owned(),
            port: *port,
        },
        ModbusLink::Rtu { serial_port } => Link::Rtu {
            serial_port: index_of(ports.iter().map(|port| port.name.as_str()), serial_port)
                .unwrap_or_else(|| {
                    unresolved.get_or_insert(Unresolved::SerialPort(serial_port.clone()));
                    0
                }),
        },
    };
    let schedule = match (device.schedule, device.poll_interval_ms) {
        (ModbusSchedule::EveryCycle, _) => Schedule::EveryCycle,
        (ModbusSchedule::Interval, Some(interval_ms)) => Schedule::Interval { interval_ms },
        (ModbusSchedule::Interval, None) => {
            unresolved.get_or_insert(Unresolved::PollInterval);
            Schedule::EveryCycle
        }
    };
    let def = DeviceDef {
        name: device.name.clone(),
        link,
        unit_id: device.unit_id,
        timeout_ms: device.timeout_ms,
        task,
        schedule,
        word_order: match device.word_order {
            project_model::WordOrder::HighFirst => WordOrder::HighFirst,
            project_model::WordOrder::LowFirst => WordOrder::LowFirst,
        },
        max_read_gap: device.max_read_gap,
        status: device.status.as_deref().map(path),
        channels: device
            .bindings
            .iter()
            .map(|binding| channel_def(binding, path))
            .collect(),
    };
    (def, unresolved)
}

/// The elementary type a value of `data_type` is held in by a program variable, by its tag.
pub fn value_type(data_type: ModbusDataType) -> IE {
    match data_type {
        ModbusDataType::Bool => IE::Bool,
        ModbusDataType::Int16 => IE::Int,
        ModbusDataType::Uint16 => IE::Uint,
        ModbusDataType::Int32 => IE::Dint,
        ModbusDataType::Uint32 => IE::Udint,
        ModbusDataType::Int64 => IE::Lint,
        ModbusDataType::Uint64 => IE::Ulint,
        ModbusDataType::Real => IE::Real,
        ModbusDataType::Lreal => IE::Lreal,
    }
}

/// A channel as the section holds it, its paths written by `path` and its function code the
/// default of §2.2 when the project names none.
fn channel_def(binding: &ModbusBinding, path: &impl Fn(&str) -> String) -> ChannelDef {
    ChannelDef {
        variable: path(&binding.variable),
        table: image_table(binding.table),
        address: binding.address,
        value_type: value_type(binding.data_type),
        count: binding.count,
        direction: match binding.direction {
            ChannelDirection::Read => Direction::Read,
            ChannelDirection::Write => Direction::Write,
        },
        function_code: binding
            .function_code
            .unwrap_or_else(|| binding.default_function_code()),
        trigger: match (binding.trigger, binding.trigger_variable.as_deref()) {
            (ChannelTrigger::RisingEdge, Some(variable)) => Trigger::RisingEdge {
                variable: path(variable),
            },
            // The checker and the model refuse an edge without its variable, so only Cyclic
            // is left.
            _ => Trigger::Cyclic,
        },
        on_error: match binding.on_error {
            ChannelErrorAction::KeepLastValue => OnError::KeepLastValue,
            ChannelErrorAction::SetToZero => OnError::SetToZero,
        },
        error_flag: binding.error_flag.as_deref().map(path),
    }
}

/// The image's table.
fn image_table(table: ModbusTable) -> ImageTable {
    match table {
        ModbusTable::Coil => ImageTable::Coils,
        ModbusTable::DiscreteInput => ImageTable::DiscreteInputs,
        ModbusTable::InputRegister => ImageTable::InputRegisters,
        ModbusTable::HoldingRegister => ImageTable::HoldingRegisters,
    }
}

/// The index of `name` among `names`, compared as IEC names.
fn index_of<'a>(names: impl Iterator<Item = &'a str>, name: &str) -> Option<u32> {
    names
        .enumerate()
        .find(|(_, other)| same_identifier(other, name))
        .and_then(|(index, _)| u32::try_from(index).ok())
}
