//! Painting the laid-out chart: lines, steps (the initial one with a double border), macro
//! steps (a double frame left and right), transitions with their conditions, jumps, branch
//! lines, action association boxes, the selection, findings and the online state.

use std::collections::HashMap;

use egui::{
    Align2, Color32, FontId, Painter, Pos2, Rect, Response, Shape, Stroke, StrokeKind, Ui, pos2,
    vec2,
};
use project_model::{ElementId, SfcNode};

use super::editor::SfcEditor;
use super::layout::{ActionBox, DOUBLE_LINE_GAP_PX, SfcPlaced, SfcShape, TRANSITION_HALF_WIDTH_PX};
use crate::diagram::measure::{OPERAND_FONT_PX, shortened};
use crate::{EditorPalette, Severity};

/// The font size of markers, times and priorities, in points at zoom 1.
const SMALL_FONT_PX: f32 = 9.0;
/// The size of the marker triangles (step action, transition object), in points at zoom 1.
const MARKER_PX: f32 = 6.0;

/// Every node of `nodes` by id, nested ones included.
fn nodes_by_id<'a>(nodes: &'a [SfcNode], map: &mut HashMap<ElementId, &'a SfcNode>) {
    for node in nodes {
        map.insert(node.id(), node);
        match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                for branch in &branches.branches {
                    nodes_by_id(&branch.nodes, map);
                }
            }
            SfcNode::Macro(macro_step) => nodes_by_id(&macro_step.body, map),
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
}

/// What one paint needs: where, how big, in which colours.
struct Pen<'a> {
    painter: &'a Painter,
    origin: Pos2,
    zoom: f32,
    line: Color32,
    text: Color32,
    palette: EditorPalette,
}

impl Pen<'_> {
    fn pos(&self, pos: Pos2) -> Pos2 {
        self.origin + pos.to_vec2() * self.zoom
    }

    fn rect(&self, rect: Rect) -> Rect {
        Rect::from_min_max(self.pos(rect.min), self.pos(rect.max))
    }

    fn stroke(&self, width: f32, color: Color32) -> Stroke {
        Stroke::new(width * self.zoom, color)
    }

    fn segment(&self, from: Pos2, to: Pos2, stroke: Stroke) {
        self.painter
            .line_segment([self.pos(from), self.pos(to)], stroke);
    }

    fn text(&self, pos: Pos2, align: Align2, text: &str, size_px: f32, color: Color32) {
        self.painter.text(
            self.pos(pos),
            align,
            text,
            FontId::monospace(size_px * self.zoom),
            color,
        );
    }

    fn triangle(&self, points: [Pos2; 3], color: Color32) {
        self.painter.add(Shape::convex_polygon(
            points.iter().map(|point| self.pos(*point)).collect(),
            color,
            Stroke::NONE,
        ));
    }
}

impl SfcEditor {
    pub(super) fn paint_ui(&self, ui: &Ui, response: &Response) {
        let palette = EditorPalette::of(ui);
        let visuals = ui.visuals();
        let pen = Pen {
            painter: ui.painter(),
            origin: self.last_origin,
            zoom: self.zoom,
            line: visuals.widgets.noninteractive.fg_stroke.color,
            text: visuals.text_color(),
            palette,
        };
        let mut nodes = HashMap::new();
        nodes_by_id(&self.chart.sequence, &mut nodes);
        for line in &self.layout.lines {
            let stroke = pen.stroke(1.5, pen.line);
            pen.segment(line.from, line.to, stroke);
            if line.double {
                let below = vec2(0.0, DOUBLE_LINE_GAP_PX);
                pen.segment(line.from + below, line.to + below, stroke);
            }
        }
        for placed in &self.layout.elements {
            if self.selection.contains(&placed.id) {
                let mut area = placed.rect.expand(4.0);
                if let Some(closing) = placed.closing {
                    area = area.union(closing.expand(4.0));
                }
                pen.painter
                    .rect_filled(pen.rect(area), 2.0, pen.palette.diagram_selection);
            }
            let Some(node) = nodes.get(&placed.id) else {
                continue;
            };
            self.paint_node(&pen, placed, node);
            if let Some(severity) = self.worst_finding(placed.id) {
                let color = match severity {
                    Severity::Error => pen.palette.error,
                    Severity::Warning => pen.palette.warning,
                    _ => pen.palette.info,
                };
                pen.painter.rect_stroke(
                    pen.rect(placed.rect.expand(3.0)),
                    2.0,
                    pen.stroke(2.0, color),
                    StrokeKind::Outside,
                );
            }
        }
        for placed in &self.layout.elements {
            if !self.debug_marks.is_empty() {
                crate::body_debug_marks::paint_element_marks(
                    pen.painter,
                    &self.debug_marks,
                    0,
                    placed.id,
                    pen.rect(placed.rect),
                    5.0 * self.zoom,
                );
            }
        }
        self.drop_target_ui(&pen, response);
        self.hover_ui(response, &nodes);
    }

