//! Preemption on the real clock, under both engines. Who interrupted whom is read from the
//! cycle log and from the programs' own notes; no assertion depends on how fast this machine
//! is, except that the watchdog test sizes its loops from a measurement with wide margins: a
//! cycle that must be interrupted waits for the interrupting task's cycles ([`Body::WaitFor`])
//! rather than looping for a time sized to one engine, and a cycle that must not be interrupted
//! lasts a time by the clock ([`Body::Lasting`]), during which the log shows the other task
//! come due. Where a safe point is reached (a back-edge, a call) is shown on the engine alone,
//! with a hook standing in for the scheduler.

use std::sync::mpsc;
use std::time::Instant;

use online_protocol::{Place, TraceConfig, TriggerKind};
use program_image::{Region, TaskKind};

use super::tests::{MS, PATIENCE, dword, scheduler, wait_for};
use super::*;
use crate::test_images::{
    Body, TestTask, count, count_in_output, dint, image, seen_at_end, seen_at_start, watch_counter,
};

/// A loop long enough that a task every millisecond comes due while it runs, even in an
/// optimised build.
const LONG: i32 = 1_000_000;

/// The milliseconds a lasting cycle runs: twenty periods of a task every millisecond.
const LASTING_MS: i32 = 20;

/// An interval longer than any test: the task runs once, when started.
const MINUTE: u64 = 60_000 * MS;

/// A watching task of `priority` looping `iterations` times every `interval_ns`.
fn watch(iterations: i32, interval_ns: u64, priority: u8) -> TestTask {
    TestTask {
        body: Body::Watch {
            iterations,
            sets_trigger: false,
        },
        ..TestTask::cyclic(interval_ns, priority)
    }
}

/// A task of `priority` whose one cycle (it runs once) lasts [`LASTING_MS`] by the clock.
fn lasting(priority: u8) -> TestTask {
    TestTask {
        body: Body::Lasting { ms: LASTING_MS },
        ..TestTask::cyclic(MINUTE, priority)
    }
}

/// Both engines, for the tests that run under each; the native engine falls back to the
/// interpreter on a machine without a native code generator, which [`loaded`] checks.
const ENGINES: [EngineChoice; 2] = [EngineChoice::Interpreter, EngineChoice::Native];

/// A task of `priority` whose one cycle (it runs once) waits until task `task` has run
/// `cycles` cycles after it started.
fn waiting_for(task: usize, cycles: i32, priority: u8) -> TestTask {
    TestTask {
        body: Body::WaitFor {
            task,
            cycles,
            sets_trigger: false,
        },
        ..TestTask::cyclic(MINUTE, priority)
    }
}

/// Loads `image` in `scheduler` and checks that it runs under `engine` as chosen: natively
/// for every POU where this machine makes machine code.
#[track_caller]
fn loaded(scheduler: &Scheduler, image: ProgramImage, engine: EngineChoice) {
    let report = scheduler.load(image).unwrap();
    assert_eq!(report.native.chosen, engine);
    if engine == EngineChoice::Native && jit::native_support().is_ok() {
        assert!(report.native.runs_natively(), "{:#?}", report.native);
        assert!(report.native.fallbacks.is_empty(), "{:#?}", report.native);
    } else {
        assert!(!report.native.runs_natively(), "{:#?}", report.native);
    }
}

/// Default options with a cycle log for `engine`, and the log's receiver.
fn logged_in(
    preemption: bool,
    engine: EngineChoice,
) -> (SchedulerOptions, mpsc::Receiver<CycleRecord>) {
    let (sender, records) = mpsc::channel();
    let options = SchedulerOptions {
        preemption,
        cycle_log: Some(sender),
        engine,
        ..SchedulerOptions::default()
    };
    (options, records)
}

/// The DINTs at `offsets` of the data region, read between two cycles.
fn data(scheduler: &Scheduler, offsets: &[u32]) -> Vec<i32> {
    let offsets = offsets.to_vec();
    scheduler
        .between(move |between| {
            let data = between.memory.as_ref().unwrap().engine.region(Region::Data);
            offsets.iter().map(|&offset| dint(data, offset)).collect()
        })
        .unwrap()
}

