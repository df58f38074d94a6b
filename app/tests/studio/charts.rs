//! Editing CFC and SFC in the studio: a CFC chart's elements moved in one undo step, an SFC
//! step-transition pair inserted and undone, and, online with the embedded simulator, the
//! active steps of the package cycle, a step activated from the editor and the CFC loop's
//! values on its pins.

use crate::support::{example_copy, login_with_download, wait_until};
use app::studio::StudioApp;
use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{Body, CfcChart, ElementId, Object, SfcChart, SfcNode, TextTarget};

fn temp_control() -> TextTarget {
    TextTarget::Pou("TempControl".to_owned())
}

fn pack_cycle() -> TextTarget {
    TextTarget::Pou("PackCycle".to_owned())
}

/// The body of the POU `name` as the model holds it.
fn body(app: &StudioApp, name: &str) -> Body {
    match app.session().unwrap().project.application.object(name) {
        Some(Object::Pou(pou)) => pou.body.clone(),
        other => panic!("no POU {name}: {other:?}"),
    }
}

fn cfc_chart(app: &StudioApp) -> CfcChart {
    match body(app, "TempControl") {
        Body::Cfc { chart } => chart,
        other => panic!("TempControl is not CFC: {other:?}"),
    }
}

fn sfc_chart(app: &StudioApp) -> SfcChart {
    match body(app, "PackCycle") {
        Body::Sfc { chart } => chart,
        other => panic!("PackCycle is not SFC: {other:?}"),
    }
}

/// The studio on `project` in a window large enough for both charts.
pub fn chart_studio(project: &std::path::Path) -> Harness<'static, StudioApp> {
    let app = StudioApp::new(app::studio::Settings::default(), Some(project.to_owned()));
    let mut harness = Harness::builder()
        .with_size([1600.0, 1000.0])
        .build_ui_state(|ui, app: &mut StudioApp| app.ui(ui), app);
    harness.step();
    harness
}

/// Opens the POU `name` from the device tree, as Enter on its node does.
pub fn open_pou(harness: &mut Harness<'_, StudioApp>, name: &str) {
    harness.get_by_label(name).focus();
    harness.step();
    harness.key_press(Key::Enter);
    harness.run_steps(3);
}

/// Clicks at `pos` with the primary button, as a mouse does.
fn click_at(harness: &mut Harness<'_, StudioApp>, pos: egui::Pos2) {
    harness.hover_at(pos);
    harness.step();
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
}

fn command(harness: &mut Harness<'_, StudioApp>, key: Key) {
    harness.key_press_modifiers(Modifiers::COMMAND, key);
    harness.run_steps(3);
}

/// Clicks the SFC element `id` of the package cycle where the editor drew it.
fn click_sfc_element(harness: &mut Harness<'_, StudioApp>, id: ElementId) {
    let rect = harness
        .state()
        .sfc_editor(&pack_cycle())
        .and_then(|editor| editor.element_screen_rect(id))
        .expect("the element is drawn");
    click_at(harness, rect.center());
    harness.run_steps(2);
}

/// The names of the steps in the main sequence, in order.
fn main_steps(chart: &SfcChart) -> Vec<String> {
    chart
        .sequence
        .iter()
        .filter_map(|node| match node {
            SfcNode::Step(step) => Some(step.name.clone()),
            _ => None,
        })
        .collect()
}

#[test]
fn moving_the_cfc_chart_is_one_undo_step() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "TempControl");
    let before = cfc_chart(harness.state());
    assert!(harness.state().cfc_editor(&temp_control()).is_some());
    // A click on the empty canvas left of the chart focuses it; Ctrl+A and an arrow move
    // every element one grid step to the right.
    let canvas = harness.get_by_label("Implementation of TempControl").rect();
    click_at(&mut harness, canvas.min + egui::vec2(6.0, 6.0));
    command(&mut harness, Key::A);
    harness.key_press(Key::ArrowRight);
    harness.run_steps(3);
    let moved = cfc_chart(harness.state());
    assert_eq!(moved.elements.len(), before.elements.len());
    for (old, new) in before.elements.iter().zip(&moved.elements) {
        assert_eq!((new.id, new.x, new.y), (old.id, old.x + 1, old.y));
    }
    command(&mut harness, Key::Z);
    assert_eq!(cfc_chart(harness.state()), before);
}

#[test]
fn a_step_transition_pair_is_inserted_in_the_sfc_chart_and_undone() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "PackCycle");
    let before = sfc_chart(harness.state());
    // After Wait (1), a new step and its transition.
    click_sfc_element(&mut harness, ElementId(1));
    command(&mut harness, Key::T);
    let after = sfc_chart(harness.state());
    assert_eq!(main_steps(&before).len() + 1, main_steps(&after).len());
    assert_eq!(main_steps(&after).first().map(String::as_str), Some("Wait"));
    command(&mut harness, Key::Z);
    assert_eq!(sfc_chart(harness.state()), before);
}

