//! The dialects of `docs/dialect.md` on each of their cases: the default (CODESYS V3.5)
//! compiles them, with a warning where CODESYS warns, and gives CODESYS's run-time result;
//! `iec-strict` refuses them with the code IEC's rule has.

use compiler::{Code, Severity, SourceProject};
use project_model::Dialect;

use super::{check, run};

/// The codes of the findings on `source` checked in `dialect`, errors and warnings, with W0001
/// and W0002 (unused variables, which the small programs have on purpose) left out.
#[track_caller]
fn codes(source: &str, dialect: Dialect) -> Vec<(Code, Severity)> {
    let mut project = SourceProject::new(source);
    assert!(
        project.parse.errors().is_empty(),
        "{:?}",
        project.parse.errors()
    );
    project.project.dialect = dialect;
    compiler::sema::check_project(&project.project)
        .into_iter()
        .map(|found| (found.diagnostic.code, found.diagnostic.severity))
        .filter(|(code, _)| !matches!(code, Code::UnusedVariable | Code::UnassignedVariable))
        .collect()
}

/// A program of `declarations` and `body`.
fn program(declarations: &str, body: &str) -> String {
    format!("PROGRAM main VAR {declarations} END_VAR\n{body}\nEND_PROGRAM")
}

#[test]
fn arithmetic_on_bit_strings_wraps_in_the_bit_string_by_default_and_is_refused_by_iec_strict() {
    let declarations = "b : BYTE := 255; w : WORD := 16#FFFF; d : DWORD := 10; bb : BYTE := 200; n : INT := 100; wide : INT; m : BYTE; q : WORD; less : BOOL; same : BOOL;";
    let body = "b := b + 1; w := w * 2; d := d - 11; wide := bb + n; m := bb MOD 7; q := w / WORD#3; less := n < bb; same := bb = UINT#200;";
    let source = program(declarations, body);
    assert_eq!(codes(&source, Dialect::Codesys), Vec::new());
    let s = run(&source, 1);
    check(
        &s,
        &[
            ("main.b", "0"),
            ("main.w", "65534"),
            ("main.d", "4294967295"),
            ("main.wide", "300"),
            ("main.m", "4"),
            ("main.q", "21844"),
            ("main.less", "TRUE"),
            ("main.same", "TRUE"),
        ],
    );
    assert_eq!(
        codes(&source, Dialect::IecStrict),
        vec![(Code::InvalidOperands, Severity::Error); 8]
    );
}

#[test]
fn narrowing_integer_assignments_warn_and_keep_the_low_bits_by_default_and_are_refused_by_iec_strict()
 {
    let declarations = "x : SINT; i : INT := 4223; s : SINT; minus : INT := -1; u : UINT; big : DINT := 70000; w : WORD; k : USINT := 250 + 10;";
    let body = "x := 127 + 1; s := i; u := minus; w := big;";
    let source = program(declarations, body);
    let warning = (Code::ImplicitNarrowing, Severity::Warning);
    assert_eq!(codes(&source, Dialect::Codesys), vec![warning; 5]);
    let s = run(&source, 1);
    check(
        &s,
        &[
            ("main.x", "-128"),
            ("main.s", "127"),
            ("main.u", "65535"),
            ("main.w", "4464"),
            ("main.k", "4"),
        ],
    );
    assert_eq!(
        codes(&source, Dialect::IecStrict),
        vec![(Code::TypeMismatch, Severity::Error); 5]
    );
}

#[test]
fn inputs_narrow_like_assignments_but_a_var_in_out_takes_only_its_own_type() {
    let source = "FUNCTION Twice : DINT VAR_INPUT x : SINT; END_VAR Twice := SINT_TO_DINT(x) * 2; END_FUNCTION
        PROGRAM main VAR i : INT := 4223; r : DINT; END_VAR r := Twice(x := i); END_PROGRAM";
    let warning = (Code::ImplicitNarrowing, Severity::Warning);
    assert_eq!(codes(source, Dialect::Codesys), vec![warning]);
    check(&run(source, 1), &[("main.r", "254")]);
    assert_eq!(
        codes(source, Dialect::IecStrict),
        vec![(Code::TypeMismatch, Severity::Error)]
    );
    let in_out =
        "FUNCTION Bump : BOOL VAR_IN_OUT x : SINT; END_VAR x := x + 1; Bump := TRUE; END_FUNCTION
        PROGRAM main VAR i : INT; b : BOOL; END_VAR b := Bump(x := i); END_PROGRAM";
    for dialect in [Dialect::Codesys, Dialect::IecStrict] {
        assert_eq!(
            codes(in_out, dialect),
            vec![(Code::TypeMismatch, Severity::Error)],
            "{dialect:?}"
        );
    }
}

#[test]
fn integers_into_reals_that_may_round_them_warn_by_default_and_are_refused_by_iec_strict() {
    let declarations =
        "d : DINT := 16777217; r : REAL; l : LINT := -3; r2 : REAL; dw : DWORD := 7; r3 : REAL;";
    let source = program(declarations, "r := d; r2 := l; r3 := dw;");
    let warning = (Code::ImplicitRealRounding, Severity::Warning);
    assert_eq!(codes(&source, Dialect::Codesys), vec![warning; 3]);
    let s = run(&source, 1);
    // 16777217 is the first integer a REAL cannot hold; the nearest REAL is 16777216.
    check(
        &s,
        &[("main.r", "16777216"), ("main.r2", "-3"), ("main.r3", "7")],
    );
    assert_eq!(
        codes(&source, Dialect::IecStrict),
        vec![(Code::TypeMismatch, Severity::Error); 3]
    );
}

