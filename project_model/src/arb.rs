//! Proptest strategies for the model, used by the round-trip and undo property tests.
//!
//! The model types derive `Arbitrary` when the `proptest` feature is on; these helpers keep the
//! generated values within what a project file can hold (identifiers for names, finite numbers,
//! short lists) and [`project`] makes the names in a project unique as the loader requires.

use proptest::prelude::*;

use crate::{
    BlockCall, BlockInput, BlockOutput, Body, Branch, Coil, CoilKind, Edge, ElementId, FlowNode,
    Folder, GlobalVarList, Network, NetworkOutput, Node, Object, Operand, Parallel, Pou, Project,
};

/// An IEC identifier of one to eight characters, sometimes with a Chinese letter.
pub fn ident() -> impl Strategy<Value = String> {
    "[A-Za-z_输送][A-Za-z0-9_带]{0,7}"
}

/// A finite `f64`; NaN would make equality checks meaningless.
pub fn finite() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        -1.0e6..1.0e6f64,
        proptest::num::f64::NORMAL | proptest::num::f64::ZERO,
    ]
}

/// A list of at most three elements, to keep nested structures small.
pub fn small_vec<T: Arbitrary>() -> impl Strategy<Value = Vec<T>> {
    proptest::collection::vec(any::<T>(), 0..3)
}

/// A list of at most three identifiers.
pub fn ident_vec() -> impl Strategy<Value = Vec<String>> {
    proptest::collection::vec(ident(), 0..3)
}

/// An optional identifier.
pub fn opt_ident() -> impl Strategy<Value = Option<String>> {
    proptest::option::of(ident())
}

/// Free text, including line breaks, quotes and non-ASCII characters.
pub fn text() -> impl Strategy<Value = String> {
    prop_oneof![Just(String::new()), "[ -~\n\t\"'\\\\中文]{0,40}"]
}

/// An optional short text.
pub fn opt_text() -> impl Strategy<Value = Option<String>> {
    proptest::option::of(text())
}

/// A folder holding only objects, so generated trees stay finite.
pub fn leaf_folder() -> impl Strategy<Value = Folder> {
    let children = proptest::collection::vec(any::<Object>().prop_map(Node::Object), 0..3);
    (ident(), children).prop_map(|(name, children)| Folder { name, children })
}

/// A project whose object and folder names are unique, as a loaded project's are. It always
/// holds at least one POU with an ST body and one global variable list, so text and variable
/// edits have something to work on.
pub fn project() -> impl Strategy<Value = Project> {
    (
        any::<Project>(),
        any::<Pou>(),
        any::<GlobalVarList>(),
        text(),
    )
        .prop_map(|(mut project, mut pou, gvl, body)| {
            pou.body = Body::St { text: body };
            project
                .application
                .children
                .push(Node::Object(Object::Pou(pou)));
            project
                .application
                .children
                .push(Node::Object(Object::Gvl(gvl)));
            // The root folder is the application itself; its name is not stored.
            project.application.name.clear();
            let mut counter = 0usize;
            make_names_unique(&mut project.application, &mut counter);
            project
        })
}

/// Appends a running number to every name in the tree, so no two objects or folders collide.
fn make_names_unique(folder: &mut Folder, counter: &mut usize) {
    for node in &mut folder.children {
        *counter += 1;
        match node {
            Node::Folder(child) => {
                child.name = format!("{}_{counter}", child.name);
                make_names_unique(child, counter);
            }
            Node::Object(object) => {
                let name = format!("{}_{counter}", object.name());
                object.set_name(name);
                if let Object::Pou(pou) = object {
                    make_member_names_unique(pou);
                }
            }
        }
    }
}

/// Methods, properties and actions get files named after them, so their names must differ too.
fn make_member_names_unique(pou: &mut Pou) {
    let names = pou
        .methods
        .iter_mut()
        .map(|method| &mut method.name)
        .chain(pou.properties.iter_mut().map(|property| &mut property.name))
        .chain(pou.actions.iter_mut().map(|action| &mut action.name))
        .chain(pou.transitions.iter_mut().map(|t| &mut t.name));
    for (index, name) in names.enumerate() {
        *name = format!("{name}_{index}");
    }
}

