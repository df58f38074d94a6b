//! The automatic layout of an SFC sequence: a pure function from the chart's structure to
//! positions, in points at zoom 1.
//!
//! The main sequence runs top to bottom on one centre line; the branches of an alternative or
//! parallel branch stand side by side to the right of the first, which continues the centre
//! line. Every node reserves room to the right of its centre for what is drawn beside it (a
//! step's action associations, a transition's condition, a jump's target), so branches never
//! overlap each other's texts.

use egui::{Pos2, Rect, Vec2, pos2, vec2};
use project_model::{ElementId, SfcNode};

use crate::diagram::measure::operand_width_px;

/// A step's box: its height, its least width, and the room around its name.
pub(crate) const STEP_HEIGHT_PX: f32 = 32.0;
const STEP_MIN_WIDTH_PX: f32 = 80.0;
const STEP_TEXT_PADDING_PX: f32 = 12.0;
/// The room a transition takes on the line, and the half width of its bar.
pub(crate) const TRANSITION_HEIGHT_PX: f32 = 26.0;
pub(crate) const TRANSITION_HALF_WIDTH_PX: f32 = 14.0;
/// The room a jump's arrow takes on the line.
const JUMP_HEIGHT_PX: f32 = 26.0;
/// The gap between a node's text and the line, and between side-by-side things.
pub(crate) const TEXT_GAP_PX: f32 = 8.0;
/// The length of the line between two nodes of a sequence.
const CONNECTOR_PX: f32 = 14.0;
/// The room between two branches.
const BRANCH_GAP_PX: f32 = 28.0;
/// The distance between the two lines of a parallel branch's double line.
pub(crate) const DOUBLE_LINE_GAP_PX: f32 = 4.0;
/// How far a branch line reaches beyond the outer branches.
const BRANCH_OVERHANG_PX: f32 = 10.0;
/// One row of a step's action association box.
pub(crate) const ACTION_ROW_PX: f32 = 18.0;
/// The width of the qualifier column of the action association box.
pub(crate) const QUALIFIER_COLUMN_PX: f32 = 30.0;
/// The padding of the action and time columns.
const COLUMN_PADDING_PX: f32 = 8.0;
/// The margin around the whole chart.
const MARGIN_PX: f32 = 24.0;

/// What a placed node is drawn as.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SfcShape {
    /// A step's box; the initial step has a double border.
    Step {
        /// Whether it is the chart's initial step.
        initial: bool,
    },
    /// A macro step's box, with a double frame left and right.
    Macro,
    /// A transition's bar, its condition to the right.
    Transition,
    /// A jump's arrow, its target's name to the right.
    Jump,
    /// The opening line of an alternative branch (single lines).
    Alternative,
    /// The opening double line of a parallel branch.
    Parallel,
}

/// The action association box beside a step: its columns' edges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActionBox {
    /// The whole box.
    pub rect: Rect,
    /// Where the action column begins.
    pub action_x: f32,
    /// Where the time column begins.
    pub time_x: f32,
}

/// One placed node.
#[derive(Clone, Debug, PartialEq)]
pub struct SfcPlaced {
    /// The node's id.
    pub id: ElementId,
    /// What it is drawn as.
    pub shape: SfcShape,
    /// Its own figure (a box, a bar, an arrow, a branch's opening line): what a click hits.
    pub rect: Rect,
    /// Where its text beside it begins (condition, jump target), on the figure's middle.
    pub text_pos: Pos2,
    /// A step's action associations, if it has any.
    pub actions: Option<ActionBox>,
    /// The branch's closing line, for alternative and parallel branches that join again.
    pub closing: Option<Rect>,
}

/// A line between placed nodes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SfcLine {
    /// Where it starts.
    pub from: Pos2,
    /// Where it ends.
    pub to: Pos2,
    /// Whether it is drawn double (a parallel branch's opening and closing lines).
    pub double: bool,
}

