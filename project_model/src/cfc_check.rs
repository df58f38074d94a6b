//! The structural rules of a CFC chart, checked on load, on save and by edits.
//!
//! These rules give every chart one meaning for the lowering into Structured Text: every
//! element is found by its id, the execution order is a dense numbering of the elements that
//! run, every wire joins an output pin to an input pin the elements have, and no input is
//! driven twice. What names mean (variables, types, labels, connection marks) is left to the
//! checker, so an empty expression is allowed here.

use std::collections::HashMap;
use std::fmt;

use crate::{CfcChart, CfcElement, CfcElementKind, CfcPin, ElementId, PinRef, is_valid_identifier};

/// A broken rule of a CFC chart, at an element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CfcProblem {
    /// The element the problem is at.
    pub element: ElementId,
    /// What is wrong, in a sentence without the location.
    pub message: String,
}

impl fmt::Display for CfcProblem {
    /// Formats as `element 7: message`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "element {}: {}", self.element.0, self.message)
    }
}

/// The names of the input pins of an element, top to bottom: a box's, composer's inputs by
/// name, `""` for the one input of an output, jump, return, selector or connection source.
pub fn cfc_input_pins(kind: &CfcElementKind) -> Vec<&str> {
    match kind {
        CfcElementKind::Box(block) => pin_names(&block.inputs),
        CfcElementKind::Composer { inputs, .. } => pin_names(inputs),
        CfcElementKind::Output { .. }
        | CfcElementKind::Jump { .. }
        | CfcElementKind::Return
        | CfcElementKind::Selector { .. }
        | CfcElementKind::ConnectionSource { .. } => vec![""],
        CfcElementKind::Input { .. }
        | CfcElementKind::Label { .. }
        | CfcElementKind::Comment { .. }
        | CfcElementKind::ConnectionSink { .. } => Vec::new(),
    }
}

/// The names of the output pins of an element, top to bottom: a box's and selector's outputs
/// by name, `""` for the one output of an input, composer or connection sink.
pub fn cfc_output_pins(kind: &CfcElementKind) -> Vec<&str> {
    match kind {
        CfcElementKind::Box(block) => pin_names(&block.outputs),
        CfcElementKind::Selector { outputs, .. } => pin_names(outputs),
        CfcElementKind::Input { .. }
        | CfcElementKind::Composer { .. }
        | CfcElementKind::ConnectionSink { .. } => vec![""],
        CfcElementKind::Output { .. }
        | CfcElementKind::Jump { .. }
        | CfcElementKind::Label { .. }
        | CfcElementKind::Return
        | CfcElementKind::Comment { .. }
        | CfcElementKind::ConnectionSource { .. } => Vec::new(),
    }
}

fn pin_names(pins: &[CfcPin]) -> Vec<&str> {
    pins.iter().map(|pin| pin.name.as_str()).collect()
}

/// Whether `pin` names one of `pins`: by name without case, or `""` for an element's only pin.
pub fn cfc_pin_matches(pins: &[&str], pin: &str) -> bool {
    pins.iter()
        .any(|name| name.eq_ignore_ascii_case(pin.trim()))
}

/// Every broken rule of `chart`, element by element; empty when the chart is sound.
pub fn cfc_problems(chart: &CfcChart) -> Vec<CfcProblem> {
    let mut problems = Vec::new();
    let mut report = |element: ElementId, message: String| {
        problems.push(CfcProblem { element, message });
    };
    let mut by_id: HashMap<ElementId, &CfcElement> = HashMap::new();
    for element in &chart.elements {
        if by_id.insert(element.id, element).is_some() {
            report(
                element.id,
                format!("two elements have the id {}", element.id.0),
            );
        }
    }
    check_order(chart, &mut report);
    for element in &chart.elements {
        check_names(element, &mut report);
    }
    let mut driven: HashMap<(ElementId, String), usize> = HashMap::new();
    for wire in &chart.wires {
        let (Some(from), Some(to)) = (by_id.get(&wire.from.element), by_id.get(&wire.to.element))
        else {
            let (at, missing) = match by_id.get(&wire.from.element) {
                Some(_) => (wire.from.element, wire.to.element),
                None => (wire.to.element, wire.from.element),
            };
            report(
                at,
                format!(
                    "a wire {} element {}, which is not in the chart",
                    if at == wire.from.element {
                        "goes to"
                    } else {
                        "comes from"
                    },
                    missing.0
                ),
            );
            continue;
        };
        if !cfc_pin_matches(&cfc_output_pins(&from.kind), &wire.from.pin) {
            report(
                from.id,
                format!(
                    "a wire starts at {}, which is not an output pin of this element",
                    pin_words(&wire.from)
                ),
            );
        }
        if !cfc_pin_matches(&cfc_input_pins(&to.kind), &wire.to.pin) {
            report(
                to.id,
                format!(
                    "a wire ends at {}, which is not an input pin of this element",
                    pin_words(&wire.to)
                ),
            );
            continue;
        }
        let count = driven
            .entry((to.id, wire.to.pin.trim().to_lowercase()))
            .or_default();
        *count += 1;
        if *count == 2 {
            report(
                to.id,
                format!("{} has two wires; an input takes one", pin_words(&wire.to)),
            );
        }
    }
    problems
}

