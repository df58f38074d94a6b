//! The trace view: the uploaded samples of a trace plotted over time, with two measuring
//! cursors, the trigger, and export to CSV and PNG.
//!
//! The view draws and reports; it performs no I/O. The app answers
//! [`TracePlotOutput::export_csv`] with a file dialog and [`TraceData::to_csv`], and
//! [`TracePlotOutput::export_png`] with a screenshot that [`crop_to_png`] cuts to the plot.

mod csv;
mod data;
mod decimate;
mod png;
#[cfg(test)]
mod tests;
pub(crate) mod text;

use egui::{Id, Rect, Role, Ui, WidgetInfo};
use egui_plot::{Legend, Line, LineStyle, Plot, PlotBounds, PlotResponse, PlotUi, VLine};

pub use data::{
    CursorReading, CursorReadings, TraceData, TraceSample, TraceSeries, nearest_sample_time,
    parse_color,
};
pub use png::{PngExportError, crop_to_png};

use crate::studio::i18n::Language;
use decimate::{DecimationCache, DecimationKey, fingerprint};
use text::PlotText;

/// How the series share the plot area.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TraceLayout {
    /// Every series on one plot with one y axis.
    #[default]
    OneAxis,
    /// One plot per series, stacked, with their time axes and hover cursors linked.
    OnePlotPerSignal,
}

/// The state of one trace view: layout, cursors and cached plot points. It lives as long as the
/// trace's tab and is not saved.
#[derive(Default)]
pub struct TracePlotView {
    /// The interface language; the app sets it from the settings before drawing.
    pub language: Language,
    /// How the series share the plot area.
    pub layout: TraceLayout,
    /// Cursor A's time in milliseconds relative to the trigger, once placed.
    pub cursor_a_ms: Option<f64>,
    /// Cursor B's time in milliseconds relative to the trigger, once placed.
    pub cursor_b_ms: Option<f64>,
    /// Decimated points, reused while the data, the visible range and the width stay the same.
    cache: DecimationCache,
    /// The relative sample times of the data `times_of` identifies, computed once per trace.
    times_ms: Vec<f64>,
    /// The fingerprint of the data `times_ms` belongs to.
    times_of: Option<u64>,
}

/// What the user asked for in one frame, for the app to carry out after drawing.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TracePlotOutput {
    /// "Export CSV…" was clicked: ask for a file and write [`TraceData::to_csv`] to it.
    pub export_csv: bool,
    /// "Export PNG…" was clicked: take a screenshot (`egui::ViewportCommand::Screenshot`) and
    /// cut this rectangle (in points) out of it with [`crop_to_png`].
    pub export_png: Option<Rect>,
}

/// The pixel columns of a plot are decimated over twice the visible width, so a pan by up to
/// half a width reuses the cached points.
const DECIMATION_SPAN: f64 = 2.0;

