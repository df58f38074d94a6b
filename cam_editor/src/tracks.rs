//! The tappets tab: each track's name, hysteresis and dead-time compensation, its tappets'
//! positions and pass actions, and adding and removing tracks.

use egui::{ComboBox, Role, Ui, WidgetInfo};
use project_model::{CamTable, TappetAction, TappetTrack};

use crate::editor::{Frame, Gesture};
use crate::number_field::{Drafts, number_text, parse_number};
use crate::tappet_lanes::{action_text, track_label};

/// The actions the pass menus offer (a timed action stays as it is until another is chosen).
const ACTIONS: [TappetAction; 4] = [
    TappetAction::None,
    TappetAction::On,
    TappetAction::Off,
    TappetAction::Invert,
];

/// Draws the tracks of `frame.cam`; a committed field, a chosen action or an added or removed
/// track gives the gesture.
pub(crate) fn tracks_ui(ui: &mut Ui, drafts: &mut Drafts, frame: &Frame<'_>) -> Option<Gesture> {
    let texts = frame.texts;
    let cam = frame.cam;
    let mut gesture = None;
    egui::ScrollArea::vertical()
        .id_salt("cam tracks")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for (track_index, track) in cam.tracks.iter().enumerate() {
                let name = track_label(texts, track.id);
                ui.horizontal(|ui| {
                    ui.strong(&name);
                    let label = format!("{name} {}", texts.name);
                    ui.label(&texts.name);
                    if let Some(text) =
                        drafts.field_ui(ui, &label, &track.name, 140.0, frame.read_only)
                    {
                        let changed =
                            with_track(cam, track_index, |t| t.name = text.trim().to_owned());
                        gesture = Some(Gesture::edit(label, changed));
                    }
                    let label = format!("{name} {}", texts.hysteresis);
                    ui.label(&texts.hysteresis);
                    if let Some(text) = drafts.field_ui(
                        ui,
                        &label,
                        &number_text(track.hysteresis),
                        70.0,
                        frame.read_only,
                    ) {
                        match parse_number(&text).filter(|value| *value >= 0.0) {
                            Some(value) => {
                                let changed =
                                    with_track(cam, track_index, |t| t.hysteresis = value);
                                gesture = Some(Gesture::edit(label, changed));
                            }
                            None => {
                                let reason = format!("\"{}\" {}", text.trim(), texts.not_a_number);
                                drafts.refuse(&label, text, reason);
                            }
                        }
                    }
                    let label = format!("{name} {}", texts.dead_time_us);
                    ui.label(&texts.dead_time_us);
                    if let Some(text) = drafts.field_ui(
                        ui,
                        &label,
                        &track.dead_time_us.to_string(),
                        70.0,
                        frame.read_only,
                    ) {
                        match text.trim().parse::<i32>() {
                            Ok(value) => {
                                let changed =
                                    with_track(cam, track_index, |t| t.dead_time_us = value);
                                gesture = Some(Gesture::edit(label, changed));
                            }
                            Err(_) => {
                                let reason =
                                    format!("\"{}\" {}", text.trim(), texts.not_an_integer);
                                drafts.refuse(&label, text, reason);
                            }
                        }
                    }
                    if !frame.read_only {
                        let label = format!("{} {}", texts.remove_track, track.id);
                        let button = ui.button(&texts.remove_track);
                        button.widget_info(|| WidgetInfo::labeled(Role::Button, true, &label));
                        if button.clicked() {
                            let mut changed = cam.clone();
                            changed.tracks.remove(track_index);
                            gesture = Some(Gesture::edit(label, changed));
                        }
                    }
                });
                ui.indent(("cam track tappets", track_index), |ui| {
                    for (tappet_index, tappet) in track.tappets.iter().enumerate() {
                        let tappet_name = format!("{name} {} {}", texts.tappet, tappet_index + 1);
                        ui.horizontal(|ui| {
                            ui.label(&tappet_name);
                            let label = format!("{tappet_name} X");
                            if let Some(text) = drafts.field_ui(
                                ui,
                                &label,
                                &number_text(tappet.position),
                                80.0,
                                frame.read_only,
                            ) {
                                let low = cam.master.start.min(cam.master.end);
                                let high = cam.master.start.max(cam.master.end);
                                match parse_number(&text).filter(|x| (low..=high).contains(x)) {
                                    Some(position) => {
                                        let changed = with_track(cam, track_index, |t| {
                                            t.tappets[tappet_index].position = position;
                                            t.tappets
                                                .sort_by(|a, b| a.position.total_cmp(&b.position));
                                        });
                                        gesture = Some(Gesture::edit(label, changed));
                                    }
                                    None => {
                                        let reason = format!(
                                            "\"{}\": {} {low} .. {high}",
                                            text.trim(),
                                            texts.master
                                        );
                                        drafts.refuse(&label, text, reason);
                                    }
                                }
                            }
                            for positive in [true, false] {
                                let pass = if positive {
                                    &texts.positive_pass
                                } else {
                                    &texts.negative_pass
                                };
                                let current = if positive {
                                    tappet.on_positive
                                } else {
                                    tappet.on_negative
                                };
                                let label = format!("{tappet_name} {pass}");
                                let mut chosen = None;
                                ui.add_enabled_ui(!frame.read_only, |ui| {
                                    let combo = ComboBox::from_id_salt((
                                        "cam tappet action",
                                        track_index,
                                        tappet_index,
                                        positive,
                                    ))
                                    .selected_text(action_text(current, texts))
                                    .show_ui(ui, |ui| {
                                        for action in ACTIONS {
                                            if ui
                                                .selectable_label(
                                                    action == current,
                                                    action_text(action, texts),
                                                )
                                                .clicked()
                                                && action != current
                                            {
                                                chosen = Some(action);
                                            }
                                        }
                                    });
                                    combo.response.widget_info(|| {
                                        WidgetInfo::labeled(
                                            Role::ComboBox,
                                            !frame.read_only,
                                            &label,
                                        )
                                    });
                                });
                                if let Some(action) = chosen {
                                    let changed = with_track(cam, track_index, |t| {
                                        let edited = &mut t.tappets[tappet_index];
                                        if positive {
                                            edited.on_positive = action;
                                        } else {
                                            edited.on_negative = action;
                                        }
                                    });
                                    gesture = Some(Gesture::edit(label, changed));
                                }
                            }
                        });
                    }
                });
                ui.separator();
            }
            if !frame.read_only && ui.button(&texts.add_track).clicked() {
                let mut changed = cam.clone();
                let id = cam
                    .tracks
                    .iter()
                    .map(|t| t.id)
                    .max()
                    .map_or(1, |id| id.saturating_add(1));
                changed.tracks.push(TappetTrack {
                    id,
                    name: String::new(),
                    dead_time_us: 0,
                    hysteresis: 0.0,
                    tappets: Vec::new(),
                });
                gesture = Some(Gesture::edit(texts.add_track.clone(), changed));
            }
        });
    gesture
}

/// `cam` with track `index` changed by `change`.
fn with_track(cam: &CamTable, index: usize, change: impl FnOnce(&mut TappetTrack)) -> CamTable {
    let mut changed = cam.clone();
    if let Some(track) = changed.tracks.get_mut(index) {
        change(track);
    }
    changed
}
