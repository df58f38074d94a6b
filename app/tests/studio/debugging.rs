//! Debugging in the studio (`docs/debugging.md`): F9 sets and clears breakpoints (kept in the
//! settings, listed in the Breakpoints pane, drawn in the gutter), a halt reported by the
//! session shows its statement and the call stack, a caller's frame opens its POU at the call,
//! and flow control marks the lines that ran.

use crate::support::{example_copy, login_with_download, studio, wait_until};
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
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
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
    // The caret is at the statement's start, nothing selected (the line is marked already).
    let caret = harness.state().body_selection(&conveyor).unwrap();
    assert!(caret.is_empty(), "{caret:?}");
    let text = pou_text(harness.state(), "FB_Conveyor");
    assert!(
        text[caret.start..].starts_with("xRunRequest := FALSE;"),
        "{:?}",
        &text[caret.start..]
    );

    // The call stack lists both frames; the caller's opens Main at the call.
    harness.get_by_label("Main.fbConveyor (FB_Conveyor) application/FB_Conveyor.st:3");
    harness.get_by_label("Main application/Main.st:2").click();
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
    let text = pou_text(harness.state(), "Main");
    assert_eq!(text[..selection.start].matches('\n').count(), 1);
    assert!(selection.is_empty(), "{selection:?}");
    assert_eq!(harness.state().debug_state().shown(), Some(("MainTask", 1)));
}

/// The Structured Text body of POU `pou` as the open project has it.
fn pou_text(app: &StudioApp, pou: &str) -> String {
    match app.session().unwrap().project.application.object(pou) {
        Some(project_model::Object::Pou(pou)) => pou.body.st_text().unwrap().to_owned(),
        _ => panic!("{pou} is a POU"),
    }
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
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label("Flow control").click();
    harness.step();
    harness.step();
    assert!(harness.state().debug_state().flow_control);
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert_eq!(marks.flow_lines, vec![1, 6]);
}

/// The line of the shown frame's halt marker in the body of `pou`, if its editor marks one.
fn halt_line(app: &StudioApp, pou: &str) -> Option<usize> {
    app.body_debug_marks(&TextTarget::Pou(pou.to_owned()))
        .and_then(|marks| marks.halt_line)
}

/// Waits until the halt marker of `pou`'s editor is on `line` (from 0).
fn wait_for_halt_at(harness: &mut Harness<'_, StudioApp>, pou: &str, line: usize) {
    wait_until(
        harness,
        &format!("the halt at line {} of {pou}", line + 1),
        |app| app.debug_state().is_halted() && halt_line(app, pou) == Some(line),
    );
}

