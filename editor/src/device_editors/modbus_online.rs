//! The Modbus device editor's read-only "Online" part (`docs/modbus-master.md` §9.2): while
//! logged in, a runtime device's state, its last error in words and the master's counters, as
//! the app worded them from the runtime's `MODBUS_DEVICES` report.

use egui::{Color32, RichText, Ui};

/// What the Online part shows, every word already in the user's language; made by the app
/// each frame from the last report and not kept.
#[derive(Clone, Copy, Debug)]
pub struct ModbusOnlinePart<'a> {
    /// The device's name, which keeps the part's layout apart from other devices'.
    pub device: &'a str,
    /// The part's heading: "Online".
    pub heading: &'a str,
    /// The label of the state's row: "State".
    pub state_label: &'a str,
    /// The state in words: "Not answering".
    pub state: &'a str,
    /// The theme's colour of the state, also the colour of the device tree's icon.
    pub state_color: Color32,
    /// The last error and the counters, each a label and its value, in the order shown.
    pub rows: &'a [(String, String)],
}

/// Draws the Online part: a heading, then the state and each row as a label and its value.
/// Nothing in it can be edited.
pub fn modbus_online_ui(ui: &mut Ui, part: &ModbusOnlinePart<'_>) {
    ui.strong(part.heading);
    egui::Grid::new(("modbus online", part.device))
        .num_columns(2)
        .spacing([12.0, 4.0])
        .show(ui, |ui| {
            ui.label(part.state_label);
            ui.label(RichText::new(part.state).strong().color(part.state_color));
            ui.end_row();
            for (label, value) in part.rows {
                ui.label(label);
                ui.label(value);
                ui.end_row();
            }
        });
    ui.separator();
}
