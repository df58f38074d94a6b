use super::*;
use crate::{CfcBox, CfcElementKind, CfcPin, CoilKind, Edge, GridPoint, PinRef, cfc_input_pins};

fn at(x: i32, y: i32) -> GridPoint {
    GridPoint { x, y }
}

fn pin(element: u32, name: &str) -> PinRef {
    PinRef::new(ElementId(element), name)
}

fn input(text: &str) -> CfcElementKind {
    CfcElementKind::Input {
        expression: text.to_owned(),
    }
}

fn output(text: &str) -> CfcElementKind {
    CfcElementKind::Output {
        expression: text.to_owned(),
        coil: CoilKind::Normal,
    }
}

fn block(type_name: &str, inputs: &[&str], outputs: &[&str]) -> CfcElementKind {
    let pins = |names: &[&str]| names.iter().map(|name| CfcPin::named(*name)).collect();
    CfcElementKind::Box(CfcBox {
        type_name: type_name.to_owned(),
        instance: String::new(),
        inputs: pins(inputs),
        outputs: pins(outputs),
    })
}

/// An input (0) into an ADD box (1) into an output (2), the box's second input from another
/// input (3).
fn small_chart() -> CfcChart {
    let chart = CfcChart::default();
    let (chart, a) = add_element(&chart, input("a"), at(0, 0));
    let (chart, add) = add_element(&chart, block("ADD", &["IN1", "IN2"], &["OUT"]), at(6, 0));
    let (chart, y) = add_element(&chart, output("y"), at(14, 0));
    let (chart, b) = add_element(&chart, input("b"), at(0, 2));
    let chart = connect(&chart, &pin(a.0, ""), &pin(add.0, "IN1")).unwrap();
    let chart = connect(&chart, &pin(b.0, ""), &pin(add.0, "IN2")).unwrap();
    connect(&chart, &pin(add.0, "OUT"), &pin(y.0, "")).unwrap()
}

fn orders(chart: &CfcChart) -> Vec<(u32, Option<u32>)> {
    let mut orders: Vec<_> = chart
        .elements
        .iter()
        .map(|element| (element.id.0, element.order))
        .collect();
    orders.sort();
    orders
}

#[test]
fn a_new_element_takes_the_next_id_and_an_executable_one_the_next_order() {
    let chart = small_chart();
    assert_eq!(
        orders(&chart),
        vec![(0, None), (1, Some(0)), (2, Some(1)), (3, None)]
    );
    let (chart, id) = add_element(&chart, CfcElementKind::Return, at(3, 9));
    assert_eq!(id, ElementId(4));
    assert_eq!(element(&chart, id).unwrap().order, Some(2));
}

#[test]
fn moving_elements_moves_the_control_points_between_them_only() {
    let chart = small_chart();
    let chart = add_control_point(&chart, &pin(1, "IN1"), 0, at(3, 1)).unwrap();
    let chart = add_control_point(&chart, &pin(2, ""), 0, at(12, 1)).unwrap();
    let moved = move_elements(&chart, &[ElementId(0), ElementId(1)], at(1, 2)).unwrap();
    assert_eq!((moved.elements[1].x, moved.elements[1].y), (7, 2));
    let into_box = moved.wires.iter().find(|w| w.to == pin(1, "IN1")).unwrap();
    assert_eq!(into_box.points, vec![at(4, 3)]);
    let into_output = moved.wires.iter().find(|w| w.to == pin(2, "")).unwrap();
    assert_eq!(into_output.points, vec![at(12, 1)]);
    assert_eq!(
        move_elements(&chart, &[ElementId(9)], at(1, 0)),
        Err(CfcEditError::NoElement(ElementId(9)))
    );
}

#[test]
fn deleting_removes_the_wires_and_closes_the_order() {
    let chart = small_chart();
    let chart = delete_elements(&chart, &[ElementId(1)]).unwrap();
    assert!(chart.wires.is_empty());
    assert_eq!(orders(&chart), vec![(0, None), (2, Some(0)), (3, None)]);
    assert_eq!(
        delete_elements(&chart, &[]),
        Err(CfcEditError::NothingSelected)
    );
}

