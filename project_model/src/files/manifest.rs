//! The manifest `rivet.toml` as it is stored.

use serde::{Deserialize, Serialize};
use toml::Spanned;

use crate::modbus_device_file::ModbusDeviceFile;
use crate::{Axis, Controller, Dialect, IoArea, SerialPort, Task};

/// The manifest's fields in file order.
///
/// The application is listed as paths under `application/`, one entry a line, so that adding or
/// moving an object is a one-line change in `git diff`; a folder is an entry ending in `/`.
#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Manifest {
    pub format_version: u32,
    pub name: String,
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub description: String,
    #[serde(default, skip_serializing_if = "Dialect::is_default")]
    pub dialect: Dialect,
    #[serde(default)]
    pub application: Vec<Spanned<String>>,
    pub controller: Controller,
    #[serde(default, rename = "task", skip_serializing_if = "Vec::is_empty")]
    pub tasks: Vec<Task>,
    #[serde(default, rename = "io_area", skip_serializing_if = "Vec::is_empty")]
    pub io_areas: Vec<IoArea>,
    #[serde(default, rename = "serial_port", skip_serializing_if = "Vec::is_empty")]
    pub serial_ports: Vec<SerialPort>,
    #[serde(
        default,
        rename = "modbus_device",
        skip_serializing_if = "Vec::is_empty"
    )]
    /// The devices as their tables read, each with its span: a table whose link is wrong is
    /// refused after it is read, so the loader converts each itself to name its own line.
    pub modbus_devices: Vec<Spanned<ModbusDeviceFile>>,
    #[serde(default, rename = "axis", skip_serializing_if = "Vec::is_empty")]
    pub axes: Vec<Axis>,
}

/// The first thing read from a manifest: only its version, so a file from another format
/// version is reported as such rather than as a list of unknown fields.
#[derive(Debug, Deserialize)]
pub(crate) struct VersionProbe {
    pub format_version: Option<Spanned<i64>>,
}
