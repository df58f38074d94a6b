//! The uploaded samples of a trace, as the trace pane shows them.

use egui::{RichText, Ui};

use super::studio_app::Studio;
use crate::value_text::numeric;

/// Draws the uploaded samples of the current trace run: per variable its last, lowest and
/// highest value over the recording.
pub(crate) fn trace_samples_ui(studio: &mut Studio, ui: &mut Ui) {
    let run = studio.online.trace();
    let samples = run.samples();
    if samples.is_empty() {
        ui.label(RichText::new("No samples yet: start the trace, then upload it.").weak());
        return;
    }
    ui.label(format!("{} samples of {}", samples.len(), run.name()));
    egui::Grid::new("trace_summary")
        .striped(true)
        .show(ui, |ui| {
            ui.strong("Variable");
            ui.strong("Last");
            ui.strong("Lowest");
            ui.strong("Highest");
            ui.end_row();
            for (index, (path, resolved)) in run.variables().iter().enumerate() {
                let values: Vec<f64> = samples
                    .iter()
                    .filter_map(|sample| sample.values.get(index))
                    .filter_map(|bytes| numeric(resolved, bytes))
                    .collect();
                ui.label(RichText::new(path).monospace());
                let show = |v: Option<f64>| v.map_or_else(|| "—".to_owned(), |v| format!("{v}"));
                ui.label(show(values.last().copied()));
                ui.label(show(values.iter().copied().reduce(f64::min)));
                ui.label(show(values.iter().copied().reduce(f64::max)));
                ui.end_row();
            }
        });
}
