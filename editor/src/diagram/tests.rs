//! Tests of the diagram editor driven through egui, as a user would: keys, text, clicks and
//! clipboard events. Each test keeps the body the way the app would, applies the reported
//! changes to it and gives it back to the editor every frame.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{Coil, ElementId, FlowNode, Network, NetworkOutput, Operand};

use super::*;
use crate::{CompletionItem, CompletionKind, Severity};

/// Services knowing a few variables and the blocks TON and ADD, as the app's would.
struct FakeServices;

impl DiagramServices for FakeServices {
    fn variables(&self, prefix: &str) -> Vec<CompletionItem> {
        ["start", "stop", "motor"]
            .into_iter()
            .filter(|name| name.starts_with(prefix))
            .map(|label| CompletionItem {
                label: label.to_owned(),
                kind: CompletionKind::Variable,
                detail: "BOOL".to_owned(),
            })
            .collect()
    }

    fn blocks(&self, prefix: &str) -> Vec<CompletionItem> {
        ["TON", "ADD"]
            .into_iter()
            .filter(|name| name.starts_with(prefix))
            .map(|label| CompletionItem {
                label: label.to_owned(),
                kind: CompletionKind::FunctionBlock,
                detail: String::new(),
            })
            .collect()
    }

    fn structure_members(&self, _type_name: &str) -> Option<Vec<String>> {
        None
    }

    fn signature(&self, type_name: &str) -> Option<BlockSignature> {
        match type_name {
            "TON" => Some(BlockSignature {
                inputs: vec!["IN".into(), "PT".into()],
                outputs: vec!["Q".into(), "ET".into()],
                function_block: true,
            }),
            _ => None,
        }
    }

    fn is_declared(&self, name: &str) -> bool {
        ["start", "stop", "motor"].contains(&name)
    }
}

/// What the app would keep: the editor, the model's body and what came out.
struct Host {
    editor: DiagramEditor,
    body: Vec<Network>,
    changes: usize,
    declared: Vec<InstanceDeclaration>,
    refusals: Vec<DiagramRefusal>,
    prepared: Vec<PreparedOperand>,
    toggles: Vec<crate::BodyPlace>,
}

fn harness(body: Vec<Network>, view: DiagramView) -> Harness<'static, Host> {
    let mut editor = DiagramEditor::new(&body, view);
    editor.request_focus();
    let host = Host {
        editor,
        body,
        changes: 0,
        declared: Vec::new(),
        refusals: Vec::new(),
        prepared: Vec::new(),
        toggles: Vec::new(),
    };
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        .build_ui_state(
            |ui, host: &mut Host| {
                host.editor.set_networks(&host.body);
                let output = host.editor.show(ui, "Body of Main", &FakeServices);
                if let Some(change) = output.change {
                    change.apply(&mut host.body);
                    host.changes += 1;
                }
                host.declared.extend(output.declare_instance);
                host.refusals.extend(output.refusal);
                host.prepared.extend(output.prepared);
                host.toggles.extend(output.toggle_breakpoint);
            },
            host,
        );
    harness.run_steps(2);
    harness
}

fn command(harness: &mut Harness<'static, Host>, key: Key) {
    harness.key_press_modifiers(Modifiers::COMMAND, key);
    harness.run_steps(3);
}

fn type_and_enter(harness: &mut Harness<'static, Host>, text: &str) {
    harness.event(Event::Text(text.to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
}

/// A primary click at `pos`, after hovering there as a mouse does.
fn click(harness: &mut Harness<'static, Host>, pos: egui::Pos2) {
    harness.hover_at(pos);
    harness.run_steps(1);
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.run_steps(2);
}

fn contact(id: u32, text: &str) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        ..Operand::default()
    })
}

/// One rung: `start` driving coil `motor`.
fn one_rung() -> Vec<Network> {
    vec![Network {
        rung: vec![contact(1, "start")],
        outputs: vec![NetworkOutput::Coil(Coil {
            id: ElementId(2),
            variable: "motor".into(),
            ..Coil::default()
        })],
        ..Network::default()
    }]
}

#[test]
fn a_rung_is_built_with_the_keyboard_only() {
    let mut harness = harness(Vec::new(), DiagramView::Ladder);
    command(&mut harness, Key::K);
    type_and_enter(&mut harness, "start");
    command(&mut harness, Key::N);
    command(&mut harness, Key::A);
    type_and_enter(&mut harness, "motor");
    let host = harness.state();
    assert_eq!(host.body.len(), 1);
    let network = &host.body[0];
    assert!(matches!(
        network.rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "start" && operand.negated
    ));
    assert!(matches!(
        network.outputs.as_slice(),
        [NetworkOutput::Coil(coil)] if coil.variable == "motor"
    ));
    // One change per gesture: contact, operand, negation, coil, variable.
    assert_eq!(host.changes, 5);
    assert_eq!(host.editor.networks(), host.body.as_slice());
}

