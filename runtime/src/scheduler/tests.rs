//! The scheduler on its thread, on the real clock; every wait is bounded.

use std::time::Instant;

use program_image::TaskKind;

use super::*;
use crate::areas::Area;
use crate::test_images::{Body, TestTask, count_in_output, image, sequence_in_memory};

pub(super) const MS: u64 = 1_000_000;

/// How long a test waits for the scheduler before it fails.
pub(super) const PATIENCE: Duration = Duration::from_secs(10);

pub(super) fn scheduler(options: SchedulerOptions) -> (Scheduler, Arc<Mutex<LocatedAreas>>) {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    (
        Scheduler::spawn(Arc::clone(&areas), options).unwrap(),
        areas,
    )
}

/// Waits until the status satisfies `done`, and returns it.
#[track_caller]
pub(super) fn wait_for(
    scheduler: &Scheduler,
    what: &str,
    done: impl Fn(&SchedulerStatus) -> bool,
) -> SchedulerStatus {
    let start = Instant::now();
    loop {
        let status = scheduler.status();
        if done(&status) {
            return status;
        }
        assert!(
            start.elapsed() < PATIENCE,
            "waited in vain for {what}: {status:#?}"
        );
        std::thread::sleep(Duration::from_millis(1));
    }
}

pub(super) fn dword(bytes: &[u8], at: u32) -> i32 {
    let at = at as usize;
    i32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
}

#[test]
fn tasks_due_together_run_highest_priority_first() {
    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    // A minute's interval: only the first cycles run during the test.
    let tasks = [
        TestTask::cyclic(60_000 * MS, 5),
        TestTask::cyclic(60_000 * MS, 0),
        TestTask::cyclic(60_000 * MS, 2),
    ];
    scheduler.load(image(&tasks, &[])).unwrap();
    scheduler.start().unwrap();
    wait_for(&scheduler, "one cycle of each task", |status| {
        status.tasks.iter().all(|task| task.cycles == 1)
    });
    scheduler.stop().unwrap();
    let areas = areas.lock().unwrap();
    let sequence: Vec<i32> = (0..3)
        .map(|task| dword(&areas.memory, sequence_in_memory(task)))
        .collect();
    assert_eq!(sequence, [3, 1, 2]);
}

#[test]
fn a_cyclic_task_keeps_statistics_and_writes_its_outputs() {
    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    scheduler
        .load(image(&[TestTask::cyclic(2 * MS, 1)], &[]))
        .unwrap();
    assert_eq!(scheduler.status().state, SchedulerState::Stopped);
    scheduler.start().unwrap();
    assert_eq!(scheduler.status().state, SchedulerState::Running);
    wait_for(&scheduler, "50 cycles", |status| {
        status.tasks[0].cycles >= 50
    });
    scheduler.stop().unwrap();
    let status = scheduler.status();
    let task = &status.tasks[0];
    assert_eq!(status.state, SchedulerState::Stopped);
    assert!(task.min_cycle_ns <= task.average_cycle_ns());
    assert!(task.average_cycle_ns() <= task.max_cycle_ns);
    assert!(task.last_cycle_ns >= task.min_cycle_ns && task.last_cycle_ns <= task.max_cycle_ns);
    assert!(task.last_jitter_ns <= task.max_jitter_ns);
    println!(
        "2 ms task over {} cycles: cycle average {} ns, max {} ns; jitter average {} ns, max {} ns",
        task.cycles,
        task.average_cycle_ns(),
        task.max_cycle_ns,
        task.average_jitter_ns(),
        task.max_jitter_ns
    );
    let areas = areas.lock().unwrap();
    assert_eq!(dword(&areas.output, count_in_output(0)) as u64, task.cycles);
}

#[test]
fn a_native_endless_loop_is_ended_by_its_watchdog_at_a_backward_jump() {
    // Natively too, i32::MAX rounds of the slow loop take far longer than 10 ms.
    ended_by_a_native_watchdog(None, |areas| {
        areas
            .lock()
            .unwrap()
            .write_bytes(Area::Memory, 0, &i32::MAX.to_le_bytes())
            .unwrap();
    });
}

#[test]
fn a_native_while_true_is_ended_by_a_10_ms_watchdog() {
    use program_image::{BinaryOp, Elementary, Instr, Operand};
    // WHILE TRUE DO n := n + 1; END_WHILE: a loop without an exit.
    let n = Operand::Global(crate::test_images::count(0));
    let endless = vec![
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Elementary::Dint,
            dst: n,
            a: n,
            b: Operand::Const(0),
        },
        Instr::Jump { target: 0 },
    ];
    ended_by_a_native_watchdog(Some(endless), |_| {});
}

