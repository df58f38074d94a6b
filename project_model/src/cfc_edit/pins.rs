//! The pins of elements and the edits of one element: extending a box, negation and edge
//! detection on a pin, an output's coil kind, texts and a box's type.

use super::{CfcEditError, element_mut};
use crate::{
    CfcChart, CfcElementKind, CfcPin, CoilKind, Edge, ElementId, PinRef, cfc_input_pins,
    cfc_output_pins,
};

/// The operators whose boxes take any number of inputs (as IEC 61131-3 allows for them).
const EXTENSIBLE: [&str; 9] = ["ADD", "MUL", "AND", "OR", "XOR", "MAX", "MIN", "SEL", "MUX"];

/// Whether a box of `type_name` can take one more input.
pub fn is_extensible(type_name: &str) -> bool {
    EXTENSIBLE
        .iter()
        .any(|name| name.eq_ignore_ascii_case(type_name))
}

/// The name the pin after `last` gets: its number plus one (`IN2` → `IN3`), or `None` when
/// the name does not end in a number.
fn next_pin_name(last: &str) -> Option<String> {
    let digits = last.len() - last.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    if digits == 0 {
        return None;
    }
    let (stem, number) = last.split_at(last.len() - digits);
    let number: u32 = number.parse().ok()?;
    Some(format!("{stem}{}", number + 1))
}

/// Gives the extensible box `id` one more input, named as its pins continue (`IN3` after
/// `IN2`).
pub fn extend_box(chart: &CfcChart, id: ElementId) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let target = element_mut(&mut chart, id)?;
    let CfcElementKind::Box(block) = &mut target.kind else {
        return Err(CfcEditError::WrongKind {
            operation: "adding an input",
            id,
        });
    };
    let refusal = || CfcEditError::NotExtensible {
        type_name: block.type_name.clone(),
    };
    if !is_extensible(&block.type_name) {
        return Err(refusal());
    }
    let name = block
        .inputs
        .iter()
        .rev()
        .find_map(|pin| next_pin_name(&pin.name))
        .ok_or_else(refusal)?;
    block.inputs.push(CfcPin::named(name));
    Ok(chart)
}

/// The modifiable pin `pin` (a box's, a composer's input or a selector's output).
fn pin_mut<'a>(
    chart: &'a mut CfcChart,
    pin: &PinRef,
    input: bool,
) -> Result<&'a mut CfcPin, CfcEditError> {
    let missing = || {
        if input {
            CfcEditError::NotAnInput(pin.clone())
        } else {
            CfcEditError::NotAnOutput(pin.clone())
        }
    };
    let target = element_mut(chart, pin.element)?;
    let pins = match (&mut target.kind, input) {
        (CfcElementKind::Box(block), true) => &mut block.inputs,
        (CfcElementKind::Box(block), false) => &mut block.outputs,
        (CfcElementKind::Composer { inputs, .. }, true) => inputs,
        (CfcElementKind::Selector { outputs, .. }, false) => outputs,
        _ => return Err(missing()),
    };
    pins.iter_mut()
        .find(|candidate| candidate.name == pin.pin)
        .ok_or_else(missing)
}

/// Negates the pin `pin` or takes its negation away. An input or output pin of a box, a
/// composer's input or a selector's output takes a negation; an output element's negation
/// is its coil kind (`Negated`).
pub fn toggle_negation(chart: &CfcChart, pin: &PinRef) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    if let CfcElementKind::Output { coil, .. } = &mut element_mut(&mut chart, pin.element)?.kind {
        *coil = if *coil == CoilKind::Negated {
            CoilKind::Normal
        } else {
            CoilKind::Negated
        };
        return Ok(chart);
    }
    let found = match pin_mut(&mut chart, pin, true) {
        Ok(found) => found,
        Err(CfcEditError::NotAnInput(_)) => pin_mut(&mut chart, pin, false)?,
        Err(other) => return Err(other),
    };
    found.negated = !found.negated;
    Ok(chart)
}

/// Sets the edge detection of the input pin `pin` of a box.
pub fn set_edge(chart: &CfcChart, pin: &PinRef, edge: Edge) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    pin_mut(&mut chart, pin, true)?.edge = edge;
    Ok(chart)
}

/// Sets how the output element `id` writes its variable.
pub fn set_coil(chart: &CfcChart, id: ElementId, kind: CoilKind) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    match &mut element_mut(&mut chart, id)?.kind {
        CfcElementKind::Output { coil, .. } => *coil = kind,
        _ => {
            return Err(CfcEditError::WrongKind {
                operation: "setting the coil",
                id,
            });
        }
    }
    Ok(chart)
}

