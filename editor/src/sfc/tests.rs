//! Tests of the SFC editor driven through egui, as a user would: clicks, keys and text. Each
//! test keeps the chart the way the app would, applies the reported changes to it and gives
//! it back to the editor every frame.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::sfc_edit::{SfcEditError, SfcRule, insert_step_transition_after};
use project_model::{ElementId, SfcChart, SfcNode};

use super::*;
use crate::{BlockSignature, CompletionItem, CompletionKind, DiagramServices};

/// Services knowing the variables `start`, `stop` and `level`, as the app's would.
struct FakeServices;

impl DiagramServices for FakeServices {
    fn variables(&self, prefix: &str) -> Vec<CompletionItem> {
        ["start", "stop", "level"]
            .into_iter()
            .filter(|name| name.starts_with(prefix))
            .map(|label| CompletionItem {
                label: label.to_owned(),
                kind: CompletionKind::Variable,
                detail: "BOOL".to_owned(),
            })
            .collect()
    }

    fn blocks(&self, _prefix: &str) -> Vec<CompletionItem> {
        Vec::new()
    }

    fn structure_members(&self, _type_name: &str) -> Option<Vec<String>> {
        None
    }

    fn signature(&self, _type_name: &str) -> Option<BlockSignature> {
        None
    }

    fn is_declared(&self, name: &str) -> bool {
        ["start", "stop", "level"].contains(&name)
    }
}

/// What the app would keep: the editor, the model's chart and what came out.
struct Host {
    editor: SfcEditor,
    chart: SfcChart,
    changes: usize,
    refusals: Vec<SfcEditError>,
    online: Vec<SfcOnlineCommand>,
    toggles: Vec<crate::BodyPlace>,
}

fn harness(chart: SfcChart) -> Harness<'static, Host> {
    let mut editor = SfcEditor::new(&chart);
    editor.request_focus();
    let host = Host {
        editor,
        chart,
        changes: 0,
        refusals: Vec::new(),
        online: Vec::new(),
        toggles: Vec::new(),
    };
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1100.0, 700.0))
        .build_ui_state(
            |ui, host: &mut Host| {
                host.editor.set_chart(&host.chart);
                let output = host.editor.show(ui, "Body of Sequence", &FakeServices);
                if let Some(change) = output.change {
                    host.chart = change.chart;
                    host.changes += 1;
                }
                host.refusals.extend(output.refusal);
                host.online.extend(output.online);
                host.toggles.extend(output.toggle_breakpoint);
            },
            host,
        );
    harness.run_steps(2);
    harness
}

fn command(harness: &mut Harness<'static, Host>, modifiers: Modifiers, key: Key) {
    harness.key_press_modifiers(modifiers, key);
    harness.run_steps(3);
}

fn type_and_enter(harness: &mut Harness<'static, Host>, text: &str) {
    harness.event(Event::Text(text.to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
}

/// A primary click on node `id`, after hovering there as a mouse does.
fn click(harness: &mut Harness<'static, Host>, id: ElementId, modifiers: Modifiers) {
    let pos = harness
        .state()
        .editor
        .element_screen_rect(id)
        .expect("the node is shown")
        .center();
    harness.hover_at(pos);
    harness.run_steps(1);
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers,
        });
    }
    harness.run_steps(2);
}

/// The main sequence's node kinds and names, for readable expectations.
fn shape(nodes: &[SfcNode]) -> Vec<String> {
    nodes
        .iter()
        .map(|node| match node {
            SfcNode::Step(step) => step.name.clone(),
            SfcNode::Transition(transition) => format!("T {}", transition.condition),
            SfcNode::Jump(jump) => format!("-> {}", jump.target),
            SfcNode::Parallel(branches) => format!(
                "P[{}]",
                branches
                    .branches
                    .iter()
                    .map(|branch| shape(&branch.nodes).join(" "))
                    .collect::<Vec<_>>()
                    .join(" | ")
            ),
            SfcNode::Alternative(branches) => format!("A{}", branches.branches.len()),
            SfcNode::Macro(macro_step) => format!("M {}", macro_step.name),
        })
        .collect()
}