/// A list of up to three LD/FBD networks that keep the rules of `network_check`, as a loaded
/// body's do: unique ids and labels, distinct pins, and no first input driven twice.
pub fn networks() -> impl Strategy<Value = Vec<Network>> {
    networks_from(1)
}

/// Like [`networks`], with element ids counted from `first_id`: networks to insert into a body
/// whose ids are all below it.
pub fn networks_from(first_id: u32) -> impl Strategy<Value = Vec<Network>> {
    proptest::collection::vec(network(), 0..3).prop_map(move |mut networks| {
        let mut next = first_id;
        for (index, network) in networks.iter_mut().enumerate() {
            if !network.label.is_empty() {
                network.label = format!("{}_{index}", network.label);
            }
            renumber_chain(&mut network.rung, &mut next, false);
            renumber_outputs(&mut network.outputs, &mut next);
        }
        networks
    })
}

/// One network with nested parallel branches, boxes and output branches.
fn network() -> impl Strategy<Value = Network> {
    (
        text(),
        text(),
        prop_oneof![Just(String::new()), ident()],
        chain(),
        outputs(),
    )
        .prop_map(|(title, comment, label, rung, outputs)| Network {
            title,
            comment,
            label,
            rung,
            outputs,
        })
}

/// A chain of operands, parallel groups and boxes, nested at most three levels deep.
fn chain() -> impl Strategy<Value = Vec<FlowNode>> {
    let operand = (text(), any::<bool>(), any::<Edge>()).prop_map(|(text, negated, edge)| {
        FlowNode::Operand(Operand {
            id: ElementId(0),
            text,
            negated,
            edge,
        })
    });
    let leaf = proptest::collection::vec(operand, 0..3);
    leaf.prop_recursive(3, 16, 3, |inner| {
        let parallel = proptest::collection::vec(inner.clone(), 2..4).prop_map(|branches| {
            FlowNode::Parallel(Parallel {
                id: ElementId(0),
                branches: branches.into_iter().map(|rung| Branch { rung }).collect(),
            })
        });
        let input = (ident(), any::<bool>(), any::<Edge>(), inner.clone()).prop_map(
            |(pin, negated, edge, source)| BlockInput {
                pin,
                negated,
                edge,
                source,
            },
        );
        let output = (
            ident(),
            any::<bool>(),
            prop_oneof![Just(String::new()), ident()],
        )
            .prop_map(|(pin, negated, assign)| BlockOutput {
                pin,
                negated,
                assign,
            });
        let block = (
            ident(),
            prop_oneof![Just(String::new()), ident()],
            proptest::collection::vec(input, 0..3),
            proptest::collection::vec(output, 1..3),
        )
            .prop_map(|(type_name, instance, mut inputs, mut outputs)| {
                // Pins of one box have distinct names.
                for (index, input) in inputs.iter_mut().enumerate() {
                    input.pin = format!("{}_i{index}", input.pin);
                }
                for (index, output) in outputs.iter_mut().enumerate() {
                    output.pin = format!("{}_o{index}", output.pin);
                }
                FlowNode::Block(BlockCall {
                    id: ElementId(0),
                    type_name,
                    instance,
                    inputs,
                    outputs,
                })
            });
        let element = prop_oneof![parallel, block];
        (inner, proptest::collection::vec(element, 0..3)).prop_map(|(mut operands, elements)| {
            operands.extend(elements);
            operands
        })
    })
}

