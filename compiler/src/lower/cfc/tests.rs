//! The Structured Text generated for small CFC charts, as expect-test snapshots
//! (`UPDATE_EXPECT=1 cargo test -p compiler lower::cfc` rewrites them after a deliberate
//! change), the findings at their elements and the probes.

use expect_test::{Expect, expect};
use project_model::{
    Body, CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, Edge, ElementId, Object,
    PinRef, Project, Wire,
};

use crate::SourceProject;
use crate::lower::{ProbeKind, lower_project};

const DECLARATIONS: &str = "TYPE Pair : STRUCT n : INT; flag : BOOL; END_STRUCT END_TYPE
PROGRAM Main
VAR a, b, q, r : BOOL; x, y : INT; t : TON; p, p2 : Pair; END_VAR
END_PROGRAM
";

fn element(id: u32, order: Option<u32>, kind: CfcElementKind) -> CfcElement {
    CfcElement {
        id: ElementId(id),
        x: 0,
        y: 0,
        order,
        kind,
    }
}

fn input(id: u32, expression: &str) -> CfcElement {
    element(
        id,
        None,
        CfcElementKind::Input {
            expression: expression.into(),
        },
    )
}

fn output(id: u32, order: u32, expression: &str, coil: CoilKind) -> CfcElement {
    element(
        id,
        Some(order),
        CfcElementKind::Output {
            expression: expression.into(),
            coil,
        },
    )
}

fn pin(name: &str) -> CfcPin {
    CfcPin::named(name)
}

fn boxed(
    id: u32,
    order: u32,
    type_name: &str,
    instance: &str,
    inputs: &[&str],
    outputs: &[&str],
) -> CfcElement {
    element(
        id,
        Some(order),
        CfcElementKind::Box(CfcBox {
            type_name: type_name.into(),
            instance: instance.into(),
            inputs: inputs.iter().map(|name| pin(name)).collect(),
            outputs: outputs.iter().map(|name| pin(name)).collect(),
        }),
    )
}

fn wire(from: u32, from_pin: &str, to: u32, to_pin: &str) -> Wire {
    Wire::routed(
        PinRef::new(ElementId(from), from_pin),
        PinRef::new(ElementId(to), to_pin),
    )
}

/// A project of `DECLARATIONS` whose `Main` is the chart.
fn project(elements: Vec<CfcElement>, wires: Vec<Wire>) -> Project {
    let chart = CfcChart { elements, wires };
    assert_eq!(project_model::cfc_problems(&chart), Vec::new());
    let mut project = SourceProject::new(DECLARATIONS).project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Cfc { chart };
    }
    project
}

/// The hidden declarations and the lowered text; the chart must check without errors.
#[track_caller]
fn check_lowering(elements: Vec<CfcElement>, wires: Vec<Wire>, expect: Expect) {
    let project = project(elements, wires);
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

/// The errors of the chart, as `element.pin code: message`.
fn findings(elements: Vec<CfcElement>, wires: Vec<Wire>) -> Vec<String> {
    crate::sema::check_project(&project(elements, wires))
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| {
            let place = d.element.map(|place| place.to_string()).unwrap_or_default();
            format!(
                "{place} {}: {}",
                d.diagnostic.code.id(),
                d.diagnostic.message
            )
        })
        .collect()
}

