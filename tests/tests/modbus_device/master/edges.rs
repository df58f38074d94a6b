//! A rising-edge write channel: sent once per edge of its trigger, with the value of the cycle
//! whose end saw the edge (`docs/modbus-master.md` §6.3).

use std::sync::Arc;

use program_image::modbus_master::{Direction, Schedule, Trigger};
use runtime::areas::LocatedAreas;
use runtime::scheduler::{Scheduler, SchedulerOptions};

use super::faults::{Fake, fake_slave};
use super::{channel, device, first, image_with, read_int, wait_until};

#[test]
fn a_rising_edge_channel_is_written_once_per_edge() {
    let fake = Fake::default();
    let (address, _slave) = fake_slave(&fake);
    let mut device = device(address, Schedule::Interval { interval_ms: 5 });
    // A failed edge write is not repeated (§6.3): a long timeout keeps a loaded machine from
    // failing one.
    device.timeout_ms = 10_000;
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
        fake.writes_to_20.lock().unwrap().len() >= 4
    });
    scheduler.stop().unwrap();
    // A write in flight at the stop may still land; a round that ends after it sends none.
    let stopped_at = first(&scheduler.modbus_devices()).rounds;
    wait_until("a round ends after the stop", || {
        first(&scheduler.modbus_devices()).rounds > stopped_at + 1
    });
    let edges = read_int(&scheduler, "Main.iEdges");
    let writes = fake.writes_to_20.lock().unwrap().clone();
    // The program counts its edges in the cycle that sets the trigger, so the k-th edge's
    // write carries k, latched at that cycle's end: the writes carry increasing counts, each
    // an edge's own. Edges come 10 cycles apart, so a write per edge is the rule; two edges
    // are merged into one write only when the master stalls longer than that (§6.3), which
    // a loaded machine may do, so gaps are allowed but not a repeated or unknown count.
    assert!(writes.len() >= 4, "{writes:?}");
    assert!(
        writes.windows(2).all(|pair| pair[0] < pair[1]),
        "every write carries a later edge's count: {writes:?}"
    );
    assert!(
        writes.iter().all(|&count| count >= 1 && count <= edges),
        "writes {writes:?} for {edges} edges"
    );
    scheduler.shutdown().unwrap();
}
