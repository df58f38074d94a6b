//! Deleting the selection: a step with its transition as a pair, a branch, a jump, or a run,
//! refused with the rule it would break when nothing around it can go with it.

use super::error::SfcEditError;
use super::insert::{checked, run_of};
use super::walk::{Place, locate, sequence_mut};
use crate::network::ElementId;
use crate::sfc::{SfcChart, SfcNode};

/// Deletes the selected nodes. Each unbroken run of the selection goes as it is if the chart
/// stays valid, else together with the node after it (a step with its transition, a
/// transition with its step), else with the node before it (the last step of a parallel
/// branch with its transition). A branch left empty is removed, and a branch left with one
/// branch is dissolved into its sequence. When no choice keeps the chart valid, the refusal
/// names the rule that breaks.
pub fn delete_nodes(chart: &SfcChart, selection: &[ElementId]) -> Result<SfcChart, SfcEditError> {
    if selection.is_empty() {
        return Err(SfcEditError::EmptySelection);
    }
    for &id in selection {
        if locate(&chart.sequence, id).is_none() {
            return Err(SfcEditError::NoSuchElement(id));
        }
    }
    let mut current = chart.clone();
    for run in runs(chart, selection) {
        let present: Vec<ElementId> = run
            .into_iter()
            .filter(|&id| locate(&current.sequence, id).is_some())
            .collect();
        if present.is_empty() {
            continue;
        }
        let (place, length) = run_of(&current, &present)?;
        current = delete_run(&current, &place, length, present[0])?;
    }
    Ok(current)
}

/// The selection as unbroken runs of single sequences, leaving out what lies inside a selected
/// branch or macro step (it goes with it).
fn runs(chart: &SfcChart, selection: &[ElementId]) -> Vec<Vec<ElementId>> {
    let places: Vec<(ElementId, Place)> = selection
        .iter()
        .filter_map(|&id| locate(&chart.sequence, id).map(|place| (id, place)))
        .collect();
    let outermost: Vec<&(ElementId, Place)> = places
        .iter()
        .filter(|(_, place)| {
            !places.iter().any(|(_, other)| {
                other.path.len() < place.path.len()
                    && place.path[..other.path.len()] == other.path[..]
                    && place.path[other.path.len()].0 == other.index
            })
        })
        .collect();
    let mut sorted = outermost;
    sorted.sort_by(|a, b| (&a.1.path, a.1.index).cmp(&(&b.1.path, b.1.index)));
    sorted.dedup_by(|a, b| a.0 == b.0);
    let mut runs: Vec<Vec<ElementId>> = Vec::new();
    let mut last: Option<&Place> = None;
    for (id, place) in sorted {
        let continues =
            last.is_some_and(|last| last.path == place.path && last.index + 1 == place.index);
        match runs.last_mut() {
            Some(run) if continues => run.push(*id),
            _ => runs.push(vec![*id]),
        }
        last = Some(place);
    }
    runs
}

fn delete_run(
    chart: &SfcChart,
    place: &Place,
    length: usize,
    first: ElementId,
) -> Result<SfcChart, SfcEditError> {
    let start = place.index;
    let end = start + length;
    let mut candidates = vec![(start, end), (start, end + 1)];
    if start > 0 {
        candidates.push((start - 1, end));
    }
    let mut first_error = None;
    let mut meaningful_error = None;
    for (from, to) in candidates {
        let mut out = chart.clone();
        let sequence = sequence_mut(&mut out.sequence, &place.path)
            .ok_or(SfcEditError::NoSuchElement(first))?;
        if to > sequence.len() {
            continue;
        }
        sequence.drain(from..to);
        remove_empty_branch(&mut out, &place.path);
        match checked(out) {
            Ok(chart) => return Ok(chart),
            Err(error) => {
                if !matches!(error, SfcEditError::Structure { .. }) {
                    meaningful_error.get_or_insert(error.clone());
                }
                first_error.get_or_insert(error);
            }
        }
    }
    Err(meaningful_error
        .or(first_error)
        .unwrap_or(SfcEditError::NoSuchElement(first)))
}

/// Removes the branch at the end of `path` if it was left empty, and dissolves its branch into
/// the enclosing sequence if only one branch is left.
fn remove_empty_branch(chart: &mut SfcChart, path: &[(usize, Option<usize>)]) {
    let Some(((node_index, Some(branch_index)), parent_path)) = path.split_last() else {
        return;
    };
    let Some(parent) = sequence_mut(&mut chart.sequence, parent_path) else {
        return;
    };
    let Some(SfcNode::Alternative(branches) | SfcNode::Parallel(branches)) =
        parent.get_mut(*node_index)
    else {
        return;
    };
    if !branches
        .branches
        .get(*branch_index)
        .is_some_and(|branch| branch.nodes.is_empty())
    {
        return;
    }
    branches.branches.remove(*branch_index);
    if branches.branches.len() == 1 {
        let remaining = branches.branches.remove(0).nodes;
        parent.splice(*node_index..node_index + 1, remaining);
    }
}