/// Waits for records until `done` holds for those received so far, and returns them.
#[track_caller]
fn records_until(
    records: &mpsc::Receiver<CycleRecord>,
    what: &str,
    done: impl Fn(&[CycleRecord]) -> bool,
) -> Vec<CycleRecord> {
    let start = Instant::now();
    let mut received = Vec::new();
    while !done(&received) {
        assert!(
            start.elapsed() < PATIENCE,
            "waited in vain for {what}: {received:#?}"
        );
        if let Ok(record) = records.recv_timeout(Duration::from_millis(10)) {
            received.push(record);
        }
    }
    received
}

/// The record of task 0's cycle among `received`, if it ended.
fn cycle_of_task_0(received: &[CycleRecord]) -> Option<&CycleRecord> {
    received.iter().find(|record| record.task == 0)
}

/// Whether task 0's cycle ended and a cycle of task 1 started after it, so that `received`
/// holds every cycle of task 1 that was due while task 0's ran.
fn followed(received: &[CycleRecord]) -> bool {
    cycle_of_task_0(received).is_some_and(|long| {
        received
            .iter()
            .any(|record| record.task == 1 && record.started_ns >= long.ended_ns)
    })
}

/// Checks that a cycle of task 1 was due before task 0's cycle ended and started only after
/// it: it waited for that cycle, however fast the engine ran it.
#[track_caller]
fn waited_for_task_0(received: &[CycleRecord], case: &str) {
    let long = cycle_of_task_0(received).unwrap();
    assert!(
        received.iter().any(|record| record.task == 1
            && record.planned_ns < long.ended_ns
            && record.started_ns >= long.ended_ns),
        "{case}: task 1 did not wait for task 0: {received:#?}"
    );
}

#[test]
fn a_higher_priority_task_runs_inside_a_long_cycle_of_a_lower_one_only_with_preemption() {
    for engine in ENGINES {
        for preemption in [true, false] {
            let (options, records) = logged_in(preemption, engine);
            let (scheduler, _areas) = scheduler(options);
            // Task 0 (priority 10, once) waits for three cycles of task 1, which counts the
            // sequence every millisecond: with preemption those cycles can only run nested in
            // it. Without, task 0 lasts LASTING_MS instead (waiting would never end), during
            // which task 1 comes due, and nothing may run inside it.
            let low = if preemption {
                waiting_for(1, 3, 10)
            } else {
                lasting(10)
            };
            loaded(
                &scheduler,
                image(&[low, TestTask::cyclic(MS, 1)], &[]),
                engine,
            );
            scheduler.start().unwrap();
            let received = records_until(&records, "the long cycle and one after", followed);
            scheduler.stop().unwrap();
            let noted = data(
                &scheduler,
                &[seen_at_start(0), seen_at_end(0), watch_counter(0), count(0)],
            );
            let nested = received
                .iter()
                .filter(|record| record.task == 1 && record.interrupted == Some(0))
                .count();
            let case = format!("{engine:?}, preemption {preemption}");
            if preemption {
                // At least three cycles of task 1 ran nested, between the two notes of its
                // cycle count (one more may have run at the call of the program, before the
                // first note).
                assert_eq!(noted[3], 1, "{case}");
                let counted = usize::try_from(noted[1] - noted[0]).unwrap();
                assert!(
                    counted >= 3 && counted <= nested,
                    "{case}: {noted:?}, {nested} nested"
                );
            } else {
                // The long cycle lasted its time, during which task 1 came due; its own
                // results are whole.
                assert!(noted[2] >= LASTING_MS, "{case}: {noted:?}");
                waited_for_task_0(&received, &case);
                assert_eq!(noted[3], 1, "{case}");
                assert_eq!((noted[0], nested), (noted[1], 0), "{case}");
            }
        }
    }
}

#[test]
fn a_task_of_equal_priority_waits_for_the_running_cycle() {
    for engine in ENGINES {
        let (options, records) = logged_in(true, engine);
        let (scheduler, _areas) = scheduler(options);
        // Both are due at the start; the first in the task table runs first and lasts
        // LASTING_MS, while task 1 (every millisecond) is due.
        let tasks = [lasting(5), TestTask::cyclic(MS, 5)];
        loaded(&scheduler, image(&tasks, &[]), engine);
        scheduler.start().unwrap();
        let received = records_until(&records, "the long cycle and one after", followed);
        scheduler.stop().unwrap();
        let noted = data(&scheduler, &[seen_at_start(0), seen_at_end(0)]);
        assert_eq!(noted[0], noted[1], "{engine:?}");
        waited_for_task_0(&received, &format!("{engine:?}"));
        assert!(
            received.iter().all(|record| record.interrupted.is_none()),
            "{engine:?}: {received:#?}"
        );
    }
}

