//! The structural rules of `sfc.rs`, checked on the result of every edit so that no edit can
//! produce a chart the editor cannot draw or the model cannot save.

use super::error::{SfcEditError, SfcRule};
use super::walk::{step_names, visit_nodes};
use crate::identifier::{is_valid_identifier, same_identifier};
use crate::network::ElementId;
use crate::sfc::{SfcChart, SfcNode};

/// Which kind of sequence is checked, for the rules on its first and last node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Context {
    Main,
    Alternative,
    Parallel,
    Macro,
}

/// Checks every structural rule of `chart`: alternation, branch shapes, jumps last and to
/// existing steps, macro bodies, step names that are identifiers without `__` and unique.
/// The first broken rule is returned with the element it breaks at.
pub fn check_structure(chart: &SfcChart) -> Result<(), SfcEditError> {
    check_sequence(&chart.sequence, Context::Main, ElementId(0))?;
    let names = step_names(chart);
    for (index, name) in names.iter().enumerate() {
        if !is_valid_identifier(name) || name.contains("__") {
            return Err(SfcEditError::InvalidName(name.clone()));
        }
        if names[..index]
            .iter()
            .any(|earlier| same_identifier(earlier, name))
        {
            return Err(SfcEditError::DuplicateName(name.clone()));
        }
    }
    let mut unknown = None;
    visit_nodes(&chart.sequence, &mut |node| {
        if let SfcNode::Jump(jump) = node
            && unknown.is_none()
            && !names.iter().any(|name| same_identifier(name, &jump.target))
        {
            unknown = Some(jump.target.clone());
        }
    });
    match unknown {
        Some(target) => Err(SfcEditError::UnknownStep(target)),
        None => Ok(()),
    }
}

fn broken(rule: SfcRule, element: ElementId) -> SfcEditError {
    SfcEditError::Structure { rule, element }
}

/// Whether an alternative branch ends every one of its branches in a jump, so nothing can
/// follow it.
fn is_terminal(node: &SfcNode) -> bool {
    match node {
        SfcNode::Jump(_) => true,
        SfcNode::Alternative(branches) => branches
            .branches
            .iter()
            .all(|branch| matches!(branch.nodes.last(), Some(SfcNode::Jump(_)))),
        _ => false,
    }
}

/// Whether `node` is one a step is needed after a transition: a step, macro step, parallel
/// branch or jump.
fn begins_like_step(node: &SfcNode) -> bool {
    matches!(
        node,
        SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_) | SfcNode::Jump(_)
    )
}

fn check_sequence(
    nodes: &[SfcNode],
    context: Context,
    owner: ElementId,
) -> Result<(), SfcEditError> {
    let (Some(first), Some(last)) = (nodes.first(), nodes.last()) else {
        return Err(broken(SfcRule::SequenceNotEmpty, owner));
    };
    for pair in nodes.windows(2) {
        let (before, after) = (&pair[0], &pair[1]);
        if is_terminal(before) {
            return Err(broken(SfcRule::JumpIsLast, before.id()));
        }
        let fits = if matches!(
            before,
            SfcNode::Step(_) | SfcNode::Macro(_) | SfcNode::Parallel(_)
        ) {
            !begins_like_step(after)
        } else {
            begins_like_step(after)
        };
        if !fits {
            let rule = if begins_like_step(before) {
                SfcRule::StepNeedsTransitionAfter
            } else {
                SfcRule::TransitionNeedsStepAfter
            };
            return Err(broken(rule, before.id()));
        }
    }
    let step_like = |node: &SfcNode| matches!(node, SfcNode::Step(_) | SfcNode::Macro(_));
    match context {
        Context::Main => {
            if !matches!(first, SfcNode::Step(_)) {
                return Err(broken(SfcRule::MainStartsWithStep, first.id()));
            }
            if !is_terminal(last) {
                return Err(broken(SfcRule::MainEndsWithJump, last.id()));
            }
        }
        Context::Alternative => {
            if !matches!(first, SfcNode::Transition(_)) {
                return Err(broken(SfcRule::AlternativeBeginsWithTransition, owner));
            }
            if !matches!(last, SfcNode::Transition(_) | SfcNode::Jump(_)) {
                return Err(broken(SfcRule::AlternativeEndsWithTransitionOrJump, owner));
            }
        }
        Context::Parallel => {
            if !step_like(first) {
                return Err(broken(SfcRule::ParallelBeginsWithStep, owner));
            }
            if !step_like(last) {
                return Err(broken(SfcRule::ParallelEndsWithStep, owner));
            }
        }
        Context::Macro => {
            if !matches!(first, SfcNode::Step(_)) || !matches!(last, SfcNode::Step(_)) {
                return Err(broken(SfcRule::MacroBeginsAndEndsWithStep, owner));
            }
            let mut jump = None;
            visit_nodes(nodes, &mut |node| {
                if matches!(node, SfcNode::Jump(_)) {
                    jump = jump.or(Some(node.id()));
                }
            });
            if let Some(jump) = jump {
                return Err(broken(SfcRule::NoJumpInMacro, jump));
            }
        }
    }
    for node in nodes {
        match node {
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => {
                if branches.branches.len() < 2 {
                    return Err(broken(SfcRule::TwoBranches, branches.id));
                }
                let inner = if matches!(node, SfcNode::Alternative(_)) {
                    Context::Alternative
                } else {
                    Context::Parallel
                };
                for branch in &branches.branches {
                    check_sequence(&branch.nodes, inner, branches.id)?;
                }
            }
            SfcNode::Macro(macro_step) => {
                check_sequence(&macro_step.body, Context::Macro, macro_step.id)?;
            }
            SfcNode::Step(_) | SfcNode::Transition(_) | SfcNode::Jump(_) => {}
        }
    }
    Ok(())
}
