//! The project: the root of the device tree.

use serde::{Deserialize, Serialize};

use crate::{Axis, Dialect, Folder, IoArea, ModbusDevice, SerialPort, Task, VendorData};

/// A whole Rivet project, as loaded from its folder.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
pub struct Project {
    /// The project's display name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub name: String,
    /// What the machine is.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub description: String,
    /// The controller the application runs on.
    pub controller: Controller,
    /// The task configuration, in display order.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub tasks: Vec<Task>,
    /// The controller's local I/O areas.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub io_areas: Vec<IoArea>,
    /// The controller's serial ports, for Modbus RTU devices.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub serial_ports: Vec<SerialPort>,
    /// Third-party Modbus devices, over TCP or on a serial port.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub modbus_devices: Vec<ModbusDevice>,
    /// Motion axes.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub axes: Vec<Axis>,
    /// The language rules the compiler checks the project by.
    pub dialect: Dialect,
    /// The application: POUs, variable lists, types, cams, traces and watch lists in folders.
    pub application: Folder,
    /// What another tool wrote into the PLCopen file the project was imported from that Rivet
    /// does not model, written back by the export; saved in `plcopen.toml`.
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::strategy::Just(VendorData::default())")
    )]
    pub vendor_data: VendorData,
}

/// The controller node: the PLC the application is downloaded to.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Controller {
    /// The controller's name in the device tree.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// Host name or IP address of the target runtime.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub host: String,
    /// Modbus TCP port of the target runtime.
    pub port: u16,
    /// How the runtime's Modbus tables map onto its memory areas; `None` uses the default map
    /// documented in the README.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub modbus_map: Option<ModbusServerMap>,
}

impl Default for Controller {
    fn default() -> Self {
        Self {
            name: "PLC".into(),
            host: "127.0.0.1".into(),
            port: 5020,
            modbus_map: None,
        }
    }
}

/// A project-specific Modbus server map: ranges of Modbus tables mapped onto located memory.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct ModbusServerMap {
    /// The mapped ranges; addresses outside every range answer with an exception.
    #[serde(default, rename = "range", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub ranges: Vec<ModbusServerRange>,
}

/// A range of one Modbus table mapped onto located memory starting at `area_address`.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct ModbusServerRange {
    /// The Modbus table.
    pub table: crate::ModbusTable,
    /// The first Modbus address of the range.
    pub start: u16,
    /// The number of coils or registers.
    pub count: u16,
    /// The located address of the first coil or register, such as `%QX0.0` or `%MW0`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub area_address: String,
}

impl Project {
    /// The task named `name`, compared as IEC identifiers are.
    pub fn task(&self, name: &str) -> Option<&Task> {
        self.tasks
            .iter()
            .find(|task| crate::same_identifier(&task.name, name))
    }

    /// The serial port named `name`, compared as IEC identifiers are.
    pub fn serial_port(&self, name: &str) -> Option<&SerialPort> {
        self.serial_ports
            .iter()
            .find(|port| crate::same_identifier(&port.name, name))
    }
}
