//! The trace pane: pick a trace of the project, start it on the target, upload and look at the
//! samples.

use egui::{RichText, Ui};
use project_model::{Object, TraceConfig};

use crate::studio::i18n::Text;
use crate::studio::online::TracePhase;
use crate::studio::studio_app::Studio;

/// What the trace pane remembers between frames.
#[derive(Default)]
pub struct TracePaneState {
    /// The trace shown; the first one when `None` or gone.
    pub selected: Option<String>,
}

fn traces(studio: &Studio) -> Vec<TraceConfig> {
    match &studio.session {
        Some(session) => project_model::object_files(&session.project)
            .into_iter()
            .filter_map(|(_, object)| match object {
                Object::Trace(trace) => Some(trace.clone()),
                _ => None,
            })
            .collect(),
        None => Vec::new(),
    }
}

pub(crate) fn trace_ui(studio: &mut Studio, ui: &mut Ui) {
    let language = studio.settings.language;
    let all = traces(studio);
    let current = studio
        .trace
        .selected
        .as_ref()
        .and_then(|name| all.iter().find(|trace| trace.name == *name))
        .or_else(|| all.first())
        .cloned();
    let Some(config) = current else {
        ui.label(RichText::new(Text::NoTrace.get(language)).weak());
        return;
    };
    let online = studio.online.is_online();
    ui.horizontal(|ui| {
        let label = ui.label(Text::Trace.get(language));
        egui::ComboBox::from_id_salt("trace_choice")
            .selected_text(&config.name)
            .show_ui(ui, |ui| {
                for trace in &all {
                    if ui
                        .selectable_label(trace.name == config.name, &trace.name)
                        .clicked()
                    {
                        studio.trace.selected = Some(trace.name.clone());
                    }
                }
            })
            .response
            .labelled_by(label.id);
        if ui
            .add_enabled(online, egui::Button::new(Text::StartTrace.get(language)))
            .clicked()
        {
            studio.online.trace_start(&config);
        }
        let phase = studio.online.trace().phase();
        let can_upload = online
            && matches!(
                phase,
                TracePhase::Recording { .. } | TracePhase::Complete | TracePhase::Uploaded
            );
        if ui
            .add_enabled(
                can_upload,
                egui::Button::new(Text::UploadTrace.get(language)),
            )
            .clicked()
        {
            studio.online.trace_upload();
        }
        phase_ui(ui, phase, config.record_count, language);
    });
    ui.label(
        RichText::new(format!(
            "{} {} · {} {} · {}",
            Text::Task.get(language),
            config.task,
            config.record_count,
            Text::Samples.get(language),
            config
                .trigger
                .as_ref()
                .map(|t| format!(
                    "{:?} {} ({}%)",
                    t.condition, t.variable, t.pre_trigger_percent
                ))
                .unwrap_or_default()
        ))
        .weak(),
    );
    ui.separator();
    super::super::trace_view::trace_samples_ui(studio, ui, Some(&config));
}

fn phase_ui(
    ui: &mut Ui,
    phase: TracePhase,
    record_count: u32,
    language: crate::studio::i18n::Language,
) {
    match phase {
        TracePhase::Idle => {}
        TracePhase::Resolving | TracePhase::Arming => {
            ui.spinner();
        }
        TracePhase::Recording {
            recorded,
            triggered,
        } => {
            let fraction = recorded as f32 / record_count.max(1) as f32;
            let text = if triggered {
                Text::Triggered.get(language)
            } else {
                Text::Recording.get(language)
            };
            ui.add(
                egui::ProgressBar::new(fraction)
                    .desired_width(160.0)
                    .text(format!("{text} {recorded}")),
            );
        }
        TracePhase::Complete => {
            ui.label(Text::Complete.get(language));
        }
        TracePhase::Uploading { received, total } => {
            let fraction = received as f32 / total.max(1) as f32;
            ui.add(
                egui::ProgressBar::new(fraction)
                    .desired_width(160.0)
                    .text(format!(
                        "{} {received}/{total}",
                        Text::Uploading.get(language)
                    )),
            );
        }
        TracePhase::Uploaded => {}
    }
}
