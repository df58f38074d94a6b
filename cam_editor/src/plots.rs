//! The four plots of a cam over the master (position, velocity, acceleration and jerk) with a
//! shared master axis and cursor, key point handles to drag on the position plot, continuity
//! warnings at their joints and the live position.

use std::sync::Arc;

use egui::{Align2, Color32, Rect, Role, Sense, Stroke, Ui, WidgetInfo, vec2};
use egui_plot::{Line, MarkerShape, Plot, PlotPoint, PlotTransform, Points, VLine};
use motion::cam::{ContinuityQuantity, ContinuityWarning};
use motion::curve::CamCurve as _;
use project_model::{CamKeyPoint, CamTable};

use crate::cam_edit::{key_points, set_key_point};
use crate::editor::{CurveView, Frame, Gesture};
use crate::output::CamLive;
use crate::palette::CamPalette;
use crate::plot_sampling::sample_for_plot;
use crate::texts::CamEditorTexts;

/// Above this many key points in view, handles are made only near the pointer, so a
/// 10,000-point table does not cost 10,000 widgets a frame.
const MAX_HANDLES: usize = 200;

/// How many handles a dense cam gets near the pointer.
const MAX_NEAR_HANDLES: usize = 16;

/// How far from the pointer, in points, a key point of a dense cam gets a handle.
const NEAR_POINTER: f32 = 10.0;

/// The plots' state between frames: a key point being dragged, the hovered master position,
/// the position plot's last transform and the sampled lines.
#[derive(Default)]
pub(crate) struct PlotState {
    /// The key point being dragged.
    drag: Option<KeyDrag>,
    /// The master position under the pointer in any of the plots.
    hover_master: Option<f64>,
    /// The position plot's transform in the last frame, which the handles and lanes use.
    transform: Option<PlotTransform>,
    /// The sampled lines and what they were sampled for.
    samples: Option<(SampleKey, Arc<[Vec<PlotPoint>; 4]>)>,
}

/// A key point being dragged: the preview shows the cam with it moved, and its release gives
/// one edit.
struct KeyDrag {
    /// The 0-based key point.
    index: usize,
    /// Where it is now.
    point: CamKeyPoint,
    /// The cam with the key point there (the last valid such cam).
    preview: CamTable,
}

/// What the lines were sampled for: the curve's generation, the master range in view and the
/// width in pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SampleKey {
    generation: u64,
    view: (f64, f64),
    columns: usize,
}

/// The four quantities in plot order, with their colours in `palette`.
fn quantities(palette: &CamPalette) -> [(ContinuityQuantity, Color32); 4] {
    [
        (ContinuityQuantity::Position, palette.position),
        (ContinuityQuantity::Velocity, palette.velocity),
        (ContinuityQuantity::Acceleration, palette.acceleration),
        (ContinuityQuantity::Jerk, palette.jerk),
    ]
}

impl PlotState {
    /// The cam with the dragged key point moved, while a drag is in progress.
    pub(crate) fn preview(&self) -> Option<&CamTable> {
        self.drag.as_ref().map(|drag| &drag.preview)
    }

    /// Abandons a drag (the cam changed from elsewhere, or the editor became read-only).
    pub(crate) fn cancel_drag(&mut self) {
        self.drag = None;
    }

    /// The position plot's transform in the last frame.
    pub(crate) fn transform(&self) -> Option<PlotTransform> {
        self.transform
    }

