//! The read-only view of the studio every pane draws from.

use std::path::Path;

use project_model::{LoadProblem, Project};

use super::build_job::BuildOutcome;
use super::cycle_plot::CycleHistory;
use super::debug::{Breakpoints, DebugState};
use super::i18n::Language;
use super::online::{Online, OnlineMessage};
use super::references::References;
use super::session::Session;
use super::settings::Settings;
use super::status::StatusMessage;
use super::tree_node::TreeNode;

/// What a pane may read of the studio while it draws. Panes change nothing through it: they
/// keep their own state and emit [`super::command::Command`]s for everything else.
///
/// It lives for one frame's UI pass.
#[derive(Clone, Copy)]
pub(crate) struct StudioView<'a> {
    /// The settings (language, theme, login target).
    pub settings: &'a Settings,
    /// The language of every word shown, from the settings.
    pub language: Language,
    /// The open project, its undo history and files, if any.
    pub session: Option<&'a Session>,
    /// The online state: phase, values, forces, trace, tasks and faults.
    pub online: &'a Online,
    /// Online messages, newest last.
    pub online_messages: &'a [OnlineMessage],
    /// Problems of the last attempt to open a project.
    pub problems: &'a [LoadProblem],
    /// The folder whose opening failed, shown with its errors.
    pub failed_dir: Option<&'a Path>,
    /// The last build's outcome.
    pub last_build: Option<&'a BuildOutcome>,
    /// Whether a build is running.
    pub building: bool,
    /// The selected device tree node.
    pub selection: Option<&'a TreeNode>,
    /// Cycle times of every task over the last minutes.
    pub cycle_history: &'a CycleHistory,
    /// The results of the last "find references".
    pub references: &'a References,
    /// The status bar's message.
    pub status: Option<&'a StatusMessage>,
    /// The located variables whose addresses overlap, computed once per project revision.
    pub overlaps: &'a [compiler::ide::Overlap],
    /// The halted tasks, the shown frame and the flow marks of the debug session.
    pub debug: &'a DebugState,
}

impl<'a> StudioView<'a> {
    /// The open project, if any.
    pub fn project(&self) -> Option<&'a Project> {
        self.session.map(|session| &session.project)
    }

    /// The open project's breakpoints (none without a project).
    pub fn breakpoints(&self) -> Option<&'a Breakpoints> {
        let session = self.session?;
        self.settings
            .breakpoints
            .get(&Settings::project_key(&session.dir))
    }
}