#[test]
fn a_parallel_branch_is_drawn_with_the_mouse_and_the_keyboard() {
    let mut harness = harness(SfcChart::new_body());
    click(&mut harness, ElementId(2), Modifiers::NONE);
    assert_eq!(harness.state().editor.selection(), [ElementId(2)]);
    command(&mut harness, Modifiers::COMMAND, Key::T);
    // The new step is selected; a second step goes below it, and both become a parallel
    // branch with a third step on the right.
    assert_eq!(harness.state().editor.selection(), [ElementId(4)]);
    command(&mut harness, Modifiers::COMMAND, Key::P);
    let host = harness.state();
    assert_eq!(
        shape(&host.chart.sequence),
        ["Init", "T FALSE", "P[Step1 | Step2]", "T FALSE", "-> Init"]
    );
    assert_eq!(host.changes, 2);
    // The new branch's step is selected; the arrows move between the branches.
    assert_eq!(host.editor.selection(), [ElementId(7)]);
    command(&mut harness, Modifiers::NONE, Key::ArrowLeft);
    assert_eq!(harness.state().editor.selection(), [ElementId(4)]);
    command(&mut harness, Modifiers::NONE, Key::ArrowRight);
    assert_eq!(harness.state().editor.selection(), [ElementId(7)]);
    // It is renamed by typing.
    harness.key_press(Key::Enter);
    harness.run_steps(2);
    harness.event(Event::Key {
        key: Key::A,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers: Modifiers::COMMAND,
    });
    harness.run_steps(1);
    type_and_enter(&mut harness, "Heat");
    let host = harness.state();
    assert_eq!(
        shape(&host.chart.sequence),
        ["Init", "T FALSE", "P[Step1 | Heat]", "T FALSE", "-> Init"]
    );
    assert_eq!(host.changes, 3);
    assert_eq!(host.editor.chart(), &host.chart);
}

#[test]
fn a_step_inserted_below_the_visible_part_is_scrolled_into_view() {
    let mut harness = harness(SfcChart::new_body());
    harness.set_size(egui::vec2(900.0, 260.0));
    harness.run_steps(2);
    click(&mut harness, ElementId(2), Modifiers::NONE);
    for _ in 0..6 {
        command(&mut harness, Modifiers::COMMAND, Key::T);
    }
    let editor = &harness.state().editor;
    let selected = editor.selection()[0];
    let shown = editor.element_screen_rect(selected).expect("laid out");
    assert!(
        shown.bottom() <= 260.0 && shown.top() >= 0.0,
        "the new step at {shown:?} is outside the view"
    );
    assert_eq!(harness.state().chart.sequence.len(), 15);
}

#[test]
fn the_arrows_move_and_extend_the_selection_for_a_branch_around_a_run() {
    let chart = insert_step_transition_after(&SfcChart::new_body(), ElementId(2)).unwrap();
    let mut harness = harness(chart);
    click(&mut harness, ElementId(2), Modifiers::NONE);
    // Down with Shift takes Step1 and its transition.
    command(&mut harness, Modifiers::SHIFT, Key::ArrowDown);
    command(&mut harness, Modifiers::SHIFT, Key::ArrowDown);
    assert_eq!(
        harness.state().editor.selection(),
        [ElementId(2), ElementId(4), ElementId(5)]
    );
    command(&mut harness, Modifiers::COMMAND, Key::R);
    let host = harness.state();
    assert_eq!(shape(&host.chart.sequence), ["Init", "A2", "-> Init"]);
    assert!(host.refusals.is_empty());
}

