//! Every standard function and function block the checker knows, compiled and run with its
//! result checked against a value worked out by hand or with Rust's own arithmetic: nothing the
//! checker accepts may fail in the code generator. A name the checker learns without a case here
//! fails `every_standard_name_has_a_case`.

use std::collections::BTreeSet;

use anyhow::{anyhow, bail};
use program_image::ProgramImage;
use runtime::simulation::Simulation;

/// What a variable must hold after the run.
enum Want {
    /// Exactly this IEC literal.
    Is(&'static str),
    /// A real within a millionth (relative) of this value.
    Near(f64),
}

/// One call of a standard name: declarations, statements and the values they must leave.
struct Case {
    /// The standard name the case calls.
    name: &'static str,
    /// The declarations inside `VAR … END_VAR` of `PROGRAM main`.
    vars: &'static str,
    /// The statements of `main`.
    body: &'static str,
    /// `main`'s variables and what they must hold after two cycles.
    want: Vec<(&'static str, Want)>,
}

fn case(
    name: &'static str,
    vars: &'static str,
    body: &'static str,
    want: Vec<(&'static str, Want)>,
) -> Case {
    Case {
        name,
        vars,
        body,
        want,
    }
}

use Want::{Is, Near};

mod bcd;

/// The cases, one or more for each standard name, with the argument types where the result
/// depends on them.
fn cases() -> Vec<Case> {
    vec![
        // Numeric, per type family.
        case(
            "ABS",
            "i : INT := -7; d : DINT; r : REAL; l : LREAL;",
            "i := ABS(i); d := ABS(DINT#-70000); r := ABS(REAL#-2.5); l := ABS(LREAL#-0.125);",
            vec![
                ("i", Is("7")),
                ("d", Is("70000")),
                ("r", Near(2.5)),
                ("l", Near(0.125)),
            ],
        ),
        case(
            "SQRT",
            "r : REAL; l : LREAL;",
            "r := SQRT(REAL#2.0); l := SQRT(LREAL#2.0);",
            vec![("r", Near(2f64.sqrt())), ("l", Near(2f64.sqrt()))],
        ),
        case(
            "LN",
            "l : LREAL;",
            "l := LN(LREAL#10.0);",
            vec![("l", Near(10f64.ln()))],
        ),
        case(
            "LOG",
            "r : REAL;",
            "r := LOG(REAL#1000.0);",
            vec![("r", Near(3.0))],
        ),
        case(
            "EXP",
            "l : LREAL;",
            "l := EXP(LREAL#1.5);",
            vec![("l", Near(1.5f64.exp()))],
        ),
        // EXPT and `**` are typed alike (`sema::ty::power_type`): LREAL from integers.
        case(
            "EXPT",
            "l : LREAL; d : LREAL; r : REAL; x : LREAL; i : INT := 3; n : DINT := -2;",
            "l := EXPT(2, 10); d := EXPT(i, 4); r := EXPT(REAL#2.0, 0.5); x := EXPT(LREAL#1.5, n);",
            vec![
                ("l", Near(1024.0)),
                ("d", Near(81.0)),
                ("r", Near(2f64.sqrt())),
                ("x", Near(1.5f64.powi(-2))),
            ],
        ),
        case(
            "SIN",
            "l : LREAL;",
            "l := SIN(LREAL#0.5);",
            vec![("l", Near(0.5f64.sin()))],
        ),
        case(
            "COS",
            "r : REAL;",
            "r := COS(REAL#0.5);",
            vec![("r", Near(0.5f64.cos()))],
        ),
        case(
            "TAN",
            "l : LREAL;",
            "l := TAN(LREAL#0.5);",
            vec![("l", Near(0.5f64.tan()))],
        ),
        case(
            "ASIN",
            "l : LREAL;",
            "l := ASIN(LREAL#0.5);",
            vec![("l", Near(0.5f64.asin()))],
        ),
        case(
            "ACOS",
            "l : LREAL;",
            "l := ACOS(LREAL#0.5);",
            vec![("l", Near(0.5f64.acos()))],
        ),
        case(
            "ATAN",
            "l : LREAL;",
            "l := ATAN(LREAL#0.5);",
            vec![("l", Near(0.5f64.atan()))],
        ),
        case(
            "ATAN2",
            "l : LREAL; r : REAL;",
            "l := ATAN2(LREAL#1.0, LREAL#-1.0); r := ATAN2(REAL#-2.0, REAL#3.0);",
            vec![
                ("l", Near(1f64.atan2(-1.0))),
                ("r", Near((-2f64).atan2(3.0))),
            ],
        ),
        // Arithmetic.
        case(
            "ADD",
            "i : INT; r : REAL; t : TIME;",
            "i := ADD(1, 2, 3); r := ADD(REAL#0.5, 0.25); t := ADD(T#1s, T#250ms);",
            vec![("i", Is("6")), ("r", Near(0.75)), ("t", Is("T#1s250ms"))],
        ),
        case(
            "SUB",
            "d : DINT; l : LREAL;",
            "d := SUB(DINT#10, 70000); l := SUB(LREAL#1.0, 0.25);",
            vec![("d", Is("-69990")), ("l", Near(0.75))],
        ),
        case(
            "MUL",
            "i : INT; r : REAL;",
            "i := MUL(2, 3, 4); r := MUL(REAL#1.5, 4.0);",
            vec![("i", Is("24")), ("r", Near(6.0))],
        ),
        case(
            "DIV",
            "i : INT; r : REAL;",
            "i := DIV(-7, 2); r := DIV(REAL#1.0, 4.0);",
            vec![("i", Is("-3")), ("r", Near(0.25))],
        ),
        case(
            "MOD",
            "i : INT; d : DINT;",
            "i := MOD(-7, 2); d := MOD(DINT#100000, 7);",
            vec![("i", Is("-1")), ("d", Is(leak(100_000 % 7)))],
        ),
        case(
            "MOVE",
            "i : INT; s : STRING;",
            "i := MOVE(42); s := MOVE('abc');",
            vec![("i", Is("42")), ("s", Is("'abc'"))],
        ),
        // Bit strings.
        case(
            "SHL",
            "b : BYTE; w : WORD;",
            "b := SHL(BYTE#16#81, 1); w := SHL(WORD#16#0081, 4);",
            vec![
                ("b", Is(leak(0x81u8 << 1))),
                ("w", Is(leak(0x0081u16 << 4))),
            ],
        ),
        case(
            "SHR",
            "b : BYTE;",
            "b := SHR(BYTE#16#81, 1);",
            vec![("b", Is(leak(0x81u8 >> 1)))],
        ),
        case(
            "ROL",
            "b : BYTE; w : WORD;",
            "b := ROL(BYTE#16#81, 1); w := ROL(WORD#16#8001, 4);",
            vec![
                ("b", Is(leak(0x81u8.rotate_left(1)))),
                ("w", Is(leak(0x8001u16.rotate_left(4)))),
            ],
        ),
        case(
            "ROR",
            "b : BYTE;",
            "b := ROR(BYTE#16#81, 1);",
            vec![("b", Is(leak(0x81u8.rotate_right(1))))],
        ),
        case(
            "AND",
            "b : BYTE; x : BOOL;",
            "b := AND(BYTE#16#F0, BYTE#16#3C, BYTE#16#1F); x := AND(TRUE, FALSE);",
            vec![("b", Is(leak(0xF0u8 & 0x3C & 0x1F))), ("x", Is("FALSE"))],
        ),
        case(
            "OR",
            "w : WORD;",
            "w := OR(WORD#16#0F00, WORD#16#00F0);",
            vec![("w", Is(leak(0x0FF0u16)))],
        ),
        case(
            "XOR",
            "b : BYTE;",
            "b := XOR(BYTE#16#FF, BYTE#16#0F);",
            vec![("b", Is(leak(0xF0u8)))],
        ),
        case(
            "NOT",
            "b : BYTE; x : BOOL;",
            "b := NOT(BYTE#16#0F); x := NOT(FALSE);",
            vec![("b", Is(leak(!0x0Fu8))), ("x", Is("TRUE"))],
        ),
        // Selection and comparison.
        case(
            "SEL",
            "i : INT; s : STRING;",
            "i := SEL(TRUE, 1, 2); s := SEL(FALSE, 'a', 'b');",
            vec![("i", Is("2")), ("s", Is("'a'"))],
        ),
        case(
            "MAX",
            "i : INT; r : REAL; t : TIME;",
            "i := MAX(3, 9, -2); r := MAX(REAL#1.5, 0.5); t := MAX(T#1s, T#2s);",
            vec![("i", Is("9")), ("r", Near(1.5)), ("t", Is("T#2s"))],
        ),
        case(
            "MAX",
            "s : STRING; x : BOOL; c : STRING;",
            "s := MAX('abc', 'abd', 'ab'); x := MAX(FALSE, TRUE, FALSE); c := LIMIT('b', 'z', 'k');",
            vec![("s", Is("'abd'")), ("x", Is("TRUE")), ("c", Is("'k'"))],
        ),
        case(
            "MIN",
            "s : STRING; x : BOOL;",
            "s := MIN('b', 'ab', 'abc'); x := MIN(TRUE, FALSE);",
            vec![("s", Is("'ab'")), ("x", Is("FALSE"))],
        ),
        case(
            "MIN",
            "i : INT; l : LREAL;",
            "i := MIN(3, 9, -2); l := MIN(LREAL#1.5, 0.5);",
            vec![("i", Is("-2")), ("l", Near(0.5))],
        ),
        case(
            "LIMIT",
            "i : INT; r : REAL;",
            "i := LIMIT(0, 120, 100); r := LIMIT(REAL#0.0, -1.0, 1.0);",
            vec![("i", Is("100")), ("r", Near(0.0))],
        ),
        case(
            "MUX",
            "i : INT; s : STRING;",
            "i := MUX(2, 10, 20, 30); s := MUX(1, 'x', 'y');",
            vec![("i", Is("30")), ("s", Is("'y'"))],
        ),
        case(
            "GT",
            "a : BOOL; b : BOOL; c : BOOL; d : BOOL;",
            "a := GT(3, 2); b := GT(REAL#1.0, 2.0); c := GT('c', 'b', 'a'); d := GT(3, 1, 2);",
            vec![
                ("a", Is("TRUE")),
                ("b", Is("FALSE")),
                ("c", Is("TRUE")),
                ("d", Is("FALSE")),
            ],
        ),
        case(
            "GE",
            "a : BOOL; b : BOOL;",
            "a := GE(2, 2, 1); b := GE(T#1s, T#2s);",
            vec![("a", Is("TRUE")), ("b", Is("FALSE"))],
        ),
        case(
            "EQ",
            "a : BOOL; b : BOOL;",
            "a := EQ(5, 5); b := EQ('ab', 'ac');",
            vec![("a", Is("TRUE")), ("b", Is("FALSE"))],
        ),
        case(
            "LE",
            "a : BOOL;",
            "a := LE(1, 2, 3);",
            vec![("a", Is("TRUE"))],
        ),
        case(
            "LT",
            "a : BOOL; b : BOOL;",
            "a := LT(1, 2); b := LT(LREAL#2.0, 1.0);",
            vec![("a", Is("TRUE")), ("b", Is("FALSE"))],
        ),
        case(
            "NE",
            "a : BOOL;",
            "a := NE(WORD#1, WORD#2);",
            vec![("a", Is("TRUE"))],
        ),
        // Strings.
        case(
            "LEN",
            "n : INT;",
            "n := LEN('hello');",
            vec![("n", Is("5"))],
        ),
        case(
            "LEFT",
            "s : STRING;",
            "s := LEFT('hello', 2);",
            vec![("s", Is("'he'"))],
        ),
        case(
            "RIGHT",
            "s : STRING;",
            "s := RIGHT('hello', 3);",
            vec![("s", Is("'llo'"))],
        ),
        case(
            "MID",
            "s : STRING;",
            "s := MID('hello', 3, 2);",
            vec![("s", Is("'ell'"))],
        ),
        case(
            "CONCAT",
            "s : STRING;",
            "s := CONCAT('ab', 'cd', 'e');",
            vec![("s", Is("'abcde'"))],
        ),
        case(
            "INSERT",
            "s : STRING;",
            "s := INSERT('abc', 'XY', 2);",
            vec![("s", Is("'abXYc'"))],
        ),
        case(
            "DELETE",
            "s : STRING;",
            "s := DELETE('abcdef', 2, 3);",
            vec![("s", Is("'abef'"))],
        ),
        case(
            "REPLACE",
            "s : STRING;",
            "s := REPLACE('abcdef', 'XY', 2, 3);",
            vec![("s", Is("'abXYef'"))],
        ),
        case(
            "FIND",
            "n : INT;",
            "n := FIND('abcabc', 'ca');",
            vec![("n", Is("3"))],
        ),
        // The string functions by formal name: CODESYS's names (Rivet's own), and the IEC
        // 61131-3 names Beremiz and matiec use (IN, IN1, IN2, L, P).
        case(
            "LEN",
            "n : INT; m : INT;",
            "n := LEN(STR := 'hello'); m := LEN(IN := 'hey');",
            vec![("n", Is("5")), ("m", Is("3"))],
        ),
        case(
            "LEFT",
            "s : STRING; t : STRING;",
            "s := LEFT(STR := 'hello', SIZE := 2); t := LEFT(L := 3, IN := 'hello');",
            vec![("s", Is("'he'")), ("t", Is("'hel'"))],
        ),
        case(
            "MID",
            "s : STRING; t : STRING;",
            "s := MID(STR := 'hello', LEN := 3, POS := 2); t := MID(IN := 'hello', P := 2, L := 3);",
            vec![("s", Is("'ell'")), ("t", Is("'ell'"))],
        ),
        case(
            "CONCAT",
            "s : STRING; t : STRING;",
            "s := CONCAT(STR1 := 'ab', STR2 := 'cd'); t := CONCAT(IN1 := 'ab', IN2 := 'cd', IN3 := 'e');",
            vec![("s", Is("'abcd'")), ("t", Is("'abcde'"))],
        ),
        case(
            "INSERT",
            "s : STRING;",
            "s := INSERT(IN1 := 'abc', IN2 := 'XY', P := 2);",
            vec![("s", Is("'abXYc'"))],
        ),
        case(
            "DELETE",
            "s : STRING;",
            "s := DELETE(IN := 'abcdef', L := 2, P := 3);",
            vec![("s", Is("'abef'"))],
        ),
        case(
            "REPLACE",
            "s : STRING; t : STRING;",
            "s := REPLACE(STR1 := 'abcdef', STR2 := 'XY', L := 2, P := 3); t := REPLACE(IN1 := 'abcdef', IN2 := 'XY', L := 2, P := 3);",
            vec![("s", Is("'abXYef'")), ("t", Is("'abXYef'"))],
        ),
        case(
            "FIND",
            "n : INT; m : INT;",
            "n := FIND(STR1 := 'abcabc', STR2 := 'ca'); m := FIND(IN2 := 'bc', IN1 := 'abcabc');",
            vec![("n", Is("3")), ("m", Is("2"))],
        ),
        // Time and date.
        // The clock operators on the simulated clock: the task time, which moves by the
        // implicit task's 10 ms from the first cycle (at 0) to the second and stands still
        // within a cycle.
        case(
            "TIME",
            "t : TIME; d : TIME; e : TIME; ms : DINT;",
            "d := TIME() - t; t := TIME(); e := TIME() - t; ms := TIME_TO_DINT(TIME());",
            vec![
                ("t", Is("T#10ms")),
                ("d", Is("T#10ms")),
                ("e", Is("T#0ms")),
                ("ms", Is("10")),
            ],
        ),
        case(
            "LTIME",
            "l : LTIME; d : LTIME; ns : LINT; r : REAL;",
            "d := LTIME() - l; l := LTIME(); ns := LTIME_TO_LINT(LTIME()); r := LTIME_TO_REAL(d);",
            vec![
                ("d", Is("LTIME#10ms")),
                ("ns", Is("10000000")),
                ("r", Near(1e7)),
            ],
        ),
        case(
            "ADD_TIME",
            "t : TIME;",
            "t := ADD_TIME(T#1s, T#500ms);",
            vec![("t", Is("T#1s500ms"))],
        ),
        case(
            "SUB_TIME",
            "t : TIME;",
            "t := SUB_TIME(T#1s, T#250ms);",
            vec![("t", Is("T#750ms"))],
        ),
        case(
            "MUL_TIME",
            "t : TIME; u : TIME;",
            "t := MUL_TIME(T#1s, 3); u := MUL_TIME(T#1s, REAL#2.5);",
            vec![("t", Is("T#3s")), ("u", Is("T#2s500ms"))],
        ),
        case(
            "DIV_TIME",
            "t : TIME;",
            "t := DIV_TIME(T#3s, 4);",
            vec![("t", Is("T#750ms"))],
        ),
        case(
            "ADD_TOD_TIME",
            "t : TOD;",
            "t := ADD_TOD_TIME(TOD#12:00:00, T#90m);",
            vec![("t", Is("TOD#13:30:00"))],
        ),
        case(
            "ADD_DT_TIME",
            "t : DT;",
            "t := ADD_DT_TIME(DT#2024-02-28-23:00:00, T#2h);",
            vec![("t", Is("DT#2024-02-29-01:00:00"))],
        ),
        case(
            "SUB_DATE_DATE",
            "t : TIME;",
            "t := SUB_DATE_DATE(D#2024-03-01, D#2024-02-28);",
            vec![("t", Is("T#2d"))],
        ),
        case(
            "SUB_TOD_TIME",
            "t : TOD;",
            "t := SUB_TOD_TIME(TOD#12:00:00, T#30m);",
            vec![("t", Is("TOD#11:30:00"))],
        ),
        case(
            "SUB_TOD_TOD",
            "t : TIME;",
            "t := SUB_TOD_TOD(TOD#12:00:00, TOD#11:59:30);",
            vec![("t", Is("T#30s"))],
        ),
        case(
            "SUB_DT_TIME",
            "t : DT;",
            "t := SUB_DT_TIME(DT#2024-03-01-00:30:00, T#1h);",
            vec![("t", Is("DT#2024-02-29-23:30:00"))],
        ),
        case(
            "SUB_DT_DT",
            "t : TIME;",
            "t := SUB_DT_DT(DT#2024-01-02-00:00:00, DT#2024-01-01-23:00:00);",
            vec![("t", Is("T#1h"))],
        ),
        case(
            "CONCAT_DATE_TOD",
            "t : DT;",
            "t := CONCAT_DATE_TOD(D#2024-05-06, TOD#07:08:09);",
            vec![("t", Is("DT#2024-05-06-07:08:09"))],
        ),
        // Conversion helpers.
        case(
            "TRUNC",
            "d : DINT; e : DINT;",
            "d := TRUNC(REAL#-2.7); e := TRUNC(LREAL#70000.9);",
            vec![("d", Is(leak(-2.7f64.trunc() as i64))), ("e", Is("70000"))],
        ),
        case(
            "TRUNC_INT",
            "i : INT;",
            "i := TRUNC_INT(REAL#9.99);",
            vec![("i", Is("9"))],
        ),
        case(
            "ROUND",
            "r : REAL; l : LREAL;",
            "r := ROUND(REAL#2.5); l := ROUND(LREAL#-1.4);",
            vec![("r", Near(2.5f64.round())), ("l", Near(-1.4f64.round()))],
        ),
        case(
            "BCD_TO_INT",
            "i : INT;",
            "i := BCD_TO_INT(WORD#16#1234);",
            vec![("i", Is("1234"))],
        ),
        case(
            "INT_TO_BCD",
            "w : WORD; b : BYTE;",
            "w := INT_TO_BCD(1234); b := INT_TO_BCD(42);",
            vec![("w", Is(leak(0x1234u16))), ("b", Is(leak(0x42u8)))],
        ),
        // Between the string widths (the other conversions: the test below).
        case(
            "STRING_TO_WSTRING",
            "w : WSTRING; s : STRING; n : INT;",
            "w := STRING_TO_WSTRING('abc'); s := WSTRING_TO_STRING(\"x$20ACy\"); n := LEN(w);",
            vec![("w", Is("'abc'")), ("s", Is("'xy'")), ("n", Is("3"))],
        ),
        // Addresses, sizes and references.
        case(
            "ADRINST",
            "t : TON; p : POINTER TO TON; q : BOOL;",
            "t(IN := TRUE, PT := T#0ms); p := ADRINST(t); q := p^.Q;",
            vec![("q", Is("TRUE"))],
        ),
        case(
            "BITADR",
            "x AT %IX2.3 : BOOL; w AT %QW4 : WORD; a : DWORD; b : DWORD; c : DWORD;",
            "a := BITADR(x); b := BITADR(w); c := BITADR(%MX1.7);",
            vec![
                ("a", Is(leak(2 * 8 + 3))),
                ("b", Is(leak(4 * 2 * 8))),
                ("c", Is(leak(8 + 7))),
            ],
        ),
        case(
            "ADR",
            "x : INT := 5; p : POINTER TO INT; y : INT;",
            "p := ADR(x); y := p^ + 1;",
            vec![("y", Is("6"))],
        ),
        case(
            "SIZEOF",
            "a : ARRAY[1..10] OF DINT; n : UDINT; w : UDINT;",
            "n := SIZEOF(a); w := SIZEOF(WORD#0);",
            vec![("n", Is("40")), ("w", Is("2"))],
        ),
        case(
            "XSIZEOF",
            "a : ARRAY[1..10] OF LREAL; n : ULINT;",
            "n := XSIZEOF(a);",
            vec![("n", Is("80"))],
        ),
        case(
            "LOWER_BOUND",
            "a : ARRAY[3..9, -2..2] OF INT; n : DINT; m : DINT;",
            "n := LOWER_BOUND(a, 1); m := LOWER_BOUND(a, 2);",
            vec![("n", Is("3")), ("m", Is("-2"))],
        ),
        case(
            "UPPER_BOUND",
            "a : ARRAY[3..9] OF INT; n : DINT;",
            "n := UPPER_BOUND(a, 1);",
            vec![("n", Is("9"))],
        ),
        case(
            "ISVALIDREF",
            "x : INT; r : REFERENCE TO INT; r2 : REFERENCE TO INT; a : BOOL; b : BOOL;",
            "r REF= x; a := ISVALIDREF(r); b := ISVALIDREF(r2);",
            vec![("a", Is("TRUE")), ("b", Is("FALSE"))],
        ),
        case(
            "__ISVALIDREF",
            "x : INT; r : REFERENCE TO INT; a : BOOL;",
            "r REF= x; a := __ISVALIDREF(r);",
            vec![("a", Is("TRUE"))],
        ),
        case(
            "ISVALIDREF",
            "x : INT; refs : ARRAY[1..3] OF REFERENCE TO INT; a : BOOL; b : BOOL;",
            "refs[1] REF= x; a := ISVALIDREF(refs[1]); b := ISVALIDREF(refs[3]);",
            vec![("a", Is("TRUE")), ("b", Is("FALSE"))],
        ),
        // Standard function blocks: two cycles of 10 ms each.
        case(
            "TON",
            "t : TON;",
            "t(IN := TRUE, PT := T#10ms);",
            vec![("t.Q", Is("TRUE")), ("t.ET", Is("T#10ms"))],
        ),
        case(
            "TOF",
            "t : TOF;",
            "t(IN := FALSE, PT := T#15ms);",
            vec![("t.Q", Is("FALSE"))],
        ),
        case(
            "TP",
            "t : TP;",
            "t(IN := TRUE, PT := T#50ms);",
            vec![("t.Q", Is("TRUE")), ("t.ET", Is("T#10ms"))],
        ),
        case(
            "LTON",
            "t : LTON;",
            "t(IN := TRUE, PT := LTIME#10ms);",
            vec![("t.Q", Is("TRUE")), ("t.ET", Is("LTIME#10ms"))],
        ),
        case(
            "LTOF",
            "t : LTOF; n : INT;",
            "n := n + 1; t(IN := n = 1, PT := LTIME#50ms);",
            vec![("t.Q", Is("TRUE")), ("t.ET", Is("LTIME#0ns"))],
        ),
        case(
            "LTP",
            "t : LTP;",
            "t(IN := TRUE, PT := LTIME#5ms);",
            vec![("t.Q", Is("FALSE")), ("t.ET", Is("LTIME#5ms"))],
        ),
        case(
            "CTU",
            "c : CTU; n : INT;",
            "n := n + 1; c(CU := n = 2, PV := 1);",
            vec![("c.CV", Is("1")), ("c.Q", Is("TRUE"))],
        ),
        case(
            "CTD",
            "c : CTD; n : INT;",
            "n := n + 1; c(CD := n = 2, LD := n = 1, PV := 5);",
            vec![("c.CV", Is("4")), ("c.Q", Is("FALSE"))],
        ),
        case(
            "CTUD",
            "c : CTUD; n : INT;",
            "n := n + 1; c(CU := n = 1, CD := n = 2, PV := 1);",
            vec![("c.CV", Is("0")), ("c.QD", Is("TRUE"))],
        ),
        case(
            "R_TRIG",
            "t : R_TRIG; hits : INT;",
            "t(CLK := TRUE); IF t.Q THEN hits := hits + 1; END_IF;",
            vec![("hits", Is("1"))],
        ),
        case(
            "F_TRIG",
            "t : F_TRIG; n : INT;",
            "n := n + 1; t(CLK := n = 1);",
            vec![("t.Q", Is("TRUE"))],
        ),
        case(
            "SR",
            "f : SR;",
            "f(SET1 := TRUE, RESET := TRUE);",
            vec![("f.Q1", Is("TRUE"))],
        ),
        case(
            "RS",
            "f : RS;",
            "f(SET := TRUE, RESET1 := TRUE);",
            vec![("f.Q1", Is("FALSE"))],
        ),
        case(
            "RTC",
            "c : RTC;",
            "c(EN := TRUE, PDT := DT#2024-01-01-00:00:00);",
            vec![("c.Q", Is("TRUE")), ("c.CDT", Is("DT#2024-01-01-00:00:00"))],
        ),
    ]
}

/// The standard names the checker refuses, each with a call and the code it is refused with.
const REFUSED: &[(&str, &str, &str, &str)] = &[
    ("INDEXOF", "n : DINT;", "n := INDEXOF(main);", "E0130"),
    ("__NEW", "p : POINTER TO INT;", "p := __NEW(INT);", "E0131"),
    ("__DELETE", "p : POINTER TO INT;", "__DELETE(p);", "E0131"),
    (
        "__QUERYINTERFACE",
        "a : POINTER TO INT; b : POINTER TO INT; ok : BOOL;",
        "ok := __QUERYINTERFACE(a, b);",
        "E0131",
    ),
    (
        "__QUERYPOINTER",
        "a : POINTER TO INT; b : POINTER TO INT; ok : BOOL;",
        "ok := __QUERYPOINTER(a, b);",
        "E0131",
    ),
    ("BITADR", "x : BOOL; a : DWORD;", "a := BITADR(x);", "E0132"),
    // Decimal digits code integers only.
    (
        "INT_TO_BCD",
        "r : REAL; w : WORD;",
        "w := INT_TO_BCD(r);",
        "E0104",
    ),
];

/// A value computed by Rust, as the literal the runtime prints.
fn leak(value: impl std::fmt::Display) -> &'static str {
    Box::leak(value.to_string().into_boxed_str())
}

/// Compiles and runs one case for two cycles, or says why it could not.
fn run_case(case: &Case) -> anyhow::Result<()> {
    let source = format!(
        "PROGRAM main VAR {} END_VAR\n{}\nEND_PROGRAM",
        case.vars, case.body
    );
    let project = compiler::SourceProject::new(&source);
    if !project.parse.errors().is_empty() {
        bail!("syntax errors: {:?}", project.parse.errors());
    }
    let image: ProgramImage = match compiler::compile_source(&project, "test.st") {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found.iter().map(|d| d.diagnostic.message.clone()).collect();
            bail!("does not check: {errors:?}");
        }
        Err(error) => bail!("does not compile: {error}"),
    };
    // Both engines, compared after each cycle (`docs/native-engine.md` §11.1).
    let simulation = runtime::differential::run_both(image, 2, |_, _| {})
        .map_err(|difference| anyhow!("the engines differ: {difference}"))?;
    if !simulation.faults().is_empty() {
        bail!("faults: {:?}", simulation.faults());
    }
    for (variable, want) in &case.want {
        let path = format!("main.{variable}");
        let got = runtime::value::read(simulation.engine(), &path)
            .map_err(|e| anyhow!("{path}: {e}"))?
            .to_string();
        let ok = match want {
            Is(text) => got == *text,
            Near(expected) => got
                .parse::<f64>()
                .is_ok_and(|value| (value - expected).abs() <= 1e-6 * expected.abs().max(1.0)),
        };
        if !ok {
            let expected = match want {
                Is(text) => (*text).to_owned(),
                Near(value) => format!("about {value}"),
            };
            bail!("{path} is {got}, expected {expected}");
        }
    }
    Ok(())
}

#[test]
fn the_refused_standard_names_are_refused_with_their_code() {
    for (name, vars, body, code) in REFUSED {
        let source = format!("PROGRAM main VAR {vars} END_VAR\n{body}\nEND_PROGRAM");
        let project = compiler::SourceProject::new(&source);
        let codes: Vec<String> = match compiler::compile_source(&project, "test.st") {
            Err(compiler::CompileError::Diagnostics(found)) => found
                .iter()
                .filter(|d| d.diagnostic.severity == compiler::Severity::Error)
                .map(|d| d.diagnostic.code.id().to_owned())
                .collect(),
            Ok(_) => panic!("{name}: compiled, but must be refused with {code}"),
            Err(error) => panic!("{name}: refused by the code generator, not the checker: {error}"),
        };
        assert_eq!(codes, [*code], "{name}");
    }
}

/// Calls the checker refuses with E0106, each with the message's gist: an input given twice
/// (by its two names, or by name and position), an extensible function's input by a name it
/// does not have.
#[test]
fn calls_giving_an_input_twice_or_by_an_unknown_name_are_refused() {
    for (vars, body, gist) in [
        (
            "s : STRING;",
            "s := MID(STR := 'abcdef', L := 2, LEN := 3);",
            "'MID': LEN gives an input L already gives",
        ),
        (
            "s : STRING;",
            "s := LEFT('abc', IN := 'def');",
            "'LEFT': IN gives an input argument 1 already gives",
        ),
        (
            "s : STRING;",
            "s := CONCAT(X := 'a', Y := 'b');",
            "'CONCAT' has no parameter 'X'",
        ),
        (
            "n : INT;",
            "n := ADD(IN0 := 1, IN1 := 2);",
            "'ADD' has no parameter 'IN0'",
        ),
        (
            "n : INT;",
            "n := ADD(IN1 := 1, IN1 := 2);",
            "'ADD': IN1 gives an input IN1 already gives",
        ),
    ] {
        let source = format!("PROGRAM main VAR {vars} END_VAR\n{body}\nEND_PROGRAM");
        let project = compiler::SourceProject::new(&source);
        let errors: Vec<(String, String)> = match compiler::compile_source(&project, "test.st") {
            Err(compiler::CompileError::Diagnostics(found)) => found
                .iter()
                .filter(|d| d.diagnostic.severity == compiler::Severity::Error)
                .map(|d| {
                    (
                        d.diagnostic.code.id().to_owned(),
                        d.diagnostic.message.clone(),
                    )
                })
                .collect(),
            Ok(_) => panic!("{body}: compiled, but must be refused"),
            Err(error) => panic!("{body}: refused by the code generator, not the checker: {error}"),
        };
        assert!(
            errors
                .iter()
                .any(|(code, message)| code == "E0106" && message.contains(gist)),
            "{body}: {errors:?}"
        );
    }
}

#[test]
fn every_standard_name_has_a_case() {
    let covered: BTreeSet<&str> = cases()
        .iter()
        .map(|c| c.name)
        .chain(REFUSED.iter().map(|(name, ..)| *name))
        .collect();
    let missing: Vec<&str> = compiler::sema::all_names()
        .filter(|name| !covered.contains(name))
        .collect();
    assert!(
        missing.is_empty(),
        "standard names without a case: {missing:?}"
    );
}

#[test]
fn every_standard_function_and_block_compiles_runs_and_computes_its_value() {
    let failures: Vec<String> = cases()
        .iter()
        .filter_map(|case| run_case(case).err().map(|e| format!("{}: {e}", case.name)))
        .collect();
    assert!(
        failures.is_empty(),
        "{} failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// `a ** b` and `EXPT(a, b)` have one type (its size tells REAL from LREAL) and one value, for
/// integer and real operands: REAL when every typed operand is REAL, LREAL otherwise.
#[test]
fn the_power_operator_and_expt_are_typed_alike() {
    // (base type, base, exponent type, exponent, size of the result in bytes, result).
    let table: &[(&str, &str, &str, &str, u32, f64)] = &[
        ("INT", "2", "INT", "10", 8, 1024.0),
        ("LINT", "3", "SINT", "3", 8, 27.0),
        ("DINT", "2", "REAL", "0.5", 8, 2f64.sqrt()),
        ("REAL", "1.5", "REAL", "2.0", 4, 2.25),
        ("REAL", "4.0", "INT", "2", 8, 16.0),
        ("LREAL", "2.0", "REAL", "-1.0", 8, 0.5),
    ];
    for (base_ty, base, exponent_ty, exponent, size, expected) in table {
        let vars = format!(
            "a : {base_ty} := {base}; b : {exponent_ty} := {exponent}; p : LREAL; q : LREAL; sp : UDINT; sq : UDINT;"
        );
        let body = "p := a ** b; q := EXPT(a, b); sp := SIZEOF(a ** b); sq := SIZEOF(EXPT(a, b));";
        let vars: &'static str = Box::leak(vars.into_boxed_str());
        let case = case(
            "EXPT",
            vars,
            body,
            vec![
                ("p", Near(*expected)),
                ("q", Near(*expected)),
                ("sp", Is(leak(size))),
                ("sq", Is(leak(size))),
            ],
        );
        if let Err(error) = run_case(&case) {
            panic!("{base_ty} ** {exponent_ty}: {error}");
        }
    }
}

/// Every `A_TO_B` and `TO_B` of two elementary types the checker accepts compiles and runs, and
/// the round trip of a value both types hold gives it back.
#[test]
fn every_conversion_the_checker_accepts_compiles_and_runs() {
    use compiler::elementary::Elementary;
    let mut failures = Vec::new();
    let mut compiled = 0;
    for from in Elementary::ALL {
        for to in Elementary::ALL {
            let (from, to) = (from.name(), to.name());
            for function in [format!("{from}_TO_{to}"), format!("TO_{to}")] {
                let source = format!(
                    "PROGRAM main VAR a : {from}; b : {to}; END_VAR\nb := {function}(a);\nEND_PROGRAM"
                );
                let project = compiler::SourceProject::new(&source);
                match compiler::compile_source(&project, "test.st") {
                    Ok(image) => {
                        compiled += 1;
                        match runtime::differential::run_both(image, 1, |_, _| {}) {
                            Ok(simulation) => {
                                if !simulation.faults().is_empty() {
                                    failures.push(format!("{function}: {:?}", simulation.faults()));
                                }
                            }
                            Err(difference) => failures.push(format!("{function}: {difference}")),
                        }
                    }
                    // Refused by the checker, with its code: not the code generator's concern.
                    Err(compiler::CompileError::Diagnostics(_)) => {}
                    Err(error) => failures.push(format!("{function}: {error}")),
                }
            }
        }
    }
    assert!(compiled > 500, "only {compiled} conversions compiled");
    assert!(
        failures.is_empty(),
        "{} failed:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// CODESYS's RTC counts whole seconds from PDT while EN is TRUE, with its outputs also read
/// through `=>`, and falls back to DT#1970-01-01-00:00:00 when EN goes FALSE.
#[test]
fn rtc_counts_seconds_from_its_preset_and_resets_when_disabled() {
    let source =
        "PROGRAM main VAR c : RTC; n : INT; enable : BOOL; stamp : DT; running : BOOL; END_VAR
        n := n + 1; enable := n <= 151;
        c(EN := enable, PDT := DT#2024-12-31-23:59:59, Q => running, CDT => stamp);
        END_PROGRAM";
    let image = match compiler::compile_source(&compiler::SourceProject::new(source), "test.st") {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found.iter().map(|d| d.diagnostic.message.clone()).collect();
            panic!("RTC does not check: {errors:?}")
        }
        Err(error) => panic!("RTC does not compile: {error}"),
    };
    // Cycles every 10 ms: the 151st is 1.5 s after the first, the rising edge of EN.
    let mut simulation = crate::simulate(image, 151);
    let read = |simulation: &Simulation, path: &str| {
        runtime::value::read(simulation.engine(), path)
            .unwrap()
            .to_string()
    };
    assert_eq!(read(&simulation, "main.stamp"), "DT#2025-01-01-00:00:00");
    assert_eq!(read(&simulation, "main.running"), "TRUE");
    simulation.run(1);
    assert_eq!(read(&simulation, "main.c.CDT"), "DT#1970-01-01-00:00:00");
    assert_eq!(read(&simulation, "main.c.Q"), "FALSE");
}