#[test]
fn in_the_simulator_a_breakpoint_halts_steps_go_on_a_caller_frame_opens_and_logout_releases() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    open_main_at_start(&mut harness);
    // F9 on the comment of line 1 sets the breakpoint on the call of fbConveyor on line 2.
    press(&mut harness, Modifiers::NONE, Key::F9);
    assert_eq!(
        breakpoints(harness.state()),
        vec![Breakpoint::at(main_place(2))]
    );
    login_with_download(&mut harness);
    harness.key_press(Key::F5);

    // The task halts there; the marker is on the line and Main's values show inline.
    wait_for_halt_at(&mut harness, "Main", 1);
    assert_eq!(harness.state().debug_state().shown(), Some(("MainTask", 0)));
    // The status bar says the running application is halted, not merely running.
    assert!(
        harness
            .query_by_label_contains("running, halted at a breakpoint")
            .is_some()
    );
    wait_until(&mut harness, "inline values of Main", |app| {
        app.inline_paths()
            .iter()
            .any(|path| path.starts_with("Main.") || path.starts_with("GVL_IO."))
    });

    // F10 runs the call whole and halts on the next statement, line 6.
    press(&mut harness, Modifiers::NONE, Key::F10);
    wait_for_halt_at(&mut harness, "Main", 5);

    // F5 goes on to the breakpoint in the next cycle; F8 there steps into FB_Conveyor.
    press(&mut harness, Modifiers::NONE, Key::F5);
    wait_for_halt_at(&mut harness, "Main", 1);
    press(&mut harness, Modifiers::NONE, Key::F8);
    wait_for_halt_at(&mut harness, "FB_Conveyor", 1);
    let frames = harness
        .state()
        .debug_state()
        .halted()
        .iter()
        .find(|task| task.task == "MainTask")
        .unwrap()
        .frames
        .clone();
    assert_eq!(frames.len(), 2);
    assert_eq!(frames[0].instance.as_deref(), Some("Main.fbConveyor"));
    // Its inline values are the halted instance's.
    wait_until(&mut harness, "inline values of Main.fbConveyor", |app| {
        app.inline_paths()
            .iter()
            .any(|path| path.starts_with("Main.fbConveyor."))
    });

    // The caller's frame in the Call stack opens Main at the call.
    harness.get_by_label("Main application/Main.st:2").click();
    harness.step();
    harness.step();
    assert_eq!(harness.state().debug_state().shown(), Some(("MainTask", 1)));
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert_eq!(marks.halt_line, Some(1));
    assert!(marks.halt_is_caller);

    // F5 continues: the task runs on and halts at the breakpoint again, shown as the halt
    // itself rather than as the caller's frame it was shown as before.
    press(&mut harness, Modifiers::NONE, Key::F5);
    wait_until(&mut harness, "the halt at the breakpoint again", |app| {
        app.debug_state().shown() == Some(("MainTask", 0)) && halt_line(app, "Main") == Some(1)
    });
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert!(!marks.halt_is_caller);

    // Logging out ends the debug session: nothing is halted any more, and logged in again
    // the target reports no halted task.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F8);
    harness.step();
    harness.step();
    assert!(!harness.state().online().is_logged_in());
    assert!(!harness.state().debug_state().is_halted());
    harness.get_by_label("Debug").click();
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label("Breakpoints").click();
    harness.step();
    harness.step();
    harness.get_by_label("Remove all").click();
    harness.step();
    assert!(breakpoints(harness.state()).is_empty());
    harness.key_press_modifiers(Modifiers::ALT, Key::F8);
    wait_until(&mut harness, "the login again", |app| {
        *app.online().phase() == app::studio::Phase::Online
    });
    let cycle = harness.state().online().cycle();
    wait_until(&mut harness, "the program running on", |app| {
        app.online().cycle() > cycle + 10
    });
    assert!(!harness.state().debug_state().is_halted());
}

#[test]
fn in_the_simulator_flow_control_marks_the_lines_of_main_that_ran() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    open_main_at_start(&mut harness);
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    harness.get_by_label("Debug").click();
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label("Flow control").click();
    harness.step();
    // The call of fbConveyor (line 2) runs every cycle; the package count (line 15) only on a
    // package, which never comes here.
    wait_until(&mut harness, "the flow marks of Main", |app| {
        app.body_debug_marks(&main_target())
            .is_some_and(|marks| marks.flow_lines.contains(&1))
    });
    let marks = harness.state().body_debug_marks(&main_target()).unwrap();
    assert!(!marks.flow_lines.contains(&14), "{:?}", marks.flow_lines);

    // A body opened while flow control is on is recorded too: FB_Conveyor's first IF.
    harness.get_by_label("FB_Conveyor").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    let conveyor = TextTarget::Pou("FB_Conveyor".to_owned());
    wait_until(&mut harness, "the flow marks of FB_Conveyor", |app| {
        app.body_debug_marks(&conveyor)
            .is_some_and(|marks| marks.flow_lines.contains(&1))
    });
}

#[test]
fn in_the_simulator_a_method_halted_in_shows_its_locals_from_its_frame() {
    let project = example_copy(|dir| {
        let main = dir.join("application/Main.st");
        let mut text = std::fs::read_to_string(&main).unwrap();
        text.push_str("GVL_Machine.xResetCounter := NOT fbConveyor.Reset();\n");
        std::fs::write(&main, text).unwrap();
    });
    let mut harness = studio(project.path());
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    open_main_at_start(&mut harness);
    // The call of the method is the last line; F9 there, then run and step into it.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::End);
    harness.step();
    harness.key_press(Key::ArrowUp);
    harness.step();
    press(&mut harness, Modifiers::NONE, Key::F9);
    assert_eq!(
        breakpoints(harness.state()),
        vec![Breakpoint::at(main_place(17))]
    );
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    wait_for_halt_at(&mut harness, "Main", 16);
    press(&mut harness, Modifiers::NONE, Key::F8);
    let method = TextTarget::Method {
        pou: "FB_Conveyor".to_owned(),
        method: "Reset".to_owned(),
    };
    wait_until(&mut harness, "the halt in FB_Conveyor.Reset", |app| {
        app.body_debug_marks(&method)
            .is_some_and(|marks| marks.halt_line == Some(0))
    });
    // The method's result lives in its frame: FRAME_READ gives it before it is set.
    wait_until(&mut harness, "the method's locals", |app| {
        app.online()
            .frame_locals()
            .iter()
            .any(|(name, value)| name == "Reset" && value == "FALSE")
    });
}

