//! The plain data the CFC editor exchanges with the app: its change, its findings, its
//! toolbox items, the payload of a variable dragged in, and what a frame produced.

use project_model::{CfcChart, CfcEditError, ElementId};

use crate::Severity;
use crate::diagram::{InstanceDeclaration, PreparedOperand};

/// One change of the chart: the whole new chart. The app applies it as the model's
/// `Edit::ReplaceChart`, one undo step per gesture.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CfcChange {
    /// The chart after the gesture.
    pub chart: CfcChart,
}

/// A compiler finding placed on an element of the chart, as the app maps it through the
/// origin map.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CfcDiagnostic {
    /// The element; `None` for a finding about the chart as a whole.
    pub element: Option<ElementId>,
    /// The pin the finding is about, if any.
    pub pin: Option<String>,
    /// Error, warning or note.
    pub severity: Severity,
    /// The stable diagnostic code, such as `E0104`.
    pub code: String,
    /// The message, shown on hover.
    pub message: String,
}

/// A variable dragged from the declaration table: dropped on a pin it connects an input or an
/// output element with this variable; dropped on an input or output element it becomes its
/// expression. The app's table sets it with `Response::dnd_set_drag_payload`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VariableDragPayload {
    /// The variable's name as the body refers to it.
    pub name: String,
    /// Its path on the target (`Main.iCount`, `GVL_IO.xStart`) when it has one path (a
    /// program's or a global variable list's variable), for a watch list to drop.
    pub path: Option<String>,
}

/// The elements of the toolbox; the payload of a drag from it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CfcTool {
    /// A value read into the chart.
    Input,
    /// A variable written by the chart.
    Output,
    /// An operator, function, function block or program (its type is asked for).
    Box,
    /// A jump to a label.
    Jump,
    /// A jump target.
    Label,
    /// A return from the POU.
    Return,
    /// A structure built from its members.
    Composer,
    /// A structure taken apart.
    Selector,
    /// A free comment.
    Comment,
    /// A connection mark's source.
    ConnectionSource,
    /// A connection mark's sink.
    ConnectionSink,
    /// One more input on the extensible box it is dropped on.
    InputPin,
    /// A control point on the selected wire.
    ControlPoint,
}

impl CfcTool {
    /// Every tool, in the toolbox's order.
    pub const ALL: [Self; 13] = [
        Self::Input,
        Self::Output,
        Self::Box,
        Self::Jump,
        Self::Label,
        Self::Return,
        Self::Composer,
        Self::Selector,
        Self::Comment,
        Self::ConnectionSource,
        Self::ConnectionSink,
        Self::InputPin,
        Self::ControlPoint,
    ];
}

/// An execution order command, from the context menu, a key or the app's menu.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CfcOrderCommand {
    /// The selection runs first.
    SendToFront,
    /// The selection runs last.
    SendToBack,
    /// The selection runs one place earlier.
    MoveUp,
    /// The selection runs one place later.
    MoveDown,
    /// The selected element runs at this place (0 first).
    SetExecutionOrder(u32),
    /// The chart is numbered by data flow, feedback last.
    OrderByDataFlow,
    /// The chart is numbered top to bottom, then left to right.
    OrderByTopology,
}

/// Why a gesture or a command did nothing, for the app's status line in the user's language.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CfcRefusal {
    /// The model edit does not apply.
    Edit(CfcEditError),
    /// No block of this name is known.
    UnknownBlock(String),
    /// No structure type of this name is known (for a composer or selector).
    UnknownStructure(String),
    /// An execution order was typed that is not a number.
    NotANumber(String),
}

/// What one frame of the CFC editor produced.
#[derive(Debug)]
pub struct CfcOutput {
    /// The canvas's response (focus, hover, the accessible label).
    pub response: egui::Response,
    /// The change made this frame: one gesture, one undo step.
    pub change: Option<CfcChange>,
    /// A function block instance to declare with the change.
    pub declare_instance: Option<InstanceDeclaration>,
    /// A value the user prepared for an input or output while online.
    pub prepared: Option<PreparedOperand>,
    /// Why the last gesture did nothing, if it did nothing.
    pub refusal: Option<CfcRefusal>,
    /// Where the user asked to set or clear a breakpoint (F9 or the context menu): the one
    /// selected element, in network 0; the app decides whether it has a statement.
    pub toggle_breakpoint: Option<crate::BodyPlace>,
}
