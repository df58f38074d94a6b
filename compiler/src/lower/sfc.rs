//! SFC charts lowered into textual SFC (`docs/sfc-semantics.md`; the rules of the lowering are
//! in `docs/graphical-semantics.md`, "SFC charts").
//!
//! The chart's structure is flattened into steps and the transitions between them: a step
//! becomes `STEP Name (properties): associations END_STEP` (the first step of the chart
//! `INITIAL_STEP`), a transition `TRANSITION FROM sources TO targets := condition;
//! END_TRANSITION` whose sources are the steps before it (all last steps of a parallel branch
//! it closes) and whose targets are the steps after it (all first steps of a parallel branch
//! it opens, the step a jump names). The transitions of an alternative branch leave the step
//! before it in left-to-right order, so text order is the order they are tested in.
//!
//! A macro step has no text and no state of its own: its body's steps are steps of the chart,
//! entered through its first step and left from its last, so the macro is active exactly while
//! one of its steps is (what the editor shows from its steps' `x`).

use std::collections::HashMap;

use project_model::{
    ElementId, SfcChart, SfcNode, Step, Transition, VarSection, Variable, is_valid_identifier,
};

use super::fragment::{Fragment, frag};
use super::{Probe, ProbeKind};

/// The lowering of one SFC body: its text, hidden variables and probes.
pub(crate) struct ChartLowering<'c> {
    /// The prefix of every hidden name of this body (`__` or `__Reset__`).
    prefix: String,
    /// The POU's transition objects, by name: a condition naming one calls it.
    transition_objects: &'c [String],
    /// The generated text.
    pub out: Fragment,
    /// The hidden variables, declared in the POU.
    pub hidden: Vec<Variable>,
    /// Each hidden name with the words a message uses for it.
    pub descriptions: Vec<(String, String)>,
    /// Where each step's and transition's live value is read.
    pub probes: Vec<Probe>,
    /// The steps, in the order the chart is walked.
    steps: Vec<&'c Step>,
    /// The transitions, in the order the chart is walked, with their sources and targets.
    transitions: Vec<Flat<'c>>,
    /// Steps and transitions in the order of the text.
    order: Vec<Item>,
    /// The priority each transition of an alternative branch is given, when one of the
    /// branches has one.
    priorities: HashMap<ElementId, u32>,
    /// The step a jump to each step or macro name (lower case) enters.
    entries: HashMap<String, String>,
}

/// A transition with the steps it leads from and to.
struct Flat<'c> {
    transition: &'c Transition,
    from: Vec<String>,
    to: Vec<String>,
}

/// A step or transition, by its index, in the order of the text.
#[derive(Clone, Copy)]
enum Item {
    Step(usize),
    Transition(usize),
}

/// What the nodes walked so far leave open for the next node.
#[derive(Clone)]
enum Open {
    /// The steps the next transitions leave from.
    Sources(Vec<String>),
    /// The transitions (by index) the next step completes.
    Pending(Vec<usize>),
    /// Nothing: a jump ended the sequence.
    Closed,
}

impl<'c> ChartLowering<'c> {
    /// A lowering of a chart whose hidden names start with `prefix`, in a POU with the
    /// transition objects `transition_objects`.
    pub fn new(prefix: String, transition_objects: &'c [String]) -> Self {
        Self {
            prefix,
            transition_objects,
            out: Fragment::default(),
            hidden: Vec::new(),
            descriptions: Vec::new(),
            probes: Vec::new(),
            steps: Vec::new(),
            transitions: Vec::new(),
            order: Vec::new(),
            priorities: HashMap::new(),
            entries: HashMap::new(),
        }
    }

    /// Lowers `chart`, which keeps the rules of `project_model::sfc_problems`.
    pub fn chart(&mut self, chart: &'c SfcChart) {
        self.collect_entries(&chart.sequence);
        self.walk(&chart.sequence, Open::Pending(Vec::new()));
        let mut shadows = Fragment::default();
        for (index, item) in self.order.clone().into_iter().enumerate() {
            match item {
                Item::Step(step) => {
                    let text = self.step(self.steps[step], index == 0);
                    self.out.push(text);
                }
                Item::Transition(transition) => {
                    let (text, shadow) = self.transition(transition);
                    self.out.push(text);
                    if let Some(shadow) = shadow {
                        shadows.push(shadow);
                    }
                }
            }
        }
        self.out.push(shadows);
    }

