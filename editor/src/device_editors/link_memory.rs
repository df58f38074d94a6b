//! The links a Modbus device had before its link kind was switched: the model keeps one link,
//! so switching TCP to RTU and back would otherwise lose the host and port (and RTU to TCP and
//! back the serial port). The editor remembers the last link of each kind while the studio
//! runs; nothing of it is saved.

use project_model::{ModbusLink, Project, same_identifier};

use super::refusal::Refusal;

/// The last TCP link and the last RTU link a device's editor has shown. Lives in the node's
/// [`DeviceEditorState`](super::DeviceEditorState) while the studio runs; not saved.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct LinkMemory {
    /// The last Modbus TCP link seen, host and port as they were.
    tcp: Option<ModbusLink>,
    /// The last Modbus RTU link seen, its serial port's name.
    rtu: Option<ModbusLink>,
}

impl LinkMemory {
    /// Remembers `link` as the last of its kind (called each frame with the device's link, so
    /// edits of the host, port or serial port are remembered too).
    pub(crate) fn remember(&mut self, link: &ModbusLink) {
        let slot = match link {
            ModbusLink::Tcp { .. } => &mut self.tcp,
            ModbusLink::Rtu { .. } => &mut self.rtu,
        };
        if slot.as_ref() != Some(link) {
            *slot = Some(link.clone());
        }
    }

    /// Renames the remembered RTU link's serial port from `old` to `new` (names compare as
    /// IEC identifiers), as the rename carries into the devices on the port: the memory names
    /// the port as a device does, and a device on TCP is not one of them.
    pub(crate) fn serial_port_renamed(&mut self, old: &str, new: &str) {
        if let Some(ModbusLink::Rtu { serial_port }) = &mut self.rtu
            && same_identifier(serial_port, old)
        {
            new.clone_into(serial_port);
        }
    }
}

/// The link a device gets when the user switches it to `rtu` (or back to TCP): the link of that
/// kind it had last (`memory`), when its serial port is still in the project; otherwise the first
/// of the project's serial ports, or a TCP device at the Modbus port of this computer. RTU is
/// refused in a project without serial ports, since there is no port to choose until one is
/// added.
pub(crate) fn switched_link(
    project: &Project,
    rtu: bool,
    memory: &LinkMemory,
) -> Result<ModbusLink, Refusal> {
    if rtu {
        let remembered = memory.rtu.as_ref().and_then(|link| match link {
            ModbusLink::Rtu { serial_port } => project
                .serial_ports
                .iter()
                .find(|port| same_identifier(&port.name, serial_port)),
            ModbusLink::Tcp { .. } => None,
        });
        let port = remembered
            .or_else(|| project.serial_ports.first())
            .ok_or(Refusal::NoSerialPorts)?;
        Ok(ModbusLink::Rtu {
            serial_port: port.name.clone(),
        })
    } else {
        Ok(memory.tcp.clone().unwrap_or_else(|| ModbusLink::Tcp {
            host: "127.0.0.1".to_owned(),
            port: 502,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::SerialPort;

    fn tcp(host: &str, port: u16) -> ModbusLink {
        ModbusLink::Tcp {
            host: host.into(),
            port,
        }
    }

    fn rtu(serial_port: &str) -> ModbusLink {
        ModbusLink::Rtu {
            serial_port: serial_port.into(),
        }
    }

    fn two_ports() -> Project {
        let mut project = Project::default();
        project
            .serial_ports
            .push(SerialPort::new("RS232", "/dev/ttyS0"));
        project
            .serial_ports
            .push(SerialPort::new("RS485", "/dev/ttyUSB0"));
        project
    }

    #[test]
    fn a_new_switch_takes_the_first_serial_port_and_back_to_tcp_the_modbus_port() {
        let memory = LinkMemory::default();
        assert_eq!(
            switched_link(&Project::default(), true, &memory),
            Err(Refusal::NoSerialPorts)
        );
        let project = two_ports();
        assert_eq!(switched_link(&project, true, &memory), Ok(rtu("RS232")));
        assert_eq!(
            switched_link(&project, false, &memory),
            Ok(tcp("127.0.0.1", 502))
        );
    }

    #[test]
    fn tcp_to_rtu_and_back_returns_to_the_host_and_port_it_had() {
        let project = two_ports();
        let mut memory = LinkMemory::default();
        memory.remember(&tcp("192.168.1.50", 1502));
        let serial = switched_link(&project, true, &memory).unwrap();
        memory.remember(&serial);
        assert_eq!(
            switched_link(&project, false, &memory),
            Ok(tcp("192.168.1.50", 1502))
        );
    }

    #[test]
    fn rtu_to_tcp_and_back_returns_to_the_port_it_had_while_the_port_exists() {
        let mut project = two_ports();
        let mut memory = LinkMemory::default();
        memory.remember(&rtu("rs485"));
        let network = switched_link(&project, false, &memory).unwrap();
        memory.remember(&network);
        assert_eq!(switched_link(&project, true, &memory), Ok(rtu("RS485")));
        // A port deleted meanwhile is not brought back: the first port stands in.
        project.serial_ports.pop();
        assert_eq!(switched_link(&project, true, &memory), Ok(rtu("RS232")));
    }

    #[test]
    fn a_port_renamed_while_the_device_is_on_tcp_is_returned_to_under_its_new_name() {
        let mut project = two_ports();
        let mut memory = LinkMemory::default();
        memory.remember(&rtu("RS485"));
        memory.remember(&tcp("192.168.1.50", 502));
        project.serial_ports[1].name = "Line2".into();
        memory.serial_port_renamed("rs485", "Line2");
        // Another port's rename leaves the memory alone.
        memory.serial_port_renamed("RS232", "Line1");
        assert_eq!(switched_link(&project, true, &memory), Ok(rtu("Line2")));
    }
}
