//! The studio application: the docking layout, the frame around it, and the one place where
//! the commands of menus, shortcuts and panes are applied.

mod apply;
mod build_flow;
mod debug_flow;
mod editor_hint;
mod export_flow;
mod frame;
mod import_flow;
mod project_io;
mod recovery_copy;
mod shortcuts;
mod state;

use std::path::{Path, PathBuf};

use egui::Ui;
use project_model::LoadProblem;

use super::build_job::BuildOutcome;
use super::chrome;
use super::command::Command;
use super::debug::{DebugState, HaltedTask};
use super::dock::{Dock, LAYOUT_KEY};
use super::fonts::install_fonts;
use super::login_dialog;
use super::online::{Online, TargetKind};
use super::pane_behavior::PaneBehavior;
use super::recovery::Recovery;
use super::session::Session;
use super::settings::{SETTINGS_KEY, Settings};
use super::status::StatusMessage;
use super::theme;
use super::tree_node::TreeNode;
use state::Studio;

/// The studio: the docking layout and everything the panes show.
pub struct StudioApp {
    dock: Dock,
    studio: Studio,
}

/// How the studio starts.
pub struct StudioOptions {
    /// The settings.
    pub settings: Settings,
    /// The saved layout, if any.
    pub layout: Option<Dock>,
    /// The project folder to open.
    pub project: Option<PathBuf>,
    /// Where copies of unsaved changes are kept; `None` keeps none.
    pub recovery: Option<Recovery>,
}

impl StudioApp {
    /// Creates the studio with the default layout and opens `project_dir` if given. Fonts and
    /// theme are installed on the first frame, so the studio runs the same in a window and in a
    /// test harness.
    pub fn new(settings: Settings, project_dir: Option<PathBuf>) -> Self {
        Self::with_options(StudioOptions {
            settings,
            layout: None,
            project: project_dir,
            recovery: None,
        })
    }

    /// Creates the studio with a saved layout (checked, see [`Dock::restored`]) and a recovery
    /// folder for unsaved changes.
    pub fn with_options(options: StudioOptions) -> Self {
        let StudioOptions {
            settings,
            layout,
            project: project_dir,
            recovery,
        } = options;
        let mut app = Self {
            dock: Dock::restored(layout),
            studio: Studio::new(settings, recovery),
        };
        if let Some(dir) = project_dir {
            app.open_project(&dir);
        }
        app
    }

    /// Opens the project in `dir`. On failure the current project stays open and the errors
    /// are listed in the messages panel; nothing on disk is touched either way.
    pub fn open_project(&mut self, dir: &Path) {
        self.studio.open_project(&mut self.dock, dir);
    }

    /// The open project, if any.
    pub fn session(&self) -> Option<&Session> {
        self.studio.shared.session.as_ref()
    }

    /// The selected device tree node.
    pub fn selection(&self) -> Option<&TreeNode> {
        self.studio.shared.selection.as_ref()
    }

    /// The documents open in tabs.
    pub fn open_documents(&self) -> Vec<TreeNode> {
        self.dock.documents()
    }

    /// The problems of the last project load.
    pub fn problems(&self) -> &[LoadProblem] {
        &self.studio.shared.problems
    }

    /// The last build's outcome.
    pub fn last_build(&self) -> Option<&BuildOutcome> {
        self.studio.shared.last_build.as_ref()
    }

    /// Whether a build is running.
    pub fn is_building(&self) -> bool {
        self.studio.shared.build.is_some()
    }

    /// The online state.
    pub fn online(&self) -> &Online {
        &self.studio.shared.online
    }

    /// The status bar's message.
    pub fn status(&self) -> Option<&StatusMessage> {
        self.studio.shared.status.as_ref()
    }

    /// The settings.
    pub fn settings(&self) -> &Settings {
        &self.studio.shared.settings
    }

    /// The live check's findings in a POU as `CODE: message`, for tests and tools.
    pub fn live_findings(&self, pou: &str) -> Vec<String> {
        self.studio.panes.texts.live_findings(pou)
    }