    /// While a toolbox item is dragged over a node, the node it would insert at is framed in
    /// the insertion colour, as CODESYS turns its insertion marks green.
    fn drop_target_ui(&self, pen: &Pen<'_>, response: &Response) {
        if response
            .dnd_hover_payload::<super::commands::SfcCommand>()
            .is_none()
        {
            return;
        }
        let Some(pointer) = response.hover_pos() else {
            return;
        };
        let pos = Pos2::ZERO + (pointer - self.last_origin) / self.zoom;
        if let Some(placed) = self.layout.hit(pos).and_then(|id| self.layout.element(id)) {
            pen.painter.rect_stroke(
                pen.rect(placed.rect.expand(5.0)),
                3.0,
                pen.stroke(2.0, pen.palette.insert_point),
                StrokeKind::Outside,
            );
        }
    }

    /// The most severe finding on `id`.
    fn worst_finding(&self, id: ElementId) -> Option<Severity> {
        let rank = |severity: Severity| match severity {
            Severity::Error => 0,
            Severity::Warning => 1,
            _ => 2,
        };
        let finding = self
            .diagnostics
            .iter()
            .filter(|diagnostic| diagnostic.element == Some(id))
            .map(|diagnostic| diagnostic.severity)
            .min_by_key(|severity| rank(*severity));
        let over_time = self
            .online
            .as_ref()
            .and_then(|online| online.steps.get(&id))
            .is_some_and(|state| state.over_max_time);
        if over_time {
            Some(Severity::Error)
        } else {
            finding
        }
    }

    /// The tooltip of what the pointer is over: its findings, a step over its maximum time, a
    /// shortened text in full.
    fn hover_ui(&self, response: &Response, nodes: &HashMap<ElementId, &SfcNode>) {
        let Some(pointer) = response.hover_pos() else {
            return;
        };
        let pos = Pos2::ZERO + (pointer - self.last_origin) / self.zoom;
        let Some(id) = self.layout.hit(pos) else {
            return;
        };
        let mut lines: Vec<String> = self
            .diagnostics
            .iter()
            .filter(|diagnostic| diagnostic.element == Some(id))
            .map(|diagnostic| format!("{}: {}", diagnostic.code, diagnostic.message))
            .collect();
        if self
            .online
            .as_ref()
            .and_then(|online| online.steps.get(&id))
            .is_some_and(|state| state.over_max_time)
        {
            lines.push(self.texts.over_max_time.clone());
        }
        if let Some(SfcNode::Transition(transition)) = nodes.get(&id)
            && shortened(&transition.condition).1
        {
            lines.push(transition.condition.clone());
        }
        if !lines.is_empty() {
            response.clone().on_hover_text(lines.join("\n"));
        }
    }

