//! Nodes of the device tree, which are also the documents tabs show.

use project_model::{Object, PouKind, Project};
use serde::{Deserialize, Serialize};

/// A node of the device tree. Named nodes are identified by name, as IEC names are unique in
/// their scope; folders by their path.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum TreeNode {
    /// The controller.
    Controller,
    /// The task configuration.
    TaskConfiguration,
    /// A task.
    Task(String),
    /// The application root.
    Application,
    /// A folder of the application, by its path of folder names.
    Folder(Vec<String>),
    /// An application object (POU, GVL, data type, cam, trace, watch list).
    Object(String),
    /// The I/O areas.
    IoAreas,
    /// An I/O area.
    IoArea(String),
    /// The Modbus devices (TCP or RTU).
    ModbusDevices,
    /// A Modbus device.
    ModbusDevice(String),
    /// The motion axes.
    Axes,
    /// A motion axis.
    Axis(String),
    /// The controller's serial ports.
    SerialPorts,
    /// A serial port, by name.
    SerialPort(String),
}

impl TreeNode {
    /// Whether double-clicking the node opens it in a tab.
    pub fn is_document(&self) -> bool {
        matches!(
            self,
            Self::Controller
                | Self::TaskConfiguration
                | Self::Task(_)
                | Self::Object(_)
                | Self::IoArea(_)
                | Self::ModbusDevice(_)
                | Self::Axis(_)
                | Self::SerialPort(_)
        )
    }

    /// The tab title of a document node.
    pub fn title(&self, project: Option<&Project>) -> String {
        match self {
            Self::Controller => project
                .map(|p| p.controller.name.clone())
                .unwrap_or_default(),
            Self::Task(name)
            | Self::Object(name)
            | Self::IoArea(name)
            | Self::ModbusDevice(name)
            | Self::Axis(name)
            | Self::SerialPort(name) => name.clone(),
            Self::Folder(path) => path.last().cloned().unwrap_or_default(),
            Self::TaskConfiguration
            | Self::Application
            | Self::IoAreas
            | Self::ModbusDevices
            | Self::Axes
            | Self::SerialPorts => String::new(),
        }
    }
}

/// The short tag shown before an object in the tree and on its tab, as CODESYS shows an icon.
pub fn object_tag(object: &Object) -> &'static str {
    match object {
        Object::Pou(pou) => match pou.kind {
            PouKind::Program => "PRG",
            PouKind::FunctionBlock => "FB",
            PouKind::Function => "FUN",
            PouKind::Interface => "ITF",
        },
        Object::Gvl(_) => "GVL",
        Object::DataType(_) => "DUT",
        Object::CamTable(_) => "CAM",
        Object::Trace(_) => "TRC",
        Object::WatchList(_) => "WCH",
    }
}
