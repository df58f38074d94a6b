//! Tests of the FBD view of networks.

use egui::{Rect, pos2, vec2};
use project_model::Edge;
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
    // The OR box stands right after c and d, the AND box a bend's length after it.
    let (or_id, or_name, or_rect) = &found[0];
    assert_eq!((or_id, or_name.as_str()), (&Some(ElementId(3)), "OR"));
    let rect_of = |id: u32| layout.element(ElementId(id)).map(|element| element.rect);
    let c = rect_of(4).unwrap_or(Rect::NOTHING);
    assert_eq!(c.right(), or_rect.left(), "c stands at its pin");
    assert_eq!(or_rect.height(), 2.0);
    let (and_id, and_name, and_rect) = &found[1];
    assert_eq!((and_id, and_name.as_str()), (&None, "AND"));
    assert_eq!(and_rect.left(), or_rect.right() + LEAD_CELLS);
    assert_eq!(and_rect.top(), 0.0);
    assert_eq!(and_rect.height(), 4.0);
    // a stands right at the AND box's first pin, not a column away.
    assert_eq!(rect_of(1).map(|rect| rect.right()), Some(and_rect.left()));
    // Boxes are as wide as their titles, far narrower than two cells.
    assert!(and_rect.width() < 1.0 && or_rect.width() < 1.0);
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
    let Some((assignment_rect, power)) = assignment else {
        panic!("no assignment");
    };
    assert_eq!(power, Power::After(ElementId(3)));
    assert_eq!(assignment_rect.left(), and_rect.right() + LEAD_CELLS);
    assert_eq!(layout.size, vec2(assignment_rect.right(), 4.0));
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
    let rect_of = |id: u32| {
        layout
            .element(ElementId(id))
            .map(|element| element.rect)
            .unwrap_or(Rect::NOTHING)
    };
    let timer = rect_of(2);
    assert_eq!(timer.min, pos2(rect_of(1).right(), 0.0));
    assert_eq!(timer.height(), 2.0);
    // The box is as wide as its instance name, the widest of its texts.
    assert_eq!(
        timer.width(),
        box_cells(
            "TON",
            "timer",
            ["IN", "PT"].into_iter(),
            ["Q"].into_iter(),
            0.0
        )
    );
    // Both operands stand right at their pins, each as wide as its text.
    assert_eq!(rect_of(1).min, pos2(timer.left() - rect_of(1).width(), 0.0));
    assert_eq!(
        rect_of(3),
        Rect::from_min_max(
            pos2(timer.left() - rect_of(3).width(), 1.0),
            pos2(timer.left(), 2.0)
        )
    );
    assert_eq!(
        rect_of(3).width(),
        operand_cells("T#5S", MIN_VARIABLE_CELLS)
    );
}

#[test]
fn a_long_operand_widens_its_cell_and_an_edge_is_marked_at_the_pin() {
    let long = "conveyor_infeed_photo_eye";
    let network = Network {
        rung: vec![
            FlowNode::Operand(Operand {
                id: ElementId(1),
                text: long.into(),
                edge: Edge::Rising,
                ..Operand::default()
            }),
            contact(2, "b", false),
        ],
        ..Network::default()
    };
    let layout = fbd_layout(&network, 0);
    let width = layout
        .element(ElementId(1))
        .map(|element| element.rect.width());
    assert_eq!(width, Some(operand_cells(long, MIN_VARIABLE_CELLS)));
    assert!(
        width
            > layout
                .element(ElementId(2))
                .map(|element| element.rect.width())
    );
    let Some(Shape::Box { inputs, .. }) = boxes(&layout)
        .first()
        .and_then(|(_, _, rect)| layout.elements.iter().find(|element| element.rect == *rect))
        .map(|element| &element.shape)
    else {
        panic!("no AND box");
    };
    assert_eq!(
        inputs.iter().map(|pin| pin.edge).collect::<Vec<_>>(),
        [Edge::Rising, Edge::None]
    );
    // The operand itself carries no edge letter; the pin does.
    assert!(matches!(
        layout.element(ElementId(1)).map(|element| &element.shape),
        Some(Shape::Variable {
            edge: Edge::None,
            ..
        })
    ));
}

#[test]
fn an_output_branch_ands_the_fan_out_with_its_operand_and_assigns_after_it() {
    // q1 := a; q2 := a AND b (an output branch with b in series).
    let network = Network {
        rung: vec![contact(1, "a", false)],
        outputs: vec![
            NetworkOutput::Coil(Coil {
                id: ElementId(2),
                variable: "q1".into(),
                ..Coil::default()
            }),
            NetworkOutput::Branch {
                id: ElementId(3),
                rung: vec![contact(4, "b", false)],
                outputs: vec![NetworkOutput::Coil(Coil {
                    id: ElementId(5),
                    variable: "q2".into(),
                    ..Coil::default()
                })],
            },
        ],
        ..Network::default()
    };
    let layout = fbd_layout(&network, 0);
    let rect_of = |id: u32| {
        layout
            .element(ElementId(id))
            .map(|element| element.rect)
            .unwrap_or(Rect::NOTHING)
    };
    let and = boxes(&layout)
        .into_iter()
        .find(|(_, name, _)| name == "AND")
        .map(|(_, _, rect)| rect)
        .unwrap_or(Rect::NOTHING);
    // The branch's AND box stands below q1, fed by the fan-out and by b, and q2 follows it.
    assert_eq!(rect_of(2).top(), 0.0);
    assert!(
        and.top() >= rect_of(2).bottom(),
        "{and:?} below {:?}",
        rect_of(2)
    );
    assert_eq!(rect_of(4).right(), and.left());
    assert_eq!(rect_of(5).left(), and.right() + LEAD_CELLS);
    assert!((layout.size.x - rect_of(5).right()).abs() < 1e-4);
    // Nothing overlaps.
    let placed: Vec<Rect> = layout.elements.iter().map(|element| element.rect).collect();
    for (index, first) in placed.iter().enumerate() {
        for second in &placed[index + 1..] {
            assert!(
                !first.intersects(*second) || first.intersect(*second).area() < 1e-4,
                "{first:?} overlaps {second:?}"
            );
        }
    }
}

#[test]
fn every_element_and_line_of_the_example_bodies_is_inside_its_network() {
    let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
    let mut checked = 0;
    for object in loaded.project.application.objects() {
        let project_model::Object::Pou(pou) = object else {
            continue;
        };
        let networks = match &pou.body {
            project_model::Body::Ld { networks } | project_model::Body::Fbd { networks } => {
                networks
            }
            _ => continue,
        };
        for (index, network) in networks.iter().enumerate() {
            for layout in [
                fbd_layout(network, index),
                crate::diagram::ld_layout(network, index),
            ] {
                checked += 1;
                let inside = |pos: Pos2| {
                    pos.x >= -0.01
                        && pos.x <= layout.size.x + 0.01
                        && pos.y >= -0.01
                        && pos.y <= layout.size.y + 0.01
                };
                for element in &layout.elements {
                    assert!(
                        inside(element.rect.min) && inside(element.rect.max),
                        "{} network {index}: {:?} at {:?} outside {:?}",
                        pou.name,
                        element.id,
                        element.rect,
                        layout.size
                    );
                }
                for wire in &layout.wires {
                    assert!(wire.points.iter().all(|point| inside(*point)), "{wire:?}");
                }
            }
        }
    }
    assert!(checked > 10);
}