/// Coils, jumps, returns and output branches.
fn outputs() -> impl Strategy<Value = Vec<NetworkOutput>> {
    let leaf = prop_oneof![
        (ident(), any::<CoilKind>()).prop_map(|(variable, kind)| NetworkOutput::Coil(Coil {
            id: ElementId(0),
            variable,
            kind,
        })),
        ident().prop_map(|label| NetworkOutput::Jump {
            id: ElementId(0),
            label,
        }),
        Just(NetworkOutput::Return { id: ElementId(0) }),
    ];
    let leaves = proptest::collection::vec(leaf, 0..3);
    leaves.prop_recursive(2, 8, 3, |inner| {
        proptest::collection::vec(
            (chain(), inner).prop_map(|(rung, outputs)| NetworkOutput::Branch {
                id: ElementId(0),
                rung,
                outputs,
            }),
            0..3,
        )
    })
}

/// Up to three LD/FBD networks as an editor draws them, keeping the rules of `network_check`:
/// operands, coils, pins and labels are identifiers, every rung has an element, parallel groups
/// have two or three branches with elements (one group of the rung and of each output branch
/// may have an empty one where one wire feeds it), boxes have an input and an
/// output (so the power goes on) and assign only their other outputs, and a first input has a
/// source only where nothing else feeds it; outputs come in any order. What a PLCopen graph
/// holds, so a plain PLCopen document gives these networks back in the normal form.
pub fn drawn_networks() -> impl Strategy<Value = Vec<Network>> {
    let network = (
        text(),
        text(),
        prop_oneof![Just(String::new()), ident()],
        drawn_chain(),
        drawn_outputs(),
        proptest::option::of(0..3usize),
    )
        .prop_map(|(title, comment, label, mut rung, mut outputs, empty)| {
            if let Some(place) = empty {
                empty_a_branch(&mut rung, place, true);
                let fed_by_one_wire = !matches!(rung.last(), Some(FlowNode::Parallel(_)));
                for output in &mut outputs {
                    if let NetworkOutput::Branch { rung: branch, .. } = output {
                        empty_a_branch(branch, place, fed_by_one_wire);
                    }
                }
            }
            Network {
                title,
                comment,
                label,
                rung,
                outputs,
            }
        });
    proptest::collection::vec(network, 0..4).prop_map(|mut networks| {
        let mut next = 1;
        for (index, network) in networks.iter_mut().enumerate() {
            if !network.label.is_empty() {
                network.label = format!("{}_{index}", network.label);
            }
            renumber_chain(&mut network.rung, &mut next, false);
            renumber_outputs(&mut network.outputs, &mut next);
        }
        networks
    })
}

/// Empties branch `place` (modulo their count) of the first parallel group of `chain` that one
/// wire feeds: the first element when `first_fed_by_one_wire`, else one after an operand or a
/// box. In LD an empty branch is a wire from where the group starts; after another group there
/// is no such point (its branches' ends are wired on one by one), and the import gives the
/// paths expanded instead, which run the same but are another spelling.
fn empty_a_branch(chain: &mut [FlowNode], place: usize, first_fed_by_one_wire: bool) {
    for index in 0..chain.len() {
        let fed_by_one_wire = match index {
            0 => first_fed_by_one_wire,
            _ => !matches!(chain[index - 1], FlowNode::Parallel(_)),
        };
        if let FlowNode::Parallel(parallel) = &mut chain[index]
            && fed_by_one_wire
        {
            let count = parallel.branches.len();
            parallel.branches[place % count].rung.clear();
            return;
        }
    }
}