    /// Draws the value readout and the four plots of `view`; a key point released after a
    /// drag gives the gesture.
    pub(crate) fn plots_ui(
        &mut self,
        ui: &mut Ui,
        frame: &Frame<'_>,
        view: &CurveView,
        live: Option<&CamLive>,
        height: f32,
    ) -> Option<Gesture> {
        let texts = frame.texts;
        let Ok(curve) = &view.curve else {
            return None;
        };
        let (first, last) = curve.master_range();
        let hovered_values = self
            .hover_master
            .map(|master| (master, curve.sample(master)));
        let readout = match hovered_values {
            Some((master, at)) => format!(
                "{} {:.3}   {} {:.4}   {} {:.4}   {} {:.4}   {} {:.4}",
                texts.master,
                master,
                texts.position,
                at.position,
                texts.velocity,
                at.velocity,
                texts.acceleration,
                at.acceleration,
                texts.jerk,
                at.jerk
            ),
            None => String::new(),
        };
        ui.label(egui::RichText::new(readout).monospace());

        let pixels_per_point = ui.ctx().pixels_per_point();
        let columns = ((ui.available_width() - 70.0).max(50.0) * pixels_per_point) as usize;
        let in_view = self
            .transform
            .map(|transform| {
                let bounds = transform.bounds();
                (bounds.min()[0].max(first), bounds.max()[0].min(last))
            })
            .filter(|(low, high)| high > low)
            .unwrap_or((first, last));
        let key = SampleKey {
            generation: view.generation,
            view: in_view,
            columns,
        };
        let samples = match &self.samples {
            Some((made_for, samples)) if *made_for == key => Arc::clone(samples),
            _ => {
                let sampled = sample_for_plot(curve, &view.key_masters, in_view, columns);
                let to_points = |line: Vec<[f64; 2]>| {
                    line.into_iter()
                        .map(|[x, y]| PlotPoint::new(x, y))
                        .collect::<Vec<_>>()
                };
                let lines = Arc::new([
                    to_points(sampled.position),
                    to_points(sampled.velocity),
                    to_points(sampled.acceleration),
                    to_points(sampled.jerk),
                ]);
                self.samples = Some((key, Arc::clone(&lines)));
                lines
            }
        };

        let group = ui.scope_id().with("cam plots link");
        let mut hover = None;
        let mut gesture = None;
        let palette = CamPalette::of(ui);
        for (index, (quantity, color)) in quantities(&palette).into_iter().enumerate() {
            let name = quantity_text(quantity, texts);
            let warnings: Vec<&ContinuityWarning> = view
                .warnings
                .iter()
                .filter(|warning| warning.quantity == quantity)
                .collect();
            let line = &samples[index];
            let plot = Plot::new(("cam plot", index))
                .height(height)
                .link_axis(group, [true, false])
                .link_cursor(group, [true, false])
                .y_axis_min_width(56.0)
                .y_axis_label(name.clone())
                .allow_drag(false)
                .allow_scroll(false)
                .allow_boxed_zoom(false)
                .allow_double_click_reset(true)
                .include_x(first)
                .include_x(last);
            let hovered_text = hovered_values.map(|(master, at)| {
                let value = match quantity {
                    ContinuityQuantity::Position => at.position,
                    ContinuityQuantity::Velocity => at.velocity,
                    ContinuityQuantity::Acceleration => at.acceleration,
                    ContinuityQuantity::Jerk => at.jerk,
                };
                (master, format!("{value:.4}"))
            });
            let response = plot.show(ui, |plot_ui| {
                plot_ui.line(Line::new(name.clone(), &line[..]).color(color).width(1.5));
                if !warnings.is_empty() {
                    let marks: Vec<[f64; 2]> = warnings
                        .iter()
                        .map(|warning| [warning.master, warning.left])
                        .collect();
                    plot_ui.points(
                        Points::new(texts.continuity_warnings.clone(), marks)
                            .shape(MarkerShape::Diamond)
                            .radius(6.0)
                            .color(palette.warning),
                    );
                }
                if let Some(live) = live {
                    plot_ui.vline(
                        VLine::new(texts.live_marker.clone(), live.master).color(palette.live),
                    );
                    if quantity == ContinuityQuantity::Position {
                        plot_ui.points(
                            Points::new(texts.live_marker.clone(), vec![[live.master, live.slave]])
                                .shape(MarkerShape::Circle)
                                .filled(true)
                                .radius(5.0)
                                .color(palette.live),
                        );
                    }
                }
            });
            // The value at the hovered master, painted over the plot rather than added as a
            // plot item, which would widen the automatic bounds frame after frame.
            if let Some((master, text)) = &hovered_text {
                let frame_rect = *response.transform.frame();
                let x = response.transform.position_from_point_x(*master);
                ui.painter_at(frame_rect).text(
                    egui::pos2(x + 4.0, frame_rect.top() + 2.0),
                    Align2::LEFT_TOP,
                    text,
                    egui::FontId::monospace(11.0),
                    color,
                );
            }
            response.response.widget_info(|| {
                WidgetInfo::labeled(Role::Canvas, true, format!("{name} {}", texts.cam_tab))
            });
            // The pointer over the plot's frame, even where a handle or a tooltip covers it,
            // so the readout does not flicker as they come and go.
            if let Some(pointer) = ui.ctx().pointer_hover_pos()
                && response.transform.frame().contains(pointer)
            {
                hover = Some(response.transform.value_from_position(pointer).x);
            }
            for warning in &warnings {
                warning_mark_ui(ui, &response.transform, warning, texts);
            }
            if quantity == ContinuityQuantity::Position {
                self.transform = Some(response.transform);
                gesture = self.handles_ui(ui, frame, view, &response.transform);
            }
        }
        // The dragged handle keeps the hover on the plot; otherwise a pointer that left the
        // plots clears the readout.
        if hover != self.hover_master {
            self.hover_master = hover;
            ui.ctx().request_repaint();
        }
        gesture
    }

