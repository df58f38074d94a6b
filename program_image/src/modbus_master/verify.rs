//! The structural checks of `docs/modbus-master.md` §5.2 that need no symbol: indices, counts,
//! ranges, function codes against table and direction, one-request limits and overlaps; and of
//! §2.4, a write channel's `on_error` and a rising edge's path. The runtime resolves the paths
//! and checks the variables' types at load itself.

use crate::{Elementary, ModbusTable};

use super::{
    BAUD_RATES, ChannelDef, DeviceDef, Direction, Link, MAX_CHANNELS_PER_DEVICE, MAX_DEVICES,
    MAX_INTER_FRAME_DELAY_US, MAX_INTERVAL_MS, MAX_READ_GAP, MAX_SERIAL_PORTS, MAX_TIMEOUT_MS,
    MasterPlace, MasterProblem, MasterSection, MasterSectionError, OnError, Schedule,
    SerialPortDef, Trigger, request_limit, table_holds_bits,
};

/// The register types a channel may have: the elementary tags of `docs/modbus-master.md` §2.2's
/// data types other than `bool`.
const REGISTER_TYPES: [Elementary; 8] = [
    Elementary::Int,
    Elementary::Uint,
    Elementary::Dint,
    Elementary::Udint,
    Elementary::Lint,
    Elementary::Ulint,
    Elementary::Real,
    Elementary::Lreal,
];

impl MasterSection {
    /// Checks the section against an image of `task_count` tasks; the first problem found is
    /// returned, naming the serial port, device or channel and the field.
    pub fn verify(&self, task_count: usize) -> Result<(), MasterSectionError> {
        let section = |field, count, max| {
            if count > max {
                Err(MasterSectionError {
                    place: MasterPlace::Section,
                    field,
                    problem: MasterProblem::TooMany { count, max },
                })
            } else {
                Ok(())
            }
        };
        section("serial_ports", self.serial_ports.len(), MAX_SERIAL_PORTS)?;
        section("devices", self.devices.len(), MAX_DEVICES)?;
        for (index, port) in self.serial_ports.iter().enumerate() {
            let earlier = self.serial_ports[..index]
                .iter()
                .position(|other| other.name.eq_ignore_ascii_case(&port.name));
            let fail = |field, problem| {
                Err(MasterSectionError {
                    place: MasterPlace::SerialPort {
                        index,
                        name: port.name.clone(),
                    },
                    field,
                    problem,
                })
            };
            if let Some(other) = earlier {
                // `--serial-port NAME=PATH` picks a port by its name.
                return fail(
                    "name",
                    MasterProblem::NameTaken {
                        name: port.name.clone(),
                        other: format!("serial port {other}"),
                    },
                );
            }
            if let Some((field, problem)) = port_problem(port) {
                return fail(field, problem);
            }
        }
        for (index, device) in self.devices.iter().enumerate() {
            let place = MasterPlace::Device {
                name: device.name.clone(),
            };
            let fail = |field, problem| {
                Err(MasterSectionError {
                    place: place.clone(),
                    field,
                    problem,
                })
            };
            if let Some(other) = self.devices[..index]
                .iter()
                .position(|other| other.name.eq_ignore_ascii_case(&device.name))
            {
                // Messages and `MODBUS_DEVICES` tell devices apart by name only; the earlier
                // device is named as spelt, which may differ in case.
                return fail(
                    "name",
                    MasterProblem::NameTaken {
                        name: device.name.clone(),
                        other: format!("device {other} ('{}')", self.devices[other].name),
                    },
                );
            }
            if let Some((field, problem)) = self.device_problem(device, task_count) {
                return fail(field, problem);
            }
            let channel_fail = |channel: usize, field, problem| {
                Err(MasterSectionError {
                    place: MasterPlace::Channel {
                        device: device.name.clone(),
                        number: channel + 1,
                        variable: device.channels[channel].variable.clone(),
                    },
                    field,
                    problem,
                })
            };
            for (number, channel) in device.channels.iter().enumerate() {
                if let Some((field, problem)) = channel_problem(channel) {
                    return channel_fail(number, field, problem);
                }
            }
            if let Some((later, earlier)) = overlap(&device.channels) {
                return channel_fail(
                    later,
                    "address",
                    MasterProblem::Overlap {
                        other: earlier + 1,
                        other_variable: device.channels[earlier].variable.clone(),
                    },
                );
            }
        }
        Ok(())
    }

