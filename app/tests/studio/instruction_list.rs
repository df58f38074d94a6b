//! Instruction List in the studio: a POU added in IL opens in a text editor that highlights
//! IL's operators and labels, its findings are on IL lines, and its text is saved in a `.il`
//! file.

use egui::{Color32, Key, Shape};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{Body, Object};

use super::tree::{enter_text, example_copy, menu, project, shortcut, studio};
use app::studio::StudioApp;

/// The colour the editor painted the first occurrence of `word` with, on the line whose
/// text is `line`.
fn color_of(harness: &Harness<'_, StudioApp>, line: &str, word: &str) -> Option<Color32> {
    let mut shapes = Vec::new();
    for clipped in &harness.output().shapes {
        collect_text(&clipped.shape, &mut shapes);
    }
    shapes
        .into_iter()
        .find_map(|galley: std::sync::Arc<egui::Galley>| {
            let job = &galley.job;
            if job.text != line {
                return None;
            }
            let at = job.text.find(word)?;
            job.sections
                .iter()
                .find(|section| section.byte_range.start.0 <= at && at < section.byte_range.end.0)
                .map(|section| section.format.color)
        })
}

fn collect_text(shape: &Shape, out: &mut Vec<std::sync::Arc<egui::Galley>>) {
    match shape {
        Shape::Text(text) => out.push(text.galley.clone()),
        Shape::Vec(shapes) => {
            for shape in shapes {
                collect_text(shape, out);
            }
        }
        _ => {}
    }
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
fn a_pou_in_il_opens_highlighted_reports_on_its_lines_and_is_saved_as_an_il_file() {
    let dir = example_copy();
    let mut harness = studio(dir.path());
    menu(&mut harness, "Application", "Add POU…");
    harness.get_by_label("Instruction List (IL)").click();
    harness.run();
    enter_text(&mut harness, "Name", "PRG_Il");
    let added = match project(&harness).application.object("PRG_Il") {
        Some(Object::Pou(pou)) => pou.body.clone(),
        other => panic!("PRG_Il is not a POU: {other:?}"),
    };
    assert_eq!(
        added,
        Body::Il {
            text: String::new()
        }
    );

    harness.get_by_label("Implementation of PRG_Il").click();
    harness.step();
    type_text(&mut harness, "LD TRUE\nJMPC Done\nDone: ST nowhere");
    harness.run();

    let operator = color_of(&harness, "JMPC Done", "JMPC");
    let target = color_of(&harness, "JMPC Done", "Done");
    let load = color_of(&harness, "LD TRUE", "LD");
    let label = color_of(&harness, "Done: ST nowhere", "Done");
    let operand = color_of(&harness, "Done: ST nowhere", "nowhere");
    assert!(operator.is_some() && target.is_some() && operand.is_some());
    assert_eq!(operator, load, "operators share the keyword colour");
    assert_eq!(target, label, "a jump's target is coloured as its label");
    assert_ne!(operator, operand, "an operand is not an operator");
    assert_ne!(label, operand, "an operand is not a label");

    // The unknown name is found on the IL line, while typing.
    super::support::wait_until(&mut harness, "the live finding", |app| {
        app.live_findings("PRG_Il")
            .iter()
            .any(|finding| finding.contains("nowhere"))
    });

    shortcut(&mut harness, Key::S);
    let saved = std::fs::read_to_string(dir.path().join("application/PRG_Il.il")).unwrap();
    assert_eq!(saved, "LD TRUE\nJMPC Done\nDone: ST nowhere");
}

/// `Main` of the example in IL: the conveyor called with its inputs, its motor output copied.
const MAIN_IL: &str = "(* The conveyor *)
CAL fbConveyor(
    xStart := GVL_IO.xStartButton,
    xStop := GVL_IO.xStopButton OR GVL_IO.xEmergencyStop,
    tStartDelay := T#2S)
LD fbConveyor.xMotorOn
ST GVL_IO.xConveyorMotor
";

/// The example with `Main` in IL.
fn example_with_il_main() -> tempfile::TempDir {
    use super::support;

    support::example_copy(|dir| {
        support::replace_in(
            dir,
            "application/Main.pou.toml",
            "language = \"st\"",
            "language = \"il\"",
        );
        std::fs::remove_file(dir.join("application/Main.st")).unwrap();
        std::fs::write(dir.join("application/Main.il"), MAIN_IL).unwrap();
    })
}

#[test]
fn an_il_body_shows_values_at_its_operands_while_online() {
    use super::support;

    let project = example_with_il_main();
    let mut harness = support::studio(project.path());
    harness.get_by_label("Main").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    support::login_with_download(&mut harness);
    harness.key_press(Key::F5);
    support::wait_until(&mut harness, "the values at the IL's operands", |app| {
        let paths = app.inline_paths();
        paths.contains(&"Main.fbConveyor.xMotorOn".to_owned())
            && paths.contains(&"GVL_IO.xConveyorMotor".to_owned())
            && app.online().value("GVL_IO.xConveyorMotor").is_some()
    });
    // The current result's hidden variable is no operand, so it shows nowhere.
    assert!(
        harness
            .state()
            .inline_paths()
            .iter()
            .all(|path| !path.contains("__"))
    );
}

#[test]
fn f9_in_an_il_body_sets_a_breakpoint_on_the_next_instruction_of_the_il_file() {
    use super::support;
    use app::studio::{Breakpoint, BreakpointPlace};
    use egui::Modifiers;

    let project = example_with_il_main();
    let mut harness = support::studio(project.path());
    harness.state_mut().build();
    support::wait_until(&mut harness, "the build", |app| {
        app.last_build().is_some_and(|build| build.image.is_some())
    });
    harness.get_by_label("Main").focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.step();
    harness.step();
    harness.get_by_label("Implementation of Main").click();
    harness.step();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Home);
    harness.step();

    // Line 1 is a comment: the breakpoint goes to the call on line 2.
    harness.key_press(Key::F9);
    harness.step();
    harness.step();
    let app = harness.state();
    let dir = &app.session().unwrap().dir;
    let set = app
        .settings()
        .breakpoints
        .get(&app::studio::Settings::project_key(dir))
        .map(|list| list.all().to_vec())
        .unwrap_or_default();
    assert_eq!(
        set,
        vec![Breakpoint::at(BreakpointPlace::text(
            "application/Main.il",
            2
        ))]
    );
    let marks = app
        .body_debug_marks(&project_model::TextTarget::Pou("Main".into()))
        .unwrap();
    assert_eq!(marks.breakpoints.len(), 1);
    assert_eq!(marks.breakpoints[0].line, 1);
}
