//! Edits of one element's texts: step names (with the jumps that target them), conditions,
//! priorities, jump targets, step properties and action associations.

use super::error::SfcEditError;
use super::insert::checked;
use super::walk::{node_mut, step_names, visit_nodes_mut};
use crate::identifier::same_identifier;
use crate::network::ElementId;
use crate::sfc::{ActionAssociation, SfcChart, SfcNode, Step};

/// A step's properties as the properties panel edits them; empty texts are stored as `None`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StepProperties {
    /// The minimum time the step stays active (a TIME constant or variable).
    pub min_time: Option<String>,
    /// The maximum time the step may stay active.
    pub max_time: Option<String>,
    /// The action run once when the step becomes active.
    pub entry_action: Option<String>,
    /// The action run in every cycle the step is active.
    pub main_action: Option<String>,
    /// The action run once after the step was left.
    pub exit_action: Option<String>,
    /// The comment shown beside the step.
    pub comment: String,
}

impl StepProperties {
    /// The properties of `step`.
    pub fn of(step: &Step) -> Self {
        Self {
            min_time: step.min_time.clone(),
            max_time: step.max_time.clone(),
            entry_action: step.entry_action.clone(),
            main_action: step.main_action.clone(),
            exit_action: step.exit_action.clone(),
            comment: step.comment.clone(),
        }
    }
}

/// A text as stored: trimmed, and `None` when nothing is left.
fn optional(text: Option<String>) -> Option<String> {
    text.map(|text| text.trim().to_owned())
        .filter(|text| !text.is_empty())
}

fn step_mut(chart: &mut SfcChart, id: ElementId) -> Result<&mut Step, SfcEditError> {
    match node_mut(&mut chart.sequence, id) {
        Some(SfcNode::Step(step)) => Ok(step),
        Some(_) => Err(SfcEditError::NotAStep(id)),
        None => Err(SfcEditError::NoSuchElement(id)),
    }
}

/// Renames step (or macro step) `id` to `name`, and every jump that targeted it.
pub fn rename_step(chart: &SfcChart, id: ElementId, name: &str) -> Result<SfcChart, SfcEditError> {
    let name = name.trim();
    let mut out = chart.clone();
    let old = match node_mut(&mut out.sequence, id) {
        Some(SfcNode::Step(step)) => std::mem::replace(&mut step.name, name.to_owned()),
        Some(SfcNode::Macro(macro_step)) => {
            std::mem::replace(&mut macro_step.name, name.to_owned())
        }
        Some(_) => return Err(SfcEditError::NotAStep(id)),
        None => return Err(SfcEditError::NoSuchElement(id)),
    };
    if old == name {
        return Ok(out);
    }
    let others = step_names(chart)
        .into_iter()
        .filter(|other| !same_identifier(other, &old))
        .any(|other| same_identifier(&other, name));
    if others {
        return Err(SfcEditError::DuplicateName(name.to_owned()));
    }
    visit_nodes_mut(&mut out.sequence, &mut |node| {
        if let SfcNode::Jump(jump) = node
            && same_identifier(&jump.target, &old)
        {
            jump.target = name.to_owned();
        }
    });
    checked(out)
}

/// Sets the condition of transition `id`: an ST expression or a transition object's name.
pub fn set_transition_condition(
    chart: &SfcChart,
    id: ElementId,
    condition: &str,
) -> Result<SfcChart, SfcEditError> {
    let condition = condition.trim();
    if condition.is_empty() {
        return Err(SfcEditError::EmptyCondition(id));
    }
    let mut out = chart.clone();
    match node_mut(&mut out.sequence, id) {
        Some(SfcNode::Transition(transition)) => transition.condition = condition.to_owned(),
        Some(_) => return Err(SfcEditError::NotATransition(id)),
        None => return Err(SfcEditError::NoSuchElement(id)),
    }
    Ok(out)
}

/// Sets (or clears) the priority of transition `id`.
pub fn set_transition_priority(
    chart: &SfcChart,
    id: ElementId,
    priority: Option<u32>,
) -> Result<SfcChart, SfcEditError> {
    let mut out = chart.clone();
    match node_mut(&mut out.sequence, id) {
        Some(SfcNode::Transition(transition)) => transition.priority = priority,
        Some(_) => return Err(SfcEditError::NotATransition(id)),
        None => return Err(SfcEditError::NoSuchElement(id)),
    }
    Ok(out)
}

