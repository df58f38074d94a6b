//! The five lists of the device tree (tasks, I/O areas, serial ports, Modbus devices, axes) seen
//! through one interface, so adding, renaming, duplicating, deleting and reordering work alike.

use project_model::{Edit, ListEdit, Project};

use super::names::{NameScope, unique_name};
use super::new_objects::{new_axis, new_io_area, new_modbus_device, new_serial_port, new_task};
use crate::studio::i18n::Text;
use crate::studio::tree_node::TreeNode;

/// Which list of the device tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ListKind {
    /// The task configuration.
    Tasks,
    /// The I/O areas.
    IoAreas,
    /// The serial ports.
    SerialPorts,
    /// The Modbus devices.
    ModbusDevices,
    /// The motion axes.
    Axes,
}

impl ListKind {
    /// The list an entry node belongs to, with the entry's name.
    pub fn of_entry(node: &TreeNode) -> Option<(Self, &str)> {
        match node {
            TreeNode::Task(name) => Some((Self::Tasks, name)),
            TreeNode::IoArea(name) => Some((Self::IoAreas, name)),
            TreeNode::SerialPort(name) => Some((Self::SerialPorts, name)),
            TreeNode::ModbusDevice(name) => Some((Self::ModbusDevices, name)),
            TreeNode::Axis(name) => Some((Self::Axes, name)),
            _ => None,
        }
    }

    /// The tree node of the entry named `name`.
    pub fn entry(self, name: String) -> TreeNode {
        match self {
            Self::Tasks => TreeNode::Task(name),
            Self::IoAreas => TreeNode::IoArea(name),
            Self::SerialPorts => TreeNode::SerialPort(name),
            Self::ModbusDevices => TreeNode::ModbusDevice(name),
            Self::Axes => TreeNode::Axis(name),
        }
    }

