//! An online change (`docs/modbus-master.md` §6.10): with the same section the master goes on
//! through the switch on its connection, with its paths resolved in the new program; with
//! another section the old master stops and the new one starts.

use std::sync::Arc;
use std::sync::atomic::Ordering;

use program_image::ProgramImage;
use program_image::modbus_master::{MasterSection, Schedule};
use runtime::areas::LocatedAreas;
use runtime::engine::{Engine, OnlineChangePlan};
use runtime::scheduler::{Scheduler, SchedulerOptions};

use super::faults::{Fake, fake_slave};
use super::{PROGRAM, compile, device, image_with, read_int, wait_until, write_int};

/// Changes the running program from `old` to `new` online.
fn change(scheduler: &Scheduler, old: &ProgramImage, new: ProgramImage) {
    let old_image = old.clone();
    let old_data = scheduler
        .between(move |between| {
            let memory = between.memory.as_ref().unwrap();
            memory.engine.region(program_image::Region::Data).to_vec()
        })
        .unwrap();
    let plan = OnlineChangePlan::new(&old_image, &old_data, &new);
    let (from, to) = (old.identity(), new.identity());
    let engine = Engine::new(new).unwrap();
    scheduler
        .online_change(engine, Arc::new(plan), from, to)
        .unwrap();
}

#[test]
fn an_equal_section_keeps_the_connection_and_follows_the_moved_variables() {
    let fake = Fake::default();
    let (address, _slave) = fake_slave(&fake);
    let mut section_device = device(address, Schedule::EveryCycle);
    // A timeout no loaded machine reaches, so that the connection count means the switch.
    section_device.timeout_ms = 10_000;
    let old = image_with(vec![section_device.clone()]);
    let areas = Arc::new(std::sync::Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler.load(old.clone()).unwrap();
    scheduler.start().unwrap();
    wait_until("the device is read", || {
        read_int(&scheduler, "Main.iIn") == 4
    });
    assert_eq!(fake.connections.load(Ordering::Acquire), 1);

    // A new variable takes the place iIn had; iIn moves.
    let moved = PROGRAM.replace("    iIn : INT;\n", "    iNew : INT;\n    iIn : INT;\n");
    let mut new = compile(&moved);
    new.modbus_master = old.modbus_master.clone();
    let offset =
        |image: &ProgramImage, path: &str| runtime::value::resolve(image, path).unwrap().offset;
    // The test means something only if the master's old place of iIn is iNew's now.
    assert_eq!(offset(&new, "Main.iNew"), offset(&old, "Main.iIn"));
    assert_ne!(offset(&new, "Main.iIn"), offset(&old, "Main.iIn"));
    change(&scheduler, &old, new.clone());
    let rounds = |scheduler: &Scheduler| scheduler.modbus_devices()[0].rounds;
    let before = rounds(&scheduler);
    wait_until("rounds go on after the switch", || {
        rounds(&scheduler) > before + 5
    });
    assert_eq!(read_int(&scheduler, "Main.iNew"), 0);
    assert_eq!(fake.connections.load(Ordering::Acquire), 1);
    // The change carried iIn's value by path, so its 4 says nothing of the master: cleared,
    // it gets the device's value again only if the copy follows iIn to its new place.
    write_int(&scheduler, "Main.iIn", 0);
    wait_until("the device's value reaches iIn at its new place", || {
        read_int(&scheduler, "Main.iIn") == 4
    });
    assert_eq!(read_int(&scheduler, "Main.iNew"), 0);

    // Another section: the master starts again, on a new connection.
    let mut other = section_device;
    other.timeout_ms += 1;
    let mut changed = new.clone();
    changed.modbus_master = Some(MasterSection {
        serial_ports: Vec::new(),
        devices: vec![other],
    });
    change(&scheduler, &new, changed);
    wait_until("the new master connects", || {
        fake.connections.load(Ordering::Acquire) >= 2
    });
    wait_until("and delivers", || scheduler.modbus_devices()[0].rounds > 3);
    write_int(&scheduler, "Main.iIn", 0);
    wait_until("the new master's values reach the program", || {
        read_int(&scheduler, "Main.iIn") == 4
    });
    scheduler.shutdown().unwrap();
}