    /// The variable paths whose values the open editors show inline.
    pub fn inline_paths(&self) -> Vec<String> {
        self.studio.panes.texts.inline.paths().cloned().collect()
    }

    /// The selection of the editor of a body, if it is open.
    pub fn body_selection(
        &self,
        target: &project_model::TextTarget,
    ) -> Option<std::ops::Range<usize>> {
        self.studio.panes.texts.body_selection(target)
    }

    /// The debugger's marks in the editor of a Structured Text body, once it was drawn.
    pub fn body_debug_marks(
        &self,
        target: &project_model::TextTarget,
    ) -> Option<&editor::StDebugMarks> {
        self.studio.panes.texts.body_debug_marks(target)
    }

    /// The debugging state: halted tasks, the shown frame, flow control.
    pub fn debug_state(&self) -> &DebugState {
        &self.studio.shared.debug
    }

    /// Takes the halted tasks and their call stacks as the online session reports them
    /// (`docs/protocol.md` §6); a new halt brings the Call stack pane forward.
    pub fn set_halted(&mut self, halted: Vec<HaltedTask>) {
        let was_halted = self.studio.shared.debug.is_halted();
        self.studio.shared.debug.set_halted(halted);
        if !was_halted && self.studio.shared.debug.is_halted() {
            // A new halt opens the Call stack and the halted statement, as CODESYS does.
            self.dock.show(&super::pane::Pane::CallStack);
            self.open_shown_frame();
        }
    }

    /// Takes in what the online session reported about debugging since the last frame; a
    /// halt that moved (a breakpoint, a step, a step into a callee) shows its innermost frame
    /// and opens its statement.
    fn take_debug_reports(&mut self) {
        if let Some(halted) = self.studio.shared.online.take_halted()
            && halted.as_slice() != self.studio.shared.debug.halted()
        {
            let was_halted = self.studio.shared.debug.is_halted();
            self.studio.shared.debug.show_innermost();
            self.set_halted(halted);
            if was_halted {
                self.open_shown_frame();
            }
        }
        if let Some(flow) = self.studio.shared.online.take_flow() {
            self.studio.shared.debug.set_flow(flow);
        }
        let shared = &mut self.studio.shared;
        shared.online.show_frame_locals(shared.debug.shown());
        if shared.debug.flow_control && shared.online.is_logged_in() {
            let bodies = self.studio.flow_bodies();
            self.studio.shared.online.keep_flow_bodies(bodies);
        }
    }

    /// Opens the shown frame's POU at its line.
    fn open_shown_frame(&mut self) {
        if let Some((task, frame)) = self.studio.shared.debug.shown() {
            let command = Command::ShowFrame(task.to_owned(), frame);
            self.studio.commands.push(command);
        }
    }

    /// Takes the flow-control lines of the last cycle as the online session reports them:
    /// each body's file with the lines (from 1) of the statements that ran.
    pub fn set_flow(&mut self, flow: Vec<(String, Vec<u32>)>) {
        self.studio.shared.debug.set_flow(flow);
    }

    /// The diagram editor of an LD or FBD body, once its document was drawn.
    pub fn diagram_editor(
        &self,
        target: &project_model::TextTarget,
    ) -> Option<&editor::DiagramEditor> {
        self.studio.panes.texts.graphical.editor(target)
    }

    /// The CFC editor of a body, once its document was drawn.
    pub fn cfc_editor(&self, target: &project_model::TextTarget) -> Option<&editor::CfcEditor> {
        self.studio.panes.texts.graphical.cfc_editor(target)
    }

    /// The SFC editor of a body, once its document was drawn.
    pub fn sfc_editor(&self, target: &project_model::TextTarget) -> Option<&editor::SfcEditor> {
        self.studio.panes.texts.graphical.sfc_editor(target)
    }

    /// The docking layout.
    pub fn dock(&self) -> &Dock {
        &self.dock
    }

    /// Opens a tree node's document in a tab, as double-clicking the node does.
    pub fn open(&mut self, node: TreeNode) {
        self.studio.shared.selection = Some(node.clone());
        self.dock.open_document(node);
    }

