//! Modbus RTU against pymodbus over a socat pair (8N1; this machine's ptys refuse parity): two
//! devices on one line, polled in turn; a slave slower than the timeout; the cable pulled (socat killed) fails every device of
//! the port with `SERIAL_PORT_ERROR`, and the line opens the port again when it comes back.

use std::sync::Arc;

use program_image::ModbusTable;
use program_image::modbus_master::{
    DeviceDef, Direction, Link, MasterSection, Parity, Schedule, SerialPortDef,
};
use runtime::areas::LocatedAreas;
use runtime::modbus::master::{DeviceState, MasterOptions, error_codes};
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tests::peers::{PymodbusServer, SocatPair};

use super::{channel, device, program, read_int, read_udint, wait_until};

/// The device `name` with unit `unit` on port 0: reads input register 0 into `variable`,
/// writes `Main.iOut` to holding register 10.
fn rtu_device(name: &str, unit: u8, variable: &str) -> DeviceDef {
    let mut input = channel(variable, 0, Direction::Read);
    input.table = ModbusTable::InputRegisters;
    input.function_code = 4;
    DeviceDef {
        name: name.to_owned(),
        link: Link::Rtu { serial_port: 0 },
        unit_id: unit,
        timeout_ms: 200,
        status: None,
        channels: vec![input, channel("Main.iOut", 10, Direction::Write)],
        // The TCP device's other settings serve as they are.
        ..device("127.0.0.1:1".parse().unwrap(), Schedule::EveryCycle)
    }
}

#[test]
fn two_units_on_one_line_are_polled_in_turn_and_the_port_is_reopened() {
    let dir = tempfile::tempdir().unwrap();
    let mut cable = SocatPair::start(dir.path());
    let mut slave = PymodbusServer::rtu(&cable.slave, 19200, 'N', 1, &[1, 2]);
    let mut image = program();
    image.modbus_master = Some(MasterSection {
        serial_ports: vec![SerialPortDef {
            name: "RS485".to_owned(),
            // The project's device file; `--serial-port` names this machine's.
            device: "/dev/ttyUSB0".to_owned(),
            baud_rate: 19200,
            parity: Parity::None,
            data_bits: 8,
            stop_bits: 1,
            inter_frame_delay_us: 0,
        }],
        devices: vec![
            rtu_device("Unit1", 1, "Main.iIn"),
            rtu_device("Unit2", 2, "Main.iZeroed"),
        ],
    });
    let options = SchedulerOptions {
        modbus_master: MasterOptions {
            serial_ports: vec![("rs485".to_owned(), cable.master.display().to_string())],
            ..MasterOptions::default()
        },
        ..SchedulerOptions::default()
    };
    let areas = Arc::new(std::sync::Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, options).unwrap();
    scheduler.load(image).unwrap();
    scheduler.start().unwrap();
    slave.set("ir", 0, 21);
    slave.set("2.ir", 0, 9);
    wait_until("both units are read and written", || {
        read_int(&scheduler, "Main.iOut") == 42
            && read_int(&scheduler, "Main.iZeroed") == 9
            && slave.get("hr", 10) == 42
            && slave.get("2.hr", 10) == 42
    });
    wait_until("both units communicate", || {
        scheduler
            .modbus_devices()
            .iter()
            .all(|device| device.state == DeviceState::Communicating)
    });

    // A slave slower than the timeout: each device times out in its turn, and the late
    // answers are dropped before the next request, so the line is in step again afterwards.
    slave.delay(300);
    wait_until("both devices time out", || {
        scheduler.modbus_devices().iter().all(|device| {
            device.state == DeviceState::NotAnswering
                && device.last_error == error_codes::RESPONSE_TIMEOUT
        })
    });
    slave.delay(0);
    slave.set("ir", 0, 22);
    wait_until("the line is in step again", || {
        read_int(&scheduler, "Main.iOut") == 44
            && scheduler
                .modbus_devices()
                .iter()
                .all(|device| device.state == DeviceState::Communicating)
    });

    // The cable is pulled: every device of the port fails with SERIAL_PORT_ERROR while the
    // task goes on.
    drop(slave);
    cable.kill();
    wait_until("every device of the port says the port failed", || {
        scheduler.modbus_devices().iter().all(|device| {
            device.state == DeviceState::SerialPortError
                && device.last_error == error_codes::SERIAL_PORT_ERROR
        })
    });
    let cycles = read_udint(&scheduler, "Main.udiCycles");
    wait_until("the task goes on", || {
        read_udint(&scheduler, "Main.udiCycles") > cycles + 5
    });
    assert_eq!(read_int(&scheduler, "Main.iIn"), 22);

    // It comes back under the same name: the port is opened again and values resume.
    cable.restart();
    let mut slave = PymodbusServer::rtu(&cable.slave, 19200, 'N', 1, &[1, 2]);
    slave.set("ir", 0, 50);
    slave.set("2.ir", 0, 3);
    wait_until("the line works again", || {
        read_int(&scheduler, "Main.iOut") == 100
            && read_int(&scheduler, "Main.iZeroed") == 3
            && slave.get("2.hr", 10) == 100
    });
    wait_until("both units communicate", || {
        scheduler
            .modbus_devices()
            .iter()
            .all(|device| device.state == DeviceState::Communicating)
    });
    scheduler.shutdown().unwrap();
}
