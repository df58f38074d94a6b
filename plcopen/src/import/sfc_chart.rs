//! An SFC graph → a structured [`SfcChart`] (docs/plcopen-xml.md §4.1–4.3): the main sequence
//! from the initial step, divergences and their convergences as branches that open and close
//! in pairs, a loop back to a step as a jump.

use std::collections::{HashMap, HashSet};

use project_model::{ElementId, MacroStep, SfcBranches, SfcChart, SfcNode};

use super::body_fault::{BodyFault, object_place};
use super::converter::{Place, comment};
use super::error::ImportErrorKind;
use super::pou_objects::PouObjects;
use super::report::{Outcome, ReportEntry};
use super::sfc_nested::NestedBodies;
use crate::body::BodyContent;
use crate::body_object::{BodyObject, ObjectKind};
use crate::connection::ConnectionPointIn;

/// How deep branches may nest (a chain of choices nests one level per choice): the walk
/// recurses per level, and this bounds its stack.
const MAX_BRANCH_DEPTH: usize = 1000;

/// The stack of the thread the walk runs on: room for [`MAX_BRANCH_DEPTH`] levels even in an
/// unoptimised build (about 20 KiB a level there), whatever stack the caller's thread has.
const WALK_STACK_BYTES: usize = 64 << 20;

/// How a sequence walked from an element ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum End {
    /// In a jump (or an alternative whose every branch jumps): nothing follows.
    Closed,
    /// At the convergence with this `localId`, which the caller's divergence closes.
    Joins(u64),
}

/// An element that reads the output of another through its `connectionPointIn`.
#[derive(Clone, Copy, Debug)]
struct Consumer {
    /// Its `localId`.
    local_id: u64,
    /// Where the wire leaves the producer, left to right: the last point of the connection's
    /// polyline, else the consumer's input point, else 0 (CODESYS draws nothing).
    x: f64,
    /// Its place in document order, which breaks ties.
    index: usize,
}

/// One SFC body in conversion.
pub(super) struct SfcChartBuilder<'o, 'p> {
    /// The objects of the body, in document order.
    objects: &'o [BodyObject],
    /// The same objects by `localId`.
    by_local_id: HashMap<u64, &'o BodyObject>,
    /// The elements reading each element's output, in document order.
    consumers: HashMap<u64, Vec<Consumer>>,
    /// The element path of the body.
    pub(super) body_path: String,
    /// Line of the body.
    body_line: u32,
    /// The steps already in the chart, by `localId`, with their names.
    placed_steps: HashMap<u64, String>,
    /// The objects that became part of the chart.
    pub(super) used: HashSet<u64>,
    /// The last element id given out (shared with the bodies of macro steps).
    last_id: u32,
    /// How many divergences the walk is inside.
    depth: usize,
    /// The name of the step walked last, which names synthesized conditions.
    pub(super) last_step: String,
    /// The actions and transition objects the body adds to its POU.
    pub(super) pou_objects: &'p mut PouObjects,
    /// The conversion of the bodies inside this one (inline actions, LD conditions).
    pub(super) bodies: &'p mut dyn NestedBodies,
    /// Report lines about parts of the body (dropped comments, renamed objects, rewrites).
    pub(super) report: Vec<ReportEntry>,
}

