//! The studio application: frame layout, menus, commands.

use std::path::{Path, PathBuf};

use egui::{RichText, Ui};
use project_model::{LoadProblem, Severity};

use super::device_tree::device_tree_ui;
use super::documents::Documents;
use super::fonts::install_fonts;
use super::i18n::{Language, Text};
use super::session::Session;
use super::settings::{SETTINGS_KEY, Settings, Theme};
use super::tree_node::TreeNode;

/// The studio: the open project, what is selected and open, and the settings.
pub struct StudioApp {
    settings: Settings,
    session: Option<Session>,
    /// Problems of the last attempt to open a project: errors when it failed, warnings when it
    /// opened. Shown in the messages panel until the next attempt.
    problems: Vec<LoadProblem>,
    /// The folder whose opening failed, shown with its errors.
    failed_dir: Option<PathBuf>,
    selection: Option<TreeNode>,
    documents: Documents,
    status: Option<StatusMessage>,
    /// Commands requested while drawing, run after the frame's UI.
    pending: Vec<Command>,
    title: String,
    /// Whether fonts and theme were installed into the egui context (done on the first frame).
    style_installed: bool,
}

/// A line for the status bar: what the last action did.
#[derive(Clone, Debug, PartialEq)]
pub struct StatusMessage {
    /// The text.
    pub text: String,
    /// Whether it reports a failure.
    pub is_error: bool,
}

/// Actions requested by menus and shortcuts, run after the UI pass so the project never changes
/// while it is drawn.
#[derive(Clone, Debug, PartialEq)]
enum Command {
    OpenDialog,
    Save,
    SaveAsDialog,
    Quit,
}

impl StudioApp {
    /// Creates the studio and opens `project_dir` if given. Fonts and theme are installed on
    /// the first frame, so the studio runs the same in a window and in a test harness.
    pub fn new(settings: Settings, project_dir: Option<PathBuf>) -> Self {
        let mut app = Self {
            settings,
            session: None,
            problems: Vec::new(),
            failed_dir: None,
            selection: None,
            documents: Documents::default(),
            status: None,
            pending: Vec::new(),
            title: String::new(),
            style_installed: false,
        };
        if let Some(dir) = project_dir {
            app.open_project(&dir);
        }
        app
    }

    /// Opens the project in `dir`. On failure the current project stays open and the errors
    /// are listed in the messages panel; nothing on disk is touched either way.
    pub fn open_project(&mut self, dir: &Path) {
        let language = self.settings.language;
        match Session::open(dir) {
            Ok(session) => {
                self.problems = session.warnings.clone();
                self.failed_dir = None;
                self.selection = None;
                self.documents.close_all();
                self.status = Some(StatusMessage {
                    text: format!("{} {}", Text::Opened.get(language), dir.display()),
                    is_error: false,
                });
                self.session = Some(session);
            }
            Err(error) => {
                self.problems = error.problems;
                self.failed_dir = Some(dir.to_owned());
                self.status = Some(StatusMessage {
                    text: format!("{}: {}", Text::CouldNotOpen.get(language), dir.display()),
                    is_error: true,
                });
            }
        }
    }

    /// The open project, if any.
    pub fn session(&self) -> Option<&Session> {
        self.session.as_ref()
    }

    /// The selected device tree node.
    pub fn selection(&self) -> Option<&TreeNode> {
        self.selection.as_ref()
    }

    /// The documents open in tabs.
    pub fn open_documents(&self) -> Vec<TreeNode> {
        self.documents.open_documents()
    }

    /// The problems listed in the messages panel.
    pub fn problems(&self) -> &[LoadProblem] {
        &self.problems
    }

    /// The status bar's message.
    pub fn status(&self) -> Option<&StatusMessage> {
        self.status.as_ref()
    }

