//! A rising-edge write channel: sent once per edge of its trigger, with the value of the cycle
//! whose end saw the edge (`docs/modbus-master.md` §6.3).

use std::sync::Arc;
use std::sync::atomic::Ordering;

use program_image::modbus_master::{Direction, Schedule, Trigger};
use runtime::areas::LocatedAreas;
use runtime::scheduler::{Scheduler, SchedulerOptions};

use super::faults::{Fake, fake_slave};
use super::{channel, device, image_with, read_int, wait_until};

#[test]
fn a_rising_edge_channel_is_written_once_per_edge() {
    let fake = Fake::default();
    let (address, _slave) = fake_slave(&fake);
    let mut device = device(address, Schedule::Interval { interval_ms: 5 });
    let mut edge = channel("Main.iEdges", 20, Direction::Write);
    edge.trigger = Trigger::RisingEdge {
        variable: "Main.xSend".to_owned(),
    };
    device.channels.push(edge);
    let areas = Arc::new(std::sync::Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler.load(image_with(vec![device])).unwrap();
    scheduler.start().unwrap();
    wait_until("several edges were sent", || {
        fake.writes_to_20.load(Ordering::Acquire) >= 4
    });
    scheduler.stop().unwrap();
    // Stopped, no more edges come; a write in flight may still land.
    std::thread::sleep(std::time::Duration::from_millis(50));
    let edges = read_int(&scheduler, "Main.iEdges");
    let writes = fake.writes_to_20.load(Ordering::Acquire);
    // One write per edge at most (an edge is never sent twice), and edges are not lost while
    // the device answers: every edge but the last few reached it.
    assert!(
        i64::from(writes) <= i64::from(edges),
        "{writes} writes for {edges} edges"
    );
    assert!(writes >= 4);
    scheduler.shutdown().unwrap();
}