impl<'o, 'p> SfcChartBuilder<'o, 'p> {
    /// A builder for the SFC `objects` of the body at `body_path` (line `body_line`), adding
    /// what it synthesizes to `pou_objects` and converting the bodies inside it with `bodies`.
    pub fn new(
        objects: &'o [BodyObject],
        body_path: &str,
        body_line: u32,
        pou_objects: &'p mut PouObjects,
        bodies: &'p mut dyn NestedBodies,
    ) -> Self {
        let by_local_id = objects
            .iter()
            .map(|object| (object.local_id, object))
            .collect();
        let mut consumers: HashMap<u64, Vec<Consumer>> = HashMap::new();
        for (index, object) in objects.iter().enumerate() {
            for point in sequence_inputs(&object.kind) {
                let own_x = object.position.map_or(0.0, |position| position.x)
                    + point.rel_position.map_or(0.0, |rel| rel.x);
                for connection in &point.connections {
                    let x = connection.points.last().map_or(own_x, |point| point.x);
                    consumers
                        .entry(connection.ref_local_id)
                        .or_default()
                        .push(Consumer {
                            local_id: object.local_id,
                            x,
                            index,
                        });
                }
            }
        }
        for list in consumers.values_mut() {
            list.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.index.cmp(&b.index)));
        }
        Self {
            objects,
            by_local_id,
            consumers,
            body_path: body_path.to_owned(),
            body_line,
            placed_steps: HashMap::new(),
            used: HashSet::new(),
            last_id: 0,
            depth: 0,
            last_step: String::new(),
            pou_objects,
            bodies,
            report: Vec::new(),
        }
    }

    /// [`Self::chart`] on a thread of its own with a stack of [`WALK_STACK_BYTES`], as the walk
    /// recurses once per nested branch.
    pub fn chart_on_own_stack(self) -> Result<(SfcChart, Vec<ReportEntry>), BodyFault> {
        let walked = std::thread::scope(|scope| {
            std::thread::Builder::new()
                .name("sfc import".to_owned())
                .stack_size(WALK_STACK_BYTES)
                .spawn_scoped(scope, move || self.chart())
                .map(|handle| handle.join())
        });
        match walked {
            Ok(Ok(result)) => result,
            // A panic in the walk is a bug: it goes on in the caller's thread.
            Ok(Err(panic)) => std::panic::resume_unwind(panic),
            Err(error) => Err(BodyFault::NotConverted(format!(
                "no thread could be started for the walk of the chart: {error}"
            ))),
        }
    }

    /// The chart, from the one step marked `initialStep`.
    pub fn chart(mut self) -> Result<(SfcChart, Vec<ReportEntry>), BodyFault> {
        let initial: Vec<&BodyObject> = self
            .objects
            .iter()
            .filter(|object| matches!(&object.kind, ObjectKind::Step(step) if step.initial))
            .collect();
        let first = match initial.as_slice() {
            [] => {
                return Err(self.body_error(
                    "no step is marked `initialStep`; a chart begins at its initial step",
                ));
            }
            [first] => first.local_id,
            [first, second, ..] => {
                return Err(BodyFault::Error(
                    self.place(second),
                    ImportErrorKind::BadSfc(format!(
                        "the steps `{}` and `{}` are both marked `initialStep`; Rivet's chart has one initial step",
                        step_name(first),
                        step_name(second)
                    )),
                ));
            }
        };
        let mut sequence = Vec::new();
        if let End::Joins(convergence) = self.sequence(first, &mut sequence, false)? {
            return Err(self.error_at(convergence, "this convergence closes no divergence"));
        }
        self.leftovers()?;
        let chart = SfcChart { sequence };
        let problems = project_model::sfc_problems(&chart);
        if !problems.is_empty() {
            return Err(self.body_error(&format!(
                "the chart made of this body breaks Rivet's rules: {}",
                problems.join("; ")
            )));
        }
        Ok((chart, self.report))
    }

    /// The objects no sequence reached: a step is an error (it would be lost), comments and
    /// other objects are reported not converted.
    fn leftovers(&mut self) -> Result<(), BodyFault> {
        for object in self.objects {
            if self.used.contains(&object.local_id) {
                continue;
            }
            let place = self.place(object);
            match &object.kind {
                ObjectKind::Step(step) => {
                    return Err(BodyFault::Error(
                        place,
                        ImportErrorKind::BadSfc(format!(
                            "the step `{}` cannot be reached from the initial step",
                            step.name
                        )),
                    ));
                }
                ObjectKind::Comment(text) => self.report.push(ReportEntry {
                    outcome: Outcome::NotConverted,
                    what: format!("comment '{}'", first_line(&text.text)),
                    path: place.path,
                    line: place.line,
                    note: "an SFC chart has no free comments".to_owned(),
                }),
                other => self.report.push(ReportEntry {
                    outcome: Outcome::NotConverted,
                    what: format!("{} (localId {})", other.element_name(), object.local_id),
                    path: place.path,
                    line: place.line,
                    note: "it is not part of the sequence or of a transition's condition"
                        .to_owned(),
                }),
            }
        }
        Ok(())
    }

    /// Walks the sequence from `current` into `nodes`, up to a jump or a convergence.
    fn sequence(
        &mut self,
        mut current: u64,
        nodes: &mut Vec<SfcNode>,
        in_macro: bool,
    ) -> Result<End, BodyFault> {
        loop {
            let object = self.object(current)?;
            match &object.kind {
                ObjectKind::Step(step) => {
                    if let Some(name) = self.placed_steps.get(&current) {
                        // A transition back to a step already in the chart is a jump to it.
                        let name = name.clone();
                        nodes.push(SfcNode::jump(self.fresh_id(), name));
                        return Ok(End::Closed);
                    }
                    self.used.insert(current);
                    self.placed_steps.insert(current, step.name.clone());
                    self.last_step = step.name.clone();
                    let converted = self.step(object, &step.name)?;
                    nodes.push(SfcNode::Step(converted));
                    match self.next_of(object)? {
                        Some(next) => current = next,
                        None if in_macro => return Ok(End::Closed),
                        None => {
                            // A last step stays active for good: a transition that never
                            // fires and a jump back to the step say exactly that.
                            nodes.push(SfcNode::transition(self.fresh_id(), "FALSE"));
                            nodes.push(SfcNode::jump(self.fresh_id(), step.name.clone()));
                            self.note(
                                object,
                                format!("step '{}'", step.name),
                                "nothing follows the step; it ends in the transition FALSE and a jump back to itself",
                            );
                            return Ok(End::Closed);
                        }
                    }
                }
                ObjectKind::MacroStep(macro_step) => {
                    if let Some(name) = self.placed_steps.get(&current) {
                        let name = name.clone();
                        nodes.push(SfcNode::jump(self.fresh_id(), name));
                        return Ok(End::Closed);
                    }
                    let name = macro_step.name.clone().unwrap_or_default();
                    if name.trim().is_empty() {
                        return Err(self.error_at(current, "a macroStep needs a name"));
                    }
                    self.used.insert(current);
                    self.placed_steps.insert(current, name.clone());
                    let id = self.fresh_id();
                    let body = self.macro_body(object, macro_step.body.as_deref())?;
                    nodes.push(SfcNode::Macro(MacroStep {
                        id,
                        name,
                        comment: comment(object.documentation.as_ref()),
                        body,
                    }));
                    match self.next_of(object)? {
                        Some(next) => current = next,
                        None => {
                            return Err(self.error_at(current, "nothing follows the macro step"));
                        }
                    }
                }
                ObjectKind::JumpStep(jump) => {
                    self.used.insert(current);
                    nodes.push(SfcNode::jump(self.fresh_id(), jump.target_name.clone()));
                    return Ok(End::Closed);
                }
                ObjectKind::Transition(transition) => {
                    self.used.insert(current);
                    let converted = self.transition(object, transition)?;
                    nodes.push(SfcNode::Transition(converted));
                    match self.next_of(object)? {
                        Some(next) => current = next,
                        None => {
                            return Err(self.error_at(
                                current,
                                "the transition leads nowhere: a step, a jumpStep or a convergence must follow it",
                            ));
                        }
                    }
                }
                ObjectKind::SelectionDivergence(_) | ObjectKind::SimultaneousDivergence(_) => {
                    self.used.insert(current);
                    let parallel = matches!(object.kind, ObjectKind::SimultaneousDivergence(_));
                    let (mut node, joins) = self.branches(object, parallel)?;
                    let Some(convergence) = joins else {
                        // Branches that never join: one may go on without a jump of its own
                        // (Beremiz draws a chain of choices so); it keeps its transition and the
                        // rest follows the alternative, which means the same.
                        let rest = self.open_branch_rest(&mut node, object)?;
                        nodes.push(node);
                        nodes.extend(rest);
                        return Ok(End::Closed);
                    };
                    nodes.push(node);
                    self.used.insert(convergence);
                    let convergence_object = self.object(convergence)?;
                    match self.next_of(convergence_object)? {
                        Some(next) => current = next,
                        None => {
                            return Err(self.error_at(convergence, "the convergence leads nowhere"));
                        }
                    }
                }
                ObjectKind::SelectionConvergence(_) | ObjectKind::SimultaneousConvergence(_) => {
                    return Ok(End::Joins(current));
                }
                other => {
                    let message = format!(
                        "a {} cannot stand in the sequence of steps and transitions",
                        other.element_name()
                    );
                    return Err(self.error_at(current, &message));
                }
            }
        }
    }

    /// The branches of the divergence `object`, and the convergence that closes them (none
    /// when every branch of a selection ends in a jump).
    fn branches(
        &mut self,
        object: &BodyObject,
        parallel: bool,
    ) -> Result<(SfcNode, Option<u64>), BodyFault> {
        if self.depth >= MAX_BRANCH_DEPTH {
            return Err(self.error_at(
                object.local_id,
                &format!("branches nest more than {MAX_BRANCH_DEPTH} deep here"),
            ));
        }
        let id = self.fresh_id();
        let firsts: Vec<u64> = self
            .consumers
            .get(&object.local_id)
            .map(|list| list.iter().map(|consumer| consumer.local_id).collect())
            .unwrap_or_default();
        if firsts.len() < 2 {
            return Err(self.error_at(
                object.local_id,
                &format!(
                    "the divergence has {} branch(es); Rivet's branches come two or more at a time",
                    firsts.len()
                ),
            ));
        }
        let mut branches = Vec::new();
        let mut joins: Option<u64> = None;
        let mut arrivals = 0;
        for first in firsts {
            let mut nodes = Vec::new();
            self.depth += 1;
            let end = self.sequence(first, &mut nodes, false);
            self.depth -= 1;
            match end? {
                End::Closed if parallel => {
                    return Err(self.error_at(
                        object.local_id,
                        "a branch of this simultaneous divergence ends without joining the others",
                    ));
                }
                End::Closed => {}
                End::Joins(convergence) => {
                    if joins.is_some_and(|earlier| earlier != convergence) {
                        return Err(self.error_at(
                            convergence,
                            "this convergence joins branches of different divergences",
                        ));
                    }
                    let expected = if parallel {
                        matches!(
                            self.object(convergence)?.kind,
                            ObjectKind::SimultaneousConvergence(_)
                        )
                    } else {
                        matches!(
                            self.object(convergence)?.kind,
                            ObjectKind::SelectionConvergence(_)
                        )
                    };
                    if !expected {
                        return Err(self.error_at(
                            convergence,
                            "this convergence closes a divergence of the other kind",
                        ));
                    }
                    joins = Some(convergence);
                    arrivals += 1;
                }
            }
            branches.push(nodes);
        }
        if let Some(convergence) = joins {
            let inputs: usize = sequence_inputs(&self.object(convergence)?.kind)
                .iter()
                .map(|point| point.connections.len())
                .sum();
            if inputs != arrivals {
                return Err(self.error_at(
                    convergence,
                    "this convergence joins branches of different divergences",
                ));
            }
        }
        let branches = SfcBranches::new(id, branches);
        let node = if parallel {
            SfcNode::Parallel(branches)
        } else {
            SfcNode::Alternative(branches)
        };
        Ok((node, joins))
    }

    /// The nodes after the first of the one branch of `node` (an alternative none of whose
    /// branches joins) that does not end in a jump, taken out of it; none when every branch
    /// ends in a jump. Two such branches cannot be written in Rivet's chart: an error.
    fn open_branch_rest(
        &self,
        node: &mut SfcNode,
        divergence: &BodyObject,
    ) -> Result<Vec<SfcNode>, BodyFault> {
        let SfcNode::Alternative(branches) = node else {
            return Ok(Vec::new());
        };
        let open: Vec<usize> = branches
            .branches
            .iter()
            .enumerate()
            .filter(|(_, branch)| !matches!(branch.nodes.last(), Some(SfcNode::Jump(_))))
            .map(|(index, _)| index)
            .collect();
        match open.as_slice() {
            [] => Ok(Vec::new()),
            [index] => Ok(branches.branches[*index].nodes.split_off(1)),
            _ => Err(self.error_at(
                divergence.local_id,
                "several branches of this selection divergence go on without joining again or jumping; Rivet's chart can continue after one of them only",
            )),
        }
    }

    /// The sequence inside a macro step: from its step without input to the step nothing
    /// follows.
    fn macro_body(
        &mut self,
        object: &BodyObject,
        body: Option<&crate::body::Body>,
    ) -> Result<Vec<SfcNode>, BodyFault> {
        let objects = match body.map(|body| &body.content) {
            Some(BodyContent::Sfc(objects)) => objects,
            _ => return Err(self.error_at(object.local_id, "a macroStep's body must be SFC")),
        };
        let path = format!(
            "{}/macroStep[@localId='{}']/body/SFC",
            self.body_path, object.local_id
        );
        let mut inner =
            SfcChartBuilder::new(objects, &path, object.line, self.pou_objects, self.bodies);
        inner.last_id = self.last_id;
        inner.depth = self.depth + 1;
        let first = objects.iter().find(|candidate| {
            matches!(&candidate.kind, ObjectKind::Step(step)
                if step.initial || step.input.as_ref().is_none_or(|point| point.connections.is_empty()))
        });
        let Some(first) = first else {
            return Err(self.error_at(object.local_id, "the macroStep's body has no first step"));
        };
        let mut nodes = Vec::new();
        inner.sequence(first.local_id, &mut nodes, true)?;
        inner.leftovers()?;
        self.last_id = inner.last_id;
        self.report.append(&mut inner.report);
        Ok(nodes)
    }

    /// The one element of the sequence after `object` (action blocks are not), if any.
    fn next_of(&self, object: &BodyObject) -> Result<Option<u64>, BodyFault> {
        let next: Vec<u64> = self
            .consumers
            .get(&object.local_id)
            .into_iter()
            .flatten()
            .map(|consumer| consumer.local_id)
            .filter(|id| {
                !matches!(
                    self.by_local_id.get(id).map(|o| &o.kind),
                    Some(ObjectKind::ActionBlock(_))
                )
            })
            .collect();
        match next.as_slice() {
            [] => Ok(None),
            [one] => Ok(Some(*one)),
            several => Err(self.error_at(
                object.local_id,
                &format!(
                    "the {} leads to {} elements; branches begin at a divergence",
                    object.kind.element_name(),
                    several.len()
                ),
            )),
        }
    }

    /// The actions blocks attached to the step `local_id`, in order.
    pub(super) fn action_blocks(&self, local_id: u64) -> Vec<&'o BodyObject> {
        self.consumers
            .get(&local_id)
            .into_iter()
            .flatten()
            .filter_map(|consumer| self.by_local_id.get(&consumer.local_id).copied())
            .filter(|object| matches!(object.kind, ObjectKind::ActionBlock(_)))
            .collect()
    }

    /// Every object of the body, in document order.
    pub(super) fn all_objects(&self) -> &'o [BodyObject] {
        self.objects
    }

    /// The object `local_id` of the body.
    pub(super) fn object(&self, local_id: u64) -> Result<&'o BodyObject, BodyFault> {
        self.by_local_id.get(&local_id).copied().ok_or_else(|| {
            self.body_error(&format!(
                "a connection refers to localId {local_id}, which is not in the body"
            ))
        })
    }

    /// A fresh element id, numbered from 1 in the order the walk meets the elements.
    pub(super) fn fresh_id(&mut self) -> ElementId {
        self.last_id += 1;
        ElementId(self.last_id)
    }

    /// The place of `object`.
    pub(super) fn place(&self, object: &BodyObject) -> Place {
        object_place(
            &self.body_path,
            object.kind.element_name(),
            object.local_id,
            object.line,
            object.column,
        )
    }

    /// An error at the object `local_id` (at the body when there is no such object).
    pub(super) fn error_at(&self, local_id: u64, message: &str) -> BodyFault {
        let place = match self.by_local_id.get(&local_id) {
            Some(object) => self.place(object),
            None => self.body_place(),
        };
        BodyFault::Error(place, ImportErrorKind::BadSfc(message.to_owned()))
    }

    fn body_place(&self) -> Place {
        Place {
            path: self.body_path.clone(),
            line: self.body_line,
            column: 1,
        }
    }

    fn body_error(&self, message: &str) -> BodyFault {
        BodyFault::Error(
            self.body_place(),
            ImportErrorKind::BadSfc(message.to_owned()),
        )
    }

    /// Reports that `what` at `object` was converted with a change worth saying.
    pub(super) fn note(&mut self, object: &BodyObject, what: String, note: &str) {
        let place = self.place(object);
        self.report.push(ReportEntry {
            outcome: Outcome::Converted,
            what,
            path: place.path,
            line: place.line,
            note: note.to_owned(),
        });
    }
}

/// The connection points through which an SFC element follows another (conditions and FBD
/// wiring are not part of the sequence).
fn sequence_inputs(kind: &ObjectKind) -> Vec<&ConnectionPointIn> {
    match kind {
        ObjectKind::Step(step) => step.input.iter().collect(),
        ObjectKind::MacroStep(step) => step.input.iter().collect(),
        ObjectKind::JumpStep(step) => step.input.iter().collect(),
        ObjectKind::Transition(transition) => transition.input.iter().collect(),
        ObjectKind::SelectionDivergence(divergence)
        | ObjectKind::SimultaneousDivergence(divergence) => divergence.input.iter().collect(),
        ObjectKind::SelectionConvergence(convergence)
        | ObjectKind::SimultaneousConvergence(convergence) => convergence.inputs.iter().collect(),
        ObjectKind::ActionBlock(block) => block.input.iter().collect(),
        _ => Vec::new(),
    }
}

fn step_name(object: &BodyObject) -> &str {
    match &object.kind {
        ObjectKind::Step(step) => &step.name,
        _ => "",
    }
}

/// The first line of a text, trimmed, for a report's `what`.
fn first_line(text: &str) -> &str {
    text.trim().lines().next().unwrap_or("").trim()
}