/// The layout of one sequence (the main one, or a macro step's body).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SfcLayout {
    /// Every node, in the order of the sequence, outer nodes before their branches' nodes.
    pub elements: Vec<SfcPlaced>,
    /// The connecting lines.
    pub lines: Vec<SfcLine>,
    /// The size of the whole drawing, margins included.
    pub size: Vec2,
}

impl SfcLayout {
    /// The placed node `id`.
    pub fn element(&self, id: ElementId) -> Option<&SfcPlaced> {
        self.elements.iter().find(|placed| placed.id == id)
    }

    /// The node whose figure (or action box) contains `pos`, the innermost first.
    pub fn hit(&self, pos: Pos2) -> Option<ElementId> {
        self.elements
            .iter()
            .rev()
            .find(|placed| {
                placed.rect.expand(3.0).contains(pos)
                    || placed
                        .actions
                        .is_some_and(|actions| actions.rect.contains(pos))
                    || placed
                        .closing
                        .is_some_and(|closing| closing.expand(3.0).contains(pos))
            })
            .map(|placed| placed.id)
    }
}

/// Lays out `nodes` top to bottom; `main` says whether this is the chart's main sequence,
/// whose first step is the initial one.
pub fn sfc_layout(nodes: &[SfcNode], main: bool) -> SfcLayout {
    let extents = sequence_extents(nodes);
    let mut layout = SfcLayout::default();
    let centre_x = MARGIN_PX + extents.left;
    let bottom = place_sequence(nodes, centre_x, MARGIN_PX, main, &mut layout);
    layout.size = vec2(centre_x + extents.right + MARGIN_PX, bottom + MARGIN_PX);
    layout
}

/// How far a node or sequence reaches left and right of its centre line.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Extents {
    left: f32,
    right: f32,
}

impl Extents {
    fn union(self, other: Self) -> Self {
        Self {
            left: self.left.max(other.left),
            right: self.right.max(other.right),
        }
    }
}

/// The width of a step's (or macro step's) box for its name.
pub(crate) fn step_width_px(name: &str) -> f32 {
    (operand_width_px(name) + 2.0 * STEP_TEXT_PADDING_PX).max(STEP_MIN_WIDTH_PX)
}

/// The action association box of a step, placed with its left edge at `left` and its top at
/// `top`, or none without associations.
fn action_box(step: &project_model::Step, left: f32, top: f32) -> Option<ActionBox> {
    if step.actions.is_empty() {
        return None;
    }
    let action_width = step
        .actions
        .iter()
        .map(|association| operand_width_px(&association.action))
        .fold(0.0, f32::max)
        + 2.0 * COLUMN_PADDING_PX;
    let time_width = step
        .actions
        .iter()
        .filter_map(|association| association.duration.as_deref())
        .map(operand_width_px)
        .fold(0.0, f32::max);
    let time_width = if time_width > 0.0 {
        time_width + 2.0 * COLUMN_PADDING_PX
    } else {
        0.0
    };
    let rows = step.actions.len() as f32;
    Some(ActionBox {
        rect: Rect::from_min_size(
            pos2(left, top),
            vec2(
                QUALIFIER_COLUMN_PX + action_width + time_width,
                (rows * ACTION_ROW_PX).max(STEP_HEIGHT_PX),
            ),
        ),
        action_x: left + QUALIFIER_COLUMN_PX,
        time_x: left + QUALIFIER_COLUMN_PX + action_width,
    })
}

