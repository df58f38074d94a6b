//! The debugging commands' words against a small compiled program.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use online::{TaskDebugState, TaskHalt};

use super::*;
use crate::debug_places::statement_at;

const SOURCE: &str = "FUNCTION_BLOCK FB_Counter
VAR_INPUT step : INT; END_VAR
VAR count : INT; END_VAR
count := count + step;
END_FUNCTION_BLOCK

PROGRAM Main
VAR fbA : FB_Counter; fbB : FB_Counter; END_VAR
fbA(step := 1);
fbB(step := 2);
END_PROGRAM
";

fn image() -> ProgramImage {
    let source = compiler::SourceProject::new(SOURCE);
    compiler::compile_source(&source, "pous/counter.st").unwrap()
}

/// The pointer value of the instance at `path` (region 1, data).
fn pointer(image: &ProgramImage, path: &str) -> u64 {
    (1 << 56) | runtime::value::resolve(image, path).unwrap().offset
}

fn halted_at(image: &ProgramImage, place: &str, reason: HaltReason) -> TaskHalt {
    let statement = statement_at(image, place).unwrap();
    TaskHalt {
        task: 0,
        state: TaskDebugState::Halted,
        reason,
        breakpoint: Some(1),
        pou: statement.pou,
        instruction: statement.instruction,
        depth: 2,
        cycle: 417,
        halted_ms: 5,
    }
}

#[test]
fn a_halt_names_the_task_the_line_the_instance_and_why() {
    let image = image();
    let fb_b = pointer(&image, "Main.fbB");
    let halt = halted_at(&image, "counter.st:4", HaltReason::Step);
    assert_eq!(
        describe_halt(
            &image,
            &GraphicalBodies::default(),
            &halt,
            fb_b,
            None,
            Some(StepKind::Over)
        ),
        "task 'MainTask' halted at pous/counter.st:4 in Main.fbB (FB_Counter): step over ended"
    );
    let halt = halted_at(&image, "counter.st:4", HaltReason::Breakpoint);
    assert_eq!(
        describe_stack_header(&image, &halt, Some(3)),
        "task 'MainTask' halted at breakpoint 1 (hit 3) in cycle 418"
    );
    let halt = halted_at(&image, "counter.st:4", HaltReason::ConditionFaulted);
    assert_eq!(
        describe_reason(&halt, None, None),
        "the condition of breakpoint 1 faulted"
    );
}

#[test]
fn stack_frames_show_the_line_of_the_call_and_the_instance_by_path() {
    let image = image();
    let inner = statement_at(&image, "counter.st:4").unwrap();
    let call = statement_at(&image, "counter.st:9").unwrap();
    let frame = |pou, instruction, instance| StackFrame {
        pou,
        instruction,
        instance,
        frame: 0,
        frame_bytes: 0,
    };
    let fb_a = pointer(&image, "Main.fbA");
    let main = pointer(&image, "Main");
    assert_eq!(
        describe_frame(
            &image,
            &GraphicalBodies::default(),
            0,
            &frame(inner.pou, inner.instruction, fb_a)
        ),
        "#0 pous/counter.st:4  Main.fbA  (FB_Counter)"
    );
    // The call instruction lies after the statement's start: the statement's line is shown.
    assert_eq!(
        describe_frame(
            &image,
            &GraphicalBodies::default(),
            1,
            &frame(call.pou, call.instruction + 1, main)
        ),
        "#1 pous/counter.st:9  Main  (Main)"
    );
}

#[test]
fn a_breakpoint_line_has_its_place_filters_and_hits() {
    let image = image();
    let statement = statement_at(&image, "counter.st:4").unwrap();
    let breakpoint = BreakpointInfo {
        id: 2,
        pou: statement.pou,
        instruction: statement.instruction,
        instance: pointer(&image, "Main.fbA"),
        task: online::ALL_TASKS,
        hit: HitRule {
            mode: HitMode::Multiple,
            target: 5,
        },
        hits: 7,
        conditional: true,
    };
    assert_eq!(
        describe_breakpoint(&image, &GraphicalBodies::default(), &breakpoint),
        "2  pous/counter.st:4 (FB_Counter)  instance Main.fbA  any task  conditional  when the hit count is a multiple of 5  hits 7"
    );
    assert_eq!(describe_task_filter(&image, 0), "task 'MainTask'");
}
