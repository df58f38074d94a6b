//! The studio application: the docking layout, menus, shortcuts and the commands they run.

use std::path::{Path, PathBuf};
use std::time::Instant;

use egui::Ui;
use project_model::LoadProblem;

use super::build_job::{BuildJob, BuildOutcome};
use super::dock::{Dock, LAYOUT_KEY};
use super::documents::close_stale_documents;
use super::fonts::install_fonts;
use super::i18n::Text;
use super::online::{Online, TargetKind};
use super::pane_behavior::PaneBehavior;
use super::panes::{TracePaneState, WatchPaneState};
use super::recovery::{Recovered, Recovery};
use super::session::Session;
use super::settings::{SETTINGS_KEY, Settings};
use super::task_editor::TaskEditorState;
use super::text_documents::{Reveal, TextDocuments};
use super::tree_actions::TreeEditState;
use super::tree_node::TreeNode;

/// The studio: the docking layout and everything the panes show.
pub struct StudioApp {
    dock: Dock,
    studio: Studio,
}

/// A line for the status bar: what the last action did.
#[derive(Clone, Debug, PartialEq)]
pub struct StatusMessage {
    /// The text.
    pub text: String,
    /// Whether it reports a failure.
    pub is_error: bool,
}

/// Actions requested by menus, panes and shortcuts, run after the UI pass so the project never
/// changes while it is drawn.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Command {
    OpenDialog,
    Save,
    SaveAsDialog,
    Quit,
    Undo,
    Redo,
    Build,
    Login,
    Logout,
    Start,
    Stop,
    Reset(online::Reset),
    WritePrepared,
    ForcePrepared,
    ReleaseAllForces,
    ResetLayout,
    /// Open a tree node's document.
    Open(TreeNode),
    /// Apply edits to the project as one undo step.
    Edit(String, Vec<project_model::Edit>),
    /// Apply a text editor's edits; typing with the same merge key joins one undo step.
    EditText {
        label: String,
        edits: Vec<project_model::Edit>,
        merge_key: Option<String>,
    },
    /// Open a document and put the caret at a place in it.
    Reveal(TreeNode, Reveal),
    /// List every reference to the name at a byte offset of a body.
    FindReferences(project_model::TextTarget, usize),
    /// Bring a tool pane forward.
    ShowPane(super::pane::Pane),
    /// Say something in the status bar.
    Status(String),
}