fn node_extents(node: &SfcNode) -> Extents {
    match node {
        SfcNode::Step(step) => {
            let half = step_width_px(&step.name) / 2.0;
            let actions = action_box(step, 0.0, 0.0)
                .map_or(0.0, |actions| TEXT_GAP_PX + actions.rect.width());
            Extents {
                left: half,
                right: half + actions,
            }
        }
        SfcNode::Macro(macro_step) => {
            let half = step_width_px(&macro_step.name) / 2.0;
            Extents {
                left: half,
                right: half,
            }
        }
        SfcNode::Transition(transition) => Extents {
            left: TRANSITION_HALF_WIDTH_PX,
            right: TRANSITION_HALF_WIDTH_PX + TEXT_GAP_PX + operand_width_px(&transition.condition),
        },
        SfcNode::Jump(jump) => Extents {
            left: TRANSITION_HALF_WIDTH_PX,
            right: TRANSITION_HALF_WIDTH_PX + TEXT_GAP_PX + operand_width_px(&jump.target),
        },
        SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
            let offsets = branch_offsets(&branches.branches);
            let first = offsets.first().map_or(Extents::default(), |(_, e)| *e);
            let last = offsets.last().map_or(0.0, |(offset, e)| offset + e.right);
            Extents {
                left: first.left.max(BRANCH_OVERHANG_PX),
                right: last.max(BRANCH_OVERHANG_PX),
            }
        }
    }
}

fn sequence_extents(nodes: &[SfcNode]) -> Extents {
    nodes
        .iter()
        .map(node_extents)
        .fold(Extents::default(), Extents::union)
}

/// Each branch's centre, as an offset from the first branch's, with its extents.
fn branch_offsets(branches: &[project_model::SfcSequence]) -> Vec<(f32, Extents)> {
    let mut offsets = Vec::with_capacity(branches.len());
    let mut previous: Option<(f32, Extents)> = None;
    for branch in branches {
        let extents = sequence_extents(&branch.nodes);
        let offset = match previous {
            None => 0.0,
            Some((offset, before)) => offset + before.right + BRANCH_GAP_PX + extents.left,
        };
        offsets.push((offset, extents));
        previous = Some((offset, extents));
    }
    offsets
}

/// Places `nodes` on the centre line `centre_x` from `top`; returns the bottom of the last.
fn place_sequence(
    nodes: &[SfcNode],
    centre_x: f32,
    top: f32,
    main: bool,
    layout: &mut SfcLayout,
) -> f32 {
    let mut y = top;
    for (index, node) in nodes.iter().enumerate() {
        if index > 0 {
            layout.lines.push(SfcLine {
                from: pos2(centre_x, y),
                to: pos2(centre_x, y + CONNECTOR_PX),
                double: false,
            });
            y += CONNECTOR_PX;
        }
        y = place_node(node, centre_x, y, main && index == 0, layout);
    }
    y
}

/// Places one node with its top at `top`; returns its bottom.
fn place_node(
    node: &SfcNode,
    centre_x: f32,
    top: f32,
    initial: bool,
    layout: &mut SfcLayout,
) -> f32 {
    let id = node.id();
    match node {
        SfcNode::Step(step) => {
            let width = step_width_px(&step.name);
            let rect = Rect::from_min_size(
                pos2(centre_x - width / 2.0, top),
                vec2(width, STEP_HEIGHT_PX),
            );
            let actions = action_box(step, rect.right() + TEXT_GAP_PX, top);
            let bottom = actions.map_or(rect.bottom(), |actions| actions.rect.bottom());
            layout.elements.push(SfcPlaced {
                id,
                shape: SfcShape::Step { initial },
                rect,
                text_pos: rect.center(),
                actions,
                closing: None,
            });
            if bottom > rect.bottom() {
                layout.lines.push(SfcLine {
                    from: pos2(centre_x, rect.bottom()),
                    to: pos2(centre_x, bottom),
                    double: false,
                });
            }
            bottom
        }
        SfcNode::Macro(macro_step) => {
            let width = step_width_px(&macro_step.name);
            let rect = Rect::from_min_size(
                pos2(centre_x - width / 2.0, top),
                vec2(width, STEP_HEIGHT_PX),
            );
            layout.elements.push(SfcPlaced {
                id,
                shape: SfcShape::Macro,
                rect,
                text_pos: rect.center(),
                actions: None,
                closing: None,
            });
            rect.bottom()
        }
        SfcNode::Transition(_) | SfcNode::Jump(_) => {
            let (shape, height) = if matches!(node, SfcNode::Transition(_)) {
                (SfcShape::Transition, TRANSITION_HEIGHT_PX)
            } else {
                (SfcShape::Jump, JUMP_HEIGHT_PX)
            };
            let rect = Rect::from_min_size(
                pos2(centre_x - TRANSITION_HALF_WIDTH_PX, top),
                vec2(2.0 * TRANSITION_HALF_WIDTH_PX, height),
            );
            layout.elements.push(SfcPlaced {
                id,
                shape,
                rect,
                text_pos: pos2(rect.right() + TEXT_GAP_PX, rect.center().y),
                actions: None,
                closing: None,
            });
            rect.bottom()
        }
        SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
            let double = matches!(node, SfcNode::Parallel(_));
            place_branches(id, &branches.branches, double, centre_x, top, layout)
        }
    }
}

