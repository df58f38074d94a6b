//! A Modbus device's round as the runtime will send it, for the device editor's "N requests per
//! round": the device converted exactly as the build converts it (`codegen::modbus_device_def`)
//! and planned with `program_image::modbus_master::plan`, the function the runtime's master
//! plans with (`docs/modbus-master.md` §6.2).

use program_image::modbus_master::{DeviceDef, plan};
use project_model::{ModbusDevice, Project};

use crate::codegen::modbus_device_def::{canonical_path, device_def, runtime_serial_ports};
use crate::sema::scope::Globals;

/// `device` as the build writes it into section 14, also while it is being edited: a task, a
/// serial port or a poll interval that the build would refuse is stood in for (index 0, every
/// cycle), since the plan does not depend on them; the build reports each of them (E0143).
pub fn modbus_device_def(project: &Project, device: &ModbusDevice) -> DeviceDef {
    let globals = Globals::new(project);
    let tasks: Vec<&str> = project
        .tasks
        .iter()
        .map(|task| task.name.as_str())
        .collect();
    let ports = runtime_serial_ports(project);
    let path = |path: &str| canonical_path(project, &globals, path);
    device_def(device, &tasks, &ports, &path).0
}

/// How many requests a round of `device` sends, planned as the runtime plans it.
pub fn modbus_round_requests(project: &Project, device: &ModbusDevice) -> usize {
    plan(&modbus_device_def(project, device)).len()
}

#[cfg(test)]
mod tests {
    use super::*;
    use program_image::modbus_master::{Link, Schedule};
    use project_model::{
        ChannelDirection, ChannelTrigger, ModbusBinding, ModbusDataType, ModbusLink, ModbusTable,
        SerialPort,
    };

    fn register(variable: &str, address: u16) -> ModbusBinding {
        ModbusBinding::new(
            variable,
            ModbusTable::HoldingRegister,
            address,
            ModbusDataType::Int16,
        )
    }

    fn device(bindings: Vec<ModbusBinding>) -> ModbusDevice {
        let mut device = ModbusDevice::tcp("Drive", "127.0.0.1", 502);
        device.task = Some("MainTask".into());
        device.bindings = bindings;
        device
    }

    #[test]
    fn adjacent_reads_share_a_request_and_a_gap_needs_the_read_gap() {
        let project = Project::default();
        let mut drive = device(vec![
            register("G.a", 0),
            register("G.b", 1),
            register("G.c", 3),
        ]);
        assert_eq!(modbus_round_requests(&project, &drive), 2);
        drive.max_read_gap = 1;
        assert_eq!(modbus_round_requests(&project, &drive), 1);
    }

    #[test]
    fn writes_and_single_writes_are_requests_of_their_own() {
        let project = Project::default();
        let mut write = register("G.out", 1);
        write.direction = ChannelDirection::Write;
        let mut single = register("G.one", 2);
        single.direction = ChannelDirection::Write;
        single.function_code = Some(6);
        let drive = device(vec![register("G.in", 0), write, single]);
        let def = modbus_device_def(&project, &drive);
        let codes: Vec<u8> = def.channels.iter().map(|c| c.function_code).collect();
        assert_eq!(codes, [3, 16, 6]);
        assert_eq!(modbus_round_requests(&project, &drive), 3);
    }

    #[test]
    fn a_rising_edge_channel_is_sent_apart_from_the_cyclic_ones() {
        let project = Project::default();
        let mut edge = register("G.b", 1);
        edge.trigger = ChannelTrigger::RisingEdge;
        edge.trigger_variable = Some("G.xSend".into());
        let drive = device(vec![register("G.a", 0), edge]);
        assert_eq!(modbus_round_requests(&project, &drive), 2);
    }

    #[test]
    fn what_the_build_would_refuse_is_stood_in_for_while_editing() {
        let mut project = Project::default();
        project
            .serial_ports
            .push(SerialPort::new("RS232", "/dev/ttyS0"));
        project
            .serial_ports
            .push(SerialPort::new("RS485", "/dev/ttyS1"));
        // Runtime devices on both ports put both into section 14, RS485 second.
        for (name, port) in [("Meter", "RS232"), ("Valve", "RS485")] {
            let mut other = device(vec![register("G.a", 0)]);
            other.name = name.into();
            other.link = ModbusLink::Rtu {
                serial_port: port.into(),
            };
            project.modbus_devices.push(other);
        }
        let mut drive = device(vec![register("G.a", 0)]);
        drive.link = ModbusLink::Rtu {
            serial_port: "rs485".into(),
        };
        assert_eq!(
            modbus_device_def(&project, &drive).link,
            Link::Rtu { serial_port: 1 }
        );
        // The device names a port and a task that do not exist, and has no interval: the
        // editor still gets a definition, and so a count.
        drive.link = ModbusLink::Rtu {
            serial_port: "Nowhere".into(),
        };
        drive.poll_interval_ms = None;
        let def = modbus_device_def(&project, &drive);
        assert_eq!(def.link, Link::Rtu { serial_port: 0 });
        assert_eq!(def.task, 0);
        assert_eq!(def.schedule, Schedule::EveryCycle);
        assert_eq!(modbus_round_requests(&project, &drive), 1);
    }
}
