//! Checks of the controller node: its name, its address and its Modbus map override.

use super::{DeviceProblem, name_problems};
use crate::{Controller, ModbusServerRange};

/// Every problem of the controller's settings: its name, host, port and Modbus map ranges.
/// The password is never part of the project, so it is never checked here.
pub fn controller_problems(controller: &Controller) -> Vec<DeviceProblem> {
    let mut problems = name_problems("controller", &controller.name, std::iter::empty());
    if controller.host.trim().is_empty() {
        problems.push(DeviceProblem::EmptyHost);
    }
    if controller.port == 0 {
        problems.push(DeviceProblem::ZeroPort);
    }
    if let Some(map) = &controller.modbus_map {
        problems.extend(map_range_problems(&map.ranges));
    }
    problems
}

/// Every problem of a Modbus map's ranges: an empty address, a count of 0, a range past
/// address 65535, two ranges of the same table sharing addresses. Whether the located address
/// is well formed is the compiler's to say (`compiler::ide::address_info`).
pub fn map_range_problems(ranges: &[ModbusServerRange]) -> Vec<DeviceProblem> {
    let mut problems = Vec::new();
    for (index, range) in ranges.iter().enumerate() {
        let row = index + 1;
        if range.area_address.trim().is_empty() {
            problems.push(DeviceProblem::EmptyRangeAddress { row });
        }
        if range.count == 0 {
            problems.push(DeviceProblem::EmptyRange { row });
            continue;
        }
        if u32::from(range.start) + u32::from(range.count) > 65536 {
            problems.push(DeviceProblem::RangePastEnd {
                row,
                start: range.start,
                count: range.count,
            });
        }
        let end = u32::from(range.start) + u32::from(range.count);
        let overlapping = ranges[..index].iter().position(|other| {
            let other_end = u32::from(other.start) + u32::from(other.count);
            other.table == range.table
                && other.count > 0
                && u32::from(other.start) < end
                && u32::from(range.start) < other_end
        });
        if let Some(other) = overlapping {
            problems.push(DeviceProblem::RangesOverlap {
                row,
                other: other + 1,
            });
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ModbusServerMap, ModbusTable};

    fn range(table: ModbusTable, start: u16, count: u16) -> ModbusServerRange {
        ModbusServerRange {
            table,
            start,
            count,
            area_address: "%MW0".into(),
        }
    }

    #[test]
    fn the_default_controller_has_no_problem() {
        assert!(controller_problems(&Controller::default()).is_empty());
    }

    #[test]
    fn an_empty_host_port_0_and_a_bad_name_are_refused() {
        let controller = Controller {
            name: "my plc".into(),
            host: "  ".into(),
            port: 0,
            modbus_map: None,
        };
        let problems = controller_problems(&controller);
        assert!(matches!(problems[0], DeviceProblem::InvalidName { .. }));
        assert_eq!(
            problems[1..],
            [DeviceProblem::EmptyHost, DeviceProblem::ZeroPort]
        );
        assert_eq!(
            problems[2].to_string(),
            "port 0 cannot be used: enter a port from 1 to 65535"
        );
    }

    #[test]
    fn map_ranges_must_hold_something_end_by_65535_and_not_overlap_in_one_table() {
        let ranges = [
            range(ModbusTable::HoldingRegister, 0, 100),
            range(ModbusTable::InputRegister, 50, 10),
            range(ModbusTable::HoldingRegister, 99, 2),
            range(ModbusTable::Coil, 65530, 7),
            range(ModbusTable::Coil, 0, 0),
        ];
        assert_eq!(
            map_range_problems(&ranges),
            [
                DeviceProblem::RangesOverlap { row: 3, other: 1 },
                DeviceProblem::RangePastEnd {
                    row: 4,
                    start: 65530,
                    count: 7
                },
                DeviceProblem::EmptyRange { row: 5 },
            ]
        );
        assert!(map_range_problems(&ranges[..2]).is_empty());
    }

    #[test]
    fn a_map_range_needs_a_located_address() {
        let mut empty = range(ModbusTable::Coil, 0, 8);
        empty.area_address.clear();
        let controller = Controller {
            modbus_map: Some(ModbusServerMap {
                ranges: vec![empty],
            }),
            ..Controller::default()
        };
        assert_eq!(
            controller_problems(&controller),
            [DeviceProblem::EmptyRangeAddress { row: 1 }]
        );
    }
}
