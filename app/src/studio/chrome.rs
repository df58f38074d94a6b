//! The studio's frame around the docking layout: menu bar, tool bar with the online controls,
//! and status bar (the login dialog is in `login_dialog.rs`).

use egui::{RichText, Ui};
use online::{Reset, TargetState};

use super::command::{Command, Commands};
use super::debug::DebugCommand;
use super::i18n::{ChartText, DebugText, ExportText, ImportText, Language, Text};
use super::modbus_online::polling_status;
use super::online::{Phase, TargetKind};
use super::pane::Pane;
use super::settings::Theme;
use super::theme::colors_for;
use super::view::StudioView;

/// What the tool bar keeps between frames.
#[derive(Default)]
pub(crate) struct ChromeState {
    /// The password typed for the controller (never saved).
    password: String,
}

impl ChromeState {
    /// The password typed for the controller, if any.
    pub fn password(&self) -> Option<String> {
        (!self.password.is_empty()).then(|| self.password.clone())
    }
}

/// The menu and tool bars and the login dialog while they draw: what they read and where their
/// commands go.
struct Chrome<'a, 'c> {
    view: StudioView<'a>,
    commands: &'c mut Commands,
}

/// The menu bar; every item emits a command.
pub(crate) fn menu_bar_ui(ui: &mut Ui, view: StudioView<'_>, commands: &mut Commands) {
    Chrome { view, commands }.menu_bar_ui(ui);
}

/// The tool bar: build, the target choice, login and run control.
pub(crate) fn tool_bar_ui(
    ui: &mut Ui,
    view: StudioView<'_>,
    state: &mut ChromeState,
    commands: &mut Commands,
) {
    Chrome { view, commands }.tool_bar_ui(ui, state);
}

