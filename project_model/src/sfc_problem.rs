//! One broken structural rule of an SFC chart, typed, so that loading (a message naming the
//! element) and every edit (an [`SfcEditError`] the editor translates) report the same finding
//! of the one check in `sfc_check.rs`.

use std::fmt;

use crate::network::ElementId;
use crate::sfc::SfcNode;
use crate::sfc_edit::{SfcEditError, SfcRule};

/// What kind of node a problem is found at, in the words of its message.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SfcNodeKind {
    /// A step.
    Step,
    /// A transition.
    Transition,
    /// An alternative branch.
    Alternative,
    /// A parallel branch.
    Parallel,
    /// A jump.
    Jump,
    /// A macro step.
    Macro,
}

impl SfcNodeKind {
    /// The kind of `node`.
    pub fn of(node: &SfcNode) -> Self {
        match node {
            SfcNode::Step(_) => Self::Step,
            SfcNode::Transition(_) => Self::Transition,
            SfcNode::Alternative(_) => Self::Alternative,
            SfcNode::Parallel(_) => Self::Parallel,
            SfcNode::Jump(_) => Self::Jump,
            SfcNode::Macro(_) => Self::Macro,
        }
    }

    /// The kind with its article, as messages write it (`a step`).
    pub fn describe(self) -> &'static str {
        match self {
            Self::Step => "a step",
            Self::Transition => "a transition",
            Self::Alternative => "an alternative branch",
            Self::Parallel => "a parallel branch",
            Self::Jump => "a jump",
            Self::Macro => "a macro step",
        }
    }
}

/// Which rule a problem breaks, with what its message needs to say.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SfcProblemKind {
    /// The chart holds no node at all.
    EmptyChart,
    /// The first node of a sequence is not what its place needs (the rule says which place).
    WrongFirst(SfcRule),
    /// A node does not fit after the one before it (a `…After` rule or [`SfcRule::JumpIsLast`]).
    OutOfOrder(SfcRule),
    /// The last node of a sequence is not what its place needs (the rule says which place).
    WrongLast(SfcRule),
    /// A macro step's body holds no node.
    EmptyMacroBody,
    /// An alternative or parallel branch has fewer than two branches.
    TooFewBranches {
        /// How many it has.
        count: usize,
    },
    /// A branch holds no node.
    EmptyBranch {
        /// The branch's number, from 1.
        number: usize,
    },
    /// A macro step's body holds a jump.
    JumpInMacro,
    /// Another element has the same id.
    DuplicateId,
    /// A step name is not an identifier.
    InvalidName(String),
    /// A step name holds `__`, which Rivet keeps for the names it makes.
    ReservedName(String),
    /// More than one step has this name (case-insensitive).
    DuplicateName {
        /// The name as this step writes it.
        name: String,
        /// How many steps have it.
        count: usize,
    },
    /// A jump names a step the chart does not have.
    UnknownStep(String),
    /// An action association names no action.
    EmptyAction,
    /// A timed qualifier has no time.
    MissingDuration {
        /// The action associated.
        action: String,
        /// The qualifier (`L`, `D`, `SD`, `DS`, `SL`).
        qualifier: &'static str,
    },
    /// A qualifier without time was given one.
    UnexpectedDuration {
        /// The action associated.
        action: String,
        /// The qualifier (`N`, `R`, `S`, `P`, `P0`, `P1`).
        qualifier: &'static str,
    },
}

/// One broken rule at one element of a chart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SfcProblem {
    /// The element where the rule breaks (0 for an empty chart).
    pub element: ElementId,
    /// The name of that element when it is a step or a macro step, for the message.
    pub step_name: Option<String>,
    /// What kind of node the element is (a step for an empty chart, whose message names no
    /// element).
    pub node: SfcNodeKind,
    /// The broken rule.
    pub kind: SfcProblemKind,
}

impl SfcProblem {
    /// A problem of `kind` at `node`.
    pub(crate) fn at(node: &SfcNode, kind: SfcProblemKind) -> Self {
        let step_name = match node {
            SfcNode::Step(step) => Some(step.name.clone()),
            SfcNode::Macro(macro_step) => Some(macro_step.name.clone()),
            _ => None,
        };
        Self {
            element: node.id(),
            step_name,
            node: SfcNodeKind::of(node),
            kind,
        }
    }

    /// Whether an edit should name this problem before others: the shape of the chart first,
    /// then its names, then the jump targets, then the action associations.
    pub(crate) fn edit_priority(&self) -> u8 {
        match &self.kind {
            SfcProblemKind::InvalidName(_)
            | SfcProblemKind::ReservedName(_)
            | SfcProblemKind::DuplicateName { .. } => 1,
            SfcProblemKind::UnknownStep(_) => 2,
            SfcProblemKind::EmptyAction
            | SfcProblemKind::MissingDuration { .. }
            | SfcProblemKind::UnexpectedDuration { .. } => 3,
            _ => 0,
        }
    }

