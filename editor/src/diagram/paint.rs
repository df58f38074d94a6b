//! Painting a laid-out network with egui's painter: lines, contacts, coils, boxes, variables,
//! the selection, diagnostics markers, online power and values, and insertion marks.

use std::collections::{HashMap, HashSet};

use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, Stroke, StrokeKind, pos2, vec2};
use project_model::{CoilKind, Edge, ElementId};

use super::measure::{BOX_LEAD_PX, OPERAND_FONT_PX, PIN_FONT_PX, shortened};
use super::placed::{NetworkLayout, PinMark, PlacedElement, Power, Shape};
use super::types::{DiagramOnline, DiagramView};
use crate::{EditorPalette, Severity};

/// The size of a grid cell of the LD view at zoom 1, in points: a contact with its operand
/// above it and its online value under it. Cells are as wide in both views, so the layouts measure texts the same way.
pub(super) const CELL_SIZE_PX: egui::Vec2 = egui::Vec2::new(84.0, 48.0);
/// The height of a row of the FBD view at zoom 1, in points: one pin with its name, the pitch
/// of CODESYS's FBD boxes, since no operand stands above a line there.
const FBD_ROW_HEIGHT_PX: f32 = 30.0;

/// The size of a grid cell of `view` at zoom 1, in points.
pub(super) fn cell_size_px(view: DiagramView) -> egui::Vec2 {
    match view {
        DiagramView::Ladder => CELL_SIZE_PX,
        DiagramView::FunctionBlock => vec2(CELL_SIZE_PX.x, FBD_ROW_HEIGHT_PX),
    }
}

/// How far below its element's top an LD box's frame starts when its instance is named above
/// it, in points at zoom 1: the height of an operand's line.
const INSTANCE_ROOM_PX: f32 = 15.0;

/// Half the height of a contact's or coil's symbol, in points at zoom 1.
const SYMBOL_HALF_HEIGHT_PX: f32 = 9.0;

/// Where the online value of a contact or coil drawn in `rect` (screen points, rows
/// `row_height` high) goes: under the symbol, centred on it, its top edge at the point given.
/// The rung line runs through the symbol's middle and a branch's lines along the cell's edges,
/// and the operand stands above, so nothing else is drawn there.
pub(super) fn operand_badge_anchor(rect: Rect, row_height: f32, zoom: f32) -> Pos2 {
    let mid_y = rect.top() + rect.height().min(row_height) * 0.5;
    pos2(
        rect.center().x,
        mid_y + (SYMBOL_HALF_HEIGHT_PX + 2.0) * zoom,
    )
}

/// The size of an online value's font, in points at zoom 1.
const BADGE_FONT_PX: f32 = 9.5;

/// The advance of a monospace character per point of font size (egui's default monospace font
/// is a little narrower; the estimate errs on the safe side).
const MONO_CHAR_WIDTH: f32 = 0.62;

/// `text` cut to at most `chars` characters, the last one an ellipsis when it was cut.
fn fitted(text: &str, chars: usize) -> String {
    if text.chars().count() <= chars {
        return text.to_owned();
    }
    let mut cut: String = text.chars().take(chars.saturating_sub(1)).collect();
    cut.push('…');
    cut
}

/// The height of a variable's frame around its text, in points at zoom 1.
const TEXT_FRAME_HEIGHT_PX: f32 = 20.0;

/// What the painter needs besides the layout; borrowed for one frame.
pub(super) struct PaintContext<'a> {
    /// Where the painting goes, clipped to the canvas.
    pub painter: &'a Painter,
    /// The colours.
    pub palette: EditorPalette,
    /// The colour of lines and symbols.
    pub line: Color32,
    /// The colour of weak text (placeholders, comments).
    pub weak: Color32,
    /// Points per point at zoom 1.
    pub zoom: f32,
    /// The size of a grid cell at zoom 1, in points.
    pub cell: egui::Vec2,
    /// LD or FBD.
    pub view: DiagramView,
    /// The selected elements.
    pub selected: &'a HashSet<ElementId>,
    /// The worst severity of the diagnostics on each element.
    pub diagnostics: &'a HashMap<ElementId, Severity>,
    /// The worst severity of the diagnostics on each pin of a box.
    pub pin_diagnostics: &'a HashMap<(ElementId, String), Severity>,
    /// The online values, when logged in.
    pub online: Option<&'a DiagramOnline>,
    /// The text shown for an empty operand.
    pub placeholder: &'a str,
}

