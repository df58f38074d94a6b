//! The messages pane: build diagnostics (click to jump to the source), problems found when the
//! project was opened, and online messages.

use egui::{RichText, Ui};
use project_model::Severity as LoadSeverity;

use crate::studio::command::{Command, Commands};
use crate::studio::i18n::Text;
use crate::studio::reveal::Reveal;
use crate::studio::theme;
use crate::studio::view::StudioView;

/// How many messages the pane lists (shown on its tab).
pub(crate) fn message_count(view: StudioView<'_>) -> usize {
    view.problems.len()
        + view.last_build.map_or(0, |build| build.messages.len())
        + usize::from(view.last_build.is_some_and(|b| b.failure.is_some()))
}

/// Draws the messages pane; a click on a message opens its place.
pub(crate) fn messages_ui(view: StudioView<'_>, commands: &mut Commands, ui: &mut Ui) {
    let language = view.language;
    let error = ui.visuals().error_fg_color;
    let warn = ui.visuals().warn_fg_color;
    ui.horizontal(|ui| {
        match view.last_build {
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
        if !view.online_messages.is_empty() && ui.small_button(Text::Close.get(language)).clicked()
        {
            commands.push(Command::ClearMessages);
        }
    });
    ui.separator();
    let mut open = None;
    let mut reveal = None;
    egui::ScrollArea::vertical()
        .id_salt("messages")
        .auto_shrink([false, false])
        .show(ui, |ui| {
            for problem in view.problems {
                let color = match problem.severity {
                    LoadSeverity::Error => error,
                    LoadSeverity::Warning => warn,
                };
                ui.label(RichText::new(problem.to_string()).monospace().color(color));
            }
            if let Some(build) = view.last_build {
                if let Some(failure) = &build.failure {
                    ui.label(RichText::new(failure.text(language)).color(error));
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
                            let location = if let Some(place) = &message.element {
                                format!("{}:{place}", message.file.display())
                            } else if message.line > 0 {
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
                                .on_hover_text(Text::OpenSourceHere.get(language))
                                .clicked();
                            let text = ui.label(&message.message).clicked();
                            if (clicked || text) && message.node.is_some() {
                                open = Some(message.clone());
                            }
                            ui.end_row();
                        }
                    });
            }
            if !view.references.items.is_empty() {
                ui.separator();
                ui.strong(format!(
                    "{} {} ({})",
                    Text::ReferencesTo.get(language),
                    view.references.of,
                    view.references.items.len()
                ));
                for reference in &view.references.items {
                    if ui
                        .link(RichText::new(&reference.label).monospace())
                        .clicked()
                    {
                        reveal = Some(reference.clone());
                    }
                }
            }
            for message in view.online_messages {
                let color = if message.is_error {
                    error
                } else {
                    theme::colors(ui).quiet_message
                };
                let text = format!("{}: {}", Text::OnlinePrefix.get(language), message.text);
                ui.label(RichText::new(text).color(color));
            }
        });
    if let Some(reference) = reveal {
        commands.push(Command::Reveal(
            reference.node,
            Reveal::Body(reference.target, reference.range),
        ));
    }
    if let Some(message) = open
        && let Some(node) = message.node
    {
        match (message.place, message.element) {
            (Some((target, range)), _) => {
                commands.push(Command::Reveal(node, Reveal::Body(target, range)))
            }
            (None, Some(place)) => commands.push(Command::Reveal(
                node,
                Reveal::Element {
                    target: place.target,
                    network: place.network,
                    element: place.element,
                },
            )),
            (None, None) => commands.push(Command::Open(node)),
        }
    }
}
