//! The normal form of an LD/FBD network: one spelling for each network the model can write in
//! two ways that draw and run the same.
//!
//! A PLCopen graph holds a network's wires, not the model's nesting, so an import rebuilds one
//! of the spellings; the export and the import agree on this one (`docs/plcopen-xml.md` §3.4).
//! Each rule keeps every element and the order in which the lowering runs them:
//!
//! - a parallel branch that is one parallel group gives its branches to the enclosing group
//!   (OR is associative), and a parallel group of one branch is that branch's chain;
//! - an output branch without elements gives its outputs to the enclosing list in its place,
//!   and outputs that are a single branch continue the chain before them; a branch that drives
//!   nothing is left as it is (merged, it would leave a result unused, or vanish).

use crate::{FlowNode, MAX_NETWORK_NESTING, Network, NetworkOutput};

/// Brings every network of a body into the normal form; element ids are kept.
pub fn normalize_networks(networks: &mut [Network]) {
    for network in networks {
        normalize_network(network);
    }
}

/// Brings `network` into the normal form; element ids are kept. A network nested deeper than
/// [`MAX_NETWORK_NESTING`] is left as it is, for `network_problems` to refuse: the rules below
/// recurse into the nesting.
pub fn normalize_network(network: &mut Network) {
    if is_nested_too_deeply(network) {
        return;
    }
    let mut outputs = std::mem::take(&mut network.outputs);
    normalize_outputs(&mut outputs);
    // A lone branch that drives nothing stays a branch: merged into the rung it would leave
    // the network's result unused, which the lowering refuses.
    while let [NetworkOutput::Branch { outputs: inner, .. }] = outputs.as_slice()
        && !inner.is_empty()
    {
        let Some(NetworkOutput::Branch {
            rung,
            outputs: inner,
            ..
        }) = outputs.pop()
        else {
            break;
        };
        network.rung.extend(rung);
        outputs = inner;
    }
    network.outputs = outputs;
    normalize_chain(&mut network.rung);
}