/// Everything but the layout, so panes can be drawn while the layout is borrowed.
pub(crate) struct Studio {
    pub settings: Settings,
    pub session: Option<Session>,
    /// Problems of the last attempt to open a project: errors when it failed, warnings when it
    /// opened.
    pub problems: Vec<LoadProblem>,
    /// The folder whose opening failed, shown with its errors.
    pub failed_dir: Option<PathBuf>,
    pub selection: Option<TreeNode>,
    pub status: Option<StatusMessage>,
    /// Commands requested while drawing, run after the frame's UI.
    pub pending: Vec<Command>,
    title: String,
    /// Whether fonts and theme were installed into the egui context (done on the first frame).
    style_installed: bool,
    /// The build running in the background.
    pub build: Option<BuildJob>,
    /// The last build's outcome.
    pub last_build: Option<BuildOutcome>,
    /// Log in as soon as the running build succeeds.
    login_after_build: bool,
    pub online: Online,
    /// Online messages shown in the messages panel, newest last.
    pub online_messages: Vec<super::online::OnlineMessage>,
    /// The password typed for the controller (never saved).
    pub password: String,
    pub watch: WatchPaneState,
    pub trace: TracePaneState,
    /// The text editors of the open documents.
    pub texts: TextDocuments,
    /// The trace plot's state.
    pub trace_view: super::trace_view::TraceViewState,
    /// Cycle times of every task over the last minutes, for the tasks pane's plot.
    pub cycle_history: super::cycle_plot::CycleHistory,
    /// The online state's task statistics generation last added to `cycle_history`.
    cycles_seen: u64,
    /// When the studio started, the time origin of the cycle plot.
    started: Instant,
    /// Whether the online state was given a way to wake the UI.
    waker_set: bool,
    /// Where copies of unsaved changes go; `None` keeps none.
    recovery: Option<Recovery>,
    /// Unsaved changes from an earlier session, offered when the project opened.
    pub recovery_offer: Option<Recovered>,
    recovery_state: RecoveryState,
    /// The device tree's dialog and dirty markers.
    pub tree_edit: TreeEditState,
    /// The task configuration editor's selection and typed text.
    pub task_editor: TaskEditorState,
    /// The cam editors of the open cam tables.
    pub cams: super::cam_documents::CamDocuments,
    /// The device editors' typed text and refusals.
    pub devices: super::device_documents::DeviceDocuments,
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

/// When the copy of unsaved changes was last written.
#[derive(Default)]
struct RecoveryState {
    /// The revision and time of the last change seen.
    last_change: Option<(u64, Instant)>,
    /// The revision last copied.
    written: Option<u64>,
    /// Whether a copy exists that a save or an undo to the saved state makes stale.
    exists: bool,
}

/// How long the project must rest after a change before a copy is written.
const RECOVERY_DELAY: std::time::Duration = std::time::Duration::from_secs(2);

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
            studio: Studio {
                settings,
                session: None,
                problems: Vec::new(),
                failed_dir: None,
                selection: None,
                status: None,
                pending: Vec::new(),
                title: String::new(),
                style_installed: false,
                build: None,
                last_build: None,
                login_after_build: false,
                online: Online::new(),
                online_messages: Vec::new(),
                password: String::new(),
                watch: WatchPaneState::default(),
                trace: TracePaneState::default(),
                texts: TextDocuments::default(),
                trace_view: super::trace_view::TraceViewState::default(),
                cycle_history: super::cycle_plot::CycleHistory::default(),
                cycles_seen: 0,
                started: Instant::now(),
                waker_set: false,
                recovery,
                recovery_offer: None,
                recovery_state: RecoveryState::default(),
                tree_edit: TreeEditState::default(),
                task_editor: TaskEditorState::default(),
                cams: super::cam_documents::CamDocuments::default(),
                devices: super::device_documents::DeviceDocuments::default(),
            },
        };
        if let Some(dir) = project_dir {
            app.open_project(&dir);
        }
        app
    }

    /// Opens the project in `dir`. On failure the current project stays open and the errors
    /// are listed in the messages panel; nothing on disk is touched either way.
    pub fn open_project(&mut self, dir: &Path) {
        let studio = &mut self.studio;
        let language = studio.settings.language;
        match Session::open(dir) {
            Ok(session) => {
                studio.online.logout();
                studio.problems = session.warnings.clone();
                studio.failed_dir = None;
                studio.selection = None;
                studio.last_build = None;
                studio.build = None;
                close_stale_documents(&mut self.dock, &session.project);
                studio.recovery_state = RecoveryState::default();
                studio.texts.clear();
                studio.cams.clear();
                studio.recovery_offer = studio
                    .recovery
                    .as_ref()
                    .and_then(|recovery| recovery.find(dir))
                    .filter(|found| found.project != session.project);
                studio.status = Some(StatusMessage {
                    text: format!("{} {}", Text::Opened.get(language), session.title()),
                    is_error: false,
                });
                studio.session = Some(session);
            }
            Err(error) => {
                studio.problems = error.problems;
                studio.failed_dir = Some(dir.to_owned());
                studio.status = Some(StatusMessage {
                    text: format!("{}: {}", Text::CouldNotOpen.get(language), dir.display()),
                    is_error: true,
                });
            }
        }
    }

    /// The open project, if any.
    pub fn session(&self) -> Option<&Session> {
        self.studio.session.as_ref()
    }

    /// The selected device tree node.
    pub fn selection(&self) -> Option<&TreeNode> {
        self.studio.selection.as_ref()
    }

    /// The documents open in tabs.
    pub fn open_documents(&self) -> Vec<TreeNode> {
        self.dock.documents()
    }

    /// The problems of the last project load.
    pub fn problems(&self) -> &[LoadProblem] {
        &self.studio.problems
    }

    /// The last build's outcome.
    pub fn last_build(&self) -> Option<&BuildOutcome> {
        self.studio.last_build.as_ref()
    }

    /// Whether a build is running.
    pub fn is_building(&self) -> bool {
        self.studio.build.is_some()
    }

    /// The online state.
    pub fn online(&self) -> &Online {
        &self.studio.online
    }

    /// The status bar's message.
    pub fn status(&self) -> Option<&StatusMessage> {
        self.studio.status.as_ref()
    }

    /// The settings.
    pub fn settings(&self) -> &Settings {
        &self.studio.settings
    }

    /// The live check's findings in a POU as `CODE: message`, for tests and tools.
    pub fn live_findings(&self, pou: &str) -> Vec<String> {
        self.studio.texts.live_findings(pou)
    }

    /// The variable paths whose values the open editors show inline.
    pub fn inline_paths(&self) -> Vec<String> {
        self.studio.texts.inline.paths().cloned().collect()
    }

    /// The selection of the editor of a body, if it is open.
    pub fn body_selection(
        &self,
        target: &project_model::TextTarget,
    ) -> Option<std::ops::Range<usize>> {
        self.studio.texts.body_selection(target)
    }

    /// The docking layout.
    pub fn dock(&self) -> &Dock {
        &self.dock
    }

    /// Opens a tree node's document in a tab, as double-clicking the node does.
    pub fn open(&mut self, node: TreeNode) {
        self.studio.selection = Some(node.clone());
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
        self.studio.online.confirm_download();
    }

    /// Starts the program on the target, as F5 does.
    pub fn start(&mut self) {
        self.studio.online.start();
    }

    /// Chooses the login target.
    pub fn set_target(&mut self, target: TargetKind) {
        self.studio.settings.target = target;
    }

    /// Saves the open project to its folder.
    pub fn save(&mut self) {
        self.studio.save();
    }

    /// Saves the open project into `dir`, which must not hold another project.
    pub fn save_as(&mut self, dir: &Path) {
        self.studio.save_as(dir);
    }

    /// Draws the whole studio into `ui` and then runs the commands requested while drawing.
    pub fn ui(&mut self, ui: &mut Ui) {
        let studio = &mut self.studio;
        if !studio.style_installed {
            install_fonts(ui.ctx());
            ui.ctx().set_theme(studio.settings.theme.egui_theme());
            studio.style_installed = true;
        }
        studio.take_in_background_results(ui.ctx());
        studio.handle_shortcuts(ui.ctx());
        studio.update_title(ui.ctx());
        egui::Panel::top("menu_bar").show(ui, |ui| studio.menu_bar_ui(ui));
        egui::Panel::top("tool_bar").show(ui, |ui| studio.tool_bar_ui(ui));
        egui::Panel::bottom("status_bar").show(ui, |ui| studio.status_bar_ui(ui));
        studio.login_dialog_ui(ui.ctx());
        studio.recovery_dialog_ui(ui.ctx());
        egui::CentralPanel::default_margins().show(ui, |ui| {
            let mut behavior = PaneBehavior { studio };
            self.dock.tree.ui(&mut behavior, ui);
            if let Some(rect) = self.dock.empty_editor_area() {
                editor_area_hint(ui, rect, studio);
            }
        });
        self.run_pending(ui.ctx());
    }

    fn run_pending(&mut self, ctx: &egui::Context) {
        for command in std::mem::take(&mut self.studio.pending) {
            match command {
                Command::Open(node) => {
                    self.studio.selection = Some(node.clone());
                    self.dock.open_document(node);
                }
                Command::Reveal(node, reveal) => {
                    self.studio.selection = Some(node.clone());
                    self.studio.texts.reveal = Some((node.clone(), reveal));
                    self.dock.open_document(node);
                }
                Command::ShowPane(pane) => self.dock.show(&pane),
                Command::FindReferences(target, offset) => {
                    self.studio.find_references(&target, offset);
                    self.dock.show(&super::pane::Pane::Messages);
                }
                Command::ResetLayout => {
                    let open = self.dock.documents();
                    self.dock = Dock::default();
                    for node in open {
                        self.dock.open_document(node);
                    }
                }
                Command::OpenDialog => {
                    if let Some(dir) = rfd::FileDialog::new()
                        .set_title("Open Rivet project folder")
                        .pick_folder()
                    {
                        self.open_project(&dir);
                    }
                }
                other => self.studio.run(other, ctx),
            }
        }
        if let Some(session) = &self.studio.session {
            close_stale_documents(&mut self.dock, &session.project);
        }
    }
}