#[test]
fn an_invalid_structure_is_refused_with_its_reason_and_nothing_changes() {
    let mut harness = harness(SfcChart::new_body());
    click(&mut harness, ElementId(3), Modifiers::NONE);
    command(&mut harness, Modifiers::NONE, Key::Delete);
    let expected = SfcEditError::Structure {
        rule: SfcRule::MainEndsWithJump,
        element: ElementId(2),
    };
    let host = harness.state();
    assert_eq!(host.refusals, std::slice::from_ref(&expected));
    assert_eq!(host.changes, 0);
    assert_eq!(host.chart, SfcChart::new_body());
    // The editor shows the reason.
    harness.get_by_label(&expected.to_string());
    // A parallel branch around a transition is refused too.
    click(&mut harness, ElementId(2), Modifiers::NONE);
    command(&mut harness, Modifiers::COMMAND, Key::P);
    assert_eq!(
        harness.state().refusals.last(),
        Some(&SfcEditError::NotAStep(ElementId(2)))
    );
}

#[test]
fn deleting_a_step_takes_its_transition_with_it() {
    let chart = insert_step_transition_after(&SfcChart::new_body(), ElementId(2)).unwrap();
    let mut harness = harness(chart);
    click(&mut harness, ElementId(4), Modifiers::NONE);
    command(&mut harness, Modifiers::NONE, Key::Delete);
    let host = harness.state();
    assert_eq!(host.chart, SfcChart::new_body());
    assert_eq!(host.changes, 1);
    assert!(host.editor.selection().is_empty());
}

#[test]
fn a_condition_is_typed_with_completion_of_variables() {
    let mut harness = harness(SfcChart::new_body());
    click(&mut harness, ElementId(2), Modifiers::NONE);
    command(&mut harness, Modifiers::NONE, Key::F2);
    harness.event(Event::Key {
        key: Key::A,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers: Modifiers::COMMAND,
    });
    harness.run_steps(1);
    harness.event(Event::Text("level AND st".to_owned()));
    harness.run_steps(3);
    // Both candidates are offered; the arrows move to the second, Enter takes it.
    harness.get_by_label("start  BOOL");
    harness.get_by_label("stop  BOOL");
    command(&mut harness, Modifiers::NONE, Key::ArrowDown);
    command(&mut harness, Modifiers::NONE, Key::ArrowDown);
    command(&mut harness, Modifiers::NONE, Key::Enter);
    let host = harness.state();
    let SfcNode::Transition(transition) = &host.chart.sequence[1] else {
        panic!("no transition");
    };
    assert_eq!(transition.condition, "level AND stop");
}

#[test]
fn an_action_association_is_added_by_typing_it() {
    let mut harness = harness(SfcChart::new_body());
    click(&mut harness, ElementId(1), Modifiers::NONE);
    command(&mut harness, Modifiers::COMMAND, Key::Q);
    type_and_enter(&mut harness, "L Fill T#5s");
    let host = harness.state();
    let SfcNode::Step(step) = &host.chart.sequence[0] else {
        panic!("no step");
    };
    assert_eq!(step.actions.len(), 1);
    assert_eq!(step.actions[0].action, "Fill");
    assert_eq!(step.actions[0].duration.as_deref(), Some("T#5s"));
    assert!(
        host.editor
            .layout()
            .element(ElementId(1))
            .unwrap()
            .actions
            .is_some()
    );
}