#[test]
fn three_priorities_nest() {
    for engine in ENGINES {
        let (options, records) = logged_in(true, engine);
        let (scheduler, _areas) = scheduler(options);
        // The highest task counts every millisecond. The middle one comes every 100 ms; its
        // first cycle waits for four cycles of the highest, which run nested in it. The lowest
        // starts after that and waits for one more cycle of the middle task, which can only
        // run nested in it, 100 ms later.
        let middle = TestTask {
            interval_ns: 100 * MS,
            ..waiting_for(2, 4, 10)
        };
        let tasks = [waiting_for(1, 1, 20), middle, TestTask::cyclic(MS, 1)];
        loaded(&scheduler, image(&tasks, &[]), engine);
        scheduler.start().unwrap();
        records_until(&records, "two levels of nesting", |received| {
            let interrupted = |task, by| {
                received
                    .iter()
                    .any(|record| record.task == by && record.interrupted == Some(task))
            };
            interrupted(1, 2) && interrupted(0, 1)
        });
        scheduler.stop().unwrap();
    }
}

#[test]
fn a_fault_of_a_preempting_task_leaves_the_interrupted_cycle_going() {
    for engine in ENGINES {
        let (options, records) = logged_in(true, engine);
        let (scheduler, _areas) = scheduler(options);
        // Task 0 (priority 10, once) first sets the trigger of event task 1 (priority 1), so
        // task 1 can only run once task 0's cycle has started, then waits for one cycle of it,
        // which runs nested at the next look at the triggers. That cycle overruns its 1 ns
        // watchdog, which faults task 1 at once (sensitivity 1). Should task 1 never come,
        // task 0's own watchdog ends its cycle, and the test fails rather than hangs.
        let low = TestTask {
            watchdog_ns: 2_000 * MS,
            body: Body::WaitFor {
                task: 1,
                cycles: 1,
                sets_trigger: true,
            },
            ..TestTask::cyclic(MINUTE, 10)
        };
        let failing = TestTask {
            kind: TaskKind::Event,
            watchdog_ns: 1,
            ..TestTask::cyclic(0, 1)
        };
        loaded(&scheduler, image(&[low, failing], &[]), engine);
        scheduler.start().unwrap();
        let status = wait_for(&scheduler, "the long cycle", |status| {
            status.tasks[0].cycles == 1
        });
        scheduler.stop().unwrap();
        assert_eq!(status.state, SchedulerState::Faulted, "{engine:?}");
        assert!(
            status.tasks[1].faulted && !status.tasks[0].faulted,
            "{engine:?}: {status:#?}"
        );
        assert_eq!(status.tasks[1].cycles, 1, "{engine:?}");
        assert_eq!(status.faults.len(), 1, "{engine:?}");
        assert_eq!(status.faults[0].task, "Task1", "{engine:?}");
        assert!(
            matches!(
                status.faults[0].kind,
                crate::engine::FaultKind::Watchdog { .. }
            ),
            "{engine:?}: {:?}",
            status.faults[0]
        );
        let preempting: Vec<CycleRecord> = records
            .try_iter()
            .filter(|record| record.task == 1)
            .collect();
        assert_eq!(preempting.len(), 1, "{engine:?}: {preempting:#?}");
        assert_eq!(preempting[0].interrupted, Some(0), "{engine:?}");
        // The interrupted cycle went on to its end after the fault: it noted task 1's count
        // before (0) and after (1) the nested cycle, and counted itself.
        let noted = data(
            &scheduler,
            &[seen_at_start(0), seen_at_end(0), count(1), count(0)],
        );
        assert_eq!(noted, [0, 1, 1, 1], "{engine:?}");
    }
}

/// Nanoseconds one iteration of a watching task's loop takes here in `engine`: the fastest of
/// a few runs.
fn iteration_ns(engine: EngineChoice) -> f64 {
    const ITERATIONS: i32 = 100_000;
    let (mut engine, _) =
        Engine::with_choice(image(&[watch(ITERATIONS, MS, 1)], &[]), engine).unwrap();
    let fastest = (0..5)
        .map(|cycle| {
            let start = Instant::now();
            engine.run_cycle(0, 0, cycle).unwrap();
            start.elapsed().as_nanos() as f64
        })
        .fold(f64::MAX, f64::min);
    fastest / f64::from(ITERATIONS)
}

