//! A task halted by the debugger, on the real clock: the others keep running, its outputs
//! keep their values, the watchdog does not trip, commands are served from inside the halt,
//! and stop abandons the halted cycle without a fault.

use std::time::Instant;

use program_image::{LineEntry, ProgramImage, Region};

use super::tests::{MS, PATIENCE, dword, scheduler, wait_for};
use super::*;
use crate::test_images::{TestTask, count, count_in_output, dint, image};

/// Two counting tasks every millisecond, the second with a 5 ms watchdog; each program's
/// first instruction starts a statement.
fn two_tasks() -> ProgramImage {
    let mut watched = TestTask::cyclic(MS, 2);
    watched.watchdog_ns = 5 * MS;
    let mut image = image(&[TestTask::cyclic(MS, 1), watched], &[]);
    for pou in &mut image.pous {
        pou.lines = vec![LineEntry {
            index: 0,
            file: 0,
            line: 1,
        }];
    }
    image
}

/// The cycle counts of both tasks in the data region, read by a command.
fn counts(scheduler: &Scheduler) -> [i32; 2] {
    scheduler
        .between(|between| {
            let memory = between.memory.as_ref().expect("a program");
            let data = memory.engine.region(Region::Data);
            [dint(data, count(0)), dint(data, count(1))]
        })
        .expect("served")
}

/// Whether task 1 is halted, asked through a command.
fn halted(scheduler: &Scheduler) -> bool {
    scheduler
        .between(|between| {
            between
                .memory
                .as_ref()
                .is_some_and(|memory| memory.engine.debug().is_halted(1))
        })
        .expect("served")
}

#[track_caller]
fn wait_until(what: &str, done: impl Fn() -> bool) {
    let start = Instant::now();
    while !done() {
        assert!(start.elapsed() < PATIENCE, "waited in vain for {what}");
        std::thread::sleep(Duration::from_millis(1));
    }
}

#[test]
fn a_halted_task_keeps_its_outputs_while_the_other_runs_and_its_watchdog_waits() {
    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    scheduler.load(two_tasks()).expect("loads");
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            memory.engine.debug_mut().begin_session();
            memory
                .engine
                .debug_mut()
                .halt_task(1)
                .expect("task 1 exists");
        })
        .expect("served");
    scheduler.start().expect("starts");
    wait_until("task 1 to halt", || halted(&scheduler));
    let at_halt = counts(&scheduler);
    let output = dword(&areas.lock().expect("areas").output, count_in_output(1));
    // Ten times the watchdog halted, while task 0 goes on.
    std::thread::sleep(Duration::from_millis(50));
    let later = counts(&scheduler);
    assert_eq!(later[1], at_halt[1], "the halted task ran");
    assert!(later[0] > at_halt[0] + 5, "{at_halt:?} then {later:?}");
    assert_eq!(
        dword(&areas.lock().expect("areas").output, count_in_output(1)),
        output
    );
    assert!(halted(&scheduler));
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            memory
                .engine
                .debug_mut()
                .continue_task(1)
                .expect("halted on top");
        })
        .expect("served");
    wait_until("task 1 to run on", || counts(&scheduler)[1] > later[1] + 3);
    let status = wait_for(&scheduler, "the status", |_| true);
    assert!(status.faults.is_empty(), "{:?}", status.faults);
    assert_eq!(status.state, SchedulerState::Running);
}

#[test]
fn stop_abandons_a_halted_cycle_without_a_fault() {
    let (scheduler, _areas) = scheduler(SchedulerOptions::default());
    scheduler.load(two_tasks()).expect("loads");
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            memory.engine.debug_mut().begin_session();
            memory
                .engine
                .debug_mut()
                .halt_task(1)
                .expect("task 1 exists");
        })
        .expect("served");
    scheduler.start().expect("starts");
    wait_until("task 1 to halt", || halted(&scheduler));
    let at_halt = counts(&scheduler);
    scheduler.stop().expect("stops");
    let status = scheduler.status();
    assert_eq!(status.state, SchedulerState::Stopped);
    assert!(status.faults.is_empty(), "{:?}", status.faults);
    // The rest of the halted cycle did not run.
    assert_eq!(counts(&scheduler)[1], at_halt[1]);
    assert!(!halted(&scheduler));
}

#[test]
fn halt_all_holds_every_task_with_one_halted_until_continue_all() {
    let (scheduler, _areas) = scheduler(SchedulerOptions::default());
    scheduler.load(two_tasks()).expect("loads");
    scheduler.start().expect("starts");
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            memory.engine.debug_mut().begin_session();
            memory.engine.debug_mut().halt_all();
        })
        .expect("served");
    let one_halted = |scheduler: &Scheduler| {
        scheduler
            .between(|between| {
                let memory = between.memory.as_ref().expect("a program");
                memory.engine.debug().halted().len()
            })
            .expect("served")
    };
    wait_until("one task to halt", || one_halted(&scheduler) == 1);
    let held = counts(&scheduler);
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(counts(&scheduler), held, "a held task ran");
    assert_eq!(one_halted(&scheduler), 1);
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            memory.engine.debug_mut().continue_all();
        })
        .expect("served");
    wait_until("both tasks to run on", || {
        let now = counts(&scheduler);
        now[0] > held[0] + 3 && now[1] > held[1] + 3
    });
}

#[test]
fn retained_values_are_saved_while_a_task_is_halted() {
    let dir = tempfile::tempdir().expect("a directory");
    let options = SchedulerOptions {
        data_dir: Some(dir.path().to_owned()),
        retain_save_interval: Duration::from_millis(10),
        ..SchedulerOptions::default()
    };
    let mut retained = image(&[TestTask::cyclic(MS, 1)], &[(count(0), 4)]);
    retained.pous[0].lines = vec![LineEntry {
        index: 0,
        file: 0,
        line: 1,
    }];
    let (scheduler, _areas) = scheduler(options);
    scheduler.load(retained.clone()).expect("loads");
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            memory.engine.debug_mut().begin_session();
            memory
                .engine
                .debug_mut()
                .halt_task(0)
                .expect("task 0 exists");
        })
        .expect("served");
    scheduler.start().expect("starts");
    let is_halted = || {
        scheduler
            .between(|between| {
                between
                    .memory
                    .as_ref()
                    .is_some_and(|memory| memory.engine.debug().is_halted(0))
            })
            .expect("served")
    };
    wait_until("task 0 to halt", is_halted);
    // A value written while halted reaches the retain file without another cycle.
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            let at = count(0) as usize;
            memory.engine.region_mut(Region::Data)[at..at + 4]
                .copy_from_slice(&4321_i32.to_le_bytes());
        })
        .expect("served");
    wait_until("the value saved", || {
        let mut engine = Engine::new(retained.clone()).expect("loads");
        crate::retain::RetainStore::new(dir.path()).restore(&mut engine);
        dint(engine.region(Region::Data), count(0)) == 4321
    });
    assert!(is_halted());
}