fn place_branches(
    id: ElementId,
    branches: &[project_model::SfcSequence],
    double: bool,
    centre_x: f32,
    top: f32,
    layout: &mut SfcLayout,
) -> f32 {
    let offsets = branch_offsets(branches);
    let last_offset = offsets.last().map_or(0.0, |(offset, _)| *offset);
    let thickness = if double { DOUBLE_LINE_GAP_PX } else { 0.0 };
    let (left, right) = if double {
        (
            centre_x - BRANCH_OVERHANG_PX,
            centre_x + last_offset + BRANCH_OVERHANG_PX,
        )
    } else {
        (centre_x, centre_x + last_offset)
    };
    let opening = Rect::from_min_max(pos2(left, top), pos2(right, top + thickness));
    let placed_index = layout.elements.len();
    layout.elements.push(SfcPlaced {
        id,
        shape: if double {
            SfcShape::Parallel
        } else {
            SfcShape::Alternative
        },
        rect: opening,
        text_pos: opening.left_center(),
        actions: None,
        closing: None,
    });
    layout.lines.push(SfcLine {
        from: pos2(left, top),
        to: pos2(right, top),
        double,
    });
    let branches_top = top + thickness + CONNECTOR_PX;
    let mut bottoms = Vec::with_capacity(branches.len());
    for (branch, (offset, _)) in branches.iter().zip(&offsets) {
        let x = centre_x + offset;
        layout.lines.push(SfcLine {
            from: pos2(x, top + thickness),
            to: pos2(x, branches_top),
            double: false,
        });
        let bottom = place_sequence(&branch.nodes, x, branches_top, false, layout);
        let joins = !matches!(branch.nodes.last(), Some(SfcNode::Jump(_)));
        bottoms.push((x, bottom, joins));
    }
    let lowest = bottoms
        .iter()
        .map(|(_, bottom, _)| *bottom)
        .fold(branches_top, f32::max);
    let joining: Vec<&(f32, f32, bool)> = bottoms.iter().filter(|(_, _, joins)| *joins).collect();
    if joining.is_empty() {
        return lowest;
    }
    let closing_y = lowest + CONNECTOR_PX;
    for (x, bottom, _) in &joining {
        layout.lines.push(SfcLine {
            from: pos2(*x, *bottom),
            to: pos2(*x, closing_y),
            double: false,
        });
    }
    let rightmost = joining.iter().map(|(x, _, _)| *x).fold(centre_x, f32::max);
    let (close_left, close_right) = if double {
        (
            centre_x - BRANCH_OVERHANG_PX,
            rightmost + BRANCH_OVERHANG_PX,
        )
    } else {
        (centre_x, rightmost)
    };
    layout.lines.push(SfcLine {
        from: pos2(close_left, closing_y),
        to: pos2(close_right, closing_y),
        double,
    });
    let closing = Rect::from_min_max(
        pos2(close_left, closing_y),
        pos2(close_right, closing_y + thickness),
    );
    layout.elements[placed_index].closing = Some(closing);
    closing.bottom()
}

#[cfg(test)]
#[path = "layout_tests.rs"]
mod tests;
