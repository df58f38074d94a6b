//! The Structured Text generated for IL bodies, line for line, as expect-test snapshots
//! (`UPDATE_EXPECT=1 cargo test -p compiler il` rewrites them after a deliberate change), and
//! the findings in the IL file at their lines.

use std::path::PathBuf;

use expect_test::{Expect, expect};
use project_model::{Body, Object, Project, TextTarget};

use crate::diagnostic::line_column;
use crate::lower::lower_project;
use crate::{SourceProject, compile_project};

const DECLARATIONS: &str = "FUNCTION Twice : INT
VAR_INPUT v : INT; END_VAR
Twice := v * 2;
END_FUNCTION
PROGRAM Main
VAR a, b, c, q : BOOL; x, y, z : INT; big : DINT; t : TON; ctr : CTU; END_VAR
END_PROGRAM
";

/// The project of `DECLARATIONS` with `il` as the body of `Main`.
fn project_with(il: &str) -> Project {
    let mut project = SourceProject::new(DECLARATIONS).project;
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = Body::Il { text: il.into() };
    }
    project
}

/// The hidden declarations and the lowered text of `il`, which must check without errors and
/// have as many lines as `il`.
#[track_caller]
fn check_lowering(il: &str, expect: Expect) {
    let project = project_with(il);
    let lowered = lower_project(&project);
    let body = &lowered.il[0];
    assert_eq!(
        body.text.lines().count(),
        il.lines().count(),
        "{}",
        body.text
    );
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

/// The errors of `il` as `file:line:column: code: message`.
fn errors(il: &str) -> Vec<String> {
    crate::sema::check_project(&project_with(il))
        .into_iter()
        .filter(|d| d.diagnostic.severity == crate::Severity::Error)
        .map(|d| {
            let (line, column) = line_column(il, d.diagnostic.range.start);
            format!(
                "{}:{line}:{column}: {}: {}",
                d.file.display(),
                d.diagnostic.code.id(),
                d.diagnostic.message
            )
        })
        .collect()
}

#[test]
fn loads_operations_and_stores_are_assignments_through_a_typed_current_result() {
    check_lowering(
        "LD x\nADD 1\nMUL y\nST z\nST big\nGT 10\nST q\n",
        expect![[r#"
            __cr0 : INT;
            __cr1 : BOOL;
            ---
            __cr0 := x;
            __cr0 := __cr0 + 1;
            __cr0 := __cr0 * y;
            z := __cr0;
            big := __cr0;
            __cr1 := __cr0 > 10;
            q := __cr1;
        "#]],
    );
}

#[test]
fn negations_set_reset_and_bit_operators_keep_their_lines_and_comments_are_skipped() {
    check_lowering(
        "LDN a (* not a *)\nANDN b\nOR c // or c\nXOR TRUE\nNOT\nS q\nR a\nSTN b\n",
        expect![[r#"
            __cr0 : BOOL;
            ---
            __cr0 := NOT a;
            __cr0 := __cr0 AND NOT b;
            __cr0 := __cr0 OR c;
            __cr0 := __cr0 XOR TRUE;
            __cr0 := NOT __cr0;
            IF __cr0 THEN q := TRUE; END_IF;
            IF __cr0 THEN a := FALSE; END_IF;
            b := NOT __cr0;
        "#]],
    );
}

#[test]
fn a_parenthesized_operation_works_on_its_own_current_result() {
    check_lowering(
        "LD a\nAND( b\nOR c\n)\nOR(\nLD x\nGT y\n)\nST q\n",
        expect![[r#"
            __cr0 : BOOL;
            __cr1 : BOOL;
            __cr2 : INT;
            ---
            __cr0 := a;
            __cr1 := b;
            __cr1 := __cr1 OR c;
            __cr0 := __cr0 AND (__cr1);

            __cr2 := x;
            __cr1 := __cr2 > y;
            __cr0 := __cr0 OR (__cr1);
            q := __cr0;
        "#]],
    );
}

#[test]
fn jumps_go_to_labels_and_the_current_result_crosses_them_in_one_variable() {
    // Beremiz's CounterIL: the counter or the reset value reaches QuitFb as the current result.
    check_lowering(
        "LD a\nJMPC Reset\nLD x\nADD 1\nJMP Quit\nReset:\nLD 0\nQuit: ST x\nST y\nLD b\nRETCN\nJMPCN Reset\n",
        expect![[r#"
            __cr0 : BOOL;
            __cr1 : INT;
            ---
            __cr0 := a;
            IF __cr0 THEN JMP Reset; END_IF;
            __cr1 := x;
            __cr1 := __cr1 + 1;
            JMP Quit;
            Reset:

            __cr1 := 0; Quit: x := __cr1;
            y := __cr1;
            __cr0 := b;
            IF NOT __cr0 THEN RETURN; END_IF;
            IF NOT __cr0 THEN JMP Reset; END_IF;
        "#]],
    );
}

#[test]
fn a_label_followed_by_a_load_takes_nothing_across_whatever_type_the_result_had() {
    check_lowering(
        "LD a\nJMPC Skip\nLD x\nADD 1\nST x\nSkip:\nLD y\nST z\n",
        expect![[r#"
            __cr0 : BOOL;
            __cr1 : INT;
            ---
            __cr0 := a;
            IF __cr0 THEN JMP Skip; END_IF;
            __cr1 := x;
            __cr1 := __cr1 + 1;
            x := __cr1;
            Skip:
            __cr1 := y;
            z := __cr1;
        "#]],
    );
}

#[test]
fn blocks_are_called_with_their_arguments_or_inputs_and_functions_with_the_current_result() {
    check_lowering(
        "CAL t(IN := a, PT := T#1s)\nLD t.Q\nCU ctr\nCALC ctr(\n  RESET := b,\n  PV := 3)\nLD x\nTwice\nST y\nLD x\nLIMIT 0, 10\nST z\nMAX(IN1 := x, IN2 := y)\nST z\n",
        expect![[r#"
            __cr0 : BOOL;
            __cr1 : INT;
            ---
            t(IN := a, PT := T#1s);
            __cr0 := t.Q;
            ctr(CU := __cr0);
            IF __cr0 THEN ctr(
              RESET := b,
              PV := 3); END_IF;
            __cr1 := x;
            __cr1 := Twice(__cr1);
            y := __cr1;
            __cr1 := x;
            __cr1 := LIMIT(__cr1, 0, 10);
            z := __cr1;
            __cr1 := MAX(IN1 := x, IN2 := y);
            z := __cr1;
        "#]],
    );
}

#[test]
fn a_transition_in_il_ends_with_its_condition() {
    let mut project = project_with("");
    if let Some(Object::Pou(main)) = project.application.object_mut("Main") {
        main.transitions.push(project_model::PouAction {
            name: "Ready".into(),
            body: Body::Il {
                text: "LD a\nAND b\n".into(),
            },
        });
    }
    let lowered = lower_project(&project);
    let body = lowered
        .il
        .iter()
        .find(|body| matches!(body.target, TextTarget::Transition { .. }))
        .map(|body| body.text.clone());
    assert_eq!(
        body.as_deref(),
        Some("__Ready__cr0 := a;\n__Ready__cr0 := __Ready__cr0 AND b; Ready := __Ready__cr0;\n")
    );
}

#[test]
fn errors_name_the_il_file_and_line() {
    let il =
        "LD x\nADD a\n1abc\nJMP Nowhere\n)\nST\nL1: LD 1\nL1:\nAND b\nJMP L1\nAND b\nLD unknown\n";
    let mut found = errors(il);
    found.sort();
    expect![[r#"
        [
            "application/Main.il:11:1: E0139: there is no current result here; load one with LD first",
            "application/Main.il:12:1: E0101: unknown name 'unknown'",
            "application/Main.il:2:1: E0105: '+' is not defined for INT and BOOL",
            "application/Main.il:3:1: E0136: '1abc' is not an instruction; expected an operator or a function",
            "application/Main.il:4:5: E0137: the jump goes to 'Nowhere', but no line of this body has that label",
            "application/Main.il:5:1: E0138: ')' closes no parenthesis; an operator such as AND( opens one",
            "application/Main.il:6:1: E0136: 'ST' needs an operand",
            "application/Main.il:8:1: E0137: the label 'L1' is declared twice",
            "application/Main.il:9:1: E0105: 'AND' is not defined for INT and BOOL",
        ]
    "#]]
    .assert_debug_eq(&found);
}

#[test]
fn the_line_table_names_the_il_file_and_its_lines() {
    let image = compile_project(&project_with("LD x\n\n(* comment *)\nADD 1\nST x\n"))
        .unwrap_or_else(|error| panic!("{error}"));
    let main = image
        .pous
        .iter()
        .find(|pou| pou.name.eq_ignore_ascii_case("Main"))
        .unwrap_or_else(|| panic!("no Main"));
    let lines: Vec<(String, u32)> = main
        .lines
        .iter()
        .map(|entry| (image.sources[entry.file as usize].clone(), entry.line))
        .collect();
    let file = PathBuf::from("application/Main.il")
        .to_string_lossy()
        .into_owned();
    assert_eq!(lines, vec![(file.clone(), 1), (file.clone(), 4), (file, 5)]);
}

#[test]
fn any_text_lowers_without_panicking_into_as_many_lines() {
    use super::IlLowering;
    use project_model::Variable;

    const FRAGMENTS: [&str; 28] = [
        "LD ", "LDN ", "ST ", "AND( ", ")", "JMP ", "JMPC ", "CAL ", "L1:", "L2: ", "(*", "*)",
        "'", "x", "a.b", "1", "T#1s", "&N ", "中文", "\n", " ", ",", "(", ":=", "$", "//", "RETC",
        "\r\n",
    ];
    let type_of = |_: &[Variable], expression: &str| {
        (!expression.contains('1')).then(|| {
            if expression.contains('x') {
                "INT".to_owned()
            } else {
                "BOOL".to_owned()
            }
        })
    };
    // A linear congruential generator keeps the cases the same from run to run.
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = |bound: usize| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 33) as usize % bound
    };
    for _ in 0..3000 {
        let length = next(40);
        let text: String = (0..length)
            .map(|_| FRAGMENTS[next(FRAGMENTS.len())])
            .collect();
        let mut lowering = IlLowering::new("__".into(), &type_of);
        let lowered = lowering.lower(&text, Some("T"));
        assert_eq!(
            lowered.matches('\n').count(),
            text.matches('\n').count(),
            "{text:?} became {lowered:?}"
        );
    }
}

#[test]
fn values_are_shown_at_the_operands_of_the_il_text() {
    let il = "LD x\nADD y (* more *)\nST z\nLDN a\nS q\nCAL t(IN := b, PT := T#1s)\nLD t.Q\nCU ctr\nLIMIT 0, big\nJMPC L\nL: ANDN c\n";
    let names =
        crate::ide::monitor_paths(&project_with(il), &TextTarget::Pou("Main".into()), "Main");
    let shown: Vec<String> = names
        .iter()
        .map(|name| {
            let (line, column) = line_column(il, name.range.start);
            format!("{line}:{column} {} {}", &il[name.range.clone()], name.path)
        })
        .collect();
    expect![[r#"
        [
            "1:4 x Main.x",
            "2:5 y Main.y",
            "3:4 z Main.z",
            "4:5 a Main.a",
            "5:3 q Main.q",
            "6:5 t Main.t",
            "6:13 b Main.b",
            "7:4 t Main.t",
            "7:6 Q Main.t.Q",
            "8:4 ctr Main.ctr",
            "9:10 big Main.big",
            "11:9 c Main.c",
        ]
    "#]]
    .assert_debug_eq(&shown);
}