#[test]
fn time_spent_in_preempting_tasks_does_not_count_against_the_watchdog() {
    preempting_time_is_not_counted(EngineChoice::Interpreter);
}

#[test]
fn a_native_cycle_is_interrupted_at_a_back_edge_and_the_interruption_is_not_counted() {
    preempting_time_is_not_counted(EngineChoice::Native);
}

/// Sizes the loops by a measurement in `engine`, then runs them in a scheduler with `engine`.
fn preempting_time_is_not_counted(engine: EngineChoice) {
    let per_iteration = iteration_ns(engine);
    let iterations = |ms: f64| (ms * 1e6 / per_iteration) as i32;
    let watchdog_ns = 150 * MS;
    // Task 0 sets the trigger of event task 1 and does about 20 ms of its own work under a
    // 150 ms watchdog; task 1 interrupts it once (when the next look at the triggers finds the
    // edge) with about 800 ms of work. The margins are wide both ways, as other tests load the
    // machine meanwhile.
    let low = TestTask {
        watchdog_ns,
        watchdog_sensitivity: 1,
        body: Body::Watch {
            iterations: iterations(20.0),
            sets_trigger: true,
        },
        ..TestTask::cyclic(MINUTE, 10)
    };
    let high = TestTask {
        kind: TaskKind::Event,
        ..watch(iterations(800.0), 0, 1)
    };
    let (options, records) = logged_in(true, engine);
    let (scheduler, _areas) = scheduler(options);
    let report = scheduler.load(image(&[low, high], &[])).unwrap();
    // Where this machine makes machine code, the native run must really be native, or the
    // test would measure the interpreter twice.
    if engine == EngineChoice::Native && jit::native_support().is_ok() {
        assert!(report.native.runs_natively(), "{:#?}", report.native);
        assert!(report.native.fallbacks.is_empty(), "{:#?}", report.native);
    }
    assert_eq!(report.native.chosen, engine);
    scheduler.start().unwrap();
    let received = records_until(&records, "the low cycle", |received| {
        received.iter().any(|record| record.task == 0)
    });
    let status = scheduler.status();
    scheduler.stop().unwrap();
    assert!(status.faults.is_empty(), "{:#?}", status.faults);
    let low = received.iter().find(|record| record.task == 0).unwrap();
    let high = received.iter().find(|record| record.task == 1).unwrap();
    assert_eq!(high.interrupted, Some(0));
    assert!(
        low.ended_ns - low.started_ns > watchdog_ns,
        "the interruption was shorter than designed: {low:?}"
    );
    assert!(status.tasks[0].last_cycle_ns < watchdog_ns);
    assert_eq!(status.tasks[0].last_cycle_ns, low.own_ns());
}

#[test]
fn forces_hold_and_the_trace_samples_in_nested_cycles() {
    forces_hold_in_nested_cycles(EngineChoice::Interpreter, LONG);
}

#[test]
fn forces_hold_and_the_trace_samples_in_nested_cycles_of_the_native_engine() {
    // The long cycle is sized by measurement, as the native engine runs LONG iterations in a
    // fraction of the interpreter's time: about 100 ms, a hundred periods of the 1 ms task.
    let iterations = (100.0 * 1e6 / iteration_ns(EngineChoice::Native)) as i32;
    forces_hold_in_nested_cycles(EngineChoice::Native, iterations.max(LONG));
}