#[test]
fn reals_into_integers_warn_and_round_by_default_and_are_refused_by_iec_strict() {
    let source = "FUNCTION Twice : DINT VAR_INPUT x : INT; END_VAR Twice := INT_TO_DINT(x) * 2; END_FUNCTION
        PROGRAM main
        VAR
            i : INT; x : INT := 3; p : DINT; half : REAL := 2.5; minus : LREAL := -2.5; low : REAL := 1.4;
            a : INT; b : DINT; c : SINT; d : INT; w : WORD; t : DINT; k : INT := 7.5;
        END_VAR
        i := EXPT(2, 10); p := x ** 4; a := half; b := minus; c := low; d := 7.6; w := half * 100.0;
        t := Twice(x := half);
        END_PROGRAM";
    let warning = (Code::ImplicitRealToInteger, Severity::Warning);
    assert_eq!(codes(source, Dialect::Codesys), vec![warning; 9]);
    let s = run(source, 1);
    // Rounded to the nearest integer, halves away from zero, as REAL_TO_INT rounds.
    check(
        &s,
        &[
            ("main.i", "1024"),
            ("main.p", "81"),
            ("main.a", "3"),
            ("main.b", "-3"),
            ("main.c", "1"),
            ("main.d", "8"),
            ("main.w", "250"),
            ("main.t", "6"),
            ("main.k", "8"),
        ],
    );
    assert_eq!(
        codes(source, Dialect::IecStrict),
        vec![(Code::TypeMismatch, Severity::Error); 9]
    );
}

#[test]
fn signed_and_unsigned_integers_combine_in_the_smallest_signed_type_holding_both_by_default() {
    let declarations = "a : INT := 32767; u : UINT := 65535; minus : INT := -1; d : DINT := -2; ud : UDINT := 4294967295;
        si : SINT := -1; us : USINT := 255; bb : BYTE := 200; sn : SINT := -100;
        sum : DINT; product : LINT; small : INT; less : BOOL; same : BOOL; greater : BOOL; bits : INT; rest : DINT; narrow : INT;";
    let body =
        "sum := a + u; product := d * ud; small := si + us; less := minus < u; same := si = us;
        greater := ud > d; bits := bb + sn; rest := minus MOD u; narrow := a + u;";
    let source = program(declarations, body);
    // Only the last assignment narrows (DINT into INT), which warns as every narrowing does.
    assert_eq!(
        codes(&source, Dialect::Codesys),
        vec![(Code::ImplicitNarrowing, Severity::Warning)]
    );
    let s = run(&source, 1);
    check(
        &s,
        &[
            // 98302 fits neither INT nor UINT: the sum is a DINT.
            ("main.sum", "98302"),
            // -8589934590 fits neither DINT nor UDINT: the product is a LINT.
            ("main.product", "-8589934590"),
            ("main.small", "254"),
            // Compared as numbers, not as bit patterns: -1 < 65535 and -1 <> 255.
            ("main.less", "TRUE"),
            ("main.same", "FALSE"),
            ("main.greater", "TRUE"),
            ("main.bits", "100"),
            ("main.rest", "-1"),
            // 98302 (16#17FFE) keeps its low 16 bits in an INT: 16#7FFE.
            ("main.narrow", "32766"),
        ],
    );
    assert_eq!(
        codes(&source, Dialect::IecStrict),
        vec![(Code::InvalidOperands, Severity::Error); 9]
    );
}

#[test]
fn integers_and_reals_combine_in_the_real_type_by_default() {
    let declarations =
        "ud : UDINT := 3; r : REAL := 0.5; i : INT := 4; l : LREAL := 0.25; d : DINT := 16777217;
        p : REAL; q : LREAL; s : REAL; less : BOOL; same : BOOL;";
    let body = "p := ud * r; q := i + l; s := d / r; less := i < r; same := i = l * 16.0;";
    let source = program(declarations, body);
    // UDINT and DINT may round in a REAL, which warns as the assignment `r := d` does; an INT
    // is exact in both real types, so IEC converts it too and only the first two are refused
    // by iec-strict.
    let warning = (Code::ImplicitRealRounding, Severity::Warning);
    assert_eq!(codes(&source, Dialect::Codesys), vec![warning; 2]);
    let s = run(&source, 1);
    check(
        &s,
        &[
            ("main.p", "1.5"),
            ("main.q", "4.25"),
            // 16777217 rounds to 16777216 in a REAL before the division.
            ("main.s", "33554432"),
            ("main.less", "FALSE"),
            ("main.same", "TRUE"),
        ],
    );
    assert_eq!(
        codes(&source, Dialect::IecStrict),
        vec![(Code::InvalidOperands, Severity::Error); 2]
    );
}

#[test]
fn what_codesys_refuses_both_dialects_refuse() {
    for (declarations, body, code) in [
        ("x : BOOL; n : INT;", "n := x + 1;", Code::InvalidOperands),
        ("t : TIME; n : DINT;", "n := t;", Code::TypeMismatch),
        // No integer type holds both a LINT's and a ULINT's range.
        (
            "l : LINT; ul : ULINT; n : LINT;",
            "n := l + ul;",
            Code::InvalidOperands,
        ),
        (
            "s : STRING; b : BYTE;",
            "b := s + 1;",
            Code::InvalidOperands,
        ),
    ] {
        let source = program(declarations, body);
        for dialect in [Dialect::Codesys, Dialect::IecStrict] {
            assert_eq!(
                codes(&source, dialect),
                vec![(code, Severity::Error)],
                "{body} in {dialect:?}"
            );
        }
    }
}
