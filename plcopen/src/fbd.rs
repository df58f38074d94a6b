//! The FBD objects (and the common ones: connectors, continuations, vendor elements).

use crate::connection::{ConnectionPointIn, ConnectionPointOut};
use crate::ld::{Edge, Storage};
use crate::text::FormattedText;

/// `block`: a function, function block instance or program call.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// `typeName`.
    pub type_name: String,
    /// `instanceName`, absent for functions.
    pub instance_name: Option<String>,
    /// `inputVariables/variable`.
    pub inputs: Vec<BlockPin>,
    /// `inOutVariables/variable`.
    pub in_outs: Vec<BlockPin>,
    /// `outputVariables/variable`.
    pub outputs: Vec<BlockPin>,
}

/// A pin of a block or vendor element.
#[derive(Clone, Debug, PartialEq)]
pub struct BlockPin {
    /// `formalParameter`.
    pub formal_parameter: String,
    /// `negated`, when written.
    pub negated: Option<bool>,
    /// `edge`, when written.
    pub edge: Option<Edge>,
    /// `storage`, when written.
    pub storage: Option<Storage>,
    /// `hidden`, when written.
    pub hidden: Option<bool>,
    /// `connectionPointIn` (inputs and in-outs).
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut` (outputs and in-outs).
    pub output: Option<ConnectionPointOut>,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

/// `inVariable`: an expression read into the diagram.
#[derive(Clone, Debug, PartialEq)]
pub struct InVariable {
    /// `expression`.
    pub expression: String,
    /// `negated`.
    pub negated: Option<bool>,
    /// `edge`.
    pub edge: Option<Edge>,
    /// `storage`.
    pub storage: Option<Storage>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `outVariable`: a variable the diagram writes.
#[derive(Clone, Debug, PartialEq)]
pub struct OutVariable {
    /// `expression`.
    pub expression: String,
    /// `negated`.
    pub negated: Option<bool>,
    /// `edge`.
    pub edge: Option<Edge>,
    /// `storage`.
    pub storage: Option<Storage>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
}

/// `inOutVariable`: a variable read and written.
#[derive(Clone, Debug, PartialEq)]
pub struct InOutVariable {
    /// `expression`.
    pub expression: String,
    /// `negatedIn`.
    pub negated_in: Option<bool>,
    /// `edgeIn`.
    pub edge_in: Option<Edge>,
    /// `storageIn`.
    pub storage_in: Option<Storage>,
    /// `negatedOut`.
    pub negated_out: Option<bool>,
    /// `edgeOut`.
    pub edge_out: Option<Edge>,
    /// `storageOut`.
    pub storage_out: Option<Storage>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `label`: a jump target.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Label {
    /// `label`.
    pub label: String,
}

/// `jump`: a conditional jump to a label.
#[derive(Clone, Debug, PartialEq)]
pub struct Jump {
    /// `label`.
    pub label: String,
    /// `connectionPointIn`, the condition.
    pub input: Option<ConnectionPointIn>,
}

/// `return`: a conditional return.
#[derive(Clone, Debug, PartialEq)]
pub struct Return {
    /// `connectionPointIn`, the condition.
    pub input: Option<ConnectionPointIn>,
}

/// `connector`: the sink of a named (or, in CODESYS CFC, unnamed) off-page link.
#[derive(Clone, Debug, PartialEq)]
pub struct Connector {
    /// `name`.
    pub name: String,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
}

/// `continuation`: a source reading the connector of the same name.
#[derive(Clone, Debug, PartialEq)]
pub struct Continuation {
    /// `name`.
    pub name: String,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `vendorElement`: an element whose meaning lives in its `addData`.
#[derive(Clone, Debug, PartialEq)]
pub struct VendorElement {
    /// `alternativeText`.
    pub alternative_text: FormattedText,
    /// `inputVariables/variable`.
    pub inputs: Vec<BlockPin>,
    /// `inOutVariables/variable`.
    pub in_outs: Vec<BlockPin>,
    /// `outputVariables/variable`.
    pub outputs: Vec<BlockPin>,
}