impl TracePlotView {
    /// Draws the toolbar, the plot (or plots) and the cursor table into the rest of `ui`.
    pub fn ui(&mut self, ui: &mut Ui, data: &TraceData) -> TracePlotOutput {
        let language = self.language;
        let mut output = TracePlotOutput::default();
        let has_data = !data.samples.is_empty() && !data.variables.is_empty();
        let mut reset = false;
        let mut png_requested = false;
        ui.horizontal_wrapped(|ui| {
            ui.selectable_value(
                &mut self.layout,
                TraceLayout::OneAxis,
                PlotText::OneAxis.get(language),
            );
            ui.selectable_value(
                &mut self.layout,
                TraceLayout::OnePlotPerSignal,
                PlotText::OnePlotPerSignal.get(language),
            );
            ui.separator();
            reset = ui
                .add_enabled(
                    has_data,
                    egui::Button::new(PlotText::ResetView.get(language)),
                )
                .clicked();
            let has_cursor = self.cursor_a_ms.is_some() || self.cursor_b_ms.is_some();
            if ui
                .add_enabled(
                    has_cursor,
                    egui::Button::new(PlotText::ClearCursors.get(language)),
                )
                .clicked()
            {
                self.cursor_a_ms = None;
                self.cursor_b_ms = None;
            }
            ui.separator();
            output.export_csv = ui
                .add_enabled(
                    has_data,
                    egui::Button::new(PlotText::ExportCsv.get(language)),
                )
                .clicked();
            png_requested = ui
                .add_enabled(
                    has_data,
                    egui::Button::new(PlotText::ExportPng.get(language)),
                )
                .clicked();
            if has_data {
                ui.separator();
                ui.weak(summary(data, language));
            }
        });
        if !has_data {
            empty_ui(ui, language);
            return output;
        }
        if reset {
            self.cache.clear();
        }
        let data_fingerprint = fingerprint(data);
        if self.times_of != Some(data_fingerprint) {
            self.times_ms = data.times_ms();
            self.times_of = Some(data_fingerprint);
        }
        let table_rows = data.variables.len() + 2;
        let row_height = ui.spacing().interact_size.y;
        let table_height = (table_rows as f32 * row_height).min(ui.available_height() * 0.35);
        let plot_height = (ui.available_height() - table_height - row_height).max(120.0);
        let plot_area = ui.allocate_ui(egui::vec2(ui.available_width(), plot_height), |ui| {
            ui.set_min_size(egui::vec2(ui.available_width(), plot_height));
            match self.layout {
                TraceLayout::OneAxis => self.one_axis_ui(ui, data, reset),
                TraceLayout::OnePlotPerSignal => self.per_signal_ui(ui, data, reset),
            }
        });
        if png_requested {
            output.export_png = Some(plot_area.response.rect);
        }
        ui.weak(PlotText::CursorHint.get(language));
        egui::ScrollArea::vertical()
            .id_salt("trace_cursor_table")
            .max_height(table_height)
            .auto_shrink([false, true])
            .show(ui, |ui| self.cursor_table_ui(ui, data));
        output
    }

    /// All series on one plot.
    fn one_axis_ui(&mut self, ui: &mut Ui, data: &TraceData, reset: bool) {
        let indices: Vec<usize> = (0..data.variables.len()).collect();
        let height = ui.available_height();
        self.plot_ui(
            ui,
            data,
            "trace_plot_one_axis",
            &indices,
            height,
            None,
            reset,
        );
    }

    /// One plot per series, stacked in a scroll area when they do not fit.
    fn per_signal_ui(&mut self, ui: &mut Ui, data: &TraceData, reset: bool) {
        let count = data.variables.len();
        let spacing = ui.spacing().item_spacing.y;
        let height = ((ui.available_height() - spacing * count as f32) / count as f32).max(80.0);
        let group = ui.scope_id().with("trace_plot_link");
        egui::ScrollArea::vertical()
            .id_salt("trace_plot_stack")
            .auto_shrink([false, false])
            .show(ui, |ui| {
                for index in 0..count {
                    let salt = ("trace_plot_signal", index);
                    self.plot_ui(ui, data, salt, &[index], height, Some(group), reset);
                }
            });
    }

