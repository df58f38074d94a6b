//! Section 14, the runtime Modbus master's devices (`docs/modbus-master.md` §5.1): every device
//! of the project that names an I/O task, with the serial ports such devices name, in manifest
//! order.
//!
//! The checker has refused every setting the runtime cannot use (`sema::modbus_master`), so
//! this is a translation, each device by `modbus_device_def`, the conversion the studio's
//! device editor counts requests with too.

use program_image::modbus_master::{MasterSection, Parity, SerialPortDef};
use project_model::{ModbusDevice, Project, SerialPort};

use super::body::Gen;
use super::error::fail;
use super::modbus_device_def::{canonical_path, device_def, runtime_serial_ports};
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
    let ports = runtime_serial_ports(project);
    let task_names: Vec<&str> = tasks.iter().map(|task| task.name.as_str()).collect();
    let path = |path: &str| canonical_path(project, globals, path);
    let mut section = MasterSection {
        serial_ports: ports.iter().map(|port| serial_port(port)).collect(),
        devices: Vec::with_capacity(devices.len()),
    };
    for device in devices {
        match device_def(device, &task_names, &ports, &path) {
            (def, None) => section.devices.push(def),
            (_, Some(unresolved)) => {
                return Err(fail!("Modbus device '{}': {unresolved}", device.name));
            }
        }
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

#[cfg(test)]
#[path = "modbus_master_tests.rs"]
mod tests;
