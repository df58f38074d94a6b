//! Snapshots of the fused element instructions (`docs/native-engine.md` §10): which element
//! accesses become `LoadElement` and `StoreElement`, and which keep the pointer of `Address`
//! and `Element` because their address is needed or their array is reached through a pointer.

use expect_test::{Expect, expect};

use super::snapshot_tests::code_of;

const POINT: &str = "TYPE ST_Point : STRUCT x : INT; y : REAL; END_STRUCT END_TYPE\n";

/// Checks the code of `PROGRAM Main` with `declarations` and `body`, after `types`, against
/// `expected`.
#[track_caller]
fn check(types: &str, declarations: &str, body: &str, expected: Expect) {
    let source =
        format!("{types}PROGRAM Main\nVAR\n{declarations}\nEND_VAR\n{body}\nEND_PROGRAM\n");
    expected.assert_eq(&code_of(&source, "Main"));
}

#[test]
fn adding_the_index_to_an_element_is_one_load_one_add_and_one_store() {
    check(
        "",
        "a : ARRAY[1..1000] OF DINT; i : DINT;",
        "FOR i := 1 TO 1000 DO\n  a[i] := a[i] + i;\nEND_FOR",
        expect![[r#"
            0   move DINT I4000 <- K0
            1   cmp.gt DINT F0 <- I4000, K8
            2   jumpif F0 8
            3   loadelement DINT F8 <- I0[I4000 DINT from 1, 1000 of 4]+0
            4   add DINT F16 <- F8, I4000
            5   storeelement DINT I0[I4000 DINT from 1, 1000 of 4]+0 <- F16
            6   add DINT I4000 <- I4000, K0
            7   jump 1
            8   return
        "#]],
    );
}

#[test]
fn members_of_structure_elements_are_read_and_written_at_their_offset() {
    check(
        POINT,
        "pts : ARRAY[-2..2] OF ST_Point; i : SINT; n : INT;",
        "pts[i].x := n;\npts[i].y := pts[i].y * 2.0;\nn := pts[i + 1].x;",
        expect![[r#"
            0   storeelement INT I0[I40 SINT from -2, 5 of 8]+0 <- I42
            1   loadelement REAL F0 <- I0[I40 SINT from -2, 5 of 8]+4
            2   mul REAL F8 <- F0, K0
            3   storeelement REAL I0[I40 SINT from -2, 5 of 8]+4 <- F8
            4   add SINT F0 <- I40, K8
            5   loadelement INT I42 <- I0[F0 SINT from -2, 5 of 8]+0
            6   return
        "#]],
    );
}

#[test]
fn one_variable_index_among_constant_ones_is_fused_and_two_are_not() {
    check(
        "",
        "m : ARRAY[1..3, 1..4] OF INT; i : INT; j : UDINT;",
        "m[2, j] := 1;\nm[i, 3] := 2;\nm[i, j] := 3;",
        expect![[r#"
            0   storeelement INT I8[I28 UDINT from 1, 4 of 2]+0 <- K0
            1   storeelement INT I0[I24 INT from 1, 3 of 8]+4 <- K8
            2   address F0 <- &I0
            3   element F8 <- F0[I24 INT from 1, 3 of 8]
            4   element F16 <- F8[I28 UDINT from 1, 4 of 2]
            5   store 2 *F16 <- K16
            6   return
        "#]],
    );
}

#[test]
fn arrays_reached_through_pointers_references_and_in_outs_keep_the_pointer_path() {
    let source = "FUNCTION Pick : INT\nVAR_IN_OUT arr : ARRAY[1..5] OF INT; END_VAR\n\
                  VAR_INPUT i : INT; END_VAR\nPick := arr[i];\narr[i] := 0;\nEND_FUNCTION\n\
                  PROGRAM Main\nVAR a : ARRAY[1..5] OF INT; p : POINTER TO ARRAY[1..5] OF INT;\n\
                  r : REFERENCE TO ARRAY[1..5] OF INT; i : INT; x : INT; END_VAR\n\
                  p := ADR(a);\nr REF= a;\nx := p^[i];\nr[i] := x;\nx := Pick(a, i);\nEND_PROGRAM\n";
    expect![[r#"
        0   element F16 <- F0[F8 INT from 1, 5 of 2]
        1   load 2 F24 <- *F16
        2   move INT F10 <- F24
        3   element F16 <- F0[F8 INT from 1, 5 of 2]
        4   store 2 *F16 <- K0
        5   return
    "#]]
    .assert_eq(&code_of(source, "Pick"));
    expect![[r#"
        0   address F0 <- &I0
        1   copy 8 I16 <- F0
        2   address F0 <- &I0
        3   copy 8 I24 <- F0
        4   element F0 <- I16[I32 INT from 1, 5 of 2]
        5   load 2 F8 <- *F0
        6   move INT I34 <- F8
        7   element F0 <- I24[I32 INT from 1, 5 of 2]
        8   store 2 *F0 <- I34
        9   address F0 <- &I0
        10  call pou0 in [F0@0:8, I32@8:2] out [F8@10:2]
        11  move INT I34 <- F8
        12  return
    "#]]
    .assert_eq(&code_of(source, "Main"));
}

#[test]
fn an_element_whose_address_is_needed_is_reached_through_its_pointer() {
    // ADR, a bit of an element, a copy of a structure element and an element passed to a
    // VAR_IN_OUT all need the element's address.
    let source = format!(
        "{POINT}FUNCTION Bump : BOOL\nVAR_IN_OUT v : INT; END_VAR\nv := v + 1;\nEND_FUNCTION\n\
         PROGRAM Main\nVAR a : ARRAY[0..3] OF WORD; pts : ARRAY[0..3] OF ST_Point; \
         q : ST_Point; n : ARRAY[0..3] OF INT; i : INT; p : POINTER TO WORD; b : BOOL; END_VAR\n\
         p := ADR(a[i]);\nb := a[i].3;\na[i].4 := TRUE;\nq := pts[i];\npts[i] := q;\n\
         b := Bump(n[i]);\nEND_PROGRAM\n"
    );
    expect![[r#"
        0   address F0 <- &I0
        1   element F8 <- F0[I56 INT from 0, 4 of 2]
        2   copy 8 I64 <- F8
        3   address F0 <- &I0
        4   element F8 <- F0[I56 INT from 0, 4 of 2]
        5   load 2 F16 <- *F8
        6   getbit WORD F24 <- F16.3
        7   move BOOL I72 <- F24
        8   address F0 <- &I0
        9   element F8 <- F0[I56 INT from 0, 4 of 2]
        10  load 2 F16 <- *F8
        11  setbit WORD F16.4 <- K8
        12  store 2 *F8 <- F16
        13  address F0 <- &I8
        14  element F8 <- F0[I56 INT from 0, 4 of 8]
        15  load 8 F16 <- *F8
        16  copy 8 I40 <- F16
        17  address F0 <- &I8
        18  element F8 <- F0[I56 INT from 0, 4 of 8]
        19  store 8 *F8 <- I40
        20  address F0 <- &I48
        21  element F8 <- F0[I56 INT from 0, 4 of 2]
        22  call pou0 in [F8@0:8] out [F16@8:1]
        23  move BOOL I72 <- F16
        24  return
    "#]]
    .assert_eq(&code_of(&source, "Main"));
}

#[test]
fn a_target_element_is_located_before_a_value_that_calls_runs() {
    // The call could change the index or fault after its effects; the element's pointer is
    // taken first, as before the fused instructions, and a plain value keeps them fused.
    let source = "FUNCTION Next : INT\nVAR_INPUT v : INT; END_VAR\nNext := v + 1;\nEND_FUNCTION\n\
                  PROGRAM Main\nVAR a : ARRAY[1..5] OF INT; f : ARRAY[1..5] OF BOOL; i : INT; END_VAR\n\
                  i := a[1];\na[i] := Next(a[i]);\nf[i] S= a[i] > 2;\nEND_PROGRAM\n";
    expect![[r#"
        0   move INT I16 <- I0
        1   address F0 <- &I0
        2   element F8 <- F0[I16 INT from 1, 5 of 2]
        3   loadelement INT F16 <- I0[I16 INT from 1, 5 of 2]+0
        4   call pou0 in [F16@0:2] out [F24@2:2]
        5   store 2 *F8 <- F24
        6   address F0 <- &I10
        7   element F8 <- F0[I16 INT from 1, 5 of 1]
        8   loadelement INT F16 <- I0[I16 INT from 1, 5 of 2]+0
        9   cmp.gt INT F24 <- F16, K8
        10  jumpifnot F24 12
        11  store 1 *F8 <- K16
        12  return
    "#]]
    .assert_eq(&code_of(source, "Main"));
}

#[test]
fn string_characters_are_read_and_written_with_the_fused_instructions() {
    check(
        "",
        "s : STRING(10); w : WSTRING(3); i : ULINT; c : BYTE;",
        "c := s[i];\ns[i] := 65;\nw[i] := w[i + 1];",
        expect![[r#"
            0   loadelement BYTE I32 <- I0[I24 ULINT from 0, 11 of 1]+0
            1   storeelement BYTE I0[I24 ULINT from 0, 11 of 1]+0 <- K0
            2   add ULINT F0 <- I24, K8
            3   loadelement WORD F8 <- I12[F0 ULINT from 0, 4 of 2]+0
            4   storeelement WORD I12[I24 ULINT from 0, 4 of 2]+0 <- F8
            5   return
        "#]],
    );
}
