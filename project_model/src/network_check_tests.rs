use super::*;
use crate::{BlockInput, BlockOutput, Branch, Coil, Operand, Parallel};

fn operand(id: u32) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: "x".into(),
        ..Operand::default()
    })
}

fn coil(id: u32) -> NetworkOutput {
    NetworkOutput::Coil(Coil {
        id: ElementId(id),
        variable: "q".into(),
        ..Coil::default()
    })
}

fn input(pin: &str, source: Vec<FlowNode>) -> BlockInput {
    BlockInput {
        pin: pin.into(),
        source,
        ..BlockInput::default()
    }
}

fn output(pin: &str) -> BlockOutput {
    BlockOutput {
        pin: pin.into(),
        ..BlockOutput::default()
    }
}

fn block(id: u32, inputs: Vec<BlockInput>, outputs: Vec<BlockOutput>) -> FlowNode {
    FlowNode::Block(BlockCall {
        id: ElementId(id),
        type_name: "ADD".into(),
        inputs,
        outputs,
        ..BlockCall::default()
    })
}

fn network(rung: Vec<FlowNode>, outputs: Vec<NetworkOutput>) -> Network {
    Network {
        rung,
        outputs,
        ..Network::default()
    }
}

/// The problems of a body as the text the loader shows after the POU's name.
fn messages(networks: &[Network]) -> Vec<String> {
    network_problems(networks)
        .iter()
        .map(ToString::to_string)
        .collect()
}

#[test]
fn a_sound_body_has_no_problems() {
    let body = vec![
        network(
            vec![
                operand(1),
                FlowNode::Parallel(Parallel {
                    id: ElementId(2),
                    branches: vec![
                        Branch {
                            rung: vec![operand(3)],
                        },
                        Branch { rung: vec![] },
                    ],
                }),
                block(
                    4,
                    vec![input("IN1", vec![]), input("IN2", vec![operand(5)])],
                    vec![output("OUT")],
                ),
            ],
            vec![coil(6)],
        ),
        network(
            vec![block(
                7,
                vec![input("IN1", vec![operand(8)])],
                vec![output("OUT")],
            )],
            vec![coil(9)],
        ),
    ];
    assert_eq!(messages(&body), Vec::<String>::new());
}

#[test]
fn a_duplicate_id_is_reported_at_its_second_use_in_any_network() {
    let body = vec![
        network(vec![operand(1), operand(1)], vec![]),
        Network {
            label: "Next".into(),
            ..network(vec![], vec![coil(1)])
        },
    ];
    assert_eq!(
        messages(&body),
        [
            "network 1, element 1: two elements have the id 1",
            "network 2 'Next', element 1: two elements have the id 1; the other is in network 1",
        ]
    );
}

#[test]
fn labels_are_identifiers_and_unique_without_case() {
    let labelled = |label: &str| Network {
        label: label.into(),
        ..Network::default()
    };
    assert_eq!(
        messages(&[labelled("Start"), labelled("START"), labelled("no good")]),
        [
            "network 2 'START': the label 'START' is also the label of network 1",
            "network 3 'no good': the label 'no good' is not an identifier (letters, digits and \
             '_')",
        ]
    );
}

#[test]
fn a_box_needs_a_type_name_and_distinct_identifier_pins() {
    let mut bad = BlockCall {
        id: ElementId(4),
        inputs: vec![input("IN", vec![]), input("in", vec![])],
        outputs: vec![output("Q"), output("2nd")],
        ..BlockCall::default()
    };
    bad.type_name = " ".into();
    let body = vec![Network {
        title: "Timer".into(),
        ..network(vec![FlowNode::Block(bad)], vec![])
    }];
    assert_eq!(
        messages(&body),
        [
            "network 1 'Timer', element 4: the box has no type name",
            "network 1 'Timer', element 4: the box has two pins named 'in'",
            "network 1 'Timer', element 4: the pin name '2nd' is not an identifier (letters, \
             digits and '_')",
        ]
    );
}

#[test]
fn a_first_input_with_a_source_is_refused_where_the_power_also_drives_it() {
    let sourced = |id: u32| {
        block(
            id,
            vec![input("IN1", vec![operand(id + 100)])],
            vec![output("OUT")],
        )
    };
    let body = vec![network(
        vec![
            sourced(1),
            sourced(2),
            FlowNode::Parallel(Parallel {
                id: ElementId(3),
                branches: vec![
                    Branch {
                        rung: vec![sourced(4)],
                    },
                    Branch {
                        rung: vec![operand(5)],
                    },
                ],
            }),
        ],
        vec![NetworkOutput::Branch {
            id: ElementId(6),
            rung: vec![sourced(7)],
            outputs: vec![coil(8)],
        }],
    )];
    let problems = network_problems(&body);
    let at: Vec<u32> = problems
        .iter()
        .filter_map(|problem| problem.element.map(|id| id.0))
        .collect();
    assert_eq!(at, [2, 4, 7], "{problems:?}");
    assert!(problems[0].message.contains("driven twice"));
}

#[test]
fn a_box_without_outputs_can_only_end_a_rung_that_drives_nothing() {
    let silent = |id: u32| block(id, vec![input("IN", vec![])], vec![]);
    let fine = vec![network(vec![operand(1), silent(2)], vec![])];
    assert_eq!(messages(&fine), Vec::<String>::new());
    let body = vec![network(vec![silent(1), operand(2)], vec![])];
    assert_eq!(network_problems(&body)[0].element, Some(ElementId(1)));
    let body = vec![network(vec![silent(1)], vec![coil(2)])];
    assert_eq!(network_problems(&body)[0].element, Some(ElementId(1)));
}

#[test]
fn a_parallel_group_needs_two_branches() {
    let body = vec![network(
        vec![FlowNode::Parallel(Parallel {
            id: ElementId(1),
            branches: vec![Branch {
                rung: vec![operand(2)],
            }],
        })],
        vec![],
    )];
    assert_eq!(
        messages(&body),
        ["network 1, element 1: a parallel group needs at least two branches; it has 1"]
    );
}

#[test]
fn nesting_deeper_than_the_limit_is_refused_without_walking_further() {
    let mut chain = vec![operand(0)];
    for id in 1..=(MAX_NETWORK_NESTING as u32 + 5) {
        chain = vec![FlowNode::Parallel(Parallel {
            id: ElementId(id),
            branches: vec![Branch { rung: chain }, Branch { rung: vec![] }],
        })];
    }
    let problems = network_problems(&[network(chain, vec![])]);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert!(problems[0].message.contains("nested more than"));
}
