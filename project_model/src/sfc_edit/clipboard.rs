//! Copy and paste of SFC nodes: the copied run keeps its shape, and the pasted one gets fresh
//! ids and unique step names.

use super::error::SfcEditError;
use super::insert::{checked, run_of, sequence_at};
use super::walk::{IdSource, StepNames, locate, visit_nodes_mut};
use crate::identifier::same_identifier;
use crate::network::ElementId;
use crate::sfc::{SfcChart, SfcNode};

/// The selected run of one sequence, as a clipboard holds it.
pub fn copy_nodes(chart: &SfcChart, selection: &[ElementId]) -> Result<Vec<SfcNode>, SfcEditError> {
    let (place, length) = run_of(chart, selection)?;
    let mut out = chart.clone();
    let sequence = sequence_at(&mut out, &place, selection[0])?;
    Ok(sequence[place.index..place.index + length].to_vec())
}

/// Pastes `nodes` after node `id`, with ids after the chart's highest and step names made
/// unique (`Fill` becomes `Fill1`); jumps inside the pasted nodes follow their steps' new
/// names.
pub fn paste_after(
    chart: &SfcChart,
    id: ElementId,
    nodes: &[SfcNode],
) -> Result<SfcChart, SfcEditError> {
    if nodes.is_empty() {
        return Err(SfcEditError::EmptyClipboard);
    }
    let place = locate(&chart.sequence, id).ok_or(SfcEditError::NoSuchElement(id))?;
    let mut ids = IdSource::after(chart);
    let mut names = StepNames::of(chart);
    let mut pasted = nodes.to_vec();
    let mut renamed: Vec<(String, String)> = Vec::new();
    visit_nodes_mut(&mut pasted, &mut |node| {
        let name = match node {
            SfcNode::Step(step) => {
                step.id = ids.take();
                Some(&mut step.name)
            }
            SfcNode::Macro(macro_step) => {
                macro_step.id = ids.take();
                Some(&mut macro_step.name)
            }
            SfcNode::Transition(transition) => {
                transition.id = ids.take();
                None
            }
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                branches.id = ids.take();
                None
            }
            SfcNode::Jump(jump) => {
                jump.id = ids.take();
                None
            }
        };
        if let Some(name) = name {
            let base = name
                .trim_end_matches(|c: char| c.is_ascii_digit())
                .to_owned();
            let fresh = names.fresh(if base.is_empty() { "Step" } else { &base });
            renamed.push((std::mem::replace(name, fresh.clone()), fresh));
        }
    });
    visit_nodes_mut(&mut pasted, &mut |node| {
        if let SfcNode::Jump(jump) = node
            && let Some((_, fresh)) = renamed
                .iter()
                .find(|(old, _)| same_identifier(old, &jump.target))
        {
            jump.target = fresh.clone();
        }
    });
    let mut out = chart.clone();
    let sequence = sequence_at(&mut out, &place, id)?;
    let at = place.index + 1;
    sequence.splice(at..at, pasted);
    checked(out)
}