#[test]
fn the_package_cycle_runs_online_and_a_step_is_activated_from_the_editor() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "PackCycle");
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    let step_active = |app: &StudioApp, id: u32| {
        app.sfc_editor(&pack_cycle())
            .and_then(|editor| editor.online())
            .and_then(|online| online.steps.get(&ElementId(id)).copied())
            .is_some_and(|step| step.active)
    };
    wait_until(&mut harness, "Wait shown active", |app| step_active(app, 1));
    assert!(!step_active(harness.state(), 6));
    // Glued is activated by hand with Ctrl+Enter, a write of PackCycle.Glued._x; it stays
    // active while Position is not.
    click_sfc_element(&mut harness, ElementId(6));
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Enter);
    wait_until(&mut harness, "Glued shown active", |app| {
        step_active(app, 6)
    });
}

#[test]
fn the_cfc_loop_shows_values_on_its_pins_online() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "TempControl");
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    // The SUB box (2) computes the error; the output element (12) shows the temperature.
    wait_until(&mut harness, "values on the pins", |app| {
        app.cfc_editor(&temp_control())
            .and_then(|editor| editor.online())
            .is_some_and(|online| {
                online
                    .values
                    .contains_key(&(ElementId(2), Some("OUT".to_owned())))
                    && online.values.contains_key(&(ElementId(12), None))
            })
    });
}

#[test]
fn a_variable_dragged_from_the_declaration_table_onto_a_cfc_input_becomes_its_expression() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "TempControl");
    harness.get_by_label("Table").click();
    harness.run_steps(2);
    let from = harness.get_by_label("Drag TempControl.rKp").rect().center();
    // The input element 1 (rSetpoint) sits at grid (2, 2), 12 points a grid unit.
    let canvas = harness.get_by_label("Implementation of TempControl").rect();
    let to = canvas.min + egui::vec2(4.0, 2.5) * 12.0;
    harness.drag_at(from);
    harness.step();
    for step in 1..=5 {
        harness.hover_at(from + (to - from) * (step as f32 / 5.0));
        harness.step();
    }
    // Released where the pointer stays, as a mouse does (the canvas places at the pointer).
    harness.event(Event::PointerButton {
        pos: to,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run_steps(3);
    let chart = cfc_chart(harness.state());
    let first = chart
        .elements
        .iter()
        .find(|element| element.id == ElementId(1))
        .map(|element| element.kind.clone());
    assert!(
        matches!(&first, Some(project_model::CfcElementKind::Input { expression }) if expression == "rKp"),
        "{first:?}"
    );
}

#[test]
fn a_type_error_in_a_transition_is_marked_and_the_message_selects_it() {
    let project = example_copy(|dir| {
        crate::support::replace_in(
            dir,
            "application/PackCycle.pou.toml",
            "condition = \"NOT xGlue\"",
            "condition = \"iPackages\"",
        );
    });
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "PackCycle");
    wait_until(&mut harness, "the finding at transition 5", |app| {
        app.sfc_editor(&pack_cycle()).is_some_and(|editor| {
            editor.diagnostics().iter().any(|diagnostic| {
                diagnostic.element == Some(ElementId(5))
                    && diagnostic.severity == editor::Severity::Error
            })
        })
    });
    harness.key_press(Key::F11);
    wait_until(&mut harness, "the build", |app| {
        !app.is_building() && app.last_build().is_some()
    });
    harness.run_steps(2);
    harness.get_by_label_contains(":PackCycle:1:5").click();
    harness.run_steps(4);
    let selected = harness
        .state()
        .sfc_editor(&pack_cycle())
        .map(|editor| editor.selection().to_vec());
    assert_eq!(selected, Some(vec![ElementId(5)]));
}

#[test]
fn a_value_prepared_on_a_cfc_input_is_written_with_ctrl_f7() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "TempControl");
    login_with_download(&mut harness);
    harness.key_press(Key::F5);
    wait_until(&mut harness, "the set point's value", |app| {
        app.cfc_editor(&temp_control())
            .and_then(|editor| editor.online())
            .is_some_and(|online| online.values.contains_key(&(ElementId(1), None)))
    });
    // The input element 1 (rSetpoint) sits at grid (2, 2), 12 points a grid unit: a click
    // selects it, Enter opens the field of the value to write.
    let canvas = harness.get_by_label("Implementation of TempControl").rect();
    click_at(&mut harness, canvas.min + egui::vec2(4.0, 2.5) * 12.0);
    harness.key_press(Key::Enter);
    harness.run_steps(2);
    harness.event(Event::Text("45.0".to_owned()));
    harness.run_steps(2);
    harness.key_press(Key::Enter);
    harness.run_steps(2);
    harness.key_press_modifiers(Modifiers::COMMAND, Key::F7);
    wait_until(&mut harness, "the set point written", |app| {
        app.online()
            .program_value("TempControl.rSetpoint")
            .is_some_and(|value| value.text.starts_with("45") && !value.forced)
    });
}

#[test]
fn an_sfc_edit_that_breaks_a_rule_is_refused_with_the_reason() {
    let project = example_copy(|_| {});
    let mut harness = chart_studio(project.path());
    open_pou(&mut harness, "PackCycle");
    let before = sfc_chart(harness.state());
    // A jump only ends a sequence: not after the transition 5, which Glued follows.
    click_sfc_element(&mut harness, ElementId(5));
    command(&mut harness, Key::J);
    assert_eq!(sfc_chart(harness.state()), before);
    let status = harness.state().status().cloned();
    assert!(
        status
            .as_ref()
            .is_some_and(|message| message.is_error && message.text.contains("jump")),
        "{status:?}"
    );
}
