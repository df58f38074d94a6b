//! The editors of the device tree's nodes, as CODESYS's device editors: the controller (name,
//! address, Modbus map override), I/O areas (direction, start byte, size), serial ports (device
//! file, line settings), Modbus devices (TCP or RTU link, timing, the runtime master's
//! settings, channel table, and while logged in the read-only Online part) and motion axes (task, unit, period, limits, scaling).
//!
//! Each editor draws the node's current value, keeps typed text in a [`DeviceEditorState`] and
//! returns the edits of one gesture as a [`DeviceEdit`]; it never changes the model. A typed
//! value is checked when it is accepted (Enter or focus lost) by `project_model`'s device checks
//! and, for a channel's variable, by `compiler::ide`; a bad one stays in its field in the error
//! colour with the reason beside it and changes nothing.

mod axis;
mod channel_master;
mod channels;
mod controller;
mod field;
mod form;
mod io_area;
mod link_memory;
mod map_ranges;
mod modbus_device;
mod modbus_master;
mod modbus_online;
mod refusal;
mod serial_port;
mod table;
mod texts;

pub use axis::axis_editor_ui;
pub use controller::controller_editor_ui;
pub use field::DeviceEditorState;
pub use io_area::io_area_editor_ui;
pub use modbus_device::modbus_device_editor_ui;
pub use modbus_online::{ModbusOnlinePart, modbus_online_ui};
pub use refusal::{Refusal, RefusalWords};
pub use serial_port::{StandardSilence, serial_port_editor_ui};
pub use texts::DeviceTexts;

use project_model::{DeviceProblem, Edit, new_problem};

use texts::fill;

/// The edits of one gesture in a device editor, with the label of its undo step.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceEdit {
    /// The undo label, in the user's language: "Set port of PLC to 502".
    pub label: String,
    /// The edits, applied in order as one undo step.
    pub edits: Vec<Edit>,
}

/// The edit that gives a node the value `item` under the undo label `label`, refused when
/// `problems` finds in `item` a problem the node's `current` value does not have.
fn checked_edit<T>(
    label: String,
    current: &T,
    item: T,
    problems: impl Fn(&T) -> Vec<DeviceProblem>,
    edit: impl FnOnce(T) -> Edit,
) -> Result<DeviceEdit, Refusal> {
    if let Some(problem) = new_problem(&problems(current), problems(&item)) {
        return Err(Refusal::Problem(problem));
    }
    Ok(DeviceEdit {
        label,
        edits: vec![edit(item)],
    })
}

/// The undo label of a field set to `value` on `node`.
fn set_label(texts: &DeviceTexts, field: &str, node: &str, value: &str) -> String {
    fill(
        &texts.set_field,
        &[
            ("field", &in_sentence(field)),
            ("node", node),
            ("value", value),
        ],
    )
}

/// A field's name inside a sentence: its first letter in lower case, unless the first word is
/// an abbreviation ("I/O task", "ID"), which keeps its capitals.
fn in_sentence(field: &str) -> String {
    let first_word = field.split(' ').next().unwrap_or_default();
    let capitals = first_word.chars().filter(|c| c.is_uppercase()).count();
    let mut chars = field.chars();
    match chars.next() {
        Some(first) if capitals < 2 => first.to_lowercase().chain(chars).collect(),
        _ => field.to_owned(),
    }
}

/// The accessible label of a field of `node`: "Port of PLC".
fn field_label(texts: &DeviceTexts, field: &str, node: &str) -> String {
    fill(&texts.field_of, &[("field", field), ("node", node)])
}

/// The accessible label of a cell of a table row: "Address of row 2".
fn row_label(texts: &DeviceTexts, field: &str, row: usize) -> String {
    fill(
        &texts.field_of_row,
        &[("field", field), ("row", &row.to_string())],
    )
}

/// Keeps the latest edit of the frame: a frame has at most one gesture.
fn keep(out: &mut Option<DeviceEdit>, edit: Option<DeviceEdit>) {
    if edit.is_some() {
        *out = edit;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_field_s_name_in_a_sentence_starts_in_lower_case_but_keeps_abbreviations() {
        assert_eq!(in_sentence("Poll interval"), "poll interval");
        assert_eq!(in_sentence("Own Modbus map"), "own Modbus map");
        assert_eq!(in_sentence("I/O task"), "I/O task");
        assert_eq!(in_sentence("端口"), "端口");
        assert_eq!(in_sentence(""), "");
    }
}