    /// The refusal an edit gives for this problem.
    pub fn to_edit_error(&self) -> SfcEditError {
        let structure = |rule| SfcEditError::Structure {
            rule,
            element: self.element,
        };
        match &self.kind {
            SfcProblemKind::WrongFirst(rule)
            | SfcProblemKind::OutOfOrder(rule)
            | SfcProblemKind::WrongLast(rule) => structure(*rule),
            SfcProblemKind::EmptyChart | SfcProblemKind::EmptyBranch { .. } => {
                structure(SfcRule::SequenceNotEmpty)
            }
            SfcProblemKind::EmptyMacroBody => structure(SfcRule::MacroBeginsAndEndsWithStep),
            SfcProblemKind::TooFewBranches { .. } => structure(SfcRule::TwoBranches),
            SfcProblemKind::JumpInMacro => structure(SfcRule::NoJumpInMacro),
            SfcProblemKind::DuplicateId => structure(SfcRule::UniqueIds),
            SfcProblemKind::InvalidName(name) | SfcProblemKind::ReservedName(name) => {
                SfcEditError::InvalidName(name.clone())
            }
            SfcProblemKind::DuplicateName { name, .. } => SfcEditError::DuplicateName(name.clone()),
            SfcProblemKind::UnknownStep(target) => SfcEditError::UnknownStep(target.clone()),
            SfcProblemKind::EmptyAction => SfcEditError::EmptyAction,
            SfcProblemKind::MissingDuration { qualifier, .. } => {
                SfcEditError::MissingDuration(qualifier)
            }
            SfcProblemKind::UnexpectedDuration { qualifier, .. } => {
                SfcEditError::UnexpectedDuration(qualifier)
            }
        }
    }

    /// The message after the element's label.
    fn message(&self) -> String {
        let what = self.node.describe();
        match &self.kind {
            SfcProblemKind::EmptyChart => {
                "the chart is empty; it must begin with its initial step".into()
            }
            SfcProblemKind::WrongFirst(rule) => match rule {
                SfcRule::MainStartsWithStep => {
                    format!("the chart must begin with its initial step, not {what}")
                }
                SfcRule::AlternativeBeginsWithTransition => {
                    format!("a branch of an alternative must begin with a transition, not {what}")
                }
                SfcRule::ParallelBeginsWithStep => {
                    format!("a branch of a parallel branch must begin with a step, not {what}")
                }
                _ => format!("the body of a macro step must begin with a step, not {what}"),
            },
            SfcProblemKind::OutOfOrder(rule) => match rule {
                SfcRule::JumpIsLast => "nothing may follow a jump in its sequence".into(),
                SfcRule::StepNeedsTransitionAfter => format!(
                    "{what} cannot follow a step; a transition or an alternative branch must"
                ),
                _ => format!(
                    "{what} cannot follow a transition; a step, a macro step, a parallel branch \
                     or a jump must"
                ),
            },
            SfcProblemKind::WrongLast(rule) => match rule {
                SfcRule::MainEndsWithJump => "the chart must end with a jump (or an alternative \
                                              branch whose every branch ends with a jump)"
                    .into(),
                SfcRule::AlternativeEndsWithTransitionOrJump => {
                    "a branch of an alternative must end with a transition or a jump".into()
                }
                SfcRule::ParallelEndsWithStep => {
                    "a branch of a parallel branch must end with a step".into()
                }
                _ => "the body of a macro step must end with a step".into(),
            },
            SfcProblemKind::EmptyMacroBody => {
                "the body of a macro step must begin with a step".into()
            }
            SfcProblemKind::TooFewBranches { count } => {
                format!("{what} needs at least two branches; it has {count}")
            }
            SfcProblemKind::EmptyBranch { number } => format!("branch {number} is empty"),
            SfcProblemKind::JumpInMacro => "a macro step's body cannot hold a jump".into(),
            SfcProblemKind::DuplicateId => {
                format!("two elements have the id {}", self.element.0)
            }
            SfcProblemKind::InvalidName(name) => {
                format!("the step name '{name}' is not an identifier (letters, digits and '_')")
            }
            SfcProblemKind::ReservedName(name) => {
                format!("the step name '{name}' contains '__', which Rivet keeps for itself")
            }
            SfcProblemKind::DuplicateName { name, count } => {
                format!("{count} steps are named '{name}'")
            }
            SfcProblemKind::UnknownStep(target) => {
                format!("the jump names the step '{target}', which does not exist")
            }
            SfcProblemKind::EmptyAction => "an action association names no action".into(),
            SfcProblemKind::MissingDuration { action, qualifier } => {
                format!("the association of '{action}' with {qualifier} needs a time")
            }
            SfcProblemKind::UnexpectedDuration { action, qualifier } => format!(
                "the association of '{action}' with {qualifier} takes no time; only L, D, SD, \
                 DS and SL do"
            ),
        }
    }
}

/// `element 7 'Fill': message` for steps and macro steps, `element 4: message` otherwise, and
/// the bare message for an empty chart: the words of a load error.
impl fmt::Display for SfcProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.kind == SfcProblemKind::EmptyChart {
            return f.write_str(&self.message());
        }
        match &self.step_name {
            Some(name) => write!(f, "element {} '{name}': ", self.element.0)?,
            None => write!(f, "element {}: ", self.element.0)?,
        }
        f.write_str(&self.message())
    }
}