    /// The key point handles on the position plot; a drag moves a preview, its release gives
    /// one edit.
    fn handles_ui(
        &mut self,
        ui: &mut Ui,
        frame: &Frame<'_>,
        view: &CurveView,
        transform: &PlotTransform,
    ) -> Option<Gesture> {
        let shown = key_points(&view.cam);
        let model = key_points(frame.cam);
        if shown.len() != model.len() {
            return None;
        }
        let plot_rect = *transform.frame();
        let bounds = transform.bounds();
        let visible_from = shown.partition_point(|point| point.master < bounds.min()[0]);
        let visible_to = shown.partition_point(|point| point.master <= bounds.max()[0]);
        let mut indices: Vec<usize> = if visible_to - visible_from <= MAX_HANDLES {
            (visible_from..visible_to).collect()
        } else {
            match ui.ctx().pointer_hover_pos() {
                Some(pointer) if plot_rect.contains(pointer) => {
                    let low = transform
                        .value_from_position(pointer - vec2(NEAR_POINTER, 0.0))
                        .x;
                    let high = transform
                        .value_from_position(pointer + vec2(NEAR_POINTER, 0.0))
                        .x;
                    let from = shown.partition_point(|point| point.master < low);
                    let to = shown.partition_point(|point| point.master <= high);
                    // The nearest ones, so the handle under the pointer is always among them.
                    let mut near: Vec<(f32, usize)> = (from..to)
                        .map(|index| (point_pos(transform, &shown[index]).distance(pointer), index))
                        .filter(|(distance, _)| *distance <= NEAR_POINTER)
                        .collect();
                    near.sort_by(|a, b| a.0.total_cmp(&b.0));
                    // The nearest is made last, so it is on top where handles overlap.
                    near.into_iter()
                        .take(MAX_NEAR_HANDLES)
                        .rev()
                        .map(|(_, index)| index)
                        .collect()
                }
                _ => Vec::new(),
            }
        };
        if let Some(drag) = &self.drag
            && !indices.contains(&drag.index)
        {
            indices.push(drag.index);
        }
        let painter = ui.painter_at(plot_rect);
        let handle_color = ui.visuals().strong_text_color();
        let mut gesture = None;
        for index in indices {
            let point = shown[index];
            let pos = point_pos(transform, &point);
            let rect = Rect::from_center_size(pos, vec2(14.0, 14.0));
            let id = ui
                .scope_id()
                .with(("cam key point", &frame.cam.name, index));
            let sense = if frame.read_only {
                Sense::hover()
            } else {
                Sense::drag()
            };
            let response = ui.interact(rect, id, sense);
            let label = format!("{} {}", frame.texts.key_point, index + 1);
            response.widget_info(|| WidgetInfo::labeled(Role::Button, !frame.read_only, &label));
            let active = response.hovered() || response.dragged();
            painter.circle(
                pos,
                if active { 6.0 } else { 4.5 },
                ui.visuals().extreme_bg_color,
                Stroke::new(2.0, handle_color),
            );
            let response =
                response.on_hover_text(format!("{label}\nX {}\nY {}", point.master, point.slave));
            if response.drag_started() {
                self.drag = Some(KeyDrag {
                    index,
                    point: model[index],
                    preview: frame.cam.clone(),
                });
            }
            if response.dragged()
                && let Some(pointer) = response.interact_pointer_pos()
                && let Some(drag) = self.drag.as_mut().filter(|drag| drag.index == index)
            {
                let wanted = transform.value_from_position(pointer);
                let [x_step, y_step] = transform.dvalue_dpos();
                let last = model.len() - 1;
                // The ends hold the master range, so they move only up and down; inner points
                // stay strictly between their neighbours.
                let master = if index == 0 || index == last {
                    model[index].master
                } else {
                    let span = model[last].master - model[0].master;
                    let gap = span * 1e-6;
                    round_to_pixel(wanted.x, x_step.abs())
                        .clamp(model[index - 1].master + gap, model[index + 1].master - gap)
                };
                drag.point = CamKeyPoint {
                    master,
                    slave: round_to_pixel(wanted.y, y_step.abs()),
                    ..model[index]
                };
                if let Ok(preview) = set_key_point(frame.cam, index, drag.point) {
                    drag.preview = preview;
                }
                ui.ctx().request_repaint();
            }
            if response.drag_stopped()
                && let Some(drag) = self.drag.take()
            {
                let label = format!("{} {}", frame.texts.move_key_point, index + 1);
                gesture = Some(match set_key_point(frame.cam, drag.index, drag.point) {
                    Ok(changed) => Gesture::edit(label, changed),
                    Err(error) => Gesture::Refused(label, error.to_string()),
                });
            }
        }
        gesture
    }
}

