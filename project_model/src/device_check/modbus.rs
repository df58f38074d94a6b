//! Checks of a Modbus device: its name, link, timing, master settings and channel table.

use super::{DeviceProblem, name_problems, others};
use crate::{
    ChannelDirection, ChannelErrorAction, ChannelTrigger, ModbusBinding, ModbusDevice, ModbusLink,
    ModbusTable, Project, is_valid_identifier, same_identifier,
};

/// The longest response timeout, in milliseconds.
pub const MAX_TIMEOUT_MS: u32 = 60_000;

/// The longest poll interval, in milliseconds (one hour).
pub const MAX_POLL_INTERVAL_MS: u32 = 3_600_000;

/// The most unused addresses a read request may bridge.
pub const MAX_READ_GAP: u16 = 125;

/// Every problem of `device` as the Modbus device at `index` of the project's devices (`None`
/// for a new one): its name, link, poll interval, timeout, master settings and channels.
/// Whether a channel's variable exists and its type fits, and whether its task exists, is the
/// compiler's to say (`compiler::ide`).
pub fn modbus_device_problems(
    project: &Project,
    index: Option<usize>,
    device: &ModbusDevice,
) -> Vec<DeviceProblem> {
    let mut problems = name_problems(
        "Modbus device",
        &device.name,
        others(&project.modbus_devices, index).map(|(_, other)| other.name.as_str()),
    );
    match &device.link {
        ModbusLink::Tcp { host, port } => {
            if host.trim().is_empty() {
                problems.push(DeviceProblem::EmptyHost);
            }
            if *port == 0 {
                problems.push(DeviceProblem::ZeroPort);
            }
        }
        ModbusLink::Rtu { serial_port } => {
            if serial_port.trim().is_empty() {
                problems.push(DeviceProblem::EmptySerialPort);
            } else if !project
                .serial_ports
                .iter()
                .any(|port| same_identifier(&port.name, serial_port))
            {
                problems.push(DeviceProblem::NoSuchSerialPort(serial_port.clone()));
            }
            if device.task.is_none() {
                problems.push(DeviceProblem::RtuWithoutTask);
            }
            if !(1..=247).contains(&device.unit_id) {
                problems.push(DeviceProblem::RtuUnitId(device.unit_id));
            }
        }
    }
    match device.poll_interval_ms {
        Some(0) => problems.push(DeviceProblem::ZeroPollInterval),
        Some(interval) if interval > MAX_POLL_INTERVAL_MS => {
            problems.push(DeviceProblem::PollIntervalTooLong(interval));
        }
        Some(_) => {}
        None if device.needs_poll_interval() => {
            problems.push(DeviceProblem::MissingPollInterval);
        }
        None => {}
    }
    if device.timeout_ms == 0 {
        problems.push(DeviceProblem::ZeroTimeout);
    } else if device.timeout_ms > MAX_TIMEOUT_MS {
        problems.push(DeviceProblem::TimeoutTooLong(device.timeout_ms));
    }
    if device.max_read_gap > MAX_READ_GAP {
        problems.push(DeviceProblem::ReadGapTooLarge(device.max_read_gap));
    }
    problems.extend(binding_problems(&device.bindings));
    problems
}

/// Every problem of a device's channels: a missing or malformed variable path, a data type its
/// table cannot hold, a count of 0 or beyond one request, a channel past address 65535, two
/// channels of one table sharing an address (the later one names the earlier), a write to a
/// read-only table, a function code that does not fit, a trigger without its variable or the
/// other way round, and `on_error` on a write channel.
pub fn binding_problems(bindings: &[ModbusBinding]) -> Vec<DeviceProblem> {
    let mut problems = Vec::new();
    for (index, binding) in bindings.iter().enumerate() {
        let row = index + 1;
        let variable = binding.variable.trim();
        if variable.is_empty() {
            problems.push(DeviceProblem::EmptyVariable { row });
        } else if !variable.split('.').all(is_valid_identifier) {
            problems.push(DeviceProblem::InvalidVariable {
                row,
                variable: variable.to_owned(),
            });
        }
        if binding.table.holds_bits() != (binding.data_type == crate::ModbusDataType::Bool) {
            problems.push(DeviceProblem::TableTypeMismatch {
                row,
                table: binding.table,
                data_type: binding.data_type,
            });
        }
        problems.extend(size_problems(row, binding));
        let end = u32::from(binding.address) + binding.span();
        let overlapping = bindings[..index].iter().position(|other| {
            other.table == binding.table
                && u32::from(other.address) < end
                && u32::from(binding.address) < u32::from(other.address) + other.span()
        });
        if let Some(other) = overlapping {
            problems.push(DeviceProblem::ChannelsOverlap {
                row,
                variable: binding.variable.clone(),
                other: other + 1,
                other_variable: bindings[other].variable.clone(),
            });
        }
        problems.extend(master_problems(row, binding));
    }
    problems
}

