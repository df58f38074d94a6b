//! The trace pane edits the project's trace objects in place, one undo step per change.

use crate::support::{example_copy, show_tab, studio};
use app::studio::StudioApp;
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable as _;
use project_model::{Object, TraceConfig};

fn trace(app: &StudioApp) -> TraceConfig {
    match app
        .session()
        .unwrap()
        .project
        .application
        .object("TRC_Conveyor")
    {
        Some(Object::Trace(trace)) => trace.clone(),
        _ => panic!("the example has TRC_Conveyor"),
    }
}

#[test]
fn variables_and_the_trigger_are_edited_in_the_trace_pane() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    show_tab(&mut harness, "Trace");
    let before = trace(harness.state());

    harness.get_by_label("Add variable").click();
    harness.step();
    harness
        .get_by_label("Add variable")
        .type_text("Main.ctuPackages.CV");
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    let after = trace(harness.state());
    assert_eq!(after.variables.len(), before.variables.len() + 1);
    assert_eq!(after.variables.last().unwrap().path, "Main.ctuPackages.CV");

    // Without a trigger the trace records as a ring; one undo step brings it back.
    harness.get_by_label("Trigger").click();
    harness.step();
    harness.step();
    assert!(trace(harness.state()).trigger.is_none());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    assert_eq!(trace(harness.state()).trigger, before.trigger);
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    assert_eq!(trace(harness.state()), before);
}
