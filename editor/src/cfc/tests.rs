//! The CFC editor driven through egui_kittest as a user would: toolbox, clicks, typing,
//! drags, keys; what the app receives is the emitted chart.

use egui::{Event, Key, Modifiers, Pos2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use project_model::{CfcChart, CfcElementKind, ElementId, PinRef};

use super::canvas::Hit;
use super::editor::FrameResult;
use super::*;
use crate::diagram::{
    BlockSignature, DiagramOnline, DiagramServices, InstanceDeclaration, OnlineValue,
    PreparedOperand,
};
use crate::{CompletionItem, CompletionKind};

/// Services knowing the variables a, b and y and the blocks ADD and TON.
struct FakeServices;

impl DiagramServices for FakeServices {
    fn variables(&self, prefix: &str) -> Vec<CompletionItem> {
        ["a", "b", "y"]
            .into_iter()
            .filter(|name| name.starts_with(prefix))
            .map(|label| CompletionItem {
                label: label.to_owned(),
                kind: CompletionKind::Variable,
                detail: "INT".to_owned(),
            })
            .collect()
    }

    fn blocks(&self, prefix: &str) -> Vec<CompletionItem> {
        ["ADD", "TON"]
            .into_iter()
            .filter(|name| name.starts_with(prefix))
            .map(|label| CompletionItem {
                label: label.to_owned(),
                kind: CompletionKind::FunctionBlock,
                detail: String::new(),
            })
            .collect()
    }

    fn signature(&self, type_name: &str) -> Option<BlockSignature> {
        let names = |list: &[&str]| list.iter().map(|name| (*name).to_owned()).collect();
        match type_name {
            "ADD" => Some(BlockSignature {
                inputs: names(&["IN1", "IN2"]),
                outputs: names(&["OUT"]),
                function_block: false,
            }),
            "TON" => Some(BlockSignature {
                inputs: names(&["IN", "PT"]),
                outputs: names(&["Q", "ET"]),
                function_block: true,
            }),
            _ => None,
        }
    }

    fn structure_members(&self, type_name: &str) -> Option<Vec<String>> {
        (type_name == "ST_Point").then(|| vec!["x".to_owned(), "y".to_owned()])
    }

    fn is_declared(&self, name: &str) -> bool {
        ["a", "b", "y"].contains(&name)
    }
}

/// What the app would keep: the editor, the model's chart and what came out.
struct Host {
    editor: CfcEditor,
    chart: CfcChart,
    changes: usize,
    declared: Vec<InstanceDeclaration>,
    refusals: Vec<CfcRefusal>,
    prepared: Vec<PreparedOperand>,
    toggles: Vec<crate::BodyPlace>,
}

fn harness(chart: CfcChart) -> Harness<'static, Host> {
    let mut editor = CfcEditor::new(&chart);
    editor.request_focus();
    let host = Host {
        editor,
        chart,
        changes: 0,
        declared: Vec::new(),
        refusals: Vec::new(),
        toggles: Vec::new(),
        prepared: Vec::new(),
    };
    let mut harness = Harness::builder()
        .with_size(egui::vec2(1000.0, 700.0))
        // Frames close enough together for two clicks to make a double click.
        .with_step_dt(0.05)
        .build_ui_state(
            |ui, host: &mut Host| {
                host.editor.set_chart(&host.chart);
                let output = host.editor.show(ui, "Body of Loop", &FakeServices);
                if let Some(change) = output.change {
                    host.chart = change.chart;
                    host.changes += 1;
                }
                host.declared.extend(output.declare_instance);
                host.refusals.extend(output.refusal);
                host.toggles.extend(output.toggle_breakpoint);
                host.prepared.extend(output.prepared);
            },
            host,
        );
    harness.run_steps(2);
    harness
}

/// The screen point of grid position (`x`, `y`).
fn screen(harness: &Harness<'static, Host>, x: f32, y: f32) -> Pos2 {
    let editor = &harness.state().editor;
    editor.screen(editor.last_origin, x, y)
}

