//! The Structured Text generated for small networks, as expect-test snapshots
//! (`UPDATE_EXPECT=1 cargo test -p compiler lower` rewrites them after a deliberate change),
//! and the findings located at elements.

use expect_test::{Expect, expect};
use project_model::{
    BlockCall, BlockInput, BlockOutput, Body, Branch, Coil, CoilKind, Edge, ElementId, FlowNode,
    Network, NetworkOutput, Object, Operand, Parallel, Project,
};

use super::{ProbeKind, lower_project};
use crate::{CompileError, SourceProject, compile_project};

pub(crate) fn contact(id: u32, text: &str) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        ..Operand::default()
    })
}

fn closed(id: u32, text: &str) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        negated: true,
        ..Operand::default()
    })
}

fn edge(id: u32, text: &str, edge: Edge) -> FlowNode {
    FlowNode::Operand(Operand {
        id: ElementId(id),
        text: text.into(),
        edge,
        ..Operand::default()
    })
}

fn coil(id: u32, variable: &str, kind: CoilKind) -> NetworkOutput {
    NetworkOutput::Coil(Coil {
        id: ElementId(id),
        variable: variable.into(),
        kind,
    })
}

fn parallel(id: u32, branches: Vec<Vec<FlowNode>>) -> FlowNode {
    FlowNode::Parallel(Parallel {
        id: ElementId(id),
        branches: branches.into_iter().map(|rung| Branch { rung }).collect(),
    })
}

fn input(pin: &str, source: Vec<FlowNode>) -> BlockInput {
    BlockInput {
        pin: pin.into(),
        source,
        ..BlockInput::default()
    }
}

fn output(pin: &str, assign: &str) -> BlockOutput {
    BlockOutput {
        pin: pin.into(),
        assign: assign.into(),
        ..BlockOutput::default()
    }
}

fn block(
    id: u32,
    type_name: &str,
    instance: &str,
    inputs: Vec<BlockInput>,
    outputs: Vec<BlockOutput>,
) -> FlowNode {
    FlowNode::Block(BlockCall {
        id: ElementId(id),
        type_name: type_name.into(),
        instance: instance.into(),
        inputs,
        outputs,
    })
}

fn network(rung: Vec<FlowNode>, outputs: Vec<NetworkOutput>) -> Network {
    Network {
        rung,
        outputs,
        ..Network::default()
    }
}

/// A project of `source` whose POU `Main` gets the LD body `networks`.
pub(crate) fn project_with(source: &str, networks: Vec<Network>) -> Project {
    let built = SourceProject::new(source);
    let mut project = built.project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Ld { networks };
    }
    project
}

const DECLARATIONS: &str = "PROGRAM Main
VAR a, b, c, d, q, r, s : BOOL; x, y : INT; t : TON; END_VAR
END_PROGRAM
";

/// The lowered text of `networks` in `DECLARATIONS`, after the hidden declarations; the
/// text must check without errors.
#[track_caller]
fn check_lowering(networks: Vec<Network>, expect: Expect) {
    let project = project_with(DECLARATIONS, networks);
    let lowered = lower_project(&project);
    let body = &lowered.bodies[0];
    let Some(Object::Pou(main)) = lowered.project.application.object("Main") else {
        panic!("no Main");
    };
    let hidden: Vec<String> = main
        .variables
        .iter()
        .filter(|v| v.name.contains("__"))
        .map(|v| format!("{} : {};\n", v.name, v.ty))
        .collect();
    expect.assert_eq(&format!("{}---\n{}", hidden.concat(), body.text));
    let errors: Vec<String> = crate::sema::check_project(&project)
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| d.diagnostic.message)
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
}

