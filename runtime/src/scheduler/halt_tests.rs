//! A task halted by the debugger, on the real clock: the others keep running, its outputs
//! keep their values, the watchdog does not trip, commands are served from inside the halt,
//! and stop abandons the halted cycle without a fault.

use std::time::Instant;

use program_image::{LineEntry, ProgramImage, Region};

use super::tests::{MS, PATIENCE, dword, scheduler, wait_for};
use super::*;
use crate::engine::FaultKind;
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

/// How long a scenario with a looping task may take before it counts as hung: far more than
/// its watchdogs, far less than a blocked test run.
const HANG: Duration = Duration::from_secs(30);

/// A watchdog far longer than a preempting task's start latency on a loaded machine.
const LOOP_WATCHDOG_NS: u64 = 50 * MS;

/// Runs `scenario` on a thread of its own and fails when it has not ended within [`HANG`], so
/// a scheduler that hangs fails the test instead of blocking the whole run (the thread is
/// left behind; the test process ends it).
#[track_caller]
fn without_hanging(scenario: impl FnOnce() + Send + 'static) {
    let (ended, end) = mpsc::channel();
    let thread = std::thread::spawn(move || {
        scenario();
        let _ = ended.send(());
    });
    match end.recv_timeout(HANG) {
        Ok(()) => thread.join().expect("the scenario ended"),
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("the scenario hung for {HANG:?}"),
        // The scenario panicked: its own message says why.
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            if let Err(panic) = thread.join() {
                std::panic::resume_unwind(panic);
            }
        }
    }
}

/// A task of `priority` every `interval_ns` whose cycle loops (practically) for ever, with a
/// watchdog of [`LOOP_WATCHDOG_NS`].
fn endless(interval_ns: u64, priority: u8) -> TestTask {
    TestTask {
        body: crate::test_images::Body::Watch {
            iterations: i32::MAX,
            sets_trigger: false,
        },
        watchdog_ns: LOOP_WATCHDOG_NS,
        ..TestTask::cyclic(interval_ns, priority)
    }
}

/// An image of `tasks` whose programs start a statement at their first instruction.
fn debuggable(tasks: &[TestTask]) -> ProgramImage {
    let mut image = image(tasks, &[]);
    for pou in &mut image.pous {
        pou.lines = vec![LineEntry {
            index: 0,
            file: 0,
            line: 1,
        }];
    }
    image
}

/// Runs `change` on the debug session's state between two cycles (or from inside a halt).
fn debug<T: Send + 'static>(
    scheduler: &Scheduler,
    change: impl FnOnce(&mut crate::engine::DebugState) -> T + Send + 'static,
) -> T {
    scheduler
        .between(|between| {
            let memory = between.memory.as_mut().expect("a program");
            change(memory.engine.debug_mut())
        })
        .expect("served")
}

/// Sets a breakpoint at the first statement of task `task`'s program that halts at its
/// `hit`-th hit only.
fn break_at_hit(scheduler: &Scheduler, task: u32, hit: u32) {
    scheduler
        .between(move |between| {
            let memory = between.memory.as_mut().expect("a program");
            memory.engine.debug_mut().begin_session();
            memory
                .engine
                .set_breakpoint(crate::engine::BreakpointSpec {
                    pou: task,
                    instruction: 0,
                    instance: 0,
                    task: None,
                    hit_mode: crate::engine::HitMode::Equal,
                    hit_target: hit,
                    condition: Vec::new(),
                })
                .expect("a statement start");
        })
        .expect("served");
}

/// The watchdog faults of task `task` so far.
fn watchdog_faults(scheduler: &Scheduler, task: usize) -> usize {
    let name = format!("Task{task}");
    scheduler
        .status()
        .faults
        .iter()
        .filter(|fault| fault.task == name && matches!(fault.kind, FaultKind::Watchdog { .. }))
        .count()
}

#[test]
fn a_lower_task_that_loops_while_a_higher_one_is_halted_ends_by_its_watchdog() {
    // Task 0 halts in its first cycle; the halt runs task 1, which loops until its watchdog
    // ends it; then commands are served again.
    halted_while_the_other_loops(&[TestTask::cyclic(MS, 1), endless(10 * MS, 10)], 0);
}

/// How a test lets a task halted inside a looping cycle go on.
#[derive(Clone, Copy, Debug)]
enum Release {
    Continue,
    /// Logout and a lost connection both end the session.
    EndSession,
    Stop,
}

