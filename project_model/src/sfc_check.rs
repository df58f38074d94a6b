//! The structural rules of an SFC chart (the header of `sfc.rs`), checked on load, on save and
//! by every edit, so that every stored chart has one meaning for the lowering into textual SFC.
//!
//! Names of actions, variables and the text of conditions and times are the compiler's
//! business; this checks the shape of the chart and the names that become step names.

use std::collections::HashMap;

use crate::{ElementId, SfcChart, SfcNode, is_valid_identifier, same_identifier};

/// Where a sequence is, which decides what may come first in it and how it must end.
#[derive(Clone, Copy, PartialEq, Eq)]
enum SequenceKind {
    /// The main sequence: the initial step first, a jump (or jumping branches) last.
    Main,
    /// A branch of an alternative: a transition first, a transition or a jump last.
    Alternative,
    /// A branch of a parallel branch: a step first and a step last.
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
    let mut checker = Checker::default();
    checker.collect_steps(&chart.sequence);
    if chart.sequence.is_empty() {
        checker
            .problems
            .push("the chart is empty; it must begin with its initial step".into());
        return checker.problems;
    }
    checker.sequence(&chart.sequence, SequenceKind::Main, false);
    checker.problems
}

#[derive(Default)]
struct Checker {
    problems: Vec<String>,
    /// Every id met so far.
    ids: HashMap<ElementId, ()>,
    /// Every step and macro step name of the chart, for the jumps.
    steps: Vec<String>,
}

/// How messages name a node: `element 7 'Fill'` for named nodes, `element 4` otherwise.
fn label(node: &SfcNode) -> String {
    match node {
        SfcNode::Step(step) => format!("element {} '{}'", step.id.0, step.name),
        SfcNode::Macro(macro_step) => format!("element {} '{}'", macro_step.id.0, macro_step.name),
        _ => format!("element {}", node.id().0),
    }
}

/// What a node is, in the words of a message.
fn what(node: &SfcNode) -> &'static str {
    match node {
        SfcNode::Step(_) => "a step",
        SfcNode::Transition(_) => "a transition",
        SfcNode::Alternative(_) => "an alternative branch",
        SfcNode::Parallel(_) => "a parallel branch",
        SfcNode::Jump(_) => "a jump",
        SfcNode::Macro(_) => "a macro step",
    }
}

impl Checker {
    fn report(&mut self, node: &SfcNode, message: impl std::fmt::Display) {
        self.problems.push(format!("{}: {message}", label(node)));
    }

