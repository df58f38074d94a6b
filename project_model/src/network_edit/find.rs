//! Finding where an element sits in a network, mutably: the chain or output list that holds
//! it, the chain that feeds it, the parallel group around it.

use crate::{ElementId, FlowNode, Network, NetworkOutput, Parallel, walk_chain};

use super::ElementMut;

pub(super) fn chain_contains(chain: &[FlowNode], id: ElementId) -> bool {
    let mut found = false;
    walk_chain(chain, &mut |element| found |= element.id() == id);
    found
}

/// The chain that holds `id` directly, and its position there.
pub(super) fn chain_holding(
    network: &mut Network,
    id: ElementId,
) -> Option<(&mut Vec<FlowNode>, usize)> {
    if let Some(found) = chain_holding_in(&mut network.rung, id) {
        return Some(found);
    }
    chain_holding_in_outputs(&mut network.outputs, id)
}

pub(super) fn chain_holding_in(
    chain: &mut Vec<FlowNode>,
    id: ElementId,
) -> Option<(&mut Vec<FlowNode>, usize)> {
    if let Some(position) = chain.iter().position(|node| node.id() == id) {
        return Some((chain, position));
    }
    for node in chain.iter_mut() {
        let found = match node {
            FlowNode::Operand(_) => None,
            FlowNode::Parallel(parallel) => parallel
                .branches
                .iter_mut()
                .find_map(|branch| chain_holding_in(&mut branch.rung, id)),
            FlowNode::Block(block) => block
                .inputs
                .iter_mut()
                .find_map(|input| chain_holding_in(&mut input.source, id)),
        };
        if found.is_some() {
            return found;
        }
    }
    None
}

pub(super) fn chain_holding_in_outputs(
    outputs: &mut [NetworkOutput],
    id: ElementId,
) -> Option<(&mut Vec<FlowNode>, usize)> {
    outputs.iter_mut().find_map(|output| match output {
        NetworkOutput::Branch { rung, outputs, .. } => {
            if chain_contains(rung, id) {
                chain_holding_in(rung, id)
            } else {
                chain_holding_in_outputs(outputs, id)
            }
        }
        _ => None,
    })
}

/// The output list that holds `id` directly, and its position there.
pub(super) fn outputs_holding(
    outputs: &mut Vec<NetworkOutput>,
    id: ElementId,
) -> Option<(&mut Vec<NetworkOutput>, usize)> {
    if let Some(position) = outputs.iter().position(|output| output.id() == id) {
        return Some((outputs, position));
    }
    outputs.iter_mut().find_map(|output| match output {
        NetworkOutput::Branch { outputs, .. } => outputs_holding(outputs, id),
        _ => None,
    })
}

/// The chain whose power feeds the output list holding output `id`.
pub(super) fn chain_feeding_output(
    network: &mut Network,
    id: ElementId,
) -> Option<&mut Vec<FlowNode>> {
    if network.outputs.iter().any(|output| output.id() == id) {
        return Some(&mut network.rung);
    }
    fn in_outputs(outputs: &mut [NetworkOutput], id: ElementId) -> Option<&mut Vec<FlowNode>> {
        outputs.iter_mut().find_map(|output| match output {
            NetworkOutput::Branch { rung, outputs, .. } => {
                if outputs.iter().any(|output| output.id() == id) {
                    Some(rung)
                } else {
                    in_outputs(outputs, id)
                }
            }
            _ => None,
        })
    }
    in_outputs(&mut network.outputs, id)
}

/// The output list fed by the chain that holds element `id` (at any depth), or the list that
/// holds output `id`.
pub(super) fn outputs_fed_by(
    network: &mut Network,
    id: ElementId,
) -> Option<&mut Vec<NetworkOutput>> {
    if chain_contains(&network.rung, id) {
        return Some(&mut network.outputs);
    }
    fn in_outputs(
        outputs: &mut Vec<NetworkOutput>,
        id: ElementId,
    ) -> Option<&mut Vec<NetworkOutput>> {
        if outputs.iter().any(|output| output.id() == id) {
            return Some(outputs);
        }
        outputs.iter_mut().find_map(|output| match output {
            NetworkOutput::Branch { rung, outputs, .. } => {
                if chain_contains(rung, id) {
                    Some(outputs)
                } else {
                    in_outputs(outputs, id)
                }
            }
            _ => None,
        })
    }
    in_outputs(&mut network.outputs, id)
}

/// The parallel group one of whose branches holds only element `id`, and that branch's index.
pub(super) fn parallel_with_sole(
    network: &mut Network,
    id: ElementId,
) -> Option<(&mut Parallel, usize)> {
    fn in_chain(chain: &mut [FlowNode], id: ElementId) -> Option<(&mut Parallel, usize)> {
        chain.iter_mut().find_map(|node| match node {
            FlowNode::Operand(_) => None,
            FlowNode::Parallel(parallel) => {
                let sole = parallel
                    .branches
                    .iter()
                    .position(|branch| branch.rung.len() == 1 && branch.rung[0].id() == id);
                match sole {
                    Some(branch) => Some((parallel, branch)),
                    None => parallel
                        .branches
                        .iter_mut()
                        .find_map(|branch| in_chain(&mut branch.rung, id)),
                }
            }
            FlowNode::Block(block) => block
                .inputs
                .iter_mut()
                .find_map(|input| in_chain(&mut input.source, id)),
        })
    }
    fn in_outputs(outputs: &mut [NetworkOutput], id: ElementId) -> Option<(&mut Parallel, usize)> {
        outputs.iter_mut().find_map(|output| match output {
            NetworkOutput::Branch { rung, outputs, .. } => {
                if chain_contains(rung, id) {
                    in_chain(rung, id)
                } else {
                    in_outputs(outputs, id)
                }
            }
            _ => None,
        })
    }
    if chain_contains(&network.rung, id) {
        in_chain(&mut network.rung, id)
    } else {
        in_outputs(&mut network.outputs, id)
    }
}

/// The output with `id`, at any depth.
pub(super) fn output_mut(network: &mut Network, id: ElementId) -> Option<&mut NetworkOutput> {
    let (outputs, position) = outputs_holding(&mut network.outputs, id)?;
    outputs.get_mut(position)
}

/// Calls `edit` with the element `id` of `network`, if it is there.
pub(super) fn edit_element(
    network: &mut Network,
    id: ElementId,
    mut edit: impl FnMut(ElementMut<'_>),
) {
    if let Some((chain, position)) = chain_holding(network, id) {
        match &mut chain[position] {
            FlowNode::Operand(operand) => edit(ElementMut::Operand(operand)),
            FlowNode::Block(block) => edit(ElementMut::Block(block)),
            FlowNode::Parallel(_) => edit(ElementMut::Other),
        }
    } else if let Some(output) = output_mut(network, id) {
        match output {
            NetworkOutput::Coil(coil) => edit(ElementMut::Coil(coil)),
            NetworkOutput::Jump { label, .. } => edit(ElementMut::Jump(label)),
            _ => edit(ElementMut::Other),
        }
    }
}
