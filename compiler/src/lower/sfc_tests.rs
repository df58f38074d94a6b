//! The textual SFC generated for charts, as expect-test snapshots (`UPDATE_EXPECT=1 cargo test
//! -p compiler lower` rewrites them after a deliberate change), the probes, and findings in
//! conditions located at their transitions.

use expect_test::{Expect, expect};
use project_model::{
    ActionAssociation, ActionQualifier, Body, ElementId, MacroStep, Object, PouAction, Project,
    SfcBranches, SfcChart, SfcNode, Step, Transition,
};

use crate::SourceProject;
use crate::lower::{ProbeKind, lower_project};

fn step(id: u32, name: &str, actions: &[(&str, ActionQualifier)]) -> SfcNode {
    SfcNode::Step(Step {
        id: ElementId(id),
        name: name.into(),
        actions: actions
            .iter()
            .map(|(action, qualifier)| ActionAssociation {
                action: (*action).into(),
                qualifier: *qualifier,
                duration: None,
                indicator: None,
            })
            .collect(),
        ..Step::default()
    })
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

const DECLARATIONS: &str = "PROGRAM Main
VAR a, b, c, go, lamp, valve : BOOL; n : INT; tMax : TIME; END_VAR
END_PROGRAM
";

/// A project of `DECLARATIONS` whose POU `Main` gets the SFC body `sequence`.
fn project_with(sequence: Vec<SfcNode>) -> Project {
    let mut project = SourceProject::new(DECLARATIONS).project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Sfc {
            chart: SfcChart { sequence },
        };
    }
    project
}

#[track_caller]
fn check_text(project: &Project, expect: Expect) {
    let lowered = lower_project(project);
    expect.assert_eq(&lowered.bodies[0].text);
}

/// A chart with an alternative branch (one branch jumping back) and a parallel branch.
fn branching() -> Vec<SfcNode> {
    vec![
        step(1, "Init", &[("lamp", ActionQualifier::N)]),
        SfcNode::Alternative(branches(
            2,
            vec![
                vec![transition(3, "go")],
                vec![transition(4, "NOT go AND c"), jump(5, "Init")],
            ],
        )),
        SfcNode::Parallel(branches(
            6,
            vec![
                vec![step(7, "Left", &[("valve", ActionQualifier::S)])],
                vec![
                    step(8, "Right", &[]),
                    transition(9, "b"),
                    step(10, "Right2", &[]),
                ],
            ],
        )),
        transition(11, "a"),
        jump(12, "Init"),
    ]
}