/// Task 0 (10 ms watchdog, every 100 ms) runs the slow program, or `code` in its place, under
/// the native engine beside a counting task every millisecond; `prepare` sets the located
/// areas before the start. The loop must end by the watchdog at a backward jump, and the
/// other task go on.
fn ended_by_a_native_watchdog(
    code: Option<Vec<program_image::Instr>>,
    prepare: impl FnOnce(&Arc<Mutex<LocatedAreas>>),
) {
    let options = SchedulerOptions {
        engine: EngineChoice::Native,
        ..SchedulerOptions::default()
    };
    let (scheduler, areas) = scheduler(options);
    let slow = TestTask {
        watchdog_ns: 10 * MS,
        watchdog_sensitivity: 1,
        body: Body::Slow,
        ..TestTask::cyclic(100 * MS, 3)
    };
    let mut image = image(&[slow, TestTask::cyclic(MS, 0)], &[]);
    if let Some(code) = code {
        image.pous[0].code = code;
    }
    let report = scheduler.load(image).unwrap();
    if jit::native_support().is_err() {
        // Nothing runs natively on this machine; the interpreter's watchdog is tested below.
        assert!(!report.native.runs_natively());
        return;
    }
    assert!(report.native.runs_natively(), "{:?}", report.native);
    assert!(report.native.fallbacks.is_empty(), "{:?}", report.native);
    prepare(&areas);
    scheduler.start().unwrap();
    let status = wait_for(&scheduler, "the watchdog", |status| {
        !status.faults.is_empty()
    });
    let fault = &status.faults[0];
    assert_eq!(fault.task, "Task0");
    assert_eq!(fault.pou, "Program0");
    assert_eq!(
        fault.kind,
        crate::engine::FaultKind::Watchdog { limit_us: 10_000 }
    );
    // The watchdog looks at the clock at a backward jump only.
    let image = scheduler
        .between(|between| between.memory.as_ref().unwrap().engine.shared_image())
        .unwrap();
    let pou = image
        .pous
        .iter()
        .find(|pou| pou.name == "Program0")
        .unwrap();
    assert!(
        matches!(
            pou.code[fault.instruction as usize],
            program_image::Instr::Jump { target } if target <= fault.instruction
        ),
        "{fault}: {:?}",
        pou.code[fault.instruction as usize]
    );
    // Machine code ran the loop.
    let entries = scheduler
        .between(|between| {
            between
                .memory
                .as_ref()
                .map_or(0, |memory| memory.engine.native_entries())
        })
        .unwrap();
    assert!(entries > 0);
    // The other task goes on.
    let cycles = status.tasks[1].cycles;
    wait_for(&scheduler, "the other task to go on", |status| {
        status.tasks[1].cycles >= cycles + 10
    });
}

#[test]
fn a_task_past_its_watchdog_faults_and_the_others_go_on() {
    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    let slow = TestTask {
        watchdog_ns: MS,
        watchdog_sensitivity: 2,
        body: Body::Slow,
        ..TestTask::cyclic(10 * MS, 3)
    };
    scheduler
        .load(image(&[slow, TestTask::cyclic(MS, 0)], &[]))
        .unwrap();
    // The slow task loops far longer than its watchdog allows.
    areas
        .lock()
        .unwrap()
        .write_bytes(Area::Memory, 0, &i32::MAX.to_le_bytes())
        .unwrap();
    scheduler.start().unwrap();
    let status = wait_for(&scheduler, "the watchdog", |status| {
        !status.faults.is_empty()
    });
    assert_eq!(status.state, SchedulerState::Faulted);
    let fault = &status.faults[0];
    assert_eq!(fault.task, "Task0");
    assert_eq!(fault.pou, "Program0");
    assert!(
        matches!(fault.kind, crate::engine::FaultKind::Watchdog { .. }),
        "{fault}"
    );
    assert!(status.tasks[0].faulted);
    let cycles = status.tasks[1].cycles;
    wait_for(&scheduler, "the other task to go on", |status| {
        status.tasks[1].cycles >= cycles + 10
    });
    assert_eq!(scheduler.status().tasks[0].cycles, status.tasks[0].cycles);
    // A reset clears the fault; the log keeps it.
    scheduler.reset(ResetKind::Warm).unwrap();
    let status = scheduler.status();
    assert_eq!(status.state, SchedulerState::Stopped);
    assert!(!status.tasks[0].faulted);
    assert_eq!(status.faults.len(), 1);
}