/// Makes jump `id` target the step named `target`, which must exist.
pub fn set_jump_target(
    chart: &SfcChart,
    id: ElementId,
    target: &str,
) -> Result<SfcChart, SfcEditError> {
    let mut out = chart.clone();
    match node_mut(&mut out.sequence, id) {
        Some(SfcNode::Jump(jump)) => jump.target = target.trim().to_owned(),
        Some(_) => return Err(SfcEditError::NotAJump(id)),
        None => return Err(SfcEditError::NoSuchElement(id)),
    }
    checked(out)
}

/// Sets the properties of step `id`.
pub fn set_step_properties(
    chart: &SfcChart,
    id: ElementId,
    properties: StepProperties,
) -> Result<SfcChart, SfcEditError> {
    let mut out = chart.clone();
    let step = step_mut(&mut out, id)?;
    step.min_time = optional(properties.min_time);
    step.max_time = optional(properties.max_time);
    step.entry_action = optional(properties.entry_action);
    step.main_action = optional(properties.main_action);
    step.exit_action = optional(properties.exit_action);
    step.comment = properties.comment.trim().to_owned();
    Ok(out)
}

/// The association as stored, or why it cannot be: an action, and a time exactly for the
/// timed qualifiers.
fn valid_association(association: ActionAssociation) -> Result<ActionAssociation, SfcEditError> {
    let action = association.action.trim().to_owned();
    if action.is_empty() {
        return Err(SfcEditError::EmptyAction);
    }
    let duration = optional(association.duration);
    let qualifier = association.qualifier;
    match (qualifier.is_timed(), &duration) {
        (true, None) => return Err(SfcEditError::MissingDuration(qualifier.as_str())),
        (false, Some(_)) => return Err(SfcEditError::UnexpectedDuration(qualifier.as_str())),
        _ => {}
    }
    Ok(ActionAssociation {
        action,
        qualifier,
        duration,
        indicator: optional(association.indicator),
    })
}

/// Appends an action association to step `id`.
pub fn add_association(
    chart: &SfcChart,
    id: ElementId,
    association: ActionAssociation,
) -> Result<SfcChart, SfcEditError> {
    let association = valid_association(association)?;
    let mut out = chart.clone();
    step_mut(&mut out, id)?.actions.push(association);
    Ok(out)
}

/// Replaces action association `index` of step `id`.
pub fn set_association(
    chart: &SfcChart,
    id: ElementId,
    index: usize,
    association: ActionAssociation,
) -> Result<SfcChart, SfcEditError> {
    let association = valid_association(association)?;
    let mut out = chart.clone();
    let slot = step_mut(&mut out, id)?
        .actions
        .get_mut(index)
        .ok_or(SfcEditError::NoSuchAssociation { step: id, index })?;
    *slot = association;
    Ok(out)
}

/// Removes action association `index` of step `id`.
pub fn remove_association(
    chart: &SfcChart,
    id: ElementId,
    index: usize,
) -> Result<SfcChart, SfcEditError> {
    let mut out = chart.clone();
    let actions = &mut step_mut(&mut out, id)?.actions;
    if index >= actions.len() {
        return Err(SfcEditError::NoSuchAssociation { step: id, index });
    }
    actions.remove(index);
    Ok(out)
}

/// Moves action association `from` of step `id` to index `to` (the processing order).
pub fn move_association(
    chart: &SfcChart,
    id: ElementId,
    from: usize,
    to: usize,
) -> Result<SfcChart, SfcEditError> {
    let mut out = chart.clone();
    let actions = &mut step_mut(&mut out, id)?.actions;
    if from >= actions.len() {
        return Err(SfcEditError::NoSuchAssociation {
            step: id,
            index: from,
        });
    }
    if to >= actions.len() {
        return Err(SfcEditError::NoSuchAssociation {
            step: id,
            index: to,
        });
    }
    let association = actions.remove(from);
    actions.insert(to, association);
    Ok(out)
}
