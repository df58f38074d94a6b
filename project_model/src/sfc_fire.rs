//! The steps a transition of an SFC chart leads from and to, so a transition can be fired by
//! hand: the steps before it are deactivated and the steps after it activated (writing each
//! step's `_x`, `docs/sfc-semantics.md`). A macro step has no state of its own: it is entered
//! through its body's first step and left from its body's last.

use crate::network::ElementId;
use crate::sfc::{SfcChart, SfcNode};

/// The steps a transition leads from and to, by name as the chart writes them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TransitionSteps {
    /// The steps that are active when the transition can fire (all of them after a parallel
    /// branch converges).
    pub before: Vec<String>,
    /// The steps that become active when it fires (each branch's first step before a parallel
    /// branch diverges, a jump's target).
    pub after: Vec<String>,
}

/// The steps the transition `id` of `chart` leads from and to; `None` when no transition of
/// the chart has this id.
pub fn transition_steps(chart: &SfcChart, id: ElementId) -> Option<TransitionSteps> {
    let mut frames = Vec::new();
    if !locate(&chart.sequence, id, &mut frames) {
        return None;
    }
    let (nodes, index) = *frames.last()?;
    if !matches!(nodes.get(index), Some(SfcNode::Transition(_))) {
        return None;
    }
    Some(TransitionSteps {
        before: before(&frames),
        after: after(chart, &frames),
    })
}

/// One level of the path to a node: the sequence and the node's index in it.
type Frame<'c> = (&'c [SfcNode], usize);

/// Fills `frames` with the path from `nodes` to the node `id`; `false` when it is not there.
fn locate<'c>(nodes: &'c [SfcNode], id: ElementId, frames: &mut Vec<Frame<'c>>) -> bool {
    for (index, node) in nodes.iter().enumerate() {
        frames.push((nodes, index));
        let found = match node {
            SfcNode::Step(step) => step.id == id,
            SfcNode::Transition(transition) => transition.id == id,
            SfcNode::Jump(jump) => jump.id == id,
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                branches.id == id
                    || branches
                        .branches
                        .iter()
                        .any(|branch| locate(&branch.nodes, id, frames))
            }
            SfcNode::Macro(macro_step) => {
                macro_step.id == id || locate(&macro_step.body, id, frames)
            }
        };
        if found {
            return true;
        }
        frames.pop();
    }
    false
}