    /// The first problem of `device`'s own fields, not its channels'.
    fn device_problem(
        &self,
        device: &DeviceDef,
        task_count: usize,
    ) -> Option<(&'static str, MasterProblem)> {
        if device.name.trim().is_empty() {
            return Some((
                "name",
                MasterProblem::Empty {
                    expected: "the device's name in the project",
                },
            ));
        }
        match &device.link {
            Link::Tcp { host, .. } if host.trim().is_empty() => {
                return Some((
                    "link.host",
                    MasterProblem::Empty {
                        expected: "a host name or IP address",
                    },
                ));
            }
            Link::Tcp { .. } => {}
            Link::Rtu { serial_port } => {
                if *serial_port as usize >= self.serial_ports.len() {
                    return Some((
                        "link.serial_port",
                        MasterProblem::IndexOutOfRange {
                            index: *serial_port,
                            count: self.serial_ports.len(),
                            of: "serial ports",
                        },
                    ));
                }
                // Address 0 is broadcast, which no device answers, and 248 to 255 are reserved.
                if !(1..=247).contains(&device.unit_id) {
                    return Some(("unit_id", out_of_range(device.unit_id, 1, 247)));
                }
            }
        }
        if device.task as usize >= task_count {
            return Some((
                "task",
                MasterProblem::IndexOutOfRange {
                    index: device.task,
                    count: task_count,
                    of: "tasks",
                },
            ));
        }
        if !(1..=MAX_TIMEOUT_MS).contains(&device.timeout_ms) {
            return Some((
                "timeout_ms",
                out_of_range(device.timeout_ms, 1, MAX_TIMEOUT_MS),
            ));
        }
        if let Schedule::Interval { interval_ms } = device.schedule
            && !(1..=MAX_INTERVAL_MS).contains(&interval_ms)
        {
            return Some((
                "schedule.interval_ms",
                out_of_range(interval_ms, 1, MAX_INTERVAL_MS),
            ));
        }
        if device.max_read_gap > MAX_READ_GAP {
            return Some((
                "max_read_gap",
                out_of_range(device.max_read_gap, 0, MAX_READ_GAP),
            ));
        }
        if device.channels.len() > MAX_CHANNELS_PER_DEVICE {
            return Some((
                "channels",
                MasterProblem::TooMany {
                    count: device.channels.len(),
                    max: MAX_CHANNELS_PER_DEVICE,
                },
            ));
        }
        None
    }
}

/// The first problem of a serial port's settings (`docs/modbus-master.md` §2.3).
fn port_problem(port: &SerialPortDef) -> Option<(&'static str, MasterProblem)> {
    if port.name.trim().is_empty() {
        return Some((
            "name",
            MasterProblem::Empty {
                expected: "the port's name in the project",
            },
        ));
    }
    if port.device.trim().is_empty() {
        return Some((
            "device",
            MasterProblem::Empty {
                expected: "a device file such as /dev/ttyUSB0",
            },
        ));
    }
    if !BAUD_RATES.contains(&port.baud_rate) {
        return Some((
            "baud_rate",
            MasterProblem::NotAllowed {
                value: u64::from(port.baud_rate),
                allowed: "1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200 or 230400",
            },
        ));
    }
    if port.data_bits != 8 {
        return Some((
            "data_bits",
            MasterProblem::NotAllowed {
                value: u64::from(port.data_bits),
                allowed: "8, the data bits of Modbus RTU",
            },
        ));
    }
    if !matches!(port.stop_bits, 1 | 2) {
        return Some((
            "stop_bits",
            MasterProblem::NotAllowed {
                value: u64::from(port.stop_bits),
                allowed: "1 or 2",
            },
        ));
    }
    if port.inter_frame_delay_us > MAX_INTER_FRAME_DELAY_US {
        return Some((
            "inter_frame_delay_us",
            out_of_range(port.inter_frame_delay_us, 0, MAX_INTER_FRAME_DELAY_US),
        ));
    }
    None
}