    fn paint_node(&self, pen: &Pen<'_>, placed: &SfcPlaced, node: &SfcNode) {
        let online = self.online.as_ref();
        match (placed.shape, node) {
            (SfcShape::Step { initial }, SfcNode::Step(step)) => {
                let state = online.and_then(|online| online.steps.get(&step.id));
                let rect = pen.rect(placed.rect);
                if state.is_some_and(|state| state.active) {
                    pen.painter.rect_filled(rect, 0.0, pen.palette.active_step);
                }
                let stroke = pen.stroke(1.5, pen.line);
                pen.painter
                    .rect_stroke(rect, 0.0, stroke, StrokeKind::Inside);
                if initial {
                    pen.painter.rect_stroke(
                        pen.rect(placed.rect.shrink(3.0)),
                        0.0,
                        stroke,
                        StrokeKind::Inside,
                    );
                }
                let text = if state.is_some_and(|state| state.active) {
                    pen.palette.active_step_text
                } else {
                    pen.text
                };
                let name_pos = if state.is_some() {
                    placed.rect.center() - vec2(0.0, 5.0)
                } else {
                    placed.rect.center()
                };
                pen.text(
                    name_pos,
                    Align2::CENTER_CENTER,
                    &shortened(&step.name).0,
                    OPERAND_FONT_PX,
                    text,
                );
                if let Some(state) = state {
                    pen.text(
                        placed.rect.center_bottom() - vec2(0.0, 3.0),
                        Align2::CENTER_BOTTOM,
                        &time_literal(state.elapsed),
                        SMALL_FONT_PX,
                        text,
                    );
                }
                self.paint_step_markers(pen, placed.rect, step);
                if let Some(actions) = placed.actions {
                    self.paint_actions(pen, placed.rect, actions, step);
                }
            }
            (SfcShape::Macro, SfcNode::Macro(macro_step)) => {
                let active = online
                    .and_then(|online| online.steps.get(&macro_step.id))
                    .is_some_and(|state| state.active);
                let rect = pen.rect(placed.rect);
                if active {
                    pen.painter.rect_filled(rect, 0.0, pen.palette.active_step);
                }
                let stroke = pen.stroke(1.5, pen.line);
                pen.painter
                    .rect_stroke(rect, 0.0, stroke, StrokeKind::Inside);
                for x in [placed.rect.left() + 5.0, placed.rect.right() - 5.0] {
                    pen.segment(
                        pos2(x, placed.rect.top()),
                        pos2(x, placed.rect.bottom()),
                        stroke,
                    );
                }
                pen.text(
                    placed.rect.center(),
                    Align2::CENTER_CENTER,
                    &shortened(&macro_step.name).0,
                    OPERAND_FONT_PX,
                    if active {
                        pen.palette.active_step_text
                    } else {
                        pen.text
                    },
                );
            }
            (SfcShape::Transition, SfcNode::Transition(transition)) => {
                let value = online.and_then(|online| online.transitions.get(&transition.id));
                let color = if value == Some(&true) {
                    pen.palette.power_on
                } else {
                    pen.line
                };
                let centre = placed.rect.center();
                pen.segment(
                    placed.rect.center_top(),
                    placed.rect.center_bottom(),
                    pen.stroke(1.5, pen.line),
                );
                pen.segment(
                    pos2(centre.x - TRANSITION_HALF_WIDTH_PX, centre.y),
                    pos2(centre.x + TRANSITION_HALF_WIDTH_PX, centre.y),
                    pen.stroke(3.0, color),
                );
                let mut text_pos = placed.text_pos;
                if self
                    .transition_objects
                    .iter()
                    .any(|name| project_model::same_identifier(name, transition.condition.trim()))
                {
                    // A transition object is marked with a small triangle, as CODESYS does.
                    let x = text_pos.x;
                    pen.triangle(
                        [
                            pos2(x, centre.y - MARKER_PX / 2.0),
                            pos2(x, centre.y + MARKER_PX / 2.0),
                            pos2(x + MARKER_PX, centre.y),
                        ],
                        pen.text,
                    );
                    text_pos.x += MARKER_PX + 3.0;
                }
                pen.text(
                    text_pos,
                    Align2::LEFT_CENTER,
                    &shortened(&transition.condition).0,
                    OPERAND_FONT_PX,
                    if value.is_some() { color } else { pen.text },
                );
                if let Some(priority) = transition.priority {
                    pen.text(
                        placed.rect.left_top(),
                        Align2::LEFT_TOP,
                        &priority.to_string(),
                        SMALL_FONT_PX,
                        pen.text,
                    );
                }
            }
            (SfcShape::Jump, SfcNode::Jump(jump)) => {
                let stroke = pen.stroke(1.5, pen.line);
                let tip = placed.rect.center_bottom();
                pen.segment(placed.rect.center_top(), tip - vec2(0.0, MARKER_PX), stroke);
                pen.triangle(
                    [
                        tip,
                        tip + vec2(-MARKER_PX, -MARKER_PX * 1.5),
                        tip + vec2(MARKER_PX, -MARKER_PX * 1.5),
                    ],
                    pen.line,
                );
                pen.text(
                    placed.text_pos,
                    Align2::LEFT_CENTER,
                    &shortened(&jump.target).0,
                    OPERAND_FONT_PX,
                    pen.text,
                );
            }
            _ => {}
        }
    }