#[test]
fn online_a_step_is_deactivated_and_a_transition_fired_in_tip_mode() {
    let mut harness = harness(SfcChart::new_body());
    let mut online = SfcOnline {
        tip_mode: true,
        ..SfcOnline::default()
    };
    online.steps.insert(
        ElementId(1),
        SfcStepOnline {
            active: true,
            elapsed: std::time::Duration::from_millis(1500),
            over_max_time: false,
        },
    );
    harness.state_mut().editor.set_online(Some(online));
    harness.state_mut().editor.set_read_only(true);
    harness.run_steps(2);
    click(&mut harness, ElementId(1), Modifiers::NONE);
    command(&mut harness, Modifiers::COMMAND, Key::Enter);
    click(&mut harness, ElementId(2), Modifiers::NONE);
    command(&mut harness, Modifiers::COMMAND, Key::Enter);
    // Read-only refuses edits while online.
    command(&mut harness, Modifiers::COMMAND, Key::T);
    let host = harness.state();
    assert_eq!(
        host.online,
        [
            SfcOnlineCommand::SetStepActive {
                step: "Init".into(),
                active: false
            },
            SfcOnlineCommand::FireTransition {
                transition: ElementId(2)
            }
        ]
    );
    assert_eq!(host.changes, 0);
}

#[test]
fn a_macro_step_is_opened_and_left_showing_its_path() {
    let chart =
        project_model::sfc_edit::insert_macro_step_after(&SfcChart::new_body(), ElementId(2))
            .unwrap();
    let mut harness = harness(chart);
    click(&mut harness, ElementId(4), Modifiers::NONE);
    command(&mut harness, Modifiers::NONE, Key::Enter);
    assert_eq!(harness.state().editor.macro_path(), [ElementId(4)]);
    harness.get_by_label("Macro1");
    // The body's step is shown and edited in place.
    assert!(
        harness
            .state()
            .editor
            .layout()
            .element(ElementId(5))
            .is_some()
    );
    command(&mut harness, Modifiers::COMMAND, Key::ArrowUp);
    assert!(harness.state().editor.macro_path().is_empty());
    assert_eq!(harness.state().editor.selection(), [ElementId(4)]);
}

#[test]
fn the_toolbox_inserts_at_the_selection_with_a_click() {
    let chart = insert_step_transition_after(&SfcChart::new_body(), ElementId(2)).unwrap();
    let mut harness = harness(chart);
    click(&mut harness, ElementId(4), Modifiers::NONE);
    harness.get_by_label("Parallel branch").click();
    harness.run_steps(3);
    harness.get_by_label("Add branch").click();
    harness.run_steps(3);
    let host = harness.state();
    assert_eq!(
        shape(&host.chart.sequence),
        [
            "Init",
            "T FALSE",
            "P[Step1 | Step2 | Step3]",
            "T FALSE",
            "-> Init"
        ]
    );
    assert_eq!(host.changes, 2);
}

#[test]
fn the_properties_panel_sets_a_steps_maximum_time() {
    let mut harness = harness(SfcChart::new_body());
    click(&mut harness, ElementId(1), Modifiers::NONE);
    harness
        .get_by_role_and_label(egui::accesskit::Role::TextInput, "Maximum time")
        .click();
    harness.run_steps(2);
    harness.event(Event::Text("T#5s".to_owned()));
    harness.run_steps(2);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    let host = harness.state();
    let SfcNode::Step(step) = &host.chart.sequence[0] else {
        panic!("no step");
    };
    assert_eq!(step.max_time.as_deref(), Some("T#5s"));
    assert_eq!(host.changes, 1);
}

#[test]
fn a_copied_pair_is_pasted_with_fresh_ids_and_names() {
    let chart = insert_step_transition_after(&SfcChart::new_body(), ElementId(2)).unwrap();
    let mut harness = harness(chart);
    click(&mut harness, ElementId(4), Modifiers::NONE);
    command(&mut harness, Modifiers::SHIFT, Key::ArrowDown);
    harness.event(Event::Copy);
    harness.run_steps(2);
    click(&mut harness, ElementId(5), Modifiers::NONE);
    harness.event(Event::Paste(String::new()));
    harness.run_steps(3);
    let host = harness.state();
    assert_eq!(
        shape(&host.chart.sequence),
        [
            "Init", "T FALSE", "Step1", "T FALSE", "Step2", "T FALSE", "-> Init"
        ]
    );
    assert_eq!(host.chart.sequence[4].id(), ElementId(6));
    assert!(host.refusals.is_empty());
}