    /// The settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Saves the open project to its folder.
    pub fn save(&mut self) {
        let language = self.settings.language;
        let Some(session) = &mut self.session else {
            return;
        };
        self.status = Some(match session.save() {
            Ok(report) if report.written.is_empty() && report.removed.is_empty() => StatusMessage {
                text: Text::NothingToSave.get(language).to_owned(),
                is_error: false,
            },
            Ok(report) => StatusMessage {
                text: format!(
                    "{}: {} file(s) written, {} removed",
                    Text::Saved.get(language),
                    report.written.len(),
                    report.removed.len()
                ),
                is_error: false,
            },
            Err(error) => StatusMessage {
                text: format!("{}: {error}", Text::SaveFailed.get(language)),
                is_error: true,
            },
        });
    }

    /// Saves the open project into `dir`, which must not hold another project.
    pub fn save_as(&mut self, dir: &Path) {
        let language = self.settings.language;
        let Some(session) = &mut self.session else {
            return;
        };
        self.status = Some(match session.save_as(dir) {
            Ok(_) => StatusMessage {
                text: format!("{} {}", Text::Saved.get(language), dir.display()),
                is_error: false,
            },
            Err(super::session::SaveAsError::FolderHoldsProject(_)) => StatusMessage {
                text: format!("{}: {}", Text::SaveAsRefused.get(language), dir.display()),
                is_error: true,
            },
            Err(error) => StatusMessage {
                text: format!("{}: {error}", Text::SaveFailed.get(language)),
                is_error: true,
            },
        });
    }

    /// Draws the whole studio into `ui` and then runs the commands requested while drawing.
    pub fn ui(&mut self, ui: &mut Ui) {
        if !self.style_installed {
            install_fonts(ui.ctx());
            ui.ctx().set_theme(self.settings.theme.egui_theme());
            self.style_installed = true;
        }
        self.handle_shortcuts(ui.ctx());
        self.update_title(ui.ctx());
        egui::Panel::top("menu_bar").show(ui, |ui| self.menu_bar_ui(ui));
        egui::Panel::bottom("status_bar").show(ui, |ui| self.status_bar_ui(ui));
        if !self.problems.is_empty() {
            egui::Panel::bottom("messages")
                .resizable(true)
                .default_size(140.0)
                .show(ui, |ui| self.messages_ui(ui));
        }
        egui::Panel::left("device_tree")
            .resizable(true)
            .default_size(260.0)
            .show(ui, |ui| self.device_tree_panel_ui(ui));
        egui::CentralPanel::default_margins().show(ui, |ui| self.central_ui(ui));
        self.run_pending(ui.ctx());
    }

    fn handle_shortcuts(&mut self, ctx: &egui::Context) {
        let save = egui::KeyboardShortcut::new(egui::Modifiers::COMMAND, egui::Key::S);
        let open = egui::KeyboardShortcut::new(egui::Modifiers::COMMAND, egui::Key::O);
        if ctx.input_mut(|input| input.consume_shortcut(&save)) {
            self.pending.push(Command::Save);
        }
        if ctx.input_mut(|input| input.consume_shortcut(&open)) {
            self.pending.push(Command::OpenDialog);
        }
    }

    fn update_title(&mut self, ctx: &egui::Context) {
        let title = match &self.session {
            Some(session) => {
                let dirty = if session.history.is_dirty() { "*" } else { "" };
                format!("{}{dirty} — Rivet", session.title())
            }
            None => "Rivet".to_owned(),
        };
        if title != self.title {
            ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.title = title;
        }
    }

