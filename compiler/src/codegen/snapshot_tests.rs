//! Snapshots of the code generated for small bodies, as `program_image::listing` writes it.
//!
//! The execution tests prove what the code does; these show what it is, so a change in the
//! generator shows up as a readable diff (`UPDATE_EXPECT=1 cargo test -p compiler` rewrites
//! them after a deliberate change).

use expect_test::{Expect, expect};

use crate::codegen::{CodegenError, StatementPlace, Within};
use crate::origin::Origin;
use crate::{CompileError, SourceProject, compile_source};

/// The listing of the POU `pou` compiled from `source`.
#[track_caller]
pub(super) fn code_of(source: &str, pou: &str) -> String {
    let project = SourceProject::new(source);
    assert!(
        project.parse.errors().is_empty(),
        "syntax errors: {:?}",
        project.parse.errors()
    );
    let image = match compile_source(&project, "test.st") {
        Ok(image) => image,
        Err(CompileError::Diagnostics(found)) => {
            let errors: Vec<&str> = found
                .iter()
                .map(|d| d.diagnostic.message.as_str())
                .collect();
            panic!("the source does not check: {errors:#?}")
        }
        Err(error) => panic!("the source does not compile: {error}"),
    };
    let compiled = image
        .pous
        .iter()
        .find(|p| p.name == pou)
        .unwrap_or_else(|| panic!("no POU '{pou}' in the image"));
    program_image::listing(&compiled.code)
}

/// Checks the code of `PROGRAM Main` with `declarations` and `body` against `expected`.
#[track_caller]
fn check_main(declarations: &str, body: &str, expected: Expect) {
    let source = format!("PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n");
    expected.assert_eq(&code_of(&source, "Main"));
}

