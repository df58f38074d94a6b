//! Tests of the LD layout: positions in cells of small rungs.

use egui::{Rect, pos2, vec2};
use project_model::{
    BlockCall, BlockInput, BlockOutput, Branch, Coil, ElementId, FlowNode, Network, NetworkOutput,
    Operand, Parallel,
};

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
        ..Coil::default()
    })
}

#[track_caller]
fn assert_at(layout: &NetworkLayout, id: u32, min: (f32, f32), size: (f32, f32)) {
    let element = layout
        .element(ElementId(id))
        .unwrap_or_else(|| panic!("element {id} is not placed"));
    assert_eq!(
        element.rect,
        Rect::from_min_size(pos2(min.0, min.1), vec2(size.0, size.1)),
        "element {id}"
    );
}

#[test]
fn a_series_runs_left_to_right_and_the_coil_sits_before_the_right_rail() {
    let network = Network {
        rung: vec![contact(1, "a"), contact(2, "b")],
        outputs: vec![coil(3, "q")],
        ..Network::default()
    };
    let layout = ld_layout(&network, 0);
    assert_eq!(layout.size, vec2(4.0, 1.0));
    assert_at(&layout, 1, (0.0, 0.0), (1.0, 1.0));
    assert_at(&layout, 2, (1.0, 0.0), (1.0, 1.0));
    assert_at(&layout, 3, (3.0, 0.0), (1.0, 1.0));
    assert_eq!(
        layout.element(ElementId(2)).map(|element| element.power_in),
        Some(Power::After(ElementId(1)))
    );
    // The line from the rung's end to the coil carries the last contact's power.
    assert!(
        layout
            .wires
            .iter()
            .any(|wire| wire.points == [pos2(2.0, 0.5), pos2(3.0, 0.5)]
                && wire.power == Power::After(ElementId(2)))
    );
}

#[test]
fn parallel_branches_stack_between_rails_and_short_branches_are_extended() {
    let network = Network {
        rung: vec![
            contact(1, "a"),
            FlowNode::Parallel(Parallel {
                id: ElementId(2),
                branches: vec![
                    Branch {
                        rung: vec![contact(3, "b")],
                    },
                    Branch {
                        rung: vec![contact(4, "c"), contact(5, "d")],
                    },
                ],
            }),
        ],
        outputs: vec![coil(6, "q")],
        ..Network::default()
    };
    let layout = ld_layout(&network, 0);
    assert_eq!(layout.size, vec2(5.0, 2.0));
    assert_at(&layout, 2, (1.0, 0.0), (2.0, 2.0));
    assert_at(&layout, 3, (1.0, 0.0), (1.0, 1.0));
    assert_at(&layout, 4, (1.0, 1.0), (1.0, 1.0));
    assert_at(&layout, 5, (2.0, 1.0), (1.0, 1.0));
    assert_at(&layout, 6, (4.0, 0.0), (1.0, 1.0));
    let wire = |from: (f32, f32), to: (f32, f32)| {
        layout
            .wires
            .iter()
            .find(|wire| wire.points == [pos2(from.0, from.1), pos2(to.0, to.1)])
            .map(|wire| wire.power)
    };
    assert_eq!(
        wire((2.0, 0.5), (3.0, 0.5)),
        Some(Power::After(ElementId(3)))
    );
    assert_eq!(
        wire((1.0, 0.5), (1.0, 1.5)),
        Some(Power::After(ElementId(1)))
    );
    assert_eq!(
        wire((3.0, 0.5), (3.0, 1.5)),
        Some(Power::After(ElementId(2)))
    );
    // The branch's contact is found where it is drawn, before the group around it.
    assert_eq!(
        layout
            .element_at(pos2(1.5, 1.5))
            .and_then(|element| element.id),
        Some(ElementId(4))
    );
}

#[test]
fn a_box_has_its_operands_left_of_its_pins_and_several_coils_fan_out() {
    let network = Network {
        rung: vec![
            contact(1, "start"),
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
                        source: vec![contact(3, "T#5S")],
                        ..BlockInput::default()
                    },
                ],
                outputs: vec![
                    BlockOutput {
                        pin: "Q".into(),
                        ..BlockOutput::default()
                    },
                    BlockOutput {
                        pin: "ET".into(),
                        assign: "elapsed".into(),
                        ..BlockOutput::default()
                    },
                ],
            }),
        ],
        outputs: vec![coil(4, "lamp"), coil(5, "horn")],
        ..Network::default()
    };
    let layout = ld_layout(&network, 0);
    assert_at(&layout, 2, (2.0, 0.0), (1.5, 2.0));
    assert_at(&layout, 3, (1.0, 1.0), (1.0, 1.0));
    assert!(matches!(
        &layout.element(ElementId(3)).map(|element| &element.shape),
        Some(Shape::Variable { text, .. }) if text == "T#5S"
    ));
    let Some(Shape::Box {
        inputs, outputs, ..
    }) = layout.element(ElementId(2)).map(|element| &element.shape)
    else {
        panic!("the box is not a box");
    };
    assert_eq!(
        inputs
            .iter()
            .map(|pin| (pin.name.as_str(), pin.row))
            .collect::<Vec<_>>(),
        [("IN", 0.0), ("PT", 1.0)]
    );
    assert_eq!(outputs[1].row, 1.0);
    // The elapsed time's variable sits right of the box; the coils stack at the right.
    assert!(
        layout
            .elements
            .iter()
            .any(|element| element.rect.min == pos2(3.5, 1.0)
                && matches!(&element.shape, Shape::Variable { text, .. } if text == "elapsed"))
    );
    assert_eq!(layout.size, vec2(6.5, 2.0));
    assert_at(&layout, 4, (5.5, 0.0), (1.0, 1.0));
    assert_at(&layout, 5, (5.5, 1.0), (1.0, 1.0));
}

#[test]
fn an_empty_network_offers_its_rung_and_outputs_for_insertion() {
    let layout = ld_layout(&Network::default(), 3);
    assert_eq!(layout.size, vec2(4.0, 1.0));
    let targets: Vec<_> = layout
        .insert_points
        .iter()
        .map(|point| point.target)
        .collect();
    assert_eq!(
        targets,
        [
            InsertTarget::Series {
                anchor: Anchor::Network(3),
                side: Side::After
            },
            InsertTarget::Output {
                anchor: Anchor::Network(3)
            }
        ]
    );
}

#[test]
fn a_long_operand_widens_its_contact_and_a_long_coil_stays_at_the_right_rail() {
    let long = "conveyor_infeed_photo_eye";
    let network = Network {
        rung: vec![contact(1, long), contact(2, "b")],
        outputs: vec![coil(3, "belt_running_and_ready_to_feed")],
        ..Network::default()
    };
    let layout = ld_layout(&network, 0);
    let rect_of = |id: u32| {
        layout
            .element(ElementId(id))
            .map(|element| element.rect)
            .unwrap_or(Rect::NOTHING)
    };
    let wide = operand_cells(long, 1.0);
    assert!(wide > 1.0);
    assert_eq!(
        rect_of(1),
        Rect::from_min_size(pos2(0.0, 0.0), vec2(wide, 1.0))
    );
    assert_eq!(rect_of(2).left(), wide);
    // The coil is as wide as its variable and ends at the right rail.
    assert!(rect_of(3).width() > 1.0);
    assert_eq!(rect_of(3).right(), layout.size.x);
}
