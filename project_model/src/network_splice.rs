//! `Edit::SpliceNetworks`: replacing a run of networks of an LD/FBD body, the one edit behind
//! inserting, deleting, changing and pasting networks.

use crate::edit::{EditError, TextTarget, pou_mut};
use crate::{Body, Edit, Folder, Network, network_problems};

/// Replaces the `remove` networks at `at` of the LD/FBD body `target` with `insert`, and
/// returns the splice that puts the old ones back.
///
/// The body must stay sound (`network_check`): an edit that would leave two elements with one
/// id, two networks with one label or any other broken rule is refused, so a saved body always
/// loads again. A refused splice changes nothing.
pub(crate) fn splice_networks(
    root: &mut Folder,
    target: TextTarget,
    at: usize,
    remove: usize,
    insert: Vec<Network>,
) -> Result<Edit, EditError> {
    let networks = networks_mut(root, &target)?;
    let len = networks.len();
    let end = at.checked_add(remove).filter(|&end| end <= len);
    let Some(end) = end else {
        return Err(EditError::NetworkRangeOutOfRange { at, remove, len });
    };
    let inserted = insert.len();
    let removed: Vec<Network> = networks.splice(at..end, insert).collect();
    if let Some(problem) = network_problems(networks).into_iter().next() {
        // Put the body back as it was before reporting, so a refusal changes nothing.
        networks.splice(at..at + inserted, removed);
        return Err(EditError::InvalidObject(format!("{target}: {problem}")));
    }
    Ok(Edit::SpliceNetworks {
        target,
        at,
        remove: inserted,
        insert: removed,
    })
}

/// The networks of the LD or FBD body `target`.
fn networks_mut<'a>(
    root: &'a mut Folder,
    target: &TextTarget,
) -> Result<&'a mut Vec<Network>, EditError> {
    let body = body_mut(root, target)?;
    match body {
        Body::Ld { networks } | Body::Fbd { networks } => Ok(networks),
        _ => Err(EditError::NotNetworks(target.to_string())),
    }
}

/// The body `target` names, whatever its language.
pub(crate) fn body_mut<'a>(
    root: &'a mut Folder,
    target: &TextTarget,
) -> Result<&'a mut Body, EditError> {
    let no_member = |pou: &str, what: &'static str, name: &str| EditError::NoSuchMember {
        pou: pou.to_owned(),
        what,
        name: name.to_owned(),
    };
    match target {
        TextTarget::Pou(pou) => Ok(&mut pou_mut(root, pou)?.body),
        TextTarget::Method { pou, method } => pou_mut(root, pou)?
            .methods
            .iter_mut()
            .find(|m| m.name == *method)
            .map(|m| &mut m.body)
            .ok_or_else(|| no_member(pou, "method", method)),
        TextTarget::Property { pou, property, get } => pou_mut(root, pou)?
            .properties
            .iter_mut()
            .find(|p| p.name == *property)
            .and_then(|p| if *get { p.get.as_mut() } else { p.set.as_mut() })
            .map(|accessor| &mut accessor.body)
            .ok_or_else(|| no_member(pou, "property", property)),
        TextTarget::Action { pou, action } => pou_mut(root, pou)?
            .actions
            .iter_mut()
            .find(|a| a.name == *action)
            .map(|a| &mut a.body)
            .ok_or_else(|| no_member(pou, "action", action)),
        TextTarget::Transition { pou, transition } => pou_mut(root, pou)?
            .transitions
            .iter_mut()
            .find(|t| t.name == *transition)
            .map(|t| &mut t.body)
            .ok_or_else(|| no_member(pou, "transition", transition)),
    }
}

#[cfg(test)]
#[path = "network_splice_tests.rs"]
mod tests;