#[test]
fn a_parallel_contact_goes_below_the_selected_one() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    command(&mut harness, Key::R);
    type_and_enter(&mut harness, "stop");
    let host = harness.state();
    let [FlowNode::Parallel(group)] = host.body[0].rung.as_slice() else {
        panic!("no parallel group: {:?}", host.body[0].rung);
    };
    let texts: Vec<_> = group
        .branches
        .iter()
        .map(|branch| match branch.rung.as_slice() {
            [FlowNode::Operand(operand)] => operand.text.clone(),
            other => format!("{other:?}"),
        })
        .collect();
    assert_eq!(texts, ["start", "stop"]);
}

#[test]
fn a_copied_network_is_pasted_below_with_fresh_ids() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness.state_mut().editor.select(Some(0), Vec::new());
    harness.run_steps(2);
    harness.event(Event::Copy);
    harness.run_steps(2);
    harness.event(Event::Paste(String::new()));
    harness.run_steps(3);
    let host = harness.state();
    assert_eq!(host.body.len(), 2);
    let mut ids = Vec::new();
    for network in &host.body {
        network.for_each_element(&mut |element| ids.push(element.id().0));
    }
    assert_eq!(ids, [1, 2, 3, 4]);
    assert_eq!(host.editor.selection().network, Some(1));
}

#[test]
fn a_diagnostic_is_shown_at_its_element() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .set_diagnostics(vec![ElementDiagnostic {
            network: 0,
            element: Some(ElementId(1)),
            pin: None,
            severity: Severity::Error,
            code: "E0201".into(),
            message: "unknown variable `start`".into(),
        }]);
    harness.run_steps(2);
    let rect = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .expect("the contact is drawn");
    harness.hover_at(rect.center());
    harness.run_steps(3);
    assert!(
        harness
            .query_by_label_contains("E0201: unknown variable `start`")
            .is_some()
    );
}

#[test]
fn an_ld_rung_is_shown_as_fbd_with_the_view_toggle() {
    let mut body = one_rung();
    body[0].rung.push(contact(3, "stop"));
    let mut harness = harness(body, DiagramView::Ladder);
    harness.get_by_label("FBD").click();
    harness.run_steps(2);
    let host = harness.state();
    assert_eq!(host.editor.view(), DiagramView::FunctionBlock);
    let layout = host.editor.layout(0).expect("the network is laid out");
    assert!(layout.elements.iter().any(|element| matches!(
        &element.shape,
        Shape::Box { type_name, .. } if type_name == "AND"
    )));
    assert!(matches!(
        layout.element(ElementId(2)).map(|element| &element.shape),
        Some(Shape::Assignment { variable, .. }) if variable == "motor"
    ));
    assert_eq!(host.changes, 0);
}

#[test]
fn a_function_block_box_asks_for_its_instance_and_its_declaration() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    command(&mut harness, Key::B);
    type_and_enter(&mut harness, "TON");
    type_and_enter(&mut harness, "delay");
    let host = harness.state();
    let Some(FlowNode::Block(block)) = host.body[0].rung.get(1) else {
        panic!("no box after the contact: {:?}", host.body[0].rung);
    };
    assert_eq!(
        (block.type_name.as_str(), block.instance.as_str()),
        ("TON", "delay")
    );
    assert_eq!(block.inputs.len(), 2);
    assert_eq!(
        host.declared,
        [InstanceDeclaration {
            name: "delay".into(),
            type_name: "TON".into()
        }]
    );
}

#[test]
fn an_unknown_block_is_refused_and_nothing_changes() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    command(&mut harness, Key::B);
    type_and_enter(&mut harness, "NOPE");
    let host = harness.state();
    assert_eq!(host.changes, 0);
    assert_eq!(host.refusals, [DiagramRefusal::UnknownBlock("NOPE".into())]);
}