/// The screen point of a pin.
fn pin_at(harness: &Harness<'static, Host>, element: u32, pin: &str, output: bool) -> Pos2 {
    let shape = &harness.state().editor.shapes[&ElementId(element)];
    let point = if output {
        shape.output(pin)
    } else {
        shape.input(pin)
    }
    .expect("the pin exists");
    screen(harness, point.x as f32, point.y as f32)
}

fn press(harness: &mut Harness<'static, Host>, pos: Pos2, pressed: bool) {
    harness.event(Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    });
}

/// A primary click at `pos`, after hovering there as a mouse does.
fn click(harness: &mut Harness<'static, Host>, pos: Pos2) {
    harness.hover_at(pos);
    harness.run_steps(1);
    press(harness, pos, true);
    press(harness, pos, false);
    harness.run_steps(2);
}

/// Two primary clicks at `pos`.
fn double_click(harness: &mut Harness<'static, Host>, pos: Pos2) {
    harness.hover_at(pos);
    harness.run_steps(1);
    for _ in 0..2 {
        press(harness, pos, true);
        press(harness, pos, false);
    }
    harness.run_steps(2);
}

/// A primary drag from `from` to `to` in a few moves.
fn drag(harness: &mut Harness<'static, Host>, from: Pos2, to: Pos2) {
    harness.hover_at(from);
    harness.run_steps(1);
    press(harness, from, true);
    harness.run_steps(1);
    for step in 1..=5 {
        let t = step as f32 / 5.0;
        harness.hover_at(from + (to - from) * t);
        harness.run_steps(1);
    }
    press(harness, to, false);
    harness.run_steps(2);
}

fn type_and_enter(harness: &mut Harness<'static, Host>, text: &str) {
    harness.event(Event::Text(text.to_owned()));
    harness.run_steps(3);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
}

/// Places the toolbox element `tool` at grid (`x`, `y`) and types `text` into its field.
fn place(harness: &mut Harness<'static, Host>, tool: &str, x: f32, y: f32, text: &str) {
    harness.get_by_label(tool).click();
    harness.run_steps(2);
    let at = screen(harness, x + 0.5, y + 0.5);
    click(harness, at);
    type_and_enter(harness, text);
}

fn orders(chart: &CfcChart) -> Vec<(u32, Option<u32>)> {
    let mut orders: Vec<_> = chart.elements.iter().map(|e| (e.id.0, e.order)).collect();
    orders.sort();
    orders
}

fn pin(element: u32, name: &str) -> PinRef {
    PinRef::new(ElementId(element), name)
}

/// Input `a` (0) and ADD (1) and output `y` (2), placed and wired through the user interface.
fn drawn_chart() -> Harness<'static, Host> {
    let mut harness = harness(CfcChart::default());
    place(&mut harness, "Input", 2.0, 4.0, "a");
    place(&mut harness, "Box", 14.0, 3.0, "ADD");
    place(&mut harness, "Output", 34.0, 4.0, "y");
    let from = pin_at(&harness, 0, "", true);
    let to = pin_at(&harness, 1, "IN1", false);
    drag(&mut harness, from, to);
    let from = pin_at(&harness, 1, "OUT", true);
    let to = pin_at(&harness, 2, "", false);
    drag(&mut harness, from, to);
    harness
}

#[test]
fn an_input_a_box_and_an_output_are_placed_typed_and_wired() {
    let harness = drawn_chart();
    let chart = &harness.state().chart;
    let kinds: Vec<&CfcElementKind> = chart.elements.iter().map(|e| &e.kind).collect();
    assert!(matches!(kinds[0], CfcElementKind::Input { expression } if expression == "a"));
    assert!(
        matches!(kinds[1], CfcElementKind::Box(block) if block.type_name == "ADD" && block.inputs.len() == 2)
    );
    assert!(matches!(kinds[2], CfcElementKind::Output { expression, .. } if expression == "y"));
    assert_eq!((chart.elements[0].x, chart.elements[0].y), (2, 4));
    let wires: Vec<(PinRef, PinRef)> = chart
        .wires
        .iter()
        .map(|wire| (wire.from.clone(), wire.to.clone()))
        .collect();
    assert_eq!(
        wires,
        vec![(pin(0, ""), pin(1, "IN1")), (pin(1, "OUT"), pin(2, ""))]
    );
    assert_eq!(orders(chart), vec![(0, None), (1, Some(0)), (2, Some(1))]);
    assert!(harness.state().refusals.is_empty());
}

