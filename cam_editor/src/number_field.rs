//! Text fields that keep what the user types as a draft until it is committed, and show why a
//! committed value was refused: the field turns red and the reason shows above the tab.

use std::collections::HashMap;

use egui::{Label, RichText, Role, TextEdit, Ui, WidgetInfo};

/// The drafts of the fields being typed in and the last refusal, kept by the editor between
/// frames and never saved.
#[derive(Clone, Debug, Default)]
pub(crate) struct Drafts {
    /// The text typed into each field, by the field's accessible label.
    texts: HashMap<String, String>,
    /// The field whose committed value was refused, and why.
    pub(crate) refusal: Option<(String, String)>,
}

impl Drafts {
    /// Forgets every draft (the cam changed from elsewhere, such as an undo).
    pub(crate) fn clear(&mut self) {
        self.texts.clear();
        self.refusal = None;
    }

    /// Keeps `text` in the field `label` and says why it was not applied.
    pub(crate) fn refuse(&mut self, label: &str, text: String, reason: String) {
        self.texts.insert(label.to_owned(), text);
        self.refusal = Some((label.to_owned(), reason));
    }

    /// Clears a refusal after an accepted change.
    pub(crate) fn accept(&mut self) {
        self.refusal = None;
    }

    /// The refusal, if any, as a line in the error colour: the field's label and the reason.
    pub(crate) fn refusal_ui(&self, ui: &mut Ui) {
        if let Some((label, reason)) = &self.refusal {
            let text = format!("{label}: {reason}");
            let shown =
                ui.add(Label::new(RichText::new(&text).color(ui.visuals().error_fg_color)).wrap());
            shown.widget_info(|| WidgetInfo::labeled(Role::Label, true, &text));
        }
    }

    /// A single-line field (red while its value is refused; Escape abandons the draft) showing `model_text`, or the draft typed into it. Returns the text
    /// when the user commits it (Enter, Tab or a click elsewhere after typing).
    pub(crate) fn field_ui(
        &mut self,
        ui: &mut Ui,
        label: &str,
        model_text: &str,
        width: f32,
        read_only: bool,
    ) -> Option<String> {
        let mut text = self
            .texts
            .get(label)
            .cloned()
            .unwrap_or_else(|| model_text.to_owned());
        let refused = self
            .refusal
            .as_ref()
            .is_some_and(|(field, _)| field == label);
        let mut committed = None;
        let mut edit = TextEdit::singleline(&mut text)
            .id_salt(("cam field", label))
            .desired_width(width);
        if refused {
            edit = edit.text_color(ui.visuals().error_fg_color);
        }
        let response = ui.add_enabled(!read_only, edit);
        response.widget_info(|| WidgetInfo {
            current_text_value: Some(text.clone()),
            ..WidgetInfo::labeled(Role::TextInput, !read_only, label)
        });
        if response.changed() {
            self.texts.insert(label.to_owned(), text.clone());
        }
        if response.lost_focus()
            && let Some(draft) = self.texts.remove(label)
        {
            // Escape abandons what was typed; the field shows the model's value again.
            if ui.input(|input| input.key_pressed(egui::Key::Escape)) {
                if self
                    .refusal
                    .as_ref()
                    .is_some_and(|(field, _)| field == label)
                {
                    self.refusal = None;
                }
            } else {
                committed = Some(draft);
            }
        }
        committed
    }
}

/// A number as a field shows it: the shortest text that reads back as the same value.
pub(crate) fn number_text(value: f64) -> String {
    if value == 0.0 {
        // Negative zero reads as 0 too.
        "0".to_owned()
    } else {
        format!("{value}")
    }
}

/// A number as a read-only cell shows it: four decimals.
pub(crate) fn rounded_text(value: f64) -> String {
    format!("{value:.4}")
}

/// The finite number in `text`, or `None`.
pub(crate) fn parse_number(text: &str) -> Option<f64> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|value| value.is_finite())
}
