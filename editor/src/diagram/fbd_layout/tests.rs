//! Tests of the FBD view of networks.

use egui::{Rect, pos2, vec2};
use project_model::{
    BlockCall, BlockInput, BlockOutput, Branch, Coil, ElementId, FlowNode, Network, NetworkOutput,
    Operand, Parallel,
};

use super::*;

fn contact(id: u32, text: &str, negated: bool) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        negated,
        ..Operand::default()
    })
}

fn boxes(layout: &NetworkLayout) -> Vec<(Option<ElementId>, String, Rect)> {
    layout
        .elements
        .iter()
        .filter_map(|element| match &element.shape {
            Shape::Box { type_name, .. } => Some((element.id, type_name.clone(), element.rect)),
            _ => None,
        })
        .collect()
}

#[test]
fn a_series_is_an_and_box_and_a_parallel_group_an_or_box() {
    // a AND NOT b AND (c OR d) := q
    let network = Network {
        rung: vec![
            contact(1, "a", false),
            contact(2, "b", true),
            FlowNode::Parallel(Parallel {
                id: ElementId(3),
                branches: vec![
                    Branch {
                        rung: vec![contact(4, "c", false)],
                    },
                    Branch {
                        rung: vec![contact(5, "d", false)],
                    },
                ],
            }),
        ],
        outputs: vec![NetworkOutput::Coil(Coil {
            id: ElementId(6),
            variable: "q".into(),
            ..Coil::default()
        })],
        ..Network::default()
    };
    let layout = fbd_layout(&network, 0);
    let found = boxes(&layout);
    assert_eq!(found.len(), 2);
    // The OR box stands left of the AND box, fed by c and d.
    let (or_id, or_name, or_rect) = &found[0];
    assert_eq!((or_id, or_name.as_str()), (&Some(ElementId(3)), "OR"));
    assert_eq!(
        *or_rect,
        Rect::from_min_size(pos2(3.0, 2.0), vec2(2.0, 2.0))
    );
    let (and_id, and_name, and_rect) = &found[1];
    assert_eq!((and_id, and_name.as_str()), (&None, "AND"));
    assert_eq!(
        *and_rect,
        Rect::from_min_size(pos2(6.0, 0.0), vec2(2.0, 4.0))
    );
    // NOT b is a circle on the AND box's second pin, not on b.
    let Some(Shape::Box { inputs, .. }) = layout
        .elements
        .iter()
        .find(|element| element.rect == *and_rect)
        .map(|element| &element.shape)
    else {
        panic!("no AND box");
    };
    assert_eq!(
        inputs
            .iter()
            .map(|pin| (pin.row, pin.negated))
            .collect::<Vec<_>>(),
        [(0.0, false), (1.0, true), (2.0, false)]
    );
    assert!(matches!(
        layout.element(ElementId(2)).map(|element| &element.shape),
        Some(Shape::Variable { negated: false, .. })
    ));
    // The assignment stands right of the root, fed with the power after the group.
    let assignment = layout
        .element(ElementId(6))
        .map(|element| (element.rect, element.power_in));
    assert_eq!(
        assignment,
        Some((
            Rect::from_min_size(pos2(9.0, 0.0), vec2(2.0, 1.0)),
            Power::After(ElementId(3))
        ))
    );
    assert_eq!(layout.size, vec2(11.0, 4.0));
}

#[test]
fn a_box_in_a_chain_takes_the_chain_before_it_on_its_first_input() {
    let network = Network {
        rung: vec![
            contact(1, "start", false),
            FlowNode::Block(BlockCall {
                id: ElementId(2),
                type_name: "TON".into(),
                instance: "timer".into(),
                inputs: vec![
                    BlockInput {
                        pin: "IN".into(),
                        ..BlockInput::default()
                    },
                    BlockInput {
                        pin: "PT".into(),
                        source: vec![contact(3, "T#5S", false)],
                        ..BlockInput::default()
                    },
                ],
                outputs: vec![BlockOutput {
                    pin: "Q".into(),
                    ..BlockOutput::default()
                }],
            }),
        ],
        ..Network::default()
    };
    let layout = fbd_layout(&network, 0);
    assert_eq!(
        layout.element(ElementId(1)).map(|element| element.rect),
        Some(Rect::from_min_size(pos2(0.0, 0.0), vec2(2.0, 1.0)))
    );
    assert_eq!(
        layout.element(ElementId(3)).map(|element| element.rect),
        Some(Rect::from_min_size(pos2(0.0, 1.0), vec2(2.0, 1.0)))
    );
    assert_eq!(
        layout.element(ElementId(2)).map(|element| element.rect),
        Some(Rect::from_min_size(pos2(3.0, 0.0), vec2(2.0, 2.0)))
    );
    assert!(
        layout
            .wires
            .iter()
            .any(|wire| wire.points == [pos2(2.0, 1.5), pos2(3.0, 1.5)])
    );
}
