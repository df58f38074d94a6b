//! The forces pane: every forced variable on the target, with release and release-all.

use egui::{RichText, Ui};

use crate::studio::command::{Command, Commands};
use crate::studio::i18n::Text;
use crate::studio::view::StudioView;

/// Draws the forces pane; releases become commands.
pub(crate) fn forces_ui(view: StudioView<'_>, commands: &mut Commands, ui: &mut Ui) {
    let language = view.language;
    if !view.online.can_write() {
        ui.label(RichText::new(Text::NotOnline.get(language)).weak());
        return;
    }
    let forced = view.online.forced_values();
    ui.horizontal(|ui| {
        if ui
            .add_enabled(
                !forced.is_empty(),
                egui::Button::new(Text::ReleaseForces.get(language)),
            )
            .on_hover_text("Alt+F7")
            .clicked()
        {
            commands.push(Command::ReleaseAllForces);
        }
    });
    ui.separator();
    if forced.is_empty() {
        ui.label(RichText::new(Text::NoForces.get(language)).weak());
        return;
    }
    let mut release = None;
    egui::ScrollArea::vertical()
        .id_salt("forces")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            egui::Grid::new("forces_grid")
                .num_columns(3)
                .striped(true)
                .spacing([16.0, 4.0])
                .show(ui, |ui| {
                    ui.strong(Text::Variable.get(language));
                    ui.strong(Text::Value.get(language));
                    ui.label("");
                    ui.end_row();
                    for value in &forced {
                        ui.label(RichText::new(&value.name).monospace());
                        ui.label(
                            RichText::new(&value.value)
                                .monospace()
                                .color(ui.visuals().error_fg_color),
                        );
                        let button = ui.button(Text::Release.get(language));
                        let name = value.name.clone();
                        let button =
                            button.on_hover_text(format!("{} {name}", Text::Release.get(language)));
                        if button.clicked() {
                            release = Some(value.source.clone());
                        }
                        ui.end_row();
                    }
                });
        });
    if let Some(place) = release {
        commands.push(Command::Unforce(place));
    }
}
