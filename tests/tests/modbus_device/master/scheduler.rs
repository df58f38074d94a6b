//! A program reads and writes a device through the scheduler's copy points; the device's server
//! stops and comes back (on a new port, behind a fault proxy that keeps the master's address)
//! while the task goes on.

use std::sync::{Arc, Mutex};

use program_image::modbus_master::Schedule;
use runtime::areas::LocatedAreas;
use runtime::modbus::master::{DeviceState, error_codes};
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tests::fault_proxy::{FaultProxy, ProxyMode};

use super::{Slave, device, first, image_with, read, read_int, read_udint, wait_until};

/// The status members the test looks at, by their offsets (§3.1).
struct Status {
    connected: bool,
    error: bool,
    last_error: u8,
    consecutive_errors: u32,
    rounds: u32,
}

fn status(scheduler: &Scheduler) -> Status {
    let bytes = read(scheduler, "Main.stDevice", 32);
    let word =
        |at: usize| u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    Status {
        connected: bytes[0] != 0,
        error: bytes[1] != 0,
        last_error: bytes[2],
        consecutive_errors: word(4),
        rounds: word(16),
    }
}

#[test]
fn a_program_reads_and_writes_a_device_and_recovers_when_its_server_comes_back() {
    let mut slave = Slave::start();
    slave.set(0, 21);
    slave.set(2, 5);
    let proxy = FaultProxy::start(slave.address).unwrap();
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler
        .load(image_with(vec![device(
            proxy.address(),
            Schedule::EveryCycle,
        )]))
        .unwrap();
    // Before the first round, the variables hold their initial values.
    assert_eq!(read_int(&scheduler, "Main.iZeroed"), 7);
    assert_eq!(status(&scheduler).last_error, 0);
    scheduler.start().unwrap();

    wait_until("the program reads 21 and the device gets 42", || {
        read_int(&scheduler, "Main.iOut") == 42 && slave.get(10) == 42
    });
    assert_eq!(read_int(&scheduler, "Main.iZeroed"), 5);
    slave.set(0, 50);
    wait_until("the device gets 100", || slave.get(10) == 100);
    wait_until("the status says connected without error", || {
        let seen = status(&scheduler);
        seen.connected && !seen.error
    });
    // Without any failure yet, the last error is none (a stray timeout on a loaded machine
    // would rightly be kept there).
    if first(&scheduler.modbus_devices()).errors == 0 {
        assert_eq!(status(&scheduler).last_error, error_codes::RESPONSE_SUCCESS);
    }
    let rounds = status(&scheduler).rounds;
    wait_until("rounds go on", || status(&scheduler).rounds > rounds + 3);
    wait_until("the device communicates", || {
        first(&scheduler.modbus_devices()).state == DeviceState::Communicating
    });

    // The server stops: the task goes on, the values stay, a set_to_zero channel is zeroed.
    // While the server is down the proxy completes each connection's handshake and resets it
    // at once, keeping its port meanwhile: the master's connection attempts succeed and its
    // requests fail, so it connects again at every round without backing off.
    proxy.set_mode(ProxyMode::Refuse);
    slave.stop();
    wait_until("the status says the connection is gone", || {
        let seen = status(&scheduler);
        !seen.connected
            && seen.error
            && seen.last_error == error_codes::TCP_COMMUNICATION_ERROR
            && seen.consecutive_errors > 2
    });
    let cycles = read_udint(&scheduler, "Main.udiCycles");
    let errors = status(&scheduler).consecutive_errors;
    wait_until("cycles and errors keep growing", || {
        read_udint(&scheduler, "Main.udiCycles") > cycles + 5
            && status(&scheduler).consecutive_errors > errors
    });
    assert_eq!(read_int(&scheduler, "Main.iIn"), 50);
    assert_eq!(read_int(&scheduler, "Main.iZeroed"), 0);
    assert_eq!(read(&scheduler, "Main.xInError", 1), [1]);
    let snapshot = first(&scheduler.modbus_devices());
    assert_eq!(snapshot.state, DeviceState::NotAnswering);
    assert!(
        snapshot.detail.contains(&proxy.address().to_string()),
        "{}",
        snapshot.detail
    );

    // It comes back, on a port of its own behind the proxy: values resume at the next round
    // (no back-off was started, as no connection attempt failed).
    slave.set(0, 8);
    slave.serve();
    proxy.set_slave(slave.address);
    proxy.set_mode(ProxyMode::Pass);
    wait_until("the device is read and written again", || {
        read_int(&scheduler, "Main.iOut") == 16 && slave.get(10) == 16
    });
    wait_until("the round without failure clears the error", || {
        let seen = status(&scheduler);
        seen.connected && !seen.error && seen.consecutive_errors == 0
    });
    assert_eq!(read(&scheduler, "Main.xInError", 1), [0]);
    assert_eq!(read_int(&scheduler, "Main.iZeroed"), 5);
    // The last failure's kind is kept for the user to read: the stopped server's, or a
    // timeout's if a request of the restart was late on a loaded machine.
    let kept = status(&scheduler).last_error;
    assert!(
        [
            error_codes::TCP_COMMUNICATION_ERROR,
            error_codes::RESPONSE_TIMEOUT
        ]
        .contains(&kept),
        "{kept:#x}"
    );
    scheduler.shutdown().unwrap();
}

