//! The studio's frame around the docking layout: menu bar, tool bar with the online controls,
//! status bar, and the login dialog.

use egui::{RichText, Ui};
use online::{Reset, TargetState};

use super::i18n::{Language, Text};
use super::online::{Phase, TargetKind};
use super::settings::Theme;
use super::studio_app::{Command, Studio};

impl Studio {
    pub(crate) fn menu_bar_ui(&mut self, ui: &mut Ui) {
        let language = self.settings.language;
        let has_project = self.session.is_some();
        let logged_in = self.online.is_logged_in();
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button(Text::File.get(language), |ui| {
                self.menu_item(ui, Text::Open, "Ctrl+O", true, Command::OpenDialog);
                self.menu_item(ui, Text::Save, "Ctrl+S", has_project, Command::Save);
                self.menu_item(ui, Text::SaveAs, "", has_project, Command::SaveAsDialog);
                ui.separator();
                self.menu_item(ui, Text::Quit, "", true, Command::Quit);
            });
            ui.menu_button(Text::Edit.get(language), |ui| {
                let (undo, redo) = match &self.session {
                    Some(session) => (
                        session.history.undo_label().map(str::to_owned),
                        session.history.redo_label().map(str::to_owned),
                    ),
                    None => (None, None),
                };
                let undo_text = match &undo {
                    Some(label) => format!("{} {label}", Text::Undo.get(language)),
                    None => Text::Undo.get(language).to_owned(),
                };
                let redo_text = match &redo {
                    Some(label) => format!("{} {label}", Text::Redo.get(language)),
                    None => Text::Redo.get(language).to_owned(),
                };
                if ui
                    .add_enabled(
                        undo.is_some(),
                        egui::Button::new(undo_text).shortcut_text("Ctrl+Z"),
                    )
                    .clicked()
                {
                    self.pending.push(Command::Undo);
                }
                if ui
                    .add_enabled(
                        redo.is_some(),
                        egui::Button::new(redo_text).shortcut_text("Ctrl+Y"),
                    )
                    .clicked()
                {
                    self.pending.push(Command::Redo);
                }
            });
            ui.menu_button(Text::View.get(language), |ui| {
                self.menu_item(ui, Text::ResetLayout, "", true, Command::ResetLayout);
            });
            ui.menu_button(Text::Build.get(language), |ui| {
                self.menu_item(ui, Text::Build, "F11", has_project, Command::Build);
            });
            ui.menu_button(Text::Online.get(language), |ui| {
                self.menu_item(
                    ui,
                    Text::Login,
                    "Alt+F8",
                    has_project && !logged_in,
                    Command::Login,
                );
                self.menu_item(ui, Text::Logout, "Ctrl+F8", logged_in, Command::Logout);
                ui.separator();
                let online = self.online.is_online();
                self.menu_item(ui, Text::Start, "F5", online, Command::Start);
                self.menu_item(ui, Text::Stop, "Shift+F8", online, Command::Stop);
                self.menu_item(ui, Text::ResetWarm, "", online, Command::Reset(Reset::Warm));
                self.menu_item(ui, Text::ResetCold, "", online, Command::Reset(Reset::Cold));
                self.menu_item(
                    ui,
                    Text::ResetOrigin,
                    "",
                    online,
                    Command::Reset(Reset::Origin),
                );
                ui.separator();
                // Modbus devices are written and forced without a login.
                let online = self.online.can_write();
                self.menu_item(
                    ui,
                    Text::WriteValues,
                    "Ctrl+F7",
                    online,
                    Command::WritePrepared,
                );
                self.menu_item(ui, Text::ForceValues, "F7", online, Command::ForcePrepared);
                self.menu_item(
                    ui,
                    Text::ReleaseForces,
                    "Alt+F7",
                    online,
                    Command::ReleaseAllForces,
                );
            });
            ui.menu_button(Text::Settings.get(language), |ui| {
                ui.menu_button(Text::LanguageMenu.get(language), |ui| {
                    for choice in Language::ALL {
                        ui.radio_value(&mut self.settings.language, choice, choice.native_name());
                    }
                });
                ui.menu_button(Text::Theme.get(language), |ui| {
                    for (theme, text) in [(Theme::Dark, Text::Dark), (Theme::Light, Text::Light)] {
                        if ui
                            .radio_value(&mut self.settings.theme, theme, text.get(language))
                            .clicked()
                        {
                            ui.ctx().set_theme(theme.egui_theme());
                        }
                    }
                });
            });
            ui.menu_button(Text::Help.get(language), |ui| {
                ui.label(Text::AboutText.get(language));
                ui.label(format!("Rivet {}", env!("CARGO_PKG_VERSION")));
            });
        });
    }

    fn menu_item(
        &mut self,
        ui: &mut Ui,
        text: Text,
        shortcut: &str,
        enabled: bool,
        command: Command,
    ) {
        let button = egui::Button::new(text.get(self.settings.language)).shortcut_text(shortcut);
        if ui.add_enabled(enabled, button).clicked() {
            self.pending.push(command);
        }
    }

    /// A tool bar button with its shortcut in the hover text.
    fn tool_button(
        &mut self,
        ui: &mut Ui,
        text: Text,
        shortcut: &str,
        enabled: bool,
        command: Command,
    ) {
        let button = egui::Button::new(text.get(self.settings.language));
        if ui
            .add_enabled(enabled, button)
            .on_hover_text(shortcut)
            .clicked()
        {
            self.pending.push(command);
        }
    }

    /// The tool bar: build, the target choice, login and run control, as buttons with their
    /// shortcuts in the hover text.
    pub(crate) fn tool_bar_ui(&mut self, ui: &mut Ui) {
        let language = self.settings.language;
        let has_project = self.session.is_some();
        let logged_in = self.online.is_logged_in();
        let online = self.online.is_online();
        ui.horizontal(|ui| {
            let building = self.build.is_some();
            if ui
                .add_enabled(
                    has_project && !building,
                    egui::Button::new(Text::Build.get(language)),
                )
                .on_hover_text("F11")
                .clicked()
            {
                self.pending.push(Command::Build);
            }
            if building {
                ui.spinner();
            }
            ui.separator();
            ui.label(Text::Target.get(language));
            ui.add_enabled_ui(!logged_in, |ui| {
                let selected = match self.settings.target {
                    TargetKind::Simulation => Text::Simulation.get(language),
                    TargetKind::Controller => Text::Controller.get(language),
                };
                egui::ComboBox::from_id_salt("target")
                    .selected_text(selected)
                    .show_ui(ui, |ui| {
                        ui.selectable_value(
                            &mut self.settings.target,
                            TargetKind::Simulation,
                            Text::Simulation.get(language),
                        );
                        ui.selectable_value(
                            &mut self.settings.target,
                            TargetKind::Controller,
                            Text::Controller.get(language),
                        );
                    })
                    .response
                    .widget_info(|| {
                        egui::WidgetInfo::labeled(
                            egui::Role::ComboBox,
                            true,
                            Text::Target.get(language),
                        )
                    });
                if self.settings.target == TargetKind::Controller {
                    if let Some(session) = &self.session {
                        let controller = &session.project.controller;
                        ui.label(
                            RichText::new(format!("{}:{}", controller.host, controller.port))
                                .monospace(),
                        );
                    }
                    let label = ui.label(Text::Password.get(language));
                    ui.add(
                        egui::TextEdit::singleline(&mut self.password)
                            .password(true)
                            .desired_width(90.0),
                    )
                    .labelled_by(label.id);
                }
            });
            ui.separator();
            if logged_in {
                self.tool_button(ui, Text::Logout, "Ctrl+F8", true, Command::Logout);
            } else {
                self.tool_button(ui, Text::Login, "Alt+F8", has_project, Command::Login);
            }
            self.tool_button(ui, Text::Start, "F5", online, Command::Start);
            self.tool_button(ui, Text::Stop, "Shift+F8", online, Command::Stop);
            ui.add_enabled_ui(online, |ui| {
                ui.menu_button(Text::ResetMenu.get(language), |ui| {
                    for (text, kind) in [
                        (Text::ResetWarm, Reset::Warm),
                        (Text::ResetCold, Reset::Cold),
                        (Text::ResetOrigin, Reset::Origin),
                    ] {
                        if ui.button(text.get(language)).clicked() {
                            self.pending.push(Command::Reset(kind));
                        }
                    }
                });
            });
            ui.separator();
            // Modbus devices are written and forced without a login.
            let writable = self.online.can_write();
            self.tool_button(
                ui,
                Text::WriteValues,
                "Ctrl+F7",
                writable,
                Command::WritePrepared,
            );
            self.tool_button(
                ui,
                Text::ForceValues,
                "F7",
                writable,
                Command::ForcePrepared,
            );
            self.tool_button(
                ui,
                Text::ReleaseForces,
                "Alt+F7",
                writable,
                Command::ReleaseAllForces,
            );
        });
    }

    /// The online state in words and colour, for the status bar.
    fn online_state(&self) -> (String, Option<egui::Color32>) {
        let language = self.settings.language;
        let target = match self.settings.target {
            TargetKind::Simulation => Text::Simulation.get(language),
            TargetKind::Controller => Text::Controller.get(language),
        };
        match self.online.phase() {
            Phase::Offline => (Text::Offline.get(language).to_owned(), None),
            Phase::Connecting | Phase::ConfirmDownload { .. } => (
                format!("{target}: {}", Text::Connecting.get(language)),
                None,
            ),
            Phase::Downloading { sent, total } => (
                format!(
                    "{target}: {} {sent}/{total}",
                    Text::Downloading.get(language)
                ),
                None,
            ),
            Phase::Lost(_) => (
                format!("{target}: {}", Text::TargetLost.get(language)),
                Some(egui::Color32::from_rgb(220, 80, 60)),
            ),
            Phase::Online => {
                let state = self.online.target_state();
                let color = match state {
                    Some(TargetState::Running) => egui::Color32::from_rgb(60, 170, 80),
                    Some(TargetState::Faulted) => egui::Color32::from_rgb(220, 80, 60),
                    _ => egui::Color32::from_rgb(200, 160, 40),
                };
                let words = state.map_or("", TargetState::describe);
                (format!("{target}: {words}"), Some(color))
            }
        }
    }

    pub(crate) fn status_bar_ui(&self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            let (state, color) = self.online_state();
            let text = RichText::new(state).strong();
            ui.label(match color {
                Some(color) => text.color(color),
                None => text,
            });
            if self.online.is_online() {
                ui.label(RichText::new(format!("cycle {}", self.online.cycle())).weak());
            }
            if let Some(session) = &self.session {
                ui.separator();
                let dirty = if session.history.is_dirty() { " *" } else { "" };
                // The folder's name is enough to tell projects apart; the full path is on hover.
                let name = session.dir.file_name().map_or_else(
                    || session.dir.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                ui.label(RichText::new(format!("{name}{dirty}")).weak())
                    .on_hover_text(session.dir.display().to_string());
            }
            if let Some(status) = &self.status {
                ui.separator();
                let text = RichText::new(&status.text);
                ui.label(if status.is_error {
                    text.color(ui.visuals().error_fg_color)
                } else {
                    text
                });
            }
        });
    }

    /// The dialog that asks before a download and shows its progress.
    pub(crate) fn login_dialog_ui(&mut self, ctx: &egui::Context) {
        let language = self.settings.language;
        let (reason, progress) = match self.online.phase() {
            Phase::ConfirmDownload { reason } => (reason.clone(), None),
            Phase::Downloading { sent, total } => (
                String::new(),
                Some(if *total == 0 {
                    0.0
                } else {
                    *sent as f32 / *total as f32
                }),
            ),
            _ => return,
        };
        egui::Modal::new(egui::Id::unique("login_dialog")).show(ctx, |ui| {
            ui.set_width(420.0);
            ui.heading(Text::Login.get(language));
            match progress {
                None => {
                    ui.label(reason);
                    ui.label(Text::DownloadQuestion.get(language));
                    ui.horizontal(|ui| {
                        if ui.button(Text::Download.get(language)).clicked() {
                            self.online.confirm_download();
                        }
                        if ui.button(Text::Cancel.get(language)).clicked() {
                            self.online.cancel_download();
                        }
                    });
                }
                Some(fraction) => {
                    ui.label(Text::Downloading.get(language));
                    ui.add(egui::ProgressBar::new(fraction).show_percentage());
                }
            }
        });
    }
}