#[test]
fn an_assignment_with_arithmetic_computes_into_a_temporary() {
    check_main(
        "a : INT; b : INT := 3; c : DINT;",
        "a := b * 2 + 1;\nc := a - b;",
        expect![[r#"
            0   mul INT F0 <- I2, K0
            1   add INT I0 <- F0, K8
            2   sub INT F0 <- I0, I2
            3   convert INT>DINT I4 <- F0
            4   return
        "#]],
    );
}

#[test]
fn if_elsif_else_jumps_past_the_other_branches() {
    check_main(
        "x : INT; y : INT;",
        "IF x > 10 THEN\n  y := 1;\nELSIF x > 5 THEN\n  y := 2;\nELSE\n  y := 3;\nEND_IF",
        expect![[r#"
            0   cmp.gt INT F0 <- I0, K0
            1   jumpifnot F0 4
            2   move INT I2 <- K8
            3   jump 9
            4   cmp.gt INT F8 <- I0, K16
            5   jumpifnot F8 8
            6   move INT I2 <- K24
            7   jump 9
            8   move INT I2 <- K32
            9   return
        "#]],
    );
}

#[test]
fn case_compares_the_kept_selector_with_each_label() {
    check_main(
        "n : INT; y : INT;",
        "CASE n OF\n  1, 2: y := 10;\n  3..5: y := 20;\nELSE\n  y := 0;\nEND_CASE",
        expect![[r#"
            0   move INT F0 <- I0
            1   cmp.eq INT F8 <- F0, K0
            2   jumpif F8 6
            3   cmp.eq INT F16 <- F0, K8
            4   jumpif F16 6
            5   jump 8
            6   move INT I2 <- K16
            7   jump 16
            8   cmp.ge INT F32 <- F0, K24
            9   cmp.le INT F24 <- F0, K32
            10  and BOOL F24 <- F24, F32
            11  jumpif F24 13
            12  jump 15
            13  move INT I2 <- K40
            14  jump 16
            15  move INT I2 <- K48
            16  return
        "#]],
    );
}

#[test]
fn for_evaluates_its_end_once_and_counts_by_a_constant_step() {
    check_main(
        "i : INT; n : INT := 4; sum : INT;",
        "FOR i := 1 TO n BY 2 DO\n  sum := sum + i;\nEND_FOR",
        expect![[r#"
            0   move INT I0 <- K0
            1   move INT F0 <- I2
            2   cmp.gt INT F8 <- I0, F0
            3   jumpif F8 7
            4   add INT I4 <- I4, I0
            5   add INT I0 <- I0, K8
            6   jump 2
            7   return
        "#]],
    );
}

#[test]
fn while_and_repeat_jump_for_exit_and_continue() {
    check_main(
        "i : INT; j : INT;",
        "WHILE i < 10 DO\n  i := i + 1;\n  IF i = 5 THEN CONTINUE; END_IF\n  IF i = 8 THEN EXIT; END_IF\nEND_WHILE\nREPEAT\n  j := j + 1;\nUNTIL j >= 3 END_REPEAT",
        expect![[r#"
            0   cmp.lt INT F0 <- I0, K0
            1   jumpifnot F0 12
            2   add INT I0 <- I0, K8
            3   cmp.eq INT F8 <- I0, K16
            4   jumpifnot F8 7
            5   jump 0
            6   jump 7
            7   cmp.eq INT F8 <- I0, K24
            8   jumpifnot F8 11
            9   jump 12
            10  jump 11
            11  jump 0
            12  add INT I2 <- I2, K8
            13  cmp.ge INT F0 <- I2, K32
            14  jumpifnot F0 12
            15  return
        "#]],
    );
}

#[test]
fn a_function_call_transfers_its_inputs_and_result() {
    let source = "FUNCTION Twice : INT\nVAR_INPUT v : INT; END_VAR\nTwice := v * 2;\nEND_FUNCTION\n\
                  PROGRAM Main\nVAR x : INT; END_VAR\nx := Twice(v := x + 1);\nEND_PROGRAM\n";
    expect![[r#"
        0   add INT F0 <- I0, K8
        1   call pou0 in [F0@0:2] out [F8@2:2]
        2   move INT I0 <- F8
        3   return
    "#]]
    .assert_eq(&code_of(source, "Main"));
    expect![[r#"
        0   mul INT F2 <- F0, K0
        1   return
    "#]]
    .assert_eq(&code_of(source, "Twice"));
}

#[test]
fn an_instance_call_sets_inputs_calls_and_reads_outputs() {
    let source = "FUNCTION_BLOCK FB_Count\nVAR_INPUT step : INT; END_VAR\nVAR_OUTPUT total : INT; END_VAR\ntotal := total + step;\nEND_FUNCTION_BLOCK\n\
                  PROGRAM Main\nVAR counter : FB_Count; t : INT; END_VAR\ncounter(step := 2, total => t);\nEND_PROGRAM\n";
    expect![[r#"
        0   move INT I0 <- K0
        1   callblock pou0 on I0
        2   move INT I4 <- I2
        3   return
    "#]]
    .assert_eq(&code_of(source, "Main"));
}

#[test]
fn a_standard_block_and_a_standard_function_are_native_calls() {
    check_main(
        "ton : TON; go : BOOL; done : BOOL; a : INT; b : INT; m : INT;",
        "ton(IN := go, PT := T#2S, Q => done);\nm := MAX(a, b);",
        expect![[r#"
            0   move BOOL I0 <- I32
            1   move TIME I4 <- K0
            2   callstd Ton on I0
            3   move BOOL I33 <- I8
            4   max INT I38 <- I34, I36
            5   return
        "#]],
    );
}

#[test]
fn a_conversion_converts_between_elementary_types() {
    check_main(
        "i : INT := 7; r : REAL; d : DINT;",
        "r := INT_TO_REAL(i);\nd := REAL_TO_DINT(r * 1.5);",
        expect![[r#"
            0   convert INT>REAL I4 <- I0
            1   mul REAL F0 <- I4, K0
            2   convert REAL>DINT I8 <- F0
            3   return
        "#]],
    );
}

#[test]
fn a_string_operation_calls_the_string_function() {
    check_main(
        "s : STRING(20) := 'ab'; t : STRING(20); n : INT;",
        "t := CONCAT(s, 'cd');\nn := LEN(t);",
        expect![[r#"
            0   callfn Concat F0:80 <- I0:20, K0:2
            1   copy 21 F88 <- F0
            2   move BYTE F108 <- K8
            3   copy 21 I21 <- F88
            4   callfn Len F0:0 <- I21:20
            5   convert DINT>INT I42 <- F0
            6   return
        "#]],
    );
}

#[test]
fn array_indexing_checks_the_bounds_of_a_variable_index() {
    check_main(
        "a : ARRAY[1..5] OF INT; i : INT := 2; x : INT;",
        "a[i] := 4;\nx := a[3];",
        expect![[r#"
            0   storeelement INT I0[I10 INT from 1, 5 of 2]+0 <- K0
            1   move INT I12 <- I4
            2   return
        "#]],
    );
}

#[test]
fn a_struct_member_is_an_offset_into_its_variable() {
    let source = "TYPE ST_Point : STRUCT x : INT; y : INT; END_STRUCT END_TYPE\n\
                  PROGRAM Main\nVAR p : ST_Point; q : INT; END_VAR\np.y := 5;\nq := p.x + p.y;\nEND_PROGRAM\n";
    expect![[r#"
        0   move INT I2 <- K0
        1   add INT I4 <- I0, I2
        2   return
    "#]]
    .assert_eq(&code_of(source, "Main"));
}

#[test]
fn a_statement_the_generator_cannot_compile_is_reported_with_its_file_pou_and_line() {
    let project = SourceProject::new(
        "PROGRAM Main\nVAR i : I_Any; fb : FB_A; END_VAR\ni := fb;\n\nfb ?= i;\nEND_PROGRAM\n\
         INTERFACE I_Any END_INTERFACE\n\
         FUNCTION_BLOCK FB_A IMPLEMENTS I_Any END_FUNCTION_BLOCK\n",
    );
    let error = compile_source(&project, "test.st")
        .err()
        .map(|e| e.to_string());
    expect!["test.st: Main: line 5: cannot compile a ATTEMPT_ASSIGN_STMT"]
        .assert_eq(error.as_deref().unwrap_or("compiled"));
}

#[test]
fn a_compile_error_hands_the_caller_the_file_pou_line_and_origin_as_data() {
    let text = "PROGRAM Main\nVAR i : I_Any; fb : FB_A; END_VAR\nfb ?= i;\nEND_PROGRAM\n\
                INTERFACE I_Any END_INTERFACE\n\
                FUNCTION_BLOCK FB_A IMPLEMENTS I_Any END_FUNCTION_BLOCK\n";
    let project = SourceProject::new(text);
    let Err(CompileError::Unsupported(CodegenError::Unsupported { location, .. })) =
        compile_source(&project, "test.st")
    else {
        panic!("the attempt assignment compiled or failed otherwise");
    };
    let Some(StatementPlace {
        line,
        origin: Origin::Text { range },
    }) = location.statement().cloned()
    else {
        panic!("the error names no statement: {location:?}");
    };
    assert_eq!(line, 3);
    assert_eq!(
        location.within[..2],
        [
            Within::File("test.st".to_owned()),
            Within::Pou("Main".to_owned())
        ]
    );
    let Some(project_model::Object::Pou(main)) = project.project.application.object("Main") else {
        panic!("no POU Main");
    };
    let body = main.body.st_text().unwrap_or_default();
    assert_eq!(body.get(range), Some("fb ?= i;"));
}

#[test]
fn the_clock_operators_read_the_clock_into_a_temporary_of_their_width() {
    check_main(
        "t : TIME; l : LTIME;",
        "t := TIME() - t;\nl := LTIME();",
        expect![[r#"
            0   time F0
            1   sub TIME I0 <- F0, I0
            2   ltime F0
            3   move LTIME I8 <- F0
            4   return
        "#]],
    );
}

#[test]
fn a_function_the_project_names_time_is_called_instead_of_the_clock() {
    // ironplc's `time_function_decl.st`: the project's own TIME shadows the clock operator.
    let source = "FUNCTION TIME : TIME\nTIME := T#5s;\nEND_FUNCTION\n\nPROGRAM Main\nVAR\n    t : TIME;\nEND_VAR\nt := TIME();\nEND_PROGRAM\n";
    expect![[r#"
        0   call pou0 in [] out [F0@0:4]
        1   move TIME I0 <- F0
        2   return
    "#]]
    .assert_eq(&code_of(source, "Main"));
}

#[test]
fn an_index_into_a_string_reads_its_bytes_from_0_with_the_terminator_inside_the_bounds() {
    check_main(
        "s : STRING(4) := 'abcd'; w : WSTRING(2); j : INT; b : BYTE; c : WORD;",
        "b := s[j];\nc := w[1];",
        expect![[r#"
            0   loadelement BYTE I14 <- I0[I12 INT from 0, 5 of 1]+0
            1   move WORD I16 <- I8
            2   return
        "#]],
    );
}
