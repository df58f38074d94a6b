//! Checks of a Modbus TCP device: its name, address, timing and channel table.

use super::{DeviceProblem, name_problems, others};
use crate::{ModbusBinding, ModbusDevice, is_valid_identifier};

/// Every problem of `device` as the Modbus device at `index` of `devices` (`None` for a new
/// one): its name, host, port, poll interval, timeout and channels. Whether a channel's
/// variable exists and its type fits is the compiler's to say (`compiler::ide`).
pub fn modbus_device_problems(
    devices: &[ModbusDevice],
    index: Option<usize>,
    device: &ModbusDevice,
) -> Vec<DeviceProblem> {
    let mut problems = name_problems(
        "Modbus device",
        &device.name,
        others(devices, index).map(|(_, other)| other.name.as_str()),
    );
    if device.host.trim().is_empty() {
        problems.push(DeviceProblem::EmptyHost);
    }
    if device.port == 0 {
        problems.push(DeviceProblem::ZeroPort);
    }
    if device.poll_interval_ms == 0 {
        problems.push(DeviceProblem::ZeroPollInterval);
    }
    if device.timeout_ms == 0 {
        problems.push(DeviceProblem::ZeroTimeout);
    }
    problems.extend(binding_problems(&device.bindings));
    problems
}

/// Every problem of a device's channels: a missing or malformed variable path, a data type its
/// table cannot hold, a channel past address 65535, two channels of one table sharing an
/// address (the later one names the earlier).
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
        let width = width_of(binding);
        let end = u32::from(binding.address) + u32::from(width);
        if end > 65536 {
            problems.push(DeviceProblem::ChannelPastEnd {
                row,
                address: binding.address,
                width,
            });
        }
        let overlapping = bindings[..index].iter().position(|other| {
            other.table == binding.table
                && u32::from(other.address) < end
                && u32::from(binding.address)
                    < u32::from(other.address) + u32::from(width_of(other))
        });
        if let Some(other) = overlapping {
            problems.push(DeviceProblem::ChannelsOverlap {
                row,
                variable: binding.variable.clone(),
                other: other + 1,
                other_variable: bindings[other].variable.clone(),
            });
        }
    }
    problems
}

/// The coils or registers a channel takes: one bit in a bit table, else its type's registers.
fn width_of(binding: &ModbusBinding) -> u16 {
    if binding.table.holds_bits() {
        1
    } else {
        binding.data_type.width()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ModbusDataType, ModbusTable, WordOrder};

    fn binding(
        variable: &str,
        table: ModbusTable,
        address: u16,
        data_type: ModbusDataType,
    ) -> ModbusBinding {
        ModbusBinding {
            variable: variable.into(),
            table,
            address,
            data_type,
            comment: String::new(),
        }
    }

    fn drive() -> ModbusDevice {
        ModbusDevice {
            name: "BeltDrive".into(),
            host: "192.168.1.50".into(),
            port: 502,
            unit_id: 1,
            word_order: WordOrder::HighFirst,
            poll_interval_ms: 100,
            timeout_ms: 500,
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

    #[test]
    fn a_device_needs_a_host_a_port_and_some_time_to_poll_and_wait() {
        let mut device = drive();
        assert!(modbus_device_problems(&[], None, &device).is_empty());
        device.host.clear();
        device.port = 0;
        device.poll_interval_ms = 0;
        device.timeout_ms = 0;
        assert_eq!(
            modbus_device_problems(&[], None, &device),
            [
                DeviceProblem::EmptyHost,
                DeviceProblem::ZeroPort,
                DeviceProblem::ZeroPollInterval,
                DeviceProblem::ZeroTimeout
            ]
        );
    }

    #[test]
    fn a_second_device_of_the_same_name_is_refused() {
        let devices = [drive()];
        assert!(modbus_device_problems(&devices, Some(0), &devices[0]).is_empty());
        assert!(matches!(
            modbus_device_problems(&devices, None, &devices[0])[..],
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
}