/// The status bar: the online state, the project and the last action's message.
pub(crate) fn status_bar_ui(ui: &mut Ui, view: StudioView<'_>) {
    ui.horizontal(|ui| {
        let (state, color) = online_state(view, ui.visuals().dark_mode);
        let text = RichText::new(state).strong();
        ui.label(match color {
            Some(color) => text.color(color),
            None => text,
        });
        if view.online.is_online() {
            let cycle = format!("{} {}", Text::Cycle.get(view.language), view.online.cycle());
            ui.label(RichText::new(cycle).weak());
        }
        if let Some(polling) = simulator_polling(view) {
            ui.separator();
            ui.label(polling);
        }
        if let Some(session) = view.session {
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
        if let Some(status) = view.status {
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

impl Chrome<'_, '_> {
    fn menu_bar_ui(&mut self, ui: &mut Ui) {
        let language = self.view.language;
        let has_project = self.view.session.is_some();
        let logged_in = self.view.online.is_logged_in();
        egui::MenuBar::new().ui(ui, |ui| {
            ui.menu_button(Text::File.get(language), |ui| {
                self.menu_item(ui, Text::Open, "Ctrl+O", true, Command::OpenDialog);
                self.menu_item(ui, Text::Save, "Ctrl+S", has_project, Command::Save);
                self.menu_item(ui, Text::SaveAs, "", has_project, Command::SaveAsDialog);
                ui.separator();
                let import = egui::Button::new(ImportText::MenuItem.get(language));
                if ui.add(import).clicked() {
                    self.commands.push(Command::ImportPlcopenDialog);
                }
                let export = egui::Button::new(ExportText::MenuItem.get(language));
                if ui.add_enabled(has_project, export).clicked() {
                    self.commands.push(Command::ExportPlcopenDialog);
                }
                ui.separator();
                self.menu_item(ui, Text::Quit, "", true, Command::Quit);
            });
            ui.menu_button(Text::Edit.get(language), |ui| {
                let (undo, redo) = match self.view.session {
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
                    self.commands.push(Command::Undo);
                }
                if ui
                    .add_enabled(
                        redo.is_some(),
                        egui::Button::new(redo_text).shortcut_text("Ctrl+Y"),
                    )
                    .clicked()
                {
                    self.commands.push(Command::Redo);
                }
            });
            ui.menu_button(Text::View.get(language), |ui| {
                self.menu_item(ui, Text::ResetLayout, "", true, Command::ResetLayout);
                let order = ChartText::DisplayExecutionOrder.get(language);
                if ui.button(order).clicked() {
                    self.commands.push(Command::ToggleExecutionOrder);
                }
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
                let online = self.view.online.is_online();
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
                let online = self.view.online.can_write();
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
            self.debug_menu_ui(ui);
            ui.menu_button(Text::Settings.get(language), |ui| {
                ui.menu_button(Text::LanguageMenu.get(language), |ui| {
                    for choice in Language::ALL {
                        if ui.radio(language == choice, choice.native_name()).clicked() {
                            self.commands.push(Command::SetLanguage(choice));
                        }
                    }
                });
                ui.menu_button(Text::Theme.get(language), |ui| {
                    for (theme, text) in [(Theme::Dark, Text::Dark), (Theme::Light, Text::Light)] {
                        let chosen = self.view.settings.theme == theme;
                        if ui.radio(chosen, text.get(language)).clicked() {
                            self.commands.push(Command::SetTheme(theme));
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

    /// The Debug menu (`docs/debugging.md` §4): breakpoints work offline, the rest while
    /// logged in, stepping while a task is halted.
    fn debug_menu_ui(&mut self, ui: &mut Ui) {
        let language = self.view.language;
        let has_project = self.view.session.is_some();
        let logged_in = self.view.online.is_logged_in();
        let halted = self.view.debug.is_halted();
        ui.menu_button(DebugText::Debug.get(language), |ui| {
            let items = [
                (
                    DebugText::ToggleBreakpoint,
                    "F9",
                    has_project,
                    Command::ToggleBreakpointAtCaret,
                ),
                (
                    DebugText::Continue,
                    "F5",
                    halted,
                    Command::Debug(DebugCommand::Continue),
                ),
                (
                    DebugText::StepOver,
                    "F10",
                    halted,
                    Command::Debug(DebugCommand::StepOver),
                ),
                (
                    DebugText::StepInto,
                    "F8",
                    halted,
                    Command::Debug(DebugCommand::StepInto),
                ),
                (
                    DebugText::StepOut,
                    "Shift+F10",
                    halted,
                    Command::Debug(DebugCommand::StepOut),
                ),
                (DebugText::RunToCursor, "", halted, Command::RunToCaret),
                (
                    DebugText::HaltAll,
                    "",
                    logged_in,
                    Command::Debug(DebugCommand::HaltAll),
                ),
            ];
            for (text, shortcut, enabled, command) in items {
                let button = egui::Button::new(text.get(language)).shortcut_text(shortcut);
                if ui.add_enabled(enabled, button).clicked() {
                    self.commands.push(command);
                }
            }
            let tasks = self.view.online.tasks();
            ui.add_enabled_ui(logged_in && !tasks.is_empty(), |ui| {
                ui.menu_button(DebugText::HaltTask.get(language), |ui| {
                    for task in tasks {
                        if ui.button(&task.name).clicked() {
                            self.commands
                                .push(Command::Debug(DebugCommand::Halt(task.name.clone())));
                        }
                    }
                });
            });
            let mut flow = self.view.debug.flow_control;
            if ui
                .checkbox(&mut flow, DebugText::FlowControl.get(language))
                .changed()
            {
                self.commands
                    .push(Command::Debug(DebugCommand::SetFlowControl(flow)));
            }
            ui.separator();
            for (text, pane) in [
                (DebugText::Breakpoints, Pane::Breakpoints),
                (DebugText::CallStack, Pane::CallStack),
            ] {
                if ui.button(text.get(language)).clicked() {
                    self.commands.push(Command::ShowPane(pane));
                }
            }
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
        let button = egui::Button::new(text.get(self.view.language)).shortcut_text(shortcut);
        if ui.add_enabled(enabled, button).clicked() {
            self.commands.push(command);
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
        let button = egui::Button::new(text.get(self.view.language));
        if ui
            .add_enabled(enabled, button)
            .on_hover_text(shortcut)
            .clicked()
        {
            self.commands.push(command);
        }
    }

    /// The tool bar's buttons have their shortcuts in the hover text.
    fn tool_bar_ui(&mut self, ui: &mut Ui, state: &mut ChromeState) {
        let language = self.view.language;
        let has_project = self.view.session.is_some();
        let logged_in = self.view.online.is_logged_in();
        let online = self.view.online.is_online();
        ui.horizontal(|ui| {
            let building = self.view.building;
            if ui
                .add_enabled(
                    has_project && !building,
                    egui::Button::new(Text::Build.get(language)),
                )
                .on_hover_text("F11")
                .clicked()
            {
                self.commands.push(Command::Build);
            }
            if building {
                ui.spinner();
            }
            ui.separator();
            ui.label(Text::Target.get(language));
            ui.add_enabled_ui(!logged_in, |ui| {
                let chosen = self.view.settings.target;
                let selected = match chosen {
                    TargetKind::Simulation => Text::Simulation.get(language),
                    TargetKind::Controller => Text::Controller.get(language),
                };
                egui::ComboBox::from_id_salt("target")
                    .selected_text(selected)
                    .show_ui(ui, |ui| {
                        for (target, text) in [
                            (TargetKind::Simulation, Text::Simulation),
                            (TargetKind::Controller, Text::Controller),
                        ] {
                            if ui
                                .selectable_label(chosen == target, text.get(language))
                                .clicked()
                                && chosen != target
                            {
                                self.commands.push(Command::SetTarget(target));
                            }
                        }
                    })
                    .response
                    .widget_info(|| {
                        egui::WidgetInfo::labeled(
                            egui::Role::ComboBox,
                            true,
                            Text::Target.get(language),
                        )
                    });
                if chosen == TargetKind::Controller {
                    if let Some(session) = self.view.session {
                        let controller = &session.project.controller;
                        ui.label(
                            RichText::new(format!("{}:{}", controller.host, controller.port))
                                .monospace(),
                        );
                    }
                    let label = ui.label(Text::Password.get(language));
                    ui.add(
                        egui::TextEdit::singleline(&mut state.password)
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
                            self.commands.push(Command::Reset(kind));
                        }
                    }
                });
            });
            ui.separator();
            // Modbus devices are written and forced without a login.
            let writable = self.view.online.can_write();
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
}

/// "Simulator: polling 2 Modbus devices" while logged in to the simulator with a program whose
/// runtime master polls devices (`docs/modbus-master.md` §6.11): the devices get real traffic
/// from this computer, which the user should know.
fn simulator_polling(view: StudioView<'_>) -> Option<String> {
    let online = view.online;
    if !online.is_online() || online.logged_in_target() != Some(TargetKind::Simulation) {
        return None;
    }
    polling_status(online.runtime_device_count(), view.language)
}

/// The online state in words and colour, for the status bar.
fn online_state(view: StudioView<'_>, dark_mode: bool) -> (String, Option<egui::Color32>) {
    let language = view.language;
    let colors = colors_for(dark_mode);
    let target = match view.settings.target {
        TargetKind::Simulation => Text::Simulation.get(language),
        TargetKind::Controller => Text::Controller.get(language),
    };
    match view.online.phase() {
        Phase::Offline => (Text::Offline.get(language).to_owned(), None),
        Phase::Connecting
        | Phase::ConfirmDownload { .. }
        | Phase::CheckingChange { .. }
        | Phase::ChooseLogin(_)
        | Phase::ApplyingChange => (
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
            Some(colors.target_failed),
        ),
        Phase::Online => {
            let state = view.online.target_state();
            if state == Some(TargetState::Running) && view.debug.is_halted() {
                // CODESYS says a running application is halted while a task stands at a
                // breakpoint: the other tasks run, but the program is not running freely.
                let words = Text::StateHalted.get(language);
                return (format!("{target}: {words}"), Some(colors.target_stopped));
            }
            let color = match state {
                Some(TargetState::Running) => colors.target_running,
                Some(TargetState::Faulted) => colors.target_failed,
                _ => colors.target_stopped,
            };
            let words = state.map_or("", |state| {
                match state {
                    TargetState::NoProgram => Text::StateNoProgram,
                    TargetState::Stopped => Text::StateStopped,
                    TargetState::Running => Text::StateRunning,
                    TargetState::Faulted => Text::StateFaulted,
                }
                .get(language)
            });
            (format!("{target}: {words}"), Some(color))
        }
    }
}