/// Sets the text the element `id` shows: an input's or output's expression, a jump's label, a
/// label's or connection mark's name, a comment, a composer's or selector's type. A box's
/// type changes with [`set_box_type`], its instance with [`set_instance`].
pub fn set_text(chart: &CfcChart, id: ElementId, text: &str) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let target = element_mut(&mut chart, id)?;
    let slot = match &mut target.kind {
        CfcElementKind::Input { expression } | CfcElementKind::Output { expression, .. } => {
            expression
        }
        CfcElementKind::Jump { label } => label,
        CfcElementKind::Label { name }
        | CfcElementKind::ConnectionSource { name }
        | CfcElementKind::ConnectionSink { name } => name,
        CfcElementKind::Comment { text, .. } => text,
        CfcElementKind::Composer { type_name, .. } | CfcElementKind::Selector { type_name, .. } => {
            type_name
        }
        CfcElementKind::Box(_) | CfcElementKind::Return => {
            return Err(CfcEditError::WrongKind {
                operation: "setting the text",
                id,
            });
        }
    };
    text.clone_into(slot);
    Ok(chart)
}

/// Sets the instance the function block box `id` calls.
pub fn set_instance(
    chart: &CfcChart,
    id: ElementId,
    instance: &str,
) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    match &mut element_mut(&mut chart, id)?.kind {
        CfcElementKind::Box(block) => instance.clone_into(&mut block.instance),
        _ => {
            return Err(CfcEditError::WrongKind {
                operation: "setting the instance",
                id,
            });
        }
    }
    Ok(chart)
}

/// Makes the box `id` a `type_name` box with the pins `inputs` and `outputs` (as the block
/// declares them): a pin whose name stays keeps its negation, edge and wires; the wires of
/// the pins that went away are removed.
pub fn set_box_type(
    chart: &CfcChart,
    id: ElementId,
    type_name: &str,
    inputs: &[String],
    outputs: &[String],
) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let target = element_mut(&mut chart, id)?;
    let CfcElementKind::Box(block) = &mut target.kind else {
        return Err(CfcEditError::WrongKind {
            operation: "setting the box type",
            id,
        });
    };
    block.inputs = remade_pins(&block.inputs, inputs);
    block.outputs = remade_pins(&block.outputs, outputs);
    type_name.clone_into(&mut block.type_name);
    drop_wires_of_lost_pins(&mut chart, id);
    Ok(chart)
}

/// Makes the composer or selector `id` one of structure `type_name` with the member pins
/// `members` (top to bottom): a member that stays keeps its negation and wires; the wires
/// of the members that went away are removed.
pub fn set_members(
    chart: &CfcChart,
    id: ElementId,
    type_name: &str,
    members: &[String],
) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let target = element_mut(&mut chart, id)?;
    let (slot, pins) = match &mut target.kind {
        CfcElementKind::Composer { type_name, inputs } => (type_name, inputs),
        CfcElementKind::Selector { type_name, outputs } => (type_name, outputs),
        _ => {
            return Err(CfcEditError::WrongKind {
                operation: "setting the structure type",
                id,
            });
        }
    };
    type_name.clone_into(slot);
    *pins = remade_pins(pins, members);
    drop_wires_of_lost_pins(&mut chart, id);
    Ok(chart)
}

/// Removes the wires at pins element `id` no longer has, after its pins were made anew.
fn drop_wires_of_lost_pins(chart: &mut CfcChart, id: ElementId) {
    let Some(kind) = chart
        .elements
        .iter()
        .find(|element| element.id == id)
        .map(|element| element.kind.clone())
    else {
        return;
    };
    let (ins, outs) = (cfc_input_pins(&kind), cfc_output_pins(&kind));
    chart.wires.retain(|wire| {
        (wire.to.element != id || ins.contains(&wire.to.pin.as_str()))
            && (wire.from.element != id || outs.contains(&wire.from.pin.as_str()))
    });
}

/// The pins named `names`, in that order: a pin of `old` with the same name is kept with its
/// negation and edge, a new name gets a plain pin.
fn remade_pins(old: &[CfcPin], names: &[String]) -> Vec<CfcPin> {
    names
        .iter()
        .map(|name| {
            old.iter()
                .find(|pin| pin.name == *name)
                .cloned()
                .unwrap_or_else(|| CfcPin::named(name.clone()))
        })
        .collect()
}
