//! The messages pane: build diagnostics (click to jump to the source), problems found when the
//! project was opened, and online messages.

use egui::{Color32, RichText, Ui};
use project_model::Severity as LoadSeverity;

use crate::studio::i18n::Text;
use crate::studio::studio_app::{Command, Studio};

/// How many messages the pane lists (shown on its tab).
pub(crate) fn message_count(studio: &Studio) -> usize {
    studio.problems.len()
        + studio
            .last_build
            .as_ref()
            .map_or(0, |build| build.messages.len())
        + usize::from(
            studio
                .last_build
                .as_ref()
                .is_some_and(|b| b.failure.is_some()),
        )
}

pub(crate) fn messages_ui(studio: &mut Studio, ui: &mut Ui) {
    let language = studio.settings.language;
    let error = ui.visuals().error_fg_color;
    let warn = ui.visuals().warn_fg_color;
    ui.horizontal(|ui| {
        match &studio.last_build {
            Some(build) => {
                let (errors, warnings) = build.counts();
                ui.label(format!(
                    "{}: {errors} {}, {warnings} {}",
                    Text::Build.get(language),
                    Text::Errors.get(language),
                    Text::Warnings.get(language)
                ));
            }
            None => {
                ui.label(RichText::new(Text::NoBuildYet.get(language)).weak());
            }
        }
        if !studio.online_messages.is_empty()
            && ui.small_button(Text::Close.get(language)).clicked()
        {
            studio.online_messages.clear();
            studio.problems.clear();
        }
    });
    ui.separator();
    let mut open = None;
    let mut reveal = None;
    egui::ScrollArea::vertical()
        .id_salt("messages")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for problem in &studio.problems {
                let color = match problem.severity {
                    LoadSeverity::Error => error,
                    LoadSeverity::Warning => warn,
                };
                ui.label(RichText::new(problem.to_string()).monospace().color(color));
            }
            if let Some(build) = &studio.last_build {
                if let Some(failure) = &build.failure {
                    ui.label(RichText::new(failure).color(error));
                }
                egui::Grid::new("build_messages")
                    .num_columns(4)
                    .striped(true)
                    .spacing([12.0, 2.0])
                    .show(ui, |ui| {
                        for message in &build.messages {
                            let color = match message.severity {
                                compiler::Severity::Error => error,
                                compiler::Severity::Warning => warn,
                            };
                            ui.label(RichText::new(&message.code).monospace().color(color));
                            let location = if message.line > 0 {
                                format!(
                                    "{}:{}:{}",
                                    message.file.display(),
                                    message.line,
                                    message.column
                                )
                            } else {
                                message.file.display().to_string()
                            };
                            let clicked = ui
                                .link(RichText::new(location).monospace())
                                .on_hover_text("Open the source at this place")
                                .clicked();
                            let text = ui.label(&message.message).clicked();
                            if (clicked || text) && message.node.is_some() {
                                open = Some(message.clone());
                            }
                            ui.end_row();
                        }
                    });
            }
            if !studio.texts.references.is_empty() {
                ui.separator();
                ui.strong(format!(
                    "{} {} ({})",
                    Text::ReferencesTo.get(language),
                    studio.texts.references_of,
                    studio.texts.references.len()
                ));
                for reference in &studio.texts.references {
                    if ui
                        .link(RichText::new(&reference.label).monospace())
                        .clicked()
                    {
                        reveal = Some(reference.clone());
                    }
                }
            }
            for message in &studio.online_messages {
                let color = if message.is_error {
                    error
                } else {
                    Color32::GRAY
                };
                ui.label(RichText::new(format!("online: {}", message.text)).color(color));
            }
        });
    if let Some(reference) = reveal {
        studio.pending.push(Command::Reveal(
            reference.node,
            crate::studio::text_documents::Reveal::Body(reference.target, reference.range),
        ));
    }
    if let Some(message) = open
        && let Some(node) = message.node
    {
        match message.place {
            Some((target, range)) => studio.pending.push(Command::Reveal(
                node,
                crate::studio::text_documents::Reveal::Body(target, range),
            )),
            None => studio.pending.push(Command::Open(node)),
        }
    }
}