/// A forced place holds, and the trace samples it, in the cycles of a 1 ms task nested in a
/// cycle of `long_iterations` of a lower one, both run by `engine`.
fn forces_hold_in_nested_cycles(engine: EngineChoice, long_iterations: i32) {
    let (options, records) = logged_in(true, engine);
    let (scheduler, areas) = scheduler(options);
    let tasks = [watch(long_iterations, MINUTE, 10), TestTask::cyclic(MS, 1)];
    let report = scheduler.load(image(&tasks, &[])).unwrap();
    if engine == EngineChoice::Native && jit::native_support().is_ok() {
        assert!(report.native.runs_natively(), "{:#?}", report.native);
        assert!(report.native.fallbacks.is_empty(), "{:#?}", report.native);
    }
    let counted = Place {
        region: 0,
        offset: count(1),
        bit: None,
        size: 4,
    };
    scheduler
        .between(move |between| {
            between.forces.set(counted, 7i32.to_le_bytes().to_vec());
            between.trace.configure(TraceConfig {
                task: 1,
                every: 1,
                samples: 100_000,
                pretrigger: 0,
                trigger: TriggerKind::None,
                trigger_place: counted,
                places: vec![counted],
            });
            assert!(between.trace.arm());
        })
        .unwrap();
    scheduler.start().unwrap();
    wait_for(&scheduler, "the long cycle", |status| {
        status.tasks[0].cycles == 1
    });
    scheduler.stop().unwrap();
    // The cycle numbers (from 1) of the counting task's cycles that ran nested.
    let nested: Vec<u64> = records
        .try_iter()
        .filter(|record| record.task == 1)
        .zip(1..)
        .filter(|(record, _)| record.interrupted == Some(0))
        .map(|(_, cycle)| cycle)
        .collect();
    assert!(!nested.is_empty());
    let samples: Vec<(u64, Vec<u8>)> = scheduler
        .between(|between| {
            between
                .trace
                .samples()
                .map(|sample| (sample.cycle, sample.values.clone()))
                .collect()
        })
        .unwrap();
    for cycle in nested {
        assert!(
            samples.contains(&(cycle, 7i32.to_le_bytes().to_vec())),
            "no sample of nested cycle {cycle} with the forced value"
        );
    }
    // Within each cycle the program added one to the forced count and copied that out.
    assert_eq!(dword(&areas.lock().unwrap().output, count_in_output(1)), 8);
}

/// Where the hand-made programs below note that their body started.
const STARTED: u32 = seen_at_start(0);
/// Where they note the sequence counter at their end.
const ENDED: u32 = seen_at_end(0);
/// Their loop counter, or the sequence counter before their call.
const NOTED: u32 = watch_counter(0);
/// Where the loop's test goes, or where the called function notes that it ran.
const SCRATCH: u32 = watch_counter(0) + 4;

/// The scheduler's part for [`interrupted`]: at the first safe point after the program's body
/// started, notes the DINT at [`NOTED`] and [`SCRATCH`] and runs one cycle of counting task 1
/// on the interrupted cycle's memory, as the scheduler runs a task that became due.
struct Interrupter<'d> {
    due: &'d std::sync::atomic::AtomicBool,
    /// The DINTs at [`NOTED`] and [`SCRATCH`] at each interruption.
    seen: Vec<(i32, i32)>,
}

impl crate::engine::Preempt for Interrupter<'_> {
    fn preempt(&mut self, mut engine: crate::engine::EngineView<'_>) {
        let data = engine.region(Region::Data);
        // The safe point at the program's own call comes before its body: the task stays due.
        if dint(data, STARTED) == 0 {
            return;
        }
        self.seen.push((dint(data, NOTED), dint(data, SCRATCH)));
        engine
            .run_cycle(1, 0, crate::engine::TaskClock::Simulated, 0, None)
            .unwrap();
        self.due.store(false, std::sync::atomic::Ordering::Relaxed);
    }
}

/// Task 0 runs `code` (and POU 2 is a function doing `called`) once under `engine` with task 1
/// (counting) due from the start; returns the interruptions the hook saw, the data region after
/// the cycle, and how often machine code was entered.
fn interrupted(
    engine: EngineChoice,
    code: Vec<program_image::Instr>,
    called: Vec<program_image::Instr>,
) -> (Vec<(i32, i32)>, Vec<u8>, u64) {
    let mut image = image(&[TestTask::cyclic(MS, 10), TestTask::cyclic(MS, 1)], &[]);
    image.pous[0].code = code;
    image.pous.push(program_image::Pou {
        name: "Called".to_owned(),
        kind: program_image::PouKind::Function,
        frame_size: 0,
        frame_init: Vec::new(),
        instance_size: 0,
        code: called,
        lines: Vec::new(),
    });
    // Const(16): the loop's 10 iterations.
    image.constants.extend(10_i32.to_le_bytes());
    let (mut engine, report) = Engine::with_choice(image, engine).unwrap();
    if report.chosen == EngineChoice::Native {
        assert_eq!(
            report.runs_natively(),
            jit::native_support().is_ok(),
            "{report:#?}"
        );
        assert!(report.fallbacks.is_empty(), "{report:#?}");
    }
    let due = std::sync::atomic::AtomicBool::new(true);
    let mut hook = Interrupter {
        due: &due,
        seen: Vec::new(),
    };
    engine
        .view()
        .run_cycle(
            0,
            0,
            crate::engine::TaskClock::Simulated,
            0,
            Some(crate::engine::Preemption {
                due: &due,
                hook: &mut hook,
            }),
        )
        .unwrap();
    let seen = hook.seen;
    let data = engine.region(Region::Data).to_vec();
    (seen, data, engine.native_entries())
}

