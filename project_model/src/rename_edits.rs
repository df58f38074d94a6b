//! What a rename carries along: everything else in the project that names the renamed task or
//! serial port, so a rename never leaves a device, an axis or a trace on something that no
//! longer exists. The edits are applied with the rename's own edit, in one undo step. Another
//! tool's vendor data of a task (`task:NAME`) is not an edit of its own: `Edit::Tasks` moves it
//! when it renames the task, as `Edit::Tree` does for an object's.

use crate::{Edit, ListEdit, ModbusLink, Object, Project, same_identifier};

/// The edits that carry a task's new name from `old` to `new` into every runtime Modbus device
/// polled in it (`modbus_devices[].task`), every axis it updates (`axes[].task`) and every trace
/// configuration it samples (`TraceConfig::task`), to be applied with the task's own edit in
/// one undo step; none when the name keeps its spelling.
pub fn task_rename_edits(project: &Project, old: &str, new: &str) -> Vec<Edit> {
    if old == new {
        return Vec::new();
    }
    let names_old = |task: &str| same_identifier(task, old);
    let devices = project
        .modbus_devices
        .iter()
        .enumerate()
        .filter(|(_, device)| device.task.as_deref().is_some_and(names_old))
        .map(|(index, device)| {
            let mut item = device.clone();
            item.task = Some(new.to_owned());
            Edit::ModbusDevices(ListEdit::Replace { index, item })
        });
    let axes = project
        .axes
        .iter()
        .enumerate()
        .filter(|(_, axis)| names_old(&axis.task))
        .map(|(index, axis)| {
            let mut item = axis.clone();
            item.task = new.to_owned();
            Edit::Axes(ListEdit::Replace { index, item })
        });
    let traces = project
        .application
        .objects()
        .into_iter()
        .filter_map(|object| match object {
            Object::Trace(trace) if names_old(&trace.task) => {
                let mut item = trace.clone();
                item.task = new.to_owned();
                Some(Edit::ReplaceObject(Object::Trace(item)))
            }
            _ => None,
        });
    devices.chain(axes).chain(traces).collect()
}

/// The edits that carry a serial port's new name from `old` to `new` into every Modbus device
/// on the port; none when the name keeps its spelling.
pub fn serial_port_rename_edits(project: &Project, old: &str, new: &str) -> Vec<Edit> {
    if old == new {
        return Vec::new();
    }
    project
        .modbus_devices
        .iter()
        .enumerate()
        .filter(|(_, device)| {
            device
                .serial_port()
                .is_some_and(|port| same_identifier(port, old))
        })
        .map(|(index, device)| {
            let mut item = device.clone();
            item.link = ModbusLink::Rtu {
                serial_port: new.to_owned(),
            };
            Edit::ModbusDevices(ListEdit::Replace { index, item })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{History, ModbusDevice, SerialPort};

    fn example() -> Project {
        crate::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn a_renamed_task_carries_into_devices_axes_and_traces_and_undoes_in_one_step() {
        let mut project = example();
        let mut drive = ModbusDevice::tcp("Drive", "127.0.0.1", 502);
        // Names compare as IEC identifiers, so another spelling of the task is carried too.
        drive.task = Some("motiontask".into());
        project.modbus_devices.push(drive);
        // Another tool's data of the task, as an import keeps it for the export.
        project.vendor_data.entries.push(crate::VendorEntry {
            place: "task:MotionTask".into(),
            xml: "<data name=\"x\" handleUnknown=\"preserve\"/>".into(),
            signature: None,
        });
        let before = project.clone();
        let index = project
            .tasks
            .iter()
            .position(|task| task.name == "MotionTask")
            .unwrap();
        let mut renamed = project.tasks[index].clone();
        renamed.name = "Motion".into();
        let mut edits = vec![Edit::Tasks(ListEdit::Replace {
            index,
            item: renamed,
        })];
        edits.extend(task_rename_edits(&project, "MotionTask", "Motion"));

        let mut history = History::default();
        history.apply(&mut project, "Rename task", edits).unwrap();
        let device = project.modbus_devices.last().unwrap();
        assert_eq!(device.task.as_deref(), Some("Motion"));
        // The example has two axes in the task; both are carried.
        assert_eq!(project.axes.len(), 2);
        assert!(project.axes.iter().all(|axis| axis.task == "Motion"));
        let places: Vec<&str> = project
            .vendor_data
            .entries
            .iter()
            .map(|entry| entry.place.as_str())
            .collect();
        assert_eq!(places, ["task:Motion"]);
        // The studio device and other tasks' names are left alone.
        assert_eq!(project.modbus_devices[0].task, None);
        let trace_task = |name: &str| match project.application.object(name) {
            Some(Object::Trace(trace)) => trace.task.clone(),
            _ => String::new(),
        };
        assert_eq!(trace_task("TRC_Knife"), "Motion");
        assert_eq!(trace_task("TRC_Conveyor"), "MainTask");

        history.undo(&mut project).unwrap();
        assert_eq!(project, before);
    }

    #[test]
    fn a_rename_that_keeps_the_spelling_carries_nothing() {
        assert!(task_rename_edits(&example(), "MainTask", "MainTask").is_empty());
    }

    fn project_with_port() -> Project {
        let mut project = Project::default();
        project
            .serial_ports
            .push(SerialPort::new("RS485", "/dev/ttyUSB0"));
        let mut drive = ModbusDevice::tcp("Drive", "127.0.0.1", 502);
        drive.link = ModbusLink::Rtu {
            serial_port: "rs485".into(),
        };
        drive.task = Some("MainTask".into());
        project
            .modbus_devices
            .push(ModbusDevice::tcp("Meter", "10.0.0.2", 502));
        project.modbus_devices.push(drive);
        project
    }

    #[test]
    fn a_renamed_port_is_renamed_in_the_devices_on_it_only() {
        let project = project_with_port();
        let edits = serial_port_rename_edits(&project, "RS485", "Line1");
        assert_eq!(edits.len(), 1);
        let Edit::ModbusDevices(ListEdit::Replace { index, item }) = &edits[0] else {
            panic!("{edits:?}");
        };
        assert_eq!(*index, 1);
        assert_eq!(item.serial_port(), Some("Line1"));
        assert!(serial_port_rename_edits(&project, "RS485", "RS485").is_empty());
    }
}