#[test]
fn the_execution_order_is_renumbered_by_key_and_by_command() {
    let mut harness = drawn_chart();
    let output = screen(&harness, 35.0, 5.0);
    click(&mut harness, output);
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Home);
    harness.run_steps(3);
    assert_eq!(
        orders(&harness.state().chart),
        vec![(0, None), (1, Some(1)), (2, Some(0))],
        "Send to Front made the output run first"
    );
    // The output now reads the box's value of the previous cycle: a feedback.
    assert!(
        harness
            .state()
            .editor
            .is_feedback(ElementId(1), ElementId(2))
    );
    harness
        .state_mut()
        .editor
        .run_command(CfcOrderCommand::OrderByDataFlow);
    harness.run_steps(3);
    assert_eq!(
        orders(&harness.state().chart),
        vec![(0, None), (1, Some(0)), (2, Some(1))]
    );
    assert!(
        !harness
            .state()
            .editor
            .is_feedback(ElementId(1), ElementId(2))
    );
}

#[test]
fn deleting_a_box_removes_its_wires_and_closes_the_order() {
    let mut harness = drawn_chart();
    let changes = harness.state().changes;
    let head = screen(&harness, 16.0, 4.0);
    click(&mut harness, head);
    assert_eq!(
        harness.state().editor.selection().elements,
        vec![ElementId(1)]
    );
    harness.key_press(Key::Delete);
    harness.run_steps(3);
    let chart = &harness.state().chart;
    assert_eq!(
        harness.state().changes,
        changes + 1,
        "one gesture, one change"
    );
    assert!(chart.wires.is_empty());
    assert_eq!(orders(chart), vec![(0, None), (2, Some(0))]);
}

#[test]
fn dragging_a_box_moves_it_on_the_grid_and_reroutes_its_wires() {
    let mut harness = drawn_chart();
    let before = harness.state().editor.routes[&pin(1, "IN1")].clone();
    let from = screen(&harness, 16.0, 4.0);
    let to = screen(&harness, 16.0, 14.0);
    drag(&mut harness, from, to);
    let chart = &harness.state().chart;
    let moved = chart
        .elements
        .iter()
        .find(|e| e.id == ElementId(1))
        .unwrap();
    assert_eq!((moved.x, moved.y), (14, 13));
    let after = &harness.state().editor.routes[&pin(1, "IN1")];
    assert_ne!(&before, after);
    assert_eq!(after.last().map(|p| p.y), Some(16));
}

#[test]
fn a_composer_takes_its_structure_members_as_pins_and_an_unknown_structure_is_refused() {
    let mut harness = harness(CfcChart::default());
    place(&mut harness, "Composer", 4.0, 4.0, "ST_Point");
    place(&mut harness, "Selector", 20.0, 4.0, "ST_Nope");
    let chart = &harness.state().chart;
    let CfcElementKind::Composer { type_name, inputs } = &chart.elements[0].kind else {
        panic!("a composer: {:?}", chart.elements[0].kind);
    };
    let members: Vec<&str> = inputs.iter().map(|pin| pin.name.as_str()).collect();
    assert_eq!((type_name.as_str(), members), ("ST_Point", vec!["x", "y"]));
    assert_eq!(
        harness.state().refusals,
        vec![CfcRefusal::UnknownStructure("ST_Nope".to_owned())]
    );
}

