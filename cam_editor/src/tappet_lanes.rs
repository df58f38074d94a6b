//! The tappet lanes under the plots: one lane per track on the plots' master axis, tappets as
//! cross-hairs that are dragged, clicked at their upper or lower end to change the positive or
//! negative pass, and deleted with the Delete key or their context menu; a double click in a
//! lane adds one.

use std::collections::HashMap;

use egui::{Align2, FontId, Key, Rect, Role, Sense, Stroke, Ui, WidgetInfo, pos2, vec2};
use egui_plot::PlotTransform;
use project_model::{CamTable, Tappet, TappetAction};

use crate::cam_edit::next_action;
use crate::editor::{Frame, Gesture};
use crate::output::CamLive;
use crate::texts::CamEditorTexts;

/// How far, in points, the pointer must move between press and release for a tappet to move;
/// less is a click.
const MIN_DRAG: f32 = 3.0;

/// The height of one lane in points.
const LANE_HEIGHT: f32 = 30.0;

/// The lanes' state between frames: a tappet being dragged, the selected tappet and where each
/// tappet was drawn.
#[derive(Default)]
pub(crate) struct LaneState {
    /// The tappet being dragged: track, tappet and its master position now.
    drag: Option<(usize, usize, f64)>,
    /// Where the pointer was when the drag started: a release near it is a click, not a move.
    drag_origin: Option<egui::Pos2>,
    /// The tappet the Delete key removes: track and tappet, 0-based.
    selected: Option<(usize, usize)>,
    /// Where each tappet was drawn in the last frame, by track and tappet.
    rects: HashMap<(usize, usize), Rect>,
}

impl LaneState {
    /// Abandons a drag and the selection (the cam changed from elsewhere).
    pub(crate) fn cancel(&mut self) {
        self.drag = None;
        self.selected = None;
    }

    /// Where a tappet was drawn in the last frame.
    pub(crate) fn tappet_rect(&self, track: usize, tappet: usize) -> Option<Rect> {
        self.rects.get(&(track, tappet)).copied()
    }

