//! Finding nodes of an SFC chart: where a node is, the chart's highest id and its step names.

use crate::identifier::same_identifier;
use crate::network::ElementId;
use crate::sfc::{SfcChart, SfcNode};

/// One step down from a sequence into a nested one: the node's index, and for a branch the
/// branch's index (`None` for a macro step's body).
pub(super) type Descent = (usize, Option<usize>);

/// Where a node is: the descents from the main sequence to the sequence holding it, and its
/// index there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Place {
    /// The descents to the node's sequence, outermost first.
    pub path: Vec<Descent>,
    /// The node's index in that sequence.
    pub index: usize,
}

/// Calls `visit` on every node of `nodes`, nested ones included, outer nodes first.
pub(super) fn visit_nodes<'a>(nodes: &'a [SfcNode], visit: &mut impl FnMut(&'a SfcNode)) {
    for node in nodes {
        visit(node);
        match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                for branch in &branches.branches {
                    visit_nodes(&branch.nodes, visit);
                }
            }
            SfcNode::Macro(macro_step) => visit_nodes(&macro_step.body, visit),
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
}

/// Calls `visit` on every node of `nodes` mutably, nested ones included.
pub(super) fn visit_nodes_mut(nodes: &mut [SfcNode], visit: &mut impl FnMut(&mut SfcNode)) {
    for node in nodes {
        visit(node);
        match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                for branch in &mut branches.branches {
                    visit_nodes_mut(&mut branch.nodes, visit);
                }
            }
            SfcNode::Macro(macro_step) => visit_nodes_mut(&mut macro_step.body, visit),
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
}

/// The highest element id of `chart` (0 for an empty chart); new elements count on from it.
pub fn max_sfc_id(chart: &SfcChart) -> u32 {
    let mut max = 0;
    visit_nodes(&chart.sequence, &mut |node| max = max.max(node.id().0));
    max
}

/// The names of every step and macro step of `chart`, in the order they appear.
pub fn step_names(chart: &SfcChart) -> Vec<String> {
    let mut names = Vec::new();
    visit_nodes(&chart.sequence, &mut |node| match node {
        SfcNode::Step(step) => names.push(step.name.clone()),
        SfcNode::Macro(macro_step) => names.push(macro_step.name.clone()),
        _ => {}
    });
    names
}

/// The node `id` of `chart`, wherever it is nested.
pub fn find_node(chart: &SfcChart, id: ElementId) -> Option<&SfcNode> {
    let mut found = None;
    visit_nodes(&chart.sequence, &mut |node| {
        if node.id() == id && found.is_none() {
            found = Some(node);
        }
    });
    found
}

/// Where the node `id` is in `nodes`.
pub(super) fn locate(nodes: &[SfcNode], id: ElementId) -> Option<Place> {
    for (index, node) in nodes.iter().enumerate() {
        if node.id() == id {
            return Some(Place {
                path: Vec::new(),
                index,
            });
        }
        let inner = match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => branches
                .branches
                .iter()
                .enumerate()
                .find_map(|(b, branch)| locate(&branch.nodes, id).map(|place| (Some(b), place))),
            SfcNode::Macro(macro_step) => locate(&macro_step.body, id).map(|place| (None, place)),
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => None,
        };
        if let Some((branch, mut place)) = inner {
            place.path.insert(0, (index, branch));
            return Some(place);
        }
    }
    None
}

/// The sequence reached from `nodes` along `path`, if the path is still valid.
pub(super) fn sequence_mut<'a>(
    nodes: &'a mut Vec<SfcNode>,
    path: &[Descent],
) -> Option<&'a mut Vec<SfcNode>> {
    let Some(((index, branch), rest)) = path.split_first() else {
        return Some(nodes);
    };
    let inner = match (nodes.get_mut(*index)?, branch) {
        (SfcNode::Alternative(branches) | SfcNode::Parallel(branches), Some(b)) => {
            &mut branches.branches.get_mut(*b)?.nodes
        }
        (SfcNode::Macro(macro_step), None) => &mut macro_step.body,
        _ => return None,
    };
    sequence_mut(inner, rest)
}

/// The node `id` of `nodes`, mutably.
pub(super) fn node_mut(nodes: &mut Vec<SfcNode>, id: ElementId) -> Option<&mut SfcNode> {
    let place = locate(nodes, id)?;
    sequence_mut(nodes, &place.path)?.get_mut(place.index)
}

/// Hands out the ids after a chart's highest one.
pub(super) struct IdSource {
    next: u32,
}

impl IdSource {
    /// Ids after the highest one of `chart`.
    pub fn after(chart: &SfcChart) -> Self {
        Self {
            next: max_sfc_id(chart) + 1,
        }
    }

    /// The next free id.
    pub fn take(&mut self) -> ElementId {
        let id = ElementId(self.next);
        self.next += 1;
        id
    }
}

/// The names taken in a chart, growing as an edit names new steps.
pub(super) struct StepNames {
    taken: Vec<String>,
}

impl StepNames {
    /// The step names of `chart`.
    pub fn of(chart: &SfcChart) -> Self {
        Self {
            taken: step_names(chart),
        }
    }

    /// Whether `name` is taken, case-insensitively.
    pub fn contains(&self, name: &str) -> bool {
        self.taken.iter().any(|taken| same_identifier(taken, name))
    }

    /// The first free name `<base><n>` from `n` = 1, taken from now on.
    pub fn fresh(&mut self, base: &str) -> String {
        let name = (1..)
            .map(|n| format!("{base}{n}"))
            .find(|candidate| !self.contains(candidate))
            .unwrap_or_else(|| base.to_owned());
        self.taken.push(name.clone());
        name
    }
}
