//! Tests of the SFC layout: nothing overlaps, branches stand side by side, the main line is
//! straight.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use project_model::sfc_edit::{
    add_association, find_node, insert_alternative_branch, insert_jump_after,
    insert_parallel_branch, insert_step_transition_after,
};
use project_model::{ActionAssociation, ActionQualifier, ElementId, SfcChart, SfcNode};

use super::*;

/// `Init, A[T2 | T11 J12], P6[Step1 | Step2 T9 Step3], T5, J3`, with an action on Step1.
fn branched_chart() -> SfcChart {
    let chart = insert_step_transition_after(&SfcChart::new_body(), ElementId(2)).unwrap();
    let chart = insert_parallel_branch(&chart, &[ElementId(4)]).unwrap();
    let chart = insert_step_transition_after(&chart, ElementId(7)).unwrap();
    let chart = insert_alternative_branch(&chart, &[ElementId(2)]).unwrap();
    let chart = insert_jump_after(&chart, ElementId(11), "Init").unwrap();
    add_association(
        &chart,
        ElementId(4),
        ActionAssociation {
            action: "FillTank".into(),
            qualifier: ActionQualifier::L,
            duration: Some("T#10s".into()),
            indicator: None,
        },
    )
    .unwrap()
}

/// Every figure (boxes, bars, arrows, action boxes, and a condition's text as wide as it is
/// measured), for the overlap check.
fn figures(chart: &SfcChart, layout: &SfcLayout) -> Vec<(ElementId, Rect)> {
    let mut figures = Vec::new();
    for placed in &layout.elements {
        match placed.shape {
            SfcShape::Alternative | SfcShape::Parallel => continue,
            SfcShape::Transition | SfcShape::Jump => {
                let text = match find_node(chart, placed.id) {
                    Some(SfcNode::Transition(t)) => t.condition.clone(),
                    Some(SfcNode::Jump(j)) => j.target.clone(),
                    _ => String::new(),
                };
                let width = operand_width_px(&text);
                figures.push((
                    placed.id,
                    placed
                        .rect
                        .union(Rect::from_min_size(placed.text_pos, vec2(width, 1.0))),
                ));
            }
            _ => figures.push((placed.id, placed.rect)),
        }
        if let Some(actions) = placed.actions {
            figures.push((placed.id, actions.rect));
        }
    }
    figures
}

#[test]
fn no_two_figures_overlap() {
    let chart = branched_chart();
    let layout = sfc_layout(&chart.sequence, true);
    let figures = figures(&chart, &layout);
    for (i, (a_id, a)) in figures.iter().enumerate() {
        for (b_id, b) in &figures[i + 1..] {
            if a_id != b_id {
                assert!(
                    !a.shrink(0.5).intersects(b.shrink(0.5)),
                    "{a_id:?} {a:?} overlaps {b_id:?} {b:?}"
                );
            }
        }
    }
    for (_, rect) in &figures {
        assert!(rect.max.x <= layout.size.x && rect.max.y <= layout.size.y);
    }
}

#[test]
fn branches_stand_side_by_side_and_the_main_line_stays_straight() {
    let chart = branched_chart();
    let layout = sfc_layout(&chart.sequence, true);
    let centre = |id: u32| layout.element(ElementId(id)).unwrap().rect.center();
    // The parallel branch: Step1 on the main line, Step2 and Step3 to its right.
    assert_eq!(centre(4).x, centre(1).x);
    assert!(centre(7).x > centre(4).x);
    assert_eq!(centre(7).x, centre(8).x);
    assert!(centre(8).y > centre(7).y);
    // Step2's branch stays right of Step1's action box.
    let actions = layout.element(ElementId(4)).unwrap().actions.unwrap();
    assert!(layout.element(ElementId(7)).unwrap().rect.left() > actions.rect.right());
    // The alternative's right branch (transition 11 and the jump) is right of transition 2's
    // condition.
    assert!(centre(11).x > centre(2).x);
    assert_eq!(centre(11).y, centre(2).y);
    // The last transition and the jump close the main line.
    assert_eq!(centre(5).x, centre(1).x);
    assert!(centre(3).y > centre(5).y);
}

#[test]
fn the_initial_step_is_marked_only_in_the_main_sequence_and_branch_lines_have_their_kind() {
    let chart = branched_chart();
    let layout = sfc_layout(&chart.sequence, true);
    assert_eq!(
        layout.element(ElementId(1)).unwrap().shape,
        SfcShape::Step { initial: true }
    );
    assert_eq!(
        layout.element(ElementId(4)).unwrap().shape,
        SfcShape::Step { initial: false }
    );
    let parallel = layout.element(ElementId(6)).unwrap();
    assert_eq!(parallel.shape, SfcShape::Parallel);
    assert!(parallel.closing.is_some());
    let alternative = layout.element(ElementId(10)).unwrap();
    assert_eq!(alternative.shape, SfcShape::Alternative);
    assert!(layout.lines.iter().any(|line| line.double));
    let body = sfc_layout(&chart.sequence[2..3], false);
    assert!(
        body.elements
            .iter()
            .all(|placed| placed.shape != SfcShape::Step { initial: true })
    );
}

#[test]
fn a_click_hits_the_innermost_figure() {
    let chart = branched_chart();
    let layout = sfc_layout(&chart.sequence, true);
    let step = layout.element(ElementId(7)).unwrap().rect;
    assert_eq!(layout.hit(step.center()), Some(ElementId(7)));
    let actions = layout.element(ElementId(4)).unwrap().actions.unwrap().rect;
    assert_eq!(layout.hit(actions.center()), Some(ElementId(4)));
    assert_eq!(layout.hit(pos2(-50.0, -50.0)), None);
}
