//! What the debugging commands print (`docs/debugging.md` §7): halts, breakpoints and stack
//! frames in words, from the answers of the debugging services and the program's image.

use online::{BreakpointInfo, HaltReason, HitMode, HitRule, StackFrame, StepKind, TaskHalt};
use program_image::ProgramImage;

use crate::debug_bodies::GraphicalBodies;
use crate::debug_places::{instance_owner, statement_of};

/// The name of task `task`, or its number when the image has no such task.
pub fn task_name(image: &ProgramImage, task: u8) -> String {
    image
        .tasks
        .get(usize::from(task))
        .map_or_else(|| format!("#{task}"), |task| task.name.clone())
}

/// The place of the statement instruction `instruction` of POU `pou` belongs to, as
/// `rivet check` prints places: `FILE:LINE`, or `FILE:POU:NETWORK:ELEMENT` in a graphical
/// body.
pub fn describe_place(
    image: &ProgramImage,
    bodies: &GraphicalBodies,
    pou: u32,
    instruction: u32,
) -> String {
    match statement_of(image, pou, instruction) {
        Some(statement) => bodies
            .place_of(&statement)
            .unwrap_or_else(|| format!("{}:{}", statement.file, statement.line)),
        None => format!("instruction {instruction}"),
    }
}

/// Where code is, with the instance it runs on by path and the POU
/// (`pous/FB_Counter.st:12 in Main.fbA (FB_Counter)`).
pub fn describe_position(
    image: &ProgramImage,
    bodies: &GraphicalBodies,
    pou: u32,
    instruction: u32,
    instance: u64,
) -> String {
    let place = describe_place(image, bodies, pou, instruction);
    let name = image
        .pous
        .get(pou as usize)
        .map_or_else(|| format!("POU {pou}"), |code| code.name.clone());
    match instance_path(image, pou, instance) {
        Some(path) => format!("{place} in {path} ({name})"),
        None => format!("{place} ({name})"),
    }
}

/// The path of the instance POU `pou` runs on; `None` for a function or an unknown instance.
pub fn instance_path(image: &ProgramImage, pou: u32, instance: u64) -> Option<String> {
    let owner = instance_owner(image, pou)?;
    image.instance_path(instance, Some(owner))
}

/// Why a task halted, in words: `breakpoint 1 (hit 3)`, `step over ended`.
pub fn describe_reason(halt: &TaskHalt, hits: Option<u32>, step: Option<StepKind>) -> String {
    let breakpoint = match (halt.breakpoint, hits) {
        (Some(id), Some(hits)) => format!("breakpoint {id} (hit {hits})"),
        (Some(id), None) => format!("breakpoint {id}"),
        (None, _) => "a breakpoint".to_owned(),
    };
    match halt.reason {
        HaltReason::Breakpoint => breakpoint,
        HaltReason::Step => match step {
            Some(kind) => format!("step {} ended", step_word(kind)),
            None => "step ended".to_owned(),
        },
        HaltReason::RunTo => "run to cursor reached".to_owned(),
        HaltReason::Halt => "halted on request".to_owned(),
        HaltReason::ConditionFaulted => format!("the condition of {breakpoint} faulted"),
    }
}

/// A halt as `rivet step` prints it: `task 'MainTask' halted at pous/FB_Counter.st:13 in
/// Main.fbA (FB_Counter): step over ended`. `instance` is the innermost frame's.
pub fn describe_halt(
    image: &ProgramImage,
    bodies: &GraphicalBodies,
    halt: &TaskHalt,
    instance: u64,
    hits: Option<u32>,
    step: Option<StepKind>,
) -> String {
    format!(
        "task '{}' halted at {}: {}",
        task_name(image, halt.task),
        describe_position(image, bodies, halt.pou, halt.instruction, instance),
        describe_reason(halt, hits, step)
    )
}

/// A halt as `rivet stack` prints it first: `task 'MainTask' halted at breakpoint 1 (hit 3)
/// in cycle 418`; a task waiting beneath a halted one says so.
pub fn describe_stack_header(image: &ProgramImage, halt: &TaskHalt, hits: Option<u32>) -> String {
    let name = task_name(image, halt.task);
    if halt.state == online::TaskDebugState::Waiting {
        return format!(
            "task '{name}' waits beneath a halted task in cycle {}",
            halt.cycle.saturating_add(1)
        );
    }
    let why = match halt.reason {
        HaltReason::Breakpoint => format!("at {}", describe_reason(halt, hits, None)),
        _ => format!("({})", describe_reason(halt, hits, None)),
    };
    format!(
        "task '{name}' halted {why} in cycle {}",
        halt.cycle.saturating_add(1)
    )
}

/// One frame of a call stack: `#0 pous/FB_Counter.st:12  Main.fbA  (FB_Counter)`; a
/// function's frame shows `-` for its instance.
pub fn describe_frame(
    image: &ProgramImage,
    bodies: &GraphicalBodies,
    index: usize,
    frame: &StackFrame,
) -> String {
    let place = describe_place(image, bodies, frame.pou, frame.instruction);
    let name = image
        .pous
        .get(frame.pou as usize)
        .map_or_else(|| format!("POU {}", frame.pou), |code| code.name.clone());
    let path = instance_path(image, frame.pou, frame.instance).unwrap_or_else(|| "-".to_owned());
    format!("#{index} {place}  {path}  ({name})")
}

/// A hit rule in words: `always`, `when the hit count equals 3`.
pub fn describe_hit_rule(rule: HitRule) -> String {
    match rule.mode {
        HitMode::Always => "always".to_owned(),
        HitMode::Equal => format!("when the hit count equals {}", rule.target),
        HitMode::Multiple => format!("when the hit count is a multiple of {}", rule.target),
        HitMode::AtLeast => format!("when the hit count is at least {}", rule.target),
    }
}

/// The task filter of a breakpoint: `task 'Fast'` or `any task`.
pub fn describe_task_filter(image: &ProgramImage, task: u8) -> String {
    if task == online::ALL_TASKS {
        "any task".to_owned()
    } else {
        format!("task '{}'", task_name(image, task))
    }
}

/// One line of `rivet break --list`: id, place, instance, task, condition, hit rule and
/// count.
pub fn describe_breakpoint(
    image: &ProgramImage,
    bodies: &GraphicalBodies,
    breakpoint: &BreakpointInfo,
) -> String {
    let place = match statement_of(image, breakpoint.pou, breakpoint.instruction) {
        Some(statement) => match bodies.place_of(&statement) {
            Some(place) => format!("{place} ({})", statement.pou_name),
            None => statement.to_string(),
        },
        None => format!(
            "instruction {} of POU {}",
            breakpoint.instruction, breakpoint.pou
        ),
    };
    let instance = match breakpoint.instance {
        0 => "every instance".to_owned(),
        pointer => format!(
            "instance {}",
            instance_path(image, breakpoint.pou, pointer)
                .unwrap_or_else(|| format!("16#{pointer:X}"))
        ),
    };
    format!(
        "{}  {place}  {instance}  {}  {}  {}  hits {}",
        breakpoint.id,
        describe_task_filter(image, breakpoint.task),
        if breakpoint.conditional {
            "conditional"
        } else {
            "no condition"
        },
        describe_hit_rule(breakpoint.hit),
        breakpoint.hits
    )
}

/// `into`, `over` or `out`.
pub fn step_word(kind: StepKind) -> &'static str {
    match kind {
        StepKind::Into => "into",
        StepKind::Over => "over",
        StepKind::Out => "out",
    }
}

#[cfg(test)]
#[path = "debug_text_tests.rs"]
mod tests;