#[test]
fn branches_become_transitions_from_and_to_several_steps_in_left_to_right_order() {
    check_text(
        &project_with(branching()),
        expect![[r#"
            INITIAL_STEP Init:
                lamp(N);
            END_STEP
            TRANSITION FROM Init TO (Left, Right) := go; END_TRANSITION
            TRANSITION FROM Init TO Init := NOT go AND c; END_TRANSITION
            STEP Left:
                valve(S);
            END_STEP
            STEP Right:
            END_STEP
            TRANSITION FROM Right TO Right2 := b; END_TRANSITION
            STEP Right2:
            END_STEP
            TRANSITION FROM (Left, Right2) TO Init := a; END_TRANSITION
            __t4 := NOT go AND c;
        "#]],
    );
}

#[test]
fn step_properties_timed_associations_priorities_and_macro_steps_are_written_out() {
    let fill = SfcNode::Step(Step {
        id: ElementId(3),
        name: "Fill".into(),
        min_time: Some("T#1s".into()),
        max_time: Some("tMax".into()),
        entry_action: Some("Open".into()),
        exit_action: Some("Close".into()),
        actions: vec![ActionAssociation {
            action: "Horn".into(),
            qualifier: ActionQualifier::L,
            duration: Some("T#2s".into()),
            indicator: Some("lamp".into()),
        }],
        ..Step::default()
    });
    let prioritised = |id: u32, condition: &str, priority: Option<u32>| {
        SfcNode::Transition(Transition {
            id: ElementId(id),
            condition: condition.into(),
            priority,
            ..Transition::default()
        })
    };
    let sequence = vec![
        step(1, "Init", &[]),
        transition(2, "go"),
        fill,
        SfcNode::Alternative(branches(
            4,
            vec![
                vec![prioritised(5, "a", None), jump(6, "Init")],
                vec![prioritised(7, "b", Some(1)), jump(8, "Fill")],
            ],
        )),
    ];
    check_text(
        &project_with(sequence),
        expect![[r#"
            INITIAL_STEP Init:
            END_STEP
            TRANSITION FROM Init TO Fill := go; END_TRANSITION
            STEP Fill (MIN_TIME := T#1s, MAX_TIME := tMax, ENTRY := Open, EXIT := Close):
                Horn(L, T#2s, lamp);
            END_STEP
            TRANSITION (PRIORITY := 2) FROM Fill TO Init := a; END_TRANSITION
            TRANSITION (PRIORITY := 1) FROM Fill TO Fill := b; END_TRANSITION
        "#]],
    );
    let with_macro = vec![
        step(1, "Init", &[]),
        transition(2, "go"),
        SfcNode::Macro(MacroStep {
            id: ElementId(3),
            name: "Work".into(),
            body: vec![step(4, "W1", &[]), transition(5, "a"), step(6, "W2", &[])],
            ..MacroStep::default()
        }),
        transition(7, "b"),
        jump(8, "Work"),
    ];
    check_text(
        &project_with(with_macro),
        expect![[r#"
            INITIAL_STEP Init:
            END_STEP
            TRANSITION FROM Init TO W1 := go; END_TRANSITION
            STEP W1:
            END_STEP
            TRANSITION FROM W1 TO W2 := a; END_TRANSITION
            STEP W2:
            END_STEP
            TRANSITION FROM W2 TO W1 := b; END_TRANSITION
        "#]],
    );
}

#[test]
fn a_condition_naming_a_transition_object_calls_it_and_the_object_becomes_a_method() {
    let mut project = project_with(vec![
        step(1, "Init", &[]),
        transition(2, "Ready"),
        step(3, "Run", &[]),
        transition(4, "NOT a"),
        jump(5, "Init"),
    ]);
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.transitions.push(PouAction {
            name: "Ready".into(),
            body: Body::st("a AND b"),
        });
    }
    let lowered = lower_project(&project);
    expect![[r#"
        INITIAL_STEP Init:
        END_STEP
        TRANSITION FROM Init TO Run := Ready(); END_TRANSITION
        STEP Run:
        END_STEP
        TRANSITION FROM Run TO Init := NOT a; END_TRANSITION
        __t4 := NOT a;
    "#]]
    .assert_eq(&lowered.bodies[0].text);
    let Some(Object::Pou(main)) = lowered.project.application.object("Main") else {
        panic!("no Main");
    };
    assert!(main.transitions.is_empty());
    let method = &main.methods[0];
    assert_eq!(
        (method.name.as_str(), method.return_type.as_deref()),
        ("Ready", Some("BOOL"))
    );
    assert_eq!(
        method.body.st_text(),
        Some("Ready := (a AND b);\n__Ready__result := Ready;\n")
    );
    let probe = lowered.bodies[0]
        .probes
        .iter()
        .find(|p| p.element == ElementId(2))
        .map(|p| p.path.as_str());
    assert_eq!(probe, Some("__Ready__result"));
}

#[test]
fn every_step_and_transition_has_its_probes() {
    let project = project_with(branching());
    let lowered = lower_project(&project);
    let probes: Vec<String> = lowered.bodies[0]
        .probes
        .iter()
        .map(|p| {
            let kind = match p.kind {
                ProbeKind::Power => "power",
                ProbeKind::Value => "value",
                ProbeKind::Edge => "edge",
            };
            format!("{} {:?} {kind} {}", p.element.0, p.pin, p.path)
        })
        .collect();
    expect![[r#"
        [
            "1 None power Init.x",
            "1 Some(\"t\") value Init.t",
            "3 None power go",
            "4 None power __t4",
            "7 None power Left.x",
            "7 Some(\"t\") value Left.t",
            "8 None power Right.x",
            "8 Some(\"t\") value Right.t",
            "9 None power b",
            "10 None power Right2.x",
            "10 Some(\"t\") value Right2.t",
            "11 None power a",
        ]
    "#]]
    .assert_debug_eq(&probes);
}

#[test]
fn a_finding_in_a_condition_lands_on_its_transition_once_with_its_range() {
    let project = project_with(vec![
        step(1, "Init", &[]),
        transition(2, "go AND nowhere"),
        step(3, "Run", &[]),
        transition(4, "a"),
        jump(5, "Init"),
    ]);
    let found: Vec<_> = crate::sema::check_project(&project)
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .collect();
    assert_eq!(found.len(), 1, "{found:#?}");
    let place = found[0].element.as_ref().expect("located at an element");
    assert_eq!(place.element, Some(ElementId(2)));
    assert_eq!(found[0].diagnostic.range, 7..14);
    assert!(found[0].diagnostic.message.contains("nowhere"));
}

#[test]
fn a_sound_chart_checks_without_errors() {
    let found: Vec<_> = crate::sema::check_project(&project_with(branching()))
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| d.diagnostic.message)
        .collect();
    assert!(found.is_empty(), "{found:#?}");
}

#[test]
fn a_transition_object_drawn_in_ld_sets_its_result_with_a_coil_and_compiles() {
    let mut project = project_with(vec![
        step(1, "Init", &[]),
        transition(2, "ready"),
        step(3, "Run", &[]),
        transition(4, "NOT b"),
        jump(5, "Init"),
    ]);
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.transitions.push(PouAction {
            name: "Ready".into(),
            body: Body::Ld {
                networks: vec![project_model::Network {
                    rung: vec![crate::lower::tests::contact(6, "a")],
                    outputs: vec![project_model::NetworkOutput::Coil(project_model::Coil {
                        id: ElementId(7),
                        variable: "Ready".into(),
                        kind: project_model::CoilKind::Normal,
                    })],
                    ..project_model::Network::default()
                }],
            },
        });
    }
    let lowered = lower_project(&project);
    let Some(Object::Pou(main)) = lowered.project.application.object("Main") else {
        panic!("no Main");
    };
    assert_eq!(
        main.methods[0].body.st_text(),
        Some("Ready := a;\n__Ready__result := Ready;\n")
    );
    let target = project_model::TextTarget::Transition {
        pou: "Main".into(),
        transition: "Ready".into(),
    };
    assert!(lowered.body("Main", &target).is_some());
    if let Err(error) = crate::compile_project(&project) {
        panic!("{error:?}");
    }
}

#[test]
fn a_chart_in_an_action_is_refused() {
    let mut project = SourceProject::new(DECLARATIONS).project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::st("Steps();");
        main.actions.push(PouAction {
            name: "Steps".into(),
            body: Body::Sfc {
                chart: SfcChart {
                    sequence: vec![
                        step(1, "Init", &[("lamp", ActionQualifier::N)]),
                        transition(2, "go"),
                        jump(3, "Init"),
                    ],
                },
            },
        });
    }
    // The steps of a chart live in the instance of the POU whose own body it is.
    let Err(error) = crate::compile_project(&project) else {
        panic!("a chart in an action compiled");
    };
    let text = format!("{error:?}");
    assert!(text.contains("program or function block"), "{text}");
}