    /// One plot of the series `indices`, with the trigger and cursors; a click places a cursor.
    #[expect(
        clippy::too_many_arguments,
        reason = "one private helper of two layouts"
    )]
    fn plot_ui(
        &mut self,
        ui: &mut Ui,
        data: &TraceData,
        id_salt: impl egui::AsIdSalt,
        indices: &[usize],
        height: f32,
        link_group: Option<Id>,
        reset: bool,
    ) {
        let language = self.language;
        let data_fingerprint = self.times_of.unwrap_or_default();
        let times = std::mem::take(&mut self.times_ms);
        let full_range = match (times.first(), times.last()) {
            (Some(&first), Some(&last)) => (first, last),
            _ => (0.0, 0.0),
        };
        let mut plot = Plot::new(id_salt)
            .height(height)
            .legend(Legend::default().follow_insertion_order(true))
            .x_axis_label(PlotText::TimeMs.get(language))
            .allow_zoom([true, true])
            .allow_scroll([true, true])
            .allow_drag([true, true]);
        if indices.iter().all(|&index| data.variables[index].is_bool) {
            plot = plot.include_y(0.0).include_y(1.0);
        }
        if let Some(group) = link_group {
            plot = plot
                .link_axis(group, [true, false])
                .link_cursor(group, [true, false]);
        }
        if reset {
            plot = plot.reset();
        }
        // The width of the whole area rather than of the plot's frame: the frames of stacked
        // plots differ by their y-axis labels, and one width lets them share one decimation.
        let width_px = f64::from(ui.available_width() * ui.ctx().pixels_per_point());
        let cursors = [self.cursor_a_ms, self.cursor_b_ms];
        let colors = crate::studio::theme::colors(ui);
        let cache = &mut self.cache;
        let times_ref = &times;
        // The decimation key comes from the bounds of the last frame, which is what the plot
        // closure sees; a changed view is drawn again below once the new bounds are known.
        let response: PlotResponse<DecimationKey> = plot.show(ui, |plot_ui: &mut PlotUi<'_>| {
            let key = decimation_key(
                data_fingerprint,
                &plot_ui.plot_bounds(),
                plot_ui.auto_bounds().x,
                width_px,
                full_range,
            );
            let all = cache.series(data, times_ref, key);
            for &index in indices {
                let Some(points) = all.get(index) else {
                    continue;
                };
                let series = &data.variables[index];
                plot_ui.line(
                    Line::new(series.path.clone(), points.clone())
                        .id(("trace_series", index))
                        .color(data.series_color(index)),
                );
            }
            if data.trigger_sample.is_some() {
                plot_ui.vline(
                    VLine::new(PlotText::Trigger.get(language), 0.0)
                        .style(LineStyle::dashed_loose())
                        .color(colors.trace_trigger),
                );
            }
            let names = [PlotText::CursorA, PlotText::CursorB];
            let cursor_colors = colors.trace_cursors;
            for ((cursor, name), color) in cursors.into_iter().zip(names).zip(cursor_colors) {
                if let Some(x) = cursor {
                    plot_ui.vline(VLine::new(name.get(language), x).color(color).width(1.5));
                }
            }
            key
        });
        response.response.widget_info(|| {
            WidgetInfo::labeled(Role::Canvas, true, PlotText::TracePlot.get(language))
        });
        self.place_cursor(ui, &response, &times);
        // Pan and zoom change the bounds after the closure ran; when the points drawn do not
        // cover the new view at pixel resolution, one more frame draws them.
        let new_bounds = response.transform.bounds();
        if !covers(&response.inner, new_bounds, width_px, full_range) {
            ui.ctx().request_repaint();
        }
        self.times_ms = times;
    }

    /// Sets cursor A on a click, cursor B on a Shift+click, on the nearest sample.
    fn place_cursor(&mut self, ui: &Ui, response: &PlotResponse<DecimationKey>, times: &[f64]) {
        // A double click resets the view; its clicks should not move cursor A as well.
        if !response.response.clicked() || response.response.double_clicked() {
            return;
        }
        let Some(pointer) = response.response.interact_pointer_pos() else {
            return;
        };
        let x = response.transform.value_from_position(pointer).x;
        let Some(snapped) = nearest_sample_time(times, x) else {
            return;
        };
        // The release that made the click carries the modifiers held at that moment, which is
        // more exact than the keyboard state at the end of the frame.
        let shift = ui.input(|input| {
            input.modifiers.shift
                || input.events.iter().any(|event| {
                    matches!(
                        event,
                        egui::Event::PointerButton { pressed: false, modifiers, .. }
                            if modifiers.shift
                    )
                })
        });
        if shift {
            self.cursor_b_ms = Some(snapped);
        } else {
            self.cursor_a_ms = Some(snapped);
        }
    }

    /// The values at the cursors, one row per series, and Δt.
    fn cursor_table_ui(&self, ui: &mut Ui, data: &TraceData) {
        let language = self.language;
        let readings = data.cursor_readings(self.cursor_a_ms, self.cursor_b_ms);
        egui::Grid::new("trace_cursor_grid")
            .striped(true)
            .num_columns(4)
            .show(ui, |ui| {
                for header in [
                    PlotText::Variable,
                    PlotText::AtA,
                    PlotText::AtB,
                    PlotText::Difference,
                ] {
                    ui.strong(header.get(language));
                }
                ui.end_row();
                for (index, row) in readings.rows.iter().enumerate() {
                    let is_bool = data.variables[index].is_bool;
                    ui.colored_label(data.series_color(index), &row.path);
                    ui.label(format_reading(row.at_a, is_bool));
                    ui.label(format_reading(row.at_b, is_bool));
                    ui.label(format_reading(row.difference, false));
                    ui.end_row();
                }
                ui.strong(PlotText::DeltaT.get(language));
                ui.label(format_reading(self.cursor_a_ms, false));
                ui.label(format_reading(self.cursor_b_ms, false));
                ui.label(format_reading(readings.delta_t_ms, false));
                ui.end_row();
            });
    }
}

