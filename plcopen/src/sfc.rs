//! The SFC objects.

use crate::add_data::AddData;
use crate::body::Body;
use crate::connection::{ConnectionPointIn, ConnectionPointOut};
use crate::header::Point;
use crate::text::FormattedText;

/// `step`.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// `name`.
    pub name: String,
    /// `initialStep`.
    pub initial: bool,
    /// `negated`.
    pub negated: Option<bool>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
    /// `connectionPointOutAction`, where action blocks attach.
    pub action_output: Option<ConnectionPointOut>,
}

/// `macroStep`.
#[derive(Clone, Debug, PartialEq)]
pub struct MacroStep {
    /// `name`.
    pub name: Option<String>,
    /// The nested `body`.
    pub body: Option<Box<Body>>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `jumpStep`.
#[derive(Clone, Debug, PartialEq)]
pub struct JumpStep {
    /// `targetName`.
    pub target_name: String,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
}

/// `transition` of an SFC body.
#[derive(Clone, Debug, PartialEq)]
pub struct SfcTransition {
    /// `priority`, evaluated after a selection divergence.
    pub priority: Option<u32>,
    /// `condition`.
    pub condition: Option<Condition>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `condition` of an SFC transition.
#[derive(Clone, Debug, PartialEq)]
pub struct Condition {
    /// `negated`.
    pub negated: Option<bool>,
    /// The form the condition is written in.
    pub form: ConditionForm,
}

/// The three forms of a transition condition.
#[derive(Clone, Debug, PartialEq)]
pub enum ConditionForm {
    /// `reference@name`: a named transition of the POU.
    Reference(String),
    /// `connectionPointIn`: wired from objects of the same body (in v1.0 a bare `connection`).
    Connection(ConnectionPointIn),
    /// `inline@name` with a body (usually ST).
    Inline {
        /// `name`.
        name: Option<String>,
        /// The body.
        body: Box<Body>,
    },
}

/// `selectionDivergence` and `simultaneousDivergence`.
#[derive(Clone, Debug, PartialEq)]
pub struct Divergence {
    /// `name` (simultaneous divergences only).
    pub name: Option<String>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut` elements, left to right.
    pub outputs: Vec<ConnectionPointOut>,
}

/// `selectionConvergence` and `simultaneousConvergence`.
#[derive(Clone, Debug, PartialEq)]
pub struct Convergence {
    /// `connectionPointIn` elements, left to right.
    pub inputs: Vec<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `actionBlock`: the actions attached to a step.
#[derive(Clone, Debug, PartialEq)]
pub struct ActionBlock {
    /// `negated`.
    pub negated: Option<bool>,
    /// `connectionPointIn`, from the step.
    pub input: Option<ConnectionPointIn>,
    /// `action` elements in order.
    pub actions: Vec<ActionBlockAction>,
}

/// One `action` of an action block.
#[derive(Clone, Debug, PartialEq)]
pub struct ActionBlockAction {
    /// `localId` (Beremiz writes 0 for every action; v1.0 files have none, read as 0).
    pub local_id: u64,
    /// `executionOrderId`.
    pub execution_order_id: Option<u64>,
    /// `qualifier`; `None` when absent, which means N.
    pub qualifier: Option<Qualifier>,
    /// `duration`, as written (D, L, DS, SD, SL need one).
    pub duration: Option<String>,
    /// `indicator`.
    pub indicator: Option<String>,
    /// `relPosition`.
    pub rel_position: Option<Point>,
    /// What the action does.
    pub content: ActionContent,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

/// An action's reference or inline body.
#[derive(Clone, Debug, PartialEq)]
pub enum ActionContent {
    /// `reference@name`: a POU action or a variable.
    Reference(String),
    /// `inline`: a body.
    Inline(Box<Body>),
}

/// The action qualifiers of the schema.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Qualifier {
    /// `P1`.
    P1,
    /// `N`.
    N,
    /// `P0`.
    P0,
    /// `R`.
    R,
    /// `S`.
    S,
    /// `L`.
    L,
    /// `D`.
    D,
    /// `P`.
    P,
    /// `DS`.
    Ds,
    /// `DL` (in the schema's enumeration, not an IEC qualifier).
    Dl,
    /// `SD`.
    Sd,
    /// `SL`.
    Sl,
}

impl Qualifier {
    /// The qualifier of an attribute value, or `None` when the schema has no such qualifier.
    pub fn parse(text: &str) -> Option<Qualifier> {
        Some(match text {
            "P1" => Qualifier::P1,
            "N" => Qualifier::N,
            "P0" => Qualifier::P0,
            "R" => Qualifier::R,
            "S" => Qualifier::S,
            "L" => Qualifier::L,
            "D" => Qualifier::D,
            "P" => Qualifier::P,
            "DS" => Qualifier::Ds,
            "DL" => Qualifier::Dl,
            "SD" => Qualifier::Sd,
            "SL" => Qualifier::Sl,
            _ => return None,
        })
    }
}
