//! The panes of the studio's docking layout.

use serde::{Deserialize, Serialize};

use super::i18n::{DebugText, Language, Text};
use super::tree_node::TreeNode;

/// A pane of the docking layout: the fixed tool panes and one pane per open document.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Pane {
    /// The device tree.
    Devices,
    /// The properties of the selected tree node.
    Properties,
    /// An open document.
    Document(TreeNode),
    /// Build, load and online messages.
    Messages,
    /// The watch lists.
    Watch,
    /// The forced variables.
    Forces,
    /// The trace view.
    Trace,
    /// Task statistics and the fault log.
    Tasks,
    /// The breakpoints of the project; opened from the Debug menu.
    Breakpoints,
    /// The call stacks of the halted tasks; opened from the Debug menu and by a halt.
    CallStack,
}

impl Pane {
    /// The tool panes every layout has, in their default order.
    pub const TOOLS: [Pane; 7] = [
        Pane::Devices,
        Pane::Properties,
        Pane::Messages,
        Pane::Watch,
        Pane::Forces,
        Pane::Trace,
        Pane::Tasks,
    ];

    /// The title of a tool pane's tab.
    pub fn tool_title(&self, language: Language) -> &'static str {
        match self {
            Pane::Devices => Text::Devices.get(language),
            Pane::Properties => Text::Properties.get(language),
            Pane::Messages => Text::Messages.get(language),
            Pane::Watch => Text::Watch.get(language),
            Pane::Forces => Text::Forces.get(language),
            Pane::Trace => Text::Trace.get(language),
            Pane::Tasks => Text::TasksAndFaults.get(language),
            Pane::Breakpoints => DebugText::Breakpoints.get(language),
            Pane::CallStack => DebugText::CallStack.get(language),
            Pane::Document(_) => "",
        }
    }
}