#[test]
fn a_toolbox_item_dragged_onto_a_node_inserts_there() {
    let mut harness = harness(SfcChart::new_body());
    let from = harness.get_by_label("Step-transition").rect().center();
    let to = harness
        .state()
        .editor
        .element_screen_rect(ElementId(2))
        .unwrap()
        .center();
    let button = |pos, pressed| Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    };
    harness.hover_at(from);
    harness.run_steps(1);
    harness.event(button(from, true));
    harness.run_steps(1);
    for step in 1..=10 {
        harness.hover_at(from.lerp(to, step as f32 / 10.0));
        harness.run_steps(1);
    }
    harness.event(button(to, false));
    harness.run_steps(3);
    let host = harness.state();
    assert_eq!(
        shape(&host.chart.sequence),
        ["Init", "T FALSE", "Step1", "T FALSE", "-> Init"]
    );
    assert_eq!(host.editor.selection(), [ElementId(4)]);
}

#[test]
fn a_finding_and_an_exceeded_maximum_time_are_shown_at_their_elements() {
    let mut harness = harness(SfcChart::new_body());
    harness.state_mut().editor.set_diagnostics(vec![
        SfcDiagnostic {
            element: Some(ElementId(2)),
            severity: crate::Severity::Error,
            code: "E0104".into(),
            message: "unknown variable 'levle'".into(),
        },
        SfcDiagnostic {
            element: None,
            severity: crate::Severity::Warning,
            code: "W0001".into(),
            message: "the chart is never called".into(),
        },
    ]);
    let mut online = SfcOnline::default();
    online.steps.insert(
        ElementId(1),
        SfcStepOnline {
            active: true,
            elapsed: std::time::Duration::from_secs(12),
            over_max_time: true,
        },
    );
    harness.state_mut().editor.set_online(Some(online));
    harness.run_steps(2);
    let transition = harness
        .state()
        .editor
        .element_screen_rect(ElementId(2))
        .unwrap()
        .center();
    // The chart's own finding stands in the bar above it.
    harness.get_by_label("W0001: the chart is never called");
    harness.hover_at(transition);
    harness.run_steps(60);
    harness.get_by_label("E0104: unknown variable 'levle'");
    let step = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .unwrap()
        .center();
    harness.hover_at(step);
    harness.run_steps(60);
    harness.get_by_label("Maximum time exceeded");
}

#[test]
fn f9_asks_for_a_breakpoint_on_a_step_or_a_transition_and_the_marks_are_drawn() {
    let mut harness = harness(SfcChart::new_body());
    let place = |id: u32| crate::BodyPlace {
        network: 0,
        element: Some(ElementId(id)),
    };
    click(&mut harness, ElementId(1), Modifiers::NONE);
    command(&mut harness, Modifiers::NONE, Key::F9);
    click(&mut harness, ElementId(2), Modifiers::NONE);
    command(&mut harness, Modifiers::NONE, Key::F9);
    // A jump has no statement of its own: nothing is asked.
    click(&mut harness, ElementId(3), Modifiers::NONE);
    assert_eq!(harness.state().editor.breakpoint_place(), None);
    command(&mut harness, Modifiers::NONE, Key::F9);
    assert_eq!(harness.state().toggles, vec![place(1), place(2)]);
    assert_eq!(harness.state().changes, 0);

    let marks = crate::BodyDebugMarks {
        breakpoints: vec![crate::BodyBreakpointMark {
            place: place(2),
            look: crate::BreakpointLook::Enabled,
        }],
        halt: Some(place(1)),
        halt_is_caller: false,
        flow: vec![place(1)],
    };
    harness.state_mut().editor.set_debug_marks(marks.clone());
    harness.run_steps(2);
    assert_eq!(harness.state().editor.debug_marks(), &marks);
}
