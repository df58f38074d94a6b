//! Inserting steps, transitions, branches, jumps and macro steps at the selection.

use super::error::{SfcEditError, SfcRule};
use super::shape::check_structure;
use super::walk::{IdSource, Place, StepNames, locate, sequence_mut};
use crate::network::ElementId;
use crate::sfc::{MacroStep, SfcBranches, SfcChart, SfcNode, SfcSequence};

/// The condition of a new transition: it never fires until the user writes one.
const NEW_CONDITION: &str = "FALSE";

/// Checks `chart` and hands it back as the edit's result.
pub(super) fn checked(chart: SfcChart) -> Result<SfcChart, SfcEditError> {
    check_structure(&chart)?;
    Ok(chart)
}

/// A new step named after the chart's free names.
pub(super) fn new_step(ids: &mut IdSource, names: &mut StepNames) -> SfcNode {
    SfcNode::step(ids.take(), names.fresh("Step"))
}

/// A new transition that never fires.
pub(super) fn new_transition(ids: &mut IdSource) -> SfcNode {
    SfcNode::transition(ids.take(), NEW_CONDITION)
}

/// Where the selection `ids` lies: one unbroken run of a single sequence, as its place (at the
/// run's first node) and its length.
pub(super) fn run_of(chart: &SfcChart, ids: &[ElementId]) -> Result<(Place, usize), SfcEditError> {
    let Some(&first) = ids.first() else {
        return Err(SfcEditError::EmptySelection);
    };
    let first_place = locate(&chart.sequence, first).ok_or(SfcEditError::NoSuchElement(first))?;
    let mut indices = Vec::with_capacity(ids.len());
    for &id in ids {
        let place = locate(&chart.sequence, id).ok_or(SfcEditError::NoSuchElement(id))?;
        if place.path != first_place.path {
            return Err(SfcEditError::NotARun);
        }
        indices.push(place.index);
    }
    indices.sort_unstable();
    indices.dedup();
    let start = indices[0];
    if indices
        .iter()
        .enumerate()
        .any(|(k, &index)| index != start + k)
    {
        return Err(SfcEditError::NotARun);
    }
    Ok((
        Place {
            path: first_place.path,
            index: start,
        },
        indices.len(),
    ))
}

/// The chart's copy, the place of node `id` and the sequence holding it, for an edit there.
fn sequence_of(chart: &SfcChart, id: ElementId) -> Result<(SfcChart, Place), SfcEditError> {
    let place = locate(&chart.sequence, id).ok_or(SfcEditError::NoSuchElement(id))?;
    Ok((chart.clone(), place))
}

/// The sequence at `place` in `chart`; the place was just located, so it exists.
pub(super) fn sequence_at<'a>(
    chart: &'a mut SfcChart,
    place: &Place,
    id: ElementId,
) -> Result<&'a mut Vec<SfcNode>, SfcEditError> {
    sequence_mut(&mut chart.sequence, &place.path).ok_or(SfcEditError::NoSuchElement(id))
}

/// Inserts a step and a transition after node `id` (CODESYS's "Insert step-transition
/// (after)"): after a step, macro step or parallel branch the transition comes first, after a
/// transition or alternative branch the step.
pub fn insert_step_transition_after(
    chart: &SfcChart,
    id: ElementId,
) -> Result<SfcChart, SfcEditError> {
    insert_pair(chart, id, PairAt::After, new_step)
}

/// Inserts a step and a transition before node `id`; before the initial step the new step
/// becomes the initial one.
pub fn insert_step_transition_before(
    chart: &SfcChart,
    id: ElementId,
) -> Result<SfcChart, SfcEditError> {
    insert_pair(chart, id, PairAt::Before, new_step)
}

/// Inserts a macro step (holding one step) and a transition after node `id`, as
/// [`insert_step_transition_after`] does with a step.
pub fn insert_macro_step_after(chart: &SfcChart, id: ElementId) -> Result<SfcChart, SfcEditError> {
    insert_pair(chart, id, PairAt::After, |ids, names| {
        let macro_id = ids.take();
        let name = names.fresh("Macro");
        let body = vec![new_step(ids, names)];
        SfcNode::Macro(MacroStep {
            id: macro_id,
            name,
            comment: String::new(),
            body,
        })
    })
}

/// Which side of the selected node a pair goes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum PairAt {
    Before,
    After,
}

fn insert_pair(
    chart: &SfcChart,
    id: ElementId,
    side: PairAt,
    make_step: impl FnOnce(&mut IdSource, &mut StepNames) -> SfcNode,
) -> Result<SfcChart, SfcEditError> {
    let (mut chart_out, place) = sequence_of(chart, id)?;
    let mut ids = IdSource::after(chart);
    let mut names = StepNames::of(chart);
    let sequence = sequence_at(&mut chart_out, &place, id)?;
    let node = &sequence[place.index];
    if side == PairAt::After && matches!(node, SfcNode::Jump(_)) {
        return Err(SfcEditError::Structure {
            rule: SfcRule::JumpIsLast,
            element: id,
        });
    }
    let ends_like_step = matches!(
        node,
        SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_)
    );
    let begins_like_step = ends_like_step || matches!(node, SfcNode::Jump(_));
    let step = make_step(&mut ids, &mut names);
    let transition = new_transition(&mut ids);
    let (at, pair) = match side {
        PairAt::After if ends_like_step => (place.index + 1, [transition, step]),
        PairAt::After => (place.index + 1, [step, transition]),
        PairAt::Before if begins_like_step => (place.index, [step, transition]),
        PairAt::Before => (place.index, [transition, step]),
    };
    sequence.splice(at..at, pair);
    checked(chart_out)
}

