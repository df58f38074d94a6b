//! SFC charts of format versions 1 and 2 (steps, transitions, divergences, convergences and
//! step jumps joined by connections) turned into the structured [`SfcChart`].
//!
//! The graph is walked from its initial step along its connections: a step or transition
//! leads to the one element it is connected to; a divergence opens one branch per element it
//! leads to, left to right by position, and every branch that does not end in a jump must meet
//! the others again at one convergence of the same kind, after which the sequence goes on. A
//! connection back to a step already walked becomes a jump to it. Elements keep their ids; a
//! jump made from a connection takes an id above the chart's largest.
//!
//! Whatever has no structured equivalent is an error naming the element: a second initial
//! step, an element that leads to two others without a divergence, branches that meet at no
//! common convergence, an element the initial step does not reach, and what the structured
//! chart's own rules refuse (`sfc_check.rs`).

use std::collections::{HashMap, HashSet};

use super::graph_chart::{BranchKind, Chart, ChartElement, ChartElementKind};
use crate::{ElementId, SfcBranches, SfcChart, SfcNode, SfcSequence, Step, sfc_problems};

/// How deeply divergences may nest, so that no file can exhaust the stack of the walk.
const MAX_NESTING: usize = 64;

/// Converts the graph of an SFC body into the structured chart, or says which elements break
/// the structure.
pub(crate) fn sfc_from_graph(graph: &Chart) -> Result<SfcChart, Vec<String>> {
    let mut walk = Walk::new(graph)?;
    let initial = walk.initial()?;
    let (sequence, end) = walk.sequence(initial, 0).map_err(|problem| vec![problem])?;
    if let End::Converged(convergence) = end {
        return Err(vec![format!(
            "element {}: the convergence closes branches that no divergence opened",
            convergence.0
        )]);
    }
    let unreached: Vec<String> = graph
        .elements
        .iter()
        .filter(|element| !walk.visited.contains(&element.id))
        .filter(|element| !matches!(element.kind, ChartElementKind::Comment { .. }))
        .map(|element| {
            format!(
                "element {}: the initial step does not lead to it, so it has no place in the \
                 converted chart",
                element.id.0
            )
        })
        .collect();
    if !unreached.is_empty() {
        return Err(unreached);
    }
    let chart = SfcChart { sequence };
    let problems = sfc_problems(&chart);
    if problems.is_empty() {
        Ok(chart)
    } else {
        Err(problems)
    }
}

/// How a walked sequence ends.
enum End {
    /// At a jump (or branches that all jump): nothing follows.
    Closed,
    /// At the convergence with this id, which the caller closes.
    Converged(ElementId),
}

struct Walk<'g> {
    elements: HashMap<ElementId, &'g ChartElement>,
    /// What each element leads to, left to right by position.
    next: HashMap<ElementId, Vec<ElementId>>,
    /// Every element walked so far.
    visited: HashSet<ElementId>,
    /// The id the next jump made from a connection takes.
    next_id: u32,
}

impl<'g> Walk<'g> {
    fn new(graph: &'g Chart) -> Result<Self, Vec<String>> {
        let elements: HashMap<ElementId, &ChartElement> =
            graph.elements.iter().map(|e| (e.id, e)).collect();
        let mut problems = Vec::new();
        for element in &graph.elements {
            let foreign = !matches!(
                element.kind,
                ChartElementKind::Step { .. }
                    | ChartElementKind::Transition { .. }
                    | ChartElementKind::Divergence { .. }
                    | ChartElementKind::Convergence { .. }
                    | ChartElementKind::StepJump { .. }
                    | ChartElementKind::Comment { .. }
            );
            if foreign {
                problems.push(format!(
                    "element {}: only steps, transitions, divergences, convergences, jumps and \
                     comments can be part of an SFC chart",
                    element.id.0
                ));
            }
        }
        let mut next: HashMap<ElementId, Vec<ElementId>> = HashMap::new();
        for connection in &graph.connections {
            let (from, to) = (connection.from.element, connection.to.element);
            if !elements.contains_key(&to) {
                problems.push(format!(
                    "element {}: a connection leads to element {}, which does not exist",
                    from.0, to.0
                ));
            }
            if !elements.contains_key(&from) {
                problems.push(format!(
                    "element {}: a connection comes from element {}, which does not exist",
                    to.0, from.0
                ));
            }
            let targets = next.entry(from).or_default();
            if !targets.contains(&to) {
                targets.push(to);
            }
        }
        if !problems.is_empty() {
            return Err(problems);
        }
        for targets in next.values_mut() {
            targets.sort_by_key(|id| elements.get(id).map(|e| (e.x, e.y, id.0)));
        }
        let next_id = graph.elements.iter().map(|e| e.id.0).max().unwrap_or(0) + 1;
        Ok(Self {
            elements,
            next,
            visited: HashSet::new(),
            next_id,
        })
    }

    /// The one initial step.
    fn initial(&self) -> Result<ElementId, Vec<String>> {
        let mut initial: Vec<&ChartElement> = self
            .elements
            .values()
            .copied()
            .filter(|e| matches!(e.kind, ChartElementKind::Step { initial: true, .. }))
            .collect();
        initial.sort_by_key(|e| e.id.0);
        match initial.as_slice() {
            [one] => Ok(one.id),
            [] => Err(vec!["the chart has no initial step".into()]),
            [_, second, ..] => Err(vec![format!(
                "element {}: a second initial step; an SFC chart has one",
                second.id.0
            )]),
        }
    }