impl PaintContext<'_> {
    /// The screen rectangle of a grid rectangle of a network drawn from `origin`.
    pub fn screen_rect(&self, origin: Pos2, rect: Rect) -> Rect {
        Rect::from_min_max(
            self.screen_pos(origin, rect.min),
            self.screen_pos(origin, rect.max),
        )
    }

    /// The screen position of a grid position of a network drawn from `origin`.
    pub fn screen_pos(&self, origin: Pos2, pos: Pos2) -> Pos2 {
        origin + vec2(pos.x * self.cell.x, pos.y * self.cell.y) * self.zoom
    }

    fn font(&self, size_px: f32) -> FontId {
        FontId::proportional(size_px * self.zoom)
    }

    /// The font of operands, box titles and pin names: monospace, so the layouts know their
    /// widths without measuring.
    fn mono(&self, size_px: f32) -> FontId {
        FontId::monospace(size_px * self.zoom)
    }

    fn severity_color(&self, severity: Severity) -> Color32 {
        match severity {
            Severity::Error => self.palette.error,
            Severity::Warning => self.palette.warning,
            Severity::Info => self.palette.info,
        }
    }

    fn stroke(&self, power: Power) -> Stroke {
        let on = match (self.online, power) {
            (Some(_), Power::Rail) => true,
            (Some(online), Power::After(id)) => online.power.get(&id).copied().unwrap_or(false),
            _ => false,
        };
        if on {
            Stroke::new(3.0 * self.zoom, self.palette.power_on)
        } else {
            Stroke::new(1.5 * self.zoom, self.line)
        }
    }

    /// Paints `layout` with its top-left corner at `origin` (screen points).
    pub fn network(&self, layout: &NetworkLayout, origin: Pos2) {
        for element in &layout.elements {
            if element.id.is_some_and(|id| self.selected.contains(&id)) {
                let rect = self.screen_rect(origin, element.rect).shrink(1.0);
                self.painter
                    .rect_filled(rect, 3.0 * self.zoom, self.palette.diagram_selection);
                self.painter.rect_stroke(
                    rect,
                    3.0 * self.zoom,
                    Stroke::new(1.5 * self.zoom, self.palette.power_on),
                    StrokeKind::Inside,
                );
            }
        }
        for wire in &layout.wires {
            let points = wire
                .points
                .iter()
                .map(|point| self.screen_pos(origin, *point))
                .collect();
            self.painter.line(points, self.stroke(wire.power));
        }
        for element in &layout.elements {
            self.element(element, origin);
        }
    }

    /// Paints a "+" mark at every insertion point, the one at `highlighted` larger.
    pub fn insert_points(&self, layout: &NetworkLayout, origin: Pos2, highlighted: Option<Pos2>) {
        for point in &layout.insert_points {
            let center = self.screen_pos(origin, point.pos);
            let big = highlighted == Some(point.pos);
            let radius = if big { 9.0 } else { 5.0 } * self.zoom;
            let stroke = Stroke::new(2.0 * self.zoom, self.palette.insert_point);
            self.painter.line_segment(
                [center - vec2(radius, 0.0), center + vec2(radius, 0.0)],
                stroke,
            );
            self.painter.line_segment(
                [center - vec2(0.0, radius), center + vec2(0.0, radius)],
                stroke,
            );
        }
    }

    fn element(&self, element: &PlacedElement, origin: Pos2) {
        let rect = self.screen_rect(origin, element.rect);
        let mid_y = rect.top() + rect.height().min(self.cell.y * self.zoom) * 0.5;
        let own = element.id.map_or(Power::None, Power::After);
        match &element.shape {
            Shape::Contact {
                text,
                negated,
                edge,
            } => {
                let center = pos2(rect.center().x, mid_y);
                let half = vec2(7.0, SYMBOL_HALF_HEIGHT_PX) * self.zoom;
                self.painter.line_segment(
                    [pos2(rect.left(), mid_y), pos2(center.x - half.x, mid_y)],
                    self.stroke(element.power_in),
                );
                self.painter.line_segment(
                    [pos2(center.x + half.x, mid_y), pos2(rect.right(), mid_y)],
                    self.stroke(own),
                );
                let stroke = self.stroke(own);
                for x in [center.x - half.x, center.x + half.x] {
                    self.painter
                        .line_segment([pos2(x, mid_y - half.y), pos2(x, mid_y + half.y)], stroke);
                }
                if *negated {
                    self.painter.line_segment(
                        [
                            center + vec2(-half.x, half.y),
                            center + vec2(half.x, -half.y),
                        ],
                        stroke,
                    );
                }
                self.edge_letter(*edge, center);
                self.operand(text, element, rect);
            }
            Shape::Coil { variable, kind } => {
                let center = pos2(rect.center().x, mid_y);
                let radius = 8.5 * self.zoom;
                self.painter.line_segment(
                    [pos2(rect.left(), mid_y), pos2(center.x - radius, mid_y)],
                    self.stroke(element.power_in),
                );
                self.painter.line_segment(
                    [pos2(center.x + radius, mid_y), pos2(rect.right(), mid_y)],
                    self.stroke(element.power_in),
                );
                self.painter
                    .circle_stroke(center, radius, self.stroke(element.power_in));
                self.coil_letter(*kind, center);
                self.operand(variable, element, rect);
            }
            Shape::Assignment { variable, kind } => {
                // The line comes in from the left past the room of a set, reset or edge
                // letter, which sits on it, into the variable's frame.
                let letter_room = 17.0 * self.zoom;
                let frame = Rect::from_min_max(
                    pos2(
                        rect.left() + letter_room,
                        mid_y - TEXT_FRAME_HEIGHT_PX / 2.0 * self.zoom,
                    ),
                    pos2(rect.right(), mid_y + TEXT_FRAME_HEIGHT_PX / 2.0 * self.zoom),
                );
                self.painter.line_segment(
                    [pos2(rect.left(), mid_y), pos2(frame.left(), mid_y)],
                    self.stroke(element.power_in),
                );
                if *kind != CoilKind::Normal {
                    let letter_at = pos2(rect.left() + letter_room / 2.0, mid_y);
                    self.coil_letter(*kind, letter_at - vec2(0.0, 8.0 * self.zoom));
                }
                self.painter.rect_stroke(
                    frame,
                    2.0 * self.zoom,
                    self.stroke(Power::None),
                    StrokeKind::Inside,
                );
                self.text_in(variable, frame.shrink2(vec2(4.0, 0.0) * self.zoom), element);
            }
            Shape::Variable {
                text,
                negated,
                edge,
            } => {
                let frame = Rect::from_center_size(
                    pos2(rect.center().x, mid_y),
                    vec2(
                        rect.width() - 8.0 * self.zoom,
                        TEXT_FRAME_HEIGHT_PX * self.zoom,
                    ),
                );
                if element.id.is_none() {
                    // An output's assignment: the line comes from the pin on the left.
                    self.painter.line_segment(
                        [
                            pos2(rect.left(), mid_y),
                            pos2(rect.left() + 3.0 * self.zoom, mid_y),
                        ],
                        self.stroke(element.power_in),
                    );
                    self.text_at(
                        text,
                        pos2(rect.left() + 4.0 * self.zoom, mid_y),
                        Align2::LEFT_CENTER,
                    );
                } else {
                    self.text_in(text, frame, element);
                    self.painter.line_segment(
                        [pos2(frame.right(), mid_y), pos2(rect.right(), mid_y)],
                        self.stroke(element.power_in),
                    );
                }
                if *negated {
                    self.negation_circle(pos2(rect.right(), mid_y));
                }
                // An operand that feeds no pin carries its edge at its end, on the line.
                self.edge_letter(
                    *edge,
                    pos2(rect.right() - 2.0 * self.zoom, mid_y - 7.0 * self.zoom),
                );
            }
            Shape::Jump { label } => {
                let tip = pos2(rect.left() + 18.0 * self.zoom, mid_y);
                self.painter.arrow(
                    pos2(rect.left(), mid_y),
                    tip - pos2(rect.left(), mid_y),
                    self.stroke(element.power_in),
                );
                let shown = if label.is_empty() {
                    self.placeholder
                } else {
                    label
                };
                self.painter.text(
                    tip + vec2(4.0 * self.zoom, 0.0),
                    Align2::LEFT_CENTER,
                    shown,
                    self.mono(OPERAND_FONT_PX),
                    self.line,
                );
            }
            Shape::Return => {
                self.painter.text(
                    pos2(rect.left() + 4.0 * self.zoom, mid_y),
                    Align2::LEFT_CENTER,
                    "RETURN",
                    self.mono(OPERAND_FONT_PX),
                    self.line,
                );
            }
            Shape::Group => {}
            Shape::Box {
                type_name,
                instance,
                inputs,
                outputs,
            } => self.block(rect, origin, type_name, instance, inputs, outputs, element),
        }
        if let Some(severity) = element.id.and_then(|id| self.diagnostics.get(&id)) {
            let color = self.severity_color(*severity);
            self.painter.rect_stroke(
                rect.shrink(1.0),
                2.0 * self.zoom,
                Stroke::new(2.0 * self.zoom, color),
                StrokeKind::Inside,
            );
            // A filled badge with "!" on a top corner: a box's left one, clear of its pins'
            // lines, the right one of other elements, clear of a set or reset letter.
            let corner = if matches!(element.shape, Shape::Box { .. }) {
                rect.left_top() + vec2(5.0, 5.0) * self.zoom
            } else {
                rect.right_top() + vec2(-5.0, 5.0) * self.zoom
            };
            self.painter.circle_filled(corner, 5.5 * self.zoom, color);
            self.painter.text(
                corner,
                Align2::CENTER_CENTER,
                "!",
                FontId::monospace(10.0 * self.zoom),
                self.palette.forced_text,
            );
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn block(
        &self,
        rect: Rect,
        origin: Pos2,
        type_name: &str,
        instance: &str,
        inputs: &[PinMark],
        outputs: &[PinMark],
        element: &PlacedElement,
    ) {
        let mut frame = rect.shrink2(vec2(BOX_LEAD_PX, 3.0) * self.zoom);
        if self.view == DiagramView::Ladder && !instance.is_empty() {
            // An LD box starts on the row of the operands above the contacts, so its instance
            // name stands where they do, inside the element, and not over the network's
            // header above it.
            frame.min.y = rect.top() + INSTANCE_ROOM_PX * self.zoom;
        }
        let stroke = self.stroke(Power::None);
        self.painter
            .rect_stroke(frame, 2.0 * self.zoom, stroke, StrokeKind::Inside);
        let title = self.painter.text(
            pos2(frame.center().x, frame.top() + 2.0 * self.zoom),
            Align2::CENTER_TOP,
            type_name,
            self.mono(OPERAND_FONT_PX),
            self.line,
        );
        if !instance.is_empty() {
            self.painter.text(
                pos2(frame.center().x, frame.top() - 1.0 * self.zoom),
                Align2::CENTER_BOTTOM,
                instance,
                self.mono(OPERAND_FONT_PX),
                self.line,
            );
        }
        let pin_y = |pin: &PinMark| self.screen_pos(origin, pos2(0.0, pin.row + 0.5)).y;
        // Only a box with a finding looks its pins up, so painting allocates no keys.
        let marked = element.id.filter(|id| self.diagnostics.contains_key(id));
        let pin_severity =
            |pin: &PinMark| marked.and_then(|id| self.pin_diagnostics.get(&(id, pin.name.clone())));
        // Where each input row's name ends, so an output's value on that row stays clear of it.
        let mut input_right: Vec<(f32, f32)> = Vec::with_capacity(inputs.len());
        for pin in inputs {
            let y = pin_y(pin);
            self.painter.line_segment(
                [pos2(rect.left(), y), pos2(frame.left(), y)],
                self.stroke(element.power_in),
            );
            // An edge is a small letter inside the box at the pin, the name moves past it.
            let mut name_x = frame.left() + 3.0 * self.zoom;
            if pin.edge != Edge::None {
                self.edge_letter(pin.edge, pos2(name_x + 3.0 * self.zoom, y));
                name_x += 9.0 * self.zoom;
            }
            let name = self.painter.text(
                pos2(name_x, y),
                Align2::LEFT_CENTER,
                &pin.name,
                self.mono(PIN_FONT_PX),
                self.line,
            );
            if pin.negated {
                self.negation_circle(pos2(frame.left() - 4.0 * self.zoom, y));
            }
            if let Some(severity) = pin_severity(pin) {
                self.pin_mark(pos2(rect.left(), y), name, *severity);
            }
            input_right.push((pin.row, name.right()));
        }
        let own = element.id.map_or(Power::None, Power::After);
        for pin in outputs {
            let y = pin_y(pin);
            self.painter.line_segment(
                [pos2(frame.right(), y), pos2(rect.right(), y)],
                self.stroke(own),
            );
            let name = self.painter.text(
                pos2(frame.right() - 3.0 * self.zoom, y),
                Align2::RIGHT_CENTER,
                &pin.name,
                self.mono(PIN_FONT_PX),
                self.line,
            );
            if pin.negated {
                self.negation_circle(pos2(frame.right() + 4.0 * self.zoom, y));
            }
            if let Some(severity) = pin_severity(pin) {
                self.pin_mark(pos2(rect.right(), y), name, *severity);
            }
            if let (Some(online), Some(id)) = (self.online, element.id)
                && let Some(value) = online.values.get(&(id, Some(pin.name.clone())))
            {
                // Inside the box, on the pin's row left of its name when it fits between the
                // names, else under the name; never over the box's frame or a line.
                let width = self.badge_galley(&value.text).size().x + 3.0 * self.zoom;
                let row_left = input_right
                    .iter()
                    .find(|(row, _)| (*row - pin.row).abs() < 0.01)
                    .map_or(frame.left(), |(_, right)| *right);
                // The type name may stand on the first row, between its names.
                let row_left = if title.y_range().contains(y) {
                    row_left.max(title.right())
                } else {
                    row_left
                };
                if name.left() - 4.0 * self.zoom - width > row_left + 2.0 * self.zoom {
                    self.value_badge(
                        pos2(name.left() - 4.0 * self.zoom, y),
                        Align2::RIGHT_CENTER,
                        &value.text,
                        value.forced,
                    );
                } else {
                    self.value_badge(
                        pos2(frame.right() - 3.0 * self.zoom, y + 6.0 * self.zoom),
                        Align2::RIGHT_TOP,
                        &value.text,
                        value.forced,
                    );
                }
            }
        }
    }

    /// A diagnostic on a pin: its lead drawn thick in the severity's colour and its name
    /// underlined, so the finding reads at the pin and not only at the box.
    fn pin_mark(&self, lead_end: Pos2, name: Rect, severity: Severity) {
        let color = self.severity_color(severity);
        let stroke = Stroke::new(3.0 * self.zoom, color);
        let lead_start = pos2(
            if lead_end.x < name.left() {
                name.left() - 3.0 * self.zoom
            } else {
                name.right() + 3.0 * self.zoom
            },
            lead_end.y,
        );
        self.painter.line_segment([lead_end, lead_start], stroke);
        if name.width() > 0.0 {
            self.painter.line_segment(
                [
                    name.left_bottom() + vec2(0.0, 1.0 * self.zoom),
                    name.right_bottom() + vec2(0.0, 1.0 * self.zoom),
                ],
                Stroke::new(1.5 * self.zoom, color),
            );
        }
    }

    /// The operand above a contact or coil, shortened past the longest shown, with its online
    /// value.
    fn operand(&self, text: &str, element: &PlacedElement, rect: Rect) {
        let shown = if text.is_empty() {
            self.placeholder
        } else {
            text
        };
        let color = if text.is_empty() {
            self.weak
        } else {
            self.line
        };
        self.painter.text(
            pos2(rect.center().x, rect.top() + 1.0 * self.zoom),
            Align2::CENTER_TOP,
            shortened(shown).0,
            self.mono(OPERAND_FONT_PX),
            color,
        );
        if let (Some(online), Some(id)) = (self.online, element.id)
            && let Some(value) = online.values.get(&(id, None))
        {
            // A long value (a string) is cut to its cell, so it never reaches a branch's
            // line along the cell's edge; the full value is in the watch.
            let room_chars = ((rect.width() - 8.0 * self.zoom)
                / (BADGE_FONT_PX * MONO_CHAR_WIDTH * self.zoom))
                .max(1.0) as usize;
            let text = fitted(&value.text, room_chars);
            self.value_badge(
                operand_badge_anchor(rect, self.cell.y * self.zoom, self.zoom),
                Align2::CENTER_TOP,
                &text,
                value.forced,
            );
        }
    }

    /// A text at `at`, shortened past the longest shown.
    fn text_at(&self, text: &str, at: Pos2, align: Align2) {
        self.painter.text(
            at,
            align,
            shortened(text).0,
            self.mono(OPERAND_FONT_PX),
            self.line,
        );
    }

    /// A variable's text in its frame.
    fn text_in(&self, text: &str, frame: Rect, element: &PlacedElement) {
        let shown = if text.is_empty() {
            self.placeholder
        } else {
            text
        };
        let color = if text.is_empty() {
            self.weak
        } else {
            self.line
        };
        self.painter.text(
            pos2(frame.right(), frame.center().y),
            Align2::RIGHT_CENTER,
            shortened(shown).0,
            self.mono(OPERAND_FONT_PX),
            color,
        );
        if let (Some(online), Some(id)) = (self.online, element.id)
            && let Some(value) = online.values.get(&(id, None))
        {
            self.value_badge(
                frame.right_top(),
                Align2::RIGHT_BOTTOM,
                &value.text,
                value.forced,
            );
        }
    }

    /// A value in a small filled box anchored at `at`.
    fn value_badge(&self, at: Pos2, anchor: Align2, text: &str, forced: bool) {
        let galley = self.badge_galley(text);
        let text_rect = anchor.anchor_size(at, galley.size());
        let rect = text_rect.expand2(vec2(1.5, 0.5) * self.zoom);
        let fill = if forced {
            self.palette.forced_fill
        } else {
            self.palette.changed_value
        };
        self.painter.rect_filled(rect, 2.0 * self.zoom, fill);
        let color = if forced {
            self.palette.forced_text
        } else {
            self.line
        };
        self.painter.galley(text_rect.min, galley, color);
    }

    /// A value's text as a badge shows it.
    fn badge_galley(&self, text: &str) -> std::sync::Arc<egui::Galley> {
        self.painter.layout_no_wrap(
            text.to_owned(),
            FontId::monospace(BADGE_FONT_PX * self.zoom),
            self.line,
        )
    }

    fn negation_circle(&self, center: Pos2) {
        self.painter.circle_stroke(
            center,
            4.0 * self.zoom,
            Stroke::new(1.5 * self.zoom, self.line),
        );
    }

    fn edge_letter(&self, edge: Edge, center: Pos2) {
        let letter = match edge {
            Edge::None => return,
            Edge::Rising => "P",
            Edge::Falling => "N",
        };
        self.painter.text(
            center,
            Align2::CENTER_CENTER,
            letter,
            self.mono(9.0),
            self.line,
        );
    }

    fn coil_letter(&self, kind: CoilKind, center: Pos2) {
        let letter = match kind {
            CoilKind::Normal => return,
            CoilKind::Negated => "/",
            CoilKind::Set => "S",
            CoilKind::Reset => "R",
            CoilKind::Rising => "P",
            CoilKind::Falling => "N",
        };
        self.painter.text(
            center,
            Align2::CENTER_CENTER,
            letter,
            self.font(11.0),
            self.line,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagram::ld_layout;
    use project_model::{Coil, ElementId, FlowNode, Network, NetworkOutput, Operand, Parallel};

    fn contact(id: u32, text: &str) -> FlowNode {
        FlowNode::Operand(Operand {
            id: ElementId(id),
            text: text.to_owned(),
            ..Operand::default()
        })
    }

    /// Whether the segment from `a` to `b` (horizontal or vertical) crosses `rect`.
    fn crosses(rect: Rect, a: Pos2, b: Pos2) -> bool {
        Rect::from_two_pos(a, b).expand(0.5).intersects(rect)
    }

    #[test]
    fn a_long_value_is_cut_with_an_ellipsis() {
        assert_eq!(fitted("TRUE", 10), "TRUE");
        assert_eq!(fitted("'a long string value'", 8), "'a long…");
        assert_eq!(fitted("'a long string value'", 8).chars().count(), 8);
    }

    #[test]
    fn a_value_under_a_contact_or_coil_covers_no_line_and_no_operand() {
        // Three contacts in parallel, as the example's stop network, then a coil.
        let network = Network {
            rung: vec![FlowNode::Parallel(Parallel {
                id: ElementId(9),
                branches: vec![
                    project_model::Branch {
                        rung: vec![contact(1, "GVL_IO.xStopButton")],
                    },
                    project_model::Branch {
                        rung: vec![contact(2, "b")],
                    },
                    project_model::Branch {
                        rung: vec![contact(3, "GVL_Machine.xBatchComplete")],
                    },
                ],
            })],
            outputs: vec![NetworkOutput::Coil(Coil {
                id: ElementId(4),
                variable: "xRunRequest".to_owned(),
                ..Coil::default()
            })],
            ..Network::default()
        };
        let layout = ld_layout(&network, 0);
        let cell = CELL_SIZE_PX;
        let to_px = |rect: Rect| {
            Rect::from_min_max(
                pos2(rect.min.x * cell.x, rect.min.y * cell.y),
                pos2(rect.max.x * cell.x, rect.max.y * cell.y),
            )
        };
        // "FALSE" in the badge's font, with its margin.
        let badge_size = vec2(
            5.0 * BADGE_FONT_PX * MONO_CHAR_WIDTH + 3.0,
            BADGE_FONT_PX * 1.25 + 1.0,
        );

        let mut checked = 0;
        for element in &layout.elements {
            if !matches!(element.shape, Shape::Contact { .. } | Shape::Coil { .. }) {
                continue;
            }
            checked += 1;
            let rect = to_px(element.rect);
            let badge =
                Align2::CENTER_TOP.anchor_size(operand_badge_anchor(rect, cell.y, 1.0), badge_size);
            for wire in &layout.wires {
                for pair in wire.points.windows(2) {
                    let a = pos2(pair[0].x * cell.x, pair[0].y * cell.y);
                    let b = pos2(pair[1].x * cell.x, pair[1].y * cell.y);
                    assert!(
                        !crosses(badge, a, b),
                        "{:?} covers a line {a:?}-{b:?}",
                        element.id
                    );
                }
            }
            for other in &layout.elements {
                let other_rect = to_px(other.rect);
                // Every operand's text is in the top 16 points of its cell.
                let text = Rect::from_min_size(other_rect.min, vec2(other_rect.width(), 16.0));
                assert!(
                    !badge.intersects(text),
                    "{:?} covers the operand of {:?}",
                    element.id,
                    other.id
                );
            }
        }
        assert_eq!(checked, 4);
    }
}