/// A drawn chain of at least one element: operands (contacts with any modifier), parallel
/// groups and boxes, nested at most three levels deep.
fn drawn_chain() -> impl Strategy<Value = Vec<FlowNode>> {
    let operand = (ident(), any::<bool>(), any::<Edge>()).prop_map(|(text, negated, edge)| {
        FlowNode::Operand(Operand {
            id: ElementId(0),
            text,
            negated,
            edge,
        })
    });
    let leaf = proptest::collection::vec(operand, 1..4);
    leaf.prop_recursive(3, 24, 3, |inner| {
        let parallel = proptest::collection::vec(inner.clone(), 2..4).prop_map(|branches| {
            FlowNode::Parallel(Parallel {
                id: ElementId(0),
                branches: branches.into_iter().map(|rung| Branch { rung }).collect(),
            })
        });
        // An input's source may be empty: the input is left open.
        let source = prop_oneof![Just(Vec::new()), inner.clone()];
        let input =
            (any::<bool>(), any::<Edge>(), source).prop_map(|(negated, edge, source)| BlockInput {
                pin: String::new(),
                negated,
                edge,
                source,
            });
        let output = (any::<bool>(), prop_oneof![Just(String::new()), ident()]).prop_map(
            |(negated, assign)| BlockOutput {
                pin: String::new(),
                negated,
                assign,
            },
        );
        let block = (
            ident(),
            prop_oneof![Just(String::new()), ident()],
            proptest::collection::vec(input, 1..4),
            proptest::collection::vec(output, 1..3),
        )
            .prop_map(|(type_name, instance, mut inputs, mut outputs)| {
                for (index, input) in inputs.iter_mut().enumerate() {
                    input.pin = format!("IN{index}");
                }
                for (index, output) in outputs.iter_mut().enumerate() {
                    output.pin = format!("OUT{index}");
                }
                // The first output passes the power on; the editors draw no assignment on it.
                if let Some(first) = outputs.first_mut() {
                    first.assign.clear();
                }
                FlowNode::Block(BlockCall {
                    id: ElementId(0),
                    type_name,
                    instance,
                    inputs,
                    outputs,
                })
            });
        let element = prop_oneof![parallel, block].boxed();
        prop_oneof![
            (inner, proptest::collection::vec(element.clone(), 0..3)).prop_map(
                |(mut operands, elements)| {
                    operands.extend(elements);
                    operands
                }
            ),
            // A chain that starts with a box or a parallel group.
            proptest::collection::vec(element, 1..3),
        ]
    })
}

/// Drawn outputs, at least one: coils of every kind, jumps, returns and output branches (some
/// without elements, which the normal form takes apart).
fn drawn_outputs() -> impl Strategy<Value = Vec<NetworkOutput>> {
    let leaf = prop_oneof![
        (ident(), any::<CoilKind>()).prop_map(|(variable, kind)| NetworkOutput::Coil(Coil {
            id: ElementId(0),
            variable,
            kind,
        })),
        ident().prop_map(|label| NetworkOutput::Jump {
            id: ElementId(0),
            label,
        }),
        Just(NetworkOutput::Return { id: ElementId(0) }),
    ]
    .boxed();
    // Every rung and branch drives something: an unfinished LD rung ending in a parallel
    // group has no point its branches meet at in a PLCopen graph.
    let leaves = proptest::collection::vec(leaf.clone(), 1..3);
    leaves.prop_recursive(2, 8, 3, move |inner| {
        let rung = prop_oneof![Just(Vec::new()), drawn_chain()];
        let branches = proptest::collection::vec(
            (rung, inner).prop_map(|(rung, outputs)| NetworkOutput::Branch {
                id: ElementId(0),
                rung,
                outputs,
            }),
            1..3,
        );
        // Coils and branches side by side, in any order.
        (proptest::collection::vec(leaf.clone(), 0..3), branches).prop_flat_map(
            |(mut outputs, branches)| {
                outputs.extend(branches);
                Just(outputs).prop_shuffle()
            },
        )
    })
}

/// Gives every element of a chain the next free id, and drops the source of a box's first
/// input where the power also drives it (`fed_by_power`: the chain's start is powered).
fn renumber_chain(chain: &mut [FlowNode], next: &mut u32, fed_by_power: bool) {
    for (position, node) in chain.iter_mut().enumerate() {
        let id = ElementId(*next);
        *next += 1;
        match node {
            FlowNode::Operand(operand) => operand.id = id,
            FlowNode::Parallel(parallel) => {
                parallel.id = id;
                for branch in &mut parallel.branches {
                    renumber_chain(&mut branch.rung, next, true);
                }
            }
            FlowNode::Block(block) => {
                block.id = id;
                if (position > 0 || fed_by_power)
                    && let Some(first) = block.inputs.first_mut()
                {
                    first.source.clear();
                }
                for input in &mut block.inputs {
                    renumber_chain(&mut input.source, next, false);
                }
            }
        }
    }
}