#[test]
fn connecting_refuses_wrong_pins_and_replaces_a_driven_input() {
    let chart = small_chart();
    assert_eq!(
        connect(&chart, &pin(1, "OUT"), &pin(0, "")),
        Err(CfcEditError::NotAnInput(pin(0, "")))
    );
    assert_eq!(
        connect(&chart, &pin(1, "IN1"), &pin(2, "")),
        Err(CfcEditError::NotAnOutput(pin(1, "IN1")))
    );
    let replaced = connect(&chart, &pin(3, ""), &pin(1, "IN1")).unwrap();
    let drivers: Vec<_> = replaced
        .wires
        .iter()
        .filter(|wire| wire.to == pin(1, "IN1"))
        .map(|wire| wire.from.clone())
        .collect();
    assert_eq!(drivers, vec![pin(3, "")]);
    // A box may feed itself back; a composer may not.
    assert!(connect(&chart, &pin(1, "OUT"), &pin(1, "IN2")).is_ok());
    let (with_composer, composer) = add_element(
        &chart,
        CfcElementKind::Composer {
            type_name: "POINT".to_owned(),
            inputs: vec![CfcPin::named("X")],
        },
        at(0, 9),
    );
    assert_eq!(
        connect(&with_composer, &pin(composer.0, ""), &pin(composer.0, "X")),
        Err(CfcEditError::SelfConnection(composer))
    );
    let disconnected = disconnect(&chart, &pin(2, "")).unwrap();
    assert_eq!(disconnected.wires.len(), 2);
    assert_eq!(
        disconnect(&disconnected, &pin(2, "")),
        Err(CfcEditError::NoWire(pin(2, "")))
    );
}

#[test]
fn control_points_are_added_moved_and_removed_by_index() {
    let chart = small_chart();
    let chart = add_control_point(&chart, &pin(2, ""), 5, at(12, 0)).unwrap();
    let chart = add_control_point(&chart, &pin(2, ""), 0, at(11, 0)).unwrap();
    let chart = move_control_point(&chart, &pin(2, ""), 1, at(12, 4)).unwrap();
    let wire = chart.wires.iter().find(|w| w.to == pin(2, "")).unwrap();
    assert_eq!(wire.points, vec![at(11, 0), at(12, 4)]);
    let chart = remove_control_point(&chart, &pin(2, ""), 0).unwrap();
    assert_eq!(
        remove_control_point(&chart, &pin(2, ""), 1),
        Err(CfcEditError::NoControlPoint {
            to: pin(2, ""),
            index: 1
        })
    );
}

#[test]
fn an_extensible_box_grows_by_the_next_numbered_input() {
    let chart = extend_box(&small_chart(), ElementId(1)).unwrap();
    assert_eq!(
        cfc_input_pins(&element(&chart, ElementId(1)).unwrap().kind),
        vec!["IN1", "IN2", "IN3"]
    );
    let (mux, id) = add_element(
        &chart,
        block("MUX", &["K", "IN0", "IN1"], &["OUT"]),
        at(0, 5),
    );
    let mux = extend_box(&mux, id).unwrap();
    assert_eq!(
        cfc_input_pins(&element(&mux, id).unwrap().kind),
        vec!["K", "IN0", "IN1", "IN2"]
    );
    let (timer, ton) = add_element(&chart, block("TON", &["IN", "PT"], &["Q", "ET"]), at(0, 5));
    assert_eq!(
        extend_box(&timer, ton),
        Err(CfcEditError::NotExtensible {
            type_name: "TON".to_owned()
        })
    );
    assert!(matches!(
        extend_box(&chart, ElementId(0)),
        Err(CfcEditError::WrongKind { .. })
    ));
}