    /// What `id` leads to, which must be exactly one element.
    fn single_next(&self, id: ElementId) -> Result<Option<ElementId>, String> {
        match self.next.get(&id).map(Vec::as_slice).unwrap_or_default() {
            [] => Ok(None),
            [one] => Ok(Some(*one)),
            _ => Err(format!(
                "element {}: it leads to several elements without a divergence",
                id.0
            )),
        }
    }

    /// Walks the sequence that begins at `start` until a jump or a convergence.
    fn sequence(&mut self, start: ElementId, depth: usize) -> Result<(Vec<SfcNode>, End), String> {
        if depth > MAX_NESTING {
            return Err(format!(
                "element {}: the branches nest more than {MAX_NESTING} levels deep",
                start.0
            ));
        }
        let mut nodes = Vec::new();
        let mut current = Some(start);
        while let Some(id) = current {
            let Some(element) = self.elements.get(&id).copied() else {
                return Err(format!("element {}: it does not exist", id.0));
            };
            if self.visited.contains(&id) {
                // A connection back to a step already walked is a jump to it.
                if let ChartElementKind::Step { name, .. } = &element.kind {
                    nodes.push(SfcNode::jump(ElementId(self.next_id), name.clone()));
                    self.next_id += 1;
                    return Ok((nodes, End::Closed));
                }
                if !matches!(element.kind, ChartElementKind::Convergence { .. }) {
                    return Err(format!(
                        "element {}: it is reached from two places without a convergence",
                        id.0
                    ));
                }
            }
            self.visited.insert(id);
            current = match &element.kind {
                ChartElementKind::Step {
                    name,
                    entry_action,
                    exit_action,
                    actions,
                    ..
                } => {
                    nodes.push(SfcNode::Step(Step {
                        id,
                        name: name.clone(),
                        entry_action: entry_action.clone(),
                        exit_action: exit_action.clone(),
                        actions: actions.clone(),
                        ..Step::default()
                    }));
                    let next = self.single_next(id)?;
                    if next.is_none() {
                        return Err(format!(
                            "element {}: the step '{name}' leads nowhere; a sequence ends with a \
                             jump",
                            id.0
                        ));
                    }
                    next
                }
                ChartElementKind::Transition { condition } => {
                    nodes.push(SfcNode::transition(id, condition.clone()));
                    let next = self.single_next(id)?;
                    if next.is_none() {
                        return Err(format!(
                            "element {}: the transition leads nowhere; a transition leads to a \
                             step or a jump",
                            id.0
                        ));
                    }
                    next
                }
                ChartElementKind::StepJump { target } => {
                    nodes.push(SfcNode::jump(id, target.clone()));
                    return Ok((nodes, End::Closed));
                }
                ChartElementKind::Convergence { .. } => return Ok((nodes, End::Converged(id))),
                ChartElementKind::Divergence { branch, .. } => {
                    match self.divergence(id, *branch, depth)? {
                        (node, Some(after)) => {
                            nodes.push(node);
                            self.single_next(after)?
                        }
                        (node, None) => {
                            nodes.push(node);
                            return Ok((nodes, End::Closed));
                        }
                    }
                }
                _ => {
                    return Err(format!(
                        "element {}: it cannot be part of an SFC chart",
                        id.0
                    ));
                }
            };
        }
        Err(format!(
            "element {}: the sequence ends without a jump",
            start.0
        ))
    }

    /// Walks the branches of the divergence `id` and returns the branch node with the
    /// convergence they meet at, or `None` when every branch jumps.
    fn divergence(
        &mut self,
        id: ElementId,
        kind: BranchKind,
        depth: usize,
    ) -> Result<(SfcNode, Option<ElementId>), String> {
        let starts = self.next.get(&id).cloned().unwrap_or_default();
        let mut branches = Vec::new();
        let mut meet: Option<ElementId> = None;
        for start in starts {
            let (nodes, end) = self.sequence(start, depth + 1)?;
            if let End::Converged(convergence) = end {
                match meet {
                    Some(other) if other != convergence => {
                        return Err(format!(
                            "element {}: its branches meet at two convergences ({} and {})",
                            id.0, other.0, convergence.0
                        ));
                    }
                    _ => meet = Some(convergence),
                }
            } else if kind == BranchKind::Simultaneous {
                return Err(format!(
                    "element {}: a parallel branch cannot end with a jump",
                    id.0
                ));
            }
            branches.push(SfcSequence { nodes });
        }
        if let Some(convergence) = meet {
            let same_kind = matches!(
                self.elements.get(&convergence).map(|e| &e.kind),
                Some(ChartElementKind::Convergence { branch, .. }) if *branch == kind
            );
            if !same_kind {
                return Err(format!(
                    "element {}: the convergence is not of the kind of divergence {}",
                    convergence.0, id.0
                ));
            }
        }
        let branches = SfcBranches { id, branches };
        let node = match kind {
            BranchKind::Selection => SfcNode::Alternative(branches),
            BranchKind::Simultaneous => SfcNode::Parallel(branches),
        };
        Ok((node, meet))
    }
}

#[cfg(test)]
#[path = "older_sfc_tests.rs"]
mod tests;
