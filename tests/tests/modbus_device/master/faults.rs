//! A fake slave that answers wrongly (short counts, wrong echoes, exceptions): the master
//! reports each as §6.6 says, keeps the other channels going, and never panics, in a debug
//! build too (tokio-modbus's convenience readers would).

use std::sync::atomic::{AtomicU8, AtomicU32, Ordering};
use std::sync::{Arc, Mutex};

use program_image::modbus_master::Schedule;
use runtime::areas::LocatedAreas;
use runtime::modbus::master::{DeviceState, error_codes};
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tokio::io::{AsyncReadExt, AsyncWriteExt};

use super::{device, first, image_with, read, read_int, wait_until};

/// Connection attempts the master may make while its device refuses during 100 rounds of
/// 10 ms: the back-off of §6.8 (100, 200, 400, 800, 1600 ms …) allows about five in the
/// second those rounds take at least, and nine in the test's whole patience; without it
/// there would be one a round.
const ATTEMPTS_BACKED_OFF: u32 = 10;

/// Answers every request right.
const RIGHT: u8 = 0;
/// Answers a read with one register too few.
const SHORT_COUNT: u8 = 1;
/// Echoes a write with another address.
const WRONG_ECHO: u8 = 2;
/// Answers a read from holding register 2 with exception 2.
const EXCEPTION: u8 = 3;
/// Answers nothing (a device slower than any timeout).
const SILENT: u8 = 4;

/// What every register of the fake slave holds.
const VALUE: i16 = 4;

/// A fake slave: how it answers, and the writes to holding register 20 it received.
#[derive(Clone, Default)]
pub(super) struct Fake {
    /// How it answers (`RIGHT`, `SHORT_COUNT` …).
    mode: Arc<AtomicU8>,
    /// The values written to holding register 20, in the order they came.
    pub(super) writes_to_20: Arc<Mutex<Vec<i16>>>,
    /// Connections accepted so far.
    pub(super) connections: Arc<AtomicU32>,
}

/// Serves connections on a runtime of its own, answering as `fake` says.
pub(super) fn fake_slave(fake: &Fake) -> (std::net::SocketAddr, tokio::runtime::Runtime) {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(1)
        .enable_all()
        .build()
        .unwrap();
    let listener = runtime
        .block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))
        .unwrap();
    let address = listener.local_addr().unwrap();
    let fake = fake.clone();
    runtime.spawn(async move {
        while let Ok((stream, _)) = listener.accept().await {
            fake.connections.fetch_add(1, Ordering::AcqRel);
            tokio::spawn(answer(stream, fake.clone()));
        }
    });
    (address, runtime)
}

/// Answers the requests of one connection until it closes.
async fn answer(mut stream: tokio::net::TcpStream, fake: Fake) {
    let mut header = [0u8; 7];
    while stream.read_exact(&mut header).await.is_ok() {
        let length = usize::from(u16::from_be_bytes([header[4], header[5]]));
        let mut pdu = vec![0u8; length.saturating_sub(1)];
        if stream.read_exact(&mut pdu).await.is_err() {
            return;
        }
        let function = pdu[0];
        let address = u16::from_be_bytes([pdu[1], pdu[2]]);
        let quantity = u16::from_be_bytes([pdu[3], pdu[4]]);
        let mode = fake.mode.load(Ordering::Acquire);
        if function == 16 && address == 20 && pdu.len() >= 8 {
            let value = i16::from_be_bytes([pdu[6], pdu[7]]);
            fake.writes_to_20.lock().unwrap().push(value);
        }
        if mode == SILENT {
            continue;
        }
        let reply: Vec<u8> = match function {
            3 if mode == EXCEPTION && address == 2 => vec![0x83, 2],
            3 => {
                let count = if mode == SHORT_COUNT {
                    quantity - 1
                } else {
                    quantity
                };
                let mut reply = vec![3, (2 * count) as u8];
                for _ in 0..count {
                    reply.extend_from_slice(&VALUE.to_be_bytes());
                }
                reply
            }
            16 => {
                let echoed = if mode == WRONG_ECHO {
                    address + 1
                } else {
                    address
                };
                let mut reply = vec![16];
                reply.extend_from_slice(&echoed.to_be_bytes());
                reply.extend_from_slice(&quantity.to_be_bytes());
                reply
            }
            other => vec![other | 0x80, 1],
        };
        let mut frame = header[..4].to_vec();
        frame.extend_from_slice(&((reply.len() + 1) as u16).to_be_bytes());
        frame.push(header[6]);
        frame.extend_from_slice(&reply);
        if stream.write_all(&frame).await.is_err() {
            return;
        }
    }
}