#[test]
fn an_unknown_box_type_is_refused_and_a_function_block_asks_for_its_instance() {
    let mut harness = harness(CfcChart::default());
    place(&mut harness, "Box", 4.0, 4.0, "NOPE");
    assert_eq!(
        harness.state().refusals,
        vec![CfcRefusal::UnknownBlock("NOPE".to_owned())]
    );
    // The box is still there, without a type; a double click on its head types one.
    let head = screen(&harness, 5.0, 5.0);
    double_click(&mut harness, head);
    assert!(
        harness.state().editor.entry.is_some(),
        "the type field is open"
    );
    type_and_enter(&mut harness, "TON");
    type_and_enter(&mut harness, "delay");
    assert_eq!(
        harness.state().declared,
        vec![InstanceDeclaration {
            name: "delay".to_owned(),
            type_name: "TON".to_owned()
        }]
    );
    let CfcElementKind::Box(block) = &harness.state().chart.elements[0].kind else {
        panic!("a box");
    };
    assert_eq!(
        (block.type_name.as_str(), block.instance.as_str()),
        ("TON", "delay")
    );
    assert_eq!(block.outputs.len(), 2);
}

#[test]
fn a_variable_dropped_on_a_box_input_connects_an_input_with_it() {
    let harness = drawn_chart();
    let mut editor = CfcEditor::new(&harness.state().chart);
    let mut frame = FrameResult::default();
    editor.drop_variable("b", Hit::Input(pin(1, "IN2")), &mut frame);
    let chart = frame.change.expect("a change").chart;
    let new = chart
        .elements
        .iter()
        .find(|e| e.id == ElementId(3))
        .unwrap();
    assert!(matches!(&new.kind, CfcElementKind::Input { expression } if expression == "b"));
    assert!(
        chart
            .wires
            .iter()
            .any(|w| w.from == pin(3, "") && w.to == pin(1, "IN2"))
    );
    let mut frame = FrameResult::default();
    editor.drop_variable("speed", Hit::Element(ElementId(2)), &mut frame);
    let chart = frame.change.expect("a change").chart;
    assert!(matches!(&chart.elements[2].kind,
        CfcElementKind::Output { expression, .. } if expression == "speed"));
}

#[test]
fn the_toolbox_arms_an_element_and_ctrl_click_places_it_again() {
    let mut harness = harness(CfcChart::default());
    harness.get_by_label("Return").click();
    harness.run_steps(2);
    for x in [4.0, 14.0] {
        let at = screen(&harness, x, 4.0);
        harness.hover_at(at);
        harness.run_steps(1);
        for pressed in [true, false] {
            harness.event(Event::PointerButton {
                pos: at,
                button: egui::PointerButton::Primary,
                pressed,
                modifiers: Modifiers::COMMAND,
            });
        }
        harness.run_steps(2);
    }
    assert_eq!(harness.state().chart.elements.len(), 2);
    assert_eq!(
        orders(&harness.state().chart),
        vec![(0, Some(0)), (1, Some(1))]
    );
}

#[test]
fn every_wire_is_routed_clear_of_the_boxes() {
    let harness = drawn_chart();
    let editor = &harness.state().editor;
    for (to, route) in &editor.routes {
        for segment in route.windows(2) {
            for shape in editor.shapes.values() {
                assert!(
                    !shape.rect.crossed_by(segment[0], segment[1]),
                    "the wire into {to:?} crosses {shape:?}"
                );
            }
        }
    }
}

/// A secondary click at `pos`, which opens the context menu.
fn right_click(harness: &mut Harness<'static, Host>, pos: Pos2) {
    harness.hover_at(pos);
    harness.run_steps(1);
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: egui::PointerButton::Secondary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.run_steps(2);
}

#[test]
fn the_context_menu_sends_an_output_to_the_front() {
    let mut harness = drawn_chart();
    let output = screen(&harness, 36.0, 5.0);
    right_click(&mut harness, output);
    harness.get_by_label("Execution Order").hover();
    harness.run_steps(3);
    harness.get_by_label("Send to Front").click();
    harness.run_steps(3);
    assert_eq!(
        orders(&harness.state().chart),
        vec![(0, None), (1, Some(1)), (2, Some(0))]
    );
}