#[test]
fn pins_take_negation_and_edges_and_outputs_a_coil_kind() {
    let chart = toggle_negation(&small_chart(), &pin(1, "IN2")).unwrap();
    let chart = set_edge(&chart, &pin(1, "IN1"), Edge::Rising).unwrap();
    let CfcElementKind::Box(add) = &element(&chart, ElementId(1)).unwrap().kind else {
        panic!("element 1 is the ADD box");
    };
    assert!(add.inputs[1].negated && !add.inputs[0].negated);
    assert_eq!(add.inputs[0].edge, Edge::Rising);
    let chart = toggle_negation(&chart, &pin(2, "")).unwrap();
    assert!(matches!(
        element(&chart, ElementId(2)).unwrap().kind,
        CfcElementKind::Output {
            coil: CoilKind::Negated,
            ..
        }
    ));
    let chart = set_coil(&chart, ElementId(2), CoilKind::Set).unwrap();
    assert!(matches!(
        element(&chart, ElementId(2)).unwrap().kind,
        CfcElementKind::Output {
            coil: CoilKind::Set,
            ..
        }
    ));
    assert!(set_coil(&chart, ElementId(1), CoilKind::Set).is_err());
    assert_eq!(
        set_edge(&chart, &pin(1, "OUT"), Edge::Rising),
        Err(CfcEditError::NotAnInput(pin(1, "OUT")))
    );
}

#[test]
fn renaming_a_box_type_recreates_its_pins_and_drops_the_lost_wires() {
    let chart = set_box_type(
        &small_chart(),
        ElementId(1),
        "SUB",
        &["IN1".to_owned(), "X".to_owned()],
        &["OUT".to_owned()],
    )
    .unwrap();
    assert_eq!(chart.wires.len(), 2, "the wire into IN2 went away");
    let chart = set_text(&chart, ElementId(0), "speed").unwrap();
    assert_eq!(element(&chart, ElementId(0)).unwrap().kind, input("speed"));
    let chart = set_instance(&chart, ElementId(1), "sub1").unwrap();
    assert!(matches!(&element(&chart, ElementId(1)).unwrap().kind,
        CfcElementKind::Box(b) if b.instance == "sub1" && b.type_name == "SUB"));
}

/// Three boxes in a row (ids 0, 1, 2 in order 0, 1, 2) and an input (3).
fn three_boxes() -> CfcChart {
    let mut chart = CfcChart::default();
    for column in 0..3 {
        chart = add_element(&chart, block("NOT", &["IN"], &["OUT"]), at(column * 8, 0)).0;
    }
    add_element(&chart, input("a"), at(0, 5)).0
}

fn sequence_of(chart: &CfcChart) -> Vec<u32> {
    order::tests_sequence(chart)
}

#[test]
fn the_order_commands_move_the_selection_as_codesys_does() {
    let chart = three_boxes();
    let ids = |list: &[u32]| list.iter().map(|id| ElementId(*id)).collect::<Vec<_>>();
    assert_eq!(
        sequence_of(&send_to_back(&chart, &ids(&[0])).unwrap()),
        [1, 2, 0]
    );
    assert_eq!(
        sequence_of(&send_to_front(&chart, &ids(&[2])).unwrap()),
        [2, 0, 1]
    );
    assert_eq!(
        sequence_of(&move_up(&chart, &ids(&[2])).unwrap()),
        [0, 2, 1]
    );
    assert_eq!(
        sequence_of(&move_up(&chart, &ids(&[0])).unwrap()),
        [0, 1, 2]
    );
    assert_eq!(
        sequence_of(&move_down(&chart, &ids(&[0, 1])).unwrap()),
        [2, 0, 1]
    );
    assert_eq!(
        sequence_of(&set_execution_order(&chart, ElementId(0), 2).unwrap()),
        [1, 2, 0]
    );
    assert_eq!(
        set_execution_order(&chart, ElementId(0), 3),
        Err(CfcEditError::OrderOutOfRange { order: 3, count: 3 })
    );
    assert_eq!(
        send_to_front(&chart, &ids(&[3])),
        Err(CfcEditError::NotExecutable(ElementId(3)))
    );
}

