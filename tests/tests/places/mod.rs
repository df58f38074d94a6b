//! Places the checker accepts reached in every way the code generator must compile: bits and
//! parts of values reached through pointers and references, read and written, and parts of
//! properties read; and the places with no storage of their own (THIS, SUPER, properties)
//! refused with E0134 where a variable is needed, as CODESYS refuses them.

use compiler::{Code, Severity, SourceProject};

use super::{check, run};

/// The error codes of the findings on `source`.
#[track_caller]
fn error_codes(source: &str) -> Vec<Code> {
    let project = SourceProject::new(source);
    assert!(
        project.parse.errors().is_empty(),
        "{:?}",
        project.parse.errors()
    );
    compiler::sema::check_project(&project.project)
        .into_iter()
        .filter(|found| found.diagnostic.severity == Severity::Error)
        .map(|found| found.diagnostic.code)
        .collect()
}

#[test]
fn bits_and_parts_of_a_value_reached_through_a_pointer_are_read_and_written_in_place() {
    let s = run(
        "PROGRAM main
         VAR
             w : WORD := 16#0008; d : DWORD := 16#12345678; l : LWORD;
             p : POINTER TO WORD; pd : POINTER TO DWORD; r : REFERENCE TO DWORD;
             bit3 : BOOL; bit4 : BOOL; xbit : BOOL; low : BYTE; high : WORD; rw : WORD;
         END_VAR
         p := ADR(w); pd := ADR(d); r REF= d;
         bit3 := p^.3; bit4 := p^.4; xbit := p^.%X3;
         p^.0 := TRUE; p^.%X15 := TRUE; p^.3 := FALSE;
         low := pd^.%B0; high := pd^.%W1; rw := r.%W1;
         r.%B3 := 16#AB; r.%X0 := FALSE; pd^.%W0 := 16#0102;
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.bit3", "TRUE"),
            ("main.bit4", "FALSE"),
            ("main.xbit", "TRUE"),
            // Bits 0 and 15 set, bit 3 cleared, every other bit kept: 16#8001.
            ("main.w", "32769"),
            ("main.low", "120"),
            ("main.high", "4660"),
            ("main.rw", "4660"),
            // Byte 3 replaced, then the low word (whose bit 0 was cleared) replaced: 16#AB340102.
            ("main.d", "2872312066"),
        ],
    );
}

#[test]
fn bits_of_an_element_and_a_member_reached_through_pointers_change_only_that_bit() {
    let s = run(
        "TYPE ST_Flags : STRUCT a : BYTE; b : WORD; END_STRUCT END_TYPE
         PROGRAM main
         VAR
             flags : ST_Flags := (a := 16#F0, b := 16#00FF); table : ARRAY[0..2] OF BYTE := [1, 2, 4];
             ps : POINTER TO ST_Flags; pt : POINTER TO ARRAY[0..2] OF BYTE; i : INT := 2;
             seen : BOOL; cleared : BOOL;
         END_VAR
         ps := ADR(flags); pt := ADR(table);
         ps^.a.0 := TRUE; ps^.b.%X8 := TRUE; pt^[i].7 := TRUE; pt^[0].0 := FALSE;
         seen := pt^[1].1; cleared := ps^.a.4 AND NOT ps^.b.9;
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.flags.a", "241"),
            ("main.flags.b", "511"),
            ("main.table", "[0, 2, 132]"),
            ("main.seen", "TRUE"),
            ("main.cleared", "TRUE"),
        ],
    );
}

const POSITION_BLOCK: &str = "TYPE ST_Pos : STRUCT x : INT; y : INT; END_STRUCT END_TYPE
     FUNCTION_BLOCK FB_Axis
     VAR mPos : ST_Pos := (x := 3, y := 4); mFlags : WORD := 16#0005; END_VAR
     PROPERTY Pos : ST_Pos
     GET Pos := mPos; END_GET
     SET mPos := Pos; END_SET
     END_PROPERTY
     PROPERTY Flags : WORD
     GET Flags := mFlags; END_GET
     SET mFlags := Flags; END_SET
     END_PROPERTY
     METHOD Inside : INT Inside := Pos.x + Pos.y; IF Flags.2 THEN Inside := Inside + 100; END_IF END_METHOD
     END_FUNCTION_BLOCK
     FUNCTION Bump : INT VAR_IN_OUT v : INT; END_VAR v := v + 1; Bump := v; END_FUNCTION
     ";

#[test]
fn parts_of_a_property_are_read_through_its_getter() {
    let source = format!(
        "{POSITION_BLOCK}
         PROGRAM main
         VAR a : FB_Axis; x : INT; bit0 : BOOL; bit1 : BOOL; low : BYTE; inside : INT; END_VAR
         x := a.Pos.y; bit0 := a.Flags.0; bit1 := a.Flags.%X1; low := a.Flags.%B0; inside := a.Inside();
         END_PROGRAM"
    );
    let s = run(&source, 1);
    check(
        &s,
        &[
            ("main.x", "4"),
            ("main.bit0", "TRUE"),
            ("main.bit1", "FALSE"),
            ("main.low", "5"),
            ("main.inside", "107"),
        ],
    );
}

