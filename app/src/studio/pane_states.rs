//! What each pane remembers between frames, grouped per pane.

use super::cam_documents::CamDocuments;
use super::device_documents::DeviceDocuments;
use super::panes::{BreakpointsPaneState, TracePaneState, WatchPaneState};
use super::task_editor::TaskEditorState;
use super::text_documents::TextDocuments;
use super::trace_view::TraceViewState;
use super::tree_actions::TreeEditState;

/// The own state of every pane and document kind. Each pane gets only its part, mutably, while
/// it draws; the command application may change any part (a reveal for a text editor, the
/// refused values of the watch pane).
#[derive(Default)]
pub(crate) struct PaneStates {
    /// The device tree's dialog and dirty markers.
    pub tree_edit: TreeEditState,
    /// The watch pane's shown list, typed path and prepared values.
    pub watch: WatchPaneState,
    /// The trace pane's shown trace and typed fields.
    pub trace: TracePaneState,
    /// The trace plot's state.
    pub trace_view: TraceViewState,
    /// The text editors of the open documents.
    pub texts: TextDocuments,
    /// The task configuration editor's selection and typed text.
    pub task_editor: TaskEditorState,
    /// The cam editors of the open cam tables.
    pub cams: CamDocuments,
    /// The device editors' typed text and refusals.
    pub devices: DeviceDocuments,
    /// The Breakpoints pane's dialog.
    pub breakpoints: BreakpointsPaneState,
}

impl PaneStates {
    /// Forgets the editors of the documents of the previous project.
    pub fn forget_documents(&mut self) {
        self.texts.clear();
        self.cams.clear();
        self.devices.clear();
    }
}
