//! What the LD/FBD, CFC and SFC canvases share of egui's input: their accessible name, and
//! the keys a focused canvas keeps for itself.

use egui::{Event, EventFilter, Id, Response, Role, Ui, WidgetInfo};

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