#[test]
fn a_click_on_a_box_pin_then_typing_sets_the_pin_operand() {
    let mut body = one_rung();
    body[0].rung.push(project_model::new_box(
        "TON",
        "delay",
        &["IN", "PT"],
        &["Q", "ET"],
    ));
    if let FlowNode::Block(block) = &mut body[0].rung[1] {
        block.id = ElementId(3);
    }
    let mut harness = harness(body, DiagramView::Ladder);
    let rect = harness
        .state()
        .editor
        .element_screen_rect(ElementId(3))
        .expect("the box is drawn");
    // The PT pin is on the box's second row, at its left.
    let pt = egui::pos2(
        rect.left() + rect.width() * 0.25,
        rect.top() + rect.height() * 0.75,
    );
    click(&mut harness, pt);
    type_and_enter(&mut harness, "T#5S");
    let host = harness.state();
    let FlowNode::Block(block) = &host.body[0].rung[1] else {
        panic!("the box went away");
    };
    assert!(matches!(
        block.inputs[1].source.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "T#5S" && operand.id == ElementId(4)
    ));
    assert!(block.inputs[0].source.is_empty());
}

#[test]
fn a_completion_candidate_clicked_becomes_the_operand() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.event(Event::Text("mo".to_owned()));
    harness.run_steps(3);
    harness.get_by_label("motor  BOOL").click();
    harness.run_steps(3);
    let host = harness.state();
    assert!(matches!(
        host.body[0].rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "motor"
    ));
    assert_eq!(host.changes, 1);
}

#[test]
fn what_was_typed_is_kept_when_the_user_clicks_elsewhere() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(2)]);
    harness.run_steps(2);
    harness.event(Event::Text("lamp".to_owned()));
    harness.run_steps(3);
    let far = egui::pos2(900.0, 650.0);
    harness.hover_at(far);
    harness.event(Event::PointerButton {
        pos: far,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    harness.event(Event::PointerButton {
        pos: far,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run_steps(3);
    let host = harness.state();
    assert!(matches!(
        host.body[0].outputs.as_slice(),
        [NetworkOutput::Coil(coil)] if coil.variable == "lamp"
    ));
}

/// Presses the primary button at `from`, moves to `to` in steps and releases it there.
fn drag(harness: &mut Harness<'static, Host>, from: egui::Pos2, to: egui::Pos2) {
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
}

#[test]
fn a_contact_dragged_from_the_toolbox_is_inserted_at_the_plus_mark() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    let from = harness.get_by_label("Contact").rect().center();
    let contact = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .expect("the contact is drawn");
    // The "+" after the contact, at its right edge on the rung.
    drag(&mut harness, from, contact.right_center());
    let host = harness.state();
    assert_eq!(host.changes, 1);
    let texts: Vec<_> = host.body[0]
        .rung
        .iter()
        .map(|node| match node {
            FlowNode::Operand(operand) => operand.text.clone(),
            other => format!("{other:?}"),
        })
        .collect();
    assert_eq!(texts, ["start", ""]);
}

#[test]
fn ctrl_wheel_zooms_and_keeps_the_element_under_the_mouse() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    let before = harness
        .state()
        .editor
        .element_screen_rect(ElementId(2))
        .expect("the coil is drawn");
    harness.hover_at(before.center());
    harness.run_steps(1);
    harness.event(Event::Zoom(1.5));
    harness.run_steps(4);
    let editor = &harness.state().editor;
    assert!((editor.zoom() - 1.5).abs() < 1e-3, "zoom {}", editor.zoom());
    let after = editor
        .element_screen_rect(ElementId(2))
        .expect("the coil is drawn");
    assert!(
        after.center().distance(before.center()) < 2.0,
        "the coil moved from {before:?} to {after:?}"
    );
    assert!((after.width() - before.width() * 1.5).abs() < 0.5);
}

#[test]
fn arrows_move_along_the_rung_and_down_into_the_next_network() {
    let mut body = one_rung();
    body[0].rung.push(contact(3, "stop"));
    body.push(Network {
        rung: vec![contact(4, "manual")],
        ..Network::default()
    });
    let mut harness = harness(body, DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    let mut visited = Vec::new();
    for key in [
        Key::ArrowRight,
        Key::ArrowRight,
        Key::ArrowLeft,
        Key::ArrowDown,
    ] {
        harness.key_press(key);
        harness.run_steps(2);
        let selection = harness.state().editor.selection().clone();
        visited.push((selection.network, selection.elements));
    }
    assert_eq!(
        visited,
        [
            (Some(0), vec![ElementId(3)]),
            (Some(0), vec![ElementId(2)]),
            (Some(0), vec![ElementId(3)]),
            (Some(1), vec![ElementId(4)]),
        ]
    );
}

#[test]
fn clicking_an_operand_online_prepares_a_value_for_the_app() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    let mut online = DiagramOnline::default();
    online.power.insert(ElementId(1), true);
    harness.state_mut().editor.set_online(Some(online));
    harness.run_steps(2);
    let contact = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .expect("the contact is drawn");
    harness.hover_at(contact.center());
    harness.run_steps(1);
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos: contact.center(),
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.run_steps(3);
    type_and_enter(&mut harness, "FALSE");
    let host = harness.state();
    assert_eq!(
        host.prepared,
        [PreparedOperand {
            element: ElementId(1),
            operand: "start".into(),
            value: "FALSE".into(),
        }]
    );
    assert_eq!(host.changes, 0);
}

#[test]
fn text_pasted_from_elsewhere_becomes_the_selected_operand() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    // Something was copied in the diagram before; the system clipboard now holds a name.
    harness.state_mut().editor.select(Some(0), Vec::new());
    harness.run_steps(2);
    harness.event(Event::Copy);
    harness.run_steps(2);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.event(Event::Paste("stop".to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    let host = harness.state();
    assert_eq!(host.body.len(), 1);
    assert!(matches!(
        host.body[0].rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "stop"
    ));
}

#[test]
fn the_input_assistant_lists_variables_and_blocks_and_fills_the_operand() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.key_press(Key::F2);
    harness.run_steps(3);
    assert!(harness.query_by_label("TON  ").is_some());
    harness.get_by_label("stop  BOOL").click();
    harness.run_steps(3);
    let host = harness.state();
    assert!(matches!(
        host.body[0].rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "stop"
    ));
}

#[test]
fn a_toolbox_item_clicked_is_inserted_at_the_selection() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.get_by_label("Negated contact").click();
    harness.run_steps(3);
    let host = harness.state();
    assert_eq!(host.changes, 1);
    // Like Ctrl+K, the contact goes left of the selected one.
    let negated: Vec<_> = host.body[0]
        .rung
        .iter()
        .map(|node| match node {
            FlowNode::Operand(operand) => (operand.text.clone(), operand.negated),
            other => (format!("{other:?}"), false),
        })
        .collect();
    assert_eq!(
        negated,
        [(String::new(), true), ("start".to_owned(), false)]
    );
}