#[test]
fn an_event_task_runs_once_per_rising_edge_of_its_trigger() {
    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    let event = TestTask {
        kind: TaskKind::Event,
        ..TestTask::cyclic(0, 0)
    };
    scheduler
        .load(image(&[event, TestTask::cyclic(5 * MS, 1)], &[]))
        .unwrap();
    scheduler.start().unwrap();
    let set_trigger = |value: bool| {
        areas
            .lock()
            .unwrap()
            .set_bit(Area::Memory, 4, 0, value)
            .unwrap();
    };
    set_trigger(true);
    wait_for(&scheduler, "the first event", |status| {
        status.tasks[0].cycles == 1
    });
    set_trigger(false);
    // Looks at the trigger happen at least every millisecond.
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(scheduler.status().tasks[0].cycles, 1);
    set_trigger(true);
    wait_for(&scheduler, "the second event", |status| {
        status.tasks[0].cycles == 2
    });
}

#[test]
fn a_freewheeling_task_leaves_room_for_lower_priorities() {
    let (scheduler, _areas) = scheduler(SchedulerOptions::default());
    let free = TestTask {
        kind: TaskKind::Freewheeling,
        ..TestTask::cyclic(0, 0)
    };
    scheduler
        .load(image(&[free, TestTask::cyclic(MS, 31)], &[]))
        .unwrap();
    scheduler.start().unwrap();
    wait_for(&scheduler, "both tasks to run", |status| {
        status.tasks[0].cycles >= 20 && status.tasks[1].cycles >= 20
    });
}

#[test]
fn a_refused_image_leaves_the_running_program_alone() {
    let (scheduler, _areas) = scheduler(SchedulerOptions::default());
    assert!(matches!(scheduler.start(), Err(SchedulerError::NoProgram)));
    scheduler
        .load(image(&[TestTask::cyclic(MS, 1)], &[]))
        .unwrap();
    scheduler.start().unwrap();
    let mut broken = image(&[TestTask::cyclic(MS, 1)], &[]);
    broken.tasks[0].programs[0].pou = 7;
    let refused = scheduler.load(broken).unwrap_err();
    assert!(refused.to_string().contains("not a program"), "{refused}");
    let cycles = scheduler.status().tasks[0].cycles;
    wait_for(&scheduler, "the old program to go on", |status| {
        status.state == SchedulerState::Running && status.tasks[0].cycles > cycles + 5
    });
}

#[test]
fn retained_values_survive_a_restart_and_resets_treat_them_by_kind() {
    let dir = tempfile::tempdir().unwrap();
    let options = SchedulerOptions {
        data_dir: Some(dir.path().to_owned()),
        ..SchedulerOptions::default()
    };
    let retained = image(
        &[TestTask::cyclic(MS, 1)],
        &[(crate::test_images::count(0), 4)],
    );
    let (first, _) = scheduler(options.clone());
    let report = first.load(retained.clone()).unwrap();
    assert!(matches!(
        report.retain,
        Some(RetainRestore::NothingSaved { .. })
    ));
    first.start().unwrap();
    wait_for(&first, "10 cycles", |status| status.tasks[0].cycles >= 10);
    first.shutdown().unwrap();

    let (second, areas) = scheduler(options);
    let report = second.load(retained).unwrap();
    assert!(
        matches!(report.retain, Some(RetainRestore::Restored { .. })),
        "{report:?}"
    );
    second.start().unwrap();
    wait_for(&second, "a cycle", |status| status.tasks[0].cycles >= 1);
    second.stop().unwrap();
    let cycles = second.status().tasks[0].cycles;
    let counted = dword(&areas.lock().unwrap().output, 0) as u64;
    assert!(
        counted >= 10 + cycles,
        "counted {counted} after {cycles} cycles"
    );

    second.reset(ResetKind::Warm).unwrap();
    second.start().unwrap();
    wait_for(&second, "a cycle", |status| status.tasks[0].cycles >= 1);
    second.stop().unwrap();
    assert!(dword(&areas.lock().unwrap().output, 0) as u64 > counted);

    second.reset(ResetKind::Cold).unwrap();
    second.start().unwrap();
    wait_for(&second, "a cycle", |status| status.tasks[0].cycles >= 1);
    second.stop().unwrap();
    let after_cold = dword(&areas.lock().unwrap().output, 0) as u64;
    assert_eq!(after_cold, second.status().tasks[0].cycles);

    second.reset(ResetKind::Origin).unwrap();
    assert!(!dir.path().join(crate::retain::RETAIN_FILE).exists());
}

