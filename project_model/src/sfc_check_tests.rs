use super::*;
use crate::{ActionAssociation, ActionQualifier, MacroStep, SfcBranches, Step};

fn step(id: u32, name: &str) -> SfcNode {
    SfcNode::step(ElementId(id), name)
}

fn transition(id: u32, condition: &str) -> SfcNode {
    SfcNode::transition(ElementId(id), condition)
}

fn jump(id: u32, target: &str) -> SfcNode {
    SfcNode::jump(ElementId(id), target)
}

fn branches(id: u32, branches: Vec<Vec<SfcNode>>) -> SfcBranches {
    SfcBranches::new(ElementId(id), branches)
}

fn chart(sequence: Vec<SfcNode>) -> SfcChart {
    SfcChart { sequence }
}

#[track_caller]
fn one_problem(chart: &SfcChart, expected: &str) {
    assert_eq!(sfc_problems(chart), vec![expected.to_owned()]);
}

/// A sound chart with every kind of node: an alternative, a parallel branch and a macro step.
fn sound() -> SfcChart {
    chart(vec![
        step(1, "Init"),
        SfcNode::Alternative(branches(
            2,
            vec![
                vec![transition(3, "a")],
                vec![transition(4, "b"), jump(5, "Init")],
            ],
        )),
        SfcNode::Parallel(branches(
            6,
            vec![
                vec![step(7, "Left")],
                vec![SfcNode::Macro(MacroStep {
                    id: ElementId(8),
                    name: "Right".into(),
                    body: vec![step(9, "R1"), transition(10, "c"), step(11, "R2")],
                    ..MacroStep::default()
                })],
            ],
        )),
        transition(12, "d"),
        jump(13, "Init"),
    ])
}

#[test]
fn a_sound_chart_and_the_new_body_have_no_problem() {
    assert_eq!(sfc_problems(&sound()), Vec::<String>::new());
    assert_eq!(sfc_problems(&SfcChart::new_body()), Vec::<String>::new());
}

#[test]
fn ids_are_unique() {
    one_problem(
        &chart(vec![step(1, "Init"), transition(1, "a"), jump(3, "Init")]),
        "element 1: two elements have the id 1",
    );
}

#[test]
fn step_names_are_identifiers_without_double_underscores() {
    one_problem(
        &chart(vec![
            step(1, "no good"),
            transition(2, "a"),
            jump(3, "no good"),
        ]),
        "element 1 'no good': the step name 'no good' is not an identifier (letters, digits and '_')",
    );
    one_problem(
        &chart(vec![step(1, "a__b"), transition(2, "a"), jump(3, "a__b")]),
        "element 1 'a__b': the step name 'a__b' contains '__', which Rivet keeps for itself",
    );
}

#[test]
fn step_names_are_unique_without_case() {
    let problems = sfc_problems(&chart(vec![
        step(1, "Init"),
        transition(2, "a"),
        step(3, "INIT"),
        transition(4, "b"),
        jump(5, "Init"),
    ]));
    assert_eq!(
        problems,
        vec![
            "element 1 'Init': 2 steps are named 'Init'",
            "element 3 'INIT': 2 steps are named 'INIT'"
        ]
    );
}

#[test]
fn steps_and_transitions_alternate() {
    one_problem(
        &chart(vec![
            step(1, "Init"),
            step(2, "Two"),
            transition(3, "a"),
            jump(4, "Init"),
        ]),
        "element 2 'Two': a step cannot follow a step; a transition or an alternative branch must",
    );
    one_problem(
        &chart(vec![
            step(1, "Init"),
            transition(2, "a"),
            transition(3, "b"),
            jump(4, "Init"),
        ]),
        "element 3: a transition cannot follow a transition; a step, a macro step, a parallel \
         branch or a jump must",
    );
}

#[test]
fn the_main_sequence_begins_with_a_step_and_ends_with_a_jump() {
    one_problem(
        &chart(vec![
            transition(1, "a"),
            step(2, "Init"),
            transition(3, "b"),
            jump(4, "Init"),
        ]),
        "element 1: the chart must begin with its initial step, not a transition",
    );
    one_problem(
        &chart(vec![step(1, "Init"), transition(2, "a"), step(3, "End")]),
        "element 3 'End': the chart must end with a jump (or an alternative branch whose every \
         branch ends with a jump)",
    );
    one_problem(
        &chart(Vec::new()),
        "the chart is empty; it must begin with its initial step",
    );
}

#[test]
fn an_alternative_whose_every_branch_jumps_ends_the_chart() {
    let ends = chart(vec![
        step(1, "Init"),
        SfcNode::Alternative(branches(
            2,
            vec![
                vec![transition(3, "a"), jump(4, "Init")],
                vec![transition(5, "b"), jump(6, "Init")],
            ],
        )),
    ]);
    assert_eq!(sfc_problems(&ends), Vec::<String>::new());
}

#[test]
fn a_jump_is_last_and_names_an_existing_step() {
    one_problem(
        &chart(vec![
            step(1, "Init"),
            transition(2, "a"),
            jump(3, "Init"),
            step(4, "After"),
        ]),
        "element 4 'After': nothing may follow a jump in its sequence",
    );
    one_problem(
        &chart(vec![
            step(1, "Init"),
            transition(2, "a"),
            jump(3, "Nowhere"),
        ]),
        "element 3: the jump names the step 'Nowhere', which does not exist",
    );
}

