//! A `[[modbus_device]]` table as the manifest stores it: the link's keys flat beside the others
//! (`host` and `port`, or `serial_port`), so a TCP device's table reads as it did before Modbus
//! RTU, and a table with both links or none is refused at load naming the device.

use serde::{Deserialize, Serialize};

use crate::{ModbusBinding, ModbusDevice, ModbusLink, ModbusSchedule, WordOrder};

/// The keys of a `[[modbus_device]]` table, in file order. Each field is the [`ModbusDevice`]
/// field of its name, but for the link, which is split into `host` and `port` (TCP) and
/// `serial_port` (RTU); keys holding their defaults are left out, but for `word_order`, which
/// files have always written.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ModbusDeviceFile {
    name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    host: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    port: Option<u16>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    serial_port: Option<String>,
    unit_id: u8,
    #[serde(default)]
    word_order: WordOrder,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    poll_interval_ms: Option<u32>,
    timeout_ms: u32,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    task: Option<String>,
    #[serde(default, skip_serializing_if = "ModbusSchedule::is_default")]
    schedule: ModbusSchedule,
    #[serde(default, skip_serializing_if = "is_zero")]
    max_read_gap: u16,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    status: Option<String>,
    #[serde(default, rename = "binding", skip_serializing_if = "Vec::is_empty")]
    bindings: Vec<ModbusBinding>,
}

/// Why a `[[modbus_device]]` table describes no link; the loader reports it at the table's line.
#[derive(Debug, thiserror::Error)]
pub(crate) enum LinkError {
    /// Both a TCP address and a serial port.
    #[error(
        "Modbus device '{0}' has both 'host'/'port' and 'serial_port': keep 'host' and 'port' for a Modbus TCP device, or 'serial_port' for a Modbus RTU device"
    )]
    Both(String),
    /// Neither a TCP address nor a serial port.
    #[error(
        "Modbus device '{0}' has neither 'host' and 'port' nor 'serial_port': give 'host' and 'port' for a Modbus TCP device, or 'serial_port' for a Modbus RTU device"
    )]
    Neither(String),
    /// A host without a port or a port without a host.
    #[error(
        "Modbus device '{name}' has '{given}' but no '{missing}': a Modbus TCP device needs both"
    )]
    HalfTcp {
        /// The device's name.
        name: String,
        /// The key given.
        given: &'static str,
        /// The key missing.
        missing: &'static str,
    },
}

/// Whether `max_read_gap` is the default, which the manifest leaves out.
fn is_zero(value: &u16) -> bool {
    *value == 0
}

impl TryFrom<ModbusDeviceFile> for ModbusDevice {
    type Error = LinkError;

    fn try_from(file: ModbusDeviceFile) -> Result<Self, LinkError> {
        let name = file.name;
        let link = match (file.host, file.port, file.serial_port) {
            (Some(host), Some(port), None) => ModbusLink::Tcp { host, port },
            (None, None, Some(serial_port)) => ModbusLink::Rtu { serial_port },
            (None, None, None) => return Err(LinkError::Neither(name)),
            (_, _, Some(_)) => return Err(LinkError::Both(name)),
            (Some(_), None, None) => {
                return Err(LinkError::HalfTcp {
                    name,
                    given: "host",
                    missing: "port",
                });
            }
            (None, Some(_), None) => {
                return Err(LinkError::HalfTcp {
                    name,
                    given: "port",
                    missing: "host",
                });
            }
        };
        Ok(Self {
            name,
            link,
            unit_id: file.unit_id,
            word_order: file.word_order,
            poll_interval_ms: file.poll_interval_ms,
            timeout_ms: file.timeout_ms,
            task: file.task,
            schedule: file.schedule,
            max_read_gap: file.max_read_gap,
            status: file.status,
            bindings: file.bindings,
        })
    }
}

impl From<ModbusDevice> for ModbusDeviceFile {
    fn from(device: ModbusDevice) -> Self {
        let (host, port, serial_port) = match device.link {
            ModbusLink::Tcp { host, port } => (Some(host), Some(port), None),
            ModbusLink::Rtu { serial_port } => (None, None, Some(serial_port)),
        };
        Self {
            name: device.name,
            host,
            port,
            serial_port,
            unit_id: device.unit_id,
            word_order: device.word_order,
            poll_interval_ms: device.poll_interval_ms,
            timeout_ms: device.timeout_ms,
            task: device.task,
            schedule: device.schedule,
            max_read_gap: device.max_read_gap,
            status: device.status,
            bindings: device.bindings,
        }
    }
}