/// The continuity warnings of `view` as a list under the plots.
pub(crate) fn warnings_ui(ui: &mut Ui, view: &CurveView, texts: &CamEditorTexts) {
    ui.add_space(4.0);
    if view.warnings.is_empty() {
        if view.curve.is_ok() {
            ui.weak(&texts.no_continuity_warnings);
        }
        return;
    }
    ui.strong(&texts.continuity_warnings);
    let color = CamPalette::of(ui).warning;
    for warning in &view.warnings {
        ui.colored_label(color, warning_text(warning, texts));
    }
}

/// A warning as the list and the marks' hover text say it: "Key point 3, X 120: Velocity 0 /
/// 1" (the values left and right of the joint).
pub(crate) fn warning_text(warning: &ContinuityWarning, texts: &CamEditorTexts) -> String {
    format!(
        "{} {}, X {}: {} {} / {}",
        texts.key_point,
        warning.joint,
        warning.master,
        quantity_text(warning.quantity, texts),
        round_for_text(warning.left),
        round_for_text(warning.right)
    )
}

/// A hoverable mark over a warning's joint on its plot.
fn warning_mark_ui(
    ui: &mut Ui,
    transform: &PlotTransform,
    warning: &ContinuityWarning,
    texts: &CamEditorTexts,
) {
    let pos = transform.position_from_point(&PlotPoint::new(warning.master, warning.left));
    if !transform.frame().contains(pos) {
        return;
    }
    let text = warning_text(warning, texts);
    let id = ui.scope_id().with((
        "cam continuity warning",
        warning.joint,
        warning.quantity as u8,
    ));
    let response = ui.interact(
        Rect::from_center_size(pos, vec2(12.0, 12.0)),
        id,
        Sense::hover(),
    );
    response.widget_info(|| WidgetInfo::labeled(Role::Image, true, &text));
    response.on_hover_text(text);
}

/// The name of a quantity in the editor's words.
fn quantity_text(quantity: ContinuityQuantity, texts: &CamEditorTexts) -> String {
    match quantity {
        ContinuityQuantity::Position => texts.position.clone(),
        ContinuityQuantity::Velocity => texts.velocity.clone(),
        ContinuityQuantity::Acceleration => texts.acceleration.clone(),
        ContinuityQuantity::Jerk => texts.jerk.clone(),
    }
}

fn point_pos(transform: &PlotTransform, point: &CamKeyPoint) -> egui::Pos2 {
    transform.position_from_point(&PlotPoint::new(point.master, point.slave))
}

/// `value` rounded to the power of ten at or below one pixel's worth, so a dragged point gets
/// the digits the user can place rather than twelve.
fn round_to_pixel(value: f64, units_per_point: f64) -> f64 {
    if !units_per_point.is_finite() || units_per_point <= 0.0 {
        return value;
    }
    let step = 10_f64.powf(units_per_point.log10().floor());
    let rounded = (value / step).round() * step;
    // Rounding to a power of ten leaves binary noise (0.30000000000000004); printing with the
    // step's decimals and reading back removes it.
    let decimals = (-step.log10()).max(0.0) as usize;
    format!("{rounded:.decimals$}").parse().unwrap_or(rounded)
}

/// A warning's value with at most six decimals.
fn round_for_text(value: f64) -> String {
    let text = format!("{value:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        text.to_owned()
    }
}