/// What the editor area shows while no document is open: the project and how to start.
fn editor_area_hint(ui: &mut Ui, rect: egui::Rect, studio: &Studio) {
    let language = studio.settings.language;
    let mut lines = Vec::new();
    match &studio.session {
        Some(session) => {
            lines.push((session.title(), 20.0, ui.visuals().strong_text_color()));
            if !session.project.description.is_empty() {
                lines.push((
                    session.project.description.clone(),
                    13.0,
                    ui.visuals().text_color(),
                ));
            }
            lines.push((
                Text::OpenObjectHint.get(language).to_owned(),
                13.0,
                ui.visuals().weak_text_color(),
            ));
            lines.push((
                "F11 build · Alt+F8 login · F5 start".to_owned(),
                13.0,
                ui.visuals().weak_text_color(),
            ));
        }
        None => lines.push((
            Text::NoProjectHint.get(language).to_owned(),
            13.0,
            ui.visuals().weak_text_color(),
        )),
    }
    let painter = ui.painter_at(rect);
    let mut y = rect.center().y - 40.0;
    for (text, size, color) in lines {
        let galley = painter.layout(
            text,
            egui::FontId::proportional(size),
            color,
            (rect.width() - 40.0).max(100.0),
        );
        let x = rect.center().x - galley.size().x / 2.0;
        let height = galley.size().y;
        painter.galley(egui::pos2(x, y), galley, color);
        y += height + 8.0;
    }
}