#[test]
fn elements_run_in_execution_order_and_results_are_stored_whatever_the_wires_direction() {
    // `y := x + 1` runs first and reads `x` as it is; then `x := x * 2`.
    check_lowering(
        vec![
            input(1, "x"),
            input(2, "1"),
            boxed(3, 2, "MUL", "", &["IN1", "IN2"], &["OUT"]),
            output(4, 3, "x", CoilKind::Normal),
            boxed(5, 0, "ADD", "", &["IN1", "IN2"], &["OUT"]),
            output(6, 1, "y", CoilKind::Normal),
            input(7, "2"),
        ],
        vec![
            wire(1, "", 3, "IN1"),
            wire(7, "", 3, "IN2"),
            wire(3, "OUT", 4, ""),
            wire(1, "", 5, "IN1"),
            wire(2, "", 5, "IN2"),
            wire(5, "OUT", 6, ""),
        ],
        expect![[r#"
            __e5_OUT : INT;
            __e3_OUT : INT;
            ---
            __e5_OUT := x + 1;
            y := __e5_OUT;
            __e3_OUT := x * 2;
            x := __e3_OUT;
        "#]],
    );
}

#[test]
fn a_feedback_loop_reads_the_previous_cycle_and_is_typed_by_what_it_feeds() {
    check_lowering(
        vec![
            input(1, "1"),
            boxed(2, 0, "ADD", "", &["IN1", "IN2"], &["OUT"]),
            output(3, 1, "x", CoilKind::Normal),
        ],
        vec![
            wire(2, "OUT", 2, "IN1"),
            wire(1, "", 2, "IN2"),
            wire(2, "OUT", 3, ""),
        ],
        expect![[r#"
            __e2_OUT : INT;
            ---
            __e2_OUT := __e2_OUT + 1;
            x := __e2_OUT;
        "#]],
    );
    // A loop through two boxes, broken where the order says, typed by the input outside it.
    check_lowering(
        vec![
            input(1, "y"),
            boxed(2, 0, "ADD", "", &["IN1", "IN2"], &["OUT"]),
            boxed(3, 1, "MAX", "", &["IN1", "IN2"], &["OUT"]),
            output(4, 2, "x", CoilKind::Normal),
        ],
        vec![
            wire(3, "OUT", 2, "IN1"),
            wire(1, "", 2, "IN2"),
            wire(2, "OUT", 3, "IN1"),
            wire(1, "", 3, "IN2"),
            wire(3, "OUT", 4, ""),
        ],
        expect![[r#"
            __e2_OUT : INT;
            __e3_OUT : INT;
            ---
            __e2_OUT := __e3_OUT + y;
            __e3_OUT := MAX(IN1 := __e2_OUT, IN2 := y);
            x := __e3_OUT;
        "#]],
    );
}

#[test]
fn a_box_with_en_runs_only_when_enabled_and_edge_and_negated_pins_and_coils_are_written_as_in_ld() {
    let mut timer = boxed(3, 0, "TON", "t", &["EN", "IN", "PT"], &["ENO", "Q", "ET"]);
    if let CfcElementKind::Box(block) = &mut timer.kind {
        block.inputs[1].edge = Edge::Rising;
        block.outputs[1].negated = true;
    }
    check_lowering(
        vec![
            input(1, "a"),
            input(2, "T#1s"),
            timer,
            output(4, 1, "q", CoilKind::Set),
            output(5, 2, "r", CoilKind::Negated),
            output(6, 3, "b", CoilKind::Rising),
        ],
        vec![
            wire(1, "", 3, "EN"),
            wire(1, "", 3, "IN"),
            wire(2, "", 3, "PT"),
            wire(3, "Q", 4, ""),
            wire(3, "ENO", 5, ""),
            wire(3, "Q", 6, ""),
        ],
        expect![[r#"
            __e3_EN : BOOL;
            __e3_IN_trig : R_TRIG;
            __e6_trig : R_TRIG;
            ---
            __e3_IN_trig(CLK := a);
            __e3_EN := a;
            IF __e3_EN THEN
                t(IN := __e3_IN_trig.Q, PT := T#1s);
            END_IF;
            IF NOT t.Q THEN q := TRUE; END_IF;
            r := NOT __e3_EN;
            __e6_trig(CLK := NOT t.Q);
            b := __e6_trig.Q;
        "#]],
    );
}

#[test]
fn connection_marks_are_resolved_composers_build_and_selectors_copy_their_structure() {
    check_lowering(
        vec![
            input(1, "x"),
            element(
                2,
                None,
                CfcElementKind::ConnectionSource {
                    name: "Level".into(),
                },
            ),
            element(
                3,
                None,
                CfcElementKind::ConnectionSink {
                    name: "level".into(),
                },
            ),
            element(
                4,
                Some(0),
                CfcElementKind::Composer {
                    type_name: "Pair".into(),
                    inputs: vec![pin("n"), pin("flag")],
                },
            ),
            output(5, 1, "p", CoilKind::Normal),
            input(6, "p2"),
            element(
                7,
                Some(2),
                CfcElementKind::Selector {
                    type_name: "Pair".into(),
                    outputs: vec![pin("n"), pin("flag")],
                },
            ),
            output(8, 3, "y", CoilKind::Normal),
            output(9, 4, "q", CoilKind::Normal),
        ],
        vec![
            wire(1, "", 2, ""),
            wire(3, "", 4, "n"),
            wire(4, "", 5, ""),
            wire(6, "", 7, ""),
            wire(7, "n", 8, ""),
            wire(7, "flag", 9, ""),
        ],
        expect![[r#"
            __e4 : Pair;
            __e7 : Pair;
            ---
            __e4.n := x;
            p := __e4;
            __e7 := p2;
            y := __e7.n;
            q := __e7.flag;
        "#]],
    );
}

#[test]
fn jumps_labels_and_returns_follow_the_execution_order() {
    check_lowering(
        vec![
            input(1, "a AND NOT b"),
            element(
                2,
                Some(0),
                CfcElementKind::Jump {
                    label: "Skip".into(),
                },
            ),
            output(3, 1, "q", CoilKind::Normal),
            element(
                4,
                Some(2),
                CfcElementKind::Label {
                    name: "Skip".into(),
                },
            ),
            element(5, Some(3), CfcElementKind::Return),
            input(6, "b"),
        ],
        vec![wire(1, "", 2, ""), wire(6, "", 3, ""), wire(1, "", 5, "")],
        expect![[r#"
            __e1 : BOOL;
            ---
            __e1 := (a AND NOT b);
            IF __e1 THEN JMP Skip; END_IF;
            q := b;
            Skip:
            __e1 := (a AND NOT b);
            IF __e1 THEN RETURN; END_IF;
        "#]],
    );
}

#[test]
fn incomplete_elements_and_broken_marks_are_reported_at_their_elements() {
    let found = findings(
        vec![
            input(1, "x"),
            boxed(2, 0, "ADD", "", &["IN1", "IN2"], &["OUT"]),
            output(3, 1, "y", CoilKind::Normal),
            element(
                4,
                None,
                CfcElementKind::ConnectionSink {
                    name: "Nowhere".into(),
                },
            ),
            element(
                5,
                None,
                CfcElementKind::ConnectionSource {
                    name: "Twice".into(),
                },
            ),
            element(
                6,
                None,
                CfcElementKind::ConnectionSource {
                    name: "twice".into(),
                },
            ),
            element(
                7,
                None,
                CfcElementKind::ConnectionSource { name: "A".into() },
            ),
            element(8, None, CfcElementKind::ConnectionSink { name: "A".into() }),
            element(
                9,
                Some(2),
                CfcElementKind::Jump {
                    label: "Away".into(),
                },
            ),
            output(10, 3, "q", CoilKind::Normal),
            boxed(11, 4, "TON", "", &["IN"], &["Q"]),
            input(12, " "),
            output(13, 5, "y", CoilKind::Normal),
            output(14, 6, "", CoilKind::Normal),
            boxed(15, 7, "ADD", "", &["IN1", "IN2"], &["OUT"]),
            element(16, Some(8), CfcElementKind::Label { name: "L".into() }),
            element(17, Some(9), CfcElementKind::Label { name: "l".into() }),
        ],
        vec![
            wire(1, "", 2, "IN1"),
            wire(2, "OUT", 3, ""),
            wire(4, "", 9, ""),
            wire(1, "", 5, ""),
            wire(1, "", 6, ""),
            wire(8, "", 7, ""),
            wire(8, "", 10, ""),
            wire(12, "", 13, ""),
            wire(1, "", 14, ""),
            wire(15, "OUT", 15, "IN1"),
        ],
    );
    expect![[r#"
        [
            "Main:1:6 E0127: the connection mark 'twice' is also the source of element 5; sinks would not know which to read",
            "Main:1:4 E0126: no connection mark source of this chart is named 'Nowhere'",
            "Main:1:8 E0129: the connection mark 'A' is fed only by connection marks that it feeds, so no value reaches it",
            "Main:1:17 E0128: the label 'l' is given to two elements",
            "Main:1:12 E0128: the input is empty; type a variable, a constant or an expression",
            "Main:1:2.IN2 E0128: the input IN2 of 'ADD' is not connected; a function needs every input",
            "Main:1:11 E0128: the function block box 'TON' has no instance",
            "Main:1:14 E0128: the output names no variable",
            "Main:1:15.IN2 E0128: the input IN2 of 'ADD' is not connected; a function needs every input",
        ]
    "#]]
    .assert_debug_eq(&found);
}

#[test]
fn a_type_error_is_found_at_the_element_in_the_user_s_words() {
    let found = findings(
        vec![
            input(1, "a"),
            input(2, "x"),
            boxed(3, 0, "AND", "", &["IN1", "IN2"], &["OUT"]),
            output(4, 1, "y", CoilKind::Normal),
        ],
        vec![
            wire(1, "", 3, "IN1"),
            wire(2, "", 3, "IN2"),
            wire(3, "OUT", 4, ""),
        ],
    );
    assert!(!found.is_empty());
    assert!(found.iter().all(|f| !f.contains("__")), "{found:#?}");
    assert!(
        found.iter().all(|f| f.starts_with("Main:1:3")),
        "{found:#?}"
    );
}

#[test]
fn every_pin_and_wire_has_a_probe() {
    let project = project(
        vec![
            input(1, "a"),
            input(2, "T#1s"),
            boxed(3, 0, "TON", "t", &["EN", "IN", "PT"], &["ENO", "Q", "ET"]),
            boxed(4, 1, "AND", "", &["IN1", "IN2"], &["OUT"]),
            output(5, 2, "q", CoilKind::Normal),
        ],
        vec![
            wire(1, "", 3, "EN"),
            wire(1, "", 3, "IN"),
            wire(2, "", 3, "PT"),
            wire(3, "Q", 4, "IN1"),
            wire(3, "ENO", 4, "IN2"),
            wire(4, "OUT", 5, ""),
        ],
    );
    let lowered = lower_project(&project);
    let body = &lowered.bodies[0];
    let path = |element: u32, pin: Option<&str>| {
        body.value_probe(ElementId(element), pin)
            .map(|probe| probe.path.as_str())
    };
    assert_eq!(path(3, Some("q")), Some("t.Q"));
    assert_eq!(path(4, Some("OUT")), Some("__e4_OUT"));
    assert_eq!(path(5, None), Some("q"));
    assert_eq!(path(2, None), None);
    let probes: Vec<String> = lowered.bodies[0]
        .probes
        .iter()
        .map(|probe| {
            let kind = match probe.kind {
                ProbeKind::Value => "value",
                ProbeKind::Edge => "edge",
                ProbeKind::Power => "power",
            };
            format!(
                "{}.{} {kind} {}",
                probe.element.0,
                probe.pin.as_deref().unwrap_or("-"),
                probe.path
            )
        })
        .collect();
    expect![[r#"
        [
            "3.ENO value __e3_EN",
            "3.Q value t.Q",
            "3.ET value t.ET",
            "4.OUT value __e4_OUT",
            "1.- value a",
            "3.IN value a",
            "3.EN value __e3_EN",
            "4.IN1 value t.Q",
            "4.IN2 value __e3_EN",
            "5.- value q",
        ]
    "#]]
    .assert_debug_eq(&probes);
}

#[test]
fn a_chart_in_an_action_has_hidden_names_of_its_own_and_checks() {
    let chart = CfcChart {
        elements: vec![
            input(1, "1"),
            boxed(2, 0, "ADD", "", &["IN1", "IN2"], &["OUT"]),
            output(3, 1, "x", CoilKind::Normal),
        ],
        wires: vec![
            wire(2, "OUT", 2, "IN1"),
            wire(1, "", 2, "IN2"),
            wire(2, "OUT", 3, ""),
        ],
    };
    let mut project =
        SourceProject::new("FUNCTION_BLOCK Main\nVAR x : DINT; END_VAR\nEND_FUNCTION_BLOCK\n")
            .project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.actions.push(project_model::PouAction {
            name: "Count".into(),
            body: Body::Cfc { chart },
        });
    }
    let lowered = lower_project(&project);
    expect![[r#"
        __Count__e2_OUT := __Count__e2_OUT + 1;
        x := __Count__e2_OUT;
    "#]]
    .assert_eq(&lowered.bodies[0].text);
    // A fault on a line of the text names the element whose statement it is.
    assert_eq!(
        lowered.bodies[0].origin_at_line(2),
        Some(crate::origin::Origin::Element {
            network: 0,
            element: Some(ElementId(3)),
            pin: None
        })
    );
    let Some(Object::Pou(main)) = lowered.project.application.object("Main") else {
        panic!("no Main");
    };
    assert!(
        main.variables
            .iter()
            .any(|v| v.name == "__Count__e2_OUT" && v.ty == "DINT")
    );
    let errors: Vec<String> = crate::sema::check_project(&project)
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| d.diagnostic.message)
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
}

#[test]
fn a_function_s_other_outputs_are_stored_in_variables_of_their_declared_types() {
    let chart = CfcChart {
        elements: vec![
            input(1, "x"),
            boxed(2, 0, "Split", "", &["v"], &["OUT", "half"]),
            output(3, 1, "y", CoilKind::Normal),
            output(4, 2, "x", CoilKind::Normal),
        ],
        wires: vec![
            wire(1, "", 2, "v"),
            wire(2, "half", 3, ""),
            wire(2, "OUT", 4, ""),
        ],
    };
    let mut project = SourceProject::new(
        "FUNCTION Split : INT
VAR_INPUT v : INT; END_VAR
VAR_OUTPUT half : INT; END_VAR
Split := v; half := v / 2;
END_FUNCTION
PROGRAM Main
VAR x, y : INT; END_VAR
END_PROGRAM
",
    )
    .project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Cfc { chart };
    }
    let lowered = lower_project(&project);
    expect![[r#"
        __e2_OUT := Split(v := x, half => __e2_half);
        y := __e2_half;
        x := __e2_OUT;
    "#]]
    .assert_eq(&lowered.bodies[0].text);
    let errors: Vec<String> = crate::sema::check_project(&project)
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| d.diagnostic.message)
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
}