    /// Draws one lane per track, aligned with the plots through `transform`.
    pub(crate) fn lanes_ui(
        &mut self,
        ui: &mut Ui,
        frame: &Frame<'_>,
        transform: &PlotTransform,
        live: Option<&CamLive>,
    ) -> Option<Gesture> {
        let cam = frame.cam;
        let texts = frame.texts;
        self.rects.clear();
        if cam.tracks.is_empty() {
            return None;
        }
        ui.add_space(4.0);
        ui.weak(&texts.lanes_hint);
        let plot_x = transform.frame().x_range();
        let mut gesture = None;
        let text_focused = ui.ctx().memory(|memory| memory.focused()).is_some();
        for (track_index, track) in cam.tracks.iter().enumerate() {
            let (rect, lane) = ui.allocate_exact_size(
                vec2(ui.available_width(), LANE_HEIGHT),
                if frame.read_only {
                    Sense::hover()
                } else {
                    Sense::click()
                },
            );
            let lane_label = track_label(texts, track.id);
            lane.widget_info(|| WidgetInfo::labeled(Role::Canvas, true, &lane_label));
            let lit = live
                .and_then(|live| live.tappets.get(track_index))
                .copied()
                .unwrap_or(false);
            let painter = ui.painter_at(rect);
            let lane_rect = Rect::from_x_y_ranges(plot_x, rect.y_range());
            painter.rect_filled(
                lane_rect,
                2.0,
                if lit {
                    crate::CamPalette::of(ui).lit_lane
                } else {
                    ui.visuals().faint_bg_color
                },
            );
            painter.text(
                pos2(rect.left() + 2.0, rect.center().y),
                Align2::LEFT_CENTER,
                if track.name.is_empty() {
                    lane_label.clone()
                } else {
                    track.name.clone()
                },
                FontId::proportional(11.0),
                ui.visuals().text_color(),
            );
            if lane.double_clicked()
                && let Some(pointer) = lane.interact_pointer_pos()
                && plot_x.contains(pointer.x)
            {
                let position = master_at(transform, pointer.x, cam);
                let mut changed = cam.clone();
                let tappets = &mut changed.tracks[track_index].tappets;
                tappets.push(Tappet {
                    position,
                    on_positive: TappetAction::On,
                    on_negative: TappetAction::Off,
                });
                sort_tappets(tappets);
                gesture = Some(Gesture::edit(
                    format!("{} ({lane_label})", texts.add_tappet),
                    changed,
                ));
            }
            for (tappet_index, tappet) in track.tappets.iter().enumerate() {
                let dragged_to = self
                    .drag
                    .filter(|(t, k, _)| (*t, *k) == (track_index, tappet_index))
                    .map(|(_, _, position)| position);
                let position = dragged_to.unwrap_or(tappet.position);
                let x = transform.position_from_point_x(position);
                let hit = Rect::from_x_y_ranges(x - 6.0..=x + 6.0, rect.y_range());
                self.rects.insert((track_index, tappet_index), hit);
                let id = ui
                    .scope_id()
                    .with(("cam tappet", &cam.name, track_index, tappet_index));
                let sense = if frame.read_only {
                    Sense::hover()
                } else {
                    Sense::click_and_drag()
                };
                let response = ui.interact(hit, id, sense);
                let label = format!("{lane_label} {} {}", texts.tappet, tappet_index + 1);
                response
                    .widget_info(|| WidgetInfo::labeled(Role::Button, !frame.read_only, &label));
                let selected = self.selected == Some((track_index, tappet_index));
                paint_tappet(ui, &painter, hit, tappet, selected || response.hovered());
                let response = response.on_hover_text(format!(
                    "{label}\nX {position}\n{}: {}\n{}: {}",
                    texts.positive_pass,
                    action_text(tappet.on_positive, texts),
                    texts.negative_pass,
                    action_text(tappet.on_negative, texts)
                ));
                if frame.read_only {
                    continue;
                }
                if response.clicked() {
                    self.selected = Some((track_index, tappet_index));
                    let upper = response
                        .interact_pointer_pos()
                        .is_some_and(|pointer| pointer.y < hit.center().y);
                    let mut changed = cam.clone();
                    let edited = &mut changed.tracks[track_index].tappets[tappet_index];
                    let pass = if upper {
                        edited.on_positive = next_action(edited.on_positive);
                        &texts.positive_pass
                    } else {
                        edited.on_negative = next_action(edited.on_negative);
                        &texts.negative_pass
                    };
                    gesture = Some(Gesture::edit(format!("{pass} ({label})"), changed));
                }
                if response.drag_started() {
                    self.selected = Some((track_index, tappet_index));
                    self.drag = Some((track_index, tappet_index, tappet.position));
                    self.drag_origin = response.interact_pointer_pos();
                }
                if response.dragged()
                    && let Some(pointer) = response.interact_pointer_pos()
                {
                    self.drag = Some((
                        track_index,
                        tappet_index,
                        master_at(transform, pointer.x, cam),
                    ));
                    ui.ctx().request_repaint();
                }
                let moved = match (self.drag_origin, response.interact_pointer_pos()) {
                    (Some(origin), Some(pointer)) => origin.distance(pointer) > MIN_DRAG,
                    _ => false,
                };
                if response.drag_stopped()
                    && let Some((_, _, to)) = self.drag.take()
                    && moved
                {
                    let mut changed = cam.clone();
                    let tappets = &mut changed.tracks[track_index].tappets;
                    tappets[tappet_index].position = to;
                    sort_tappets(tappets);
                    self.selected = None;
                    gesture = Some(Gesture::edit(
                        format!("{} ({label})", texts.move_tappet),
                        changed,
                    ));
                }
                // The key is consumed, so the device tree does not delete its selection too.
                let mut delete = selected
                    && !text_focused
                    && ui.input_mut(|input| input.consume_key(egui::Modifiers::NONE, Key::Delete));
                response.context_menu(|ui| {
                    if ui.button(&texts.delete_tappet).clicked() {
                        delete = true;
                        ui.close();
                    }
                });
                if delete {
                    let mut changed = cam.clone();
                    changed.tracks[track_index].tappets.remove(tappet_index);
                    self.selected = None;
                    gesture = Some(Gesture::edit(
                        format!("{} ({label})", texts.delete_tappet),
                        changed,
                    ));
                }
            }
            ui.add_space(2.0);
        }
        gesture
    }
}

