//! Painting the chart: wires first (feedback wires dashed in the warning colour), then the
//! elements with their pins, modifiers, execution order badges, findings and online values,
//! then the gesture in progress. Only what is in view is painted.

use egui::{
    Align2, Color32, CursorIcon, FontId, Painter, Pos2, Rect, Response, Shape, Stroke, StrokeKind,
    Ui, pos2, vec2,
};
use project_model::{CfcElement, CfcElementKind, CfcPin, CoilKind, Edge, ElementId};

use super::editor::{CfcEditor, Drag};
use super::geometry::{ElementShape, ROW_UNITS, element_title};
use crate::diagram::measure::{OPERAND_FONT_PX, PIN_FONT_PX, shortened};
use crate::{EditorPalette, Severity};

/// The colours of one frame, from the theme.
struct Colors {
    text: Color32,
    weak: Color32,
    fill: Color32,
    palette: EditorPalette,
}

impl CfcEditor {
    pub(super) fn paint(&self, ui: &Ui, origin: Pos2, visible: Rect, response: &Response) {
        let painter = ui.painter().with_clip_rect(visible);
        let visuals = ui.visuals();
        let colors = Colors {
            text: visuals.text_color(),
            weak: visuals.weak_text_color(),
            fill: visuals.extreme_bg_color,
            palette: EditorPalette::of(ui),
        };
        self.paint_wires(&painter, origin, visible, &colors);
        for element in &self.chart.elements {
            let Some(shape) = self.shape_now(element.id) else {
                continue;
            };
            let rect = self.screen_rect(origin, shape.rect);
            // The instance row above a box and the badges stick out of the frame.
            if !visible.intersects(rect.expand(ROW_UNITS as f32 * self.unit_px() + 20.0)) {
                continue;
            }
            self.paint_element(&painter, origin, element, &shape, rect, &colors);
            if !self.debug_marks.is_empty() {
                crate::body_debug_marks::paint_element_marks(
                    &painter,
                    &self.debug_marks,
                    0,
                    element.id,
                    rect,
                    5.0 * self.zoom,
                );
            }
        }
        self.paint_wire_values(&painter, origin, &colors);
        self.paint_gesture(&painter, origin, &colors);
        if response.hovered() && self.tool.is_some() {
            ui.ctx().set_cursor_icon(CursorIcon::Crosshair);
        }
        self.findings_tooltip(origin, response);
    }

    fn paint_wires(&self, painter: &Painter, origin: Pos2, visible: Rect, colors: &Colors) {
        let unit = self.unit_px();
        for wire in &self.chart.wires {
            let Some(route) = self
                .drag_routes
                .get(&wire.to)
                .or_else(|| self.routes.get(&wire.to))
            else {
                continue;
            };
            let points: Vec<Pos2> = route
                .iter()
                .map(|p| self.screen(origin, p.x as f32, p.y as f32))
                .collect();
            if !visible.intersects(Rect::from_points(&points)) {
                continue;
            }
            let selected = self.selection.wire.as_ref() == Some(&wire.to);
            let feedback = self.is_feedback(wire.from.element, wire.to.element);
            let color = if selected {
                colors.palette.diagram_selection
            } else if feedback {
                colors.palette.warning
            } else {
                colors.text
            };
            let stroke = Stroke::new(if selected { 2.0 } else { 1.0 }, color);
            if feedback {
                // A feedback reads the previous cycle's value: dashed, with a ring where it
                // enters, so a loop shows at a glance.
                painter.extend(Shape::dashed_line(&points, stroke, 0.5 * unit, 0.3 * unit));
                if let Some(end) = points.last() {
                    painter.circle_stroke(*end - vec2(0.6 * unit, 0.0), 0.25 * unit, stroke);
                }
            } else {
                painter.add(Shape::line(points.clone(), stroke));
            }
            if selected {
                for point in &wire.points {
                    let at = self.screen(origin, point.x as f32, point.y as f32);
                    painter.rect_filled(
                        Rect::from_center_size(at, vec2(0.5 * unit, 0.5 * unit)),
                        0.0,
                        colors.palette.diagram_selection,
                    );
                }
            }
        }
    }