#[test]
fn the_context_menu_negates_a_pin_and_sets_its_execution_order_by_number() {
    let mut harness = drawn_chart();
    let in2 = pin_at(&harness, 1, "IN2", false);
    right_click(&mut harness, in2);
    harness.get_by_label("Negate").click();
    harness.run_steps(3);
    let CfcElementKind::Box(block) = &harness.state().chart.elements[1].kind else {
        panic!("a box");
    };
    assert!(block.inputs[1].negated && !block.inputs[0].negated);
    let head = screen(&harness, 16.0, 4.0);
    right_click(&mut harness, head);
    harness.get_by_label("Execution Order").hover();
    harness.run_steps(3);
    harness.get_by_label("Set Execution Order…").click();
    harness.run_steps(3);
    harness.key_press(Key::Backspace);
    type_and_enter(&mut harness, "1");
    assert_eq!(
        orders(&harness.state().chart),
        vec![(0, None), (1, Some(1)), (2, Some(0))]
    );
    let head = screen(&harness, 16.0, 4.0);
    right_click(&mut harness, head);
    harness.get_by_label("Execution Order").hover();
    harness.run_steps(3);
    harness.get_by_label("Set Execution Order…").click();
    harness.run_steps(3);
    harness.key_press(Key::Backspace);
    type_and_enter(&mut harness, "x");
    assert_eq!(
        harness.state().refusals,
        vec![CfcRefusal::NotANumber("x".to_owned())]
    );
}

#[test]
fn the_toolbox_control_point_pins_a_wire_and_its_route_passes_there() {
    let mut harness = drawn_chart();
    let route = harness.state().editor.routes[&pin(2, "")].clone();
    // The middle of the wire's longest segment, away from the pins.
    let longest = route
        .windows(2)
        .max_by_key(|s| (s[0].x - s[1].x).abs() + (s[0].y - s[1].y).abs())
        .unwrap();
    let middle = (
        (longest[0].x + longest[1].x) / 2,
        (longest[0].y + longest[1].y) / 2,
    );
    harness.get_by_label("Control point").click();
    harness.run_steps(2);
    let at = screen(&harness, middle.0 as f32, middle.1 as f32);
    click(&mut harness, at);
    let wire = harness
        .state()
        .chart
        .wires
        .iter()
        .find(|w| w.to == pin(2, ""))
        .unwrap()
        .clone();
    assert_eq!(
        wire.points,
        vec![project_model::GridPoint {
            x: middle.0,
            y: middle.1
        }]
    );
    // Dragged down, the point takes the route with it.
    let to = screen(&harness, middle.0 as f32, middle.1 as f32 + 8.0);
    drag(&mut harness, at, to);
    let moved = project_model::GridPoint {
        x: middle.0,
        y: middle.1 + 8,
    };
    let wire = harness
        .state()
        .chart
        .wires
        .iter()
        .find(|w| w.to == pin(2, ""))
        .unwrap()
        .clone();
    assert_eq!(wire.points, vec![moved]);
    let route = &harness.state().editor.routes[&pin(2, "")];
    assert!(
        route.windows(2).any(|s| {
            (s[0].x == moved.x && (s[0].y.min(s[1].y)..=s[0].y.max(s[1].y)).contains(&moved.y))
                || (s[0].y == moved.y
                    && (s[0].x.min(s[1].x)..=s[0].x.max(s[1].x)).contains(&moved.x))
        }),
        "{route:?} passes {moved:?}"
    );
}

#[test]
fn the_toolbox_input_pin_extends_an_add_box_and_enter_retypes_a_box() {
    let mut harness = drawn_chart();
    harness.get_by_label("Input pin").click();
    harness.run_steps(2);
    let head = screen(&harness, 16.0, 4.0);
    click(&mut harness, head);
    let CfcElementKind::Box(block) = &harness.state().chart.elements[1].kind else {
        panic!("a box");
    };
    let names: Vec<&str> = block.inputs.iter().map(|pin| pin.name.as_str()).collect();
    assert_eq!(names, ["IN1", "IN2", "IN3"]);
    // Enter on the selected box opens its type; TON re-creates the pins and drops the wires
    // of the pins that went away.
    click(&mut harness, head);
    harness.key_press(Key::Enter);
    harness.run_steps(3);
    for _ in 0..3 {
        harness.key_press(Key::Backspace);
    }
    type_and_enter(&mut harness, "TON");
    harness.key_press(Key::Escape);
    harness.run_steps(3);
    let chart = &harness.state().chart;
    let CfcElementKind::Box(block) = &chart.elements[1].kind else {
        panic!("a box");
    };
    assert_eq!(block.type_name, "TON");
    assert!(chart.wires.is_empty(), "{:?}", chart.wires);
}

