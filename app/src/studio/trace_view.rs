//! The uploaded samples of a trace as the trace pane plots them, and the CSV and PNG exports.

use std::sync::Arc;

use egui::Ui;

use super::command::{Command, Commands};
use super::online::TraceRun;
use super::trace_plot::{
    PngExportError, TraceData, TraceSample, TraceSeries, crop_to_png, parse_color,
};
use super::view::StudioView;
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

impl TraceViewState {
    /// The plotted data as CSV.
    pub fn csv(&self) -> String {
        self.data.to_csv()
    }

    /// Asks egui for a screenshot, of which `rect` (in points) will be saved as PNG.
    pub fn request_png(&mut self, ctx: &egui::Context, rect: egui::Rect) {
        let (send, receive) = std::sync::mpsc::channel();
        let wake = ctx.clone();
        self.png = Some((rect, receive));
        ctx.send_viewport_cmd(egui::ViewportCommand::Screenshot(
            egui::ScreenshotCallback::new(move |image| {
                // The export may have been replaced by another meanwhile; then nobody waits.
                let _ = send.send(image);
                wake.request_repaint();
            }),
        ));
    }

    /// The PNG of the plot area, once the screenshot a PNG export asked for arrived.
    pub fn take_png(&mut self, pixels_per_point: f32) -> Option<Result<Vec<u8>, PngExportError>> {
        let (rect, arrived) = self.png.as_ref()?;
        let rect = *rect;
        let image = arrived.try_recv().ok()?;
        self.png = None;
        Some(crop_to_png(&image, rect, pixels_per_point))
    }
}

/// Plots the current trace run; the exports the plot asks for become commands.
pub(crate) fn trace_samples_ui(
    view: StudioView<'_>,
    state: &mut TraceViewState,
    commands: &mut Commands,
    ui: &mut Ui,
    config: Option<&project_model::TraceConfig>,
) {
    let run = view.online.trace();
    let key = (
        run.name().to_owned(),
        run.samples().len(),
        run.samples().first().map_or(0, |s| s.cycle),
    );
    if state.made_from.as_ref() != Some(&key) {
        state.data = Arc::new(trace_data(run, config));
        state.made_from = Some(key);
    }
    state.plot.language = view.language;
    let data = Arc::clone(&state.data);
    let output = state.plot.ui(ui, &data);
    if output.export_csv {
        commands.push(Command::ExportTraceCsv);
    }
    if let Some(rect) = output.export_png {
        commands.push(Command::ExportTracePng(rect));
    }
}
