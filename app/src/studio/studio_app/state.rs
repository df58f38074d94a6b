//! The studio's state without the layout: what panes read, what they keep, and the flows the
//! studio runs between frames (build, login, recovery copies).

use std::path::PathBuf;
use std::sync::mpsc::Receiver;
use std::time::Instant;

use project_model::LoadProblem;

use crate::studio::build_job::{BuildJob, BuildOutcome};
use crate::studio::chrome::ChromeState;
use crate::studio::command::Commands;
use crate::studio::cycle_plot::CycleHistory;
use crate::studio::debug::DebugState;
use crate::studio::import_dialog::ImportDialog;
use crate::studio::online::{Online, OnlineMessage};
use crate::studio::pane_states::PaneStates;
use crate::studio::recovery::{Recovered, Recovery};
use crate::studio::recovery_schedule::RecoverySchedule;
use crate::studio::references::References;
use crate::studio::session::Session;
use crate::studio::settings::Settings;
use crate::studio::status::StatusMessage;
use crate::studio::tree_node::TreeNode;
use crate::studio::view::StudioView;

/// Everything but the layout, so panes can be drawn while the layout is borrowed.
pub(crate) struct Studio {
    /// What every pane reads, through [`Shared::view`].
    pub(super) shared: Shared,
    /// What each pane keeps between frames.
    pub(super) panes: PaneStates,
    /// The commands emitted this frame, applied after its UI.
    pub(super) commands: Commands,
    /// The menu, tool and status bars' own state.
    pub(super) chrome: ChromeState,
    /// The window title last sent.
    pub(super) title: String,
    /// Whether fonts and theme were installed into the egui context (done on the first frame).
    pub(super) style_installed: bool,
    /// Log in as soon as the running build succeeds.
    pub(super) login_after_build: bool,
    /// The online state's task statistics generation last added to the cycle history.
    pub(super) cycles_seen: u64,
    /// When the studio started, the time origin of the cycle plot.
    pub(super) started: Instant,
    /// Whether the online state was given a way to wake the UI.
    pub(super) waker_set: bool,
    /// Copies of unsaved changes.
    pub(super) recovery: RecoveryCopies,
    /// The preview of a PLCopen XML import, while it is open.
    pub(super) import: Option<ImportDialog>,
}

/// What panes read of the studio; changed only between frames, by the studio.
pub(crate) struct Shared {
    /// The settings, saved by eframe.
    pub(super) settings: Settings,
    /// The open project.
    pub(super) session: Option<Session>,
    /// Problems of the last attempt to open a project: errors when it failed, warnings when it
    /// opened.
    pub(super) problems: Vec<LoadProblem>,
    /// The folder whose opening failed, shown with its errors.
    pub(super) failed_dir: Option<PathBuf>,
    /// The selected device tree node.
    pub(super) selection: Option<TreeNode>,
    /// The status bar's message.
    pub(super) status: Option<StatusMessage>,
    /// The build running in the background.
    pub(super) build: Option<BuildJob>,
    /// The last build's outcome.
    pub(super) last_build: Option<BuildOutcome>,
    /// The online state.
    pub(super) online: Online,
    /// Online messages shown in the messages panel, newest last.
    pub(super) online_messages: Vec<OnlineMessage>,
    /// Cycle times of every task over the last minutes, for the tasks pane's plot.
    pub(super) cycle_history: CycleHistory,
    /// The results of the last "find references".
    pub(super) references: References,
    /// The located variables whose addresses overlap, and the project revision they are of.
    pub(super) overlaps: (Option<u64>, Vec<compiler::ide::Overlap>),
    /// The halted tasks, the shown frame and the flow marks of the debug session.
    pub(super) debug: DebugState,
}

/// Copies of unsaved changes: where they go, the one offered at opening, and when to write.
pub(crate) struct RecoveryCopies {
    /// Where copies of unsaved changes go; `None` keeps none.
    pub(super) recovery: Option<Recovery>,
    /// Unsaved changes from an earlier session, offered when the project opened.
    pub(super) offer: Option<Recovered>,
    /// When to write and remove the copy.
    pub(super) schedule: RecoverySchedule,
    /// The outcome of the copy being written on its thread.
    pub(super) writing: Option<Receiver<std::io::Result<()>>>,
}

impl Studio {
    /// A studio with `settings` and no project.
    pub(super) fn new(settings: Settings, recovery: Option<Recovery>) -> Self {
        Self {
            shared: Shared {
                settings,
                session: None,
                problems: Vec::new(),
                failed_dir: None,
                selection: None,
                status: None,
                build: None,
                last_build: None,
                online: Online::new(),
                online_messages: Vec::new(),
                cycle_history: CycleHistory::default(),
                references: References::default(),
                overlaps: (None, Vec::new()),
                debug: DebugState::default(),
            },
            panes: PaneStates::default(),
            commands: Commands::default(),
            chrome: ChromeState::default(),
            title: String::new(),
            style_installed: false,
            login_after_build: false,
            cycles_seen: 0,
            started: Instant::now(),
            waker_set: false,
            recovery: RecoveryCopies {
                recovery,
                offer: None,
                schedule: RecoverySchedule::default(),
                writing: None,
            },
            import: None,
        }
    }

    /// Says `message` in the status bar.
    pub(super) fn report(&mut self, message: StatusMessage) {
        self.shared.status = Some(message);
    }
}

impl Shared {
    /// The read-only view panes draw from.
    pub(crate) fn view(&self) -> StudioView<'_> {
        StudioView {
            settings: &self.settings,
            language: self.settings.language,
            session: self.session.as_ref(),
            online: &self.online,
            online_messages: &self.online_messages,
            problems: &self.problems,
            failed_dir: self.failed_dir.as_deref(),
            last_build: self.last_build.as_ref(),
            building: self.build.is_some(),
            selection: self.selection.as_ref(),
            cycle_history: &self.cycle_history,
            references: &self.references,
            status: self.status.as_ref(),
            overlaps: &self.overlaps.1,
            debug: &self.debug,
        }
    }

    /// The current project revision (changes with every edit, undo and redo).
    pub(super) fn revision(&self) -> Option<u64> {
        self.session
            .as_ref()
            .map(|session| session.history.revision())
    }

    /// Computes the address overlaps again when the project changed since they were.
    pub(super) fn refresh_overlaps(&mut self) {
        let revision = self.revision();
        if self.overlaps.0 == revision && revision.is_some() {
            return;
        }
        self.overlaps = (
            revision,
            self.session
                .as_ref()
                .map(|session| compiler::ide::located_overlaps(&session.project))
                .unwrap_or_default(),
        );
    }
}