/// The most coils (or discrete inputs) and registers one request reads or writes: the Modbus
/// limits of function codes 1 to 4, and of 15 and 16.
pub fn request_limit(table: ModbusTable, direction: ChannelDirection) -> u32 {
    match (table.holds_bits(), direction) {
        (true, ChannelDirection::Read) => 2000,
        (true, ChannelDirection::Write) => 1968,
        (false, ChannelDirection::Read) => 125,
        (false, ChannelDirection::Write) => 123,
    }
}

/// A channel's count of 0, its size beyond one request, or its end past address 65535.
fn size_problems(row: usize, binding: &ModbusBinding) -> Vec<DeviceProblem> {
    let mut problems = Vec::new();
    if binding.count == 0 {
        problems.push(DeviceProblem::ZeroCount { row });
        return problems;
    }
    let span = binding.span();
    let limit = request_limit(binding.table, binding.direction);
    if span > limit {
        problems.push(DeviceProblem::ChannelTooLong {
            row,
            count: binding.count,
            span,
            limit,
        });
    }
    if u32::from(binding.address) + span > 65536 {
        problems.push(DeviceProblem::ChannelPastEnd {
            row,
            address: binding.address,
            width: span,
        });
    }
    problems
}

/// The problems of a channel's master settings: direction, function code, trigger, `on_error`.
fn master_problems(row: usize, binding: &ModbusBinding) -> Vec<DeviceProblem> {
    let mut problems = Vec::new();
    let writes = binding.direction == ChannelDirection::Write;
    let writable = matches!(
        binding.table,
        ModbusTable::Coil | ModbusTable::HoldingRegister
    );
    if writes && !writable {
        problems.push(DeviceProblem::WriteToReadOnlyTable {
            row,
            table: binding.table,
        });
    }
    if let Some(code) = binding.function_code {
        let (single, multiple) = match binding.table {
            ModbusTable::Coil => (5, 15),
            _ => (6, 16),
        };
        if !writes {
            problems.push(DeviceProblem::FunctionCodeOnRead { row, code });
        } else if writable && code != single && code != multiple {
            problems.push(DeviceProblem::FunctionCodeMisfit {
                row,
                code,
                table: binding.table,
            });
        } else if writable && code == single && binding.span() > 1 {
            problems.push(DeviceProblem::SingleWriteTooWide {
                row,
                code,
                span: binding.span(),
            });
        }
    }
    match (binding.trigger, &binding.trigger_variable) {
        (ChannelTrigger::Cyclic, Some(_)) => {
            problems.push(DeviceProblem::TriggerVariableWithoutEdge { row });
        }
        (ChannelTrigger::RisingEdge, None) => {
            problems.push(DeviceProblem::EdgeWithoutTriggerVariable { row });
        }
        _ => {}
    }
    if writes && binding.on_error != ChannelErrorAction::KeepLastValue {
        problems.push(DeviceProblem::OnErrorOnWrite { row });
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ModbusDataType, ModbusSchedule, SerialPort, WordOrder};

    fn binding(
        variable: &str,
        table: ModbusTable,
        address: u16,
        data_type: ModbusDataType,
    ) -> ModbusBinding {
        ModbusBinding::new(variable, table, address, data_type)
    }

    fn drive() -> ModbusDevice {
        ModbusDevice {
            name: "BeltDrive".into(),
            link: ModbusLink::Tcp {
                host: "192.168.1.50".into(),
                port: 502,
            },
            unit_id: 1,
            word_order: WordOrder::HighFirst,
            poll_interval_ms: Some(100),
            timeout_ms: 500,
            task: None,
            schedule: ModbusSchedule::Interval,
            max_read_gap: 0,
            status: None,
            bindings: vec![
                binding(
                    "GVL.rSpeed",
                    ModbusTable::InputRegister,
                    0,
                    ModbusDataType::Real,
                ),
                binding(
                    "GVL.xReady",
                    ModbusTable::DiscreteInput,
                    0,
                    ModbusDataType::Bool,
                ),
            ],
        }
    }

    /// A project with one serial port `RS485` and `devices`.
    fn project(devices: Vec<ModbusDevice>) -> Project {
        Project {
            serial_ports: vec![SerialPort::new("RS485", "/dev/ttyUSB0")],
            modbus_devices: devices,
            ..Project::default()
        }
    }

    /// The problems of `device` as a new device of a project without devices.
    fn problems(device: &ModbusDevice) -> Vec<DeviceProblem> {
        modbus_device_problems(&project(Vec::new()), None, device)
    }

    /// An RTU device on `RS485` polled every cycle of `MainTask`.
    fn rtu() -> ModbusDevice {
        ModbusDevice {
            link: ModbusLink::Rtu {
                serial_port: "rs485".into(),
            },
            poll_interval_ms: None,
            task: Some("MainTask".into()),
            schedule: ModbusSchedule::EveryCycle,
            ..drive()
        }
    }

    #[test]
    fn a_device_needs_a_host_a_port_and_some_time_to_poll_and_wait() {
        let mut device = drive();
        assert!(problems(&device).is_empty());
        device.link = ModbusLink::Tcp {
            host: " ".into(),
            port: 0,
        };
        device.poll_interval_ms = Some(0);
        device.timeout_ms = 0;
        assert_eq!(
            problems(&device),
            [
                DeviceProblem::EmptyHost,
                DeviceProblem::ZeroPort,
                DeviceProblem::ZeroPollInterval,
                DeviceProblem::ZeroTimeout
            ]
        );
    }

    #[test]
    fn timing_and_the_read_gap_have_upper_limits() {
        let mut device = drive();
        device.poll_interval_ms = Some(MAX_POLL_INTERVAL_MS);
        device.timeout_ms = MAX_TIMEOUT_MS;
        device.max_read_gap = MAX_READ_GAP;
        assert!(problems(&device).is_empty());
        device.poll_interval_ms = Some(3_600_001);
        device.timeout_ms = 60_001;
        device.max_read_gap = 126;
        assert_eq!(
            problems(&device),
            [
                DeviceProblem::PollIntervalTooLong(3_600_001),
                DeviceProblem::TimeoutTooLong(60_001),
                DeviceProblem::ReadGapTooLarge(126),
            ]
        );
        assert_eq!(
            DeviceProblem::TimeoutTooLong(60_001).to_string(),
            "the timeout is 60001 ms; it is at most 60000 ms"
        );
    }

    #[test]
    fn only_an_rtu_device_polled_every_cycle_may_leave_the_poll_interval_out() {
        let mut device = rtu();
        assert!(problems(&device).is_empty(), "{:?}", problems(&device));
        device.schedule = ModbusSchedule::Interval;
        assert_eq!(problems(&device), [DeviceProblem::MissingPollInterval]);
        let mut tcp = drive();
        tcp.poll_interval_ms = None;
        tcp.task = Some("MainTask".into());
        tcp.schedule = ModbusSchedule::EveryCycle;
        assert_eq!(problems(&tcp), [DeviceProblem::MissingPollInterval]);
    }

    #[test]
    fn an_rtu_device_needs_a_known_port_a_task_and_a_unit_of_the_serial_line() {
        let mut device = rtu();
        device.task = None;
        device.unit_id = 0;
        assert_eq!(
            problems(&device),
            [DeviceProblem::RtuWithoutTask, DeviceProblem::RtuUnitId(0)]
        );
        device.task = Some("MainTask".into());
        device.unit_id = 248;
        device.link = ModbusLink::Rtu {
            serial_port: "RS232".into(),
        };
        assert_eq!(
            problems(&device),
            [
                DeviceProblem::NoSuchSerialPort("RS232".into()),
                DeviceProblem::RtuUnitId(248)
            ]
        );
        device.link = ModbusLink::Rtu {
            serial_port: String::new(),
        };
        device.unit_id = 247;
        assert_eq!(problems(&device), [DeviceProblem::EmptySerialPort]);
        // A TCP device may use every unit id: gateways route by it.
        let mut tcp = drive();
        tcp.unit_id = 255;
        assert!(problems(&tcp).is_empty());
    }

    #[test]
    fn a_second_device_of_the_same_name_is_refused() {
        let project = project(vec![drive()]);
        let device = &project.modbus_devices[0];
        assert!(modbus_device_problems(&project, Some(0), device).is_empty());
        assert!(matches!(
            modbus_device_problems(&project, None, device)[..],
            [DeviceProblem::DuplicateName { .. }]
        ));
    }

    #[test]
    fn a_channel_overlapping_another_of_its_table_names_both() {
        let mut bindings = drive().bindings;
        bindings.push(binding(
            "GVL.iTorque",
            ModbusTable::InputRegister,
            1,
            ModbusDataType::Int16,
        ));
        bindings.push(binding(
            "GVL.iOther",
            ModbusTable::HoldingRegister,
            1,
            ModbusDataType::Int16,
        ));
        let problems = binding_problems(&bindings);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert_eq!(
            problems[0].to_string(),
            "channel 3 (GVL.iTorque) overlaps channel 1 (GVL.rSpeed) in the same table"
        );
    }

    #[test]
    fn an_array_channel_overlaps_by_its_whole_count_whatever_the_directions() {
        let mut temperatures = binding(
            "GVL.aiTemp",
            ModbusTable::HoldingRegister,
            0,
            ModbusDataType::Int16,
        );
        temperatures.count = 8;
        let mut setpoint = binding(
            "GVL.iSet",
            ModbusTable::HoldingRegister,
            7,
            ModbusDataType::Int16,
        );
        setpoint.direction = ChannelDirection::Write;
        assert!(matches!(
            binding_problems(&[temperatures.clone(), setpoint.clone()])[..],
            [DeviceProblem::ChannelsOverlap {
                row: 2,
                other: 1,
                ..
            }]
        ));
        setpoint.address = 8;
        assert!(binding_problems(&[temperatures, setpoint]).is_empty());
    }

    #[test]
    fn a_channel_past_65535_a_bad_path_and_a_misfit_type_are_refused() {
        let bindings = [
            binding(
                "GVL.lrBig",
                ModbusTable::HoldingRegister,
                65533,
                ModbusDataType::Lreal,
            ),
            binding("", ModbusTable::Coil, 0, ModbusDataType::Bool),
            binding("GVL.x y", ModbusTable::Coil, 1, ModbusDataType::Int16),
        ];
        assert_eq!(
            binding_problems(&bindings),
            [
                DeviceProblem::ChannelPastEnd {
                    row: 1,
                    address: 65533,
                    width: 4
                },
                DeviceProblem::EmptyVariable { row: 2 },
                DeviceProblem::InvalidVariable {
                    row: 3,
                    variable: "GVL.x y".into()
                },
                DeviceProblem::TableTypeMismatch {
                    row: 3,
                    table: ModbusTable::Coil,
                    data_type: ModbusDataType::Int16
                },
            ]
        );
        let last = [binding(
            "GVL.lrBig",
            ModbusTable::HoldingRegister,
            65532,
            ModbusDataType::Lreal,
        )];
        assert!(binding_problems(&last).is_empty());
    }

    #[test]
    fn a_count_is_at_least_one_and_fits_one_request_of_its_direction() {
        let mut reals = binding(
            "GVL.arValues",
            ModbusTable::HoldingRegister,
            0,
            ModbusDataType::Real,
        );
        reals.count = 0;
        assert_eq!(
            binding_problems(std::slice::from_ref(&reals)),
            [DeviceProblem::ZeroCount { row: 1 }]
        );
        // 62 REALs are 124 registers: one read carries 125, one write 123.
        reals.count = 62;
        assert!(binding_problems(std::slice::from_ref(&reals)).is_empty());
        reals.direction = ChannelDirection::Write;
        let too_long = DeviceProblem::ChannelTooLong {
            row: 1,
            count: 62,
            span: 124,
            limit: 123,
        };
        assert_eq!(
            binding_problems(std::slice::from_ref(&reals)),
            std::slice::from_ref(&too_long)
        );
        assert_eq!(
            too_long.to_string(),
            "channel 1: 62 values take 124 coils or registers, more than one request carries (123)"
        );
        let mut coils = binding("GVL.axOut", ModbusTable::Coil, 0, ModbusDataType::Bool);
        coils.count = 2000;
        assert!(binding_problems(std::slice::from_ref(&coils)).is_empty());
        coils.count = 2001;
        assert!(matches!(
            binding_problems(&[coils])[..],
            [DeviceProblem::ChannelTooLong { limit: 2000, .. }]
        ));
    }

    #[test]
    fn only_coils_and_holding_registers_are_written_with_their_own_function_codes() {
        let write = |table, data_type, code: Option<u8>, count| {
            let mut channel = binding("GVL.x", table, 0, data_type);
            channel.direction = ChannelDirection::Write;
            channel.function_code = code;
            channel.count = count;
            binding_problems(&[channel])
        };
        let coil = (ModbusTable::Coil, ModbusDataType::Bool);
        let register = (ModbusTable::HoldingRegister, ModbusDataType::Int16);
        for (table, data_type, code) in [
            (coil.0, coil.1, None),
            (coil.0, coil.1, Some(5)),
            (coil.0, coil.1, Some(15)),
            (register.0, register.1, Some(6)),
            (register.0, register.1, Some(16)),
        ] {
            assert!(write(table, data_type, code, 1).is_empty(), "{code:?}");
        }
        assert_eq!(
            write(ModbusTable::InputRegister, ModbusDataType::Int16, None, 1),
            [DeviceProblem::WriteToReadOnlyTable {
                row: 1,
                table: ModbusTable::InputRegister
            }]
        );
        assert_eq!(
            write(coil.0, coil.1, Some(6), 1),
            [DeviceProblem::FunctionCodeMisfit {
                row: 1,
                code: 6,
                table: ModbusTable::Coil
            }]
        );
        assert_eq!(
            write(register.0, register.1, Some(6), 2),
            [DeviceProblem::SingleWriteTooWide {
                row: 1,
                code: 6,
                span: 2
            }]
        );
        assert_eq!(
            write(register.0, ModbusDataType::Real, Some(6), 1),
            [DeviceProblem::SingleWriteTooWide {
                row: 1,
                code: 6,
                span: 2
            }]
        );
        let mut read = binding("GVL.x", register.0, 0, register.1);
        read.function_code = Some(3);
        assert_eq!(
            binding_problems(&[read]),
            [DeviceProblem::FunctionCodeOnRead { row: 1, code: 3 }]
        );
    }

    #[test]
    fn a_rising_edge_needs_its_trigger_variable_and_only_it_has_one() {
        let mut channel = binding("GVL.x", ModbusTable::Coil, 0, ModbusDataType::Bool);
        channel.trigger_variable = Some("GVL.xSend".into());
        assert_eq!(
            binding_problems(std::slice::from_ref(&channel)),
            [DeviceProblem::TriggerVariableWithoutEdge { row: 1 }]
        );
        channel.trigger = ChannelTrigger::RisingEdge;
        assert!(binding_problems(std::slice::from_ref(&channel)).is_empty());
        channel.trigger_variable = None;
        assert_eq!(
            binding_problems(&[channel]),
            [DeviceProblem::EdgeWithoutTriggerVariable { row: 1 }]
        );
    }

    #[test]
    fn only_a_read_channel_chooses_what_its_variable_holds_after_an_error() {
        let mut channel = binding("GVL.x", ModbusTable::Coil, 0, ModbusDataType::Bool);
        channel.on_error = ChannelErrorAction::SetToZero;
        assert!(binding_problems(std::slice::from_ref(&channel)).is_empty());
        channel.direction = ChannelDirection::Write;
        assert_eq!(
            binding_problems(&[channel]),
            [DeviceProblem::OnErrorOnWrite { row: 1 }]
        );
    }
}
