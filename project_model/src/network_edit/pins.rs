//! Edits of a box's pins: EN/ENO on and off, and edge detection on an input.

use super::{
    BodySplice, ElementMut, NetworkEditError, edit_element, network_index_of, not_applicable,
    one_network,
};
use crate::{BlockInput, BlockOutput, EN_PIN, ENO_PIN, Edge, ElementId, Network};

/// Gives the box `id` EN and ENO pins, or takes them away (CODESYS's "Box with EN/ENO").
///
/// With EN, the box runs only while EN is TRUE and passes the power on through ENO, so in a
/// chain EN takes the power that its first input took before, and that input is left
/// unconnected for an operand. Taking EN away hands the power back to the first remaining
/// input, which is refused when that input is driven by operands of its own and the box is not
/// the first element of its chain (the body would then drive it twice; the model's checks
/// refuse such a body anyway).
pub fn toggle_en_eno(body: &[Network], id: ElementId) -> Result<BodySplice, NetworkEditError> {
    let index = network_index_of(body, id)?;
    let mut network = body[index].clone();
    let mut applied = false;
    edit_element(&mut network, id, |element| {
        let ElementMut::Block(block) = element else {
            return;
        };
        if block.has_en_eno() {
            block.inputs.remove(0);
            block
                .outputs
                .retain(|output| !output.pin.eq_ignore_ascii_case(ENO_PIN));
        } else {
            block.inputs.insert(
                0,
                BlockInput {
                    pin: EN_PIN.to_owned(),
                    ..BlockInput::default()
                },
            );
            block.outputs.insert(
                0,
                BlockOutput {
                    pin: ENO_PIN.to_owned(),
                    ..BlockOutput::default()
                },
            );
        }
        applied = true;
    });
    if !applied {
        return Err(not_applicable(id, "EN/ENO"));
    }
    if crate::network_problems(std::slice::from_ref(&network))
        .iter()
        .any(|problem| problem.element == Some(id))
    {
        return Err(not_applicable(id, "EN/ENO"));
    }
    Ok(one_network(index, network, Some(id)))
}

/// Cycles the edge detection of the input `pin` of box `id`: none → rising (P) → falling (N)
/// → none, as the pin modifiers of CODESYS's FBD.
pub fn cycle_pin_edge(
    body: &[Network],
    id: ElementId,
    pin: &str,
) -> Result<BodySplice, NetworkEditError> {
    let index = network_index_of(body, id)?;
    let mut network = body[index].clone();
    let mut applied = false;
    edit_element(&mut network, id, |element| {
        let ElementMut::Block(block) = element else {
            return;
        };
        if let Some(input) = block.inputs.iter_mut().find(|input| input.pin == pin) {
            input.edge = match input.edge {
                Edge::None => Edge::Rising,
                Edge::Rising => Edge::Falling,
                Edge::Falling => Edge::None,
            };
            applied = true;
        }
    });
    if !applied {
        return Err(not_applicable(id, "edge detection"));
    }
    Ok(one_network(index, network, Some(id)))
}
