//! What the LD/FBD, CFC and SFC canvases share of egui's input: their accessible name, the
//! keys a focused canvas keeps for itself, and zooming and panning.

use egui::{
    Event, EventFilter, Id, PointerButton, Pos2, Rect, Response, Role, Sense, Ui, Vec2, WidgetInfo,
};

/// The smallest and largest zoom factors of the graphical editors.
pub(crate) const ZOOM_RANGE: (f32, f32) = (0.25, 4.0);

/// Allocates a canvas of `size` with the id `id`, named `label`, that takes the keyboard
/// focus when it was asked for (`focus_requested`, cleared here) or when clicked or dragged.
pub(crate) fn canvas_response(
    ui: &mut Ui,
    size: Vec2,
    id: Id,
    label: &str,
    focus_requested: &mut bool,
) -> Response {
    let (_, rect) = ui.allocate_space(size);
    let response = ui.interact(rect, id, Sense::click_and_drag());
    describe_canvas(ui, &response, label);
    if std::mem::take(focus_requested) || response.clicked() || response.drag_started() {
        response.request_focus();
    }
    response
}

/// Names the canvas `response` for screen readers and tests as a canvas labelled `label`.
pub(crate) fn describe_canvas(ui: &Ui, response: &Response, label: &str) {
    let enabled = ui.is_enabled();
    let label = label.to_owned();
    response.widget_info(|| WidgetInfo::labeled(Role::Canvas, enabled, &label));
}

/// The events of this frame for the focused canvas `id`. The arrows and Escape stay with the
/// canvas (they move its selection, not egui's focus); Tab still moves the focus on.
pub(crate) fn focused_canvas_events(ui: &Ui, id: Id) -> Vec<Event> {
    let filter = EventFilter {
        tab: false,
        horizontal_arrows: true,
        vertical_arrows: true,
        escape: true,
    };
    ui.memory_mut(|memory| memory.set_focus_lock_filter(id, filter));
    ui.input(|input| input.filtered_events(&filter))
}

/// The zoom and scroll of a canvas in a scroll area: what [`zoom_and_pan_ui`] changes.
pub(crate) struct CanvasView<'a> {
    /// Points on screen per point of content.
    pub zoom: &'a mut f32,
    /// The scroll offset to apply in the next frame.
    pub pending_offset: &'a mut Option<Vec2>,
    /// The scroll offset of the last frame.
    pub scroll_offset: Vec2,
}

/// Zooms the canvas `response` with Ctrl and the wheel (or a pinch) so that the content point
/// under the mouse stays under it, and pans it with the middle button. `origin` is the
/// content's top-left corner on screen, `viewport` the visible part of the scroll area.
pub(crate) fn zoom_and_pan_ui(
    ui: &Ui,
    response: &Response,
    origin: Pos2,
    viewport: Rect,
    view: CanvasView<'_>,
) {
    if let Some(pointer) = response.hover_pos() {
        let factor = ui.input(|input| input.zoom_delta());
        if (factor - 1.0).abs() > f32::EPSILON {
            let zoom = (*view.zoom * factor).clamp(ZOOM_RANGE.0, ZOOM_RANGE.1);
            let under_mouse = (pointer - origin) / *view.zoom;
            let in_viewport = pointer - (origin + viewport.min.to_vec2());
            *view.pending_offset = Some((under_mouse * zoom - in_viewport).max(Vec2::ZERO));
            *view.zoom = zoom;
        }
    }
    if response.dragged_by(PointerButton::Middle) {
        *view.pending_offset = Some((view.scroll_offset - response.drag_delta()).max(Vec2::ZERO));
    }
}
