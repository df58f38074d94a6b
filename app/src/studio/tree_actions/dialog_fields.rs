//! The fields the device tree's dialogs share: a labelled name or type, and the choice of the
//! implementation language.

use egui::{Key, Ui};

use super::body_language::BodyLanguage;
use crate::studio::i18n::{Language, Text};

/// A labelled single-line field; true when Enter was pressed in it. The first field of a
/// dialog takes the keyboard focus once, so the user can type right away.
pub(super) fn text_field(ui: &mut Ui, label: &str, text: &mut String, focused: &mut bool) -> bool {
    ui.horizontal(|ui| {
        let label = ui.label(label);
        let response = ui
            .add(egui::TextEdit::singleline(text).desired_width(220.0))
            .labelled_by(label.id);
        if !*focused {
            response.request_focus();
            *focused = true;
        }
        response.lost_focus() && ui.input(|input| input.key_pressed(Key::Enter))
    })
    .inner
}

/// The implementation language as one radio button per offered language, under its label.
/// SFC is offered only where a chart may be (`sfc_allowed`: the body of a program or function
/// block itself); a choice of SFC elsewhere falls back to ST.
pub(super) fn body_language_ui(
    ui: &mut Ui,
    chosen: &mut BodyLanguage,
    language: Language,
    sfc_allowed: bool,
) {
    if !sfc_allowed && *chosen == BodyLanguage::Sfc {
        *chosen = BodyLanguage::St;
    }
    ui.label(Text::ImplementationLanguage.get(language));
    ui.horizontal_wrapped(|ui| {
        for offered in BodyLanguage::OFFERED {
            if offered != BodyLanguage::Sfc || sfc_allowed {
                ui.radio_value(chosen, offered, offered.text().get(language));
            }
        }
    });
}
