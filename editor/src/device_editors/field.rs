//! The pieces every device editor is made of: typed text fields accepted on Enter or when
//! left, combo boxes and check boxes, each refusing a bad value in place with its reason.

use std::any::Any;
use std::collections::HashMap;

use egui::{Key, RichText, Ui, WidgetInfo};

use super::DeviceEdit;
use super::link_memory::LinkMemory;
use super::refusal::Refusal;
use super::texts::DeviceTexts;

/// What a device editor keeps between frames: text typed into a field and not yet accepted,
/// and why a value was refused, per field. Both are dropped when the node's value changes
/// (an undo, an edit from elsewhere), so a field never shows a stale draft. Not saved.
#[derive(Debug, Default)]
pub struct DeviceEditorState {
    /// Typed text not yet accepted, by field key.
    drafts: HashMap<String, String>,
    /// Why the last value given to a field was refused, by field key.
    refused: HashMap<String, Refusal>,
    /// A copy of the node's value the drafts belong to; `None` before the first frame.
    seen: Option<Box<dyn Any>>,
    /// The option a combo box shows without it being applied yet, by field key: a choice that
    /// needs another field first (a rising edge needs its trigger variable). Dropped with the
    /// drafts when the node's value changes.
    pending: HashMap<String, usize>,
    /// A Modbus device's last link of each kind, so switching the kind back restores it; kept
    /// when the value changes, unlike the drafts.
    pub(crate) links: LinkMemory,
}

impl DeviceEditorState {
    /// Carries a serial port's rename from `old` to `new` into what the editor remembers, so a
    /// device switched to TCP and back onto RTU returns to the port it was on under its new
    /// name; the studio calls it for every node's state when a port is renamed (or a rename is
    /// undone).
    pub fn serial_port_renamed(&mut self, old: &str, new: &str) {
        self.links.serial_port_renamed(old, new);
    }

    /// Forgets drafts and refusals when the node's value is no longer the one they were typed
    /// against.
    ///
    /// The value is compared with a copy of the one last seen rather than printed, so a device
    /// with hundreds of channels costs a comparison per frame, not an allocation per field.
    pub(crate) fn follow<T: Clone + PartialEq + 'static>(&mut self, value: &T) {
        let same = self
            .seen
            .as_ref()
            .and_then(|seen| seen.downcast_ref::<T>())
            .is_some_and(|seen| seen == value);
        if !same {
            self.drafts.clear();
            self.refused.clear();
            self.pending.clear();
            self.seen = Some(Box::new(value.clone()));
        }
    }

    /// Whether the combo box `key` shows a choice that waits for another field.
    pub(crate) fn is_pending(&self, key: &str) -> bool {
        self.pending.contains_key(key)
    }

    /// Why the value last given to the field `key` was refused, if it was.
    pub fn refusal(&self, key: &str) -> Option<&Refusal> {
        self.refused.get(key)
    }

    /// Records the outcome of a change of field `key`: the edit, or the reason it was refused.
    pub(crate) fn settle(
        &mut self,
        key: &str,
        outcome: Result<DeviceEdit, Refusal>,
    ) -> Option<DeviceEdit> {
        match outcome {
            Ok(edit) => {
                self.drafts.remove(key);
                self.refused.remove(key);
                Some(edit)
            }
            Err(reason) => {
                self.refused.insert(key.to_owned(), reason);
                None
            }
        }
    }
}

/// A field being drawn: its key in the state, its accessible label and its width.
pub(crate) struct FieldId<'a> {
    /// The key of its draft and refusal.
    pub key: &'a str,
    /// What screen readers and tests call it: "Port of PLC".
    pub label: &'a str,
    /// Its width in points.
    pub width: f32,
}

/// A single-line field showing `current`; typed text is given to `accept` when the field is
/// left (Enter, Tab or a click elsewhere). A refused text stays, in the error colour, with the
/// reason beside it; Escape puts the current value back.
pub(crate) fn text_field_ui(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    field: FieldId<'_>,
    current: &str,
    suffix: &str,
    accept: impl FnOnce(&str) -> Result<DeviceEdit, Refusal>,
) -> Option<DeviceEdit> {
    let mut text = state
        .drafts
        .get(field.key)
        .cloned()
        .unwrap_or_else(|| current.to_owned());
    let mut edit = None;
    ui.horizontal(|ui| {
        let refused = state.refused.contains_key(field.key);
        let mut editor = egui::TextEdit::singleline(&mut text).desired_width(field.width);
        if refused {
            editor = editor.text_color(ui.visuals().error_fg_color);
        }
        // A sized allocation, because a grid's middle column would otherwise squeeze the field
        // to the width of its title.
        let size = egui::vec2(field.width, ui.spacing().interact_size.y);
        let response = ui.add_sized(size, editor);
        let label = field.label.to_owned();
        response.widget_info(|| WidgetInfo::labeled(egui::Role::TextInput, true, label.clone()));
        if response.changed() {
            state.drafts.insert(field.key.to_owned(), text.clone());
            state.refused.remove(field.key);
        }
        if response.lost_focus() {
            let escaped = ui.input(|input| input.key_pressed(Key::Escape));
            if escaped || text.trim() == current.trim() {
                state.drafts.remove(field.key);
                state.refused.remove(field.key);
            } else {
                edit = state.settle(field.key, accept(text.trim()));
            }
        }
        if !suffix.is_empty() {
            ui.label(RichText::new(suffix).weak());
        }
        reason_ui(ui, state, texts, field.key);
    });
    edit
}