    /// Records which step a jump to each step or macro step enters.
    fn collect_entries(&mut self, nodes: &[SfcNode]) {
        for node in nodes {
            match node {
                SfcNode::Step(step) => {
                    self.entries
                        .insert(step.name.to_lowercase(), step.name.clone());
                }
                SfcNode::Macro(macro_step) => {
                    self.collect_entries(&macro_step.body);
                    if let Some(entry) = macro_step
                        .body
                        .first()
                        .and_then(|first| self.entry_of(first))
                    {
                        self.entries.insert(macro_step.name.to_lowercase(), entry);
                    }
                }
                SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                    for branch in &branches.branches {
                        self.collect_entries(&branch.nodes);
                    }
                }
                SfcNode::Transition(_) | SfcNode::Jump(_) => {}
            }
        }
    }

    /// The step a node that begins a sequence enters by.
    fn entry_of(&self, node: &SfcNode) -> Option<String> {
        match node {
            SfcNode::Step(step) => Some(step.name.clone()),
            SfcNode::Macro(macro_step) => {
                self.entries.get(&macro_step.name.to_lowercase()).cloned()
            }
            _ => None,
        }
    }

    /// Walks a sequence from what `open` leaves open, recording its steps and transitions.
    fn walk(&mut self, nodes: &'c [SfcNode], mut open: Open) -> Open {
        for node in nodes {
            open = match node {
                SfcNode::Step(step) => {
                    if let Open::Pending(pending) = &open {
                        for &at in pending {
                            self.transitions[at].to.push(step.name.clone());
                        }
                    }
                    self.order.push(Item::Step(self.steps.len()));
                    self.steps.push(step);
                    Open::Sources(vec![step.name.clone()])
                }
                SfcNode::Macro(macro_step) => self.walk(&macro_step.body, open),
                SfcNode::Transition(transition) => {
                    let from = match open {
                        Open::Sources(sources) => sources,
                        Open::Pending(_) | Open::Closed => Vec::new(),
                    };
                    self.order.push(Item::Transition(self.transitions.len()));
                    self.transitions.push(Flat {
                        transition,
                        from,
                        to: Vec::new(),
                    });
                    Open::Pending(vec![self.transitions.len() - 1])
                }
                SfcNode::Alternative(branches) => {
                    self.prioritise(branches);
                    let mut pending = Vec::new();
                    let mut joined = false;
                    for branch in &branches.branches {
                        if let Open::Pending(mut more) = self.walk(&branch.nodes, open.clone()) {
                            joined = true;
                            pending.append(&mut more);
                        }
                    }
                    if joined {
                        Open::Pending(pending)
                    } else {
                        Open::Closed
                    }
                }
                SfcNode::Parallel(branches) => {
                    let mut sources = Vec::new();
                    for branch in &branches.branches {
                        if let Open::Sources(mut last) = self.walk(&branch.nodes, open.clone()) {
                            sources.append(&mut last);
                        }
                    }
                    Open::Sources(sources)
                }
                SfcNode::Jump(jump) => {
                    if let Open::Pending(pending) = &open {
                        let entry = self
                            .entries
                            .get(&jump.target.to_lowercase())
                            .cloned()
                            .unwrap_or_else(|| jump.target.clone());
                        for &at in pending {
                            self.transitions[at].to.push(entry.clone());
                        }
                    }
                    Open::Closed
                }
            };
        }
        open
    }

    /// Gives every transition that opens a branch of `branches` a priority when one of them
    /// has one: those with one keep it, the others follow them in left-to-right order, as the
    /// model says (`Transition::priority`).
    fn prioritise(&mut self, branches: &project_model::SfcBranches) {
        let firsts: Vec<&Transition> = branches
            .branches
            .iter()
            .filter_map(|branch| match branch.nodes.first() {
                Some(SfcNode::Transition(transition)) => Some(transition),
                _ => None,
            })
            .collect();
        let Some(highest) = firsts.iter().filter_map(|t| t.priority).max() else {
            return;
        };
        let mut next = highest;
        for transition in firsts {
            let priority = transition.priority.unwrap_or_else(|| {
                next = next.saturating_add(1);
                next
            });
            self.priorities.insert(transition.id, priority);
        }
    }

    /// The text of a step, with its probes.
    fn step(&mut self, step: &Step, initial: bool) -> Fragment {
        let keyword = if initial { "INITIAL_STEP" } else { "STEP" };
        let mut head = frag!(keyword, " ", step.name.as_str());
        let properties = [
            ("MIN_TIME", "min_time", &step.min_time),
            ("MAX_TIME", "max_time", &step.max_time),
            ("ENTRY", "entry_action", &step.entry_action),
            ("MAIN", "main_action", &step.main_action),
            ("EXIT", "exit_action", &step.exit_action),
        ];
        let mut first = true;
        for (keyword, field, value) in properties {
            let Some(value) = value else { continue };
            head.push_str(if first { " (" } else { ", " });
            first = false;
            head.push(frag!(
                keyword,
                " := ",
                Fragment::plain(value.trim()).mark_user(0, step.id, Some(field))
            ));
        }
        if !first {
            head.push_str(")");
        }
        let mut text = frag!(head, ":\n");
        for association in &step.actions {
            let mut line = frag!("    ", association.action.trim(), "(");
            line.push_str(association.qualifier.as_str());
            if let Some(duration) = &association.duration {
                line.push_str(", ");
                line.push_str(duration.trim());
            }
            if let Some(indicator) = &association.indicator {
                line.push_str(", ");
                line.push_str(indicator.trim());
            }
            line.push_str(");");
            text.push(line.mark(0, Some(step.id), None));
            text.push_str("\n");
        }
        text.push_str("END_STEP");
        let text = frag!(text.mark(0, Some(step.id), None), "\n");
        self.probes.push(Probe {
            network: 0,
            element: step.id,
            pin: None,
            kind: ProbeKind::Power,
            path: format!("{}.x", step.name),
        });
        self.probes.push(Probe {
            network: 0,
            element: step.id,
            pin: Some("t".into()),
            kind: ProbeKind::Value,
            path: format!("{}.t", step.name),
        });
        text
    }

    /// The text of a transition and, when its condition is an expression, the statement that
    /// keeps its value in a hidden BOOL for the probe; with the transition's probe.
    fn transition(&mut self, at: usize) -> (Fragment, Option<Fragment>) {
        let flat = &self.transitions[at];
        let transition = flat.transition;
        let steps = |names: &[String]| match names {
            [one] => one.clone(),
            many => format!("({})", many.join(", ")),
        };
        let (from, to) = (steps(&flat.from), steps(&flat.to));
        let condition = transition.condition.trim();
        let object = self
            .transition_objects
            .iter()
            .find(|name| name.eq_ignore_ascii_case(condition))
            .cloned();
        let mut text = Fragment::plain("TRANSITION ");
        if let Some(priority) = transition
            .priority
            .or_else(|| self.priorities.get(&transition.id).copied())
        {
            text.push_str(&format!("(PRIORITY := {priority}) "));
        }
        text.push_str(&format!("FROM {from} TO {to} := "));
        let written = match &object {
            Some(name) => format!("{name}()"),
            None => condition.to_owned(),
        };
        text.push(Fragment::plain(written.as_str()).mark_user(0, transition.id, None));
        // A line comment in the condition would swallow the semicolon.
        text.push_str(if written.contains("//") { "\n;" } else { ";" });
        text.push_str(" END_TRANSITION");
        let text = frag!(text.mark(0, Some(transition.id), None), "\n");
        let (path, shadow) = match object {
            Some(name) => {
                let result = transition_result(&name);
                if !self.hidden.iter().any(|v| v.name == result) {
                    self.hidden.push(Variable {
                        name: result.clone(),
                        section: VarSection::Var,
                        ty: "BOOL".into(),
                        ..Variable::default()
                    });
                    self.descriptions.push((
                        result.clone(),
                        format!("the last value of transition '{name}'"),
                    ));
                }
                (result, None)
            }
            None if is_path(condition) => (condition.to_owned(), None),
            None => {
                let name = format!("{}t{}", self.prefix, transition.id.0);
                self.hidden.push(Variable {
                    name: name.clone(),
                    section: VarSection::Var,
                    ty: "BOOL".into(),
                    ..Variable::default()
                });
                self.descriptions.push((
                    name.clone(),
                    format!("the condition of transition {}", transition.id.0),
                ));
                let shadow =
                    frag!(name.as_str(), " := ", condition, ";").mark_shadow(0, transition.id);
                (name, Some(frag!(shadow, "\n")))
            }
        };
        self.probes.push(Probe {
            network: 0,
            element: transition.id,
            pin: None,
            kind: ProbeKind::Power,
            path,
        });
        (text, shadow)
    }
}

/// The hidden variable of a POU that keeps the last result of its transition object `name`,
/// which the method the object compiles into writes.
pub(crate) fn transition_result(name: &str) -> String {
    format!("__{name}__result")
}

/// Whether `text` is a variable's path (`xStart`, `Fill.x`, `fb.Q`), which a probe reads as
/// it is.
fn is_path(text: &str) -> bool {
    let literal = text.eq_ignore_ascii_case("TRUE") || text.eq_ignore_ascii_case("FALSE");
    !literal && text.split('.').all(is_valid_identifier)
}

#[cfg(test)]
#[path = "sfc_tests.rs"]
mod tests;