/// The range and resolution to decimate for: the whole trace while the plot fits its data
/// (auto bounds), else twice the visible width snapped to half-width steps, so small pans reuse
/// the cached points.
fn decimation_key(
    data: u64,
    bounds: &PlotBounds,
    auto_x: bool,
    width_px: f64,
    full_range: (f64, f64),
) -> DecimationKey {
    let visible = bounds.range_x();
    let (lo, hi) = (*visible.start(), *visible.end());
    let columns = width_px.max(1.0).round() as usize;
    if auto_x || !bounds.is_valid_x() || hi <= lo {
        return DecimationKey {
            data,
            x_lo: full_range.0,
            x_hi: full_range.1,
            columns,
        };
    }
    let step = (hi - lo) / 2.0;
    let x_lo = (lo / step).floor() * step - step;
    DecimationKey {
        data,
        x_lo,
        x_hi: x_lo + DECIMATION_SPAN * 2.0 * step,
        columns: (DECIMATION_SPAN * width_px).max(1.0).round() as usize,
    }
}

/// Whether points decimated for `key` draw the view `bounds` (`width_px` wide) at least at pixel
/// resolution.
/// `full_range` is the first and last sample time: no data exists beyond them, so a view reaching
/// past them is covered when the key reaches the ends.
fn covers(key: &DecimationKey, bounds: &PlotBounds, width_px: f64, full_range: (f64, f64)) -> bool {
    let visible = bounds.range_x();
    let (lo, hi) = (*visible.start(), *visible.end());
    if !bounds.is_valid_x() || hi <= lo {
        return true;
    }
    let key_span = key.x_hi - key.x_lo;
    let covers_range = key.x_lo <= lo.max(full_range.0) && key.x_hi >= hi.min(full_range.1);
    let drawn_per_ms = key.columns as f64 / key_span.max(f64::MIN_POSITIVE);
    let needed_per_ms = width_px / (hi - lo);
    covers_range && drawn_per_ms >= needed_per_ms * 0.75
}

/// The short summary beside the toolbar: sample count and task cycle time.
fn summary(data: &TraceData, language: Language) -> String {
    let mut text = format!("{} {}", data.samples.len(), PlotText::Samples.get(language));
    if let Some(cycle_ns) = data.cycle_time_ns {
        let cycle_ms = cycle_ns as f64 / 1e6;
        text.push_str(&format!(
            " · {} {cycle_ms} ms",
            PlotText::CycleTime.get(language)
        ));
    }
    text
}

/// The message shown before any sample arrived.
fn empty_ui(ui: &mut Ui, language: Language) {
    ui.vertical_centered(|ui| {
        ui.add_space(ui.available_height() * 0.3);
        ui.heading(PlotText::NoSamples.get(language));
        ui.label(PlotText::NoSamplesHint.get(language));
    });
}

/// A reading for the table: TRUE/FALSE for a BOOL, up to six decimals otherwise, a dash when
/// there is none.
pub fn format_reading(value: Option<f64>, is_bool: bool) -> String {
    match value {
        None => "—".to_owned(),
        Some(value) if is_bool => if value != 0.0 { "TRUE" } else { "FALSE" }.to_owned(),
        Some(value) => {
            let text = format!("{value:.6}");
            let text = text.trim_end_matches('0').trim_end_matches('.');
            if text == "-0" {
                "0".to_owned()
            } else {
                text.to_owned()
            }
        }
    }
}
