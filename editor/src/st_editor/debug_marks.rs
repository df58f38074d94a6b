//! What the debugger shows in the Structured Text editor: breakpoints in the gutter, the
//! current statement of a halted task (a yellow arrow and a highlighted line, as CODESYS shows
//! it) and the flow-control bars of the statements that ran in the last cycle.
//!
//! The editor only draws these marks from plain data the app gives it and reports where the
//! user asked for a breakpoint; it knows nothing of targets or sessions.

use egui::{Painter, Rect, Shape, Stroke, pos2, vec2};

use crate::EditorPalette;

use super::StEditor;
use super::layout::{LineLayout, Metrics};

/// How a breakpoint looks in the gutter, from what the user set on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BreakpointLook {
    /// A plain breakpoint: a filled circle.
    Enabled,
    /// A breakpoint that is switched off: a ring.
    Disabled,
    /// A breakpoint with a condition: a filled circle with a bar across.
    Conditional,
    /// A breakpoint with a hit count (and perhaps a condition): a filled circle with a dot.
    HitCount,
}

/// A breakpoint on one line of the text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BreakpointMark {
    /// The line, counted from 0.
    pub line: usize,
    /// How it looks.
    pub look: BreakpointLook,
}

/// The debugger's marks for one text, given by the app every frame (empty when offline).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StDebugMarks {
    /// The breakpoints on lines of this text.
    pub breakpoints: Vec<BreakpointMark>,
    /// The line (from 0) of the statement where a task is halted in this text, or where the
    /// shown frame of the call stack is; it has not run yet.
    pub halt_line: Option<usize>,
    /// Whether `halt_line` is the halt itself (the yellow arrow) or a caller's line (a hollow
    /// arrow, as CODESYS marks the frames below the halt).
    pub halt_is_caller: bool,
    /// The lines (from 0) of the statements that ran in the last cycle (flow control).
    pub flow_lines: Vec<usize>,
}

impl StDebugMarks {
    /// The look of the breakpoint on `line`, if there is one.
    pub fn breakpoint_at(&self, line: usize) -> Option<BreakpointLook> {
        self.breakpoints
            .iter()
            .find(|mark| mark.line == line)
            .map(|mark| mark.look)
    }
}

/// The width of the breakpoint column at the gutter's left, in monospace chars.
pub(super) const BREAKPOINT_COLUMN_CHARS: f32 = 2.0;

impl StEditor {
    /// The debugger's marks to draw until replaced; an empty value removes them.
    pub fn set_debug_marks(&mut self, marks: StDebugMarks) {
        self.debug_marks = marks;
    }

    /// The debugger's marks being drawn.
    pub fn debug_marks(&self) -> &StDebugMarks {
        &self.debug_marks
    }

    /// The line the caret is on, counted from 0: where F9 and "run to cursor" act.
    pub fn caret_line(&self) -> usize {
        self.buffer.line_of(self.caret)
    }

    /// The halted statement's line across the text, drawn under the text.
    pub(super) fn paint_halt_line(
        &self,
        painter: &Painter,
        layouts: &[LineLayout],
        clip: Rect,
        row_top: &dyn Fn(usize) -> f32,
        metrics: &Metrics,
    ) {
        let Some(halt_line) = self.debug_marks.halt_line else {
            return;
        };
        let palette = EditorPalette::in_context(painter.ctx());
        for layout in layouts.iter().filter(|layout| layout.line == halt_line) {
            let area = Rect::from_min_size(
                pos2(clip.min.x, row_top(layout.row)),
                vec2(clip.width(), metrics.row_height),
            );
            let fill = if self.debug_marks.halt_is_caller {
                palette.halt_line.gamma_multiply(0.5)
            } else {
                palette.halt_line
            };
            painter.rect_filled(area, 0.0, fill);
        }
    }

    /// Breakpoints, the halt arrow and the flow bars in the gutter, over its background.
    pub(super) fn paint_debug_gutter(
        &self,
        painter: &Painter,
        layouts: &[LineLayout],
        clip: Rect,
        row_top: &dyn Fn(usize) -> f32,
        metrics: &Metrics,
    ) {
        let palette = EditorPalette::in_context(painter.ctx());
        let radius = metrics.char_width.min(metrics.row_height * 0.5) * 0.55;
        let center_x = clip.min.x + metrics.char_width * BREAKPOINT_COLUMN_CHARS * 0.5;
        for layout in layouts {
            let top = row_top(layout.row);
            let center = pos2(center_x, top + metrics.row_height * 0.5);
            if let Some(look) = self.debug_marks.breakpoint_at(layout.line) {
                paint_breakpoint(painter, center, radius, look, &palette);
            }
            if self.debug_marks.flow_lines.contains(&layout.line) {
                let x = clip.min.x + metrics.gutter_width - metrics.char_width * 0.4;
                let bar = Rect::from_min_max(
                    pos2(x, top),
                    pos2(x + metrics.char_width * 0.3, top + metrics.row_height),
                );
                painter.rect_filled(bar, 0.0, palette.flow_mark);
            }
            if self.debug_marks.halt_line == Some(layout.line) {
                paint_halt_arrow(
                    painter,
                    center,
                    radius,
                    self.debug_marks.halt_is_caller,
                    &palette,
                );
            }
        }
    }
}

/// One breakpoint's symbol, as CODESYS draws them: red and filled when on, a ring when off.
pub(crate) fn paint_breakpoint(
    painter: &Painter,
    center: egui::Pos2,
    radius: f32,
    look: BreakpointLook,
    palette: &EditorPalette,
) {
    match look {
        BreakpointLook::Disabled => {
            painter.circle_stroke(center, radius, Stroke::new(1.5, palette.breakpoint));
        }
        BreakpointLook::Enabled => {
            painter.circle_filled(center, radius, palette.breakpoint);
        }
        BreakpointLook::Conditional => {
            painter.circle_filled(center, radius, palette.breakpoint);
            painter.line_segment(
                [
                    center - vec2(radius * 0.6, 0.0),
                    center + vec2(radius * 0.6, 0.0),
                ],
                Stroke::new(1.5, palette.breakpoint_symbol),
            );
        }
        BreakpointLook::HitCount => {
            painter.circle_filled(center, radius, palette.breakpoint);
            painter.circle_filled(center, radius * 0.3, palette.breakpoint_symbol);
        }
    }
}

/// The arrow that points at the halted statement: filled for the halt, hollow for a caller.
pub(crate) fn paint_halt_arrow(
    painter: &Painter,
    center: egui::Pos2,
    radius: f32,
    caller: bool,
    palette: &EditorPalette,
) {
    let points = vec![
        center + vec2(-radius, -radius * 0.7),
        center + vec2(radius * 0.2, -radius * 0.7),
        center + vec2(radius, 0.0),
        center + vec2(radius * 0.2, radius * 0.7),
        center + vec2(-radius, radius * 0.7),
    ];
    let outline = Stroke::new(1.0, palette.halt_outline);
    if caller {
        painter.add(Shape::closed_line(points, outline));
    } else {
        painter.add(Shape::convex_polygon(points, palette.halt_marker, outline));
    }
}
