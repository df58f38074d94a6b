//! The marks Rivet's export puts on boxes (`docs/plcopen-xml.md` §3.4, §5.2): the FBD boxes
//! written for what its networks have no box for, the `AND` of a chain's operand and the `OR` of
//! a parallel group, each marked with Rivet's `…/gate` entry, which the import reads back as the
//! chain and the group; and a box's first input driven by a source of its own (`…/source`). A
//! marked box whose wires no longer fit the mark (another tool edited them) is an ordinary box.

use super::network_graph::{InputPoint, Producer};
use super::rivet_attributes::rivet_attributes;
use crate::body_object::{BodyObject, ObjectKind};
use crate::ld::Edge;

/// What a marked box stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Gate {
    /// The chain before `IN1` followed by the operand whose `inVariable` drives `IN2`.
    Series {
        /// The index of that `inVariable`.
        operand: usize,
    },
    /// A parallel group whose branches end at the box's inputs, in order.
    Parallel,
}

/// The gate `objects[object]` is, given every object's input points and how many inputs each
/// output drives (`readers(object, pin)`).
pub(super) fn gate_of(
    objects: &[BodyObject],
    inputs: &[Vec<InputPoint<'_>>],
    object: usize,
    readers: impl Fn(usize, usize) -> usize,
) -> Option<Gate> {
    let ObjectKind::Block(block) = &objects[object].kind else {
        return None;
    };
    let attributes = rivet_attributes(&objects[object].add_data, "gate")?;
    let plain = block.instance_name.as_deref().is_none_or(str::is_empty)
        && block.in_outs.is_empty()
        && block.outputs.len() == 1
        && block.outputs[0].negated != Some(true)
        && block
            .inputs
            .iter()
            .all(|pin| pin.negated != Some(true) && pin.edge.is_none_or(|edge| edge == Edge::None));
    if !plain {
        return None;
    }
    match attributes.get("of").map(String::as_str) {
        Some("series") if block.type_name.trim().eq_ignore_ascii_case("AND") => {
            let [_, second] = inputs[object].as_slice() else {
                return None;
            };
            let [
                Producer::Output {
                    object: operand, ..
                },
            ] = second.producers.as_slice()
            else {
                return None;
            };
            let is_variable = matches!(objects[*operand].kind, ObjectKind::InVariable(_));
            (is_variable && readers(*operand, 0) == 1).then_some(Gate::Series { operand: *operand })
        }
        // A group has two branches or more; an OR with fewer inputs was edited by another
        // tool, and its output would be reached by no wire.
        Some("parallel")
            if block.type_name.trim().eq_ignore_ascii_case("OR") && inputs[object].len() >= 2 =>
        {
            Some(Gate::Parallel)
        }
        _ => None,
    }
}

/// Whether `objects[object]` is a box whose first input Rivet's export marked as driven by a
/// source of its own (the `…/source` entry naming that pin), given how many inputs each output
/// drives (`readers(object, pin)`). The mark holds only where the wires fit it: something other
/// than the power rail alone drives the pin, and each element that does drives nothing else (a
/// source is read by its pin only); a mark another tool's edits made stale is ignored, and the
/// box is an ordinary one.
pub(super) fn has_own_first_source(
    objects: &[BodyObject],
    inputs: &[Vec<InputPoint<'_>>],
    object: usize,
    readers: impl Fn(usize, usize) -> usize,
) -> bool {
    let ObjectKind::Block(block) = &objects[object].kind else {
        return false;
    };
    let Some(attributes) = rivet_attributes(&objects[object].add_data, "source") else {
        return false;
    };
    let Some(first) = block.inputs.first() else {
        return false;
    };
    let Some(point) = inputs[object].first() else {
        return false;
    };
    let is_rail = |producer: usize| matches!(objects[producer].kind, ObjectKind::LeftPowerRail(_));
    let mut only_rails = true;
    for producer in &point.producers {
        let Producer::Output {
            object: producer,
            pin,
        } = producer
        else {
            return false;
        };
        // An empty parallel branch of an LD source starts at the rail, as the source does.
        if is_rail(*producer) {
            continue;
        }
        only_rails = false;
        if readers(*producer, *pin) != 1 {
            return false;
        }
    }
    attributes.get("pin") == Some(&first.formal_parameter) && !only_rails
}