#[test]
fn a_higher_task_halted_inside_a_looping_lower_one_goes_on_cleanly() {
    for release in [Release::Continue, Release::EndSession, Release::Stop] {
        without_hanging(move || {
            // The default engine, which makes machine code where there is a backend.
            let (scheduler, _areas) = scheduler(SchedulerOptions::default());
            let report = scheduler
                .load(debuggable(&[
                    TestTask::cyclic(MS, 1),
                    endless(60_000 * MS, 10),
                ]))
                .expect("loads");
            let native = jit::native_support().is_ok();
            assert_eq!(
                report.native.runs_natively(),
                native,
                "{:#?}",
                report.native
            );
            // Task 0 runs first, then task 1 loops; task 0's third cycle halts inside it.
            break_at_hit(&scheduler, 0, 3);
            scheduler.start().expect("starts");
            wait_until("task 0 to halt", || {
                debug(&scheduler, |debug| debug.is_halted(0))
            });
            assert!(debug(&scheduler, |debug| debug.waiting(1)), "{release:?}");
            // Longer than task 1's watchdog: the time halted does not count.
            std::thread::sleep(Duration::from_nanos(2 * LOOP_WATCHDOG_NS));
            assert_eq!(watchdog_faults(&scheduler, 1), 0, "{release:?}");
            assert_eq!(counts(&scheduler)[0], 2, "{release:?}");
            match release {
                Release::Continue => {
                    debug(&scheduler, |debug| debug.continue_task(0).expect("on top"));
                }
                Release::EndSession => debug(&scheduler, |debug| debug.end_session()),
                Release::Stop => {
                    scheduler.stop().expect("stops");
                    assert_eq!(scheduler.status().state, SchedulerState::Stopped);
                    assert!(!debug(&scheduler, |debug| debug.is_halted(0)));
                    assert_eq!(counts(&scheduler)[0], 2, "the abandoned cycle went on");
                    let entries = scheduler
                        .between(|between| {
                            between
                                .memory
                                .as_ref()
                                .map_or(0, |memory| memory.engine.native_entries())
                        })
                        .expect("served");
                    // No machine code ran, although it was made: task 1 may be interrupted by
                    // task 0, which may halt, so its cycle runs with the debugger
                    // (`DebugState::cycle_needs_debugger`), in the interpreter. A halt is
                    // therefore never abandoned through a native frame beneath it.
                    assert_eq!(entries, 0, "{entries} native entries");
                    assert!(scheduler.status().faults.is_empty());
                    return;
                }
            }
            // The looping cycle goes on, task 0 interrupting it, until its watchdog ends it.
            wait_until("task 1's watchdog", || watchdog_faults(&scheduler, 1) == 1);
            wait_until("task 0 to run on", || counts(&scheduler)[0] > 5);
            assert_eq!(watchdog_faults(&scheduler, 0), 0, "{release:?}");
            scheduler.stop().expect("stops");
        });
    }
}

#[test]
fn a_higher_task_that_loops_while_a_lower_one_is_halted_ends_by_its_watchdog() {
    // Task 0 loops first and faults; task 1 then halts, and nothing else is due.
    halted_while_the_other_loops(&[endless(10 * MS, 1), TestTask::cyclic(MS, 10)], 1);
}

/// Runs the two `tasks`, one of which loops without end, with task `halted` (the other one)
/// told to halt: it halts, the looping task's watchdog ends its cycle, and the halted task
/// then goes on when continued, its own watchdog untouched.
fn halted_while_the_other_loops(tasks: &[TestTask], halted: usize) {
    let looping = 1 - halted;
    let image = debuggable(tasks);
    without_hanging(move || {
        let (scheduler, _areas) = scheduler(SchedulerOptions::default());
        scheduler.load(image).expect("loads");
        debug(&scheduler, move |debug| {
            debug.begin_session();
            debug.halt_task(halted).expect("the task exists");
        });
        scheduler.start().expect("starts");
        wait_until("the task to halt", || {
            debug(&scheduler, move |debug| debug.is_halted(halted))
        });
        wait_until("the looping task's watchdog", || {
            watchdog_faults(&scheduler, looping) == 1
        });
        let halted_at = counts(&scheduler)[halted];
        debug(&scheduler, move |debug| {
            debug.continue_task(halted).expect("on top")
        });
        wait_until("the halted task to run on", || {
            counts(&scheduler)[halted] > halted_at + 3
        });
        assert_eq!(watchdog_faults(&scheduler, halted), 0);
        scheduler.stop().expect("stops");
    });
}

