//! A project's Modbus TCP devices as `online::device` connections: each binding of the device
//! node becomes a typed channel, so the device's registers are monitored, written, forced and
//! traced without downloading anything.

use std::net::ToSocketAddrs as _;
use std::time::Duration;

use online::OnlineError;
use online::device::{Channel, Device, Table, WordOrder};
use program_image::Elementary;
use project_model::{ModbusDataType, ModbusDevice, ModbusLink, ModbusTable};

/// The channels of a device node's bindings, in their order.
pub fn channels_of(device: &ModbusDevice) -> Vec<Channel> {
    device
        .bindings
        .iter()
        .map(|binding| Channel {
            name: binding.variable.clone(),
            table: match binding.table {
                ModbusTable::Coil => Table::Coils,
                ModbusTable::DiscreteInput => Table::DiscreteInputs,
                ModbusTable::HoldingRegister => Table::HoldingRegisters,
                ModbusTable::InputRegister => Table::InputRegisters,
            },
            address: binding.address,
            ty: match binding.data_type {
                ModbusDataType::Bool => Elementary::Bool,
                ModbusDataType::Int16 => Elementary::Int,
                ModbusDataType::Uint16 => Elementary::Uint,
                ModbusDataType::Int32 => Elementary::Dint,
                ModbusDataType::Uint32 => Elementary::Udint,
                ModbusDataType::Int64 => Elementary::Lint,
                ModbusDataType::Uint64 => Elementary::Ulint,
                ModbusDataType::Real => Elementary::Real,
                ModbusDataType::Lreal => Elementary::Lreal,
            },
        })
        .collect()
}

/// Connects to a device node with its host, port, unit, word order, timeout and bindings; a
/// Modbus RTU device is refused, since the studio does not poll serial ports.
pub async fn connect(device: &ModbusDevice) -> Result<Device, OnlineError> {
    let ModbusLink::Tcp { host, port } = &device.link else {
        return Err(OnlineError::Rejected(format!(
            "device '{}' is on a serial port, which only the runtime polls",
            device.name
        )));
    };
    let text = format!("{host}:{port}");
    let address = text
        .to_socket_addrs()
        .ok()
        .and_then(|mut addresses| addresses.next())
        .ok_or_else(|| {
            OnlineError::Rejected(format!(
                "device '{}': '{text}' is not an address",
                device.name
            ))
        })?;
    let order = match device.word_order {
        project_model::WordOrder::HighFirst => WordOrder::HighFirst,
        project_model::WordOrder::LowFirst => WordOrder::LowFirst,
    };
    let timeout = Duration::from_millis(u64::from(device.timeout_ms.max(1)));
    Device::connect(address, device.unit_id, order, timeout, channels_of(device)).await
}

#[cfg(test)]
mod tests {
    use std::sync::{Arc, Mutex};

    use super::*;

    #[test]
    fn the_example_s_belt_drive_becomes_typed_channels() {
        let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
        let drive = &loaded.project.modbus_devices[0];
        let channels = channels_of(drive);
        assert_eq!(channels.len(), drive.bindings.len());
        assert_eq!(channels[0].table, Table::InputRegisters);
        assert_eq!(channels[0].ty, Elementary::Real);
        assert_eq!(channels[0].width(), 2);
        assert_eq!(channels[1].ty, Elementary::Bool);
    }

    #[test]
    fn a_project_device_on_loopback_is_polled_written_and_forced() {
        let tokio = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .unwrap();
        tokio.block_on(async {
            let areas = Arc::new(Mutex::new(runtime::areas::LocatedAreas::new(16, 64, 8192)));
            let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
            let port = listener.local_addr().unwrap().port();
            tokio::spawn(runtime::modbus::serve(
                listener,
                areas,
                runtime::modbus::MapSlot::new(runtime::modbus::ModbusMap::default()),
                runtime::modbus::ServerOptions::default(),
            ));
            let device = ModbusDevice {
                word_order: project_model::WordOrder::LowFirst,
                poll_interval_ms: Some(10),
                timeout_ms: 1000,
                bindings: vec![project_model::ModbusBinding::new(
                    "GVL.rSpeed",
                    ModbusTable::HoldingRegister,
                    1024,
                    ModbusDataType::Real,
                )],
                ..ModbusDevice::tcp("Drive", "127.0.0.1", port)
            };
            let mut connected = connect(&device).await.unwrap();
            connected
                .force(0, 12.5f32.to_le_bytes().to_vec())
                .await
                .unwrap();
            let snapshot = connected.poll().await.unwrap();
            assert_eq!(snapshot.values[0], 12.5f32.to_le_bytes().to_vec());
        });
    }
}