/// The first problem of a channel on its own (`docs/modbus-master.md` §2.2).
fn channel_problem(channel: &ChannelDef) -> Option<(&'static str, MasterProblem)> {
    let bits = table_holds_bits(channel.table);
    let type_fits = if bits {
        channel.value_type == Elementary::Bool
    } else {
        REGISTER_TYPES.contains(&channel.value_type)
    };
    if !type_fits {
        return Some((
            "value_type",
            MasterProblem::TypeNotInTable {
                table: channel.table,
                value_type: channel.value_type,
            },
        ));
    }
    if channel.count == 0 {
        return Some(("count", out_of_range(0u16, 1, u16::MAX)));
    }
    let code_fits = match (channel.direction, channel.table) {
        (Direction::Read, ModbusTable::Coils) => channel.function_code == 1,
        (Direction::Read, ModbusTable::DiscreteInputs) => channel.function_code == 2,
        (Direction::Read, ModbusTable::HoldingRegisters) => channel.function_code == 3,
        (Direction::Read, ModbusTable::InputRegisters) => channel.function_code == 4,
        (Direction::Write, ModbusTable::Coils) => matches!(channel.function_code, 5 | 15),
        (Direction::Write, ModbusTable::HoldingRegisters) => {
            matches!(channel.function_code, 6 | 16)
        }
        (Direction::Write, _) => false,
    };
    if !code_fits {
        return Some((
            "function_code",
            MasterProblem::FunctionCode {
                code: channel.function_code,
                table: channel.table,
                direction: channel.direction,
            },
        ));
    }
    let span = channel.span();
    if matches!(channel.function_code, 5 | 6) && span != 1 {
        return Some((
            "function_code",
            MasterProblem::SingleWriteOfMany {
                code: channel.function_code,
                span,
            },
        ));
    }
    let max = request_limit(channel.direction, channel.table);
    if span > max {
        return Some((
            "count",
            MasterProblem::LargerThanRequest {
                span,
                direction: channel.direction,
                max,
            },
        ));
    }
    if u32::from(channel.address) + span > 65_536 {
        return Some((
            "address",
            MasterProblem::PastLastAddress {
                address: channel.address,
                span,
            },
        ));
    }
    // `on_error` says what a read channel's variable holds after a failure; the master never
    // writes a write channel's variable, so setting it to zero there is a corrupt section
    // (§2.4 refuses `on_error` on a write channel).
    if channel.direction == Direction::Write && channel.on_error == OnError::SetToZero {
        return Some(("on_error", MasterProblem::SetToZeroOnWrite));
    }
    // A rising edge needs the BOOL whose edge it is (§2.4: `rising_edge` without
    // `trigger_variable`).
    if let Trigger::RisingEdge { variable } = &channel.trigger
        && variable.trim().is_empty()
    {
        return Some((
            "trigger.variable",
            MasterProblem::Empty {
                expected: "the path of the BOOL whose rising edge transfers the channel",
            },
        ));
    }
    None
}

/// Two channels of one table that share an address, whatever their directions: the later
/// channel's index and the earlier's. Sorted by table and address, two channels overlap only if
/// two neighbours do, so a device of many channels costs a sort, not every pair.
fn overlap(channels: &[ChannelDef]) -> Option<(usize, usize)> {
    let mut order: Vec<usize> = (0..channels.len()).collect();
    order.sort_by_key(|&index| (channels[index].table as u8, channels[index].address, index));
    order.windows(2).find_map(|pair| {
        let (first, second) = (&channels[pair[0]], &channels[pair[1]]);
        let overlaps = first.table == second.table
            && u32::from(first.address) + first.span() > u32::from(second.address);
        overlaps.then(|| (pair[0].max(pair[1]), pair[0].min(pair[1])))
    })
}

/// A range problem of any unsigned field.
fn out_of_range<T: Into<u64>>(value: T, min: T, max: T) -> MasterProblem {
    MasterProblem::OutOfRange {
        value: value.into(),
        min: min.into(),
        max: max.into(),
    }
}
