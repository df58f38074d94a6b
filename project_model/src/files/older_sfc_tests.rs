use super::*;
use crate::PinRef;
use crate::files::graph_chart::Connection;

fn element(id: u32, x: i32, y: i32, kind: ChartElementKind) -> ChartElement {
    ChartElement {
        id: ElementId(id),
        x,
        y,
        execution_order: None,
        kind,
    }
}

fn step(id: u32, x: i32, y: i32, name: &str, initial: bool) -> ChartElement {
    element(
        id,
        x,
        y,
        ChartElementKind::Step {
            name: name.into(),
            initial,
            entry_action: None,
            exit_action: None,
            actions: Vec::new(),
        },
    )
}

fn transition(id: u32, x: i32, y: i32, condition: &str) -> ChartElement {
    element(
        id,
        x,
        y,
        ChartElementKind::Transition {
            condition: condition.into(),
        },
    )
}

fn fork(id: u32, x: i32, y: i32, branch: BranchKind, join: bool) -> ChartElement {
    let kind = if join {
        ChartElementKind::Convergence {
            branch,
            branches: 2,
        }
    } else {
        ChartElementKind::Divergence {
            branch,
            branches: 2,
        }
    };
    element(id, x, y, kind)
}

fn graph(elements: Vec<ChartElement>, wires: &[(u32, u32)]) -> Chart {
    let pin = |id: u32| PinRef {
        element: ElementId(id),
        pin: String::new(),
    };
    Chart {
        elements,
        connections: wires
            .iter()
            .map(|&(from, to)| Connection {
                from: pin(from),
                to: pin(to),
            })
            .collect(),
        ..Chart::default()
    }
}

fn names(nodes: &[SfcNode]) -> Vec<String> {
    nodes
        .iter()
        .map(|node| match node {
            SfcNode::Step(step) => format!("step {}", step.name),
            SfcNode::Transition(t) => format!("transition {}", t.condition),
            SfcNode::Jump(jump) => format!("jump {} to {}", jump.id.0, jump.target),
            SfcNode::Alternative(b) | SfcNode::Parallel(b) => {
                let kind = if matches!(node, SfcNode::Alternative(_)) {
                    "alternative"
                } else {
                    "parallel"
                };
                let inner: Vec<String> = b
                    .branches
                    .iter()
                    .map(|branch| names(&branch.nodes).join(", "))
                    .collect();
                format!("{kind} [{}]", inner.join(" | "))
            }
            SfcNode::Macro(m) => format!("macro {}", m.name),
        })
        .collect()
}

#[test]
fn a_graph_with_an_alternative_and_a_parallel_branch_becomes_the_structured_chart() {
    // Init -> alternative (left: t "go" joins; right: t "stop" jumps to Init) -> parallel
    // (A | B) -> t "done" -> back to Init by a connection.
    let chart = sfc_from_graph(&graph(
        vec![
            step(1, 0, 0, "Init", true),
            fork(2, 0, 1, BranchKind::Selection, false),
            transition(3, 0, 2, "go"),
            transition(4, 5, 2, "stop"),
            element(
                5,
                5,
                3,
                ChartElementKind::StepJump {
                    target: "Init".into(),
                },
            ),
            fork(6, 0, 3, BranchKind::Selection, true),
            fork(7, 0, 4, BranchKind::Simultaneous, false),
            step(8, 0, 5, "A", false),
            step(9, 5, 5, "B", false),
            fork(10, 0, 6, BranchKind::Simultaneous, true),
            transition(11, 0, 7, "done"),
        ],
        &[
            (1, 2),
            (2, 4),
            (2, 3),
            (3, 6),
            (4, 5),
            (6, 7),
            (7, 8),
            (7, 9),
            (8, 10),
            (9, 10),
            (10, 11),
            (11, 1),
        ],
    ))
    .unwrap();
    assert_eq!(
        names(&chart.sequence),
        [
            "step Init",
            "alternative [transition go | transition stop, jump 5 to Init]",
            "parallel [step A | step B]",
            "transition done",
            "jump 12 to Init",
        ]
    );
}

#[test]
fn a_graph_without_a_structure_is_refused_naming_the_element() {
    let two_ways = graph(
        vec![
            step(1, 0, 0, "Init", true),
            transition(2, 0, 1, "a"),
            transition(3, 5, 1, "b"),
        ],
        &[(1, 2), (1, 3), (2, 1), (3, 1)],
    );
    assert_eq!(
        sfc_from_graph(&two_ways),
        Err(vec![
            "element 1: it leads to several elements without a divergence".to_owned()
        ])
    );
    let dangling = graph(
        vec![
            step(1, 0, 0, "Init", true),
            transition(2, 0, 1, "a"),
            step(3, 0, 2, "End", false),
        ],
        &[(1, 2), (2, 3)],
    );
    assert_eq!(
        sfc_from_graph(&dangling),
        Err(vec![
            "element 3: the step 'End' leads nowhere; a sequence ends with a jump".to_owned()
        ])
    );
    let two_initial = graph(
        vec![step(1, 0, 0, "A", true), step(2, 0, 2, "B", true)],
        &[],
    );
    assert_eq!(
        sfc_from_graph(&two_initial),
        Err(vec![
            "element 2: a second initial step; an SFC chart has one".to_owned()
        ])
    );
    let unreached = graph(
        vec![
            step(1, 0, 0, "Init", true),
            transition(2, 0, 1, "a"),
            step(3, 9, 9, "Lost", false),
        ],
        &[(1, 2), (2, 1)],
    );
    assert_eq!(
        sfc_from_graph(&unreached),
        Err(vec![
            "element 3: the initial step does not lead to it, so it has no place in the \
             converted chart"
                .to_owned()
        ])
    );
    let step_after_step = graph(
        vec![step(1, 0, 0, "Init", true), step(2, 0, 1, "Two", false)],
        &[(1, 2), (2, 1)],
    );
    assert_eq!(
        sfc_from_graph(&step_after_step),
        Err(vec![
            "element 2 'Two': a step cannot follow a step; a transition or an alternative \
             branch must"
                .to_owned()
        ])
    );
}
