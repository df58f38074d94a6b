//! Which part of a POU a document shows: the POU itself, a method, an action or a property
//! accessor.

use project_model::{Body, Pou, TextTarget};

use crate::studio::reveal::Reveal;

/// The part of a POU a document shows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Part {
    /// The POU's own declarations and implementation.
    #[default]
    Main,
    /// A method.
    Method(String),
    /// An action.
    Action(String),
    /// A property's getter or setter.
    Property(String, bool),
    /// A transition object of an SFC program or function block.
    Transition(String),
}

/// The POU part a document shows, and where to put the caret in it this frame.
#[derive(Clone, Copy)]
pub(super) struct Shown<'a> {
    /// The POU.
    pub pou: &'a Pou,
    /// Its part shown.
    pub part: &'a Part,
    /// The place to reveal, once.
    pub reveal: Option<&'a Reveal>,
}

/// The body of a POU part, with its target.
pub(super) fn body_of<'p>(pou: &'p Pou, part: &Part) -> Option<(TextTarget, &'p Body)> {
    let name = pou.name.clone();
    Some(match part {
        Part::Main => (TextTarget::Pou(name), &pou.body),
        Part::Method(method) => (
            TextTarget::Method {
                pou: name,
                method: method.clone(),
            },
            &pou.methods.iter().find(|m| m.name == *method)?.body,
        ),
        Part::Action(action) => (
            TextTarget::Action {
                pou: name,
                action: action.clone(),
            },
            &pou.actions.iter().find(|a| a.name == *action)?.body,
        ),
        Part::Transition(transition) => (
            TextTarget::Transition {
                pou: name,
                transition: transition.clone(),
            },
            &pou.transitions.iter().find(|t| t.name == *transition)?.body,
        ),
        Part::Property(property, get) => {
            let property_data = pou.properties.iter().find(|p| p.name == *property)?;
            let accessor = if *get {
                property_data.get.as_ref()
            } else {
                property_data.set.as_ref()
            }?;
            (
                TextTarget::Property {
                    pou: name,
                    property: property.clone(),
                    get: *get,
                },
                &accessor.body,
            )
        }
    })
}

pub(super) fn part_of(target: &TextTarget) -> Part {
    match target {
        TextTarget::Pou(_) => Part::Main,
        TextTarget::Method { method, .. } => Part::Method(method.clone()),
        TextTarget::Action { action, .. } => Part::Action(action.clone()),
        TextTarget::Property { property, get, .. } => Part::Property(property.clone(), *get),
        TextTarget::Transition { transition, .. } => Part::Transition(transition.clone()),
    }
}

/// A body's name for labels: `Main`, `FB_Motor.Start`, `FB_Motor.Speed.Get`.
pub fn target_label(target: &TextTarget) -> String {
    match target {
        TextTarget::Pou(pou) => pou.clone(),
        TextTarget::Method { pou, method } => format!("{pou}.{method}"),
        TextTarget::Action { pou, action } => format!("{pou}.{action}"),
        TextTarget::Transition { pou, transition } => format!("{pou}.{transition}"),
        TextTarget::Property { pou, property, get } => {
            format!("{pou}.{property}.{}", if *get { "Get" } else { "Set" })
        }
    }
}
