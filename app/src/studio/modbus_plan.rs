//! The requests of a Modbus device's round as the runtime will send them, for the device
//! editor's "N requests per round": the project's device turned into the image's `DeviceDef`
//! and planned with `program_image::modbus_master::plan`, the function the runtime's master
//! plans with (`docs/modbus-master.md` §6.2), so the count shown is the count sent.

use program_image::ModbusTable;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, OnError, Schedule, Trigger, WordOrder, plan,
};
use project_model::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDevice, ModbusLink,
    ModbusSchedule, Project, same_identifier,
};

/// How many requests a round of `device` sends, planned as the build will plan it.
pub(crate) fn round_requests(project: &Project, device: &ModbusDevice) -> usize {
    plan(&device_def(project, device)).len()
}

/// The image's definition of `device` with what planning needs: its channels, function codes,
/// triggers and read gap. The task index is the project's (0 when it names no task), and a
/// device without a poll interval is scheduled every cycle; neither changes the plan.
pub(crate) fn device_def(project: &Project, device: &ModbusDevice) -> DeviceDef {
    let link = match &device.link {
        ModbusLink::Tcp { host, port } => Link::Tcp {
            host: host.clone(),
            port: *port,
        },
        ModbusLink::Rtu { serial_port } => Link::Rtu {
            serial_port: position(
                project.serial_ports.iter().map(|port| port.name.as_str()),
                serial_port,
            ),
        },
    };
    let task = device.task.as_deref().map_or(0, |task| {
        position(project.tasks.iter().map(|t| t.name.as_str()), task)
    });
    let schedule = match (device.schedule, device.poll_interval_ms) {
        (ModbusSchedule::Interval, Some(interval_ms)) => Schedule::Interval { interval_ms },
        _ => Schedule::EveryCycle,
    };
    DeviceDef {
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
        status: device.status.clone(),
        channels: device.bindings.iter().map(channel_def).collect(),
    }
}

/// The image's definition of a channel, with the function code §2.2 gives it when the project
/// leaves it out.
fn channel_def(binding: &ModbusBinding) -> ChannelDef {
    let table = match binding.table {
        project_model::ModbusTable::Coil => ModbusTable::Coils,
        project_model::ModbusTable::DiscreteInput => ModbusTable::DiscreteInputs,
        project_model::ModbusTable::HoldingRegister => ModbusTable::HoldingRegisters,
        project_model::ModbusTable::InputRegister => ModbusTable::InputRegisters,
    };
    let direction = match binding.direction {
        ChannelDirection::Read => Direction::Read,
        ChannelDirection::Write => Direction::Write,
    };
    let trigger = match (binding.trigger, &binding.trigger_variable) {
        (ChannelTrigger::RisingEdge, Some(variable)) => Trigger::RisingEdge {
            variable: variable.clone(),
        },
        _ => Trigger::Cyclic,
    };
    ChannelDef {
        variable: binding.variable.clone(),
        table,
        address: binding.address,
        value_type: crate::modbus_devices::elementary_of(binding.data_type),
        count: binding.count,
        direction,
        function_code: binding
            .function_code
            .unwrap_or_else(|| binding.default_function_code()),
        trigger,
        on_error: match binding.on_error {
            ChannelErrorAction::KeepLastValue => OnError::KeepLastValue,
            ChannelErrorAction::SetToZero => OnError::SetToZero,
        },
        error_flag: binding.error_flag.clone(),
    }
}

/// The index of `name` among `names`, compared as IEC names; 0 when it is not there (the
/// device checks and the build report that, and the plan does not depend on it).
fn position<'a>(names: impl Iterator<Item = &'a str>, name: &str) -> u32 {
    names
        .enumerate()
        .find(|(_, other)| same_identifier(other, name))
        .and_then(|(index, _)| u32::try_from(index).ok())
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::{ModbusDataType, ModbusTable as Table, SerialPort};

    fn register(variable: &str, address: u16) -> ModbusBinding {
        ModbusBinding::new(
            variable,
            Table::HoldingRegister,
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
        assert_eq!(round_requests(&project, &drive), 2);
        drive.max_read_gap = 1;
        assert_eq!(round_requests(&project, &drive), 1);
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
        let def = device_def(&project, &drive);
        assert_eq!(def.channels[0].function_code, 3);
        assert_eq!(def.channels[1].function_code, 16);
        assert_eq!(def.channels[2].function_code, 6);
        assert_eq!(round_requests(&project, &drive), 3);
    }

    #[test]
    fn a_rising_edge_channel_is_sent_apart_from_the_cyclic_ones() {
        let project = Project::default();
        let mut edge = register("G.b", 1);
        edge.trigger = ChannelTrigger::RisingEdge;
        edge.trigger_variable = Some("G.xSend".into());
        let drive = device(vec![register("G.a", 0), edge]);
        assert_eq!(round_requests(&project, &drive), 2);
    }

    #[test]
    fn an_rtu_device_names_its_port_by_index_and_a_device_without_interval_runs_every_cycle() {
        let mut project = Project::default();
        project
            .serial_ports
            .push(SerialPort::new("RS232", "/dev/ttyS0"));
        project
            .serial_ports
            .push(SerialPort::new("RS485", "/dev/ttyS1"));
        let mut drive = device(Vec::new());
        drive.link = ModbusLink::Rtu {
            serial_port: "rs485".into(),
        };
        drive.poll_interval_ms = None;
        let def = device_def(&project, &drive);
        assert_eq!(def.link, Link::Rtu { serial_port: 1 });
        assert_eq!(def.schedule, Schedule::EveryCycle);
        assert_eq!(round_requests(&project, &drive), 0);
    }
}
