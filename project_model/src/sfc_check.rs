//! The structural rules of an SFC chart (the header of `sfc.rs`), checked on load, on save and
//! by every edit, so that every stored chart has one meaning for the lowering into textual SFC.
//!
//! Names of actions, variables and the text of conditions and times are the compiler's
//! business; this checks the shape of the chart and the names that become step names. It is
//! the one implementation of the rules: loading formats its [`SfcProblem`]s as messages, and
//! `sfc_edit::check_structure` refuses an edit with the first of them.

use std::collections::HashSet;

use crate::sfc_edit::{SfcRule, step_names};
use crate::sfc_problem::{SfcNodeKind, SfcProblem, SfcProblemKind};
use crate::{ElementId, SfcChart, SfcNode, is_valid_identifier, same_identifier};

/// Where a sequence is, which decides what may come first in it and how it must end.
#[derive(Clone, Copy, PartialEq, Eq)]
enum SequenceKind {
    /// The main sequence: the initial step first, a jump (or jumping branches) last.
    Main,
    /// A branch of an alternative: a transition first, a transition or a jump last.
    Alternative,
    /// A branch of a parallel branch: a step (or macro step) first and last.
    Parallel,
    /// A macro step's body: a step first and a step last, no jump.
    Macro,
}

/// What the sequence's last node leaves open: what the next node may be.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Open {
    /// After a step, a macro step or a parallel branch: a transition or an alternative.
    AfterStep,
    /// After a transition or a joined alternative: a step, a macro step, a parallel branch
    /// or a jump.
    AfterTransition,
    /// After a jump (or an alternative whose every branch jumps): nothing.
    Closed,
}

/// Every broken rule of `chart`, each as `element 7 'Fill': message`; empty when it is sound.
pub fn sfc_problems(chart: &SfcChart) -> Vec<String> {
    sfc_chart_problems(chart)
        .iter()
        .map(ToString::to_string)
        .collect()
}

/// Every broken rule of `chart`, typed, in the order of the chart: a sequence's own order
/// before what its nodes hold. Empty when the chart is sound.
pub fn sfc_chart_problems(chart: &SfcChart) -> Vec<SfcProblem> {
    // The step names are gathered first, so a jump may name a step that comes after it.
    let mut checker = Checker {
        steps: step_names(chart),
        ..Checker::default()
    };
    if chart.sequence.is_empty() {
        return vec![SfcProblem {
            element: ElementId(0),
            step_name: None,
            node: SfcNodeKind::Step,
            kind: SfcProblemKind::EmptyChart,
        }];
    }
    checker.sequence(&chart.sequence, SequenceKind::Main, false);
    checker.problems
}

/// The problem an edit names when its result breaks a rule: the first of the chart's shape,
/// else of its names, of its jumps, of its associations.
pub(crate) fn first_edit_problem(chart: &SfcChart) -> Option<SfcProblem> {
    sfc_chart_problems(chart)
        .into_iter()
        .min_by_key(SfcProblem::edit_priority)
}

#[derive(Default)]
struct Checker {
    problems: Vec<SfcProblem>,
    /// Every id met so far.
    ids: HashSet<ElementId>,
    /// Every step and macro step name of the chart, for the jumps.
    steps: Vec<String>,
}

/// What `node` leaves open for the node after it.
fn leaves_open(node: &SfcNode) -> Open {
    match node {
        SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_) => Open::AfterStep,
        SfcNode::Transition(_) => Open::AfterTransition,
        SfcNode::Jump(_) => Open::Closed,
        SfcNode::Alternative(branches) => {
            let every_branch_jumps = !branches.branches.is_empty()
                && branches
                    .branches
                    .iter()
                    .all(|branch| matches!(branch.nodes.last(), Some(SfcNode::Jump(_))));
            if every_branch_jumps {
                Open::Closed
            } else {
                Open::AfterTransition
            }
        }
    }
}

impl Checker {
    fn report(&mut self, node: &SfcNode, kind: SfcProblemKind) {
        self.problems.push(SfcProblem::at(node, kind));
    }

