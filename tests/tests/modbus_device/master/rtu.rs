//! Modbus RTU against pymodbus over a socat pair (8N1; this machine's ptys refuse parity): two
//! devices on one line, polled in turn; a slave slower than the timeout; the cable pulled (socat killed) fails every device of
//! the port with `SERIAL_PORT_ERROR`, and the line opens the port again when it comes back. A
//! fake slave written here answers a write with a frame tokio-modbus cannot decode: that
//! request fails, and the line goes on over the same port.

use std::io::{Read, Write};
use std::sync::Arc;
use std::sync::atomic::{AtomicU32, Ordering};

use program_image::modbus_master::{
    DeviceDef, Direction, Link, MasterSection, Parity, Schedule, SerialPortDef,
};
use program_image::{Elementary, ModbusTable};
use runtime::areas::LocatedAreas;
use runtime::modbus::master::{DeviceState, MasterOptions, error_codes};
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tests::peers::{PymodbusServer, SocatPair};

use runtime::modbus::rtu_slave::{crc16, rtu_frame};

use super::{channel, device, first, program, read_int, read_udint, wait_until};

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

/// The value every register of the fake RTU slave holds.
const FAKE_VALUE: u16 = 17;

/// A fake RTU slave on `path` (unit 1): answers reads of registers with [`FAKE_VALUE`] and
/// echoes writes of one coil, except that the first `bad_echoes` such writes are echoed with
/// the value 0x0001, which is no coil value: a frame with a right CRC that tokio-modbus's
/// decoder refuses. Ends when the cable goes.
fn fake_rtu_slave(path: &std::path::Path, bad_echoes: Arc<AtomicU32>) {
    let mut port = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(path)
        .unwrap();
    std::thread::spawn(move || {
        let mut buffer = Vec::new();
        let mut chunk = [0u8; 256];
        while let Ok(read) = port.read(&mut chunk) {
            if read == 0 {
                return;
            }
            buffer.extend_from_slice(&chunk[..read]);
            // Every request the master sends is 8 bytes, or 9 and its data for 15 and 16.
            while buffer.len() >= 8 {
                let length = match buffer[1] {
                    15 | 16 if buffer.len() >= 7 => 9 + usize::from(buffer[6]),
                    _ => 8,
                };
                if buffer.len() < length {
                    break;
                }
                let frame: Vec<u8> = buffer.drain(..length).collect();
                let crc = u16::from_le_bytes([frame[length - 2], frame[length - 1]]);
                if crc != crc16(&frame[..length - 2]) {
                    buffer.clear();
                    break;
                }
                let pdu = &frame[1..length - 2];
                let reply = match pdu[0] {
                    3 | 4 => {
                        let count = u16::from_be_bytes([pdu[3], pdu[4]]);
                        let mut reply = vec![pdu[0], (2 * count) as u8];
                        for _ in 0..count {
                            reply.extend_from_slice(&FAKE_VALUE.to_be_bytes());
                        }
                        reply
                    }
                    5 => {
                        let mut reply = pdu.to_vec();
                        let bad = bad_echoes
                            .fetch_update(Ordering::AcqRel, Ordering::Acquire, |left| {
                                left.checked_sub(1)
                            })
                            .is_ok();
                        if bad {
                            reply[3..5].copy_from_slice(&1u16.to_be_bytes());
                        }
                        reply
                    }
                    other => vec![other | 0x80, 1],
                };
                if port.write_all(&rtu_frame(frame[0], &reply)).is_err() {
                    return;
                }
            }
        }
    });
}

#[test]
fn an_answer_the_decoder_refuses_fails_its_request_and_the_port_stays_open() {
    let dir = tempfile::tempdir().unwrap();
    let cable = SocatPair::start(dir.path());
    let bad_echoes = Arc::new(AtomicU32::new(3));
    fake_rtu_slave(&cable.slave, Arc::clone(&bad_echoes));
    let mut image = program();
    let mut coil = channel("Main.xSend", 7, Direction::Write);
    coil.table = ModbusTable::Coils;
    coil.value_type = Elementary::Bool;
    coil.function_code = 5;
    let mut device = rtu_device("Unit1", 1, "Main.iIn");
    device.schedule = Schedule::Interval { interval_ms: 20 };
    device.channels = vec![channel("Main.iIn", 0, Direction::Read), coil];
    image.modbus_master = Some(MasterSection {
        serial_ports: vec![SerialPortDef {
            name: "RS485".to_owned(),
            device: cable.master.display().to_string(),
            baud_rate: 19200,
            parity: Parity::None,
            data_bits: 8,
            stop_bits: 1,
            inter_frame_delay_us: 0,
        }],
        devices: vec![device],
    });
    let areas = Arc::new(std::sync::Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler.load(image).unwrap();
    scheduler.start().unwrap();
    wait_until("the bad echoes were sent", || {
        bad_echoes.load(Ordering::Acquire) == 0
    });
    // Each bad echo fails its write only; the read of the same round and every later round
    // go over the same open port, so the last failure stays the invalid answer, never a
    // port error.
    let rounds = first(&scheduler.modbus_devices()).rounds;
    wait_until("the device communicates again", || {
        let device = first(&scheduler.modbus_devices());
        device.state == DeviceState::Communicating && device.rounds > rounds + 3
    });
    // A stray timeout of a loaded machine may replace the kept failure; what must never be
    // kept is a port error.
    let device = first(&scheduler.modbus_devices());
    assert!(
        [
            error_codes::RESPONSE_INVALID_PROTOCOL,
            error_codes::RESPONSE_TIMEOUT
        ]
        .contains(&device.last_error),
        "{:#x}: {}",
        device.last_error,
        device.detail
    );
    assert_eq!(read_int(&scheduler, "Main.iIn"), FAKE_VALUE as i16);
    scheduler.shutdown().unwrap();
}