    fn menu_bar_ui(&mut self, ui: &mut Ui) {
        let language = self.settings.language;
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button(Text::File.get(language), |ui| {
                if ui.button(Text::Open.get(language)).clicked() {
                    self.pending.push(Command::OpenDialog);
                }
                let has_project = self.session.is_some();
                if ui
                    .add_enabled(
                        has_project,
                        egui::Button::new(Text::Save.get(language)).shortcut_text("Ctrl+S"),
                    )
                    .clicked()
                {
                    self.pending.push(Command::Save);
                }
                if ui
                    .add_enabled(has_project, egui::Button::new(Text::SaveAs.get(language)))
                    .clicked()
                {
                    self.pending.push(Command::SaveAsDialog);
                }
                ui.separator();
                if ui.button(Text::Quit.get(language)).clicked() {
                    self.pending.push(Command::Quit);
                }
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

    fn status_bar_ui(&self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            if let Some(session) = &self.session {
                ui.label(RichText::new(session.dir.display().to_string()).weak());
                ui.separator();
                ui.label(format!(
                    "{} objects",
                    session.project.application.objects().len()
                ));
                ui.separator();
                ui.label(RichText::new(Text::ReadOnly.get(self.settings.language)).weak());
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

    fn messages_ui(&mut self, ui: &mut Ui) {
        let language = self.settings.language;
        ui.horizontal(|ui| {
            ui.strong(Text::Messages.get(language));
            ui.label(format!(
                "{} {}",
                self.problems.len(),
                Text::ProblemsFound.get(language)
            ));
            if ui.small_button(Text::Close.get(language)).clicked() {
                self.problems.clear();
            }
        });
        egui::ScrollArea::vertical()
            .auto_shrink([false, false])
            .show(ui, |ui| {
                for problem in &self.problems {
                    let color = match problem.severity {
                        Severity::Error => ui.visuals().error_fg_color,
                        Severity::Warning => ui.visuals().warn_fg_color,
                    };
                    ui.label(RichText::new(problem.to_string()).monospace().color(color));
                }
            });
    }

    fn device_tree_panel_ui(&mut self, ui: &mut Ui) {
        let language = self.settings.language;
        ui.heading(Text::Devices.get(language));
        ui.separator();
        let Some(session) = &self.session else {
            ui.label(Text::NoProjectOpen.get(language));
            return;
        };
        let response = device_tree_ui(ui, &session.project, self.selection.as_ref(), language);
        if let Some(node) = response.clicked {
            self.selection = Some(node);
        }
        if let Some(node) = response.opened {
            self.selection = Some(node.clone());
            if node.is_document() {
                self.documents.open(node);
            }
        }
    }

    fn central_ui(&mut self, ui: &mut Ui) {
        let language = self.settings.language;
        if let Some(dir) = &self.failed_dir
            && self.session.is_none()
        {
            ui.heading(Text::CouldNotOpen.get(language));
            ui.label(dir.display().to_string());
            ui.label(Text::NoProjectHint.get(language));
            return;
        }
        match &self.session {
            Some(session) if !self.documents.is_empty() => {
                self.documents.ui(ui, Some(&session.project), language);
            }
            Some(session) => {
                ui.vertical_centered(|ui| {
                    ui.add_space(ui.available_height() / 3.0);
                    ui.heading(session.title());
                    if !session.project.description.is_empty() {
                        ui.label(&session.project.description);
                    }
                    ui.label(RichText::new(Text::OpenObjectHint.get(language)).weak());
                });
            }
            None => {
                ui.vertical_centered(|ui| {
                    ui.add_space(ui.available_height() / 3.0);
                    ui.heading(Text::NoProjectOpen.get(language));
                    ui.label(Text::NoProjectHint.get(language));
                });
            }
        }
    }

    fn run_pending(&mut self, ctx: &egui::Context) {
        for command in std::mem::take(&mut self.pending) {
            match command {
                Command::OpenDialog => {
                    if let Some(dir) = rfd::FileDialog::new()
                        .set_title("Open Rivet project folder")
                        .pick_folder()
                    {
                        self.open_project(&dir);
                    }
                }
                Command::Save => self.save(),
                Command::SaveAsDialog => {
                    if let Some(dir) = rfd::FileDialog::new()
                        .set_title("Save Rivet project into folder")
                        .pick_folder()
                    {
                        self.save_as(&dir);
                    }
                }
                Command::Quit => ctx.send_viewport_cmd(egui::ViewportCommand::Close),
            }
        }
    }
}

impl eframe::App for StudioApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        StudioApp::ui(self, ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, SETTINGS_KEY, &self.settings);
    }
}