/// Gives every output, and everything in its branches, the next free id.
fn renumber_outputs(outputs: &mut [NetworkOutput], next: &mut u32) {
    for output in outputs {
        let id = ElementId(*next);
        *next += 1;
        match output {
            NetworkOutput::Coil(coil) => coil.id = id,
            NetworkOutput::Jump { id: slot, .. } | NetworkOutput::Return { id: slot } => *slot = id,
            NetworkOutput::Branch {
                id: slot,
                rung,
                outputs,
            } => {
                *slot = id;
                renumber_chain(rung, next, true);
                renumber_outputs(outputs, next);
            }
        }
    }
}

/// A valid CFC chart: inputs wired into an `AND` box whose result goes to an output, with
/// the box and the output numbered in the execution order.
pub fn cfc_chart() -> impl Strategy<Value = crate::CfcChart> {
    use crate::{CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, PinRef, Wire};
    (ident(), ident(), ident(), 0..40i32, 0..40i32).prop_map(|(a, b, out, x, y)| {
        let element = |id: u32, x: i32, y: i32, order: Option<u32>, kind| CfcElement {
            id: ElementId(id),
            x,
            y,
            order,
            kind,
        };
        let pin = |name: &str| CfcPin::named(name);
        let wire = |from: u32, from_pin: &str, to: u32, to_pin: &str| {
            Wire::routed(
                PinRef::new(ElementId(from), from_pin),
                PinRef::new(ElementId(to), to_pin),
            )
        };
        CfcChart {
            elements: vec![
                element(1, x, y, None, CfcElementKind::Input { expression: a }),
                element(2, x, y + 2, None, CfcElementKind::Input { expression: b }),
                element(
                    3,
                    x + 6,
                    y,
                    Some(0),
                    CfcElementKind::Box(CfcBox {
                        type_name: "AND".into(),
                        instance: String::new(),
                        inputs: vec![pin("IN1"), pin("IN2")],
                        outputs: vec![pin("OUT")],
                    }),
                ),
                element(
                    4,
                    x + 12,
                    y,
                    Some(1),
                    CfcElementKind::Output {
                        expression: out,
                        coil: CoilKind::Normal,
                    },
                ),
            ],
            wires: vec![
                wire(1, "", 3, "IN1"),
                wire(2, "", 3, "IN2"),
                wire(3, "OUT", 4, ""),
            ],
        }
    })
}

/// A valid SFC chart: the initial step, then pairs of transitions and steps, and a jump
/// back to the initial step.
pub fn sfc_chart() -> impl Strategy<Value = crate::SfcChart> {
    use crate::{Jump, SfcChart, SfcNode, Step, Transition};
    proptest::collection::vec(ident(), 0..3).prop_map(|conditions| {
        let mut next = 1;
        let mut id = || {
            next += 1;
            ElementId(next - 1)
        };
        let step = |id: ElementId, index: usize| {
            SfcNode::Step(Step {
                id,
                name: format!("Step{index}"),
                ..Step::default()
            })
        };
        let mut sequence = vec![step(id(), 0)];
        for (index, condition) in conditions.into_iter().enumerate() {
            sequence.push(SfcNode::Transition(Transition {
                id: id(),
                condition,
                ..Transition::default()
            }));
            sequence.push(step(id(), index + 1));
        }
        sequence.push(SfcNode::Transition(Transition {
            id: id(),
            condition: "TRUE".into(),
            ..Transition::default()
        }));
        sequence.push(SfcNode::Jump(Jump {
            id: id(),
            target: "Step0".into(),
        }));
        SfcChart { sequence }
    })
}