#[test]
fn a_common_block_clicked_in_the_toolbox_is_inserted_with_its_signature_pins() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.get_by_label("TON").click();
    harness.run_steps(3);
    // A function block asks for its instance at once.
    type_and_enter(&mut harness, "delay");
    let host = harness.state();
    let Some(FlowNode::Block(block)) = host.body[0].rung.get(1) else {
        panic!("no box after the contact: {:?}", host.body[0].rung);
    };
    let pins: Vec<_> = block
        .inputs
        .iter()
        .map(|input| input.pin.as_str())
        .collect();
    assert_eq!((block.type_name.as_str(), pins), ("TON", vec!["IN", "PT"]));
    assert_eq!(block.instance, "delay");
    // A block the project does not know is refused, not inserted without pins.
    harness.get_by_label("SEL").click();
    harness.run_steps(3);
    assert_eq!(
        harness.state().refusals,
        [DiagramRefusal::UnknownBlock("SEL".into())]
    );
}

#[test]
fn a_diagnostic_on_a_pin_marks_the_pin_and_names_it_on_hover() {
    let mut body = one_rung();
    body[0].rung.push(project_model::new_box(
        "TON",
        "delay",
        &["IN", "PT"],
        &["Q", "ET"],
    ));
    let id = ElementId(3);
    if let FlowNode::Block(block) = &mut body[0].rung[1] {
        block.id = id;
    }
    let mut harness = harness(body, DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .set_diagnostics(vec![ElementDiagnostic {
            network: 0,
            element: Some(id),
            pin: Some("PT".into()),
            severity: Severity::Warning,
            code: "E0301".into(),
            message: "PT expects TIME".into(),
        }]);
    harness.run_steps(2);
    let editor = &harness.state().editor;
    assert_eq!(
        editor.pin_marks.get(&(id, "PT".to_owned())),
        Some(&Severity::Warning)
    );
    assert_eq!(editor.pin_marks.len(), 1);
    let rect = editor.element_screen_rect(id).expect("the box is drawn");
    harness.hover_at(rect.center());
    harness.run_steps(3);
    assert!(
        harness
            .query_by_label_contains("E0301 (PT): PT expects TIME")
            .is_some()
    );
}

#[test]
fn a_shortened_operand_shows_in_full_on_hover() {
    let long = "the_conveyor_infeed_photo_eye_of_line_two";
    let mut harness = harness(
        vec![Network {
            rung: vec![contact(1, long)],
            ..Network::default()
        }],
        DiagramView::Ladder,
    );
    let rect = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .expect("the contact is drawn");
    harness.hover_at(rect.center());
    harness.run_steps(3);
    assert!(harness.query_by_label_contains(long).is_some());
}

#[test]
fn enter_takes_the_highlighted_completion_and_the_arrows_move_it() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    type_and_enter(&mut harness, "mo");
    assert!(matches!(
        harness.state().body[0].rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "motor"
    ));
    // "st" offers start and stop; the down arrow moves from the first to the second.
    harness.run_steps(2);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.event(Event::Text("st".to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::ArrowDown);
    harness.run_steps(2);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    assert!(matches!(
        harness.state().body[0].rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "stop"
    ));
}

#[test]
fn a_text_without_candidates_is_kept_as_typed_on_enter() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    type_and_enter(&mut harness, "lamp");
    assert!(matches!(
        harness.state().body[0].rung.as_slice(),
        [FlowNode::Operand(operand)] if operand.text == "lamp"
    ));
}

