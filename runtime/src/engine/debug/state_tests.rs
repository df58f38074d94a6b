use super::*;
use crate::test_images::{TestTask, image};

fn three_tasks() -> DebugState {
    let tasks = [
        TestTask::cyclic(1_000_000, 3),
        TestTask::cyclic(1_000_000, 2),
        TestTask::cyclic(1_000_000, 1),
    ];
    DebugState::new(&image(&tasks, &[]))
}

#[test]
fn a_task_waits_only_beneath_a_task_halted_in_a_cycle_nested_in_its_own() {
    let mut debug = three_tasks();
    debug.cycle_starts(0);
    debug.cycle_starts(1);
    debug.enter_halt(1, HaltReason::Halt);
    // Task 2 runs a cycle from inside task 1's halt: it is above the halt, not beneath.
    debug.cycle_starts(2);
    assert!(debug.waiting(0));
    assert!(!debug.waiting(1), "halted, not waiting");
    assert!(!debug.waiting(2));
    debug.cycle_ends(2);
    debug.continue_task(1).expect("on top");
    debug.cycle_ends(1);
    debug.cycle_ends(0);
    assert!(!debug.waiting(0));
}

#[test]
fn halts_resume_last_in_first_out() {
    let mut debug = three_tasks();
    debug.cycle_starts(0);
    debug.enter_halt(0, HaltReason::Halt);
    // Task 1 runs from inside task 0's halt and halts on top of it.
    debug.cycle_starts(1);
    debug.enter_halt(1, HaltReason::Halt);
    let error = debug.step(0, StepKind::Into).expect_err("beneath");
    assert_eq!(
        error.to_string(),
        "task 'Task0' is halted beneath task 'Task1': continue 'Task1' first"
    );
    debug.continue_task(1).expect("on top");
    debug.step(0, StepKind::Into).expect("on top now");
    let error = debug.step(2, StepKind::Into).expect_err("not halted");
    assert_eq!(error.to_string(), "task 'Task2' is not halted");
}

#[test]
fn ending_the_session_forgets_breakpoints_steps_and_halts() {
    let mut debug = three_tasks();
    debug.begin_session();
    debug.halt_all();
    assert!(!debug.holding(), "the next cycle may start, to halt");
    debug.cycle_starts(2);
    assert!(debug.holding());
    debug.enter_halt(2, HaltReason::Halt);
    let generation = debug.generation();
    debug.end_session();
    assert!(!debug.active() && !debug.holding() && !debug.is_halted(2));
    assert!(debug.generation() != generation);
}

#[test]
fn a_cycle_runs_with_the_debugger_only_when_something_can_halt_while_it_runs() {
    // Task i runs POU i; task 2 has the highest priority, task 0 the lowest.
    let tasks = [
        TestTask::cyclic(1_000_000, 3),
        TestTask::cyclic(1_000_000, 2),
        TestTask::cyclic(1_000_000, 1),
    ];
    let mut image = image(&tasks, &[]);
    for pou in &mut image.pous {
        pou.lines = vec![program_image::LineEntry {
            index: 0,
            file: 0,
            line: 1,
        }];
    }
    let mut debug = DebugState::new(&image);
    let needs = |debug: &DebugState, interrupted| -> Vec<bool> {
        (0..3)
            .map(|task| debug.cycle_needs_debugger(task, interrupted))
            .collect()
    };
    let spec = |pou: u32, task: Option<u8>| BreakpointSpec {
        pou,
        instruction: 0,
        instance: 0,
        task,
        hit_mode: HitMode::Always,
        hit_target: 0,
        condition: Vec::new(),
    };
    // No session, then a session with nothing set: no cycle needs it.
    debug.insert_breakpoint(spec(1, None), None).expect("set");
    assert_eq!(needs(&debug, true), [false; 3]);
    debug.end_session();
    debug.begin_session();
    assert_eq!(needs(&debug, true), [false; 3]);
    // A breakpoint in task 1's POU: task 1, and task 0 when task 1 may interrupt it.
    let (id, _) = debug.insert_breakpoint(spec(1, None), None).expect("set");
    assert_eq!(needs(&debug, true), [true, true, false]);
    assert_eq!(needs(&debug, false), [false, true, false]);
    // The same breakpoint for task 0 only: no task reaches it.
    debug
        .insert_breakpoint(spec(1, Some(0)), None)
        .expect("set");
    debug.clear_breakpoint(id).expect("cleared");
    assert_eq!(needs(&debug, true), [false; 3]);
    debug.clear_breakpoint(0xFFFF).expect("cleared");
    // Flow recording of task 2, and a halt asked of task 1.
    debug.configure_flow(2, &[(2, 0)]).expect("configured");
    assert_eq!(needs(&debug, false), [false, false, true]);
    debug.halt_task(1).expect("task 1 exists");
    assert_eq!(needs(&debug, false), [false, true, true]);
    assert_eq!(needs(&debug, true), [true, true, true]);
}

#[test]
fn a_pou_recorded_in_two_tasks_marks_its_statements_in_the_task_that_ran_them() {
    let tasks = [
        TestTask::cyclic(1_000_000, 2),
        TestTask::cyclic(1_000_000, 1),
    ];
    let mut image = image(&tasks, &[]);
    image.pous[0].lines = vec![program_image::LineEntry {
        index: 0,
        file: 0,
        line: 1,
    }];
    let mut debug = DebugState::new(&image);
    debug.begin_session();
    debug.configure_flow(0, &[(0, 0)]).expect("task 0 records");
    debug.configure_flow(1, &[(0, 0)]).expect("task 1 records");
    debug.record_flow(1, 0, 0, 0);
    debug.end_flow_cycle(1, 1);
    debug.end_flow_cycle(0, 1);
    let last = |debug: &DebugState, entry| {
        debug
            .flow()
            .entry(entry)
            .map(|(task, track)| (task, track.last.clone()))
    };
    assert_eq!(last(&debug, 0), Some((0, vec![0])));
    assert_eq!(last(&debug, 1), Some((1, vec![1])));
    // Ending one task's recording keeps the POU recorded while the other task records it.
    debug.configure_flow(0, &[]).expect("task 0 ends");
    assert!(debug.pou_recorded[0]);
    debug.configure_flow(1, &[]).expect("task 1 ends");
    assert!(!debug.pou_recorded[0] && debug.flow().is_empty());
}
