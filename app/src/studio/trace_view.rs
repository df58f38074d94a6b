//! The uploaded samples of a trace as the trace pane plots them, and the CSV and PNG exports.

use std::sync::Arc;

use egui::Ui;

use super::online::TraceRun;
use super::studio_app::Studio;
use super::trace_plot::{TraceData, TraceSample, TraceSeries, crop_to_png, parse_color};
use crate::value_text::{is_bool, numeric};

/// The trace pane's plot state and the data it shows, rebuilt only when new samples arrive.
#[derive(Default)]
pub struct TraceViewState {
    /// The plot's own state (layout, cursors, zoom).
    pub plot: super::trace_plot::TracePlotView,
    data: Arc<TraceData>,
    /// The run the data was made from: its name, sample count and first cycle.
    made_from: Option<(String, usize, u64)>,
    /// The plot area and the screenshot a PNG export asked for, until it arrives.
    png: Option<(egui::Rect, std::sync::mpsc::Receiver<Arc<egui::ColorImage>>)>,
}

/// The samples of `run` as plot data: numbers per series (BOOL as 0/1, strings as gaps),
/// coloured as the project's trace object says.
pub fn trace_data(run: &TraceRun, config: Option<&project_model::TraceConfig>) -> TraceData {
    let variables = run
        .variables()
        .iter()
        .map(|(path, resolved)| TraceSeries {
            path: path.clone(),
            color: config
                .and_then(|config| config.variables.iter().find(|v| v.path == *path))
                .and_then(|variable| variable.color.as_deref())
                .and_then(parse_color),
            is_bool: is_bool(resolved),
        })
        .collect();
    let samples = run
        .samples()
        .iter()
        .map(|sample| TraceSample {
            cycle: sample.cycle,
            time_ns: sample.time_ns,
            values: run
                .variables()
                .iter()
                .zip(&sample.values)
                .map(|((_, resolved), bytes)| numeric(resolved, bytes).unwrap_or(f64::NAN))
                .collect(),
        })
        .collect();
    TraceData {
        variables,
        samples,
        trigger_sample: run.trigger_sample().map(|index| index as usize),
        cycle_time_ns: None,
    }
}

/// Plots the current trace run and performs the exports the plot asks for.
pub(crate) fn trace_samples_ui(
    studio: &mut Studio,
    ui: &mut Ui,
    config: Option<&project_model::TraceConfig>,
) {
    let run = studio.online.trace();
    let key = (
        run.name().to_owned(),
        run.samples().len(),
        run.samples().first().map_or(0, |s| s.cycle),
    );
    let view = &mut studio.trace_view;
    if view.made_from.as_ref() != Some(&key) {
        view.data = Arc::new(trace_data(run, config));
        view.made_from = Some(key);
    }
    view.plot.language = studio.settings.language;
    let data = Arc::clone(&view.data);
    let output = view.plot.ui(ui, &data);
    if output.export_csv
        && let Some(path) = rfd::FileDialog::new()
            .set_title("Export trace as CSV")
            .add_filter("CSV", &["csv"])
            .set_file_name(format!("{}.csv", run_name(studio)))
            .save_file()
    {
        report(studio, std::fs::write(&path, data.to_csv()), &path);
    }
    if let Some(rect) = output.export_png {
        let (send, receive) = std::sync::mpsc::channel();
        let wake = ui.ctx().clone();
        studio.trace_view.png = Some((rect, receive));
        ui.ctx()
            .send_viewport_cmd(egui::ViewportCommand::Screenshot(
                egui::ScreenshotCallback::new(move |image| {
                    let _ = send.send(image);
                    wake.request_repaint();
                }),
            ));
    }
    take_screenshot(studio, ui);
}

fn run_name(studio: &Studio) -> String {
    let name = studio.online.trace().name();
    if name.is_empty() {
        "trace".to_owned()
    } else {
        name.to_owned()
    }
}

/// Saves the plot area of a screenshot that arrived for a PNG export.
fn take_screenshot(studio: &mut Studio, ui: &Ui) {
    let Some((rect, arrived)) = &studio.trace_view.png else {
        return;
    };
    let rect = *rect;
    let Ok(image) = arrived.try_recv() else {
        return;
    };
    studio.trace_view.png = None;
    let pixels_per_point = ui.ctx().pixels_per_point();
    match crop_to_png(&image, rect, pixels_per_point) {
        Ok(png) => {
            if let Some(path) = rfd::FileDialog::new()
                .set_title("Export trace as PNG")
                .add_filter("PNG", &["png"])
                .set_file_name(format!("{}.png", run_name(studio)))
                .save_file()
            {
                report(studio, std::fs::write(&path, png), &path);
            }
        }
        Err(error) => {
            studio.status = Some(super::studio_app::StatusMessage {
                text: format!("PNG export: {error}"),
                is_error: true,
            });
        }
    }
}

fn report(studio: &mut Studio, result: std::io::Result<()>, path: &std::path::Path) {
    studio.status = Some(match result {
        Ok(()) => super::studio_app::StatusMessage {
            text: format!("exported {}", path.display()),
            is_error: false,
        },
        Err(error) => super::studio_app::StatusMessage {
            text: format!("{}: {error}", path.display()),
            is_error: true,
        },
    });
}