    /// Gathers the step names first, so a jump may name a step that comes after it.
    fn collect_steps(&mut self, nodes: &[SfcNode]) {
        for node in nodes {
            match node {
                SfcNode::Step(step) => self.steps.push(step.name.clone()),
                SfcNode::Macro(macro_step) => {
                    self.steps.push(macro_step.name.clone());
                    self.collect_steps(&macro_step.body);
                }
                SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                    for branch in &branches.branches {
                        self.collect_steps(&branch.nodes);
                    }
                }
                SfcNode::Transition(_) | SfcNode::Jump(_) => {}
            }
        }
    }

    /// Checks one sequence of `kind`; `in_macro` forbids jumps. Returns what it leaves open.
    fn sequence(&mut self, nodes: &[SfcNode], kind: SequenceKind, in_macro: bool) -> Open {
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
            let before = self.problems.len();
            match kind {
                SequenceKind::Main if !matches!(first, SfcNode::Step(_)) => {
                    self.report(
                        first,
                        format!(
                            "the chart must begin with its initial step, not {}",
                            what(first)
                        ),
                    );
                }
                SequenceKind::Alternative if !matches!(first, SfcNode::Transition(_)) => {
                    self.report(
                        first,
                        format!(
                            "a branch of an alternative must begin with a transition, not {}",
                            what(first)
                        ),
                    );
                }
                SequenceKind::Parallel | SequenceKind::Macro
                    if !matches!(first, SfcNode::Step(_) | SfcNode::Macro(_)) =>
                {
                    let place = if kind == SequenceKind::Macro {
                        "the body of a macro step"
                    } else {
                        "a branch of a parallel branch"
                    };
                    self.report(
                        first,
                        format!("{place} must begin with a step, not {}", what(first)),
                    );
                }
                _ => {}
            }
            reported_order = self.problems.len() > before;
        }
        for node in nodes {
            self.node_itself(node, in_macro);
            let allowed = match (open, node) {
                (Open::Closed, _) => false,
                (Open::AfterStep, SfcNode::Transition(_) | SfcNode::Alternative(_)) => true,
                (
                    Open::AfterTransition,
                    SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_) | SfcNode::Jump(_),
                ) => true,
                _ => false,
            };
            if !allowed && !reported_order {
                reported_order = true;
                let message = match open {
                    Open::Closed => "nothing may follow a jump in its sequence".to_owned(),
                    Open::AfterStep => format!(
                        "{} cannot follow a step; a transition or an alternative branch must",
                        what(node)
                    ),
                    Open::AfterTransition => format!(
                        "{} cannot follow a transition; a step, a macro step, a parallel \
                         branch or a jump must",
                        what(node)
                    ),
                };
                self.report(node, message);
            }
            open = self.inside(node, in_macro);
        }
        let Some(last) = nodes.last().filter(|_| !reported_order) else {
            return open;
        };
        match kind {
            SequenceKind::Main if open != Open::Closed => self.report(
                last,
                "the chart must end with a jump (or an alternative branch whose every branch \
                 ends with a jump)",
            ),
            SequenceKind::Alternative if open == Open::AfterStep => self.report(
                last,
                "a branch of an alternative must end with a transition or a jump",
            ),
            SequenceKind::Parallel | SequenceKind::Macro if open != Open::AfterStep => {
                let place = if kind == SequenceKind::Macro {
                    "the body of a macro step"
                } else {
                    "a branch of a parallel branch"
                };
                self.report(last, format!("{place} must end with a step"));
            }
            _ => {}
        }
        open
    }

    /// Checks the rules of a node by itself: its id, its name, its associations, its target.
    fn node_itself(&mut self, node: &SfcNode, in_macro: bool) {
        let id = node.id();
        if self.ids.insert(id, ()).is_some() {
            self.report(node, format!("two elements have the id {}", id.0));
        }
        match node {
            SfcNode::Step(step) => {
                self.name(node, &step.name);
                for association in &step.actions {
                    let action = &association.action;
                    if action.trim().is_empty() {
                        self.report(node, "an action association names no action");
                    }
                    let qualifier = association.qualifier.as_str();
                    match (association.qualifier.is_timed(), &association.duration) {
                        (true, None) => self.report(
                            node,
                            format!("the association of '{action}' with {qualifier} needs a time"),
                        ),
                        (true, Some(time)) if time.trim().is_empty() => self.report(
                            node,
                            format!("the association of '{action}' with {qualifier} needs a time"),
                        ),
                        (false, Some(_)) => self.report(
                            node,
                            format!(
                                "the association of '{action}' with {qualifier} takes no time; \
                                 only L, D, SD, DS and SL do"
                            ),
                        ),
                        _ => {}
                    }
                }
            }
            SfcNode::Macro(macro_step) => self.name(node, &macro_step.name),
            SfcNode::Jump(jump) => {
                if in_macro {
                    self.report(node, "a macro step's body cannot hold a jump");
                }
                if !self
                    .steps
                    .iter()
                    .any(|step| same_identifier(step, &jump.target))
                {
                    self.report(
                        node,
                        format!(
                            "the jump names the step '{}', which does not exist",
                            jump.target
                        ),
                    );
                }
            }
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                if branches.branches.len() < 2 {
                    self.report(
                        node,
                        format!(
                            "{} needs at least two branches; it has {}",
                            what(node),
                            branches.branches.len()
                        ),
                    );
                }
                if let Some(empty) = branches.branches.iter().position(|b| b.nodes.is_empty()) {
                    self.report(node, format!("branch {} is empty", empty + 1));
                }
            }
            SfcNode::Transition(_) => {}
        }
    }

    /// Checks a step or macro name: an identifier without `__`, unique without case.
    fn name(&mut self, node: &SfcNode, name: &str) {
        if !is_valid_identifier(name) {
            self.report(
                node,
                format!("the step name '{name}' is not an identifier (letters, digits and '_')"),
            );
        } else if name.contains("__") {
            self.report(
                node,
                format!("the step name '{name}' contains '__', which Rivet keeps for itself"),
            );
        }
        let count = self
            .steps
            .iter()
            .filter(|step| same_identifier(step, name))
            .count();
        if count > 1 {
            self.report(node, format!("{count} steps are named '{name}'"));
        }
    }

    /// Checks what a node holds (branches, a macro's body) and returns what it leaves open.
    fn inside(&mut self, node: &SfcNode, in_macro: bool) -> Open {
        match node {
            SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_) => {
                if let SfcNode::Macro(macro_step) = node {
                    if macro_step.body.is_empty() {
                        self.report(node, "the body of a macro step must begin with a step");
                    }
                    self.sequence(&macro_step.body, SequenceKind::Macro, true);
                }
                if let SfcNode::Parallel(branches) = node {
                    for branch in &branches.branches {
                        self.sequence(&branch.nodes, SequenceKind::Parallel, in_macro);
                    }
                }
                Open::AfterStep
            }
            SfcNode::Transition(_) => Open::AfterTransition,
            SfcNode::Jump(_) => Open::Closed,
            SfcNode::Alternative(branches) => {
                let mut joined = false;
                for branch in &branches.branches {
                    let end = self.sequence(&branch.nodes, SequenceKind::Alternative, in_macro);
                    joined |= end != Open::Closed;
                }
                if joined || branches.branches.is_empty() {
                    Open::AfterTransition
                } else {
                    Open::Closed
                }
            }
        }
    }
}

#[cfg(test)]
#[path = "sfc_check_tests.rs"]
mod tests;