impl Studio {
    fn save(&mut self) {
        let language = self.settings.language;
        let Some(session) = &mut self.session else {
            return;
        };
        let saved = session.save();
        if saved.is_ok()
            && let Some(recovery) = &self.recovery
        {
            recovery.clear(&session.dir);
            self.recovery_state.exists = false;
        }
        self.status = Some(match saved {
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

    fn save_as(&mut self, dir: &Path) {
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

    /// Collects what background work produced since the last frame: the build's outcome and
    /// online events. Keeps the UI drawing while something is under way.
    /// Keeps the copy of unsaved changes current: written once the project rested
    /// [`RECOVERY_DELAY`] after a change, removed once the project equals its files again.
    fn keep_recovery_copy(&mut self, ctx: &egui::Context) {
        let (Some(recovery), Some(session)) = (&self.recovery, &self.session) else {
            return;
        };
        let revision = session.history.revision();
        let state = &mut self.recovery_state;
        if !session.history.is_dirty() {
            if state.exists {
                recovery.clear(&session.dir);
                state.exists = false;
            }
            state.written = Some(revision);
            return;
        }
        if state.written == Some(revision) {
            return;
        }
        let now = Instant::now();
        match state.last_change {
            Some((seen, at)) if seen == revision => {
                if now.duration_since(at) >= RECOVERY_DELAY {
                    // The copy is written on a thread so a large project never stalls a frame.
                    let recovery = recovery.clone();
                    let dir = session.dir.clone();
                    let project = session.project.clone();
                    let _ = std::thread::Builder::new()
                        .name("rivet-recovery".into())
                        .spawn(move || recovery.write(&dir, &project));
                    state.written = Some(revision);
                    state.exists = true;
                } else {
                    ctx.request_repaint_after(RECOVERY_DELAY);
                }
            }
            _ => {
                state.last_change = Some((revision, now));
                ctx.request_repaint_after(RECOVERY_DELAY);
            }
        }
    }

    /// Offers the unsaved changes of an earlier session, if any were found.
    pub(crate) fn recovery_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some(offer) = &self.recovery_offer else {
            return;
        };
        let language = self.settings.language;
        let age = offer
            .written
            .elapsed()
            .map(|age| format!("{} min", age.as_secs() / 60))
            .unwrap_or_default();
        let mut choice = None;
        egui::Modal::new(egui::Id::unique("recovery_dialog")).show(ctx, |ui| {
            ui.set_width(460.0);
            ui.heading(Text::RecoverTitle.get(language));
            ui.label(format!("{} ({age})", Text::RecoverQuestion.get(language)));
            ui.horizontal(|ui| {
                if ui.button(Text::Recover.get(language)).clicked() {
                    choice = Some(true);
                }
                if ui.button(Text::Discard.get(language)).clicked() {
                    choice = Some(false);
                }
            });
        });
        match choice {
            Some(true) => {
                if let Some(offer) = self.recovery_offer.take() {
                    self.apply(
                        "Recover unsaved changes",
                        vec![project_model::Edit::ReplaceProject(Box::new(offer.project))],
                    );
                }
            }
            Some(false) => {
                self.recovery_offer = None;
                if let (Some(recovery), Some(session)) = (&self.recovery, &self.session) {
                    recovery.clear(&session.dir);
                }
            }
            None => {}
        }
    }

    fn take_in_background_results(&mut self, ctx: &egui::Context) {
        self.keep_recovery_copy(ctx);
        self.texts.inline.begin_frame();
        self.texts.set_language(self.settings.language);
        if let Some(job) = &self.build {
            match job.poll() {
                Some(outcome) => {
                    self.build = None;
                    self.finish_build(outcome, ctx);
                }
                None => ctx.request_repaint_after(std::time::Duration::from_millis(50)),
            }
        }
        if !self.waker_set {
            let wake = ctx.clone();
            self.online
                .set_waker(std::sync::Arc::new(move || wake.request_repaint()));
            self.waker_set = true;
        }
        let devices = self
            .session
            .as_ref()
            .map(|session| session.project.modbus_devices.as_slice())
            .unwrap_or_default();
        let mut watched = self.watch.watched_paths(self.session.as_ref());
        // The shown trace's device channels are polled too, so the trace can record them.
        for path in self.trace.variable_paths(self.session.as_ref()) {
            if !watched.contains(&path)
                && devices.iter().any(|d| {
                    d.bindings
                        .iter()
                        .any(|b| b.variable.eq_ignore_ascii_case(&path))
                })
            {
                watched.push(path);
            }
        }
        for path in self.texts.inline.paths() {
            if !watched.contains(path) {
                watched.push(path.clone());
            }
        }
        for path in self.cams.take_live_paths() {
            if !watched.contains(&path) {
                watched.push(path);
            }
        }
        self.online.set_watch(watched, devices);
        self.online.poll(Instant::now());
        if self.online.tasks_generation() != self.cycles_seen {
            self.cycles_seen = self.online.tasks_generation();
            let at_s = self.started.elapsed().as_secs_f64();
            for task in self.online.tasks() {
                self.cycle_history.push(
                    &task.name,
                    at_s,
                    task.last_ns,
                    task.average_ns,
                    task.max_ns,
                    task.min_ns,
                    task.jitter_max_ns,
                    task.cycles,
                );
            }
        }
        for message in self.online.take_messages() {
            self.status = Some(StatusMessage {
                text: message.text.clone(),
                is_error: message.is_error,
            });
            self.online_messages.push(message);
        }
        if self.online_messages.len() > 200 {
            let excess = self.online_messages.len() - 200;
            self.online_messages.drain(..excess);
        }
        if self.online.is_logged_in() || self.online.can_write() {
            // Values, statistics and trace states arrive by polling; redraw to show them.
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
    }

    fn finish_build(&mut self, outcome: BuildOutcome, ctx: &egui::Context) {
        let language = self.settings.language;
        let (errors, warnings) = outcome.counts();
        self.status = Some(match (&outcome.image, &outcome.failure) {
            (Some(_), _) => StatusMessage {
                text: format!(
                    "{}: {errors} {}, {warnings} {} ({} ms)",
                    Text::BuildSucceeded.get(language),
                    Text::Errors.get(language),
                    Text::Warnings.get(language),
                    outcome.elapsed.as_millis()
                ),
                is_error: false,
            },
            (None, Some(reason)) => StatusMessage {
                text: format!("{}: {reason}", Text::BuildFailed.get(language)),
                is_error: true,
            },
            (None, None) => StatusMessage {
                text: format!(
                    "{}: {errors} {}, {warnings} {}",
                    Text::BuildFailed.get(language),
                    Text::Errors.get(language),
                    Text::Warnings.get(language)
                ),
                is_error: true,
            },
        });
        if errors > 0 {
            self.pending
                .push(Command::ShowPane(super::pane::Pane::Messages));
        }
        let login = std::mem::take(&mut self.login_after_build);
        let built = outcome.image.is_some();
        self.last_build = Some(outcome);
        if login && built {
            self.login(ctx);
        }
    }

    /// The current project revision (changes with every edit, undo and redo).
    fn revision(&self) -> Option<u64> {
        self.session
            .as_ref()
            .map(|session| session.history.revision())
    }

    fn start_build(&mut self) {
        let Some(session) = &self.session else { return };
        let revision = session.history.revision();
        if self
            .build
            .as_ref()
            .is_some_and(|job| job.revision() == revision)
        {
            return;
        }
        self.build = Some(BuildJob::start(session.project.clone(), revision));
        self.status = Some(StatusMessage {
            text: Text::Building.get(self.settings.language).to_owned(),
            is_error: false,
        });
    }

    /// Logs in with the current build, building first when the project changed since.
    fn login(&mut self, ctx: &egui::Context) {
        let current = self
            .last_build
            .as_ref()
            .filter(|outcome| Some(outcome.revision) == self.revision())
            .and_then(|outcome| outcome.image.clone());
        let Some(image) = current else {
            let failed = self
                .last_build
                .as_ref()
                .is_some_and(|outcome| Some(outcome.revision) == self.revision());
            if failed {
                self.status = Some(StatusMessage {
                    text: "login needs a program that builds: see the messages".to_owned(),
                    is_error: true,
                });
            } else {
                self.login_after_build = true;
                self.start_build();
            }
            return;
        };
        let address = self.session.as_ref().and_then(|session| {
            use std::net::ToSocketAddrs as _;
            let controller = &session.project.controller;
            (controller.host.as_str(), controller.port)
                .to_socket_addrs()
                .ok()
                .and_then(|mut addresses| addresses.next())
        });
        let password = (!self.password.is_empty()).then(|| self.password.clone());
        let wake = ctx.clone();
        self.online
            .login(self.settings.target, address, password, image, move || {
                wake.request_repaint();
            });
    }

    fn run(&mut self, command: Command, ctx: &egui::Context) {
        match command {
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
            Command::Undo | Command::Redo => self.undo_redo(command == Command::Undo),
            Command::Build => self.start_build(),
            Command::Login => self.login(ctx),
            Command::Logout => self.online.logout(),
            Command::Start => self.online.start(),
            Command::Stop => self.online.stop(),
            Command::Reset(kind) => self.online.reset(kind),
            Command::WritePrepared | Command::ForcePrepared => {
                let mut prepared = self.watch.prepared_values(self.session.as_ref());
                // Values prepared in an editor's inline boxes go too, and are used up as
                // CODESYS uses them up.
                let inline: Vec<(String, String)> = std::mem::take(&mut self.texts.inline.prepared)
                    .into_iter()
                    .collect();
                prepared.extend(inline);
                let result = if command == Command::WritePrepared {
                    self.online.write(&prepared)
                } else {
                    self.online.force(&prepared)
                };
                self.watch.refused = match result {
                    Ok(()) => Vec::new(),
                    Err(refused) => refused,
                };
                if let Some((path, reason)) = self.watch.refused.first() {
                    self.status = Some(StatusMessage {
                        text: format!("{path}: {reason}"),
                        is_error: true,
                    });
                }
            }
            Command::ReleaseAllForces => self.online.unforce_all(),
            Command::Edit(label, edits) => self.apply(&label, edits),
            Command::EditText {
                label,
                edits,
                merge_key,
            } => self.apply_text(&label, edits, merge_key.as_deref()),
            Command::Status(text) => {
                self.status = Some(StatusMessage {
                    text,
                    is_error: false,
                })
            }
            Command::Open(_)
            | Command::ResetLayout
            | Command::OpenDialog
            | Command::Reveal(..)
            | Command::ShowPane(_)
            | Command::FindReferences(..) => {}
        }
    }

    /// Applies a text editor's edits: typing with the same merge key joins the last undo
    /// step, anything else is a step of its own.
    fn apply_text(
        &mut self,
        label: &str,
        edits: Vec<project_model::Edit>,
        merge_key: Option<&str>,
    ) {
        let Some(session) = &mut self.session else {
            return;
        };
        let result = match merge_key {
            Some(key) => session
                .history
                .apply_merging(&mut session.project, label, edits, key),
            None => {
                session.history.break_merging();
                session.history.apply(&mut session.project, label, edits)
            }
        };
        if let Err(error) = result {
            self.status = Some(StatusMessage {
                text: format!("{label}: {error}"),
                is_error: true,
            });
        }
    }

    /// Lists every reference to the name at `offset` of `target` for the messages pane.
    fn find_references(&mut self, target: &project_model::TextTarget, offset: usize) {
        let Some(session) = &self.session else { return };
        let project = &session.project;
        let name = compiler::ide::definition(project, target, offset)
            .map(|definition| definition.name)
            .unwrap_or_default();
        let bodies = project_model::st_body_files(project);
        let found = compiler::ide::references(project, target, offset);
        self.texts.references = found
            .into_iter()
            .filter_map(|reference| {
                let body = bodies.iter().find(|body| body.target == reference.target)?;
                let (line, column) =
                    super::build_job::line_column(body.text, reference.range.start);
                let text = body.text.lines().nth(line - 1).unwrap_or_default().trim();
                Some(super::text_documents::ReferenceItem {
                    label: format!("{}:{line}:{column}: {text}", reference.file.display()),
                    node: TreeNode::Object(body.pou.name.clone()),
                    target: reference.target.clone(),
                    range: reference.range.clone(),
                })
            })
            .collect();
        self.texts.references_of = name;
    }

    /// Applies one gesture's edits as one undo step.
    pub fn apply(&mut self, label: &str, edits: Vec<project_model::Edit>) {
        let Some(session) = &mut self.session else {
            return;
        };
        if let Err(error) = session.history.apply(&mut session.project, label, edits) {
            self.status = Some(StatusMessage {
                text: format!("{label}: {error}"),
                is_error: true,
            });
        }
    }

    fn undo_redo(&mut self, undo: bool) {
        let Some(session) = &mut self.session else {
            return;
        };
        let result = if undo {
            session.history.undo(&mut session.project)
        } else {
            session.history.redo(&mut session.project)
        };
        let language = self.settings.language;
        let verb = if undo { Text::Undo } else { Text::Redo }.get(language);
        self.status = match result {
            Ok(Some(label)) => Some(StatusMessage {
                text: format!("{verb}: {label}"),
                is_error: false,
            }),
            Ok(None) => None,
            Err(error) => Some(StatusMessage {
                text: format!("{verb}: {error}"),
                is_error: true,
            }),
        };
    }

    fn handle_shortcuts(&mut self, ctx: &egui::Context) {
        use egui::{Key, KeyboardShortcut, Modifiers};
        let shortcuts = [
            (
                KeyboardShortcut::new(Modifiers::COMMAND, Key::S),
                Command::Save,
            ),
            (
                KeyboardShortcut::new(Modifiers::COMMAND, Key::O),
                Command::OpenDialog,
            ),
            (
                KeyboardShortcut::new(Modifiers::COMMAND, Key::Z),
                Command::Undo,
            ),
            (
                KeyboardShortcut::new(Modifiers::COMMAND, Key::Y),
                Command::Redo,
            ),
            (
                KeyboardShortcut::new(Modifiers::NONE, Key::F11),
                Command::Build,
            ),
            (
                KeyboardShortcut::new(Modifiers::ALT, Key::F8),
                Command::Login,
            ),
            (
                KeyboardShortcut::new(Modifiers::COMMAND, Key::F8),
                Command::Logout,
            ),
            (
                KeyboardShortcut::new(Modifiers::SHIFT, Key::F8),
                Command::Stop,
            ),
            (
                KeyboardShortcut::new(Modifiers::NONE, Key::F5),
                Command::Start,
            ),
            (
                KeyboardShortcut::new(Modifiers::COMMAND, Key::F7),
                Command::WritePrepared,
            ),
            (
                KeyboardShortcut::new(Modifiers::ALT, Key::F7),
                Command::ReleaseAllForces,
            ),
            (
                KeyboardShortcut::new(Modifiers::NONE, Key::F7),
                Command::ForcePrepared,
            ),
        ];
        for (shortcut, command) in shortcuts {
            if ctx.input_mut(|input| input.consume_shortcut(&shortcut)) {
                self.pending.push(command);
            }
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
}

impl eframe::App for StudioApp {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        StudioApp::ui(self, ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, SETTINGS_KEY, &self.studio.settings);
        eframe::set_value(storage, LAYOUT_KEY, &self.dock);
    }
}