/// `place := src` on DINTs.
fn set(place: u32, src: program_image::Operand) -> program_image::Instr {
    program_image::Instr::Move {
        ty: program_image::Elementary::Dint,
        dst: program_image::Operand::Global(place),
        src,
    }
}

/// Checks that the native run entered machine code where this machine makes it, and left the
/// same data as the interpreter's.
#[track_caller]
fn as_interpreted(
    native: &(Vec<(i32, i32)>, Vec<u8>, u64),
    interpreted: &(Vec<(i32, i32)>, Vec<u8>, u64),
) {
    assert_eq!(interpreted.2, 0);
    if jit::native_support().is_ok() {
        assert!(native.2 > 0, "no machine code was entered");
    }
    assert_eq!(native.0, interpreted.0);
    assert!(native.1 == interpreted.1, "the data regions differ");
}

#[test]
fn a_cycle_is_interrupted_at_its_first_loop_back_edge_under_both_engines() {
    use program_image::{CompareOp, Elementary, Instr, Operand};
    let (one, zero, ten) = (Operand::Const(0), Operand::Const(4), Operand::Const(16));
    let counter = Operand::Global(NOTED);
    let done = Operand::Global(SCRATCH);
    // started := 1; i := 0; REPEAT i := i + 1 UNTIL i >= 10; ended := sequence.
    let code = vec![
        set(STARTED, one),
        set(NOTED, zero),
        Instr::Binary {
            op: program_image::BinaryOp::Add,
            ty: Elementary::Dint,
            dst: counter,
            a: counter,
            b: one,
        },
        Instr::Compare {
            op: CompareOp::Ge,
            ty: Elementary::Dint,
            dst: done,
            a: counter,
            b: ten,
        },
        Instr::JumpIfNot {
            cond: done,
            target: 2,
        },
        set(ENDED, Operand::Global(crate::test_images::SEQUENCE)),
        Instr::Return,
    ];
    let runs = ENGINES.map(|engine| interrupted(engine, code.clone(), vec![Instr::Return]));
    let [interpreted, native] = &runs;
    for (seen, data, _) in &runs {
        // Interrupted once, at the first backward jump: the loop ran once, and its counter,
        // which the native engine may keep in a register, was in memory for the scheduler.
        assert_eq!(seen, &[(1, 0)]);
        // The rest of the cycle read what the interrupting task wrote.
        assert_eq!(dint(data, ENDED), 1);
        assert_eq!(dint(data, NOTED), 10);
        assert_eq!(dint(data, count(1)), 1);
    }
    as_interpreted(native, interpreted);
}

#[test]
fn a_cycle_is_interrupted_at_a_call_under_both_engines() {
    use program_image::{Instr, Operand};
    let sequence = Operand::Global(crate::test_images::SEQUENCE);
    // started := 1; noted := sequence; Called(); ended := sequence. Called sets SCRATCH.
    let code = vec![
        set(STARTED, Operand::Const(0)),
        set(NOTED, sequence),
        Instr::CallFunction {
            pou: 2,
            instance: None,
            inputs: Vec::new(),
            outputs: Vec::new(),
        },
        set(ENDED, sequence),
        Instr::Return,
    ];
    let called = vec![set(SCRATCH, Operand::Const(0)), Instr::Return];
    let runs = ENGINES.map(|engine| interrupted(engine, code.clone(), called.clone()));
    let [interpreted, native] = &runs;
    for (seen, data, _) in &runs {
        // Interrupted once, at the call: after the note before it, before the callee's body.
        assert_eq!(seen, &[(0, 0)]);
        assert_eq!(dint(data, ENDED), 1);
        assert_eq!(dint(data, SCRATCH), 1);
        assert_eq!(dint(data, count(1)), 1);
    }
    as_interpreted(native, interpreted);
}
