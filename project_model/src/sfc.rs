//! Sequential Function Chart bodies, structured as CODESYS's SFC editor draws them.
//!
//! A chart is one **sequence** that starts at the initial step. Along every path steps and
//! transitions alternate; branches open and close in pairs, so the structure itself rules out
//! a lone step, a lone transition or crossing paths, and an imported chart without geometry
//! lays itself out (as LD and FBD networks do, `network.rs`). The rules, checked on load, on
//! save and by every edit (`sfc_check.rs`):
//!
//! - the main sequence begins with the initial step and ends with a [`SfcNode::Jump`] (or with
//!   an alternative branch whose every branch ends in a jump);
//! - after a step (or macro step) comes a transition or an alternative branch; after a
//!   transition comes a step, a macro step, a parallel branch or a jump;
//! - an [`SfcNode::Alternative`] (single lines: one branch is taken, tested left to right, the
//!   first TRUE transition wins unless priorities say otherwise) has two or more branches, each
//!   beginning with a transition and ending with a transition (it joins again) or a jump;
//! - an [`SfcNode::Parallel`] (double lines: every branch runs) has two or more branches, each
//!   beginning with a step (or macro step) and ending with a step (or macro step); the
//!   transition after the branch fires when the last step of every branch is active;
//! - a jump is the last node of its sequence and names a step of the chart;
//! - a macro step's body begins and ends with a step and holds no jump;
//! - step names are identifiers, unique in the chart (macro steps included, case-insensitive).
//!
//! Every node has an [`ElementId`] unique in the body, as in LD and FBD, for diagnostics,
//! online values and (later) breakpoints.

use serde::{Deserialize, Serialize};

use crate::network::ElementId;

/// An SFC body: the main sequence, from the initial step.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SfcChart {
    /// The main sequence; its first node is the initial step.
    #[serde(default, rename = "node", skip_serializing_if = "Vec::is_empty")]
    pub sequence: Vec<SfcNode>,
}

/// One node of a sequence.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum SfcNode {
    /// A step.
    Step(Step),
    /// A transition.
    Transition(Transition),
    /// Alternative (selection) branches: exactly one is taken.
    Alternative(SfcBranches),
    /// Parallel (simultaneous) branches: all run together.
    Parallel(SfcBranches),
    /// A jump to a step; always the last node of its sequence.
    Jump(Jump),
    /// A macro step: a step drawn as a box that holds a sequence of its own.
    Macro(MacroStep),
}

/// A step: while active, its actions run by their qualifiers.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    /// The stable id.
    pub id: ElementId,
    /// The step's name, unique in the chart (`Fill`; its flags are `Fill.x`, `Fill.t`…).
    pub name: String,
    /// A comment shown beside the step.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
    /// The minimum time the step stays active (a TIME constant or variable, as written):
    /// its transitions do not fire before it has elapsed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min_time: Option<String>,
    /// The maximum time the step may stay active (a TIME constant or variable, as written);
    /// beyond it the chart reports a timeout (`SFCError`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_time: Option<String>,
    /// CODESYS's entry action: an action of the POU run once when the step becomes active.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entry_action: Option<String>,
    /// CODESYS's (non-IEC) step action: an action of the POU run in every cycle the step is
    /// active.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub main_action: Option<String>,
    /// CODESYS's exit action: an action of the POU run once, at the start of the cycle after
    /// the step was left.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exit_action: Option<String>,
    /// IEC action associations, processed top to bottom.
    #[serde(default, rename = "action", skip_serializing_if = "Vec::is_empty")]
    pub actions: Vec<ActionAssociation>,
}

/// A transition: it fires when every step before it is active and its condition is TRUE.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Transition {
    /// The stable id.
    pub id: ElementId,
    /// The condition: a BOOL expression in Structured Text (`start AND NOT stop`), or the name
    /// of a transition object of the POU (`Pou::transitions`), which may hold several
    /// statements in any language.
    pub condition: String,
    /// An explicit priority among the transitions of an alternative branch: lower numbers are
    /// tested first; without one, branches are tested left to right after those with one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub priority: Option<u32>,
    /// A comment shown beside the transition.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
}

/// The branches of an alternative or parallel branch, left to right.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SfcBranches {
    /// The stable id of the branch as a whole (its opening line).
    pub id: ElementId,
    /// The branches, left to right; at least two.
    #[serde(default, rename = "branch", skip_serializing_if = "Vec::is_empty")]
    pub branches: Vec<SfcSequence>,
}

/// One branch: a sequence of nodes.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SfcSequence {
    /// The nodes, top to bottom.
    #[serde(default, rename = "node", skip_serializing_if = "Vec::is_empty")]
    pub nodes: Vec<SfcNode>,
}

/// A jump to a step.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Jump {
    /// The stable id.
    pub id: ElementId,
    /// The target step's name.
    pub target: String,
}