    /// Where the entries' names must be unique.
    pub fn scope(self) -> NameScope<'static> {
        match self {
            Self::Tasks => NameScope::Task,
            Self::IoAreas => NameScope::IoArea,
            Self::SerialPorts => NameScope::SerialPort,
            Self::ModbusDevices => NameScope::ModbusDevice,
            Self::Axes => NameScope::Axis,
        }
    }

    /// What one entry is called in undo labels.
    pub fn noun(self) -> Text {
        match self {
            Self::Tasks => Text::NounTask,
            Self::IoAreas => Text::NounIoArea,
            Self::SerialPorts => Text::NounSerialPort,
            Self::ModbusDevices => Text::NounModbusDevice,
            Self::Axes => Text::NounAxis,
        }
    }

    /// The default name new entries start from.
    fn base_name(self) -> &'static str {
        match self {
            Self::Tasks => "Task",
            Self::IoAreas => "IoArea",
            Self::SerialPorts => "COM",
            Self::ModbusDevices => "ModbusDevice",
            Self::Axes => "Axis",
        }
    }

    /// The entries' names in list order.
    pub fn names(self, project: &Project) -> Vec<&str> {
        match self {
            Self::Tasks => project.tasks.iter().map(|t| t.name.as_str()).collect(),
            Self::IoAreas => project.io_areas.iter().map(|a| a.name.as_str()).collect(),
            Self::SerialPorts => project
                .serial_ports
                .iter()
                .map(|p| p.name.as_str())
                .collect(),
            Self::ModbusDevices => project
                .modbus_devices
                .iter()
                .map(|d| d.name.as_str())
                .collect(),
            Self::Axes => project.axes.iter().map(|a| a.name.as_str()).collect(),
        }
    }

    /// The position of the entry named exactly `name`.
    pub fn index_of(self, project: &Project, name: &str) -> Option<usize> {
        self.names(project).iter().position(|other| *other == name)
    }

    /// A name no entry of the list has yet, starting from `base`.
    pub fn fresh_name(self, project: &Project, base: &str) -> String {
        unique_name(base, |name| self.scope().is_taken(project, name, None))
    }

    /// Appends a new entry with a fresh name; returns the edit and the name.
    pub fn add(self, project: &Project) -> (Edit, String) {
        let name = self.fresh_name(project, self.base_name());
        let edit = match self {
            Self::Tasks => Edit::Tasks(ListEdit::Insert {
                index: project.tasks.len(),
                item: new_task(name.clone()),
            }),
            Self::IoAreas => Edit::IoAreas(ListEdit::Insert {
                index: project.io_areas.len(),
                item: new_io_area(project, name.clone()),
            }),
            Self::SerialPorts => Edit::SerialPorts(ListEdit::Insert {
                index: project.serial_ports.len(),
                item: new_serial_port(name.clone()),
            }),
            Self::ModbusDevices => Edit::ModbusDevices(ListEdit::Insert {
                index: project.modbus_devices.len(),
                item: new_modbus_device(name.clone()),
            }),
            Self::Axes => Edit::Axes(ListEdit::Insert {
                index: project.axes.len(),
                item: new_axis(project, name.clone()),
            }),
        };
        (edit, name)
    }

    /// The entry at `index` under another name (`None` when there is no such entry).
    pub fn renamed(self, project: &Project, index: usize, name: &str) -> Option<Edit> {
        let named = |item: &mut dyn SetName| item.set_name(name);
        Some(match self {
            Self::Tasks => Edit::Tasks(replace(&project.tasks, index, named)?),
            Self::IoAreas => Edit::IoAreas(replace(&project.io_areas, index, named)?),
            Self::SerialPorts => Edit::SerialPorts(replace(&project.serial_ports, index, named)?),
            Self::ModbusDevices => {
                Edit::ModbusDevices(replace(&project.modbus_devices, index, named)?)
            }
            Self::Axes => Edit::Axes(replace(&project.axes, index, named)?),
        })
    }

    /// A copy of the entry at `index` named `name`, inserted right after it.
    pub fn duplicated(self, project: &Project, index: usize, name: &str) -> Option<Edit> {
        let named = |item: &mut dyn SetName| item.set_name(name);
        Some(match self {
            Self::Tasks => Edit::Tasks(copy_after(&project.tasks, index, named)?),
            Self::IoAreas => Edit::IoAreas(copy_after(&project.io_areas, index, named)?),
            Self::SerialPorts => {
                Edit::SerialPorts(copy_after(&project.serial_ports, index, named)?)
            }
            Self::ModbusDevices => {
                Edit::ModbusDevices(copy_after(&project.modbus_devices, index, named)?)
            }
            Self::Axes => Edit::Axes(copy_after(&project.axes, index, named)?),
        })
    }

    /// Removes the entry at `index`.
    pub fn removed(self, index: usize) -> Edit {
        match self {
            Self::Tasks => Edit::Tasks(ListEdit::Remove { index }),
            Self::IoAreas => Edit::IoAreas(ListEdit::Remove { index }),
            Self::SerialPorts => Edit::SerialPorts(ListEdit::Remove { index }),
            Self::ModbusDevices => Edit::ModbusDevices(ListEdit::Remove { index }),
            Self::Axes => Edit::Axes(ListEdit::Remove { index }),
        }
    }

    /// Moves the entry at `from` so that it ends up at `to`.
    pub fn moved(self, from: usize, to: usize) -> Edit {
        match self {
            Self::Tasks => Edit::Tasks(ListEdit::Move { from, to }),
            Self::IoAreas => Edit::IoAreas(ListEdit::Move { from, to }),
            Self::SerialPorts => Edit::SerialPorts(ListEdit::Move { from, to }),
            Self::ModbusDevices => Edit::ModbusDevices(ListEdit::Move { from, to }),
            Self::Axes => Edit::Axes(ListEdit::Move { from, to }),
        }
    }
}

/// Entries whose name can be changed, so one closure renames any of them.
trait SetName {
    fn set_name(&mut self, name: &str);
}

macro_rules! set_name_field {
    ($($ty:ty),*) => {
        $(impl SetName for $ty {
            fn set_name(&mut self, name: &str) {
                self.name = name.to_owned();
            }
        })*
    };
}

set_name_field!(
    project_model::Task,
    project_model::IoArea,
    project_model::SerialPort,
    project_model::ModbusDevice,
    project_model::Axis
);

fn replace<T: Clone + SetName>(
    list: &[T],
    index: usize,
    change: impl Fn(&mut dyn SetName),
) -> Option<ListEdit<T>> {
    let mut item = list.get(index)?.clone();
    change(&mut item);
    Some(ListEdit::Replace { index, item })
}

fn copy_after<T: Clone + SetName>(
    list: &[T],
    index: usize,
    change: impl Fn(&mut dyn SetName),
) -> Option<ListEdit<T>> {
    let mut item = list.get(index)?.clone();
    change(&mut item);
    Some(ListEdit::Insert {
        index: index + 1,
        item,
    })
}
