//! Ladder Diagram and Function Block Diagram bodies: lists of networks that lay themselves out.
//!
//! CODESYS's model: a POU body is a list of networks run top to bottom; each network is one
//! piece of logic read left to right. An LD rung and an FBD network are the same structure seen
//! two ways, so one type serves both and the body's language only picks the default view:
//!
//! - a [`Network`]'s `rung` is a **chain**: power (a BOOL) enters on the left, at TRUE from the
//!   left power rail, and each [`FlowNode`] of the chain passes it on to the next;
//! - an [`Operand`] is an LD contact, or an FBD input: in a chain it ANDs its value into the
//!   power (negated for a normally closed contact, through an edge trigger for P and N);
//! - a [`Parallel`] group runs each of its branches (chains) with the same incoming power and
//!   ORs their results (LD parallel contacts, FBD's OR box);
//! - a [`BlockCall`] is a box: a function, operator, function block instance or program. In a
//!   chain its first input (EN when the box has EN/ENO) takes the incoming power when nothing
//!   else drives it, and its ENO (or else its first output) passes power on. Every other input
//!   is driven by a chain of its own (an FBD subtree, or one operand: a variable, a literal, an
//!   expression), and every other output may be assigned to a variable;
//! - the power at the end of the rung drives the network's [`NetworkOutput`]s: coils (FBD
//!   assignments), a jump, a return, or a branch with more contacts and outputs of its own.
//!
//! Nothing is placed by hand: the editor computes positions from this structure, so an
//! imported network without geometry looks as if it were drawn. Every element has an
//! [`ElementId`] that is unique in its body and survives edits, moves and reloads; diagnostics,
//! breakpoints and online values are attached to it.

use serde::{Deserialize, Serialize};

/// A stable element id, unique within its POU body; it survives moves, edits and reloads.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(transparent)]
pub struct ElementId(pub u32);

/// One LD rung or FBD network.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Network {
    /// The network's title, shown in its header.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub title: String,
    /// The network's comment, shown under the title.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
    /// A jump label for the network, if any (an identifier; empty for none).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub label: String,
    /// The chain of elements from the left power rail.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rung: Vec<FlowNode>,
    /// What the power at the end of the rung drives, top to bottom.
    #[serde(default, rename = "output", skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<NetworkOutput>,
}

/// One element of a chain.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum FlowNode {
    /// An LD contact or FBD input.
    Operand(Operand),
    /// Branches in parallel, ORed.
    Parallel(Parallel),
    /// A box.
    Block(BlockCall),
}

/// An LD contact, or an FBD input: a variable, literal or expression read into the network.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Operand {
    /// The stable id.
    pub id: ElementId,
    /// What is read, as written: a variable's path, a literal or an expression.
    pub text: String,
    /// A normally closed contact, or a negated FBD input.
    #[serde(default, skip_serializing_if = "crate::variable::is_false")]
    pub negated: bool,
    /// Edge detection: a P or N contact.
    #[serde(default, skip_serializing_if = "crate::variable::is_default")]
    pub edge: Edge,
}

/// Branches that receive the same power and whose results are ORed.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Parallel {
    /// The stable id.
    pub id: ElementId,
    /// The branches, top to bottom; each is a chain.
    #[serde(default, rename = "branch")]
    pub branches: Vec<Branch>,
}

/// One branch of a parallel group: a chain.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Branch {
    /// The chain.
    #[serde(default)]
    pub rung: Vec<FlowNode>,
}

/// A box: a call of a function, operator, function block instance or program.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlockCall {
    /// The stable id.
    pub id: ElementId,
    /// The function, operator, function block or program name, such as `TON` or `ADD`.
    pub type_name: String,
    /// The instance's path for a function block; empty for functions and operators.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub instance: String,
    /// The inputs in display order; an `EN` input, if any, comes first.
    #[serde(default, rename = "input", skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<BlockInput>,
    /// The outputs in display order; an `ENO` output, if any, comes first.
    #[serde(default, rename = "output", skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<BlockOutput>,
}

/// The name of the enable input of a box with EN/ENO.
pub const EN_PIN: &str = "EN";
/// The name of the enable output of a box with EN/ENO.
pub const ENO_PIN: &str = "ENO";

