//! What the debugger shows in a graphical body (LD, FBD, CFC, SFC): breakpoints on networks
//! and elements, the halted element (CODESYS's yellow arrow) and the flow-control bars of the
//! elements that ran in the last cycle (`docs/debugging.md` §3 and §5).
//!
//! Like [`crate::StDebugMarks`] for text, the editors only draw these marks from plain data
//! the app gives them and report where the user asked for a breakpoint.

use egui::{Painter, Pos2, Rect, pos2, vec2};
use project_model::ElementId;

use crate::st_editor::{paint_breakpoint, paint_halt_arrow};
use crate::{BreakpointLook, EditorPalette};

/// A network of a body, or one element of it; CFC and SFC charts are network 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyPlace {
    /// The network's index in the body, from 0.
    pub network: usize,
    /// The element's stable id, or `None` for the network itself (its first statement).
    pub element: Option<ElementId>,
}

/// A breakpoint on a network or element.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyBreakpointMark {
    /// Where it is.
    pub place: BodyPlace,
    /// How it looks.
    pub look: BreakpointLook,
}

/// The debugger's marks for one graphical body, given by the app (empty when offline).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BodyDebugMarks {
    /// The breakpoints of this body.
    pub breakpoints: Vec<BodyBreakpointMark>,
    /// The element (or network) whose statement a task is halted at, or the shown frame's;
    /// it has not run yet.
    pub halt: Option<BodyPlace>,
    /// Whether `halt` is a caller's place (a hollow arrow) rather than the halt itself.
    pub halt_is_caller: bool,
    /// The elements (and networks) whose statements ran in the last cycle (flow control).
    pub flow: Vec<BodyPlace>,
}

impl BodyDebugMarks {
    /// The look of the breakpoint on exactly `place`, if there is one.
    pub fn breakpoint_at(&self, place: BodyPlace) -> Option<BreakpointLook> {
        self.breakpoints
            .iter()
            .find(|mark| mark.place == place)
            .map(|mark| mark.look)
    }

    /// Whether any statement of network `network` ran in the last cycle.
    pub fn network_flowed(&self, network: usize) -> bool {
        self.flow.iter().any(|place| place.network == network)
    }

    /// Whether the statement of `element` ran in the last cycle.
    pub fn element_flowed(&self, element: ElementId) -> bool {
        self.flow.iter().any(|place| place.element == Some(element))
    }

    /// Whether there is nothing to draw.
    pub fn is_empty(&self) -> bool {
        self.breakpoints.is_empty() && self.halt.is_none() && self.flow.is_empty()
    }
}

/// Paints a network's marks in the margin left of it: its breakpoint, the halt arrow when the
/// halt is in it and a flow bar beside it when some of it ran. `center` is where the symbols
/// go, `bar` the rectangle of the flow bar, `radius` the symbols' size in points.
pub(crate) fn paint_network_marks(
    painter: &Painter,
    marks: &BodyDebugMarks,
    network: usize,
    center: Pos2,
    bar: Rect,
    radius: f32,
) {
    let palette = EditorPalette::in_context(painter.ctx());
    if marks.network_flowed(network) {
        painter.rect_filled(bar, 0.0, palette.flow_mark);
    }
    let place = BodyPlace {
        network,
        element: None,
    };
    if let Some(look) = marks.breakpoint_at(place) {
        paint_breakpoint(painter, center, radius, look, &palette);
    }
    if marks.halt.is_some_and(|halt| halt.network == network) {
        paint_halt_arrow(painter, center, radius, marks.halt_is_caller, &palette);
    }
}

/// Paints an element's marks over its rectangle `rect` on screen: the halted element's
/// background and arrow at its top left, its breakpoint at its top right and a flow bar along
/// its bottom when it ran.
pub(crate) fn paint_element_marks(
    painter: &Painter,
    marks: &BodyDebugMarks,
    network: usize,
    element: ElementId,
    rect: Rect,
    radius: f32,
) {
    let palette = EditorPalette::in_context(painter.ctx());
    let place = BodyPlace {
        network,
        element: Some(element),
    };
    if marks.halt.is_some_and(|halt| halt.element == Some(element)) {
        let fill = if marks.halt_is_caller {
            palette.halt_line.gamma_multiply(0.5)
        } else {
            palette.halt_line
        };
        painter.rect_filled(rect, 2.0, fill);
        paint_halt_arrow(
            painter,
            pos2(rect.left() - radius * 1.2, rect.top() + radius),
            radius,
            marks.halt_is_caller,
            &palette,
        );
    }
    if marks.element_flowed(element) {
        let bar = Rect::from_min_max(
            pos2(rect.left(), rect.bottom() - radius * 0.4),
            rect.right_bottom(),
        );
        painter.rect_filled(bar, 0.0, palette.flow_mark);
    }
    if let Some(look) = marks.breakpoint_at(place) {
        paint_breakpoint(
            painter,
            rect.right_top() + vec2(-radius, radius),
            radius,
            look,
            &palette,
        );
    }
}