/// A macro step: a named box standing for a sequence that begins and ends with a step.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MacroStep {
    /// The stable id.
    pub id: ElementId,
    /// The macro's name, unique among the chart's steps.
    pub name: String,
    /// A comment shown beside the macro.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub comment: String,
    /// The sequence inside, shown when the user zooms into the macro.
    #[serde(default, rename = "node", skip_serializing_if = "Vec::is_empty")]
    pub body: Vec<SfcNode>,
}

/// An IEC action association of a step: a qualifier, a time for the timed qualifiers, and the
/// action it controls.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct ActionAssociation {
    /// The action's name (an action of the POU) or a BOOL variable (a boolean action).
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub action: String,
    /// The qualifier.
    pub qualifier: ActionQualifier,
    /// The time of the timed qualifiers (L, D, SD, DS, SL) as written: a TIME constant such as
    /// `T#2s` or a TIME variable.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub duration: Option<String>,
    /// A BOOL indicator variable, TRUE while the action is active, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::ident())")
    )]
    pub indicator: Option<String>,
}

/// IEC 61131-3 action qualifiers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
pub enum ActionQualifier {
    /// Non-stored: active while the step is.
    #[default]
    N,
    /// Overriding reset of a stored action.
    R,
    /// Set (stored): active until reset.
    S,
    /// Time limited: active from activation until the time elapses or the step ends.
    L,
    /// Time delayed: active once the time has elapsed, while the step is still active.
    D,
    /// Pulse: one cycle on activation.
    P,
    /// Stored and time delayed: active once the time has elapsed, even if the step has ended,
    /// until reset.
    SD,
    /// Delayed and stored: active once the time has elapsed while the step is still active,
    /// then until reset.
    DS,
    /// Stored and time limited: active from activation for the time, or until reset.
    SL,
    /// Pulse on the falling edge of the step's activity.
    P0,
    /// Pulse on the rising edge of the step's activity.
    P1,
}

impl ActionQualifier {
    /// Every qualifier, in the order menus list them.
    pub const ALL: [Self; 11] = [
        Self::N,
        Self::R,
        Self::S,
        Self::L,
        Self::D,
        Self::P,
        Self::SD,
        Self::DS,
        Self::SL,
        Self::P0,
        Self::P1,
    ];

    /// Whether the qualifier takes a time (L, D, SD, DS, SL).
    pub fn is_timed(self) -> bool {
        matches!(self, Self::L | Self::D | Self::SD | Self::DS | Self::SL)
    }

    /// The qualifier written `text`, in any case (`sd` is `SD`).
    pub fn parse(text: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|qualifier| qualifier.as_str().eq_ignore_ascii_case(text))
    }

    /// The qualifier as IEC 61131-3 writes it, such as `SD`.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::N => "N",
            Self::R => "R",
            Self::S => "S",
            Self::L => "L",
            Self::D => "D",
            Self::P => "P",
            Self::SD => "SD",
            Self::DS => "DS",
            Self::SL => "SL",
            Self::P0 => "P0",
            Self::P1 => "P1",
        }
    }
}

impl SfcNode {
    /// A step named `name` with no actions, times or comment.
    pub fn step(id: ElementId, name: impl Into<String>) -> Self {
        Self::Step(Step {
            id,
            name: name.into(),
            ..Step::default()
        })
    }

    /// A transition firing on `condition` (an ST expression or a transition object's name).
    pub fn transition(id: ElementId, condition: impl Into<String>) -> Self {
        Self::Transition(Transition {
            id,
            condition: condition.into(),
            ..Transition::default()
        })
    }

    /// A jump to the step named `target`.
    pub fn jump(id: ElementId, target: impl Into<String>) -> Self {
        Self::Jump(Jump {
            id,
            target: target.into(),
        })
    }

    /// The node's stable id.
    pub fn id(&self) -> ElementId {
        match self {
            Self::Step(step) => step.id,
            Self::Transition(transition) => transition.id,
            Self::Alternative(branches) | Self::Parallel(branches) => branches.id,
            Self::Jump(jump) => jump.id,
            Self::Macro(macro_step) => macro_step.id,
        }
    }
}

impl SfcBranches {
    /// Branches `id` holding the sequences `branches`, left to right.
    pub fn new(id: ElementId, branches: Vec<Vec<SfcNode>>) -> Self {
        Self {
            id,
            branches: branches
                .into_iter()
                .map(|nodes| SfcSequence { nodes })
                .collect(),
        }
    }
}

impl SfcChart {
    /// The chart of a new SFC body, as CODESYS starts one: the initial step `Init`, a
    /// transition `FALSE`, and a jump back to `Init` (ids 1 to 3).
    pub fn new_body() -> Self {
        Self {
            sequence: vec![
                SfcNode::step(ElementId(1), "Init"),
                SfcNode::transition(ElementId(2), "FALSE"),
                SfcNode::jump(ElementId(3), "Init"),
            ],
        }
    }
}