#[test]
fn a_member_completion_replaces_only_what_follows_the_dot() {
    assert_eq!(field::accepted_text("tonA.q", "Q"), "tonA.Q");
    assert_eq!(field::accepted_text("GVL.st.r", "rSpeed"), "GVL.st.rSpeed");
    assert_eq!(field::accepted_text("mo", "motor"), "motor");
}

#[test]
fn a_completion_row_names_the_candidate_once() {
    assert_eq!(
        field::detail_without_label("tWarningElapsed", "tWarningElapsed : TIME"),
        "TIME"
    );
    assert_eq!(
        field::detail_without_label("LIMIT", "FUNCTION LIMIT"),
        "FUNCTION"
    );
    assert_eq!(field::detail_without_label("motor", "BOOL"), "BOOL");
}

#[test]
fn a_diagnostic_tooltip_is_shown_at_its_element() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .set_diagnostics(vec![ElementDiagnostic {
            network: 0,
            element: Some(ElementId(1)),
            pin: None,
            severity: Severity::Error,
            code: "E0101".into(),
            message: "unknown name".into(),
        }]);
    harness.run_steps(2);
    let rect = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .expect("the contact is drawn");
    harness.hover_at(rect.center());
    harness.run_steps(3);
    let tip = harness
        .query_by_label_contains("E0101: unknown name")
        .expect("the tooltip is shown");
    let tip = tip.rect();
    // Next to the element, not at the bottom of the 700 points high canvas.
    assert!(
        (tip.min.y - rect.max.y).abs() < 40.0 || (rect.min.y - tip.max.y).abs() < 40.0,
        "tooltip at {tip:?}, element at {rect:?}"
    );
}

#[test]
fn the_fbd_toolbox_offers_inputs_and_assignments_mapped_to_the_same_edits() {
    let mut harness = harness(one_rung(), DiagramView::FunctionBlock);
    assert!(harness.query_by_label("Contact").is_none());
    assert!(harness.query_by_label("Coil").is_none());
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.get_by_label("Set assignment").click();
    harness.run_steps(3);
    assert!(matches!(
        harness.state().body[0].outputs.as_slice(),
        [NetworkOutput::Coil(_), NetworkOutput::Coil(set)] if set.kind == project_model::CoilKind::Set
    ));
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(1)]);
    harness.run_steps(2);
    harness.get_by_label("Negation").click();
    harness.run_steps(3);
    harness.get_by_label("Input").click();
    harness.run_steps(3);
    let inputs: Vec<_> = harness.state().body[0]
        .rung
        .iter()
        .map(|node| match node {
            FlowNode::Operand(operand) => (operand.text.clone(), operand.negated),
            other => (format!("{other:?}"), false),
        })
        .collect();
    assert_eq!(inputs, [(String::new(), false), ("start".to_owned(), true)]);
}

#[test]
fn tab_takes_the_highlighted_completion_too() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(2)]);
    harness.run_steps(2);
    harness.event(Event::Text("sto".to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::Tab);
    harness.run_steps(3);
    assert!(matches!(
        harness.state().body[0].outputs.as_slice(),
        [NetworkOutput::Coil(coil)] if coil.variable == "stop"
    ));
}

