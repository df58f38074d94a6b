//! The scheduler's thread never waits for a lock another thread holds: a test holds the located
//! areas or the status, the cycles go on meanwhile, and what they produced arrives once the
//! lock is released.

use std::sync::mpsc;
use std::time::Instant;

use super::tests::{MS, PATIENCE, dword, scheduler};
use super::*;
use program_image::Region;

use crate::areas::Area;
use crate::test_images::{TestTask, count, count_in_output, dint, image};

/// Receives cycle records until `cycles` more of task `task` ended.
#[track_caller]
fn cycles_end(records: &mpsc::Receiver<CycleRecord>, task: usize, cycles: usize) {
    let start = Instant::now();
    let mut ended = 0;
    while ended < cycles {
        assert!(
            start.elapsed() < PATIENCE,
            "{ended} of {cycles} cycles ended"
        );
        if let Ok(record) = records.recv_timeout(Duration::from_millis(10)) {
            ended += usize::from(record.task == task);
        }
    }
}

/// Default options with a cycle log, and its receiver.
fn logged() -> (SchedulerOptions, mpsc::Receiver<CycleRecord>) {
    let (sender, records) = mpsc::channel();
    let options = SchedulerOptions {
        cycle_log: Some(sender),
        ..SchedulerOptions::default()
    };
    (options, records)
}

#[test]
fn cycles_run_while_the_areas_are_held_and_their_data_arrives_once_released() {
    let (options, records) = logged();
    let (scheduler, areas) = scheduler(options);
    scheduler
        .load(image(&[TestTask::cyclic(MS, 1)], &[]))
        .unwrap();
    scheduler.start().unwrap();
    cycles_end(&records, 0, 3);
    let mut held = areas.lock().unwrap();
    let published = dword(&held.output, count_in_output(0));
    // A client's write while the program cannot take the areas in.
    held.write_bytes(Area::Memory, 0, &77_i32.to_le_bytes())
        .unwrap();
    cycles_end(&records, 0, 20);
    // Nothing was published meanwhile, and an action between cycles waits for the areas.
    assert_eq!(dword(&held.output, count_in_output(0)), published);
    let (answer, answered) = mpsc::channel();
    let asking = std::thread::scope(|scope| {
        scope.spawn(|| {
            let counted = scheduler.between(|between| {
                let memory = between.memory.as_ref().unwrap();
                (
                    dint(memory.engine.region(Region::Data), count(0)),
                    dword(&memory.areas.memory, 0),
                )
            });
            let _ = answer.send(counted);
        });
        cycles_end(&records, 0, 5);
        assert!(answered.try_recv().is_err(), "served without the areas");
        drop(held);
        answered.recv_timeout(PATIENCE).unwrap().unwrap()
    });
    // The program's count reached the areas, and the client's write the program.
    let (counted, written) = asking;
    assert!(counted > published + 20, "{published} then {counted}");
    assert_eq!(written, 77);
    let start = Instant::now();
    while dword(&areas.lock().unwrap().output, count_in_output(0)) < counted {
        assert!(start.elapsed() < PATIENCE, "the count was never published");
        std::thread::sleep(Duration::from_millis(1));
    }
    cycles_end(&records, 0, 2);
    let taken = scheduler
        .between(|between| {
            let memory = between.memory.as_ref().unwrap();
            dword(memory.engine.region(Region::Memory), 0)
        })
        .unwrap();
    assert_eq!(taken, 77, "the program never took the client's write in");
}

#[test]
fn cycles_run_while_the_status_is_held_and_their_statistics_and_faults_arrive_once_released() {
    let (options, records) = logged();
    let (scheduler, areas) = scheduler(options);
    // Task 1 loops past its watchdog once its trigger %MX4.0 rises.
    let faulting = TestTask {
        kind: program_image::TaskKind::Event,
        watchdog_ns: MS,
        body: crate::test_images::Body::Watch {
            iterations: i32::MAX,
            sets_trigger: false,
        },
        ..TestTask::cyclic(0, 5)
    };
    scheduler
        .load(image(&[TestTask::cyclic(MS, 1), faulting], &[]))
        .unwrap();
    // Start waits for the status, so it comes before holding it.
    scheduler.start().unwrap();
    let held = scheduler.status.lock().unwrap();
    let seen = held.tasks[0].cycles;
    areas
        .lock()
        .unwrap()
        .set_bit(Area::Memory, 4, 0, true)
        .unwrap();
    // Task 1 faults by its watchdog, and task 0 goes on, while nobody can publish.
    cycles_end(&records, 1, 1);
    cycles_end(&records, 0, 20);
    assert_eq!(held.tasks[0].cycles, seen);
    assert!(held.faults.is_empty());
    drop(held);
    cycles_end(&records, 0, 2);
    let status = scheduler.status();
    assert!(
        status.tasks[0].cycles >= seen + 20,
        "{seen} then {status:?}"
    );
    assert_eq!(status.faults.len(), 1, "{:?}", status.faults);
    assert_eq!(status.state, SchedulerState::Faulted);
}