/// The steps active before the node at the end of `frames`: those ending the node before it,
/// or, for the first node of an alternative branch, those before the branch.
fn before(frames: &[Frame<'_>]) -> Vec<String> {
    let Some(((nodes, index), outer)) = frames.split_last() else {
        return Vec::new();
    };
    match index
        .checked_sub(1)
        .and_then(|previous| nodes.get(previous))
    {
        Some(previous) => last_steps(previous),
        None => before(outer),
    }
}

/// The steps entered after the node at the end of `frames`: those beginning the node after
/// it, or, for the last node of a branch, those after the branch.
fn after(chart: &SfcChart, frames: &[Frame<'_>]) -> Vec<String> {
    let Some(((nodes, index), outer)) = frames.split_last() else {
        return Vec::new();
    };
    match nodes.get(index + 1) {
        Some(next) => first_steps(chart, next),
        None => after(chart, outer),
    }
}

/// The steps that end `node`: itself for a step, every branch's last step for a parallel
/// branch, a macro's last step.
fn last_steps(node: &SfcNode) -> Vec<String> {
    match node {
        SfcNode::Step(step) => vec![step.name.clone()],
        SfcNode::Parallel(branches) | SfcNode::Alternative(branches) => branches
            .branches
            .iter()
            .filter_map(|branch| branch.nodes.last())
            .flat_map(last_steps)
            .collect(),
        SfcNode::Macro(macro_step) => macro_step.body.last().map(last_steps).unwrap_or_default(),
        SfcNode::Transition(_) | SfcNode::Jump(_) => Vec::new(),
    }
}

/// The steps that begin `node`: itself for a step, every branch's first step for a parallel
/// branch, a macro's first step, the step a jump enters.
fn first_steps(chart: &SfcChart, node: &SfcNode) -> Vec<String> {
    match node {
        SfcNode::Step(step) => vec![step.name.clone()],
        SfcNode::Parallel(branches) | SfcNode::Alternative(branches) => branches
            .branches
            .iter()
            .filter_map(|branch| branch.nodes.first())
            .flat_map(|first| first_steps(chart, first))
            .collect(),
        SfcNode::Macro(macro_step) => macro_step
            .body
            .first()
            .map(|first| first_steps(chart, first))
            .unwrap_or_default(),
        SfcNode::Jump(jump) => named(&chart.sequence, &jump.target)
            .map(|target| first_steps(chart, target))
            .unwrap_or_default(),
        SfcNode::Transition(_) => Vec::new(),
    }
}

/// The step or macro step named `name` (without case) anywhere in `nodes`.
fn named<'c>(nodes: &'c [SfcNode], name: &str) -> Option<&'c SfcNode> {
    nodes.iter().find_map(|node| match node {
        SfcNode::Step(step) if step.name.eq_ignore_ascii_case(name) => Some(node),
        SfcNode::Macro(macro_step) if macro_step.name.eq_ignore_ascii_case(name) => Some(node),
        SfcNode::Macro(macro_step) => named(&macro_step.body, name),
        SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => branches
            .branches
            .iter()
            .find_map(|branch| named(&branch.nodes, name)),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sfc::{Jump, SfcBranches, SfcSequence, Step, Transition};
    use crate::{Body, Object};

    fn pack_cycle() -> SfcChart {
        let project = crate::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        match project.application.object("PackCycle") {
            Some(Object::Pou(pou)) => match &pou.body {
                Body::Sfc { chart } => chart.clone(),
                other => panic!("PackCycle is not SFC: {other:?}"),
            },
            other => panic!("no PackCycle: {other:?}"),
        }
    }

    fn steps(names: &[&str]) -> Vec<String> {
        names.iter().map(|name| (*name).to_owned()).collect()
    }

    #[test]
    fn a_transition_into_a_parallel_branch_enters_every_branch() {
        let found = transition_steps(&pack_cycle(), ElementId(2)).expect("transition 2");
        assert_eq!(found.before, steps(&["Wait"]));
        assert_eq!(found.after, steps(&["Glue", "Position"]));
    }

    #[test]
    fn a_transition_after_a_parallel_branch_leaves_every_branch() {
        let found = transition_steps(&pack_cycle(), ElementId(8)).expect("transition 8");
        assert_eq!(found.before, steps(&["Glued", "Position"]));
        assert_eq!(found.after, steps(&["Cut"]));
    }

    #[test]
    fn a_transition_inside_a_branch_and_before_a_jump() {
        let chart = pack_cycle();
        let inside = transition_steps(&chart, ElementId(5)).expect("transition 5");
        assert_eq!(
            (inside.before, inside.after),
            (steps(&["Glue"]), steps(&["Glued"]))
        );
        let last = transition_steps(&chart, ElementId(10)).expect("transition 10");
        assert_eq!(
            (last.before, last.after),
            (steps(&["Cut"]), steps(&["Wait"]))
        );
    }

    #[test]
    fn an_alternative_branch_begins_after_the_step_before_it() {
        let step = |id, name: &str| {
            SfcNode::Step(Step {
                id: ElementId(id),
                name: name.to_owned(),
                ..Step::default()
            })
        };
        let transition = |id| {
            SfcNode::Transition(Transition {
                id: ElementId(id),
                condition: "TRUE".to_owned(),
                ..Transition::default()
            })
        };
        let jump = |id, target: &str| {
            SfcNode::Jump(Jump {
                id: ElementId(id),
                target: target.to_owned(),
            })
        };
        let chart = SfcChart {
            sequence: vec![
                step(1, "Init"),
                SfcNode::Alternative(SfcBranches {
                    id: ElementId(2),
                    branches: vec![
                        SfcSequence {
                            nodes: vec![transition(3), step(4, "Left"), transition(5)],
                        },
                        SfcSequence {
                            nodes: vec![transition(6), jump(7, "Init")],
                        },
                    ],
                }),
                step(8, "After"),
                transition(9),
                jump(10, "Init"),
            ],
        };
        let left = transition_steps(&chart, ElementId(3)).expect("transition 3");
        assert_eq!(
            (left.before, left.after),
            (steps(&["Init"]), steps(&["Left"]))
        );
        let joined = transition_steps(&chart, ElementId(5)).expect("transition 5");
        assert_eq!(
            (joined.before, joined.after),
            (steps(&["Left"]), steps(&["After"]))
        );
        let back = transition_steps(&chart, ElementId(6)).expect("transition 6");
        assert_eq!(
            (back.before, back.after),
            (steps(&["Init"]), steps(&["Init"]))
        );
        // A step's id names no transition.
        assert_eq!(transition_steps(&chart, ElementId(4)), None);
        assert_eq!(transition_steps(&chart, ElementId(99)), None);
    }
}