#[test]
fn wrong_answers_are_invalid_data_exceptions_fail_one_request_and_nothing_panics() {
    let fake = Fake::default();
    let mode = Arc::clone(&fake.mode);
    mode.store(SHORT_COUNT, Ordering::Release);
    let (address, _slave) = fake_slave(&fake);
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler
        .load(image_with(vec![device(
            address,
            Schedule::Interval { interval_ms: 10 },
        )]))
        .unwrap();
    scheduler.start().unwrap();
    wait_until("short counts are invalid data", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::RESPONSE_INVALID_DATA
            && device.state == DeviceState::AnsweringWithErrors
            && device.errors > 5
    });
    // Every read was refused: the variables keep their initial values, the flag says so (from
    // the next cycle's start on).
    wait_until("the program sees the refused reads", || {
        read(&scheduler, "Main.xInError", 1) == [1]
    });
    assert_eq!(read_int(&scheduler, "Main.iIn"), 0);

    mode.store(RIGHT, Ordering::Release);
    wait_until("right answers deliver", || {
        read_int(&scheduler, "Main.iIn") == VALUE
            && first(&scheduler.modbus_devices()).state == DeviceState::Communicating
    });

    // A wrong echo: invalid data, and a new connection each time, since the stream may be
    // out of step (§4.2).
    mode.store(WRONG_ECHO, Ordering::Release);
    let errors = first(&scheduler.modbus_devices()).errors;
    let connections = fake.connections.load(Ordering::Acquire);
    wait_until("a wrong echo is invalid data, and the reads go on", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::RESPONSE_INVALID_DATA
            && device.errors > errors + 3
            && fake.connections.load(Ordering::Acquire) > connections + 3
    });
    wait_until("the reads' channel is not in error", || {
        read(&scheduler, "Main.xInError", 1) == [0]
    });

    mode.store(EXCEPTION, Ordering::Release);
    wait_until("an exception fails its request only", || {
        let device = first(&scheduler.modbus_devices());
        device.last_exception == 2 && device.last_error == 2
    });
    // The channel of the refused register is zeroed (set_to_zero), the other still delivers.
    wait_until("the refused channel is zeroed", || {
        read_int(&scheduler, "Main.iZeroed") == 0
    });
    // A stray timeout on a loaded machine passes with the next round: the state is waited for.
    wait_until(
        "the other channel delivers and the status says answering with errors",
        || {
            read(&scheduler, "Main.xInError", 1) == [0]
                && first(&scheduler.modbus_devices()).state == DeviceState::AnsweringWithErrors
                && read(&scheduler, "Main.stDevice", 4)[..2] == [1, 1]
        },
    );

    // A device that stops answering: a timeout ends the round, the connection is made anew.
    mode.store(SILENT, Ordering::Release);
    let connections = fake.connections.load(Ordering::Acquire);
    wait_until("silence is a timeout", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::RESPONSE_TIMEOUT
            && device.state == DeviceState::NotAnswering
            && device.consecutive_errors > 3
            && fake.connections.load(Ordering::Acquire) > connections + 1
    });
    // The program sees it at the next cycle's start.
    wait_until("the program sees the failure", || {
        read(&scheduler, "Main.xInError", 1) == [1] && read(&scheduler, "Main.stDevice", 1) == [0]
    });
    mode.store(RIGHT, Ordering::Release);
    wait_until("answers again", || {
        first(&scheduler.modbus_devices()).state == DeviceState::Communicating
    });
    scheduler.shutdown().unwrap();
}

#[test]
fn a_refused_connection_is_reported_and_backed_off() {
    // A port bound and never listened on: the kernel refuses every connection to it (a host
    // whose server has stopped), and no other test can take the port meanwhile.
    let reserved =
        socket2::Socket::new(socket2::Domain::IPV4, socket2::Type::STREAM, None).unwrap();
    reserved
        .bind(&std::net::SocketAddr::from(([127, 0, 0, 1], 0)).into())
        .unwrap();
    let address = reserved.local_addr().unwrap().as_socket().unwrap();
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler
        .load(image_with(vec![device(
            address,
            Schedule::Interval { interval_ms: 10 },
        )]))
        .unwrap();
    scheduler.start().unwrap();

    let refused = format!("connection refused by {address}");
    wait_until("the refusal is reported", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::TCP_COMMUNICATION_ERROR
            && device.state == DeviceState::NotAnswering
            && device.detail == refused
            && first_attempts(&scheduler) > 0
    });
    // A hundred rounds (a second at least): few attempts, as the back-off spaces them.
    let before = first(&scheduler.modbus_devices());
    let attempts_before = first_attempts(&scheduler);
    wait_until("a hundred rounds more", || {
        first(&scheduler.modbus_devices()).rounds >= before.rounds + 100
    });
    let after = first(&scheduler.modbus_devices());
    let attempts_after = first_attempts(&scheduler);
    let attempts = attempts_after - attempts_before;
    assert!(
        attempts <= ATTEMPTS_BACKED_OFF,
        "{attempts} connection attempts in {} rounds",
        after.rounds - before.rounds
    );
    // Every round not sent is counted as failed, with the refusal kept in words.
    assert!(
        after.consecutive_errors > before.consecutive_errors,
        "{after:?}"
    );
    assert_eq!(after.last_error, error_codes::TCP_COMMUNICATION_ERROR);
    assert_eq!(after.detail, refused);
    assert_eq!(after.requests, 0);
    // And the master goes on trying.
    wait_until("another attempt", || {
        first_attempts(&scheduler) > attempts_after
    });
    assert_eq!(read(&scheduler, "Main.xInError", 1), [1]);
    scheduler.shutdown().unwrap();
    drop(reserved);
}

/// The connection attempts of the scheduler's first Modbus device.
fn first_attempts(scheduler: &Scheduler) -> u32 {
    scheduler
        .modbus_connection_attempts()
        .first()
        .copied()
        .unwrap_or(0)
}