#[test]
fn retained_values_are_saved_periodically_while_running() {
    let dir = tempfile::tempdir().unwrap();
    let options = SchedulerOptions {
        data_dir: Some(dir.path().to_owned()),
        retain_save_interval: Duration::from_millis(10),
        ..SchedulerOptions::default()
    };
    let retained = image(
        &[TestTask::cyclic(MS, 1)],
        &[(crate::test_images::count(0), 4)],
    );
    let (scheduler, _areas) = scheduler(options);
    scheduler.load(retained.clone()).unwrap();
    scheduler.start().unwrap();
    let file = dir.path().join(crate::retain::RETAIN_FILE);
    let start = Instant::now();
    while !file.exists() {
        assert!(start.elapsed() < PATIENCE, "no periodic save");
        std::thread::sleep(Duration::from_millis(2));
    }
    assert_eq!(scheduler.status().state, SchedulerState::Running);
    assert_eq!(scheduler.status().retain_problem, None);
    // The file is whole while the scheduler keeps writing it.
    let mut engine = Engine::new(retained).unwrap();
    let restored = crate::retain::RetainStore::new(dir.path()).restore(&mut engine);
    assert!(
        matches!(restored, RetainRestore::Restored { .. }),
        "{restored}"
    );
}

#[test]
fn cycles_that_finish_past_the_watchdog_time_fault_the_task_at_the_sensitivity() {
    let (scheduler, _areas) = scheduler(SchedulerOptions::default());
    // Every cycle takes longer than 1 ns, and without a loop the engine never looks at its
    // clock: only the scheduler's count of overruns can stop the task.
    let watched = TestTask {
        watchdog_ns: 1,
        watchdog_sensitivity: 3,
        ..TestTask::cyclic(MS, 0)
    };
    scheduler.load(image(&[watched], &[])).unwrap();
    scheduler.start().unwrap();
    let status = wait_for(&scheduler, "the watchdog", |status| {
        !status.faults.is_empty()
    });
    let fault = &status.faults[0];
    assert_eq!(
        fault.kind,
        crate::engine::FaultKind::Watchdog { limit_us: 0 }
    );
    assert_eq!((fault.cycle, status.tasks[0].cycles), (2, 3));
    assert_eq!(status.tasks[0].consecutive_overruns, 3);
    assert_eq!(
        fault.to_string(),
        "task 'Task0' stopped: watchdog: the cycle ran longer than 0 µs in Program0 (instruction 0)"
    );
}

#[test]
fn a_forced_count_holds_before_and_after_every_cycle_and_a_load_releases_it() {
    use crate::test_images::count;
    use online_protocol::Place;

    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    let tasks = [TestTask::cyclic(MS, 1)];
    scheduler.load(image(&tasks, &[])).unwrap();
    let counted = Place {
        region: 0,
        offset: count(0),
        bit: None,
        size: 4,
    };
    let output = Place {
        region: 2,
        offset: count_in_output(0),
        bit: None,
        size: 4,
    };
    let forced = scheduler
        .between(move |between| {
            between.forces.set(counted, 7i32.to_le_bytes().to_vec());
            between.cycles
        })
        .unwrap();
    scheduler.start().unwrap();
    wait_for(&scheduler, "ten cycles", |status| {
        status.tasks[0].cycles >= 10
    });
    let (cycles, value, copied) = scheduler
        .between(move |between| {
            let memory = between.memory.as_ref().unwrap();
            (between.cycles, memory.read(counted), memory.read(output))
        })
        .unwrap();
    assert!(cycles >= forced + 10);
    assert_eq!(value, 7i32.to_le_bytes());
    // Within the cycle the program added one to the forced count and copied that out.
    assert_eq!(copied, 8i32.to_le_bytes());
    scheduler.load(image(&tasks, &[])).unwrap();
    wait_for(&scheduler, "cycles of the new program", |status| {
        status.tasks[0].cycles >= 20
    });
    assert!(dword(&areas.lock().unwrap().output, count_in_output(0)) >= 19);
}