    /// Builds the project in the background, as F11 does.
    pub fn build(&mut self) {
        self.studio.start_build();
    }

    /// Logs in to the chosen target, as Alt+F8 does (building first when the project changed).
    pub fn login(&mut self, ctx: &egui::Context) {
        self.studio.login(ctx);
    }

    /// Answers the login dialog's question with Download.
    pub fn confirm_download(&mut self) {
        self.studio.shared.online.confirm_download();
    }

    /// Starts the program on the target, as F5 does.
    pub fn start(&mut self) {
        self.studio.shared.online.start();
    }

    /// Chooses the login target.
    pub fn set_target(&mut self, target: TargetKind) {
        self.studio.shared.settings.target = target;
    }

    /// Reads and converts a PLCopen XML file and shows the import preview, as File ▸ Import
    /// PLCopen XML… does once the file is chosen.
    pub fn import_plcopen(&mut self, path: &Path) {
        self.studio.open_import(path.to_owned());
    }

    /// Exports the open project as it is in the editor (unsaved changes included) to the
    /// PLCopen XML file `path`, as File ▸ Export PLCopen XML… does once the file is chosen; the
    /// status bar says what was written or why nothing was.
    pub fn export_plcopen(&mut self, path: &Path) {
        self.studio.export_plcopen(path);
    }

    /// Whether the import preview is open.
    pub fn is_import_open(&self) -> bool {
        self.studio.import.is_some()
    }

    /// Writes the previewed import into `dir` and opens it, as the preview's "Import as new
    /// project…" does once the folder is chosen.
    pub fn import_as_new_project(&mut self, dir: &Path) {
        self.studio.import_as_new_project(&mut self.dock, dir);
    }

    /// Saves the open project to its folder.
    pub fn save(&mut self) {
        self.studio.save();
    }

    /// Saves the open project into `dir`, which must not hold another project.
    pub fn save_as(&mut self, dir: &Path) {
        self.studio.save_as(dir);
    }

    /// Draws the whole studio into `ui` and then applies the commands emitted while drawing.
    pub fn ui(&mut self, ui: &mut Ui) {
        let studio = &mut self.studio;
        if !studio.style_installed {
            install_fonts(ui.ctx());
            ui.ctx()
                .set_theme(studio.shared.settings.theme.egui_theme());
            studio.style_installed = true;
        }
        theme::install_palettes(ui.ctx());
        studio.take_in_background_results(ui.ctx());
        self.take_debug_reports();
        let studio = &mut self.studio;
        shortcuts::handle_shortcuts(ui.ctx(), &mut studio.commands);
        studio.update_title(ui.ctx());
        let view = studio.shared.view();
        let commands = &mut studio.commands;
        let chrome_state = &mut studio.chrome;
        egui::Panel::top("menu_bar").show(ui, |ui| chrome::menu_bar_ui(ui, view, commands));
        egui::Panel::top("tool_bar").show(ui, |ui| {
            chrome::tool_bar_ui(ui, view, chrome_state, commands)
        });
        egui::Panel::bottom("status_bar").show(ui, |ui| chrome::status_bar_ui(ui, view));
        login_dialog::login_dialog_ui(ui.ctx(), view, commands);
        studio.recovery_dialog_ui(ui.ctx());
        studio.import_dialog_ui(ui.ctx());
        let view = studio.shared.view();
        egui::CentralPanel::default_margins().show(ui, |ui| {
            let mut behavior = PaneBehavior {
                view,
                panes: &mut studio.panes,
                commands: &mut studio.commands,
            };
            self.dock.tree.ui(&mut behavior, ui);
            if let Some(rect) = self.dock.empty_editor_area() {
                editor_hint::editor_area_hint(ui, rect, view);
            }
        });
        apply::apply_commands(&mut self.studio, &mut self.dock, ui.ctx());
    }
}

impl eframe::App for StudioApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        StudioApp::ui(self, ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, SETTINGS_KEY, &self.studio.shared.settings);
        eframe::set_value(storage, LAYOUT_KEY, &self.dock);
    }
}