/// A combo box of `options` showing the one equal to `current`; a choice is given to `accept`.
pub(crate) fn combo_ui<T: PartialEq + Copy>(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    field: FieldId<'_>,
    current: T,
    options: &[(String, T)],
    accept: impl FnOnce(T) -> Result<DeviceEdit, Refusal>,
) -> Option<DeviceEdit> {
    pending_combo_ui(ui, state, texts, field, current, options, |_| false, accept)
}

/// A combo box of `options` whose choice waits, shown but not applied, while `waits` says it
/// needs another field first; the other field's edit applies it (and drops the wait, as any
/// change of the node does). Any other choice is given to `accept`. Shows the option equal to
/// `current` when nothing waits.
#[allow(clippy::too_many_arguments)]
pub(crate) fn pending_combo_ui<T: PartialEq + Copy>(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    field: FieldId<'_>,
    current: T,
    options: &[(String, T)],
    waits: impl Fn(T) -> bool,
    accept: impl FnOnce(T) -> Result<DeviceEdit, Refusal>,
) -> Option<DeviceEdit> {
    let shown = state
        .pending
        .get(field.key)
        .and_then(|&index| options.get(index))
        .map_or(current, |(_, value)| *value);
    let value = combo_choice_ui(ui, state, texts, &field, shown, options)?;
    state.refused.remove(field.key);
    if waits(value) {
        let index = options.iter().position(|(_, option)| *option == value)?;
        state.pending.insert(field.key.to_owned(), index);
        return None;
    }
    state.pending.remove(field.key);
    if value == current {
        // Back to the value the node has: only the wait is dropped.
        return None;
    }
    state.settle(field.key, accept(value))
}

/// Draws a combo box of `options` showing the one equal to `current`, with the field's refusal
/// beside it, and returns the option chosen this frame, if another than `current`.
fn combo_choice_ui<T: PartialEq + Copy>(
    ui: &mut Ui,
    state: &DeviceEditorState,
    texts: &DeviceTexts,
    field: &FieldId<'_>,
    current: T,
    options: &[(String, T)],
) -> Option<T> {
    let shown = options
        .iter()
        .find(|(_, value)| *value == current)
        .map(|(text, _)| text.clone())
        .unwrap_or_default();
    let mut chosen = None;
    ui.horizontal(|ui| {
        let label = field.label.to_owned();
        egui::ComboBox::from_id_salt(("device combo", field.key))
            .selected_text(shown)
            .width(field.width)
            .show_ui(ui, |ui| {
                for (text, value) in options {
                    if ui.selectable_label(*value == current, text).clicked() && *value != current {
                        chosen = Some(*value);
                    }
                }
            })
            .response
            .widget_info(|| WidgetInfo::labeled(egui::Role::ComboBox, true, label.clone()));
        reason_ui(ui, state, texts, field.key);
    });
    chosen
}

/// A check box; a change is given to `accept`, and a refusal is shown beside it.
pub(crate) fn checkbox_ui(
    ui: &mut Ui,
    state: &mut DeviceEditorState,
    texts: &DeviceTexts,
    field: FieldId<'_>,
    text: &str,
    current: bool,
    accept: impl FnOnce(bool) -> Result<DeviceEdit, Refusal>,
) -> Option<DeviceEdit> {
    let mut checked = current;
    let mut edit = None;
    ui.horizontal(|ui| {
        let response = ui.checkbox(&mut checked, text);
        let label = field.label.to_owned();
        response.widget_info(|| WidgetInfo::labeled(egui::Role::CheckBox, true, label.clone()));
        if response.changed() {
            edit = state.settle(field.key, accept(checked));
        }
        reason_ui(ui, state, texts, field.key);
    });
    edit
}

/// The reason the field `key` was refused, in the error colour, if it was.
pub(crate) fn reason_ui(ui: &mut Ui, state: &DeviceEditorState, texts: &DeviceTexts, key: &str) {
    if let Some(refusal) = state.refused.get(key) {
        let reason = texts.refusal.describe(refusal);
        ui.label(RichText::new(reason).color(ui.visuals().error_fg_color));
    }
}

/// Reads a whole number from `min` to `max`, or says it is not one.
pub(crate) fn parse_whole<T>(text: &str, min: T, max: T) -> Result<T, Refusal>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display + Copy,
{
    text.parse::<T>()
        .ok()
        .filter(|value| *value >= min && *value <= max)
        .ok_or_else(|| Refusal::NotAWholeNumber {
            text: text.to_owned(),
            min: min.to_string(),
            max: max.to_string(),
        })
}

/// Reads a finite number, or says it is not one.
pub(crate) fn parse_number(text: &str) -> Result<f64, Refusal> {
    text.parse::<f64>()
        .ok()
        .filter(|value| value.is_finite())
        .ok_or_else(|| Refusal::NotANumber {
            text: text.to_owned(),
        })
}

/// A label and its field as one row of a two-column grid.
pub(crate) fn row_ui<R>(ui: &mut Ui, label: &str, add: impl FnOnce(&mut Ui) -> R) -> R {
    ui.label(label);
    let result = add(ui);
    ui.end_row();
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drafts_and_refusals_stay_while_the_value_is_the_same_and_go_when_it_changes() {
        let mut state = DeviceEditorState::default();
        let value = vec![1, 2, 3];
        state.follow(&value);
        state.drafts.insert("port".into(), "50x".into());
        let refusal = parse_whole("50x", 0u16, u16::MAX).unwrap_err();
        assert_eq!(state.settle("port", Err(refusal.clone())), None);
        state.follow(&value.clone());
        assert_eq!(state.refusal("port"), Some(&refusal));
        assert!(state.drafts.contains_key("port"));
        state.follow(&vec![1, 2, 4]);
        assert_eq!(state.refusal("port"), None);
        assert!(state.drafts.is_empty());
    }
}
