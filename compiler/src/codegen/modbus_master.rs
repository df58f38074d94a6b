//! Section 14, the runtime Modbus master's devices (`docs/modbus-master.md` §5.1): every device
//! of the project that names an I/O task, with the serial ports such devices name, in manifest
//! order.
//!
//! The checker has refused every setting the runtime cannot use (`sema::modbus_master`), so
//! this is a translation: task and serial port names become indices, function codes are
//! resolved from the table and direction, data types become elementary tags, and variable paths
//! are written as the runtime finds them among the image's symbols.

use program_image::Elementary as IE;
use program_image::ModbusTable as ImageTable;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, MasterSection, OnError, Parity, Schedule,
    SerialPortDef, Trigger, WordOrder,
};
use project_model::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDataType,
    ModbusDevice, ModbusLink, ModbusSchedule, ModbusTable, Project, SerialPort, same_identifier,
};

use super::body::Gen;
use super::error::fail;
use crate::ide::variable_type::bound_path;
use crate::sema::scope::Globals;

/// The section of `project`'s runtime devices, whose tasks are `tasks` (the image's task table,
/// by name); `None` when no device names an I/O task.
pub(super) fn master_section(
    project: &Project,
    globals: &Globals<'_>,
    tasks: &[program_image::Task],
) -> Gen<Option<MasterSection>> {
    let devices: Vec<&ModbusDevice> = project
        .modbus_devices
        .iter()
        .filter(|device| device.is_runtime_device())
        .collect();
    if devices.is_empty() {
        return Ok(None);
    }
    // The ports the runtime devices name, in manifest order.
    let ports: Vec<&SerialPort> = project
        .serial_ports
        .iter()
        .filter(|port| {
            devices.iter().any(|device| {
                device
                    .serial_port()
                    .is_some_and(|name| same_identifier(name, &port.name))
            })
        })
        .collect();
    let path = |path: &str| {
        bound_path(project, globals, path)
            .map(|bound| bound.canonical)
            .unwrap_or_else(|_| path.trim().to_owned())
    };
    let mut section = MasterSection {
        serial_ports: ports.iter().map(|port| serial_port(port)).collect(),
        devices: Vec::with_capacity(devices.len()),
    };
    for device in devices {
        let place = format!("Modbus device '{}'", device.name);
        let task_name = device.task.as_deref().unwrap_or_default();
        let task = tasks
            .iter()
            .position(|task| same_identifier(&task.name, task_name))
            .ok_or_else(|| fail!("{place}: there is no task named '{task_name}'"))?;
        let link = match &device.link {
            ModbusLink::Tcp { host, port } => Link::Tcp {
                host: host.trim().to_owned(),
                port: *port,
            },
            ModbusLink::Rtu { serial_port } => Link::Rtu {
                serial_port: ports
                    .iter()
                    .position(|port| same_identifier(&port.name, serial_port))
                    .ok_or_else(|| {
                        fail!("{place}: there is no serial port named '{serial_port}'")
                    })? as u32,
            },
        };
        let schedule = match (device.schedule, device.poll_interval_ms) {
            (ModbusSchedule::EveryCycle, _) => Schedule::EveryCycle,
            (ModbusSchedule::Interval, Some(interval_ms)) => Schedule::Interval { interval_ms },
            (ModbusSchedule::Interval, None) => {
                return Err(fail!("{place}: the poll interval is missing"));
            }
        };
        section.devices.push(DeviceDef {
            name: device.name.clone(),
            link,
            unit_id: device.unit_id,
            timeout_ms: device.timeout_ms,
            task: task as u32,
            schedule,
            word_order: match device.word_order {
                project_model::WordOrder::HighFirst => WordOrder::HighFirst,
                project_model::WordOrder::LowFirst => WordOrder::LowFirst,
            },
            max_read_gap: device.max_read_gap,
            status: device.status.as_deref().map(&path),
            channels: device
                .bindings
                .iter()
                .map(|binding| channel(binding, &path))
                .collect(),
        });
    }
    Ok(Some(section))
}

/// A serial port as the section holds it.
fn serial_port(port: &SerialPort) -> SerialPortDef {
    SerialPortDef {
        name: port.name.clone(),
        device: port.device.trim().to_owned(),
        baud_rate: port.baud_rate,
        parity: match port.parity {
            project_model::Parity::None => Parity::None,
            project_model::Parity::Odd => Parity::Odd,
            project_model::Parity::Even => Parity::Even,
        },
        data_bits: port.data_bits,
        stop_bits: port.stop_bits,
        inter_frame_delay_us: port.inter_frame_delay_us,
    }
}

/// A channel as the section holds it, its paths written by `path`.
fn channel(binding: &ModbusBinding, path: &impl Fn(&str) -> String) -> ChannelDef {
    let direction = match binding.direction {
        ChannelDirection::Read => Direction::Read,
        ChannelDirection::Write => Direction::Write,
    };
    ChannelDef {
        variable: path(&binding.variable),
        table: image_table(binding.table),
        address: binding.address,
        value_type: value_type(binding.data_type),
        count: binding.count,
        direction,
        function_code: binding
            .function_code
            .unwrap_or_else(|| default_function_code(binding.table, binding.direction)),
        trigger: match (binding.trigger, binding.trigger_variable.as_deref()) {
            (ChannelTrigger::RisingEdge, Some(variable)) => Trigger::RisingEdge {
                variable: path(variable),
            },
            // The checker refuses an edge without its variable, so only Cyclic is left.
            _ => Trigger::Cyclic,
        },
        on_error: match binding.on_error {
            ChannelErrorAction::KeepLastValue => OnError::KeepLastValue,
            ChannelErrorAction::SetToZero => OnError::SetToZero,
        },
        error_flag: binding.error_flag.as_deref().map(path),
    }
}

/// The function code of a channel that names none: 1, 2, 3 or 4 to read its table, 15 or 16 to
/// write it (`docs/modbus-master.md` §2.2).
fn default_function_code(table: ModbusTable, direction: ChannelDirection) -> u8 {
    match (direction, table) {
        (ChannelDirection::Read, ModbusTable::Coil) => 1,
        (ChannelDirection::Read, ModbusTable::DiscreteInput) => 2,
        (ChannelDirection::Read, ModbusTable::HoldingRegister) => 3,
        (ChannelDirection::Read, ModbusTable::InputRegister) => 4,
        (ChannelDirection::Write, ModbusTable::Coil | ModbusTable::DiscreteInput) => 15,
        (ChannelDirection::Write, _) => 16,
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

/// The elementary type a value of `data_type` is, by its tag.
fn value_type(data_type: ModbusDataType) -> IE {
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

#[cfg(test)]
#[path = "modbus_master_tests.rs"]
mod tests;
