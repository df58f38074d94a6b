//! A project's Modbus TCP devices as `online::device` connections: each binding of one value
//! becomes a typed channel, so the device's registers are monitored, written, forced and traced
//! without downloading anything.

use std::net::ToSocketAddrs as _;
use std::time::Duration;

use online::OnlineError;
use online::device::{Channel, Device, Table, WordOrder};
use project_model::{ModbusBinding, ModbusDevice, ModbusLink, ModbusTable};

/// Why the studio could not connect to a device; the studio words it in the user's language.
#[derive(Debug, thiserror::Error)]
pub enum ConnectError {
    /// The device is on a serial port, which the studio never polls. The studio asks to connect
    /// only to the devices it polls, which are all TCP devices, so this is a guard, not a path.
    #[error("device '{0}' is on a serial port, which only the runtime polls")]
    OnSerialPort(String),
    /// The device's host and port name no socket address.
    #[error("device '{device}': '{address}' is not an address")]
    NotAnAddress {
        /// The device's name.
        device: String,
        /// The host and port as written, `host:port`.
        address: String,
    },
    /// The connection itself failed.
    #[error(transparent)]
    Online(#[from] OnlineError),
}

/// The bindings the studio's own poll reads, in order: those of one value.
///
/// A binding of several values (`count` above 1, an array variable) is read by the runtime
/// only: `online::device` reads one value per channel, and the studio refuses such a binding
/// with a message rather than showing its first element as the whole array. A write channel
/// is polled like a read one: reading back the coil or holding register it writes is harmless,
/// and shows what the device holds, as CODESYS's online view of a write channel does.
pub fn polled_bindings(device: &ModbusDevice) -> impl Iterator<Item = &ModbusBinding> {
    device.bindings.iter().filter(|binding| binding.count == 1)
}

/// The index among [`channels_of`] of the binding at `binding_index` of `device`'s bindings;
/// `None` for a binding the studio does not poll.
pub fn channel_index(device: &ModbusDevice, binding_index: usize) -> Option<usize> {
    let binding = device.bindings.get(binding_index)?;
    (binding.count == 1).then(|| {
        device.bindings[..binding_index]
            .iter()
            .filter(|before| before.count == 1)
            .count()
    })
}

/// The channels of a device node's bindings of one value ([`polled_bindings`]), in their order.
pub fn channels_of(device: &ModbusDevice) -> Vec<Channel> {
    polled_bindings(device)
        .map(|binding| Channel {
            name: binding.variable.clone(),
            table: match binding.table {
                ModbusTable::Coil => Table::Coils,
                ModbusTable::DiscreteInput => Table::DiscreteInputs,
                ModbusTable::HoldingRegister => Table::HoldingRegisters,
                ModbusTable::InputRegister => Table::InputRegisters,
            },
            address: binding.address,
            // The type the runtime's master reads the channel as, so the studio's poll shows
            // the value the program gets.
            ty: compiler::ide::modbus_value_type(binding.data_type),
        })
        .collect()
}

/// Connects to a device node with its host, port, unit, word order, timeout and bindings; a
/// Modbus RTU device is refused, since the studio does not poll serial ports.
pub async fn connect(device: &ModbusDevice) -> Result<Device, ConnectError> {
    let ModbusLink::Tcp { host, port } = &device.link else {
        return Err(ConnectError::OnSerialPort(device.name.clone()));
    };
    let text = format!("{host}:{port}");
    let address = text
        .to_socket_addrs()
        .ok()
        .and_then(|mut addresses| addresses.next())
        .ok_or_else(|| ConnectError::NotAnAddress {
            device: device.name.clone(),
            address: text.clone(),
        })?;
    let order = match device.word_order {
        project_model::WordOrder::HighFirst => WordOrder::HighFirst,
        project_model::WordOrder::LowFirst => WordOrder::LowFirst,
    };
    let timeout = Duration::from_millis(u64::from(device.timeout_ms.max(1)));
    Ok(Device::connect(address, device.unit_id, order, timeout, channels_of(device)).await?)
}

#[cfg(test)]
mod tests {
    use std::sync::{Arc, Mutex};

    use program_image::Elementary;
    use project_model::ModbusDataType;

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
    fn a_channel_of_several_values_is_not_polled_and_the_others_keep_their_order() {
        let mut device = ModbusDevice::tcp("Island", "127.0.0.1", 502);
        let one = |variable: &str, address| {
            ModbusBinding::new(
                variable,
                ModbusTable::HoldingRegister,
                address,
                ModbusDataType::Int16,
            )
        };
        let mut array = one("GVL.aWords", 10);
        array.count = 8;
        let mut written = one("GVL.iSetpoint", 30);
        written.direction = project_model::ChannelDirection::Write;
        device.bindings = vec![one("GVL.iFirst", 0), array, written];
        let channels = channels_of(&device);
        let names: Vec<&str> = channels.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["GVL.iFirst", "GVL.iSetpoint"]);
        assert_eq!(channels[1].address, 30);
        assert_eq!(channel_index(&device, 0), Some(0));
        assert_eq!(channel_index(&device, 1), None);
        assert_eq!(channel_index(&device, 2), Some(1));
        assert_eq!(channel_index(&device, 3), None);
    }

    #[test]
    fn an_rtu_device_is_refused_by_connect() {
        let device = ModbusDevice {
            link: ModbusLink::Rtu {
                serial_port: "RS485".into(),
            },
            ..ModbusDevice::tcp("Meter", "127.0.0.1", 502)
        };
        let tokio = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .unwrap();
        let error = tokio.block_on(connect(&device)).err().unwrap();
        assert!(matches!(error, ConnectError::OnSerialPort(name) if name == "Meter"));
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
                bindings: vec![ModbusBinding::new(
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