#[test]
fn order_by_topology_runs_top_to_bottom_then_left_to_right() {
    let mut chart = three_boxes();
    chart.elements[0].y = 4;
    chart.elements[2].x = -3;
    assert_eq!(sequence_of(&order_by_topology(&chart)), [2, 1, 0]);
}

#[test]
fn order_by_data_flow_follows_the_wires_and_puts_feedback_last() {
    // 2 feeds 1 feeds 0, though 0 is left and on top: data flow wins over topology.
    let chart = three_boxes();
    let chart = connect(&chart, &pin(2, "OUT"), &pin(1, "IN")).unwrap();
    let chart = connect(&chart, &pin(1, "OUT"), &pin(0, "IN")).unwrap();
    assert_eq!(sequence_of(&order_by_data_flow(&chart)), [2, 1, 0]);
    // Closing the loop 0 → 2: the topmost-leftmost element of the loop runs first and reads
    // the feedback from the previous cycle.
    let looped = connect(&chart, &pin(0, "OUT"), &pin(2, "IN")).unwrap();
    assert_eq!(sequence_of(&order_by_data_flow(&looped)), [0, 2, 1]);
    // Through a connection mark: the sink reads what drives the source.
    let mut marked = three_boxes();
    marked = add_element(
        &marked,
        CfcElementKind::ConnectionSource {
            name: "M".to_owned(),
        },
        at(30, 0),
    )
    .0;
    marked = add_element(
        &marked,
        CfcElementKind::ConnectionSink {
            name: "m".to_owned(),
        },
        at(-5, 0),
    )
    .0;
    let marked = connect(&marked, &pin(2, "OUT"), &pin(4, "")).unwrap();
    let marked = connect(&marked, &pin(5, ""), &pin(0, "IN")).unwrap();
    assert_eq!(sequence_of(&order_by_data_flow(&marked)), [1, 2, 0]);
}

#[test]
fn copy_and_paste_give_fresh_ids_and_keep_the_inner_wires() {
    let chart = small_chart();
    let fragment = copy_elements(&chart, &[ElementId(0), ElementId(1)]).unwrap();
    assert_eq!(fragment.wires.len(), 1);
    let (pasted, ids) = paste_elements(&chart, &fragment, at(0, 10));
    assert_eq!(ids, vec![ElementId(4), ElementId(5)]);
    assert_eq!(pasted.elements.len(), 6);
    let new_wire = pasted.wires.last().unwrap();
    assert_eq!(
        (new_wire.from.clone(), new_wire.to.clone()),
        (pin(4, ""), pin(5, "IN1"))
    );
    assert_eq!(element(&pasted, ElementId(5)).unwrap().order, Some(2));
    assert_eq!(element(&pasted, ElementId(5)).unwrap().y, 10);
}

#[test]
fn a_composer_takes_the_members_of_its_structure() {
    let (chart, id) = add_element(
        &CfcChart::default(),
        CfcElementKind::Composer {
            type_name: "???".to_owned(),
            inputs: Vec::new(),
        },
        at(5, 5),
    );
    let (chart, x) = add_element(&chart, input("1"), at(0, 5));
    let chart = set_members(&chart, id, "POINT", &["X".to_owned(), "Y".to_owned()]).unwrap();
    assert_eq!(
        cfc_input_pins(&element(&chart, id).unwrap().kind),
        vec!["X", "Y"]
    );
    let chart = connect(&chart, &pin(x.0, ""), &pin(id.0, "Y")).unwrap();
    let chart = set_members(&chart, id, "LINE", &["X".to_owned()]).unwrap();
    assert!(chart.wires.is_empty(), "the wire into Y went away");
    assert!(set_members(&chart, x, "LINE", &[]).is_err());
}