#[test]
fn a_property_part_written_or_passed_by_reference_and_this_assigned_are_refused_with_e0134() {
    let refused = [
        "a.Pos.x := 1;",
        "a.Flags.3 := TRUE;",
        "a.Flags.%B1 := 2;",
        "Bump(v := a.Pos.x);",
        "p := ADR(a.Pos);",
        "r REF= a.Pos;",
        "FOR i := 0 TO 1 DO END_FOR; FOR a.Pos.x := 0 TO 1 DO END_FOR;",
    ];
    for body in refused {
        let source = format!(
            "{POSITION_BLOCK}
             PROGRAM main VAR a : FB_Axis; p : POINTER TO ST_Pos; r : REFERENCE TO ST_Pos; i : INT; END_VAR
             {body}
             END_PROGRAM"
        );
        assert_eq!(error_codes(&source), vec![Code::UnwritablePlace], "{body}");
    }
    // The whole property is written through its setter.
    let source = format!(
        "{POSITION_BLOCK}
         PROGRAM main VAR a : FB_Axis; q : ST_Pos := (x := 7, y := 8); x : INT; END_VAR
         a.Pos := q; x := a.Pos.x;
         END_PROGRAM"
    );
    check(&run(&source, 1), &[("main.x", "7")]);
    let this_assigned = "FUNCTION_BLOCK FB_Self VAR other : POINTER TO FB_Self; END_VAR
         METHOD Swap : BOOL THIS := other; END_METHOD
         METHOD Pass : BOOL other := ADR(THIS); END_METHOD
         END_FUNCTION_BLOCK";
    assert_eq!(
        error_codes(this_assigned),
        vec![Code::UnwritablePlace, Code::UnwritablePlace]
    );
}

#[test]
fn a_single_bit_passed_by_reference_is_refused_with_e0135_and_copied_through_a_bool_it_runs() {
    let declarations = "FUNCTION Flip : BOOL VAR_IN_OUT v : BOOL; END_VAR v := NOT v; Flip := v; END_FUNCTION
         PROGRAM main VAR w : WORD; x AT %IX0.1 : BOOL; p : POINTER TO BOOL; r : REFERENCE TO BOOL; pw : POINTER TO WORD; b : BOOL; END_VAR";
    for body in [
        "Flip(v := w.3);",
        "Flip(v := w.%X3);",
        "Flip(v := pw^.2);",
        "Flip(v := x);",
        "p := ADR(w.3);",
        "p := ADR(x);",
        "r REF= w.3;",
    ] {
        let source = format!("{declarations}\n{body}\nEND_PROGRAM");
        assert_eq!(error_codes(&source), vec![Code::BitByReference], "{body}");
    }
    // The way CODESYS asks for: through a BOOL variable, copied back.
    let source = format!(
        "{declarations}\nw := 16#0008; b := w.3; Flip(v := b); w.3 := b; pw := ADR(w); pw^.0 := Flip(v := b);\nEND_PROGRAM"
    );
    check(&run(&source, 1), &[("main.w", "1"), ("main.b", "TRUE")]);
}

#[test]
fn a_reference_member_reached_through_a_pointer_reaches_its_target() {
    let s = run(
        "TYPE ST_Link : STRUCT target : REFERENCE TO INT; scale : INT := 3; END_STRUCT END_TYPE
         PROGRAM main
         VAR value : INT := 5; link : ST_Link; p : POINTER TO ST_Link; read : INT; bit1 : BOOL; END_VAR
         link.target REF= value; p := ADR(link);
         read := p^.target * p^.scale; p^.target := p^.target + 1; p^.target.3 := TRUE; bit1 := p^.target.1;
         END_PROGRAM",
        1,
    );
    // 5 * 3 read, then 6 written and bit 3 set: 14, whose bit 1 is set.
    check(
        &s,
        &[
            ("main.read", "15"),
            ("main.value", "14"),
            ("main.bit1", "TRUE"),
        ],
    );
}

#[test]
fn an_open_array_reached_through_this_is_indexed_and_passed_on() {
    let s = run(
        "FUNCTION Total : INT VAR_IN_OUT values : ARRAY[*] OF INT; END_VAR VAR i : DINT; END_VAR
         FOR i := LOWER_BOUND(values, 1) TO UPPER_BOUND(values, 1) DO Total := Total + values[i]; END_FOR
         END_FUNCTION
         FUNCTION_BLOCK FB_Sum
         VAR_IN_OUT values : ARRAY[*] OF INT; END_VAR
         VAR_OUTPUT first : INT; sum : INT; END_VAR
         first := THIS^.values[1]; THIS^.values[2] := 30; sum := Total(values := THIS^.values);
         END_FUNCTION_BLOCK
         PROGRAM main VAR data : ARRAY[1..3] OF INT := [1, 2, 3]; fb : FB_Sum; END_VAR
         fb(values := data);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.fb.first", "1"),
            ("main.fb.sum", "34"),
            ("main.data", "[1, 30, 3]"),
        ],
    );
}

#[test]
fn structures_instances_and_arrays_are_not_compared_as_codesys_compares_elementary_values_only() {
    let declarations = "TYPE ST_P : STRUCT x : INT; END_STRUCT END_TYPE
         INTERFACE I_A END_INTERFACE
         FUNCTION_BLOCK FB_A IMPLEMENTS I_A END_FUNCTION_BLOCK
         PROGRAM main VAR s1, s2 : ST_P; f1, f2 : FB_A; t1, t2 : TON; a1, a2 : ARRAY[0..1] OF INT; i1, i2 : I_A; b : BOOL; p1, p2 : POINTER TO INT; END_VAR";
    for body in [
        "b := s1 = s2;",
        "b := s1 <> s2;",
        "b := f1 = f2;",
        "b := t1 = t2;",
        "b := a1 = a2;",
    ] {
        let source = format!("{declarations}\n{body}\nEND_PROGRAM");
        assert_eq!(error_codes(&source), vec![Code::InvalidOperands], "{body}");
    }
    // Interfaces compare the instance they hold, pointers their address.
    let source = format!(
        "{declarations}\ni1 := f1; i2 := f1; p1 := ADR(s1.x); p2 := ADR(s2.x); b := i1 = i2 AND p1 <> p2;\nEND_PROGRAM"
    );
    check(&run(&source, 1), &[("main.b", "TRUE")]);
}