    /// The online value each wire carries, at its start: painted after the elements, on the
    /// canvas's colour, so a value wider than a short wire stays readable over the box it
    /// runs into.
    fn paint_wire_values(&self, painter: &Painter, origin: Pos2, colors: &Colors) {
        if self.online.is_none() {
            return;
        }
        let unit = self.unit_px();
        for wire in &self.chart.wires {
            let Some(route) = self
                .drag_routes
                .get(&wire.to)
                .or_else(|| self.routes.get(&wire.to))
            else {
                continue;
            };
            let value_key = (wire.from.element, Some(wire.from.pin.clone()));
            if let (Some(value), Some(start)) = (self.online_value(&value_key), route.first()) {
                let start = self.screen(origin, start.x as f32, start.y as f32);
                self.paint_value(
                    painter,
                    start + vec2(0.3 * unit, -0.2 * unit),
                    value,
                    colors,
                );
            }
        }
    }

    /// The online value of `key`, or of the element's only pin.
    fn online_value(
        &self,
        key: &(ElementId, Option<String>),
    ) -> Option<&crate::diagram::OnlineValue> {
        let online = self.online.as_ref()?;
        online.values.get(key).or_else(|| match &key.1 {
            Some(pin) if pin.is_empty() => online.values.get(&(key.0, None)),
            _ => None,
        })
    }

    fn paint_value(
        &self,
        painter: &Painter,
        bottom_left: Pos2,
        value: &crate::diagram::OnlineValue,
        colors: &Colors,
    ) {
        let font = FontId::monospace(PIN_FONT_PX * self.zoom);
        let (color, fill) = if value.forced {
            (colors.palette.forced_text, colors.palette.forced_fill)
        } else {
            (colors.palette.syntax.number, colors.fill)
        };
        let galley = painter.layout_no_wrap(value.text.clone(), font, color);
        let rect = Rect::from_min_size(bottom_left - vec2(0.0, galley.size().y), galley.size());
        painter.rect_filled(rect.expand(1.0), 2.0, fill);
        painter.galley(rect.min, galley, color);
    }