#[test]
fn a_narrow_body_at_100_percent_needs_no_horizontal_scrolling() {
    let harness = harness(one_rung(), DiagramView::FunctionBlock);
    let canvas = harness.get_by_label("Body of Main").rect();
    // The harness is 1000 points wide; the canvas fits in it beside the toolbox.
    assert!(
        canvas.right() <= 1000.0,
        "the canvas reaches {}",
        canvas.right()
    );
}

#[test]
fn ctrl_shift_b_gives_the_selected_box_en_and_eno_and_takes_them_away() {
    let mut body = one_rung();
    body[0].rung.push(project_model::new_box(
        "TON",
        "delay",
        &["IN", "PT"],
        &["Q", "ET"],
    ));
    if let FlowNode::Block(block) = &mut body[0].rung[1] {
        block.id = ElementId(3);
    }
    let mut harness = harness(body, DiagramView::Ladder);
    let rect = harness
        .state()
        .editor
        .element_screen_rect(ElementId(3))
        .expect("the box is drawn");
    // The box's title, away from its pins.
    let title = egui::pos2(rect.center().x, rect.top() + 6.0);
    click(&mut harness, title);
    let pins = |host: &Host| match &host.body[0].rung[1] {
        FlowNode::Block(block) => block
            .inputs
            .iter()
            .map(|input| input.pin.clone())
            .collect::<Vec<_>>(),
        _ => Vec::new(),
    };
    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::B);
    harness.run_steps(3);
    assert_eq!(pins(harness.state()), ["EN", "IN", "PT"]);
    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::B);
    harness.run_steps(3);
    assert_eq!(pins(harness.state()), ["IN", "PT"]);
    assert_eq!(harness.state().changes, 2);
}

#[test]
fn f9_and_the_context_menu_ask_for_a_breakpoint_on_the_selected_element_or_network() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    harness
        .state_mut()
        .editor
        .select(Some(0), vec![ElementId(2)]);
    harness.run_steps(2);
    harness.key_press(Key::F9);
    harness.run_steps(2);
    // Shift+F9 is not the toggle.
    harness.key_press_modifiers(Modifiers::SHIFT, Key::F9);
    harness.run_steps(2);
    harness.state_mut().editor.select(Some(0), Vec::new());
    harness.run_steps(2);
    harness.key_press(Key::F9);
    harness.run_steps(2);
    let coil = crate::BodyPlace {
        network: 0,
        element: Some(ElementId(2)),
    };
    let network = crate::BodyPlace {
        network: 0,
        element: None,
    };
    assert_eq!(harness.state().toggles, vec![coil, network]);
    // A right-click on the contact selects it and offers the toggle.
    let contact = harness
        .state()
        .editor
        .element_screen_rect(ElementId(1))
        .unwrap();
    harness.hover_at(contact.center());
    harness.run_steps(1);
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos: contact.center(),
            button: egui::PointerButton::Secondary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.run_steps(3);
    harness.get_by_label("Toggle breakpoint").click();
    harness.run_steps(3);
    assert_eq!(
        harness.state().toggles.last(),
        Some(&crate::BodyPlace {
            network: 0,
            element: Some(ElementId(1)),
        })
    );
    assert!(
        harness.state().body == one_rung(),
        "the toggle changes nothing in the body"
    );
}

#[test]
fn debug_marks_are_kept_until_replaced_and_tell_what_ran() {
    let mut harness = harness(one_rung(), DiagramView::Ladder);
    let marks = crate::BodyDebugMarks {
        breakpoints: vec![crate::BodyBreakpointMark {
            place: crate::BodyPlace {
                network: 0,
                element: Some(ElementId(2)),
            },
            look: crate::BreakpointLook::Conditional,
        }],
        halt: Some(crate::BodyPlace {
            network: 0,
            element: Some(ElementId(2)),
        }),
        halt_is_caller: false,
        flow: vec![crate::BodyPlace {
            network: 0,
            element: Some(ElementId(1)),
        }],
    };
    harness.state_mut().editor.set_debug_marks(marks.clone());
    harness.run_steps(2);
    let editor = &harness.state().editor;
    assert_eq!(editor.debug_marks(), &marks);
    assert!(editor.debug_marks().network_flowed(0) && !editor.debug_marks().network_flowed(1));
    assert!(editor.debug_marks().element_flowed(ElementId(1)));
    assert!(!editor.debug_marks().element_flowed(ElementId(2)));
    harness
        .state_mut()
        .editor
        .set_debug_marks(crate::BodyDebugMarks::default());
    harness.run_steps(1);
    assert!(harness.state().editor.debug_marks().is_empty());
}