#[test]
fn two_tasks_halted_at_once_go_on_top_first() {
    without_hanging(|| {
        let (scheduler, _areas) = scheduler(SchedulerOptions::default());
        scheduler.load(two_tasks()).expect("loads");
        debug(&scheduler, |debug| {
            debug.begin_session();
            debug.halt_task(0).expect("task 0 exists");
            debug.halt_task(1).expect("task 1 exists");
        });
        scheduler.start().expect("starts");
        // Task 0 halts first; its halt runs task 1, which halts on top of it.
        wait_until("both to halt", || {
            debug(&scheduler, |debug| debug.halted().to_vec()) == [0, 1]
        });
        let refused = debug(&scheduler, |debug| debug.continue_task(0).is_err());
        assert!(refused, "task 0 went on beneath task 1");
        std::thread::sleep(Duration::from_millis(20));
        assert_eq!(counts(&scheduler), [0, 0]);
        debug(&scheduler, |debug| debug.continue_task(1).expect("on top"));
        wait_until("task 0 alone halted", || {
            debug(&scheduler, |debug| debug.halted().to_vec()) == [0]
        });
        debug(&scheduler, |debug| debug.continue_task(0).expect("on top"));
        wait_until("both to run on", || {
            counts(&scheduler).iter().all(|&n| n > 3)
        });
        let status = scheduler.status();
        assert!(status.faults.is_empty(), "{:?}", status.faults);
        scheduler.stop().expect("stops");
    });
}

/// The processor time the scheduler's thread has used, read on that thread (Linux).
#[cfg(target_os = "linux")]
fn thread_time(scheduler: &Scheduler) -> Duration {
    let text = scheduler
        .between(|_| std::fs::read_to_string("/proc/thread-self/schedstat"))
        .expect("served")
        .expect("the thread's scheduling statistics");
    let nanoseconds = text
        .split_whitespace()
        .next()
        .and_then(|field| field.parse().ok())
        .expect("a time in nanoseconds");
    Duration::from_nanos(nanoseconds)
}

#[cfg(target_os = "linux")]
#[test]
fn a_halt_waits_for_commands_without_spinning() {
    let (records, log) = mpsc::channel();
    let options = SchedulerOptions {
        cycle_log: Some(records),
        ..SchedulerOptions::default()
    };
    let (scheduler, _areas) = scheduler(options);
    // One task, halted in its first cycle: nothing else is due, so the thread only waits.
    scheduler
        .load(debuggable(&[TestTask::cyclic(MS, 1)]))
        .expect("loads");
    debug(&scheduler, |debug| {
        debug.begin_session();
        debug.halt_task(0).expect("task 0 exists");
    });
    scheduler.start().expect("starts");
    wait_until("task 0 to halt", || {
        debug(&scheduler, |debug| debug.is_halted(0))
    });
    let thread = thread_time(&scheduler);
    std::thread::sleep(Duration::from_millis(200));
    let busy = thread_time(&scheduler).saturating_sub(thread);
    assert!(
        busy < Duration::from_millis(20),
        "busy {busy:?} of 200 ms halted"
    );
    assert!(log.try_recv().is_err(), "a cycle ended while halted");
}

#[test]
fn commands_are_served_while_a_task_run_by_a_halt_loops() {
    for release in [Release::Continue, Release::EndSession, Release::Stop] {
        without_hanging(move || {
            let scheduler = looping_above_a_halt(debuggable(&looping_above_a_halt_tasks()));
            match release {
                Release::Continue => {
                    debug(&scheduler, |debug| debug.continue_task(0).expect("on top"));
                    assert!(!debug(&scheduler, |debug| debug.is_halted(0)));
                }
                Release::EndSession => {
                    debug(&scheduler, |debug| debug.end_session());
                    assert!(!debug(&scheduler, |debug| debug.active()));
                }
                Release::Stop => {}
            }
            // Task 0 goes on once task 1's cycle ends, which only a stop makes it do.
            scheduler.stop().expect("stops");
            let status = scheduler.status();
            assert_eq!(status.state, SchedulerState::Stopped, "{release:?}");
            assert!(status.faults.is_empty(), "{release:?}: {:?}", status.faults);
            // Neither abandoned cycle ran on.
            assert_eq!(counts(&scheduler), [0, 0], "{release:?}");
            assert!(!debug(&scheduler, |debug| debug.abandoning()));
        });
    }
}