/// Whether an element of `network` lies [`MAX_NETWORK_NESTING`] levels deep or deeper (in
/// parallel branches, box inputs and output branches), the depth at which `network_problems`
/// refuses it; found without recursion, so any depth is answered.
pub fn is_nested_too_deeply(network: &Network) -> bool {
    enum Part<'n> {
        Chain(&'n [FlowNode]),
        Outputs(&'n [NetworkOutput]),
    }
    let mut stack = vec![
        (Part::Chain(&network.rung), 0usize),
        (Part::Outputs(&network.outputs), 0),
    ];
    while let Some((part, depth)) = stack.pop() {
        let is_empty = match part {
            Part::Chain(chain) => chain.is_empty(),
            Part::Outputs(outputs) => outputs.is_empty(),
        };
        if is_empty {
            continue;
        }
        if depth >= MAX_NETWORK_NESTING {
            return true;
        }
        match part {
            Part::Chain(chain) => {
                for node in chain {
                    match node {
                        FlowNode::Operand(_) => {}
                        FlowNode::Parallel(parallel) => stack.extend(
                            parallel
                                .branches
                                .iter()
                                .map(|branch| (Part::Chain(&branch.rung), depth + 1)),
                        ),
                        FlowNode::Block(block) => stack.extend(
                            block
                                .inputs
                                .iter()
                                .map(|input| (Part::Chain(&input.source), depth + 1)),
                        ),
                    }
                }
            }
            Part::Outputs(outputs) => {
                for output in outputs {
                    if let NetworkOutput::Branch {
                        rung,
                        outputs: inner,
                        ..
                    } = output
                    {
                        stack.push((Part::Chain(rung), depth + 1));
                        stack.push((Part::Outputs(inner), depth + 1));
                    }
                }
            }
        }
    }
    false
}

/// Normalizes a chain and the chains inside it.
fn normalize_chain(chain: &mut Vec<FlowNode>) {
    let mut nodes = Vec::with_capacity(chain.len());
    for mut node in std::mem::take(chain) {
        match &mut node {
            FlowNode::Operand(_) => {}
            FlowNode::Block(block) => {
                for input in &mut block.inputs {
                    normalize_chain(&mut input.source);
                }
            }
            FlowNode::Parallel(parallel) => {
                let mut branches = Vec::with_capacity(parallel.branches.len());
                for mut branch in std::mem::take(&mut parallel.branches) {
                    normalize_chain(&mut branch.rung);
                    match branch.rung.as_mut_slice() {
                        [FlowNode::Parallel(inner)] => {
                            branches.append(&mut inner.branches);
                        }
                        _ => branches.push(branch),
                    }
                }
                if let [only] = branches.as_mut_slice() {
                    nodes.append(&mut only.rung);
                    continue;
                }
                parallel.branches = branches;
            }
        }
        nodes.push(node);
    }
    *chain = nodes;
}

/// Normalizes the outputs of a rung or branch: the chains of branches, and the outputs of
/// branches without elements spliced in their place.
fn normalize_outputs(outputs: &mut Vec<NetworkOutput>) {
    let mut flat = Vec::with_capacity(outputs.len());
    for output in std::mem::take(outputs) {
        match output {
            NetworkOutput::Branch {
                id,
                mut rung,
                outputs: mut inner,
            } => {
                normalize_outputs(&mut inner);
                // A branch with neither elements nor outputs is kept: the normal form changes
                // the spelling, never drops what a body holds.
                if rung.is_empty() && !inner.is_empty() {
                    flat.append(&mut inner);
                    continue;
                }
                if let [NetworkOutput::Branch { outputs: last, .. }] = inner.as_slice()
                    && !last.is_empty()
                    && let Some(NetworkOutput::Branch {
                        rung: more,
                        outputs: last,
                        ..
                    }) = inner.pop()
                {
                    rung.extend(more);
                    inner = last;
                }
                normalize_chain(&mut rung);
                flat.push(NetworkOutput::Branch {
                    id,
                    rung,
                    outputs: inner,
                });
            }
            other => flat.push(other),
        }
    }
    *outputs = flat;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BlockCall, BlockInput, BlockOutput, Branch, Coil, ElementId, Operand, Parallel};

    fn operand(id: u32, text: &str) -> FlowNode {
        FlowNode::Operand(Operand {
            id: ElementId(id),
            text: text.to_owned(),
            ..Operand::default()
        })
    }

    fn block(id: u32, first_source: Vec<FlowNode>) -> FlowNode {
        FlowNode::Block(BlockCall {
            id: ElementId(id),
            type_name: "ADD".to_owned(),
            inputs: vec![
                BlockInput {
                    pin: "IN1".to_owned(),
                    source: first_source,
                    ..BlockInput::default()
                },
                BlockInput {
                    pin: "IN2".to_owned(),
                    ..BlockInput::default()
                },
            ],
            outputs: vec![BlockOutput {
                pin: "OUT".to_owned(),
                ..BlockOutput::default()
            }],
            ..BlockCall::default()
        })
    }

    fn parallel(id: u32, branches: Vec<Vec<FlowNode>>) -> FlowNode {
        FlowNode::Parallel(Parallel {
            id: ElementId(id),
            branches: branches.into_iter().map(|rung| Branch { rung }).collect(),
        })
    }

    fn coil(id: u32, variable: &str) -> NetworkOutput {
        NetworkOutput::Coil(Coil {
            id: ElementId(id),
            variable: variable.to_owned(),
            ..Coil::default()
        })
    }

    fn normalized(network: &Network) -> Network {
        let mut copy = network.clone();
        normalize_network(&mut copy);
        copy
    }

    #[test]
    fn a_source_of_a_first_box_stays_at_its_pin_and_nested_chains_are_normalized() {
        // The lowering takes what stands before a box as power, a first input's own source as
        // a value: the two spellings differ, so both stay as they are.
        let nested = parallel(
            5,
            vec![
                vec![parallel(
                    6,
                    vec![vec![operand(7, "c")], vec![operand(8, "d")]],
                )],
                vec![operand(9, "e")],
            ],
        );
        let network = Network {
            rung: vec![block(1, vec![operand(2, "a")]), operand(3, "b")],
            ..Network::default()
        };
        assert_eq!(normalized(&network), network);
        let with_group = Network {
            rung: vec![block(1, vec![nested])],
            ..Network::default()
        };
        let FlowNode::Block(call) = &normalized(&with_group).rung[0] else {
            panic!("not a box")
        };
        assert_eq!(
            call.inputs[0].source,
            vec![parallel(
                5,
                vec![
                    vec![operand(7, "c")],
                    vec![operand(8, "d")],
                    vec![operand(9, "e")]
                ]
            )]
        );
    }

    #[test]
    fn a_branch_holding_one_parallel_group_gives_its_branches_to_the_enclosing_group() {
        let nested = parallel(2, vec![vec![operand(3, "a")], vec![operand(4, "b")]]);
        let network = Network {
            rung: vec![parallel(1, vec![vec![nested], vec![operand(5, "c")]])],
            ..Network::default()
        };
        let Network { rung, .. } = normalized(&network);
        assert_eq!(
            rung,
            vec![parallel(
                1,
                vec![
                    vec![operand(3, "a")],
                    vec![operand(4, "b")],
                    vec![operand(5, "c")]
                ]
            )]
        );
        // A group of one branch is its chain.
        let single = Network {
            rung: vec![operand(1, "x"), parallel(2, vec![vec![operand(3, "a")]])],
            ..Network::default()
        };
        assert_eq!(
            normalized(&single).rung,
            vec![operand(1, "x"), operand(3, "a")]
        );
    }

    #[test]
    fn output_branches_without_elements_or_alone_are_merged_into_what_holds_them() {
        let network = Network {
            rung: vec![operand(1, "a")],
            outputs: vec![
                coil(2, "x"),
                NetworkOutput::Branch {
                    id: ElementId(3),
                    rung: Vec::new(),
                    outputs: vec![coil(4, "y"), coil(5, "z")],
                },
            ],
            ..Network::default()
        };
        assert_eq!(
            normalized(&network).outputs,
            vec![coil(2, "x"), coil(4, "y"), coil(5, "z")]
        );
        let alone = Network {
            rung: vec![operand(1, "a")],
            outputs: vec![NetworkOutput::Branch {
                id: ElementId(2),
                rung: vec![operand(3, "b")],
                outputs: vec![
                    coil(4, "y"),
                    NetworkOutput::Branch {
                        id: ElementId(5),
                        rung: vec![operand(6, "c")],
                        outputs: vec![NetworkOutput::Branch {
                            id: ElementId(7),
                            rung: vec![operand(8, "d")],
                            outputs: vec![coil(9, "z")],
                        }],
                    },
                ],
            }],
            ..Network::default()
        };
        let result = normalized(&alone);
        assert_eq!(result.rung, vec![operand(1, "a"), operand(3, "b")]);
        assert_eq!(
            result.outputs,
            vec![
                coil(4, "y"),
                NetworkOutput::Branch {
                    id: ElementId(5),
                    rung: vec![operand(6, "c"), operand(8, "d")],
                    outputs: vec![coil(9, "z")],
                }
            ]
        );
    }

    #[test]
    fn a_network_in_the_normal_form_is_left_as_it_is() {
        let network = Network {
            rung: vec![
                operand(1, "a"),
                parallel(2, vec![vec![operand(3, "b")], vec![operand(4, "c")]]),
                block(5, vec![]),
            ],
            outputs: vec![
                coil(6, "x"),
                NetworkOutput::Branch {
                    id: ElementId(7),
                    rung: vec![operand(8, "d")],
                    outputs: vec![coil(9, "y")],
                },
            ],
            ..Network::default()
        };
        assert_eq!(normalized(&network), network);
    }

    #[test]
    fn a_branch_that_drives_nothing_is_neither_merged_nor_dropped() {
        // Merged into the rung, the group's result would go nowhere, which the lowering refuses.
        let lone = Network {
            rung: vec![operand(1, "a")],
            outputs: vec![NetworkOutput::Branch {
                id: ElementId(2),
                rung: vec![parallel(
                    3,
                    vec![vec![operand(4, "a")], vec![operand(5, "b")]],
                )],
                outputs: Vec::new(),
            }],
            ..Network::default()
        };
        assert_eq!(normalized(&lone), lone);
        let nested = Network {
            rung: vec![operand(1, "a")],
            outputs: vec![
                coil(2, "x"),
                NetworkOutput::Branch {
                    id: ElementId(3),
                    rung: vec![operand(4, "b")],
                    outputs: vec![NetworkOutput::Branch {
                        id: ElementId(5),
                        rung: vec![operand(6, "c")],
                        outputs: Vec::new(),
                    }],
                },
                NetworkOutput::Branch {
                    id: ElementId(7),
                    rung: Vec::new(),
                    outputs: Vec::new(),
                },
            ],
            ..Network::default()
        };
        assert_eq!(normalized(&nested), nested);
    }

    /// A rung of `levels` parallel groups of one branch each, one inside the other.
    fn groups_of_one_branch(levels: u32) -> Network {
        let mut chain = vec![operand(1, "a")];
        for level in 0..levels {
            chain = vec![parallel(level + 2, vec![chain])];
        }
        Network {
            rung: chain,
            outputs: vec![coil(levels + 2, "x")],
            ..Network::default()
        }
    }

    #[test]
    fn a_network_nested_too_deeply_is_left_for_the_check_to_refuse() {
        let limit = MAX_NETWORK_NESTING as u32;
        // The operand in `limit` groups lies `limit` levels deep.
        assert!(!is_nested_too_deeply(&groups_of_one_branch(limit - 1)));
        assert!(is_nested_too_deeply(&groups_of_one_branch(limit)));
        let deep = groups_of_one_branch(limit + 36);
        assert_eq!(normalized(&deep), deep);
        assert!(!crate::network_problems(std::slice::from_ref(&deep)).is_empty());
        // Within the limit, the groups of one branch are their chains.
        assert_eq!(
            normalized(&groups_of_one_branch(limit - 1)).rung,
            vec![operand(1, "a")]
        );
    }
}