/// Wraps the selected run (beginning with a transition) into an alternative branch whose new
/// right branch is one transition.
pub fn insert_alternative_branch(
    chart: &SfcChart,
    selection: &[ElementId],
) -> Result<SfcChart, SfcEditError> {
    wrap_run(chart, selection, |first, ids, _| {
        if !matches!(first, SfcNode::Transition(_) | SfcNode::Alternative(_)) {
            return Err(SfcEditError::NotATransition(first.id()));
        }
        Ok(Wrapper::Alternative(vec![new_transition(ids)]))
    })
}

/// Wraps the selected run (beginning with a step) into a parallel branch whose new right
/// branch is one step.
pub fn insert_parallel_branch(
    chart: &SfcChart,
    selection: &[ElementId],
) -> Result<SfcChart, SfcEditError> {
    wrap_run(chart, selection, |first, ids, names| {
        if !matches!(
            first,
            SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_)
        ) {
            return Err(SfcEditError::NotAStep(first.id()));
        }
        Ok(Wrapper::Parallel(vec![new_step(ids, names)]))
    })
}

/// Wraps the selected run of steps and transitions (beginning and ending with a step) into a
/// new macro step.
pub fn wrap_in_macro(chart: &SfcChart, selection: &[ElementId]) -> Result<SfcChart, SfcEditError> {
    wrap_run(chart, selection, |first, _, names| {
        if !matches!(first, SfcNode::Step(_)) {
            return Err(SfcEditError::NotAStep(first.id()));
        }
        Ok(Wrapper::Macro(names.fresh("Macro")))
    })
}

/// What a selected run is wrapped into.
enum Wrapper {
    /// An alternative branch with this new right branch.
    Alternative(Vec<SfcNode>),
    /// A parallel branch with this new right branch.
    Parallel(Vec<SfcNode>),
    /// A macro step of this name.
    Macro(String),
}

fn wrap_run(
    chart: &SfcChart,
    selection: &[ElementId],
    wrapper: impl FnOnce(&SfcNode, &mut IdSource, &mut StepNames) -> Result<Wrapper, SfcEditError>,
) -> Result<SfcChart, SfcEditError> {
    let (place, length) = run_of(chart, selection)?;
    let mut out = chart.clone();
    let mut ids = IdSource::after(chart);
    let mut names = StepNames::of(chart);
    let sequence = sequence_at(&mut out, &place, selection[0])?;
    let wrapper_id = ids.take();
    let wrapper = wrapper(&sequence[place.index], &mut ids, &mut names)?;
    let run: Vec<SfcNode> = sequence.drain(place.index..place.index + length).collect();
    let node = match wrapper {
        Wrapper::Alternative(right) => {
            SfcNode::Alternative(SfcBranches::new(wrapper_id, vec![run, right]))
        }
        Wrapper::Parallel(right) => {
            SfcNode::Parallel(SfcBranches::new(wrapper_id, vec![run, right]))
        }
        Wrapper::Macro(name) => SfcNode::Macro(MacroStep {
            id: wrapper_id,
            name,
            comment: String::new(),
            body: run,
        }),
    };
    sequence.insert(place.index, node);
    checked(out)
}

/// Adds a branch at the right of the alternative or parallel branch `id`: a transition for an
/// alternative, a step for a parallel branch.
pub fn add_branch(chart: &SfcChart, id: ElementId) -> Result<SfcChart, SfcEditError> {
    let (mut out, place) = sequence_of(chart, id)?;
    let mut ids = IdSource::after(chart);
    let mut names = StepNames::of(chart);
    let sequence = sequence_at(&mut out, &place, id)?;
    match &mut sequence[place.index] {
        SfcNode::Alternative(branches) => branches.branches.push(SfcSequence {
            nodes: vec![new_transition(&mut ids)],
        }),
        SfcNode::Parallel(branches) => branches.branches.push(SfcSequence {
            nodes: vec![new_step(&mut ids, &mut names)],
        }),
        _ => return Err(SfcEditError::NotABranch(id)),
    }
    checked(out)
}

/// Appends a jump to step `target` after transition `id`, which must end its sequence (a
/// branch of an alternative).
pub fn insert_jump_after(
    chart: &SfcChart,
    id: ElementId,
    target: &str,
) -> Result<SfcChart, SfcEditError> {
    let (mut out, place) = sequence_of(chart, id)?;
    let jump_id = IdSource::after(chart).take();
    let sequence = sequence_at(&mut out, &place, id)?;
    if !matches!(sequence[place.index], SfcNode::Transition(_)) {
        return Err(SfcEditError::NotATransition(id));
    }
    if place.index + 1 != sequence.len() {
        return Err(SfcEditError::JumpNotAtEnd(id));
    }
    sequence.push(SfcNode::jump(jump_id, target.trim()));
    checked(out)
}