#[test]
fn a_stopped_program_writes_nothing_and_an_interval_device_is_still_read() {
    let slave = Slave::start();
    slave.set(0, 3);
    slave.set(10, -1);
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler
        .load(image_with(vec![device(
            slave.address,
            Schedule::Interval { interval_ms: 20 },
        )]))
        .unwrap();
    // Stopped: rounds read the device (the counters grow), nothing is written, and no cycle
    // copies anything into the program.
    wait_until("rounds run while the program is stopped", || {
        first(&scheduler.modbus_devices()).rounds > 3
    });
    assert_eq!(slave.get(10), -1);
    assert_eq!(read_int(&scheduler, "Main.iIn"), 0);
    scheduler.start().unwrap();
    wait_until("the program runs with the device", || slave.get(10) == 6);
    scheduler.stop().unwrap();
    // A round begun before the stop may have sent its write already; the next one sends none.
    let stopped_at = first(&scheduler.modbus_devices()).rounds;
    wait_until("a round ends after the stop", || {
        first(&scheduler.modbus_devices()).rounds > stopped_at + 1
    });
    slave.set(10, -1);
    let rounds = first(&scheduler.modbus_devices()).rounds;
    wait_until("more rounds after the stop", || {
        first(&scheduler.modbus_devices()).rounds > rounds + 3
    });
    assert_eq!(slave.get(10), -1);
    // An image whose paths do not fit its program is refused, and the old one runs on.
    let mut wrong = image_with(vec![device(slave.address, Schedule::EveryCycle)]);
    if let Some(section) = wrong.modbus_master.as_mut() {
        section.devices[0].channels[0].variable = "Main.udiCycles".to_owned();
    }
    let refused = scheduler.load(wrong).unwrap_err().to_string();
    assert_eq!(
        refused,
        "the image is inconsistent: Modbus device 'Slave', channel 1 (Main.udiCycles), field variable: the channel carries INT values, but the variable's element type is UDINT"
    );
    assert_eq!(scheduler.modbus_devices().len(), 1);
    scheduler.shutdown().unwrap();
}

#[test]
fn a_stopped_program_s_every_cycle_device_is_still_polled() {
    let slave = Slave::start();
    slave.set(0, 3);
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler
        .load(image_with(vec![device(
            slave.address,
            Schedule::EveryCycle,
        )]))
        .unwrap();
    scheduler.start().unwrap();
    wait_until("the program runs with the device", || slave.get(10) == 6);
    // Stopped while its round waits for a cycle end that never comes: the device goes on
    // being polled at its task's pace (§6.10).
    scheduler.stop().unwrap();
    let rounds = first(&scheduler.modbus_devices()).rounds;
    wait_until("rounds go on after the stop", || {
        first(&scheduler.modbus_devices()).rounds > rounds + 3
    });
    scheduler.shutdown().unwrap();
}