    /// Checks one sequence of `kind`, then what its nodes hold; `in_macro` forbids jumps.
    fn sequence(&mut self, nodes: &[SfcNode], kind: SequenceKind, in_macro: bool) {
        let mut open = match kind {
            SequenceKind::Main | SequenceKind::Parallel | SequenceKind::Macro => {
                Open::AfterTransition
            }
            SequenceKind::Alternative => Open::AfterStep,
        };
        // One message a sequence about its order: after the first break, every node (and the
        // sequence's end) would be out of place.
        let mut reported_order = false;
        if let Some(first) = nodes.first() {
            let rule = match kind {
                SequenceKind::Main if !matches!(first, SfcNode::Step(_)) => {
                    Some(SfcRule::MainStartsWithStep)
                }
                SequenceKind::Alternative if !matches!(first, SfcNode::Transition(_)) => {
                    Some(SfcRule::AlternativeBeginsWithTransition)
                }
                SequenceKind::Parallel
                    if !matches!(first, SfcNode::Step(_) | SfcNode::Macro(_)) =>
                {
                    Some(SfcRule::ParallelBeginsWithStep)
                }
                SequenceKind::Macro if !matches!(first, SfcNode::Step(_)) => {
                    Some(SfcRule::MacroBeginsAndEndsWithStep)
                }
                _ => None,
            };
            if let Some(rule) = rule {
                self.report(first, SfcProblemKind::WrongFirst(rule));
                reported_order = true;
            }
        }
        for node in nodes {
            self.node_itself(node, in_macro);
            let rule = match (open, node) {
                (Open::Closed, _) => Some(SfcRule::JumpIsLast),
                (Open::AfterStep, SfcNode::Transition(_) | SfcNode::Alternative(_)) => None,
                (Open::AfterStep, _) => Some(SfcRule::StepNeedsTransitionAfter),
                (
                    Open::AfterTransition,
                    SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_) | SfcNode::Jump(_),
                ) => None,
                (Open::AfterTransition, _) => Some(SfcRule::TransitionNeedsStepAfter),
            };
            if let Some(rule) = rule.filter(|_| !reported_order) {
                reported_order = true;
                self.report(node, SfcProblemKind::OutOfOrder(rule));
            }
            open = leaves_open(node);
        }
        if let Some(last) = nodes.last().filter(|_| !reported_order) {
            let rule = match kind {
                SequenceKind::Main if open != Open::Closed => Some(SfcRule::MainEndsWithJump),
                SequenceKind::Alternative
                    if !matches!(last, SfcNode::Transition(_) | SfcNode::Jump(_)) =>
                {
                    Some(SfcRule::AlternativeEndsWithTransitionOrJump)
                }
                SequenceKind::Parallel if !matches!(last, SfcNode::Step(_) | SfcNode::Macro(_)) => {
                    Some(SfcRule::ParallelEndsWithStep)
                }
                SequenceKind::Macro if !matches!(last, SfcNode::Step(_)) => {
                    Some(SfcRule::MacroBeginsAndEndsWithStep)
                }
                _ => None,
            };
            if let Some(rule) = rule {
                self.report(last, SfcProblemKind::WrongLast(rule));
            }
        }
        for node in nodes {
            self.inside(node, in_macro);
        }
    }

    /// Checks the rules of a node by itself: its id, its name, its associations, its target.
    fn node_itself(&mut self, node: &SfcNode, in_macro: bool) {
        if !self.ids.insert(node.id()) {
            self.report(node, SfcProblemKind::DuplicateId);
        }
        match node {
            SfcNode::Step(step) => {
                self.name(node, &step.name);
                for association in &step.actions {
                    let action = association.action.clone();
                    if action.trim().is_empty() {
                        self.report(node, SfcProblemKind::EmptyAction);
                    }
                    let qualifier = association.qualifier.as_str();
                    let has_time = association
                        .duration
                        .as_ref()
                        .is_some_and(|time| !time.trim().is_empty());
                    match (association.qualifier.is_timed(), has_time) {
                        (true, false) => {
                            self.report(node, SfcProblemKind::MissingDuration { action, qualifier })
                        }
                        (false, _) if association.duration.is_some() => self.report(
                            node,
                            SfcProblemKind::UnexpectedDuration { action, qualifier },
                        ),
                        _ => {}
                    }
                }
            }
            SfcNode::Macro(macro_step) => self.name(node, &macro_step.name),
            SfcNode::Jump(jump) => {
                if in_macro {
                    self.report(node, SfcProblemKind::JumpInMacro);
                }
                if !self
                    .steps
                    .iter()
                    .any(|step| same_identifier(step, &jump.target))
                {
                    self.report(node, SfcProblemKind::UnknownStep(jump.target.clone()));
                }
            }
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                let count = branches.branches.len();
                if count < 2 {
                    self.report(node, SfcProblemKind::TooFewBranches { count });
                }
                if let Some(empty) = branches.branches.iter().position(|b| b.nodes.is_empty()) {
                    self.report(node, SfcProblemKind::EmptyBranch { number: empty + 1 });
                }
            }
            SfcNode::Transition(_) => {}
        }
    }

    /// Checks a step or macro name: an identifier without `__`, unique without case.
    fn name(&mut self, node: &SfcNode, name: &str) {
        if !is_valid_identifier(name) {
            self.report(node, SfcProblemKind::InvalidName(name.to_owned()));
        } else if name.contains("__") {
            self.report(node, SfcProblemKind::ReservedName(name.to_owned()));
        }
        let count = self
            .steps
            .iter()
            .filter(|step| same_identifier(step, name))
            .count();
        if count > 1 {
            self.report(
                node,
                SfcProblemKind::DuplicateName {
                    name: name.to_owned(),
                    count,
                },
            );
        }
    }

    /// Checks the sequences a node holds: its branches, a macro step's body.
    fn inside(&mut self, node: &SfcNode, in_macro: bool) {
        match node {
            SfcNode::Macro(macro_step) => {
                if macro_step.body.is_empty() {
                    self.report(node, SfcProblemKind::EmptyMacroBody);
                }
                self.sequence(&macro_step.body, SequenceKind::Macro, true);
            }
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                let kind = if matches!(node, SfcNode::Alternative(_)) {
                    SequenceKind::Alternative
                } else {
                    SequenceKind::Parallel
                };
                for branch in &branches.branches {
                    self.sequence(&branch.nodes, kind, in_macro);
                }
            }
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
}

#[cfg(test)]
#[path = "sfc_check_tests.rs"]
mod tests;
