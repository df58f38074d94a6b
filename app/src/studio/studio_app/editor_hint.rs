//! What the editor area shows while no document is open.

use egui::Ui;

use crate::studio::i18n::Text;
use crate::studio::view::StudioView;

/// Draws the project and how to start into the empty editor area `rect`.
pub(super) fn editor_area_hint(ui: &mut Ui, rect: egui::Rect, view: StudioView<'_>) {
    let language = view.language;
    let mut lines = Vec::new();
    match view.session {
        Some(session) => {
            lines.push((session.title(), 20.0, ui.visuals().strong_text_color()));
            if !session.project.description.is_empty() {
                lines.push((
                    session.project.description.clone(),
                    13.0,
                    ui.visuals().text_color(),
                ));
            }
            lines.push((
                Text::OpenObjectHint.get(language).to_owned(),
                13.0,
                ui.visuals().weak_text_color(),
            ));
            lines.push((
                Text::StartKeysHint.get(language).to_owned(),
                13.0,
                ui.visuals().weak_text_color(),
            ));
        }
        None => lines.push((
            Text::NoProjectHint.get(language).to_owned(),
            13.0,
            ui.visuals().weak_text_color(),
        )),
    }
    let painter = ui.painter_at(rect);
    let mut y = rect.center().y - 40.0;
    for (text, size, color) in lines {
        let galley = painter.layout(
            text,
            egui::FontId::proportional(size),
            color,
            (rect.width() - 40.0).max(100.0),
        );
        let x = rect.center().x - galley.size().x / 2.0;
        let height = galley.size().y;
        painter.galley(egui::pos2(x, y), galley, color);
        y += height + 8.0;
    }
}