#[test]
fn in_the_simulator_flow_control_marks_the_programs_of_both_tasks() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    open_main_at_start(&mut harness);
    // MotionControl runs in MotionTask, Main in MainTask.
    harness.get_by_label("MotionControl").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    harness.get_by_label("Debug").click();
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label("Flow control").click();
    harness.step();
    // MotionControl's editor is in front: its first line runs every cycle of MotionTask.
    let motion = TextTarget::Pou("MotionControl".to_owned());
    wait_until(&mut harness, "the flow marks of MotionControl", |app| {
        app.body_debug_marks(&motion)
            .is_some_and(|marks| marks.flow_lines.contains(&0))
    });
    // Main's editor, brought to the front by its tab, marks the call on line 2 of MainTask.
    for node in harness.query_all_by_label("Main") {
        node.click();
    }
    harness.step();
    harness.step();
    wait_until(&mut harness, "the flow marks of Main", |app| {
        app.body_debug_marks(&main_target())
            .is_some_and(|marks| marks.flow_lines.contains(&1))
    });
}

#[test]
fn in_the_simulator_flow_while_halted_marks_the_halted_cycle_so_far() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    open_main_at_start(&mut harness);
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    harness.get_by_label("Debug").click();
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label("Flow control").click();
    harness.step();
    // Line 12 runs every cycle, so a complete cycle marks it.
    wait_until(&mut harness, "the flow marks of a complete cycle", |app| {
        app.body_debug_marks(&main_target())
            .is_some_and(|marks| marks.flow_lines.contains(&11))
    });
    // A breakpoint on line 7 halts the cycle before line 12 runs.
    harness.get_by_label("Implementation of Main").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Home);
    harness.step();
    for _ in 0..6 {
        harness.key_press(Key::ArrowDown);
        harness.step();
    }
    press(&mut harness, Modifiers::NONE, Key::F9);
    assert_eq!(
        breakpoints(harness.state()),
        vec![Breakpoint::at(main_place(7))]
    );
    wait_for_halt_at(&mut harness, "Main", 6);
    wait_until(&mut harness, "the flow marks of the halted cycle", |app| {
        app.body_debug_marks(&main_target()).is_some_and(|marks| {
            marks.flow_lines.contains(&1)
                && marks.flow_lines.contains(&6)
                && !marks.flow_lines.contains(&11)
        })
    });
}

#[test]
fn in_the_simulator_a_condition_that_does_not_compile_is_named_under_its_breakpoint() {
    let project = example_copy(|_| {});
    let mut list = app::studio::Breakpoints::default();
    let mut broken = Breakpoint::at(main_place(2));
    broken.condition = "xNoSuchVariable AND".to_owned();
    list.toggle(main_place(2));
    list.update(broken);
    let mut settings = app::studio::Settings::default();
    settings
        .breakpoints
        .insert(app::studio::Settings::project_key(project.path()), list);
    let app = StudioApp::new(settings, Some(project.path().to_owned()));
    let mut harness = Harness::builder()
        .with_size([1400.0, 900.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness.state_mut().build();
    wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    login_with_download(&mut harness);
    // The condition compiles on a worker thread; its error then names the breakpoint.
    wait_until(&mut harness, "the condition's error", |app| {
        app.online().breakpoint_problem(&main_place(2)).is_some()
    });
    let problem = harness
        .state()
        .online()
        .breakpoint_problem(&main_place(2))
        .unwrap()
        .to_owned();
    assert!(problem.contains("application/Main.st:2"), "{problem}");
    assert!(problem.contains("xNoSuchVariable AND"), "{problem}");
    // The Breakpoints pane shows it under the breakpoint, besides the status line.
    let shown = |harness: &Harness<'_, StudioApp>| harness.query_all_by_label(&problem).count();
    let elsewhere = shown(&harness);
    harness.get_by_label("Debug").click();
    // Logged in, the studio repaints every 100 ms, so `run` may never settle under load.
    harness.run_steps(3);
    harness.get_by_label("Breakpoints").click();
    harness.step();
    harness.step();
    assert_eq!(shown(&harness), elsewhere + 1);
}