#[test]
fn a_task_looping_in_a_cycle_run_by_a_halt_can_be_halted_too() {
    without_hanging(|| {
        // The loop jumps back to instruction 2 of task 1's program: a statement start there
        // is where a halt can stop it.
        let mut image = debuggable(&looping_above_a_halt_tasks());
        image.pous[1].lines.push(LineEntry {
            index: 2,
            file: 0,
            line: 2,
        });
        let scheduler = looping_above_a_halt(image);
        // Task 1's cycle started while task 0 was halted, so it runs with the debugger: a
        // halt given while it loops stops it at its next statement, not at its watchdog.
        debug(&scheduler, |debug| {
            debug.halt_task(1).expect("task 1 exists")
        });
        wait_until("task 1 to halt", || {
            debug(&scheduler, |debug| debug.is_halted(1))
        });
        scheduler.stop().expect("stops");
        assert!(scheduler.status().faults.is_empty());
    });
}

/// Two tasks: task 0 every millisecond at priority 1, and task 1 at priority 10, whose cycle
/// never ends and whose watchdog is longer than a test may take, so only serving the
/// commands from its safe points lets a test go on.
fn looping_above_a_halt_tasks() -> [TestTask; 2] {
    let looping = TestTask {
        watchdog_ns: 2 * HANG.as_nanos() as u64,
        ..endless(10 * MS, 10)
    };
    [TestTask::cyclic(MS, 1), looping]
}

/// Runs `image` (of [`looping_above_a_halt_tasks`]) in a debug session with task 0 told to
/// halt, and returns once task 0 is halted and task 1's endless cycle, run by the halt, loops.
fn looping_above_a_halt(image: ProgramImage) -> Scheduler {
    let (scheduler, _areas) = scheduler(SchedulerOptions::default());
    scheduler.load(image).expect("loads");
    debug(&scheduler, |debug| {
        debug.begin_session();
        debug.halt_task(0).expect("task 0 exists");
    });
    scheduler.start().expect("starts");
    wait_until("task 0 to halt", || {
        debug(&scheduler, |debug| debug.is_halted(0))
    });
    wait_until("task 1 to loop", || {
        scheduler
            .between(|between| {
                let memory = between.memory.as_ref().expect("a program");
                let data = memory.engine.region(Region::Data);
                dint(data, crate::test_images::watch_counter(1)) > 1000
            })
            .expect("served")
    });
    scheduler
}

#[test]
fn a_command_postponed_while_the_areas_were_busy_is_served_by_a_halt_that_follows() {
    without_hanging(|| {
        let (scheduler, areas) = scheduler(SchedulerOptions::default());
        scheduler
            .load(debuggable(&[TestTask::cyclic(MS, 1)]))
            .expect("loads");
        scheduler.start().expect("starts");
        // The task halts at its 30th cycle from now.
        let before = scheduler.status().tasks[0].cycles;
        break_at_hit(&scheduler, 0, 30);
        let scheduler = Arc::new(scheduler);
        let held = areas.lock().expect("the areas");
        // A client's request comes while a Modbus thread holds the areas: it is postponed.
        let (answered, answer) = mpsc::channel();
        let asking = Arc::clone(&scheduler);
        let client = std::thread::spawn(move || {
            let halted = asking
                .between(|between| {
                    let memory = between.memory.as_mut().expect("a program");
                    memory.engine.debug().is_halted(0)
                })
                .expect("served");
            let _ = answered.send(halted);
        });
        // The cycles go on meanwhile, and the task halts in its 30th.
        wait_for(&scheduler, "the cycles before the halt", |status| {
            status.tasks[0].cycles >= before + 29
        });
        std::thread::sleep(Duration::from_millis(100));
        drop(held);
        // The halt serves the postponed request (the task is still halted when it runs)
        // instead of keeping it until the halt ends, which that client may have to ask for.
        let halted = answer
            .recv_timeout(PATIENCE)
            .expect("the postponed request is answered during the halt");
        assert!(halted);
        client.join().expect("the client ends");
        scheduler.stop().expect("stops");
    });
}