#[test]
fn online_values_show_and_a_double_click_prepares_a_value() {
    let mut harness = drawn_chart();
    let mut online = DiagramOnline::default();
    online.values.insert(
        (ElementId(0), None),
        OnlineValue {
            text: "42".to_owned(),
            forced: false,
        },
    );
    online.values.insert(
        (ElementId(1), Some("OUT".to_owned())),
        OnlineValue {
            text: "43".to_owned(),
            forced: true,
        },
    );
    harness.state_mut().editor.set_online(Some(online));
    harness.run_steps(2);
    let changes = harness.state().changes;
    let input = screen(&harness, 3.0, 5.0);
    double_click(&mut harness, input);
    type_and_enter(&mut harness, "7");
    assert_eq!(
        harness.state().prepared,
        vec![PreparedOperand {
            element: ElementId(0),
            operand: "a".to_owned(),
            value: "7".to_owned(),
        }]
    );
    assert_eq!(
        harness.state().changes,
        changes,
        "preparing a value changes nothing"
    );
}

#[test]
fn copy_and_paste_give_fresh_elements_with_their_wire_beside_the_originals() {
    let mut harness = drawn_chart();
    harness.state_mut().editor.selection = CfcSelection {
        elements: vec![ElementId(0), ElementId(1)],
        wire: None,
    };
    harness.event(Event::Copy);
    harness.run_steps(2);
    harness.event(Event::Paste("a ADD".to_owned()));
    harness.run_steps(2);
    let chart = &harness.state().chart;
    assert_eq!(chart.elements.len(), 5);
    assert!(
        chart
            .wires
            .iter()
            .any(|w| w.from == pin(3, "") && w.to == pin(4, "IN1"))
    );
    let pasted = chart
        .elements
        .iter()
        .find(|e| e.id == ElementId(3))
        .unwrap();
    assert_eq!((pasted.x, pasted.y), (4, 6));
    assert_eq!(
        harness.state().editor.selection().elements,
        vec![ElementId(3), ElementId(4)]
    );
}

#[test]
fn a_wire_dropped_on_an_element_takes_its_only_pin_and_output_to_output_is_refused() {
    let mut harness = drawn_chart();
    // A second output, below; the box's output dropped on its frame.
    place(&mut harness, "Output", 34.0, 12.0, "b");
    let from = pin_at(&harness, 1, "OUT", true);
    let frame = screen(&harness, 36.0, 13.0);
    drag(&mut harness, from, frame);
    assert!(
        harness
            .state()
            .chart
            .wires
            .iter()
            .any(|w| w.from == pin(1, "OUT") && w.to == pin(3, ""))
    );
    let from = pin_at(&harness, 1, "OUT", true);
    let input_output = pin_at(&harness, 0, "", true);
    drag(&mut harness, from, input_output);
    assert_eq!(
        harness.state().refusals,
        vec![CfcRefusal::Edit(project_model::CfcEditError::NotAnInput(
            pin(0, "")
        ))]
    );
}

#[test]
fn a_clicked_wire_is_selected_and_delete_removes_only_it() {
    let mut harness = drawn_chart();
    let route = harness.state().editor.routes[&pin(2, "")].clone();
    let longest = route
        .windows(2)
        .max_by_key(|s| (s[0].x - s[1].x).abs() + (s[0].y - s[1].y).abs())
        .unwrap();
    let at = screen(
        &harness,
        (longest[0].x + longest[1].x) as f32 / 2.0,
        (longest[0].y + longest[1].y) as f32 / 2.0,
    );
    click(&mut harness, at);
    assert_eq!(harness.state().editor.selection().wire, Some(pin(2, "")));
    harness.key_press(Key::Delete);
    harness.run_steps(3);
    let chart = &harness.state().chart;
    assert_eq!(chart.elements.len(), 3);
    assert_eq!(chart.wires.len(), 1);
    assert_eq!(chart.wires[0].to, pin(1, "IN1"));
}

