//! Breakpoints of the packaging machine example as `BREAK_SET` takes them.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::path::Path;

use super::*;
use crate::studio::i18n::Language;
use project_model::Project;

/// The example project and its image.
fn example() -> (Project, ProgramImage) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let project = project_model::load_project(&dir).unwrap().project;
    let image = compiler::compile_project(&project).unwrap();
    (project, image)
}

/// The breakpoint as `BREAK_SET` takes it, its condition compiled against `project` now.
fn breakpoint_spec(
    image: &ProgramImage,
    project: &Project,
    bodies: &GraphicalBodies,
    breakpoint: &Breakpoint,
) -> Result<BreakpointSpec, BreakpointError> {
    breakpoint_spec_with(image, image.identity(), bodies, breakpoint, &mut |key| {
        super::super::compile_condition(project, key)
    })
}

fn at(file: &str, line: u32) -> Breakpoint {
    Breakpoint::at(BreakpointPlace::text(format!("application/{file}"), line))
}

#[test]
fn a_plain_breakpoint_on_a_comment_goes_to_the_next_statement_for_every_instance_and_task() {
    let (project, image) = example();
    let statement = breakpoint_statement(
        &image,
        &GraphicalBodies::of_project(&project),
        &at("Main.st", 1).place,
    )
    .unwrap();
    assert_eq!((statement.pou_name.as_str(), statement.line), ("Main", 2));
    let spec = breakpoint_spec(
        &image,
        &project,
        &GraphicalBodies::of_project(&project),
        &at("Main.st", 1),
    )
    .unwrap();
    assert_eq!(
        (spec.pou, spec.instruction),
        (statement.pou, statement.instruction)
    );
    assert_eq!(spec.instance, 0);
    assert_eq!(spec.task, ALL_TASKS);
    assert_eq!(spec.hit, HitRule::ALWAYS);
    assert!(spec.condition.is_empty());
}

#[test]
fn filters_hit_rules_and_conditions_go_with_the_breakpoint() {
    let (project, image) = example();
    let mut breakpoint = at("FB_Conveyor.st", 3);
    breakpoint.instance = "Main.fbConveyor".to_owned();
    breakpoint.task = "maintask".to_owned();
    breakpoint.hit_mode = HitMode::MultipleOf;
    breakpoint.hit_target = 3;
    breakpoint.condition = "xStart AND NOT xStop".to_owned();
    let spec = breakpoint_spec(
        &image,
        &project,
        &GraphicalBodies::of_project(&project),
        &breakpoint,
    )
    .unwrap();
    assert_eq!(
        image.instance_path(spec.instance, Some("FB_Conveyor")),
        Some("Main.fbConveyor".to_owned())
    );
    assert_eq!(spec.task, 0);
    assert_eq!(
        spec.hit,
        HitRule {
            mode: online::HitMode::Multiple,
            target: 3
        }
    );
    assert!(!spec.condition.is_empty());
}

#[test]
fn a_condition_that_does_not_compile_names_the_place_and_the_compilers_message() {
    let (project, image) = example();
    let mut breakpoint = at("FB_Conveyor.st", 3);
    breakpoint.condition = "xNoSuchVariable > 1".to_owned();
    let error = breakpoint_spec(
        &image,
        &project,
        &GraphicalBodies::of_project(&project),
        &breakpoint,
    )
    .unwrap_err();
    let text = error.text(Language::English);
    assert!(
        text.starts_with("breakpoint application/FB_Conveyor.st:3 not set: the condition 'xNoSuchVariable > 1' does not compile:"),
        "{text}"
    );
    assert!(text.contains("xNoSuchVariable"), "{text}");
}

#[test]
fn a_wrong_instance_task_or_place_is_refused_with_the_place() {
    let (project, image) = example();
    let mut breakpoint = at("FB_Conveyor.st", 3);
    breakpoint.instance = "Main.rtrigPackage".to_owned();
    assert!(matches!(
        breakpoint_spec(
            &image,
            &project,
            &GraphicalBodies::of_project(&project),
            &breakpoint
        ),
        Err(BreakpointError::Instance { .. })
    ));
    let mut breakpoint = at("FB_Conveyor.st", 3);
    breakpoint.task = "NoTask".to_owned();
    let error = breakpoint_spec(
        &image,
        &project,
        &GraphicalBodies::of_project(&project),
        &breakpoint,
    )
    .unwrap_err();
    assert_eq!(
        error.text(Language::English),
        "breakpoint application/FB_Conveyor.st:3 not set: the program has no task 'NoTask'"
    );
    let error = breakpoint_spec(
        &image,
        &project,
        &GraphicalBodies::of_project(&project),
        &at("Main.st", 9999),
    )
    .unwrap_err();
    assert!(matches!(error, BreakpointError::Place { .. }), "{error:?}");
}