impl BlockCall {
    /// Whether the box has EN and ENO pins.
    pub fn has_en_eno(&self) -> bool {
        self.inputs
            .first()
            .is_some_and(|input| input.pin.eq_ignore_ascii_case(EN_PIN))
    }

    /// The index of the output that passes the power (or value) on in a chain: ENO when the
    /// box has one, else its first output.
    pub fn chain_output(&self) -> Option<usize> {
        if self.outputs.is_empty() {
            None
        } else {
            Some(
                self.outputs
                    .iter()
                    .position(|output| output.pin.eq_ignore_ascii_case(ENO_PIN))
                    .unwrap_or(0),
            )
        }
    }
}

/// An input pin of a box.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlockInput {
    /// The formal parameter's name, such as `IN`, or `IN1`, `IN2` … for an extensible
    /// operator.
    pub pin: String,
    /// The input is negated.
    #[serde(default, skip_serializing_if = "crate::variable::is_false")]
    pub negated: bool,
    /// Edge detection on the input.
    #[serde(default, skip_serializing_if = "crate::variable::is_default")]
    pub edge: Edge,
    /// What drives the input: a chain. Empty for the box's first input when the box sits in a
    /// chain (the power drives it) and for an input left unconnected.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub source: Vec<FlowNode>,
}

/// An output pin of a box.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlockOutput {
    /// The formal parameter's name, such as `Q`.
    pub pin: String,
    /// The output is negated before it is passed on or assigned.
    #[serde(default, skip_serializing_if = "crate::variable::is_false")]
    pub negated: bool,
    /// The variable the output is assigned to; empty for none.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub assign: String,
}

/// What the power at the end of a rung drives.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum NetworkOutput {
    /// An LD coil, or an FBD assignment.
    Coil(Coil),
    /// A jump to the network with this label when the power is TRUE.
    Jump {
        /// The stable id.
        id: ElementId,
        /// The target network's label.
        label: String,
    },
    /// A return from the POU when the power is TRUE.
    Return {
        /// The stable id.
        id: ElementId,
    },
    /// A branch of the output side: a chain of its own, then outputs.
    Branch {
        /// The stable id.
        id: ElementId,
        /// The chain, fed with the power at the end of the rung.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        rung: Vec<FlowNode>,
        /// What the power at the end of the branch drives.
        #[serde(default, rename = "output", skip_serializing_if = "Vec::is_empty")]
        outputs: Vec<NetworkOutput>,
    },
}

/// An LD coil or FBD assignment.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Coil {
    /// The stable id.
    pub id: ElementId,
    /// The variable written, as its path.
    pub variable: String,
    /// How the coil writes it.
    #[serde(default, skip_serializing_if = "crate::variable::is_default")]
    pub kind: CoilKind,
}

/// Edge detection of an LD contact or an FBD pin.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum Edge {
    /// Passes the value.
    #[default]
    None,
    /// Passes TRUE for one cycle on a rising edge (`P` contact).
    Rising,
    /// Passes TRUE for one cycle on a falling edge (`N` contact).
    Falling,
}

/// How an LD coil writes its variable.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum CoilKind {
    /// Writes the power flow.
    #[default]
    Normal,
    /// Writes the negated power flow.
    Negated,
    /// Sets the variable when power flows (`S`).
    Set,
    /// Resets the variable when power flows (`R`).
    Reset,
    /// Writes TRUE for one cycle on a rising power flow.
    Rising,
    /// Writes TRUE for one cycle on a falling power flow.
    Falling,
}

impl FlowNode {
    /// The element's stable id.
    pub fn id(&self) -> ElementId {
        match self {
            Self::Operand(operand) => operand.id,
            Self::Parallel(parallel) => parallel.id,
            Self::Block(block) => block.id,
        }
    }
}

impl NetworkOutput {
    /// The element's stable id.
    pub fn id(&self) -> ElementId {
        match self {
            Self::Coil(coil) => coil.id,
            Self::Jump { id, .. } | Self::Return { id } | Self::Branch { id, .. } => *id,
        }
    }
}