/// `the pin 'IN1'`, or `the element's pin` for an element's only pin.
fn pin_words(pin: &PinRef) -> String {
    if pin.pin.trim().is_empty() {
        "the element's only pin".to_owned()
    } else {
        format!("the pin '{}'", pin.pin)
    }
}

/// The elements that run are numbered 0 to n-1, each number once; the others have none.
fn check_order(chart: &CfcChart, report: &mut impl FnMut(ElementId, String)) {
    let count = chart
        .elements
        .iter()
        .filter(|element| element.kind.is_executable())
        .count();
    let mut numbers: HashMap<u32, ElementId> = HashMap::new();
    for element in &chart.elements {
        match (element.kind.is_executable(), element.order) {
            (true, None) => report(
                element.id,
                "the element runs, so it needs a number in the execution order".to_owned(),
            ),
            (false, Some(number)) => report(
                element.id,
                format!(
                    "the element does not run by itself, so it has no place in the execution order, but is numbered {number}"
                ),
            ),
            (true, Some(number)) if usize::try_from(number).map_or(true, |n| n >= count) => {
                report(
                    element.id,
                    format!(
                        "the execution order number {number} is out of range: the {count} elements that run are numbered 0 to {}",
                        count.saturating_sub(1)
                    ),
                );
            }
            (true, Some(number)) => {
                if let Some(other) = numbers.insert(number, element.id) {
                    numbers.insert(number, other);
                    report(
                        element.id,
                        format!(
                            "the execution order number {number} is also element {}'s",
                            other.0
                        ),
                    );
                }
            }
            (false, None) => {}
        }
    }
}

/// Pin names are identifiers, unique in their element; box type names are present; no name
/// holds `__`, which Rivet keeps for the names it generates.
fn check_names(element: &CfcElement, report: &mut impl FnMut(ElementId, String)) {
    let id = element.id;
    let mut reserved = |what: &str, name: &str| {
        if name.contains("__") {
            report(
                id,
                format!(
                    "the {what} '{name}' contains '__', which IEC 61131-3 does not allow in names and Rivet keeps for the names it generates"
                ),
            );
        }
    };
    match &element.kind {
        CfcElementKind::Box(block) => {
            reserved("type name", &block.type_name);
            reserved("instance", &block.instance);
        }
        CfcElementKind::Composer { type_name, .. } | CfcElementKind::Selector { type_name, .. } => {
            reserved("type name", type_name);
        }
        CfcElementKind::Jump { label } => reserved("label", label),
        CfcElementKind::Label { name } => reserved("label", name),
        CfcElementKind::ConnectionSource { name } | CfcElementKind::ConnectionSink { name } => {
            reserved("connection mark name", name);
        }
        _ => {}
    }
    let pins: Vec<&CfcPin> = match &element.kind {
        CfcElementKind::Box(block) => block.inputs.iter().chain(&block.outputs).collect(),
        CfcElementKind::Composer { inputs, .. } => inputs.iter().collect(),
        CfcElementKind::Selector { outputs, .. } => outputs.iter().collect(),
        _ => Vec::new(),
    };
    for pin in &pins {
        reserved("pin name", &pin.name);
    }
    match &element.kind {
        CfcElementKind::Box(block) if block.type_name.trim().is_empty() => {
            report(id, "the box has no type name".to_owned());
        }
        CfcElementKind::Composer { type_name, .. } | CfcElementKind::Selector { type_name, .. }
            if type_name.trim().is_empty() =>
        {
            report(id, "the element names no structure type".to_owned());
        }
        CfcElementKind::Label { name } if !is_valid_identifier(name.trim()) => {
            report(
                id,
                format!("the label '{name}' is not an identifier (letters, digits and '_')"),
            );
        }
        _ => {}
    }
    let mut seen: Vec<&str> = Vec::new();
    for pin in pins {
        let name = pin.name.trim();
        if !is_valid_identifier(name) {
            report(
                id,
                format!(
                    "the pin name '{}' is not an identifier (letters, digits and '_')",
                    pin.name
                ),
            );
        } else if seen.iter().any(|other| other.eq_ignore_ascii_case(name)) {
            report(id, format!("the element has two pins named '{name}'"));
        } else {
            seen.push(name);
        }
    }
}

#[cfg(test)]
#[path = "cfc_check_tests.rs"]
mod tests;
