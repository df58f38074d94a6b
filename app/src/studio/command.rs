//! The commands menus, shortcuts and panes emit, and the sender they emit them through.
//!
//! Panes never change the studio while they draw: they read a [`super::view::StudioView`] and
//! push commands; the studio applies them in one place after the frame's UI, so the project and
//! the online state never change while they are drawn.

use project_model::{Edit, TextTarget, TraceConfig};

use super::debug::{Breakpoint, BreakpointPlace, DebugCommand};
use super::i18n::Language;
use super::online::{ForceSource, LoginChoice, TargetKind};
use super::pane::Pane;
use super::reveal::Reveal;
use super::settings::Theme;
use super::status::StatusMessage;
use super::tree_node::TreeNode;

/// An action requested by a menu, a pane or a shortcut, run after the UI pass.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Command {
    /// Ask for a project folder and open it.
    OpenDialog,
    /// Save the project to its folder.
    Save,
    /// Ask for a folder and save the project into it.
    SaveAsDialog,
    /// Ask for a PLCopen XML file and preview its import (`docs/plcopen-xml.md` §6.2).
    ImportPlcopenDialog,
    /// Apply the import preview's plan to the open project, as one undo step.
    ImportIntoProject,
    /// Ask for an empty folder, write the previewed import there and open it.
    ImportAsNewProjectDialog,
    /// Close the import preview; nothing changes.
    CloseImport,
    /// Ask for a file and export the open project to it as PLCopen XML
    /// (`docs/plcopen-xml.md` §6.4).
    ExportPlcopenDialog,
    /// Close the window.
    Quit,
    /// Undo the last change.
    Undo,
    /// Redo the last undone change.
    Redo,
    /// Build in the background.
    Build,
    /// Log in to the chosen target.
    Login,
    /// Log out.
    Logout,
    /// Start the program on the target.
    Start,
    /// Stop the program on the target.
    Stop,
    /// Reset the target.
    Reset(online::Reset),
    /// Write the prepared values.
    WritePrepared,
    /// Force the prepared values.
    ForcePrepared,
    /// Write these values once, by path (an SFC step activated or a transition fired by
    /// hand); never undoable.
    WriteValues(Vec<(String, String)>),
    /// Show or hide the execution order in the CFC editors.
    ToggleExecutionOrder,
    /// Release every force.
    ReleaseAllForces,
    /// Release one force.
    Unforce(ForceSource),
    /// Answer the login dialog's question with Download.
    ConfirmDownload,
    /// Answer the login dialog's three choices (a target running another program).
    ChooseLogin(LoginChoice),
    /// Answer the login dialog's question with Cancel.
    CancelDownload,
    /// Start recording a trace on the target (or on the Modbus devices it reads).
    StartTrace(TraceConfig),
    /// Upload the recorded samples of the running trace.
    UploadTrace,
    /// Ask for a file and write the trace plot's data as CSV.
    ExportTraceCsv,
    /// Take a screenshot and save this area of it (in points) as PNG.
    ExportTracePng(egui::Rect),
    /// Ask for a CSV file and replace the points of the named cam with it.
    ImportCamCsv(String),
    /// Ask for a file and write the points of the named cam to it as CSV.
    ExportCamCsv(String),
    /// Put the default layout back, keeping the open documents.
    ResetLayout,
    /// Open a tree node's document.
    Open(TreeNode),
    /// Select a tree node, or nothing.
    Select(Option<TreeNode>),
    /// Apply edits to the project as one undo step.
    Edit(String, Vec<Edit>),
    /// Apply a text editor's edits; typing with the same merge key joins one undo step.
    EditText {
        /// The undo step's label.
        label: String,
        /// The edits.
        edits: Vec<Edit>,
        /// Edits with the same key as the last step's join it.
        merge_key: Option<String>,
    },
    /// Open a document and put the caret at a place in it.
    Reveal(TreeNode, Reveal),
    /// List every reference to the name at a byte offset of a body.
    FindReferences(TextTarget, usize),
    /// Bring a tool pane forward.
    ShowPane(Pane),
    /// Say something in the status bar.
    Report(StatusMessage),
    /// Forget the online messages and the problems of the last project load.
    ClearMessages,
    /// Show the studio in another language.
    SetLanguage(Language),
    /// Show the studio in another theme.
    SetTheme(Theme),
    /// Log in to another kind of target next time.
    SetTarget(TargetKind),
    /// Set or clear the breakpoint of a line of a body (F9, a click in the gutter); the line
    /// moves to the statement that starts there or next.
    ToggleBreakpoint(BreakpointPlace),
    /// Toggle the breakpoint at the caret of the last Structured Text editor used (the menu).
    ToggleBreakpointAtCaret,
    /// Replace the breakpoint on its place (enabled, condition, hit count, filters).
    UpdateBreakpoint(Breakpoint),
    /// Remove the breakpoint on a place.
    RemoveBreakpoint(BreakpointPlace),
    /// Remove every breakpoint of the project.
    RemoveAllBreakpoints,
    /// Send a debugging command to the target.
    Debug(DebugCommand),
    /// Run the halted task to the caret of the last Structured Text editor used.
    RunToCaret,
    /// Show a frame of a halted task's call stack and open its POU at its line.
    ShowFrame(String, usize),
}

/// Where panes, menus and shortcuts put their commands during a frame; the studio takes them
/// after the frame's UI and applies them in order.
#[derive(Debug, Default)]
pub(crate) struct Commands {
    /// The commands emitted this frame, oldest first.
    queued: Vec<Command>,
}

impl Commands {
    /// Queues `command`.
    pub fn push(&mut self, command: Command) {
        self.queued.push(command);
    }

    /// Queues a status bar message that reports success or progress.
    pub fn status(&mut self, text: impl Into<String>) {
        self.push(Command::Report(StatusMessage::info(text)));
    }

    /// Queues a status bar message that reports a failure.
    pub fn error(&mut self, text: impl Into<String>) {
        self.push(Command::Report(StatusMessage::error(text)));
    }

    /// Takes every queued command, oldest first.
    pub fn take(&mut self) -> Vec<Command> {
        std::mem::take(&mut self.queued)
    }
}