/// "Track 2": a track as the lanes and the tracks tab name it.
pub(crate) fn track_label(texts: &CamEditorTexts, id: u16) -> String {
    format!("{} {id}", texts.track)
}

/// The words of a pass action.
pub(crate) fn action_text(action: TappetAction, texts: &CamEditorTexts) -> String {
    match action {
        TappetAction::None => texts.no_action.clone(),
        TappetAction::On => texts.switch_on.clone(),
        TappetAction::Off => texts.switch_off.clone(),
        TappetAction::Invert => texts.invert.clone(),
        TappetAction::TimedOn { duration_us } => {
            format!("{} {} ms", texts.timed_on, f64::from(duration_us) / 1000.0)
        }
    }
}

/// The master position at screen `x`, inside the cam's master range and rounded to what a
/// pixel resolves.
fn master_at(transform: &PlotTransform, x: f32, cam: &CamTable) -> f64 {
    let value = transform
        .value_from_position(pos2(x, transform.frame().center().y))
        .x;
    let step = transform.dvalue_dpos()[0].abs();
    let rounded = if step > 0.0 && step.is_finite() {
        let unit = 10_f64.powf(step.log10().floor());
        let decimals = (-unit.log10()).max(0.0) as usize;
        format!("{:.decimals$}", (value / unit).round() * unit)
            .parse()
            .unwrap_or(value)
    } else {
        value
    };
    rounded.clamp(
        cam.master.start.min(cam.master.end),
        cam.master.end.max(cam.master.start),
    )
}

/// Tappets in master order, as the runtime expects them per track.
fn sort_tappets(tappets: &mut [Tappet]) {
    tappets.sort_by(|a, b| a.position.total_cmp(&b.position));
}

/// A tappet as a cross-hair: a vertical line over the lane, a horizontal tick in the middle,
/// the positive pass's action drawn in the upper half and the negative pass's in the lower.
fn paint_tappet(ui: &Ui, painter: &egui::Painter, rect: Rect, tappet: &Tappet, highlighted: bool) {
    let stroke_color = if highlighted {
        ui.visuals().strong_text_color()
    } else {
        ui.visuals().text_color()
    };
    let x = rect.center().x;
    let width = if highlighted { 2.0 } else { 1.2 };
    painter.line_segment(
        [pos2(x, rect.top() + 2.0), pos2(x, rect.bottom() - 2.0)],
        Stroke::new(width, stroke_color),
    );
    painter.line_segment(
        [
            pos2(x - 5.0, rect.center().y),
            pos2(x + 5.0, rect.center().y),
        ],
        Stroke::new(width, stroke_color),
    );
    let palette = crate::CamPalette::of(ui);
    let upper = pos2(x, rect.top() + rect.height() * 0.25);
    let lower = pos2(x, rect.top() + rect.height() * 0.75);
    for (center, action) in [(upper, tappet.on_positive), (lower, tappet.on_negative)] {
        let mark = Rect::from_center_size(center, vec2(8.0, 6.0));
        match action {
            TappetAction::None => {}
            TappetAction::On | TappetAction::TimedOn { .. } => {
                painter.rect_filled(mark, 1.0, palette.tappet_on);
            }
            TappetAction::Off => {
                painter.rect_stroke(
                    mark,
                    1.0,
                    Stroke::new(1.5, palette.tappet_off),
                    egui::StrokeKind::Inside,
                );
            }
            TappetAction::Invert => {
                painter.rect_filled(mark, 1.0, palette.tappet_invert);
            }
        }
    }
}