#[test]
fn a_toolbox_element_dragged_onto_the_canvas_is_placed_where_it_is_dropped() {
    let mut harness = harness(CfcChart::default());
    let label = harness.get_by_label("Label").rect().center();
    let at = screen(&harness, 20.5, 8.5);
    drag(&mut harness, label, at);
    type_and_enter(&mut harness, "retry");
    let chart = &harness.state().chart;
    assert_eq!(chart.elements.len(), 1, "{chart:?}");
    assert_eq!((chart.elements[0].x, chart.elements[0].y), (20, 8));
    assert!(matches!(&chart.elements[0].kind, CfcElementKind::Label { name } if name == "retry"));
    assert_eq!(chart.elements[0].order, Some(0));
}

#[test]
fn a_rubber_band_selects_elements_and_a_drag_moves_them_together() {
    let mut harness = drawn_chart();
    let from = screen(&harness, 1.0, 1.0);
    let to = screen(&harness, 24.0, 11.0);
    drag(&mut harness, from, to);
    assert_eq!(
        harness.state().editor.selection().elements,
        vec![ElementId(0), ElementId(1)]
    );
    let grab = screen(&harness, 16.0, 4.0);
    let drop = screen(&harness, 16.0, 24.0);
    drag(&mut harness, grab, drop);
    let chart = &harness.state().chart;
    let places: Vec<(i32, i32)> = chart.elements.iter().map(|e| (e.x, e.y)).collect();
    assert_eq!(places, vec![(2, 24), (14, 23), (34, 4)]);
}

#[test]
fn findings_mark_their_element_and_pin_with_the_worst_severity() {
    let harness = drawn_chart();
    let mut editor = CfcEditor::new(&harness.state().chart);
    let finding = |severity, pin: Option<&str>| CfcDiagnostic {
        element: Some(ElementId(1)),
        pin: pin.map(str::to_owned),
        severity,
        code: "E0104".to_owned(),
        message: "type mismatch".to_owned(),
    };
    editor.set_diagnostics(vec![
        finding(crate::Severity::Warning, None),
        finding(crate::Severity::Error, Some("IN2")),
        finding(crate::Severity::Info, Some("IN2")),
    ]);
    assert_eq!(editor.marks[&ElementId(1)], crate::Severity::Error);
    assert_eq!(
        editor.pin_marks[&(ElementId(1), "IN2".to_owned())],
        crate::Severity::Error
    );
    assert!(!editor.marks.contains_key(&ElementId(0)));
}

#[test]
fn a_jump_completes_the_labels_of_the_chart() {
    let mut harness = harness(CfcChart::default());
    place(&mut harness, "Label", 2.0, 2.0, "retry");
    place(&mut harness, "Jump", 2.0, 8.0, "re");
    let chart = &harness.state().chart;
    assert!(matches!(&chart.elements[1].kind, CfcElementKind::Jump { label } if label == "retry"));
}

#[test]
fn f9_asks_for_a_breakpoint_on_the_selected_element_and_the_marks_are_kept() {
    let mut harness = drawn_chart();
    harness.state_mut().editor.reveal(ElementId(2));
    harness.run_steps(2);
    harness.key_press(Key::F9);
    harness.run_steps(2);
    let output = crate::BodyPlace {
        network: 0,
        element: Some(ElementId(2)),
    };
    assert_eq!(harness.state().toggles, vec![output]);
    let marks = crate::BodyDebugMarks {
        breakpoints: vec![crate::BodyBreakpointMark {
            place: output,
            look: crate::BreakpointLook::HitCount,
        }],
        halt: Some(output),
        halt_is_caller: true,
        flow: vec![output],
    };
    harness.state_mut().editor.set_debug_marks(marks.clone());
    harness.run_steps(2);
    assert_eq!(harness.state().editor.debug_marks(), &marks);
    assert_eq!(harness.state().editor.breakpoint_place(), Some(output));
}
