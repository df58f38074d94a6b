//! The elements of a network as Rivet writes them: operands, edges and coil kinds from the
//! attributes of contacts, variables and coils (`docs/plcopen-xml.md` §3.3).

use project_model::{CoilKind, Edge, FlowNode, Operand};

use super::network_build::BuildFailure;
use super::network_error::NetworkError;
use super::network_graph::ObjectFault;
use crate::ld::{Edge as XmlEdge, Storage};

/// A contact or inVariable as an operand.
pub(super) fn operand(
    text: &str,
    negated: Option<bool>,
    edge_attribute: Option<XmlEdge>,
) -> FlowNode {
    FlowNode::Operand(Operand {
        id: Default::default(),
        text: text.trim().to_owned(),
        negated: negated.unwrap_or(false),
        edge: edge(edge_attribute),
    })
}

/// The edge an attribute asks for (none when absent).
pub(super) fn edge(edge: Option<XmlEdge>) -> Edge {
    match edge {
        Some(XmlEdge::Rising) => Edge::Rising,
        Some(XmlEdge::Falling) => Edge::Falling,
        Some(XmlEdge::None) | None => Edge::None,
    }
}

/// The coil kind its attributes ask for; two at once are refused.
pub(super) fn coil_kind(
    object: usize,
    variable: &str,
    negated: Option<bool>,
    edge: Option<XmlEdge>,
    storage: Option<Storage>,
) -> Result<CoilKind, BuildFailure> {
    let mut kinds = Vec::new();
    if negated == Some(true) {
        kinds.push(("negated", CoilKind::Negated));
    }
    match storage {
        Some(Storage::Set) => kinds.push(("set", CoilKind::Set)),
        Some(Storage::Reset) => kinds.push(("reset", CoilKind::Reset)),
        Some(Storage::None) | None => {}
    }
    match edge {
        Some(XmlEdge::Rising) => kinds.push(("rising", CoilKind::Rising)),
        Some(XmlEdge::Falling) => kinds.push(("falling", CoilKind::Falling)),
        Some(XmlEdge::None) | None => {}
    }
    match kinds.as_slice() {
        [] => Ok(CoilKind::Normal),
        [(_, kind)] => Ok(*kind),
        several => Err(BuildFailure::Fault(ObjectFault {
            object,
            error: NetworkError::ConflictingCoil {
                variable: variable.trim().to_owned(),
                attributes: several
                    .iter()
                    .map(|(word, _)| *word)
                    .collect::<Vec<_>>()
                    .join(" and "),
            },
        })),
    }
}