#[test]
fn a_series_rung_with_one_coil_is_the_assignment_a_user_writes() {
    check_lowering(
        vec![network(
            vec![contact(1, "a"), closed(2, "b")],
            vec![coil(3, "q", CoilKind::Normal)],
        )],
        expect![[r#"
            ---
            q := a AND NOT b;
        "#]],
    );
}

#[test]
fn parallel_contacts_are_ored_and_several_coils_read_the_power_once() {
    check_lowering(
        vec![network(
            vec![
                contact(1, "a"),
                parallel(
                    2,
                    vec![vec![contact(3, "b")], vec![closed(4, "c"), contact(5, "d")]],
                ),
            ],
            vec![
                coil(6, "q", CoilKind::Set),
                coil(7, "a", CoilKind::Reset),
                coil(8, "r", CoilKind::Negated),
            ],
        )],
        expect![[r#"
            __e2 : BOOL;
            ---
            __e2 := a AND (b OR NOT c AND d);
            IF __e2 THEN q := TRUE; END_IF;
            IF __e2 THEN a := FALSE; END_IF;
            r := NOT __e2;
        "#]],
    );
}

#[test]
fn edge_contacts_and_coils_update_their_trigger_every_scan() {
    check_lowering(
        vec![network(
            vec![contact(1, "a"), edge(2, "b", Edge::Rising)],
            vec![
                coil(3, "q", CoilKind::Falling),
                NetworkOutput::Branch {
                    id: ElementId(4),
                    rung: vec![edge(5, "c", Edge::Falling)],
                    outputs: vec![coil(6, "r", CoilKind::Normal)],
                },
            ],
        )],
        expect![[r#"
            __e2_trig : R_TRIG;
            __e2 : BOOL;
            __e3_trig : F_TRIG;
            __e5_trig : F_TRIG;
            ---
            __e2_trig(CLK := b);
            __e2 := a AND __e2_trig.Q;
            __e3_trig(CLK := __e2);
            q := __e3_trig.Q;
            __e5_trig(CLK := c);
            r := __e2 AND __e5_trig.Q;
        "#]],
    );
}

#[test]
fn a_timer_box_takes_the_power_and_passes_its_output_on() {
    check_lowering(
        vec![network(
            vec![
                contact(1, "a"),
                block(
                    2,
                    "TON",
                    "t",
                    vec![input("IN", vec![]), input("PT", vec![contact(3, "T#5s")])],
                    vec![output("Q", ""), output("ET", "")],
                ),
            ],
            vec![coil(4, "q", CoilKind::Normal)],
        )],
        expect![[r#"
            ---
            t(IN := a, PT := T#5s);
            q := t.Q;
        "#]],
    );
}

#[test]
fn a_box_with_en_runs_only_when_enabled_and_its_eno_is_the_enable() {
    check_lowering(
        vec![network(
            vec![
                contact(1, "a"),
                block(
                    2,
                    "ADD",
                    "",
                    vec![
                        input("EN", vec![]),
                        input("IN1", vec![contact(3, "x")]),
                        input("IN2", vec![contact(4, "1")]),
                    ],
                    vec![output("ENO", "s"), output("OUT", "y")],
                ),
            ],
            vec![coil(5, "q", CoilKind::Normal)],
        )],
        expect![[r#"
            __e2_EN : BOOL;
            ---
            __e2_EN := a;
            IF __e2_EN THEN
                y := x + 1;
            END_IF;
            s := __e2_EN;
            q := __e2_EN;
        "#]],
    );
}

#[test]
fn fbd_operator_results_are_stored_for_their_pins_and_functions_are_called_by_their_pins() {
    check_lowering(
        vec![network(
            vec![block(
                1,
                "GT",
                "",
                vec![
                    input(
                        "IN1",
                        vec![block(
                            2,
                            "LIMIT",
                            "",
                            vec![
                                input("MN", vec![contact(3, "0")]),
                                input(
                                    "IN",
                                    vec![block(
                                        4,
                                        "MUL",
                                        "",
                                        vec![
                                            input("IN1", vec![contact(5, "x")]),
                                            input("IN2", vec![contact(6, "-2")]),
                                        ],
                                        vec![output("OUT", "")],
                                    )],
                                ),
                                input("MX", vec![contact(7, "100")]),
                            ],
                            vec![output("OUT", "y")],
                        )],
                    ),
                    input("IN2", vec![contact(8, "10")]),
                ],
                vec![output("OUT", "")],
            )],
            vec![coil(9, "q", CoilKind::Normal)],
        )],
        expect![[r#"
            __e4_OUT : INT;
            __e1_OUT : BOOL;
            ---
            __e4_OUT := x * (-2);
            y := LIMIT(MN := 0, IN := __e4_OUT, MX := 100);
            __e1_OUT := y > 10;
            q := __e1_OUT;
        "#]],
    );
}

#[test]
fn jumps_go_to_labels_forwards_and_backwards_and_return_returns() {
    let mut second = network(vec![contact(3, "b")], vec![coil(4, "q", CoilKind::Normal)]);
    second.label = "Skip".into();
    check_lowering(
        vec![
            network(
                vec![contact(1, "a")],
                vec![NetworkOutput::Jump {
                    id: ElementId(2),
                    label: "Skip".into(),
                }],
            ),
            second,
            network(
                vec![contact(5, "c")],
                vec![NetworkOutput::Return { id: ElementId(6) }],
            ),
        ],
        expect![[r#"
            ---
            IF a THEN JMP Skip; END_IF;
            Skip:
            q := b;
            IF c THEN RETURN; END_IF;
        "#]],
    );
}

#[test]
fn a_box_inside_a_branch_gets_the_stored_power_and_the_branches_are_ored() {
    check_lowering(
        vec![network(
            vec![
                contact(1, "a"),
                parallel(
                    2,
                    vec![
                        vec![contact(3, "b")],
                        vec![block(
                            4,
                            "TON",
                            "t",
                            vec![input("IN", vec![]), input("PT", vec![contact(5, "T#1s")])],
                            vec![output("Q", "r")],
                        )],
                    ],
                ),
            ],
            vec![coil(6, "q", CoilKind::Normal)],
        )],
        expect![[r#"
            __e2_in : BOOL;
            __e2_b0 : BOOL;
            ---
            __e2_in := a;
            __e2_b0 := __e2_in AND b;
            t(IN := __e2_in, PT := T#1s);
            r := t.Q;
            q := __e2_b0 OR t.Q;
        "#]],
    );
}

/// The listings of `Main` (drawn as `networks`) and `Text` (written as `text`), both with the
/// variables `declarations`.
#[track_caller]
fn listings(declarations: &str, networks: Vec<Network>, text: &str) -> (String, String) {
    let source = format!(
        "PROGRAM Main\nVAR {declarations} END_VAR\nEND_PROGRAM\n\
         PROGRAM Text\nVAR {declarations} END_VAR\n{text}\nEND_PROGRAM\n"
    );
    let mut project = project_with(&source, networks);
    project.tasks = vec![project_model::Task {
        name: "MainTask".into(),
        kind: project_model::TaskKind::Freewheeling,
        priority: 1,
        watchdog: None,
        programs: vec!["Main".into(), "Text".into()],
    }];
    let image = match compile_project(&project) {
        Ok(image) => image,
        Err(error) => panic!("{error}: {error:?}"),
    };
    let code = |name: &str| {
        let pou = image.pous.iter().find(|pou| pou.name == name);
        pou.map(|pou| program_image::listing(&pou.code))
            .unwrap_or_default()
    };
    (code("Main"), code("Text"))
}

#[test]
fn a_rung_costs_exactly_the_instructions_of_the_equivalent_st() {
    let (drawn, written) = listings(
        "a, b, c : BOOL;",
        vec![network(
            vec![contact(1, "a"), closed(2, "b")],
            vec![coil(3, "c", CoilKind::Normal)],
        )],
        "c := a AND NOT b;",
    );
    assert!(!drawn.is_empty());
    assert_eq!(drawn, written);
    let (drawn, written) = listings(
        "a, b, c, d, q : BOOL;",
        vec![network(
            vec![
                contact(1, "a"),
                parallel(2, vec![vec![contact(3, "b")], vec![closed(4, "c")]]),
            ],
            vec![coil(5, "q", CoilKind::Set)],
        )],
        "IF a AND (b OR NOT c) THEN q := TRUE; END_IF;",
    );
    assert_eq!(drawn, written);
}

#[test]
fn a_rung_driving_several_coils_costs_no_more_than_the_st_that_repeats_its_logic() {
    let (drawn, written) = listings(
        "a, b, c, q, r : BOOL;",
        vec![network(
            vec![contact(1, "a"), closed(2, "b"), contact(3, "c")],
            vec![
                coil(4, "q", CoilKind::Normal),
                coil(5, "r", CoilKind::Negated),
            ],
        )],
        "q := a AND NOT b AND c; r := NOT (a AND NOT b AND c);",
    );
    assert!(
        drawn.lines().count() <= written.lines().count(),
        "drawn:\n{drawn}\nwritten:\n{written}"
    );
}

#[test]
fn a_type_error_in_an_operand_is_found_at_its_element_in_the_user_s_words() {
    let project = project_with(
        DECLARATIONS,
        vec![
            network(vec![contact(1, "a")], vec![coil(2, "q", CoilKind::Normal)]),
            network(
                vec![contact(3, "a"), contact(4, "x")],
                vec![
                    coil(5, "q", CoilKind::Normal),
                    coil(6, "r", CoilKind::Normal),
                ],
            ),
        ],
    );
    let Err(CompileError::Diagnostics(found)) = compile_project(&project) else {
        panic!("an INT contact compiled");
    };
    let errors: Vec<_> = found
        .iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .collect();
    assert!(!errors.is_empty());
    for error in &errors {
        let place = error.element.as_ref().expect("located at an element");
        assert_eq!(
            error.file,
            std::path::PathBuf::from("application/Main.pou.toml")
        );
        assert_eq!(
            (place.network, place.element),
            (1, Some(ElementId(4))),
            "{error:?}"
        );
        assert!(
            !error.diagnostic.message.contains("__"),
            "{}",
            error.diagnostic.message
        );
    }
}

#[test]
fn a_jump_to_a_missing_label_and_a_name_with_two_underscores_are_refused_at_their_elements() {
    let project = project_with(
        DECLARATIONS,
        vec![network(
            vec![contact(1, "a__b")],
            vec![NetworkOutput::Jump {
                id: ElementId(2),
                label: "Nowhere".into(),
            }],
        )],
    );
    let found = crate::sema::check_project(&project);
    let at = |id: u32| {
        found
            .iter()
            .find(|d| d.element.as_ref().and_then(|p| p.element) == Some(ElementId(id)))
            .map(|d| (d.diagnostic.code, d.diagnostic.message.clone()))
    };
    assert!(
        matches!(at(1), Some((crate::Code::ReservedName, _))),
        "{found:#?}"
    );
    assert!(
        matches!(at(2), Some((crate::Code::InvalidNetwork, message)) if message.contains("Nowhere")),
        "{found:#?}"
    );
    let mut declared = project_with(DECLARATIONS, Vec::new());
    if let Some(Object::Pou(main)) = declared.application.object_mut("Main") {
        main.variables[0].name = "a__".into();
    }
    let found = crate::sema::check_project(&declared);
    assert!(
        found
            .iter()
            .any(|d| d.diagnostic.code == crate::Code::ReservedName
                && d.declaration.as_deref() == Some("a__")),
        "{found:#?}"
    );
    // An ST body cannot reach a hidden variable of the LD body beside it either.
    let mut reaching = project_with(
        "FUNCTION_BLOCK Main\nVAR a, q : BOOL; END_VAR\nq := __e2;\nEND_FUNCTION_BLOCK\n",
        Vec::new(),
    );
    if let Some(Object::Pou(main)) = reaching.application.object_mut("Main") {
        main.actions.push(project_model::PouAction {
            name: "Drawn".into(),
            body: Body::Ld {
                networks: vec![network(
                    vec![contact(1, "a")],
                    vec![coil(2, "q", CoilKind::Normal), coil(3, "q", CoilKind::Set)],
                )],
            },
        });
        main.body = Body::st("q := __Drawn__e2;");
    }
    let found = crate::sema::check_project(&reaching);
    assert!(
        found.iter().any(
            |d| d.diagnostic.code == crate::Code::ReservedName && d.diagnostic.range == (5..16)
        ),
        "{found:#?}"
    );
    // Nor is a hidden name ever suggested.
    assert!(
        found
            .iter()
            .all(|d| !d.diagnostic.message.contains("__Drawn__e1")),
        "{found:#?}"
    );
}

#[test]
fn every_element_tells_where_its_live_value_is_read() {
    let project = project_with(
        DECLARATIONS,
        vec![network(
            vec![contact(1, "a"), edge(2, "b", Edge::Rising)],
            vec![
                coil(3, "q", CoilKind::Normal),
                coil(4, "r", CoilKind::Normal),
            ],
        )],
    );
    let lowered = lower_project(&project);
    let probes: Vec<String> = lowered.bodies[0]
        .probes
        .iter()
        .map(|probe| {
            let kind = match probe.kind {
                ProbeKind::Power => "power",
                ProbeKind::Value => "value",
                ProbeKind::Edge => "edge",
            };
            format!(
                "{}:{} {kind} {}",
                probe.network, probe.element.0, probe.path
            )
        })
        .collect();
    expect![[r#"
        0:1 value a
        0:2 value b
        0:2 edge __e2_trig.Q
        0:2 power __e2
        0:3 value q
        0:4 value r"#]]
    .assert_eq(&probes.join("\n"));
}

#[test]
fn a_finding_about_generated_text_names_the_power_flow_never_a_hidden_name() {
    let project = project_with(
        DECLARATIONS,
        vec![network(
            vec![contact(1, "a"), edge(2, "x", Edge::Rising)],
            vec![coil(3, "q", CoilKind::Normal)],
        )],
    );
    let found = crate::sema::check_project(&project);
    let messages: Vec<String> = found
        .iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| {
            let place = d
                .element
                .as_ref()
                .map(ToString::to_string)
                .unwrap_or_default();
            format!(
                "{place}: {}: {}",
                d.diagnostic.code.id(),
                d.diagnostic.message
            )
        })
        .collect();
    expect!["Main:1:2: E0104: input 'CLK' of 'the rising edge detection of element 2' expects BOOL, found INT; IEC converts only to wider types, so write INT_TO_BOOL(…)"].assert_eq(&messages.join("\n"));
}

#[test]
fn each_line_of_the_lowered_text_names_its_element() {
    let project = project_with(
        DECLARATIONS,
        vec![
            network(vec![contact(1, "a")], vec![coil(2, "q", CoilKind::Normal)]),
            network(
                vec![
                    contact(3, "b"),
                    block(
                        4,
                        "ADD",
                        "",
                        vec![
                            input("EN", vec![]),
                            input("IN1", vec![contact(5, "x")]),
                            input("IN2", vec![contact(6, "1")]),
                        ],
                        vec![output("ENO", ""), output("OUT", "x")],
                    ),
                ],
                vec![],
            ),
        ],
    );
    let lowered = lower_project(&project);
    let body = &lowered.bodies[0];
    let elements: Vec<String> = (1..=6)
        .map(|line| match body.origin_at_line(line) {
            Some(crate::origin::Origin::Element {
                network, element, ..
            }) => format!("{}:{}", network, element.map_or(0, |e| e.0)),
            other => format!("{other:?}"),
        })
        .collect();
    expect![[r#"
        q := a;
        __e4_EN := b;
        IF __e4_EN THEN
            x := x + 1;
        END_IF;

        0:2 1:4 1:4 1:4 1:4 None"#]]
    .assert_eq(&format!("{}\n{}", body.text, elements.join(" ")));
}

#[test]
fn standard_functions_with_more_inputs_are_called_with_their_pins() {
    let value = |id: u32, text: &str| vec![contact(id, text)];
    check_lowering(
        vec![
            network(
                vec![block(
                    1,
                    "MUX",
                    "",
                    vec![
                        input("K", value(2, "x")),
                        input("IN0", value(3, "y")),
                        input("IN1", value(4, "5")),
                        input("IN2", value(5, "7")),
                    ],
                    vec![output("OUT", "y")],
                )],
                vec![],
            ),
            network(
                vec![block(
                    6,
                    "MIN",
                    "",
                    vec![
                        input("IN1", value(7, "x")),
                        input("IN2", value(8, "y")),
                        input("IN3", value(9, "3")),
                    ],
                    vec![output("OUT", "x")],
                )],
                vec![],
            ),
        ],
        expect![[r#"
            ---
            y := MUX(K := x, IN0 := y, IN1 := 5, IN2 := 7);
            x := MIN(IN1 := x, IN2 := y, IN3 := 3);
        "#]],
    );
}

#[test]
fn a_code_generation_error_in_a_network_names_the_pou_file_and_the_element() {
    let source = "FUNCTION_BLOCK Main\nVAR q : BOOL; p : POINTER TO ARRAY[-9223372036854775807..9223372036854775807] OF BOOL; END_VAR\nEND_FUNCTION_BLOCK\n\
                  PROGRAM Run\nVAR m : Main; END_VAR\nm();\nEND_PROGRAM\n";
    let project = project_with(
        source,
        vec![network(
            vec![contact(1, "p^[0]")],
            vec![coil(2, "q", CoilKind::Normal)],
        )],
    );
    let error = match compile_project(&project) {
        Err(CompileError::Unsupported(error)) => error,
        other => panic!("expected a code generation error, got {other:?}"),
    };
    let crate::codegen::CodegenError::Unsupported { location, message } = &error else {
        panic!("{error:?}");
    };
    assert!(
        location.within.contains(&crate::codegen::Within::File(
            "application/Main.pou.toml".into()
        )),
        "{location:?}"
    );
    assert!(
        matches!(
            location.statement().map(|s| &s.origin),
            Some(crate::origin::Origin::Element {
                network: 0,
                element: Some(ElementId(2)),
                ..
            })
        ),
        "{location:?}"
    );
    assert!(!message.contains("__"));
    expect!["application/Main.pou.toml: Main: 1:2: the array is larger than a memory region"]
        .assert_eq(&error.to_string());
}

#[test]
fn the_check_of_one_pou_finds_what_the_check_of_the_project_finds_in_it() {
    let mut project = project_with(
        DECLARATIONS,
        vec![network(
            vec![contact(1, "a"), contact(2, "x")],
            vec![NetworkOutput::Jump {
                id: ElementId(3),
                label: "Nowhere".into(),
            }],
        )],
    );
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.variables[0].name = "a__".into();
    }
    let summary = |found: Vec<crate::sema::ProjectDiagnostic>| {
        let mut lines: Vec<String> = found
            .into_iter()
            .map(|d| {
                let place = d.element.map(|p| p.to_string()).unwrap_or_default();
                format!("{} {place} {}", d.file.display(), d.diagnostic.code.id())
            })
            .collect();
        lines.sort();
        lines.join("\n")
    };
    let whole = summary(crate::sema::check_project(&project));
    assert_eq!(summary(crate::sema::check_pou(&project, "Main")), whole);
    expect![[r#"
        application/Main.pou.toml  E0113
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml  W0001
        application/Main.pou.toml Main:1:3 E0114"#]]
    .assert_eq(&whole);
}

#[test]
fn a_rung_of_contacts_driving_nothing_is_reported_but_a_box_alone_is_not() {
    let project = project_with(
        DECLARATIONS,
        vec![
            network(vec![contact(1, "a"), contact(2, "b")], vec![]),
            network(
                vec![block(
                    3,
                    "TON",
                    "t",
                    vec![input("IN", vec![contact(4, "c")])],
                    vec![output("Q", "")],
                )],
                vec![],
            ),
        ],
    );
    let found: Vec<String> = crate::sema::check_project(&project)
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| {
            format!(
                "{}: {}",
                d.element.map(|p| p.to_string()).unwrap_or_default(),
                d.diagnostic.message
            )
        })
        .collect();
    expect![[r#"Main:1:2: the result of this network drives nothing; add a coil, an assignment, a jump or a return"#]]
        .assert_eq(&found.join("\n"));
}

#[test]
fn a_function_block_box_with_en_is_called_only_when_enabled_and_its_outputs_hold() {
    check_lowering(
        vec![network(
            vec![
                contact(1, "a"),
                closed(2, "b"),
                block(
                    3,
                    "TON",
                    "t",
                    vec![
                        input("EN", vec![]),
                        input("IN", vec![contact(4, "c")]),
                        input("PT", vec![contact(5, "T#2s")]),
                    ],
                    vec![output("ENO", ""), output("Q", "q"), output("ET", "")],
                ),
            ],
            vec![coil(6, "r", CoilKind::Normal)],
        )],
        expect![[r#"
            __e3_EN : BOOL;
            ---
            __e3_EN := a AND NOT b;
            IF __e3_EN THEN
                t(IN := c, PT := T#2s);
                q := t.Q;
            END_IF;
            r := __e3_EN;
        "#]],
    );
}

#[test]
fn every_box_output_pin_has_a_probe_and_a_constant_result_stays_in_its_expression() {
    let gt = |id: u32, first: Vec<FlowNode>, second: Vec<FlowNode>| {
        block(
            id,
            "GT",
            "",
            vec![input("IN1", first), input("IN2", second)],
            vec![output("OUT", "")],
        )
    };
    let add = block(
        5,
        "ADD",
        "",
        vec![
            input("IN1", vec![contact(6, "1")]),
            input("IN2", vec![contact(7, "2")]),
        ],
        vec![output("OUT", "")],
    );
    let networks = vec![
        network(
            vec![gt(1, vec![contact(2, "x")], vec![contact(3, "10")])],
            vec![coil(4, "q", CoilKind::Normal)],
        ),
        network(
            vec![gt(8, vec![add], vec![contact(9, "y")])],
            vec![coil(10, "r", CoilKind::Normal)],
        ),
    ];
    check_lowering(
        networks.clone(),
        expect![[r#"
            __e1_OUT : BOOL;
            __e8_OUT : BOOL;
            ---
            __e1_OUT := x > 10;
            q := __e1_OUT;
            __e8_OUT := 1 + 2 > y;
            r := __e8_OUT;
        "#]],
    );
    let project = project_with(DECLARATIONS, networks);
    let lowered = lower_project(&project);
    let pins: Vec<String> = lowered.bodies[0]
        .probes
        .iter()
        .filter(|probe| probe.pin.is_some())
        .map(|probe| {
            format!(
                "{}:{}.{} {:?} {}",
                probe.network,
                probe.element.0,
                probe.pin.as_deref().unwrap_or_default(),
                probe.kind,
                probe.path
            )
        })
        .collect();
    expect![[r#"
        0:1.OUT Value __e1_OUT
        1:8.OUT Value __e8_OUT"#]]
    .assert_eq(&pins.join("\n"));
}

#[test]
fn a_stored_box_result_costs_one_store_and_load_more_than_the_st_at_most() {
    let (drawn, written) = listings(
        "x : INT; q : BOOL;",
        vec![network(
            vec![block(
                1,
                "GT",
                "",
                vec![
                    input("IN1", vec![contact(2, "x")]),
                    input("IN2", vec![contact(3, "10")]),
                ],
                vec![output("OUT", "")],
            )],
            vec![coil(4, "q", CoilKind::Normal)],
        )],
        "q := x > 10;",
    );
    assert!(
        drawn.lines().count() <= written.lines().count() + 2,
        "drawn:\n{drawn}\nwritten:\n{written}"
    );
}
