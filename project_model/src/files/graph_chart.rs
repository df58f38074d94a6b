//! The graphical bodies of format versions 1 and 2: placed elements joined by connections.
//!
//! Version 1 stored every graphical body this way, version 2 its CFC and SFC charts. They are
//! read only to be converted: LD and FBD into networks (`chart_conversion.rs`), CFC into a
//! [`crate::CfcChart`] and SFC into a structured [`crate::SfcChart`]
//! (`older_charts.rs`).

use serde::{Deserialize, Serialize};

use crate::cfc::PinRef;
use crate::network::{CoilKind, Edge, ElementId};
use crate::sfc::ActionAssociation;

/// A CFC or SFC chart: placed elements and the wires between their pins.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Chart {
    /// A jump label for the chart, if any.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub label: String,
    /// The chart's title and comment.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
    /// The elements, in no particular order; `execution_order` decides evaluation.
    #[serde(default, rename = "element", skip_serializing_if = "Vec::is_empty")]
    pub elements: Vec<ChartElement>,
    /// Wires between element pins.
    #[serde(default, rename = "connection", skip_serializing_if = "Vec::is_empty")]
    pub connections: Vec<Connection>,
}

/// One element of a chart.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChartElement {
    /// The stable id.
    pub id: ElementId,
    /// Column of the element's top-left corner in grid units.
    pub x: i32,
    /// Row of the element's top-left corner in grid units.
    pub y: i32,
    /// Evaluation order in CFC (and explicit order elsewhere), lowest first.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub execution_order: Option<u32>,
    /// What the element is.
    pub kind: ChartElementKind,
}

/// The kinds of chart elements.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ChartElementKind {
    /// LD left power rail.
    LeftRail {
        /// Number of outgoing connection points.
        height: u32,
    },
    /// LD right power rail.
    RightRail {
        /// Number of incoming connection points.
        height: u32,
    },
    /// LD contact on a BOOL variable.
    Contact {
        /// The variable's path.
        variable: String,
        /// A normally closed contact.
        #[serde(default, skip_serializing_if = "crate::variable::is_false")]
        negated: bool,
        /// Edge detection.
        #[serde(default, skip_serializing_if = "crate::variable::is_default")]
        edge: Edge,
    },
    /// LD coil on a BOOL variable.
    Coil {
        /// The variable's path.
        variable: String,
        /// How the coil writes the variable.
        #[serde(default, skip_serializing_if = "crate::variable::is_default")]
        coil: CoilKind,
    },
    /// A function, function block or operator box.
    Block {
        /// The function, FB or operator name, such as `TON` or `ADD`.
        type_name: String,
        /// The FB instance's path; empty for functions and operators.
        #[serde(default, skip_serializing_if = "String::is_empty")]
        instance: String,
        /// Input pin names in display order.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        inputs: Vec<String>,
        /// Output pin names in display order.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        outputs: Vec<String>,
        /// Whether the box has EN and ENO pins.
        #[serde(default, skip_serializing_if = "crate::variable::is_false")]
        en_eno: bool,
    },
    /// An expression read into a network (FBD/CFC input).
    Input {
        /// The expression as written.
        expression: String,
    },
    /// A variable written by a network (FBD/CFC output).
    Output {
        /// The variable's path as written.
        expression: String,
    },
    /// A jump to a network label when the input is TRUE.
    Jump {
        /// The target label.
        label: String,
    },
    /// A return from the POU when the input is TRUE.
    Return,
    /// A free comment box.
    Comment {
        /// The comment.
        text: String,
        /// Width in grid units.
        width: u32,
        /// Height in grid units.
        height: u32,
    },
    /// A named connector: the value wired into it is available at every continuation of the
    /// same name.
    Connector {
        /// The connector's name.
        name: String,
    },
    /// Where a connector's value comes out again.
    Continuation {
        /// The connector's name.
        name: String,
    },
    /// An SFC step.
    Step {
        /// The step's name.
        name: String,
        /// The initial step of the chart.
        #[serde(default, skip_serializing_if = "crate::variable::is_false")]
        initial: bool,
        /// CODESYS step entry action, run once when the step becomes active.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        entry_action: Option<String>,
        /// CODESYS step exit action, run once when the step is left.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        exit_action: Option<String>,
        /// IEC action associations with qualifiers.
        #[serde(default, rename = "action", skip_serializing_if = "Vec::is_empty")]
        actions: Vec<ActionAssociation>,
    },
    /// An SFC transition.
    Transition {
        /// The transition condition: a BOOL expression in Structured Text.
        condition: String,
    },
    /// The start of parallel or alternative SFC branches.
    Divergence {
        /// Selection (alternative) or simultaneous (parallel).
        branch: BranchKind,
        /// Number of branches.
        branches: u32,
    },
    /// The end of parallel or alternative SFC branches.
    Convergence {
        /// Selection (alternative) or simultaneous (parallel).
        branch: BranchKind,
        /// Number of branches.
        branches: u32,
    },
    /// An SFC jump to a step.
    StepJump {
        /// The target step's name.
        target: String,
    },
}

/// Alternative or parallel SFC branches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BranchKind {
    /// One branch is taken (selection).
    Selection,
    /// All branches run (simultaneous).
    Simultaneous,
}

/// A wire between an output pin and an input pin.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Connection {
    /// The driving pin.
    pub from: PinRef,
    /// The driven pin.
    pub to: PinRef,
}