    /// CODESYS's markers of a step's own actions: `E` (entry) at the top left, `X` (exit) at
    /// the bottom right, and a triangle at the top right for the step action.
    fn paint_step_markers(&self, pen: &Pen<'_>, rect: Rect, step: &project_model::Step) {
        if step.entry_action.is_some() {
            pen.text(
                rect.left_top() + vec2(4.0, 3.0),
                Align2::LEFT_TOP,
                "E",
                SMALL_FONT_PX,
                pen.text,
            );
        }
        if step.exit_action.is_some() {
            pen.text(
                rect.right_bottom() - vec2(4.0, 3.0),
                Align2::RIGHT_BOTTOM,
                "X",
                SMALL_FONT_PX,
                pen.text,
            );
        }
        if step.main_action.is_some() {
            let corner = rect.right_top() + vec2(-4.0, 4.0);
            pen.triangle(
                [
                    corner,
                    corner - vec2(MARKER_PX, 0.0),
                    corner + vec2(0.0, MARKER_PX),
                ],
                pen.text,
            );
        }
    }

    /// The association box: qualifier | action | time, one row per association, an active
    /// action filled as an active step is.
    fn paint_actions(
        &self,
        pen: &Pen<'_>,
        step_rect: Rect,
        actions: ActionBox,
        step: &project_model::Step,
    ) {
        let stroke = pen.stroke(1.0, pen.line);
        pen.segment(
            pos2(step_rect.right(), step_rect.center().y),
            pos2(actions.rect.left(), step_rect.center().y),
            stroke,
        );
        let row_height = super::layout::ACTION_ROW_PX;
        let active_actions = self.online.as_ref().map(|online| &online.actions);
        for (index, association) in step.actions.iter().enumerate() {
            let top = actions.rect.top() + index as f32 * row_height;
            let row = Rect::from_min_size(
                pos2(actions.rect.left(), top),
                vec2(actions.rect.width(), row_height),
            );
            let active = active_actions
                .and_then(|active| active.get(&association.action))
                .copied()
                .unwrap_or(false);
            if active {
                pen.painter
                    .rect_filled(pen.rect(row), 0.0, pen.palette.active_step);
            }
            let text = if active {
                pen.palette.active_step_text
            } else {
                pen.text
            };
            let middle = top + row_height / 2.0;
            pen.text(
                pos2((actions.rect.left() + actions.action_x) / 2.0, middle),
                Align2::CENTER_CENTER,
                association.qualifier.as_str(),
                OPERAND_FONT_PX,
                text,
            );
            pen.text(
                pos2(actions.action_x + 4.0, middle),
                Align2::LEFT_CENTER,
                &shortened(&association.action).0,
                OPERAND_FONT_PX,
                text,
            );
            if let Some(duration) = &association.duration {
                pen.text(
                    pos2(actions.time_x + 4.0, middle),
                    Align2::LEFT_CENTER,
                    &shortened(duration).0,
                    OPERAND_FONT_PX,
                    text,
                );
            }
            if index > 0 {
                pen.segment(
                    pos2(actions.rect.left(), top),
                    pos2(actions.rect.right(), top),
                    stroke,
                );
            }
        }
        let rows_bottom = actions.rect.top() + step.actions.len() as f32 * row_height;
        let table = Rect::from_min_max(
            actions.rect.min,
            pos2(
                actions.rect.right(),
                rows_bottom.max(actions.rect.top() + row_height),
            ),
        );
        pen.painter
            .rect_stroke(pen.rect(table), 0.0, stroke, StrokeKind::Inside);
        pen.segment(
            pos2(actions.action_x, table.top()),
            pos2(actions.action_x, table.bottom()),
            stroke,
        );
        if actions.time_x + 1.0 < actions.rect.right() {
            pen.segment(
                pos2(actions.time_x, table.top()),
                pos2(actions.time_x, table.bottom()),
                stroke,
            );
        }
    }
}

/// An elapsed time as an IEC TIME literal (`T#1s250ms`), the same in every language.
pub(super) fn time_literal(elapsed: std::time::Duration) -> String {
    let total_ms = elapsed.as_millis();
    let (hours, rest) = (total_ms / 3_600_000, total_ms % 3_600_000);
    let (minutes, rest) = (rest / 60_000, rest % 60_000);
    let (seconds, millis) = (rest / 1000, rest % 1000);
    let mut text = String::from("T#");
    for (value, unit) in [(hours, "h"), (minutes, "m"), (seconds, "s"), (millis, "ms")] {
        if value > 0 {
            text.push_str(&format!("{value}{unit}"));
        }
    }
    if text.len() == 2 {
        text.push_str("0ms");
    }
    text
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use super::time_literal;

    #[test]
    fn elapsed_times_are_written_as_time_literals() {
        assert_eq!(time_literal(Duration::from_millis(0)), "T#0ms");
        assert_eq!(time_literal(Duration::from_millis(1250)), "T#1s250ms");
        assert_eq!(time_literal(Duration::from_secs(3723)), "T#1h2m3s");
    }
}