    #[allow(clippy::too_many_arguments)]
    fn paint_element(
        &self,
        painter: &Painter,
        origin: Pos2,
        element: &CfcElement,
        shape: &ElementShape,
        rect: Rect,
        colors: &Colors,
    ) {
        let unit = self.unit_px();
        let selected = self.selection.elements.contains(&element.id);
        let frame_color = match self.marks.get(&element.id) {
            _ if selected => colors.palette.diagram_selection,
            Some(Severity::Error) => colors.palette.error,
            Some(Severity::Warning) => colors.palette.warning,
            Some(_) => colors.palette.info,
            None => colors.text,
        };
        let stroke = Stroke::new(if selected { 2.0 } else { 1.0 }, frame_color);
        let operand_font = FontId::monospace(OPERAND_FONT_PX * self.zoom);
        let pin_font = FontId::monospace(PIN_FONT_PX * self.zoom);
        let row = ROW_UNITS as f32 * unit;
        let title = element_title(&element.kind);
        let (shown_title, _) = shortened(title);
        match &element.kind {
            CfcElementKind::Comment { .. } => {
                painter.rect_stroke(rect, 2.0, Stroke::new(1.0, colors.weak), StrokeKind::Inside);
                let galley = painter.layout(
                    title.to_owned(),
                    operand_font,
                    colors.weak,
                    rect.width() - 4.0,
                );
                painter.galley(rect.min + vec2(2.0, 2.0), galley, colors.weak);
                if selected {
                    painter.rect_stroke(rect, 2.0, stroke, StrokeKind::Outside);
                }
                return;
            }
            CfcElementKind::Box(_)
            | CfcElementKind::Composer { .. }
            | CfcElementKind::Selector { .. } => {
                painter.rect_filled(rect, 2.0, colors.fill);
                painter.rect_stroke(rect, 2.0, stroke, StrokeKind::Inside);
                painter.text(
                    pos2(rect.center().x, rect.top() + row / 2.0),
                    Align2::CENTER_CENTER,
                    shown_title,
                    operand_font.clone(),
                    colors.text,
                );
                if let CfcElementKind::Box(block) = &element.kind
                    && !block.instance.is_empty()
                {
                    painter.text(
                        pos2(rect.center().x, rect.top() - 2.0),
                        Align2::CENTER_BOTTOM,
                        &block.instance,
                        operand_font,
                        colors.text,
                    );
                }
            }
            _ => {
                painter.rect_filled(rect, 2.0, colors.fill);
                painter.rect_stroke(rect, 2.0, stroke, StrokeKind::Inside);
                let text = match &element.kind {
                    CfcElementKind::Label { .. } => format!("{shown_title}:"),
                    CfcElementKind::Output {
                        coil: CoilKind::Set,
                        ..
                    } => format!("S {shown_title}"),
                    CfcElementKind::Output {
                        coil: CoilKind::Reset,
                        ..
                    } => format!("R {shown_title}"),
                    _ => shown_title.into_owned(),
                };
                painter.text(
                    pos2(rect.left() + 0.5 * unit, rect.center().y),
                    Align2::LEFT_CENTER,
                    text,
                    operand_font,
                    colors.text,
                );
                // Jumps and connection marks point the way the value goes.
                if matches!(
                    element.kind,
                    CfcElementKind::Jump { .. } | CfcElementKind::ConnectionSource { .. }
                ) {
                    let tip = pos2(rect.right() + 0.6 * unit, rect.center().y);
                    painter.add(Shape::convex_polygon(
                        vec![
                            pos2(rect.right(), rect.top()),
                            tip,
                            pos2(rect.right(), rect.bottom()),
                        ],
                        colors.fill,
                        stroke,
                    ));
                }
                if let Some(value) = self.online_value(&(element.id, None))
                    && matches!(element.kind, CfcElementKind::Output { .. })
                {
                    self.paint_value(
                        painter,
                        rect.right_top() + vec2(0.3 * unit, 0.0),
                        value,
                        colors,
                    );
                }
            }
        }
        self.paint_pins(painter, origin, element, shape, &pin_font, stroke, colors);
        if self.show_order
            && let Some(order) = element.order
        {
            let galley = painter.layout_no_wrap(order.to_string(), pin_font, colors.fill);
            let badge = Rect::from_min_size(
                rect.right_top() + vec2(-galley.size().x - 4.0, -galley.size().y - 2.0),
                galley.size() + vec2(4.0, 2.0),
            );
            painter.rect_filled(badge, 3.0, colors.palette.info);
            painter.galley(badge.min + vec2(2.0, 1.0), galley, colors.fill);
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn paint_pins(
        &self,
        painter: &Painter,
        origin: Pos2,
        element: &CfcElement,
        shape: &ElementShape,
        font: &FontId,
        stroke: Stroke,
        colors: &Colors,
    ) {
        let unit = self.unit_px();
        let (inputs, outputs): (&[CfcPin], &[CfcPin]) = match &element.kind {
            CfcElementKind::Box(block) => (&block.inputs, &block.outputs),
            CfcElementKind::Composer { inputs, .. } => (inputs, &[]),
            CfcElementKind::Selector { outputs, .. } => (&[], outputs),
            _ => (&[], &[]),
        };
        let ring = |at: Pos2| painter.circle_stroke(at, 0.3 * unit, stroke);
        // A pin a finding names is written in the finding's colour.
        let pin_color = |name: &str| match self.pin_marks.get(&(element.id, name.to_owned())) {
            Some(Severity::Error) => colors.palette.error,
            Some(Severity::Warning) => colors.palette.warning,
            Some(_) => colors.palette.info,
            None => colors.text,
        };
        for (name, point) in &shape.inputs {
            let at = self.screen(origin, point.x as f32, point.y as f32);
            let pin = inputs.iter().find(|pin| pin.name == *name);
            let negated = pin.is_some_and(|pin| pin.negated)
                || matches!(
                    element.kind,
                    CfcElementKind::Output {
                        coil: CoilKind::Negated,
                        ..
                    }
                );
            if negated {
                ring(at - vec2(0.3 * unit, 0.0));
            }
            let edge = match pin.map(|pin| pin.edge) {
                Some(Edge::Rising) => ">",
                Some(Edge::Falling) => "<",
                _ => "",
            };
            if !name.is_empty() || !edge.is_empty() {
                painter.text(
                    at + vec2(0.3 * unit, 0.0),
                    Align2::LEFT_CENTER,
                    format!("{edge}{name}"),
                    font.clone(),
                    pin_color(name),
                );
            }
            if let Some(value) = self.online_value(&(element.id, Some(name.clone())))
                && !name.is_empty()
            {
                let galley = painter.layout_no_wrap(value.text.clone(), font.clone(), colors.text);
                let left = at - vec2(galley.size().x + 0.6 * unit, 0.0);
                self.paint_value(painter, left, value, colors);
            }
        }
        for (name, point) in &shape.outputs {
            let at = self.screen(origin, point.x as f32, point.y as f32);
            if outputs.iter().any(|pin| pin.name == *name && pin.negated) {
                ring(at + vec2(0.3 * unit, 0.0));
            }
            if !name.is_empty() {
                painter.text(
                    at - vec2(0.3 * unit, 0.0),
                    Align2::RIGHT_CENTER,
                    name,
                    font.clone(),
                    pin_color(name),
                );
            }
        }
    }

    fn paint_gesture(&self, painter: &Painter, origin: Pos2, colors: &Colors) {
        let stroke = Stroke::new(1.5, colors.palette.diagram_selection);
        match &self.drag {
            Some(Drag::Connect {
                from,
                from_output,
                pointer,
            }) => {
                let start = self.shapes.get(&from.element).and_then(|shape| {
                    if *from_output {
                        shape.output(&from.pin)
                    } else {
                        shape.input(&from.pin)
                    }
                });
                if let Some(start) = start {
                    let a = self.screen(origin, start.x as f32, start.y as f32);
                    let b = self.screen(origin, pointer.x, pointer.y);
                    painter.extend(Shape::dashed_line(&[a, b], stroke, 6.0, 4.0));
                }
            }
            Some(Drag::Band { from, to }) => {
                let rect = Rect::from_two_pos(
                    self.screen(origin, from.x, from.y),
                    self.screen(origin, to.x, to.y),
                );
                painter.rect_stroke(rect, 0.0, stroke, StrokeKind::Inside);
            }
            Some(Drag::ControlPoint { at, .. }) => {
                let at = self.screen(origin, at.x as f32, at.y as f32);
                painter.circle_stroke(at, 0.4 * self.unit_px(), stroke);
            }
            _ => {}
        }
    }

    /// The messages of the findings on the element under the pointer, as a tooltip.
    fn findings_tooltip(&self, origin: Pos2, response: &Response) {
        if self.diagnostics.is_empty() {
            return;
        }
        let Some(pointer) = response.hover_pos() else {
            return;
        };
        let super::canvas::Hit::Element(id) = self.hit(self.grid_at(origin, pointer)) else {
            return;
        };
        let messages: Vec<String> = self
            .diagnostics
            .iter()
            .filter(|diagnostic| diagnostic.element == Some(id))
            .map(|diagnostic| format!("{}: {}", diagnostic.code, diagnostic.message))
            .collect();
        if !messages.is_empty() {
            response.clone().on_hover_text(messages.join("\n"));
        }
    }
}
