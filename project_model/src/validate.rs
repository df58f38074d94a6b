//! Checks that keep an object storable: what the loader rejects and edits refuse.

use crate::files::body_slots;
use crate::{Body, Object, is_valid_identifier, network_problems, same_identifier};

/// Describes why an object cannot be stored as it is, or returns `None` when it can.
///
/// Methods, properties and actions of a POU get files named after them, so their names must be
/// identifiers and differ from each other; LD and FBD bodies must keep the structural rules of
/// `network_check`. Everything else in an object is free text that the compiler checks.
pub(crate) fn object_problem(object: &Object) -> Option<String> {
    member_problem(object).or_else(|| body_problems(object).into_iter().next())
}

/// Every broken structural rule of the LD and FBD bodies of a POU, each as
/// `POU 'Main', method 'Reset', network 3 'Start', element 17: message`.
pub(crate) fn body_problems(object: &Object) -> Vec<String> {
    let Object::Pou(pou) = object else {
        return Vec::new();
    };
    let mut problems = Vec::new();
    for slot in body_slots(pou) {
        if let Body::Ld { networks } | Body::Fbd { networks } = slot.body {
            problems.extend(
                network_problems(networks)
                    .into_iter()
                    .map(|problem| format!("{}, {problem}", slot.owner)),
            );
        }
        problems.extend(
            chart_problems(slot.body)
                .into_iter()
                .map(|problem| format!("{}, {problem}", slot.owner)),
        );
    }
    problems
}

/// Every broken structural rule of a CFC or SFC body, each naming the element; nothing for
/// the other languages.
pub(crate) fn chart_problems(body: &Body) -> Vec<String> {
    match body {
        Body::Sfc { chart } => crate::sfc_problems(chart),
        Body::Cfc { chart } => crate::cfc_problems(chart)
            .iter()
            .map(ToString::to_string)
            .collect(),
        _ => Vec::new(),
    }
}

/// Describes why the names of a POU's methods, properties and actions cannot be stored.
pub(crate) fn member_problem(object: &Object) -> Option<String> {
    let Object::Pou(pou) = object else {
        return None;
    };
    let members = pou
        .methods
        .iter()
        .map(|method| ("method", method.name.as_str()))
        .chain(pou.properties.iter().map(|p| ("property", p.name.as_str())))
        .chain(pou.actions.iter().map(|a| ("action", a.name.as_str())))
        .chain(
            pou.transitions
                .iter()
                .map(|t| ("transition", t.name.as_str())),
        );
    let mut seen: Vec<&str> = Vec::new();
    for (what, name) in members {
        if !is_valid_identifier(name) {
            return Some(format!(
                "the {what} name '{name}' of '{}' is not an identifier",
                pou.name
            ));
        }
        if seen.iter().any(|other| same_identifier(other, name)) {
            return Some(format!(
                "'{}' has two methods, properties, actions or transitions named '{name}'",
                pou.name
            ));
        }
        seen.push(name);
    }
    None
}
