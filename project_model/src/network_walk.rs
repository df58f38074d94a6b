//! Visiting every element of LD/FBD networks, for validation, lookup by id and the lowering.

use crate::{BlockCall, ElementId, FlowNode, Network, NetworkOutput, Operand, Parallel};

/// One element of a network, borrowed.
#[derive(Clone, Copy, Debug)]
pub enum ElementRef<'a> {
    /// A contact or FBD input.
    Operand(&'a Operand),
    /// A parallel group.
    Parallel(&'a Parallel),
    /// A box.
    Block(&'a BlockCall),
    /// A coil, jump, return or output branch.
    Output(&'a NetworkOutput),
}

impl ElementRef<'_> {
    /// The element's stable id.
    pub fn id(&self) -> ElementId {
        match self {
            Self::Operand(operand) => operand.id,
            Self::Parallel(parallel) => parallel.id,
            Self::Block(block) => block.id,
            Self::Output(output) => output.id(),
        }
    }
}

impl Network {
    /// Calls `visit` with every element of the network, depth first in display order: the
    /// rung's chain (a parallel group before its branches, a box before its inputs' sources),
    /// then the outputs (a branch before its chain and outputs).
    pub fn for_each_element<'a>(&'a self, visit: &mut impl FnMut(ElementRef<'a>)) {
        walk_chain(&self.rung, visit);
        walk_outputs(&self.outputs, visit);
    }

    /// The element with `id`, if the network holds it.
    pub fn element(&self, id: ElementId) -> Option<ElementRef<'_>> {
        let mut found = None;
        self.for_each_element(&mut |element| {
            if found.is_none() && element.id() == id {
                found = Some(element);
            }
        });
        found
    }
}

/// The largest element id used in `networks`, or 0 when they hold no element; a new element
/// takes the next one so ids are never reused within a body.
pub fn max_element_id(networks: &[Network]) -> ElementId {
    let mut max = ElementId(0);
    for network in networks {
        network.for_each_element(&mut |element| max = max.max(element.id()));
    }
    max
}

/// Calls `visit` with every element of `chain` and of everything nested in it.
pub fn walk_chain<'a>(chain: &'a [FlowNode], visit: &mut impl FnMut(ElementRef<'a>)) {
    for node in chain {
        match node {
            FlowNode::Operand(operand) => visit(ElementRef::Operand(operand)),
            FlowNode::Parallel(parallel) => {
                visit(ElementRef::Parallel(parallel));
                for branch in &parallel.branches {
                    walk_chain(&branch.rung, visit);
                }
            }
            FlowNode::Block(block) => {
                visit(ElementRef::Block(block));
                for input in &block.inputs {
                    walk_chain(&input.source, visit);
                }
            }
        }
    }
}

/// Calls `visit` with every output of `outputs` and everything in their branches.
pub fn walk_outputs<'a>(outputs: &'a [NetworkOutput], visit: &mut impl FnMut(ElementRef<'a>)) {
    for output in outputs {
        visit(ElementRef::Output(output));
        if let NetworkOutput::Branch { rung, outputs, .. } = output {
            walk_chain(rung, visit);
            walk_outputs(outputs, visit);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BlockInput, BlockOutput, Branch, Coil};

    fn operand(id: u32, text: &str) -> FlowNode {
        FlowNode::Operand(Operand {
            id: ElementId(id),
            text: text.into(),
            ..Operand::default()
        })
    }

    /// `a` then (`b` parallel to `c`) then a TON box fed by `d` on PT, driving coil `q` and a
    /// branch with contact `e` and a return.
    fn sample() -> Network {
        Network {
            rung: vec![
                operand(1, "a"),
                FlowNode::Parallel(Parallel {
                    id: ElementId(2),
                    branches: vec![
                        Branch {
                            rung: vec![operand(3, "b")],
                        },
                        Branch {
                            rung: vec![operand(4, "c")],
                        },
                    ],
                }),
                FlowNode::Block(BlockCall {
                    id: ElementId(5),
                    type_name: "TON".into(),
                    instance: "t".into(),
                    inputs: vec![
                        BlockInput {
                            pin: "IN".into(),
                            ..BlockInput::default()
                        },
                        BlockInput {
                            pin: "PT".into(),
                            source: vec![operand(6, "d")],
                            ..BlockInput::default()
                        },
                    ],
                    outputs: vec![BlockOutput {
                        pin: "Q".into(),
                        ..BlockOutput::default()
                    }],
                }),
            ],
            outputs: vec![
                NetworkOutput::Coil(Coil {
                    id: ElementId(7),
                    variable: "q".into(),
                    ..Coil::default()
                }),
                NetworkOutput::Branch {
                    id: ElementId(8),
                    rung: vec![operand(9, "e")],
                    outputs: vec![NetworkOutput::Return { id: ElementId(10) }],
                },
            ],
            ..Network::default()
        }
    }

    #[test]
    fn elements_are_visited_depth_first_in_display_order() {
        let network = sample();
        let mut ids = Vec::new();
        network.for_each_element(&mut |element| ids.push(element.id().0));
        assert_eq!(ids, (1..=10).collect::<Vec<_>>());
    }

    #[test]
    fn elements_are_found_by_id_and_the_largest_id_is_known() {
        let network = sample();
        assert!(matches!(
            network.element(ElementId(6)),
            Some(ElementRef::Operand(operand)) if operand.text == "d"
        ));
        assert!(network.element(ElementId(11)).is_none());
        assert_eq!(
            max_element_id(&[Network::default(), network]),
            ElementId(10)
        );
        assert_eq!(max_element_id(&[]), ElementId(0));
    }
}
