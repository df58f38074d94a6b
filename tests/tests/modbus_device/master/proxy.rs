//! The fault proxy between the master and Rivet's own server (`docs/modbus-master.md` §4.2,
//! §10 item 5): a slow slave, a pulled cable and a stopped server, each with the task going on
//! and the values resuming afterwards.

use std::sync::Arc;
use std::time::Duration;

use program_image::modbus_master::Schedule;
use runtime::areas::LocatedAreas;
use runtime::modbus::master::{DeviceState, error_codes};
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tests::fault_proxy::{FaultProxy, ProxyMode};

use super::{Slave, device, first, image_with, read_int, read_udint, wait_until};

#[test]
fn a_slow_slave_a_pulled_cable_and_a_stopped_server_fail_and_recover() {
    let slave = Slave::start();
    slave.set(0, 11);
    let proxy = FaultProxy::start(slave.address).unwrap();
    let areas = Arc::new(std::sync::Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    // The device's timeout is 300 ms.
    scheduler
        .load(image_with(vec![device(
            proxy.address(),
            Schedule::Interval { interval_ms: 20 },
        )]))
        .unwrap();
    scheduler.start().unwrap();
    wait_until("the device is read through the proxy", || {
        read_int(&scheduler, "Main.iOut") == 22
    });
    let cycles_go_on = |what: &str| {
        let cycles = read_udint(&scheduler, "Main.udiCycles");
        wait_until(what, || {
            read_udint(&scheduler, "Main.udiCycles") > cycles + 5
        });
    };
    let resumes = |value: i16| {
        slave.set(0, value);
        wait_until("values resume", || {
            read_int(&scheduler, "Main.iOut") == 2 * value
                && first(&scheduler.modbus_devices()).state == DeviceState::Communicating
        });
    };

    // A slave three times slower than the timeout: timeouts, and a new connection each time.
    let connections = proxy.connections();
    proxy.set_mode(ProxyMode::Delay(Duration::from_millis(900)));
    wait_until("a slow slave times out", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::RESPONSE_TIMEOUT
            && device.state == DeviceState::NotAnswering
            && proxy.connections() > connections + 1
    });
    cycles_go_on("the task goes on while the slave is slow");
    proxy.set_mode(ProxyMode::Pass);
    resumes(12);

    // A pulled cable: nothing comes back and nothing is closed; requests time out, then the
    // connection attempts do (§4.2: as a timeout, then TCP_COMMUNICATION_ERROR).
    proxy.set_mode(ProxyMode::Swallow);
    wait_until("a pulled cable times out", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::RESPONSE_TIMEOUT
            && device.state == DeviceState::NotAnswering
    });
    wait_until("then its connection attempts time out", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::TCP_COMMUNICATION_ERROR
            && device.state == DeviceState::NotAnswering
            && device.detail.ends_with("within 1000 ms")
    });
    cycles_go_on("the task goes on without the cable");
    proxy.set_mode(ProxyMode::Pass);
    resumes(13);

    // A stopped server behind the proxy: each connection's handshake completes and the proxy
    // resets it at once, so the master's connection attempts succeed, its requests fail, and
    // it connects again at every round, without backing off (a real refusal, which starts the
    // back-off, is `a_refused_connection_is_reported_and_backed_off` in `faults.rs`).
    proxy.set_mode(ProxyMode::Refuse);
    wait_until("a stopped server is a communication error", || {
        let device = first(&scheduler.modbus_devices());
        device.last_error == error_codes::TCP_COMMUNICATION_ERROR
            && device.state == DeviceState::NotAnswering
            && device.consecutive_errors > 3
    });
    assert_eq!(read_int(&scheduler, "Main.iIn"), 13);
    cycles_go_on("the task goes on without the server");
    proxy.set_mode(ProxyMode::Pass);
    resumes(14);
    scheduler.shutdown().unwrap();
}
