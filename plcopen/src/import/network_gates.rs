//! The FBD boxes Rivet's export writes for what its networks have no box for
//! (`docs/plcopen-xml.md` §3.4, §5.2): the `AND` of a chain's operand and the `OR` of a parallel
//! group, each marked with Rivet's `…/gate` entry. The import reads them back as the chain and
//! the group; a marked box whose wires no longer fit the mark (another tool edited them) is an
//! ordinary box.

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
