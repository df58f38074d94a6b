//! Checks of the device tree's settings: what an editor refuses and what the loader warns about.
//!
//! Each check takes a candidate value (with the lists it must agree with) and gives every
//! problem found, each naming its field and saying what is expected. The editors refuse a value
//! that brings a problem the current value does not have ([`new_problem`]), so a project loaded
//! with an old problem can still be edited field by field. The loader accepts every value the
//! files can hold (the model never rejects what only the build needs), so these checks are not
//! load errors; [`device_problems`] lists them for the whole project.

mod axis;
mod controller;
mod io_area;
mod modbus;
mod problem;
mod serial_port;

pub use axis::axis_problems;
pub use controller::{controller_problems, map_range_problems};
pub use io_area::{LOCATED_AREA_BYTES, io_area_problems};
pub use modbus::{
    MAX_POLL_INTERVAL_MS, MAX_READ_GAP, MAX_TIMEOUT_MS, binding_problems, modbus_device_problems,
    request_limit,
};
pub use problem::DeviceProblem;
pub use serial_port::serial_port_problems;

use crate::{Project, is_valid_identifier, same_identifier};

/// The first problem of `candidate` that `current` does not have, or `None` when the candidate
/// brings no new problem. Both lists come from the same check.
pub fn new_problem(
    current: &[DeviceProblem],
    candidate: Vec<DeviceProblem>,
) -> Option<DeviceProblem> {
    candidate
        .into_iter()
        .find(|problem| !current.contains(problem))
}

/// Every problem of the device tree's settings, node by node, each with the node it belongs to
/// (`Modbus device 'BeltDrive'`).
pub fn device_problems(project: &Project) -> Vec<(String, DeviceProblem)> {
    let of = |node: String| move |problem| (node.clone(), problem);
    let mut problems: Vec<(String, DeviceProblem)> = controller_problems(&project.controller)
        .into_iter()
        .map(of(format!("controller '{}'", project.controller.name)))
        .collect();
    for (index, area) in project.io_areas.iter().enumerate() {
        let found = io_area_problems(&project.io_areas, Some(index), area);
        problems.extend(
            found
                .into_iter()
                .map(of(format!("I/O area '{}'", area.name))),
        );
    }
    for (index, port) in project.serial_ports.iter().enumerate() {
        let found = serial_port_problems(&project.serial_ports, Some(index), port);
        problems.extend(
            found
                .into_iter()
                .map(of(format!("serial port '{}'", port.name))),
        );
    }
    for (index, device) in project.modbus_devices.iter().enumerate() {
        let found = modbus_device_problems(project, Some(index), device);
        problems.extend(
            found
                .into_iter()
                .map(of(format!("Modbus device '{}'", device.name))),
        );
    }
    for (index, axis) in project.axes.iter().enumerate() {
        let found = axis_problems(project, Some(index), axis);
        problems.extend(found.into_iter().map(of(format!("axis '{}'", axis.name))));
    }
    problems
}

/// The problems of a node's name: it must be an identifier and differ from the names of the
/// other nodes of its list (`others`, without the node itself).
fn name_problems<'a>(
    kind: &'static str,
    name: &str,
    mut others: impl Iterator<Item = &'a str>,
) -> Vec<DeviceProblem> {
    if !is_valid_identifier(name) {
        return vec![DeviceProblem::InvalidName {
            kind,
            name: name.to_owned(),
        }];
    }
    if others.any(|other| same_identifier(other, name)) {
        return vec![DeviceProblem::DuplicateName {
            kind,
            name: name.to_owned(),
        }];
    }
    Vec::new()
}

/// The items of `list` other than the one at `index` (the node being edited).
fn others<T>(list: &[T], index: Option<usize>) -> impl Iterator<Item = (usize, &T)> {
    list.iter()
        .enumerate()
        .filter(move |(position, _)| Some(*position) != index)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_problems_the_current_value_lacks_are_new() {
        let old = DeviceProblem::ZeroPort;
        let fresh = DeviceProblem::EmptyHost;
        let current = [old.clone()];
        assert_eq!(new_problem(&current, vec![old.clone()]), None);
        assert_eq!(new_problem(&current, vec![old, fresh.clone()]), Some(fresh));
    }

    #[test]
    fn the_example_project_has_no_device_problem() {
        let loaded = crate::load_project(&assets::example_project_dir()).unwrap();
        assert_eq!(device_problems(&loaded.project), Vec::new());
    }

    #[test]
    fn the_problems_of_serial_ports_are_listed_by_port_before_the_devices() {
        let mut project = crate::load_project(&assets::example_project_dir())
            .unwrap()
            .project;
        let mut port = crate::SerialPort::new("RS485", "");
        port.stop_bits = 3;
        project.serial_ports.push(port);
        project.modbus_devices[0].link = crate::ModbusLink::Rtu {
            serial_port: "RS232".into(),
        };
        let node = |name: &str| format!("serial port '{name}'");
        let device = "Modbus device 'BeltDrive'".to_owned();
        assert_eq!(
            device_problems(&project),
            [
                (node("RS485"), DeviceProblem::EmptyDevice),
                (node("RS485"), DeviceProblem::UnsupportedStopBits(3)),
                (
                    device.clone(),
                    DeviceProblem::NoSuchSerialPort("RS232".into())
                ),
                (device, DeviceProblem::RtuWithoutTask),
            ]
        );
    }

    #[test]
    fn names_must_be_identifiers_and_unique_in_their_list() {
        assert_eq!(
            name_problems("axis", "1st", std::iter::empty()),
            vec![DeviceProblem::InvalidName {
                kind: "axis",
                name: "1st".into()
            }]
        );
        assert_eq!(
            name_problems("axis", "knife", ["Knife"].into_iter()),
            vec![DeviceProblem::DuplicateName {
                kind: "axis",
                name: "knife".into()
            }]
        );
        assert!(name_problems("axis", "Knife", ["Master"].into_iter()).is_empty());
    }
}
