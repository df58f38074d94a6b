//! A read-only view of a cam table: ranges, the segment table and the tappet table, laid out
//! as the CODESYS cam table and tappet table tabs are.

use egui::{RichText, Ui};
use project_model::{CamProfile, CamTable, TappetAction};

use super::i18n::{Language, Text};

/// Draws `cam` as tables.
pub fn cam_view_ui(ui: &mut Ui, cam: &CamTable, language: Language) {
    let t = |text: Text| text.get(language);
    if !cam.comment.is_empty() {
        ui.label(&cam.comment);
        ui.add_space(6.0);
    }
    egui::Grid::new(ui.make_persistent_id(("cam_ranges", &cam.name)))
        .num_columns(2)
        .spacing([24.0, 4.0])
        .show(ui, |ui| {
            ui.strong(t(Text::CamMaster));
            ui.label(format!(
                "{} .. {} {}",
                cam.master.start, cam.master.end, cam.master.unit
            ));
            ui.end_row();
            ui.strong(t(Text::CamSlave));
            ui.label(format!(
                "{} .. {} {}",
                cam.slave.start, cam.slave.end, cam.slave.unit
            ));
            ui.end_row();
            ui.strong(t(Text::CompileFormat));
            ui.label(format!("{:?}", cam.compile_format));
            ui.end_row();
        });
    ui.add_space(8.0);
    match &cam.profile {
        CamProfile::Segments { start, segments } => {
            ui.label(RichText::new(t(Text::Segments)).strong());
            egui::Grid::new(ui.make_persistent_id(("cam_segments", &cam.name)))
                .striped(true)
                .spacing([18.0, 4.0])
                .show(ui, |ui| {
                    for title in [
                        "#",
                        t(Text::Law),
                        t(Text::MasterFrom),
                        t(Text::MasterTo),
                        t(Text::SlaveFrom),
                        t(Text::SlaveTo),
                        t(Text::VelocityEnd),
                        t(Text::AccelerationEnd),
                    ] {
                        ui.label(RichText::new(title).strong());
                    }
                    ui.end_row();
                    let mut from = *start;
                    for (index, segment) in segments.iter().enumerate() {
                        ui.label((index + 1).to_string());
                        ui.label(format!("{:?}", segment.law));
                        for value in [
                            from.master,
                            segment.end.master,
                            from.slave,
                            segment.end.slave,
                            segment.end.velocity,
                            segment.end.acceleration,
                        ] {
                            ui.monospace(format!("{value:.3}"));
                        }
                        ui.end_row();
                        from = segment.end;
                    }
                });
        }
        CamProfile::Points {
            interpolation,
            points,
        } => {
            ui.label(RichText::new(format!("{} ({interpolation:?})", t(Text::Points))).strong());
            egui::Grid::new(ui.make_persistent_id(("cam_points", &cam.name)))
                .striped(true)
                .spacing([18.0, 4.0])
                .show(ui, |ui| {
                    for title in ["#", t(Text::CamMaster), t(Text::CamSlave)] {
                        ui.label(RichText::new(title).strong());
                    }
                    ui.end_row();
                    for (index, point) in points.iter().enumerate() {
                        ui.label((index + 1).to_string());
                        ui.monospace(format!("{:.3}", point.master));
                        ui.monospace(format!("{:.3}", point.slave));
                        ui.end_row();
                    }
                });
        }
    }
    if cam.tracks.is_empty() {
        return;
    }
    ui.add_space(8.0);
    ui.label(RichText::new(t(Text::Tappets)).strong());
    egui::Grid::new(ui.make_persistent_id(("cam_tappets", &cam.name)))
        .striped(true)
        .spacing([18.0, 4.0])
        .show(ui, |ui| {
            for title in [
                t(Text::Track),
                t(Text::Name),
                t(Text::Position),
                t(Text::PositivePass),
                t(Text::NegativePass),
            ] {
                ui.label(RichText::new(title).strong());
            }
            ui.end_row();
            for track in &cam.tracks {
                for tappet in &track.tappets {
                    ui.label(track.id.to_string());
                    ui.label(&track.name);
                    ui.monospace(format!("{:.3}", tappet.position));
                    ui.label(action_text(tappet.on_positive, language));
                    ui.label(action_text(tappet.on_negative, language));
                    ui.end_row();
                }
            }
        });
}

/// The CODESYS wording of a tappet action.
fn action_text(action: TappetAction, language: Language) -> String {
    let text = match action {
        TappetAction::None => Text::NoAction,
        TappetAction::On => Text::SwitchOn,
        TappetAction::Off => Text::SwitchOff,
        TappetAction::Invert => Text::Invert,
        TappetAction::TimedOn { duration_us } => {
            let millis = f64::from(duration_us) / 1000.0;
            return format!("{} {millis} ms", Text::OnFor.get(language));
        }
    };
    text.get(language).to_owned()
}
