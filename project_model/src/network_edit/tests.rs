//! Tests of the structural edits.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;

fn contact(id: u32, text: &str) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        ..Operand::default()
    })
}

fn coil(id: u32, variable: &str) -> NetworkOutput {
    NetworkOutput::Coil(Coil {
        id: ElementId(id),
        variable: variable.into(),
        kind: CoilKind::Normal,
    })
}

/// One rung: `a` `b` driving coil `q`.
fn body() -> Vec<Network> {
    vec![Network {
        rung: vec![contact(1, "a"), contact(2, "b")],
        outputs: vec![coil(3, "q")],
        ..Network::default()
    }]
}

fn applied(mut body: Vec<Network>, splice: &BodySplice) -> Vec<Network> {
    splice.apply(&mut body);
    body
}

/// The texts of a chain, with parallel groups as `(x | y)`.
fn chain_text(chain: &[FlowNode]) -> String {
    chain
        .iter()
        .map(|node| match node {
            FlowNode::Operand(operand) => operand.text.clone(),
            FlowNode::Parallel(parallel) => format!(
                "({})",
                parallel
                    .branches
                    .iter()
                    .map(|branch| chain_text(&branch.rung))
                    .collect::<Vec<_>>()
                    .join(" | ")
            ),
            FlowNode::Block(block) => format!("[{}]", block.type_name),
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn a_contact_goes_before_or_after_the_selection_with_a_fresh_id() {
    let before = insert_series(
        &body(),
        Anchor::Element(ElementId(2)),
        Side::Before,
        new_contact("x"),
    )
    .unwrap();
    assert_eq!((before.at, before.remove), (0, 1));
    assert_eq!(before.focus, Some(ElementId(4)));
    let body_after = applied(body(), &before);
    assert_eq!(chain_text(&body_after[0].rung), "a x b");
    let after = insert_series(
        &body_after,
        Anchor::Element(ElementId(2)),
        Side::After,
        new_contact("y"),
    )
    .unwrap();
    assert_eq!(after.focus, Some(ElementId(5)));
    assert_eq!(chain_text(&applied(body_after, &after)[0].rung), "a x b y");
}

#[test]
fn a_contact_inserted_at_a_coil_ends_the_rung_and_none_goes_after_a_coil() {
    let splice = insert_series(
        &body(),
        Anchor::Element(ElementId(3)),
        Side::Before,
        new_contact("x"),
    )
    .unwrap();
    assert_eq!(chain_text(&applied(body(), &splice)[0].rung), "a b x");
    let refused = insert_series(
        &body(),
        Anchor::Element(ElementId(3)),
        Side::After,
        new_contact("x"),
    );
    assert_eq!(
        refused,
        Err(NetworkEditError::NotApplicable {
            id: ElementId(3),
            operation: "inserting in series"
        })
    );
}

#[test]
fn a_parallel_contact_wraps_the_selection_and_then_joins_its_group() {
    let below = insert_parallel(
        &body(),
        &[ElementId(2)],
        ParallelSide::Below,
        new_contact("c"),
    )
    .unwrap();
    let body = applied(body(), &below);
    assert_eq!(chain_text(&body[0].rung), "a (b | c)");
    // The group took the next id after the new contact.
    assert_eq!(body[0].rung[1].id(), ElementId(5));
    let above = insert_parallel(
        &body,
        &[ElementId(2)],
        ParallelSide::Above,
        new_contact("d"),
    )
    .unwrap();
    let body = applied(body, &above);
    assert_eq!(chain_text(&body[0].rung), "a (d | b | c)");
    let around_two = insert_parallel(
        &body,
        &[ElementId(1), ElementId(5)],
        ParallelSide::Below,
        new_contact("e"),
    )
    .unwrap();
    assert_eq!(
        chain_text(&applied(body.clone(), &around_two)[0].rung),
        "(a (d | b | c) | e)"
    );
}

#[test]
fn a_parallel_contact_needs_neighbours_in_one_chain() {
    let body = vec![Network {
        rung: vec![contact(1, "a"), contact(2, "b"), contact(3, "c")],
        ..Network::default()
    }];
    assert_eq!(
        insert_parallel(
            &body,
            &[ElementId(1), ElementId(3)],
            ParallelSide::Below,
            new_contact("x")
        ),
        Err(NetworkEditError::NotOneChain)
    );
    assert_eq!(
        insert_parallel(&body, &[], ParallelSide::Below, new_contact("x")),
        Err(NetworkEditError::NothingSelected)
    );
}

#[test]
fn coils_jumps_and_returns_go_below_the_selected_output_or_at_the_end() {
    let set = insert_output(
        &body(),
        Anchor::Element(ElementId(3)),
        new_coil("s", CoilKind::Set),
    )
    .unwrap();
    let body = applied(body(), &set);
    assert_eq!(body[0].outputs.len(), 2);
    assert!(
        matches!(&body[0].outputs[1], NetworkOutput::Coil(coil) if coil.kind == CoilKind::Set && coil.id == ElementId(4))
    );
    let jump = insert_output(&body, Anchor::Element(ElementId(1)), new_jump("end")).unwrap();
    let body = applied(body, &jump);
    assert!(matches!(&body[0].outputs[2], NetworkOutput::Jump { label, .. } if label == "end"));
    let ret = insert_output(&body, Anchor::Network(0), new_return()).unwrap();
    let body = applied(body, &ret);
    assert!(matches!(body[0].outputs[3], NetworkOutput::Return { id } if id == ElementId(6)));
}

#[test]
fn a_box_goes_on_the_power_line_with_its_first_input_unconnected() {
    let splice = insert_series(
        &body(),
        Anchor::Element(ElementId(2)),
        Side::After,
        new_box("TON", "timer", &["IN", "PT"], &["Q", "ET"]),
    )
    .unwrap();
    let body = applied(body(), &splice);
    let FlowNode::Block(block) = &body[0].rung[2] else {
        panic!("no box at the end of the rung");
    };
    assert_eq!(block.id, ElementId(4));
    assert!(block.inputs[0].source.is_empty());
    let pt = set_pin_operand(&body, ElementId(4), "PT", "T#5S").unwrap();
    let body = applied(body, &pt);
    let FlowNode::Block(block) = &body[0].rung[2] else {
        panic!("the box went away");
    };
    assert_eq!(chain_text(&block.inputs[1].source), "T#5S");
    assert_eq!(block.inputs[1].source[0].id(), ElementId(5));
}

#[test]
fn networks_are_inserted_above_or_below() {
    let below = insert_network(&body(), 0, Side::After, Network::default()).unwrap();
    assert_eq!(
        (below.at, below.remove, below.focus_network),
        (1, 0, Some(1))
    );
    let above = insert_network(&body(), 0, Side::Before, Network::default()).unwrap();
    assert_eq!(above.at, 0);
    assert_eq!(
        insert_network(&[], 0, Side::After, Network::default())
            .unwrap()
            .at,
        0
    );
    assert!(matches!(
        insert_network(&body(), 3, Side::After, Network::default()),
        Err(NetworkEditError::NoSuchNetwork { index: 3, count: 1 })
    ));
}

#[test]
fn negation_and_the_modifier_cycle_through_contact_and_coil_kinds() {
    let mut body = body();
    let mut seen = Vec::new();
    for _ in 0..4 {
        body = applied(body.clone(), &cycle_modifier(&body, ElementId(1)).unwrap());
        let FlowNode::Operand(operand) = &body[0].rung[0] else {
            panic!("the contact went away");
        };
        seen.push((operand.negated, operand.edge));
    }
    assert_eq!(
        seen,
        [
            (true, Edge::None),
            (false, Edge::Rising),
            (false, Edge::Falling),
            (false, Edge::None)
        ]
    );
    let mut kinds = Vec::new();
    for _ in 0..6 {
        body = applied(body.clone(), &cycle_modifier(&body, ElementId(3)).unwrap());
        let NetworkOutput::Coil(coil) = &body[0].outputs[0] else {
            panic!("the coil went away");
        };
        kinds.push(coil.kind);
    }
    assert_eq!(
        kinds,
        [
            CoilKind::Negated,
            CoilKind::Set,
            CoilKind::Reset,
            CoilKind::Rising,
            CoilKind::Falling,
            CoilKind::Normal
        ]
    );
    let negated = applied(
        body.clone(),
        &toggle_negation(&body, ElementId(2), None).unwrap(),
    );
    assert!(matches!(&negated[0].rung[1], FlowNode::Operand(operand) if operand.negated));
    let with_box = applied(
        body.clone(),
        &insert_series(
            &body,
            Anchor::Network(0),
            Side::After,
            new_box("TON", "t", &["IN"], &["Q"]),
        )
        .unwrap(),
    );
    assert!(toggle_negation(&with_box, ElementId(4), None).is_err());
    let pin = applied(
        with_box.clone(),
        &toggle_negation(&with_box, ElementId(4), Some("Q")).unwrap(),
    );
    assert!(matches!(&pin[0].rung[2], FlowNode::Block(block) if block.outputs[0].negated));
}

#[test]
fn deleting_a_branch_element_collapses_a_group_left_with_one_branch() {
    let body = vec![Network {
        rung: vec![
            contact(1, "a"),
            FlowNode::Parallel(Parallel {
                id: ElementId(2),
                branches: vec![
                    Branch {
                        rung: vec![contact(3, "b"), contact(4, "c")],
                    },
                    Branch {
                        rung: vec![contact(5, "d")],
                    },
                ],
            }),
        ],
        outputs: vec![coil(6, "q")],
        ..Network::default()
    }];
    let splice = delete_elements(&body, &[ElementId(5)]).unwrap();
    let collapsed = applied(body.clone(), &splice);
    assert_eq!(chain_text(&collapsed[0].rung), "a b c");
    let one = delete_elements(&body, &[ElementId(4), ElementId(6)]).unwrap();
    let kept = applied(body.clone(), &one);
    assert_eq!(chain_text(&kept[0].rung), "a (b | d)");
    assert!(kept[0].outputs.is_empty());
    let group = delete_elements(&body, &[ElementId(2)]).unwrap();
    assert_eq!(chain_text(&applied(body.clone(), &group)[0].rung), "a");
    assert_eq!(
        delete_elements(&body, &[ElementId(9)]),
        Err(NetworkEditError::NoSuchElement { id: ElementId(9) })
    );
}

#[test]
fn copied_elements_and_networks_paste_with_fresh_ids() {
    let clipboard = copy_elements(&body(), &[ElementId(1), ElementId(3)]).unwrap();
    assert_eq!(clipboard.nodes.len(), 1);
    assert_eq!(clipboard.outputs.len(), 1);
    let splice = paste(&body(), Anchor::Element(ElementId(2)), &clipboard).unwrap();
    let pasted = applied(body(), &splice);
    assert_eq!(chain_text(&pasted[0].rung), "a b a");
    assert_eq!(pasted[0].rung[2].id(), ElementId(4));
    assert_eq!(pasted[0].outputs[1].id(), ElementId(5));
    let networks = copy_networks(&pasted, 0..1).unwrap();
    let splice = paste(&pasted, Anchor::Network(0), &networks).unwrap();
    let doubled = applied(pasted.clone(), &splice);
    assert_eq!(doubled.len(), 2);
    let mut ids = Vec::new();
    for network in &doubled {
        network.for_each_element(&mut |element| ids.push(element.id().0));
    }
    assert_eq!(ids, [1, 2, 4, 3, 5, 6, 7, 8, 9, 10]);
    assert_eq!(
        paste(&body(), Anchor::Network(0), &NetworkClipboard::default()),
        Err(NetworkEditError::NothingSelected)
    );
}

#[test]
fn texts_and_headers_are_set_on_their_elements() {
    let body = applied(
        body(),
        &set_element_text(&body(), ElementId(1), "start").unwrap(),
    );
    let body = applied(
        body.clone(),
        &set_element_text(&body, ElementId(3), "motor").unwrap(),
    );
    assert!(matches!(&body[0].rung[0], FlowNode::Operand(operand) if operand.text == "start"));
    assert!(matches!(&body[0].outputs[0], NetworkOutput::Coil(coil) if coil.variable == "motor"));
    let titled = applied(
        body.clone(),
        &set_network_header(&body, 0, HeaderField::Title, "Start the motor").unwrap(),
    );
    assert_eq!(titled[0].title, "Start the motor");
    let deleted = delete_networks(&titled, 0..1).unwrap();
    assert_eq!(
        (deleted.at, deleted.remove, deleted.focus_network),
        (0, 1, None)
    );
}

#[test]
fn en_and_eno_are_added_to_a_box_and_taken_away_again() {
    let splice = insert_series(
        &body(),
        Anchor::Element(ElementId(2)),
        Side::After,
        new_box("TON", "timer", &["IN", "PT"], &["Q", "ET"]),
    )
    .unwrap();
    let plain = applied(body(), &splice);
    let with_en = applied(plain.clone(), &toggle_en_eno(&plain, ElementId(4)).unwrap());
    let FlowNode::Block(block) = &with_en[0].rung[2] else {
        panic!("the box went away");
    };
    let pins = |pins: Vec<&str>| pins.into_iter().map(str::to_owned).collect::<Vec<_>>();
    assert_eq!(
        block
            .inputs
            .iter()
            .map(|i| i.pin.clone())
            .collect::<Vec<_>>(),
        pins(vec!["EN", "IN", "PT"])
    );
    assert_eq!(block.chain_output(), Some(0));
    assert!(crate::network_problems(&with_en).is_empty());
    let without = applied(
        with_en.clone(),
        &toggle_en_eno(&with_en, ElementId(4)).unwrap(),
    );
    assert_eq!(without, plain);
    // A contact has no EN.
    assert!(matches!(
        toggle_en_eno(&plain, ElementId(1)),
        Err(NetworkEditError::NotApplicable { .. })
    ));
}

#[test]
fn taking_en_away_is_refused_when_the_first_input_would_be_driven_twice() {
    let splice = insert_series(
        &body(),
        Anchor::Element(ElementId(2)),
        Side::After,
        new_box("TON", "timer", &["EN", "IN", "PT"], &["ENO", "Q", "ET"]),
    )
    .unwrap();
    let body = applied(body(), &splice);
    let body = applied(
        body.clone(),
        &set_pin_operand(&body, ElementId(4), "IN", "start").unwrap(),
    );
    assert!(matches!(
        toggle_en_eno(&body, ElementId(4)),
        Err(NetworkEditError::NotApplicable { .. })
    ));
}

#[test]
fn an_input_pin_s_edge_cycles_through_rising_and_falling() {
    let splice = insert_series(
        &body(),
        Anchor::Element(ElementId(2)),
        Side::After,
        new_box("CTU", "counter", &["CU", "RESET", "PV"], &["Q", "CV"]),
    )
    .unwrap();
    let mut body = applied(body(), &splice);
    let mut edges = Vec::new();
    for _ in 0..3 {
        body = applied(
            body.clone(),
            &cycle_pin_edge(&body, ElementId(4), "RESET").unwrap(),
        );
        let FlowNode::Block(block) = &body[0].rung[2] else {
            panic!("the box went away");
        };
        edges.push(block.inputs[1].edge);
    }
    assert_eq!(edges, [Edge::Rising, Edge::Falling, Edge::None]);
    assert!(cycle_pin_edge(&body, ElementId(4), "Q").is_err());
}