#[test]
fn branches_have_their_shapes_and_at_least_two_of_them() {
    one_problem(
        &chart(vec![
            step(1, "Init"),
            SfcNode::Alternative(branches(
                2,
                vec![vec![transition(3, "a")], vec![step(4, "X")]],
            )),
            jump(5, "Init"),
        ]),
        "element 4 'X': a branch of an alternative must begin with a transition, not a step",
    );
    one_problem(
        &chart(vec![
            step(1, "Init"),
            transition(2, "a"),
            SfcNode::Parallel(branches(
                3,
                vec![vec![step(4, "L")], vec![step(5, "R"), transition(6, "b")]],
            )),
            transition(7, "c"),
            jump(8, "Init"),
        ]),
        "element 6: a branch of a parallel branch must end with a step",
    );
    one_problem(
        &chart(vec![
            step(1, "Init"),
            SfcNode::Alternative(branches(2, vec![vec![transition(3, "a")]])),
            jump(4, "Init"),
        ]),
        "element 2: an alternative branch needs at least two branches; it has 1",
    );
}

#[test]
fn a_macro_body_begins_and_ends_with_a_step_and_holds_no_jump() {
    let with_body = |body: Vec<SfcNode>| {
        chart(vec![
            step(1, "Init"),
            transition(2, "a"),
            SfcNode::Macro(MacroStep {
                id: ElementId(3),
                name: "M".into(),
                body,
                ..MacroStep::default()
            }),
            transition(4, "b"),
            jump(5, "Init"),
        ])
    };
    one_problem(
        &with_body(vec![step(6, "In"), transition(7, "c")]),
        "element 7: the body of a macro step must end with a step",
    );
    assert_eq!(
        sfc_problems(&with_body(vec![
            step(6, "In"),
            transition(7, "c"),
            jump(8, "Init")
        ])),
        vec![
            "element 8: a macro step's body cannot hold a jump",
            "element 8: the body of a macro step must end with a step"
        ]
    );
}

#[test]
fn a_duration_is_given_exactly_for_the_timed_qualifiers() {
    let with = |qualifier, duration: Option<&str>| {
        chart(vec![
            SfcNode::Step(Step {
                id: ElementId(1),
                name: "Init".into(),
                actions: vec![ActionAssociation {
                    action: "Horn".into(),
                    qualifier,
                    duration: duration.map(str::to_owned),
                    indicator: None,
                }],
                ..Step::default()
            }),
            transition(2, "a"),
            jump(3, "Init"),
        ])
    };
    one_problem(
        &with(ActionQualifier::L, None),
        "element 1 'Init': the association of 'Horn' with L needs a time",
    );
    one_problem(
        &with(ActionQualifier::N, Some("T#1s")),
        "element 1 'Init': the association of 'Horn' with N takes no time; only L, D, SD, DS \
         and SL do",
    );
    assert_eq!(
        sfc_problems(&with(ActionQualifier::SD, Some("tDelay"))),
        Vec::<String>::new()
    );
}

#[test]
fn a_branch_is_not_empty_and_an_association_names_its_action() {
    one_problem(
        &chart(vec![
            step(1, "Init"),
            SfcNode::Alternative(branches(2, vec![vec![transition(3, "a")], Vec::new()])),
            jump(4, "Init"),
        ]),
        "element 2: branch 2 is empty",
    );
    one_problem(
        &chart(vec![
            SfcNode::Step(Step {
                id: ElementId(1),
                name: "Init".into(),
                actions: vec![ActionAssociation {
                    action: " ".into(),
                    qualifier: ActionQualifier::N,
                    duration: None,
                    indicator: None,
                }],
                ..Step::default()
            }),
            transition(2, "a"),
            jump(3, "Init"),
        ]),
        "element 1 'Init': an action association names no action",
    );
}

#[test]
fn a_branch_ends_as_the_header_of_sfc_rs_says_and_edits_get_the_same_finding_typed() {
    // A parallel branch ending in a parallel branch, and an alternative branch ending in an
    // alternative branch, break the rules of `sfc.rs` (the load check once let them pass).
    let nested_parallel = chart(vec![
        step(1, "Init"),
        transition(2, "a"),
        SfcNode::Parallel(branches(
            3,
            vec![
                vec![step(4, "L")],
                vec![
                    step(5, "R"),
                    transition(6, "b"),
                    SfcNode::Parallel(branches(7, vec![vec![step(8, "X")], vec![step(9, "Y")]])),
                ],
            ],
        )),
        transition(10, "c"),
        jump(11, "Init"),
    ]);
    one_problem(
        &nested_parallel,
        "element 7: a branch of a parallel branch must end with a step",
    );
    let problems = sfc_chart_problems(&nested_parallel);
    assert_eq!(
        problems[0].to_edit_error(),
        crate::sfc_edit::SfcEditError::Structure {
            rule: SfcRule::ParallelEndsWithStep,
            element: ElementId(7)
        }
    );
    assert_eq!(
        crate::sfc_edit::check_structure(&nested_parallel),
        Err(problems[0].to_edit_error())
    );
    let nested_alternative = chart(vec![
        step(1, "Init"),
        SfcNode::Alternative(branches(
            2,
            vec![
                vec![transition(3, "a"), jump(4, "Init")],
                vec![
                    transition(5, "b"),
                    step(6, "S"),
                    SfcNode::Alternative(branches(
                        7,
                        vec![vec![transition(8, "c")], vec![transition(9, "d")]],
                    )),
                ],
            ],
        )),
        step(10, "After"),
        transition(11, "e"),
        jump(12, "Init"),
    ]);
    one_problem(
        &nested_alternative,
        "element 7: a branch of an alternative must end with a transition or a jump",
    );
}
