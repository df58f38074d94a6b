//! Debugging in the studio (`docs/debugging.md`): F9 sets and clears breakpoints (kept in the
//! settings, listed in the Breakpoints pane, drawn in the gutter), a halt reported by the
//! session shows its statement and the call stack, a caller's frame opens its POU at the call,
//! and flow control marks the lines that ran.

use crate::support::{example_copy, studio, wait_until};
use app::studio::{Breakpoint, BreakpointPlace, HaltedTask, StackFrame, StudioApp};
use editor::{BreakpointLook, BreakpointMark};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::TextTarget;

fn main_target() -> TextTarget {
    TextTarget::Pou("Main".to_owned())
}

/// Opens Main and puts the caret at the start of its body, on its first line (a comment).
fn open_main_at_start(harness: &mut Harness<'_, StudioApp>) {
    harness.get_by_label("Main").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    harness.get_by_label("Implementation of Main").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Home);
    harness.step();
}

fn breakpoints(app: &StudioApp) -> Vec<Breakpoint> {
    let dir = &app.session().unwrap().dir;
    app.settings()
        .breakpoints
        .get(&app::studio::Settings::project_key(dir))
        .map(|list| list.all().to_vec())
        .unwrap_or_default()
}

fn main_place(line: u32) -> BreakpointPlace {
    BreakpointPlace::text("application/Main.st", line)
}

fn press(harness: &mut Harness<'_, StudioApp>, modifiers: Modifiers, key: Key) {
    harness.key_press_modifiers(modifiers, key);
    harness.step();
    harness.step();
}

#[test]
fn f9_sets_a_breakpoint_on_the_next_statement_lists_it_and_clears_it() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    open_main_at_start(&mut harness);

    // Line 1 is a comment: the breakpoint goes to the statement on line 2.
    press(&mut harness, Modifiers::NONE, Key::F9);
    assert_eq!(
        breakpoints(harness.state()),
        vec![Breakpoint::at(main_place(2))]
    );
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert_eq!(
        marks.breakpoints,
        vec![BreakpointMark {
            line: 1,
            look: BreakpointLook::Enabled
        }]
    );

    // The Breakpoints pane lists it; switching it off there changes its look.
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label("Breakpoints").click();
    harness.step();
    harness.step();
    harness.get_by_label("application/Main.st:2").click();
    harness.step();
    harness.step();
    assert!(!breakpoints(harness.state())[0].enabled);
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert_eq!(marks.breakpoints[0].look, BreakpointLook::Disabled);

    // F9 on the same line clears it.
    harness.get_by_label("Implementation of Main").focus();
    harness.step();
    press(&mut harness, Modifiers::NONE, Key::F9);
    assert!(breakpoints(harness.state()).is_empty());
    harness.get_by_label("No breakpoints (F9 on a statement sets one)");
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert!(marks.breakpoints.is_empty());
}

#[test]
fn stepping_offline_says_to_log_in() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    press(&mut harness, Modifiers::NONE, Key::F10);
    let status = harness.state().status().map(|status| status.text.clone());
    assert_eq!(status.as_deref(), Some("log in to debug (Alt+F8)"));
}

fn halted_in_conveyor() -> Vec<HaltedTask> {
    vec![HaltedTask {
        task: "MainTask".to_owned(),
        beneath: None,
        frames: vec![
            StackFrame {
                pou: "FB_Conveyor".to_owned(),
                instance: Some("Main.fbConveyor".to_owned()),
                file: "application/FB_Conveyor.st".to_owned(),
                line: 3,
            },
            StackFrame {
                pou: "Main".to_owned(),
                instance: Some("Main".to_owned()),
                file: "application/Main.st".to_owned(),
                line: 2,
            },
        ],
    }]
}

#[test]
fn a_halt_shows_its_statement_and_a_callers_frame_opens_the_caller_at_the_call() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.state_mut().set_halted(halted_in_conveyor());
    harness.step();
    harness.step();
    harness.step();

    // The halted statement is open with the yellow arrow.
    let conveyor = TextTarget::Pou("FB_Conveyor".to_owned());
    let marks = harness.state().body_debug_marks(&conveyor).unwrap();
    assert_eq!(marks.halt_line, Some(2));
    assert!(!marks.halt_is_caller);

    // The call stack lists both frames; the caller's opens Main at the call.
    harness.get_by_label("Main.fbConveyor (FB_Conveyor) application/FB_Conveyor.st:3");
    harness
        .get_by_label("Main (Main) application/Main.st:2")
        .click();
    harness.step();
    harness.step();
    harness.step();
    assert!(
        harness
            .state()
            .open_documents()
            .contains(&app::studio::TreeNode::Object("Main".to_owned()))
    );
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert_eq!(marks.halt_line, Some(1));
    assert!(marks.halt_is_caller);
    let selection = harness.state().body_selection(&main_target()).unwrap();
    let body = harness
        .state()
        .session()
        .unwrap()
        .project
        .application
        .object("Main");
    let text = match body {
        Some(project_model::Object::Pou(pou)) => pou.body.st_text().unwrap().to_owned(),
        _ => panic!("Main is a POU"),
    };
    assert_eq!(text[..selection.start].matches('\n').count(), 1);
    assert_eq!(harness.state().debug_state().shown(), Some(("MainTask", 1)));
}

#[test]
fn flow_control_marks_the_lines_that_ran_once_switched_on() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    open_main_at_start(&mut harness);
    harness
        .state_mut()
        .set_flow(vec![("application/Main.st".to_owned(), vec![2, 7])]);
    harness.step();
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert!(marks.flow_lines.is_empty());
    harness.get_by_label("Debug").click();
    harness.run();
    harness.get_by_label("Flow control").click();
    harness.step();
    harness.step();
    assert!(harness.state().debug_state().flow_control);
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert_eq!(marks.flow_lines, vec![1, 6]);
}
