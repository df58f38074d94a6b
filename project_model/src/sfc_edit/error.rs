//! Why an SFC edit was refused.

use crate::network::ElementId;

/// A structural rule of an SFC chart (the header of `sfc.rs`), named by a refusal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SfcRule {
    /// The main sequence begins with the initial step.
    MainStartsWithStep,
    /// The main sequence ends with a jump, or with an alternative branch whose every branch
    /// ends in one.
    MainEndsWithJump,
    /// After a step (or macro step, or parallel branch) comes a transition or an alternative
    /// branch.
    StepNeedsTransitionAfter,
    /// After a transition (or joined alternative branch) comes a step, a macro step, a
    /// parallel branch or a jump.
    TransitionNeedsStepAfter,
    /// A jump is the last node of its sequence.
    JumpIsLast,
    /// A branch has at least two branches.
    TwoBranches,
    /// A branch of an alternative begins with a transition.
    AlternativeBeginsWithTransition,
    /// A branch of an alternative ends with a transition or a jump.
    AlternativeEndsWithTransitionOrJump,
    /// A branch of a parallel branch begins with a step.
    ParallelBeginsWithStep,
    /// A branch of a parallel branch ends with a step.
    ParallelEndsWithStep,
    /// A macro step's body begins and ends with a step.
    MacroBeginsAndEndsWithStep,
    /// A macro step's body holds no jump.
    NoJumpInMacro,
    /// A sequence holds at least one node.
    SequenceNotEmpty,
    /// Every element has an id of its own.
    UniqueIds,
}

impl SfcRule {
    /// The rule in words, as refusals show it.
    pub fn describe(self) -> &'static str {
        match self {
            Self::MainStartsWithStep => "the chart begins with its initial step",
            Self::MainEndsWithJump => "the main sequence ends with a jump",
            Self::StepNeedsTransitionAfter => "a step needs a transition after it",
            Self::TransitionNeedsStepAfter => "a transition needs a step after it",
            Self::JumpIsLast => "a jump is the last element of its sequence",
            Self::TwoBranches => "a branch has at least two branches",
            Self::AlternativeBeginsWithTransition => {
                "each alternative branch begins with a transition"
            }
            Self::AlternativeEndsWithTransitionOrJump => {
                "each alternative branch ends with a transition or a jump"
            }
            Self::ParallelBeginsWithStep => "each parallel branch begins with a step",
            Self::ParallelEndsWithStep => "each parallel branch ends with a step",
            Self::MacroBeginsAndEndsWithStep => "a macro step begins and ends with a step",
            Self::NoJumpInMacro => "a macro step holds no jump",
            Self::SequenceNotEmpty => "a sequence cannot be empty",
            Self::UniqueIds => "every element has an id of its own",
        }
    }
}

impl std::fmt::Display for SfcRule {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.describe())
    }
}

/// Why an SFC edit did nothing; the chart is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SfcEditError {
    /// The edit would break a structural rule at an element.
    #[error("element {}: {rule}", number(element))]
    Structure {
        /// The rule that would break.
        rule: SfcRule,
        /// The element where it would break (the node or the branch holding the sequence).
        element: ElementId,
    },
    /// Nothing is selected.
    #[error("nothing is selected")]
    EmptySelection,
    /// An element of the selection is not in the chart.
    #[error("element {} is not in the chart", number(.0))]
    NoSuchElement(ElementId),
    /// The edit needs a step (or macro step) and the element is none.
    #[error("element {} is not a step", number(.0))]
    NotAStep(ElementId),
    /// The edit needs a transition and the element is none.
    #[error("element {} is not a transition", number(.0))]
    NotATransition(ElementId),
    /// The edit needs an alternative or parallel branch and the element is none.
    #[error("element {} is not a branch", number(.0))]
    NotABranch(ElementId),
    /// The edit needs a jump and the element is none.
    #[error("element {} is not a jump", number(.0))]
    NotAJump(ElementId),
    /// The selected elements are not one unbroken run of a single sequence.
    #[error("the selected elements are not one run of a sequence")]
    NotARun,
    /// A jump can only be inserted after the last transition of a sequence.
    #[error("element {}: a jump can only follow the last transition of a sequence", number(.0))]
    JumpNotAtEnd(ElementId),
    /// A step's name is not an identifier (or holds `__`).
    #[error("'{0}' is not a valid step name")]
    InvalidName(String),
    /// Another step of the chart already has this name (case-insensitive).
    #[error("a step named '{0}' already exists")]
    DuplicateName(String),
    /// A jump names a step the chart does not have.
    #[error("no step is named '{0}'")]
    UnknownStep(String),
    /// A transition's condition is empty.
    #[error("element {}: a transition needs a condition", number(.0))]
    EmptyCondition(ElementId),
    /// An action association names no action.
    #[error("an action association needs an action")]
    EmptyAction,
    /// A timed qualifier (L, D, SD, DS, SL) has no time.
    #[error("qualifier {0} needs a time")]
    MissingDuration(&'static str),
    /// A qualifier without time (N, R, S, P, P0, P1) was given one.
    #[error("qualifier {0} takes no time")]
    UnexpectedDuration(&'static str),
    /// The step has no action association at this index.
    #[error("element {}: there is no action association {index}", number(step))]
    NoSuchAssociation {
        /// The step.
        step: ElementId,
        /// The index asked for, from 0.
        index: usize,
    },
    /// The clipboard holds nothing to paste.
    #[error("the clipboard holds no SFC elements")]
    EmptyClipboard,
}

/// An element's number as messages write it.
fn number(id: &ElementId) -> u32 {
    id.0
}
