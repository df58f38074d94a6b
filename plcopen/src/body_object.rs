//! The objects of a graphical body.

use crate::add_data::AddData;
use crate::connection::ConnectionPointIn;
use crate::fbd::{
    Block, Connector, Continuation, InOutVariable, InVariable, Jump, Label, OutVariable, Return,
    VendorElement,
};
use crate::header::Point;
use crate::ld::{Coil, Contact, LeftPowerRail, RightPowerRail};
use crate::sfc::{ActionBlock, Convergence, Divergence, JumpStep, MacroStep, SfcTransition, Step};
use crate::text::FormattedText;

/// One object of an FBD, LD, SFC or CFC body, with what every object has.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyObject {
    /// `localId`, unique in its body (CODESYS uses values above `u32::MAX`).
    pub local_id: u64,
    /// `executionOrderId`: `None` when absent, which is not the same as `Some(0)` (Beremiz's
    /// "unordered").
    pub execution_order_id: Option<u64>,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `position`, when written.
    pub position: Option<Point>,
    /// `width` and `height`.
    pub size: Size,
    /// What the object is.
    pub kind: ObjectKind,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the element (1-based).
    pub line: u32,
    /// Column of the element (1-based).
    pub column: u32,
}

/// `width` and `height` of an object, when written.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Size {
    /// `width`.
    pub width: Option<f64>,
    /// `height`.
    pub height: Option<f64>,
}

/// The kinds of body objects, one per element of the schema.
#[derive(Clone, Debug, PartialEq)]
pub enum ObjectKind {
    /// `block`.
    Block(Block),
    /// `inVariable`.
    InVariable(InVariable),
    /// `outVariable`.
    OutVariable(OutVariable),
    /// `inOutVariable`.
    InOutVariable(InOutVariable),
    /// `label`.
    Label(Label),
    /// `jump`.
    Jump(Jump),
    /// `return`.
    Return(Return),
    /// `connector`.
    Connector(Connector),
    /// `continuation`.
    Continuation(Continuation),
    /// `comment` with its content.
    Comment(FormattedText),
    /// `error` with its content (what an earlier converter could not interpret).
    Error(FormattedText),
    /// `vendorElement`.
    VendorElement(VendorElement),
    /// `leftPowerRail`.
    LeftPowerRail(LeftPowerRail),
    /// `rightPowerRail`.
    RightPowerRail(RightPowerRail),
    /// `contact`.
    Contact(Contact),
    /// `coil`.
    Coil(Coil),
    /// `step`.
    Step(Step),
    /// `macroStep`.
    MacroStep(MacroStep),
    /// `jumpStep`.
    JumpStep(JumpStep),
    /// `transition` (of an SFC body, not a POU's named transition).
    Transition(SfcTransition),
    /// `selectionDivergence`.
    SelectionDivergence(Divergence),
    /// `selectionConvergence`.
    SelectionConvergence(Convergence),
    /// `simultaneousDivergence`.
    SimultaneousDivergence(Divergence),
    /// `simultaneousConvergence`.
    SimultaneousConvergence(Convergence),
    /// `actionBlock`.
    ActionBlock(ActionBlock),
}

impl ObjectKind {
    /// The connection points through which an FBD, LD or CFC object reads others (a block's
    /// and a vendor element's inputs and in-outs, a variable's, connector's, contact's, coil's,
    /// jump's and return's input, a right rail's inputs), in document order; none for the
    /// others.
    pub fn graph_inputs(&self) -> Vec<&ConnectionPointIn> {
        match self {
            ObjectKind::Block(block) => block
                .inputs
                .iter()
                .chain(&block.in_outs)
                .filter_map(|pin| pin.input.as_ref())
                .collect(),
            ObjectKind::VendorElement(element) => element
                .inputs
                .iter()
                .chain(&element.in_outs)
                .filter_map(|pin| pin.input.as_ref())
                .collect(),
            ObjectKind::OutVariable(variable) => variable.input.iter().collect(),
            ObjectKind::InOutVariable(variable) => variable.input.iter().collect(),
            ObjectKind::Connector(connector) => connector.input.iter().collect(),
            ObjectKind::Contact(contact) => contact.input.iter().collect(),
            ObjectKind::Coil(coil) => coil.input.iter().collect(),
            ObjectKind::Jump(jump) => jump.input.iter().collect(),
            ObjectKind::Return(ret) => ret.input.iter().collect(),
            ObjectKind::RightPowerRail(rail) => rail.inputs.iter().collect(),
            _ => Vec::new(),
        }
    }

    /// [`Self::graph_inputs`], to be rewired.
    pub fn graph_inputs_mut(&mut self) -> Vec<&mut ConnectionPointIn> {
        match self {
            ObjectKind::Block(block) => block
                .inputs
                .iter_mut()
                .chain(&mut block.in_outs)
                .filter_map(|pin| pin.input.as_mut())
                .collect(),
            ObjectKind::VendorElement(element) => element
                .inputs
                .iter_mut()
                .chain(&mut element.in_outs)
                .filter_map(|pin| pin.input.as_mut())
                .collect(),
            ObjectKind::OutVariable(variable) => variable.input.iter_mut().collect(),
            ObjectKind::InOutVariable(variable) => variable.input.iter_mut().collect(),
            ObjectKind::Connector(connector) => connector.input.iter_mut().collect(),
            ObjectKind::Contact(contact) => contact.input.iter_mut().collect(),
            ObjectKind::Coil(coil) => coil.input.iter_mut().collect(),
            ObjectKind::Jump(jump) => jump.input.iter_mut().collect(),
            ObjectKind::Return(ret) => ret.input.iter_mut().collect(),
            ObjectKind::RightPowerRail(rail) => rail.inputs.iter_mut().collect(),
            _ => Vec::new(),
        }
    }

    /// The element name of the kind.
    pub fn element_name(&self) -> &'static str {
        match self {
            ObjectKind::Block(_) => "block",
            ObjectKind::InVariable(_) => "inVariable",
            ObjectKind::OutVariable(_) => "outVariable",
            ObjectKind::InOutVariable(_) => "inOutVariable",
            ObjectKind::Label(_) => "label",
            ObjectKind::Jump(_) => "jump",
            ObjectKind::Return(_) => "return",
            ObjectKind::Connector(_) => "connector",
            ObjectKind::Continuation(_) => "continuation",
            ObjectKind::Comment(_) => "comment",
            ObjectKind::Error(_) => "error",
            ObjectKind::VendorElement(_) => "vendorElement",
            ObjectKind::LeftPowerRail(_) => "leftPowerRail",
            ObjectKind::RightPowerRail(_) => "rightPowerRail",
            ObjectKind::Contact(_) => "contact",
            ObjectKind::Coil(_) => "coil",
            ObjectKind::Step(_) => "step",
            ObjectKind::MacroStep(_) => "macroStep",
            ObjectKind::JumpStep(_) => "jumpStep",
            ObjectKind::Transition(_) => "transition",
            ObjectKind::SelectionDivergence(_) => "selectionDivergence",
            ObjectKind::SelectionConvergence(_) => "selectionConvergence",
            ObjectKind::SimultaneousDivergence(_) => "simultaneousDivergence",
            ObjectKind::SimultaneousConvergence(_) => "simultaneousConvergence",
            ObjectKind::ActionBlock(_) => "actionBlock",
        }
    }
}
