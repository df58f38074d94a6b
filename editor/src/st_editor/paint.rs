//! Painting what goes over and beside the text: find matches, inline values, diagnostics and
//! the gutter.

use std::ops::Range;

use egui::{Color32, FontId, Painter, Rect, Stroke, pos2, vec2};

use crate::EditorPalette;

use super::layout::{LineLayout, Metrics};
use super::{Severity, StEditor};

impl StEditor {
    #[allow(clippy::too_many_arguments)]
    pub(super) fn paint_range(
        &self,
        painter: &Painter,
        layout: &LineLayout,
        range: &Range<usize>,
        text_x: f32,
        top: f32,
        metrics: &Metrics,
        color: Color32,
    ) {
        if let Some(area) = self.range_rect(layout, range, text_x, top, metrics) {
            painter.rect_filled(area, 0.0, color);
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn paint_inline_values(
        &self,
        painter: &Painter,
        layout: &LineLayout,
        text_x: f32,
        top: f32,
        metrics: &Metrics,
        font: &FontId,
        visuals: &egui::Visuals,
    ) {
        let palette = EditorPalette::in_context(painter.ctx());
        let small = FontId::new(font.size * 0.9, font.family.clone());
        for (col, width, index) in &layout.boxes {
            let Some(value) = self.inline_values.get(*index) else {
                continue;
            };
            let x0 = text_x + layout.x_of_col(*col) + metrics.char_width * 0.5;
            let x1 = x0 + (*width as f32 - 1.0) * metrics.char_width;
            let area = Rect::from_min_max(
                pos2(x0, top + 1.0),
                pos2(x1, top + metrics.row_height - 1.0),
            );
            let fill = if value.changed {
                palette.changed_value
            } else {
                visuals.extreme_bg_color
            };
            painter.rect_filled(area, 2.0, fill);
            painter.rect_stroke(
                area,
                2.0,
                Stroke::new(1.0, visuals.weak_text_color()),
                egui::StrokeKind::Inside,
            );
            let mut text_left = area.min.x + metrics.char_width * 0.5;
            if value.forced {
                let badge = Rect::from_min_size(
                    pos2(area.min.x + 1.0, area.min.y + 1.0),
                    vec2(metrics.char_width * 1.4, area.height() - 2.0),
                );
                painter.rect_filled(badge, 2.0, palette.forced_fill);
                painter.text(
                    badge.center(),
                    egui::Align2::CENTER_CENTER,
                    "F",
                    small.clone(),
                    palette.forced_text,
                );
                text_left += metrics.char_width * 2.0;
            }
            painter.text(
                pos2(text_left, area.center().y),
                egui::Align2::LEFT_CENTER,
                &value.text,
                small.clone(),
                visuals.text_color(),
            );
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn paint_diagnostics(
        &self,
        painter: &Painter,
        layouts: &[LineLayout],
        text_x: f32,
        row_top: &dyn Fn(usize) -> f32,
        metrics: &Metrics,
        first: usize,
        last: usize,
    ) {
        let palette = EditorPalette::in_context(painter.ctx());
        for diagnostic in &self.diagnostics {
            if diagnostic.range.end < first || diagnostic.range.start > last {
                continue;
            }
            let color = severity_color(&palette, diagnostic.severity);
            let range = if diagnostic.range.is_empty() {
                diagnostic.range.start
                    ..self
                        .next_char(diagnostic.range.start)
                        .max(diagnostic.range.start + 1)
            } else {
                diagnostic.range.clone()
            };
            for layout in layouts {
                let top = row_top(layout.row);
                let area = self
                    .range_rect(layout, &range, text_x, top, metrics)
                    .or_else(|| {
                        // An empty range at a line's end still gets a short mark.
                        let line_range = self.buffer.line_range(layout.line);
                        (range.start == line_range.end).then(|| {
                            let x = text_x + layout.galley.size().x;
                            Rect::from_min_size(
                                pos2(x, top),
                                vec2(metrics.char_width, metrics.row_height),
                            )
                        })
                    });
                if let Some(area) = area {
                    wavy_line(painter, area.min.x, area.max.x, area.max.y - 2.0, color);
                }
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn paint_gutter(
        &mut self,
        painter: &Painter,
        layouts: &[LineLayout],
        clip: Rect,
        row_top: &dyn Fn(usize) -> f32,
        metrics: &Metrics,
        font: &FontId,
        visuals: &egui::Visuals,
    ) {
        let palette = EditorPalette::in_context(painter.ctx());
        let gutter = Rect::from_min_size(clip.min, vec2(metrics.gutter_width, clip.height()));
        painter.rect_filled(gutter, 0.0, visuals.panel_fill);
        let Some(first) = layouts.first() else {
            return;
        };
        let last_line = layouts.last().map_or(first.line, |layout| layout.line);
        let folds = self
            .syntax
            .folds_starting_in(&self.buffer, first.line..last_line + 1);
        let number_right = clip.min.x + metrics.gutter_width - metrics.char_width * 1.5;
        for layout in layouts {
            let top = row_top(layout.row);
            painter.text(
                pos2(number_right, top),
                egui::Align2::RIGHT_TOP,
                (layout.line + 1).to_string(),
                font.clone(),
                visuals.weak_text_color(),
            );
            let foldable = folds.iter().any(|(start, _)| *start == layout.line);
            if foldable {
                let marker = if self.folding.is_folded_at(layout.line) {
                    "+"
                } else {
                    "−"
                };
                painter.text(
                    pos2(number_right + metrics.char_width * 0.3, top),
                    egui::Align2::LEFT_TOP,
                    marker,
                    font.clone(),
                    visuals.weak_text_color(),
                );
            }
            let line_range = self.buffer.line_range(layout.line);
            let worst = self
                .diagnostics
                .iter()
                .filter(|diagnostic| {
                    diagnostic.range.start >= line_range.start
                        && diagnostic.range.start <= line_range.end
                })
                .map(|diagnostic| diagnostic.severity)
                .min_by_key(|severity| match severity {
                    Severity::Error => 0,
                    Severity::Warning => 1,
                    Severity::Info => 2,
                });
            if let Some(severity) = worst {
                // Diagnostics sit right of the breakpoint column.
                let center = pos2(
                    clip.min.x
                        + metrics.char_width * (super::debug_marks::BREAKPOINT_COLUMN_CHARS + 0.6),
                    top + metrics.row_height * 0.5,
                );
                painter.circle_filled(
                    center,
                    metrics.char_width * 0.35,
                    severity_color(&palette, severity),
                );
            }
        }
        self.paint_debug_gutter(painter, layouts, clip, row_top, metrics);
    }
}

pub(super) fn severity_color(palette: &EditorPalette, severity: Severity) -> Color32 {
    match severity {
        Severity::Error => palette.error,
        Severity::Warning => palette.warning,
        Severity::Info => palette.info,
    }
}

/// A zigzag line from `x0` to `x1` at height `y`, the usual mark of a diagnostic.
fn wavy_line(painter: &Painter, x0: f32, x1: f32, y: f32, color: Color32) {
    let step = 2.0;
    let mut points = Vec::new();
    let mut x = x0;
    let mut up = true;
    while x <= x1 {
        points.push(pos2(x, if up { y - 1.5 } else { y + 1.0 }));
        x += step;
        up = !up;
    }
    if points.len() >= 2 {
        painter.add(egui::Shape::line(points, Stroke::new(1.0, color)));
    }
}
