//! The plain data the diagram editor exchanges with the app: its change, the diagnostics and
//! online values it shows, what it asks of the app, and the services the app provides.

use std::collections::HashMap;

use project_model::{ElementId, Network, NetworkEditError};

use crate::{CompletionItem, Severity};

/// How a body is drawn: as a ladder or as function blocks. The body's language picks the
/// default; the user switches with the view toggle. Kept by the editor, never saved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DiagramView {
    /// Ladder Diagram: rails, contacts, coils.
    #[default]
    Ladder,
    /// Function Block Diagram: boxes and lines.
    FunctionBlock,
}

impl DiagramView {
    /// The view a body of `language` opens in: FBD for FBD, LD for everything else.
    pub fn of_language(language: project_model::Language) -> Self {
        match language {
            project_model::Language::Fbd => Self::FunctionBlock,
            _ => Self::Ladder,
        }
    }
}

/// One change of the body: `remove` networks from index `at` are replaced by `insert`. The app
/// turns it into the model's `Edit::SpliceNetworks` and applies it as one undo step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DiagramChange {
    /// The index of the first replaced network.
    pub at: usize,
    /// How many networks are replaced.
    pub remove: usize,
    /// The networks put in their place.
    pub insert: Vec<Network>,
}

impl DiagramChange {
    /// Applies the change to `body`, as the app's edit will; indices past the end are clamped.
    pub fn apply(&self, body: &mut Vec<Network>) {
        let at = self.at.min(body.len());
        let end = (at + self.remove).min(body.len());
        body.splice(at..end, self.insert.iter().cloned());
    }
}

/// A compiler diagnostic placed on a network's element, as the app maps it through the origin
/// map.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ElementDiagnostic {
    /// The network's index in the body.
    pub network: usize,
    /// The element; `None` for a finding about the network as a whole.
    pub element: Option<ElementId>,
    /// The pin of a box the finding is about, if any.
    pub pin: Option<String>,
    /// Error, warning or note.
    pub severity: Severity,
    /// The stable diagnostic code, such as `E0104`.
    pub code: String,
    /// The message, shown on hover.
    pub message: String,
}

/// What the target reports while logged in: the power after each element and the values of
/// operands and pins. Replaced by the app each time new values arrive; never saved.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DiagramOnline {
    /// The power flow after each element (a contact's output, a box's ENO, a group's OR).
    pub power: HashMap<ElementId, bool>,
    /// Values shown beside elements: by element and pin (`None` for the element's operand).
    pub values: HashMap<(ElementId, Option<String>), OnlineValue>,
}

/// One monitored value.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OnlineValue {
    /// The value as text.
    pub text: String,
    /// Whether the variable is forced.
    pub forced: bool,
}

/// A function block instance the user named on a box and the app should declare.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InstanceDeclaration {
    /// The instance's name.
    pub name: String,
    /// The function block's type.
    pub type_name: String,
}

/// A value the user prepared for an operand while online, to write or force.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PreparedOperand {
    /// The element whose operand it is.
    pub element: ElementId,
    /// The operand as written (a variable's path).
    pub operand: String,
    /// The value typed, as an IEC literal.
    pub value: String,
}

/// Why a command did nothing, for the app's status line in the user's language.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DiagramRefusal {
    /// The structural operation does not apply to the selection.
    Edit(NetworkEditError),
    /// No block of this name is known.
    UnknownBlock(String),
}

/// The pins of a block, as the app's compiler knows them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BlockSignature {
    /// The input pins in order (`EN` first for a box with EN/ENO).
    pub inputs: Vec<String>,
    /// The output pins in order (`ENO` first for a box with EN/ENO).
    pub outputs: Vec<String>,
    /// Whether the block is a function block, whose box needs an instance.
    pub function_block: bool,
}

/// The project-level services the diagram editor asks for; the app implements them with
/// `compiler::ide`, tests with a fake.
pub trait DiagramServices {
    /// Variables (and constants) whose names start with `prefix`, for operands.
    fn variables(&self, prefix: &str) -> Vec<CompletionItem>;
    /// Functions, function blocks and operators whose names start with `prefix`, for boxes.
    fn blocks(&self, prefix: &str) -> Vec<CompletionItem>;
    /// The pins of block `type_name`, if it is known.
    fn signature(&self, type_name: &str) -> Option<BlockSignature>;
    /// The members of the structure type `type_name`, if it is one: the pins of a CFC
    /// composer or selector.
    fn structure_members(&self, type_name: &str) -> Option<Vec<String>>;
    /// Whether a variable `name` is declared where the body is.
    fn is_declared(&self, name: &str) -> bool;
}

/// What one frame of the diagram editor produced.
#[derive(Debug)]
pub struct DiagramOutput {
    /// The canvas's response (focus, hover, the accessible label).
    pub response: egui::Response,
    /// The change made this frame: one gesture, one undo step.
    pub change: Option<DiagramChange>,
    /// A function block instance to declare with the change.
    pub declare_instance: Option<InstanceDeclaration>,
    /// A value the user prepared for an operand while online.
    pub prepared: Option<PreparedOperand>,
    /// Why the last command did nothing, if it did nothing.
    pub refusal: Option<DiagramRefusal>,
    /// Where the user asked to set or clear a breakpoint (F9 or the context menu): the selected
    /// network or element; the app decides whether it has a statement.
    pub toggle_breakpoint: Option<crate::BodyPlace>,
}
