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
        Some("parallel") if block.type_name.trim().eq_ignore_ascii_case("OR") => {
            Some(Gate::Parallel)
        }
        _ => None,
    }
}

/// Whether `objects[object]` is a box whose first input Rivet's export marked as driven by a
/// source of its own (the `…/source` entry naming that pin) and something drives it.
pub(super) fn has_own_first_source(
    objects: &[BodyObject],
    inputs: &[Vec<InputPoint<'_>>],
    object: usize,
) -> bool {
    let ObjectKind::Block(block) = &objects[object].kind else {
        return false;
    };
    let Some(attributes) = rivet_attributes(&objects[object].add_data, "source") else {
        return false;
    };
    let first = block.inputs.first();
    first.is_some_and(|pin| {
        attributes.get("pin") == Some(&pin.formal_parameter)
            && inputs[object]
                .first()
                .is_some_and(|point| !point.producers.is_empty())
    })
}
