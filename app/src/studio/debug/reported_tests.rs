//! The session's reports in the studio's terms, against the packaging machine example.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::path::Path;

use online::{HaltReason, StackFrame as ReportedFrame, TaskHalt};

use super::*;
use crate::debug_places::statement_at;

fn image() -> ProgramImage {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let project = project_model::load_project(&dir).unwrap().project;
    compiler::compile_project(&project).unwrap()
}

fn halt(task: u8, state: TaskDebugState) -> TaskHalt {
    TaskHalt {
        task,
        state,
        reason: HaltReason::Breakpoint,
        breakpoint: None,
        pou: 0,
        instruction: 0,
        depth: 0,
        cycle: 0,
        halted_ms: 0,
    }
}

#[test]
fn frames_are_named_by_pou_instance_file_and_line_and_a_waiting_task_is_beneath_the_halted() {
    let image = image();
    let inside = statement_at(&image, "application/FB_Conveyor.st:3").unwrap();
    let call = statement_at(&image, "application/Main.st:2").unwrap();
    let instance = (1u64 << 56)
        | runtime::value::resolve(&image, "Main.fbConveyor")
            .unwrap()
            .offset;
    let frame = |pou: u32, instruction: u32, instance: u64| ReportedFrame {
        pou,
        instruction,
        instance,
        frame: 0,
        frame_bytes: 0,
    };
    let reported = vec![
        ReportedTask {
            halt: halt(1, TaskDebugState::Waiting),
            frames: Vec::new(),
        },
        ReportedTask {
            halt: halt(0, TaskDebugState::Halted),
            frames: vec![
                frame(inside.pou, inside.instruction, instance),
                // A call's instruction lies inside its statement.
                frame(call.pou, call.instruction + 1, 0),
            ],
        },
    ];
    let tasks = halted_tasks(&image, &reported);
    assert_eq!(tasks[0].task, "MotionTask");
    assert_eq!(tasks[0].beneath, Some(Beneath::Task("MainTask".to_owned())));
    assert_eq!(tasks[1].beneath, None);
    assert_eq!(
        tasks[1].frames[0],
        StackFrame {
            pou: "FB_Conveyor".to_owned(),
            instance: Some("Main.fbConveyor".to_owned()),
            file: "application/FB_Conveyor.st".to_owned(),
            line: 3,
        }
    );
    assert_eq!(
        (tasks[1].frames[1].pou.as_str(), tasks[1].frames[1].line),
        ("Main", 2)
    );
}

#[test]
fn a_task_waiting_while_two_tasks_are_halted_names_neither_as_what_it_waits_beneath() {
    let image = image();
    let task = |index: u8, state: TaskDebugState| ReportedTask {
        halt: halt(index, state),
        frames: Vec::new(),
    };
    // The target does not say whether task 2 waits beneath task 0's cycle or task 1's.
    let reported = vec![
        task(0, TaskDebugState::Halted),
        task(1, TaskDebugState::Halted),
        task(2, TaskDebugState::Waiting),
    ];
    let tasks = halted_tasks(&image, &reported);
    assert_eq!(
        (tasks[0].beneath.clone(), tasks[1].beneath.clone()),
        (None, None)
    );
    assert_eq!(tasks[2].task, "#2");
    assert_eq!(tasks[2].beneath, Some(Beneath::AHaltedTask));
}

#[test]
fn flow_bits_become_the_lines_of_their_statements_per_file() {
    let image = image();
    let main = statement_at(&image, "application/Main.st:2").unwrap();
    let entries = &image.pous[main.pou as usize].lines;
    // The first and third statements of Main ran.
    let mut bitmap = vec![0u8; entries.len().div_ceil(8)];
    bitmap[0] = 0b101;
    let entry = FlowEntry {
        pou: main.pou,
        instance: 0,
    };
    let bitmap = FlowBitmap {
        cycle: 4,
        statements: entries.len() as u32,
        bitmap,
    };
    let mut expected = vec![entries[0].line, entries[2].line];
    expected.sort_unstable();
    expected.dedup();
    assert_eq!(
        flow_lines(&image, [(&entry, &bitmap)]),
        vec![("application/Main.st".to_owned(), expected)]
    );
}
