//! Editing Structured Text in the studio: typing goes to the model as one undo step per run,
//! diagnostics follow as you type, declarations typed as text become variables, a message
//! jumps to its place, and values show inline while online.

use crate::support::{example_copy, login_with_download, studio, wait_until};
use app::studio::StudioApp;
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{Object, TextTarget};

fn main_body(app: &StudioApp) -> String {
    match app.session().unwrap().project.application.object("Main") {
        Some(Object::Pou(pou)) => pou.body.st_text().unwrap_or_default().to_owned(),
        _ => String::new(),
    }
}

fn main_variables(app: &StudioApp) -> Vec<String> {
    match app.session().unwrap().project.application.object("Main") {
        Some(Object::Pou(pou)) => pou.variables.iter().map(|v| v.name.clone()).collect(),
        _ => Vec::new(),
    }
}

/// Opens Main and puts the caret at the start of its body.
fn open_main(harness: &mut Harness<'_, StudioApp>) {
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

/// Types `text` as a user would: characters as text events, line breaks with Enter.
fn type_text(harness: &mut Harness<'_, StudioApp>, text: &str) {
    for (index, line) in text.split('\n').enumerate() {
        if index > 0 {
            harness.key_press(Key::Enter);
            harness.step();
        }
        if !line.is_empty() {
            harness.event(egui::Event::Text(line.to_owned()));
            harness.step();
        }
    }
    harness.step();
}

#[test]
fn typing_is_one_undo_step_and_diagnostics_follow_as_you_type() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    open_main(&mut harness);
    let original = main_body(harness.state());

    for c in ["a", "b", "c"] {
        type_text(&mut harness, c);
    }
    assert_eq!(main_body(harness.state()), format!("abc{original}"));
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.step();
    harness.step();
    assert_eq!(main_body(harness.state()), original);

    // A name nobody declared is reported while typing, without F11.
    harness.get_by_label("Implementation of Main").click();
    harness.step();
    type_text(&mut harness, "undefinedThing := 1;");
    wait_until(&mut harness, "the live diagnostic", |app| {
        app.live_findings("Main")
            .iter()
            .any(|finding| finding.contains("undefinedThing"))
    });
}

#[test]
fn declarations_typed_as_text_become_variables() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    open_main(&mut harness);
    harness.get_by_label("Declarations of Main").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::End);
    harness.step();
    type_text(&mut harness, "VAR\niExtra : INT := 4;\nEND_VAR\n");
    wait_until(&mut harness, "the new variable", |app| {
        main_variables(app).contains(&"iExtra".to_owned())
    });
    // The table shows the same declarations.
    harness.get_by_label("Table").click();
    harness.step();
    harness.step();
    assert!(harness.query_by_label("Name of iExtra").is_some());
}

#[test]
fn a_build_message_opens_its_place() {
    let project = example_copy(|dir| {
        crate::support::replace_in(
            dir,
            "application/Main.st",
            "GVL_Machine.xBatchComplete := ctuPackages.Q;",
            "GVL_Machine.xBatchComplete := ctuPackages.Q;\nnoSuchVariable := 1;",
        );
    });
    let mut harness = studio(project.path());
    harness.key_press(Key::F11);
    wait_until(&mut harness, "the build", |app| app.last_build().is_some());
    let message = harness
        .state()
        .last_build()
        .unwrap()
        .messages
        .iter()
        .find(|m| m.message.contains("noSuchVariable"))
        .cloned()
        .unwrap();
    let location = format!(
        "{}:{}:{}",
        message.file.display(),
        message.line,
        message.column
    );
    harness.get_by_label(&location).click();
    harness.step();
    harness.step();
    harness.step();
    let (_, range) = message.place.clone().unwrap();
    assert_eq!(
        harness
            .state()
            .body_selection(&TextTarget::Pou("Main".into())),
        Some(range)
    );
}

#[test]
fn values_show_inline_while_online() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    open_main(&mut harness);
    // Alt+F8 logs in; the target has no program, so the studio offers the download.
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    wait_until(&mut harness, "the inline values", |app| {
        app.inline_paths()
            .contains(&"Main.fbConveyor.xMotorOn".to_owned())
            && app.online().value("Main.fbConveyor.xMotorOn").is_some()
            && app.online().value("GVL_IO.xConveyorMotor").is_some()
    });
    // Instances that are called or followed by a member show no value of their own.
    assert!(
        !harness
            .state()
            .inline_paths()
            .contains(&"Main.fbConveyor".to_owned())
    );
}

#[test]
fn a_variable_dragged_from_a_declaration_table_joins_the_watch_list() {
    let project = example_copy(|_| {});
    let mut harness = studio(project.path());
    crate::support::show_tab(&mut harness, "Watch");
    harness.get_by_label("GVL_IO").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    harness.get_by_label("Table").click();
    harness.step();
    harness.step();
    let from = harness
        .get_by_label("Drag GVL_IO.xStartButton")
        .rect()
        .center();
    let to = harness
        .get_by_label("GVL_Machine.eMachineState")
        .rect()
        .center();
    harness.drag_at(from);
    harness.step();
    harness.hover_at(from + egui::vec2(10.0, 10.0));
    harness.step();
    harness.hover_at(to);
    harness.step();
    harness.drop_at(to);
    harness.step();
    harness.step();
    let watched = match harness
        .state()
        .session()
        .unwrap()
        .project
        .application
        .object("WATCH_Machine")
    {
        Some(Object::WatchList(list)) => list.entries.iter().map(|e| e.path.clone()).collect(),
        _ => Vec::new(),
    };
    assert!(
        watched.contains(&"GVL_IO.xStartButton".to_owned()),
        "{watched:?}"
    );
}
