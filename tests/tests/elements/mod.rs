//! Array elements and string characters indexed by a value known only when the code runs:
//! read and written with the fused `LoadElement` and `StoreElement` where the array is a direct
//! place (`docs/native-engine.md` §10), and through the pointer of `Address` and `Element`
//! where its address is needed or the array is reached through a pointer, both with the same
//! values and the same faults.

use program_image::Instr;
use runtime::engine::FaultKind;

use super::{check, compile, run, value};

/// The instructions of POU `pou` in the image compiled from `source` that `wanted` accepts.
#[track_caller]
fn count_of(source: &str, pou: &str, wanted: fn(&Instr) -> bool) -> usize {
    let image = compile(source);
    let Some(found) = image.pous.iter().find(|p| p.name == pou) else {
        panic!("no POU '{pou}'");
    };
    found.code.iter().filter(|instr| wanted(instr)).count()
}

fn is_fused(instr: &Instr) -> bool {
    matches!(
        instr,
        Instr::LoadElement { .. } | Instr::StoreElement { .. }
    )
}

fn is_pointer_element(instr: &Instr) -> bool {
    matches!(instr, Instr::Element { .. })
}

/// The one fault of `s`, which must have stopped the task.
#[track_caller]
fn only_fault(s: &runtime::simulation::Simulation) -> &runtime::engine::FaultRecord {
    let [fault] = s.faults() else {
        panic!("one fault: {:?}", s.faults())
    };
    fault
}

#[test]
fn arrays_of_every_elementary_type_are_written_and_read_by_a_variable_index() {
    let types = [
        ("BOOL", "TRUE"),
        ("BYTE", "16#A5"),
        ("WORD", "16#BEEF"),
        ("DWORD", "16#DEADBEEF"),
        ("LWORD", "16#0123456789ABCDEF"),
        ("SINT", "-100"),
        ("INT", "-30000"),
        ("DINT", "-2000000000"),
        ("LINT", "-9000000000000000000"),
        ("USINT", "200"),
        ("UINT", "60000"),
        ("UDINT", "4000000000"),
        ("ULINT", "18000000000000000000"),
        ("REAL", "1.5"),
        ("LREAL", "-2.25"),
        ("TIME", "T#1s500ms"),
        ("LTIME", "LTIME#2h3ns"),
        ("DATE", "D#2024-02-29"),
        ("LDATE", "LDATE#2024-02-29"),
        ("TOD", "TOD#12:34:56"),
        ("LTOD", "LTOD#01:02:03.5"),
        ("DT", "DT#2024-02-29-12:00:00"),
        ("LDT", "LDT#2024-02-29-12:00:00"),
    ];
    for (ty, literal) in types {
        // The middle element of three from -1 is written and read back through a variable
        // index; its neighbours keep the type's default, which `z` holds too.
        let source = format!(
            "PROGRAM main VAR a : ARRAY[-1..1] OF {ty}; v : {ty} := {literal}; z : {ty}; b : {ty}; i : DINT := 0; END_VAR
             a[i] := v; b := a[i]; END_PROGRAM"
        );
        assert_eq!(count_of(&source, "main", is_fused), 2, "{ty}");
        let s = run(&source, 1);
        let written = value(&s, "main.v");
        let default = value(&s, "main.z");
        assert_ne!(written, default, "{ty}: the test value is the default");
        check(
            &s,
            &[
                ("main.b", &written),
                ("main.a[0]", &written),
                ("main.a[-1]", &default),
                ("main.a[1]", &default),
            ],
        );
    }
}

#[test]
fn members_of_structure_elements_are_written_and_read_at_their_offsets() {
    let source = "TYPE ST_Sample : STRUCT flag : BOOL; count : INT; level : REAL; total : LREAL; END_STRUCT END_TYPE
         PROGRAM main
         VAR samples : ARRAY[-2..2] OF ST_Sample; i : INT; counts : DINT; level : REAL; total : LREAL; flags : INT; END_VAR
         FOR i := -2 TO 2 DO
             samples[i].count := i * 10;
             samples[i].level := INT_TO_REAL(i) / 2.0;
             samples[i].total := samples[i].level * 4.0;
             samples[i].flag := i > 0;
         END_FOR
         FOR i := -2 TO 2 DO
             counts := counts + samples[i].count;
             level := level + samples[i].level;
             total := total + samples[i].total;
             IF samples[i].flag THEN flags := flags + 1; END_IF
         END_FOR
         END_PROGRAM";
    assert_eq!(count_of(source, "main", is_pointer_element), 0);
    let s = run(source, 1);
    check(
        &s,
        &[
            ("main.samples[-2].count", "-20"),
            ("main.samples[2].level", "1"),
            ("main.samples[-1].level", "-0.5"),
            ("main.samples[1].total", "2"),
            ("main.samples[0].flag", "FALSE"),
            ("main.samples[2].flag", "TRUE"),
            ("main.counts", "0"),
            ("main.level", "0"),
            ("main.total", "0"),
            ("main.flags", "2"),
        ],
    );
}

#[test]
fn string_characters_are_written_and_read_by_a_variable_index() {
    let source = "PROGRAM main VAR s : STRING(5) := 'hello'; w : WSTRING(3) := \"abc\"; i : ULINT; last : BYTE; END_VAR
         FOR i := 0 TO 4 DO s[i] := s[i] - 32; END_FOR
         FOR i := 0 TO 2 DO w[i] := w[2 - i]; END_FOR
         i := 5; last := s[i];
         END_PROGRAM";
    assert_eq!(count_of(source, "main", is_pointer_element), 0);
    let s = run(source, 1);
    // The reversal overwrote the first character before the last was read from it.
    check(
        &s,
        &[
            ("main.s", "'HELLO'"),
            ("main.w", "'cbc'"),
            ("main.last", "0"),
        ],
    );
    let s = run(
        "PROGRAM main VAR s : STRING(5); i : INT := 6; END_VAR s[i] := 65; END_PROGRAM",
        1,
    );
    assert_eq!(
        only_fault(&s).kind,
        FaultKind::IndexOutOfBounds {
            index: 6,
            low: 0,
            high: 5
        }
    );
}

#[test]
fn a_negative_low_bound_counts_elements_from_it_and_faults_below_it() {
    let source =
        "PROGRAM main VAR a : ARRAY[-5..-3] OF DINT; i : SINT; first : DINT; x : DINT; END_VAR
         FOR i := -5 TO -3 DO a[i] := i * i; END_FOR
         first := a[-5];
         i := -6; x := a[i];
         END_PROGRAM";
    let s = run(source, 1);
    assert_eq!(value(&s, "main.first"), "25");
    assert_eq!(value(&s, "main.a[-3]"), "9");
    let fault = only_fault(&s);
    assert_eq!(
        fault.kind,
        FaultKind::IndexOutOfBounds {
            index: -6,
            low: -5,
            high: -3
        }
    );
    assert_eq!((fault.pou.as_str(), fault.line), ("main", Some(4)));
}

#[test]
fn a_ulint_index_above_2_pow_63_is_out_of_bounds_and_reported_as_i64_max() {
    // Read as i64, 2^63 + 1 would be negative; it is outside whatever the bounds, and the
    // fault reports it saturated (docs/program-image.md, Element).
    let s = run(
        "PROGRAM main VAR a : ARRAY[0..3] OF INT; u : ULINT := 16#8000000000000001; ok : ULINT := 3; x : INT; END_VAR
         a[ok] := 7; x := a[ok];
         a[u] := 1;
         END_PROGRAM",
        1,
    );
    assert_eq!(value(&s, "main.x"), "7");
    let fault = only_fault(&s);
    assert_eq!(
        fault.kind,
        FaultKind::IndexOutOfBounds {
            index: i64::MAX,
            low: 0,
            high: 3
        }
    );
    assert_eq!(fault.line, Some(3));
}

/// The one fault of `source` run for a cycle, with the value of `main.a[-1]` after it.
#[track_caller]
fn fault_and_minus_one(source: &str) -> (FaultKind, Option<u32>, String) {
    let s = run(source, 1);
    let fault = only_fault(&s);
    (fault.kind.clone(), fault.line, value(&s, "main.a[-1]"))
}

#[test]
fn an_unsigned_64_bit_index_of_2_pow_64_minus_1_does_not_reach_index_minus_1() {
    // 2^64 - 1 read as i64 is -1, inside -2..2: the fused read and write, the pointer of
    // Element (a VAR_IN_OUT array) and OpenElement (an ARRAY[*]) must all fault instead.
    let expected = FaultKind::IndexOutOfBounds {
        index: i64::MAX,
        low: -2,
        high: 2,
    };
    // ST takes only integers as indices; LWORD is pinned by the jit's and the runtime's own
    // tests, where an image may carry it.
    let read = "PROGRAM main VAR a : ARRAY[-2..2] OF INT; u : ULINT := 16#FFFFFFFFFFFFFFFF; x : INT; END_VAR
         a[-1] := 5;
         x := a[u];
         END_PROGRAM";
    assert_eq!(count_of(read, "main", is_fused), 1);
    assert_eq!(
        fault_and_minus_one(read),
        (expected.clone(), Some(3), "5".to_string()),
        "read"
    );
    let write = read.replace("x := a[u];", "a[u] := 9;");
    assert_eq!(count_of(&write, "main", is_fused), 1);
    assert_eq!(
        fault_and_minus_one(&write),
        (expected.clone(), Some(3), "5".to_string()),
        "write"
    );
    let through_pointer = "FUNCTION Put : BOOL VAR_IN_OUT v : ARRAY[-2..2] OF INT; END_VAR VAR_INPUT i : ULINT; END_VAR
         v[i] := 9;
         END_FUNCTION
         PROGRAM main VAR a : ARRAY[-2..2] OF INT; u : ULINT := 16#FFFFFFFFFFFFFFFF; END_VAR
         a[-1] := 5;
         Put(v := a, i := u);
         END_PROGRAM";
    assert_eq!(count_of(through_pointer, "Put", is_pointer_element), 1);
    assert_eq!(
        fault_and_minus_one(through_pointer),
        (expected.clone(), Some(2), "5".to_string()),
        "through Element"
    );
    let open = through_pointer.replace("v : ARRAY[-2..2] OF INT", "v : ARRAY[*] OF INT");
    let is_open = |instr: &Instr| matches!(instr, Instr::OpenElement { .. });
    assert_eq!(count_of(&open, "Put", is_open), 1);
    assert_eq!(
        fault_and_minus_one(&open),
        (expected, Some(2), "5".to_string()),
        "through OpenElement"
    );
}

#[test]
fn an_index_out_of_bounds_names_the_pou_and_line_of_the_read_or_the_write() {
    let source = "FUNCTION_BLOCK FB_Ring
         VAR_INPUT pos : INT; END_VAR
         VAR data : ARRAY[1..4] OF INT; out : INT; END_VAR
         out := data[pos];
         data[pos + 1] := out + 1;
         END_FUNCTION_BLOCK
         PROGRAM main VAR ring : FB_Ring; n : INT; END_VAR
         n := n + 1; ring(pos := n + 2);
         END_PROGRAM";
    assert_eq!(count_of(source, "FB_Ring", is_fused), 2);
    // Cycle 1 reads 3 and writes 4; cycle 2 reads 4 and writes 5, outside.
    let s = run(source, 3);
    let fault = only_fault(&s);
    assert_eq!(
        fault.kind,
        FaultKind::IndexOutOfBounds {
            index: 5,
            low: 1,
            high: 4
        }
    );
    assert_eq!(fault.pou, "FB_Ring");
    // The task's second cycle, counted from 0.
    assert_eq!(
        (fault.file.as_deref(), fault.line, fault.cycle),
        (Some("test.st"), Some(5), 1)
    );
    assert_eq!(value(&s, "main.ring.data[4]"), "1");
    // The read faults first when its own index is outside.
    let s = run(&source.replace("pos := n + 2", "pos := n + 4"), 1);
    let fault = only_fault(&s);
    assert_eq!(
        fault.kind,
        FaultKind::IndexOutOfBounds {
            index: 5,
            low: 1,
            high: 4
        }
    );
    assert_eq!((fault.pou.as_str(), fault.line), ("FB_Ring", Some(4)));
}

#[test]
fn elements_reached_through_pointers_in_outs_bits_and_calls_keep_their_values() {
    let source = "TYPE ST_Point : STRUCT x : INT; y : INT; END_STRUCT END_TYPE
         FUNCTION Pick : INT VAR_IN_OUT arr : ARRAY[1..4] OF INT; END_VAR VAR_INPUT i : INT; END_VAR
             Pick := arr[i]; arr[i] := arr[i] * 10;
         END_FUNCTION
         FUNCTION Bump : INT VAR_IN_OUT v : INT; END_VAR v := v + 1; Bump := 7; END_FUNCTION
         FUNCTION_BLOCK FB_Count VAR_INPUT step : INT; END_VAR VAR_OUTPUT total : INT; END_VAR
             total := total + step;
         END_FUNCTION_BLOCK
         PROGRAM main
         VAR
             a : ARRAY[1..4] OF INT := [1, 2, 3, 4]; p : POINTER TO ARRAY[1..4] OF INT;
             r : REFERENCE TO ARRAY[1..4] OF INT; pw : POINTER TO WORD;
             w : ARRAY[0..1] OF WORD; pts : ARRAY[0..2] OF ST_Point; q : ST_Point;
             counters : ARRAY[1..2] OF FB_Count; i : INT := 2; j : INT; picked : INT; via : INT;
             bit : BOOL; calls : ARRAY[1..4] OF INT; totals : INT;
         END_VAR
         picked := Pick(a, i);
         p := ADR(a); via := p^[i + 1]; p^[i + 1] := 30;
         r REF= a; r[4] := r[i] + 1;
         pw := ADR(w[i - 1]); pw^ := 16#00F0; bit := w[i - 1].4; w[i - 1].0 := TRUE;
         pts[i].x := 5; pts[i].y := 6; q := pts[i]; pts[i - 2] := q;
         j := 1; calls[j] := Bump(j);
         counters[i](step := 3); counters[i](step := 4); totals := counters[i].total;
         END_PROGRAM";
    let s = run(source, 1);
    check(
        &s,
        &[
            ("main.picked", "2"),
            ("main.a[2]", "20"),
            ("main.via", "3"),
            ("main.a[3]", "30"),
            ("main.a[4]", "21"),
            ("main.w[1]", "241"),
            ("main.bit", "TRUE"),
            ("main.pts[0].x", "5"),
            ("main.pts[0].y", "6"),
            // The element is the one `j` named before `Bump` changed it.
            ("main.calls[1]", "7"),
            ("main.calls[2]", "0"),
            ("main.j", "2"),
            ("main.totals", "7"),
            ("main.counters[1].total", "0"),
        ],
    );
}

#[test]
fn eno_into_an_element_is_computed_before_en_skips_the_call() {
    // Both branches of `EN` store into ENO's place, so its index is computed before the skip:
    // with EN FALSE, `ok[k + 1]` is ok[2], and an index outside faults even then.
    let source = "FUNCTION Twice : INT VAR_INPUT v : INT; END_VAR Twice := v * 2; END_FUNCTION
         PROGRAM main VAR ok : ARRAY[0..3] OF BOOL; k : INT := 1; r : INT := 7; e : BOOL := FALSE; j : INT; END_VAR
         FOR j := 0 TO 3 DO ok[j] := TRUE; END_FOR
         r := Twice(EN := e, v := 5, ENO => ok[k + 1]);
         END_PROGRAM";
    let s = run(source, 1);
    assert!(s.faults().is_empty(), "{:?}", s.faults());
    check(
        &s,
        &[
            ("main.r", "0"),
            ("main.ok[0]", "TRUE"),
            ("main.ok[1]", "TRUE"),
            ("main.ok[2]", "FALSE"),
            ("main.ok[3]", "TRUE"),
        ],
    );
    let s = run(&source.replace("e : BOOL := FALSE", "e : BOOL := TRUE"), 1);
    check(&s, &[("main.r", "10"), ("main.ok[2]", "TRUE")]);
    let s = run(&source.replace("k : INT := 1", "k : INT := 3"), 1);
    let fault = only_fault(&s);
    assert_eq!(
        fault.kind,
        FaultKind::IndexOutOfBounds {
            index: 4,
            low: 0,
            high: 3
        }
    );
    assert_eq!(fault.line, Some(4));
}

#[test]
fn an_assignment_whose_value_runs_no_code_stops_at_the_value_s_fault_first() {
    // docs/native-engine.md §10: the target's index is checked by the store, after the value.
    let source = "PROGRAM main VAR a : ARRAY[0..3] OF INT; b : ARRAY[1..2] OF INT; i : INT := 7; j : INT := 9; x : INT := 5; z : INT; END_VAR
         a[i] := b[j];
         END_PROGRAM";
    let s = run(source, 1);
    assert_eq!(
        only_fault(&s).kind,
        FaultKind::IndexOutOfBounds {
            index: 9,
            low: 1,
            high: 2
        }
    );
    let s = run(&source.replace("a[i] := b[j];", "a[i] := x / z;"), 1);
    let fault = only_fault(&s);
    assert_eq!(fault.kind, FaultKind::DivisionByZero);
    assert_eq!(fault.line, Some(2));
    // With a good index the value's fault still comes first, and a good value lets the
    // target's index fault at the store.
    let s = run(&source.replace("a[i] := b[j];", "a[i] := b[2];"), 1);
    assert_eq!(
        only_fault(&s).kind,
        FaultKind::IndexOutOfBounds {
            index: 7,
            low: 0,
            high: 3
        }
    );
}

#[test]
fn code_that_changes_the_index_runs_after_the_element_written_is_chosen() {
    // Each statement's value (or end, or output) runs code that increments the global i; the
    // element written is the one i named before that code ran, as before the fused form.
    let s = run(
        "VAR_GLOBAL i : INT; END_VAR
         FUNCTION Bump : INT i := i + 1; Bump := i; END_FUNCTION
         FUNCTION Emit : BOOL VAR_OUTPUT x : INT; END_VAR i := i + 1; x := 100 + i; Emit := TRUE; END_FUNCTION
         FUNCTION_BLOCK FB_Bump VAR own : ARRAY[0..9] OF INT; END_VAR
         PROPERTY Next : INT
         GET i := i + 1; Next := 10 * i; END_GET
         END_PROPERTY
         METHOD Step : INT i := i + 1; Step := 20 * i; END_METHOD
         METHOD Fill : BOOL own[i] := Next; Fill := TRUE; END_METHOD
         END_FUNCTION_BLOCK
         PROGRAM main VAR b : FB_Bump; a : ARRAY[0..9] OF INT; c : ARRAY[0..9] OF INT; refs : ARRAY[0..9] OF REFERENCE TO INT; seen : INT; END_VAR
         i := 0;
         a[i] := b.Next;
         a[i] := b.Step();
         b.Fill();
         refs[i] REF= c[Bump()];
         c[4] := 77; seen := refs[3]^;
         FOR a[i] := 1 TO Bump() DO END_FOR
         FOR c[i] := 1 TO 3 DO i := i + 1; END_FOR
         Emit(x => a[i]);
         END_PROGRAM",
        1,
    );
    assert!(s.faults().is_empty(), "{:?}", s.faults());
    check(
        &s,
        &[
            // The property read through the instance: i was 0.
            ("main.a[0]", "10"),
            // The method: i was 1.
            ("main.a[1]", "40"),
            // The property of the method's own POU, by name: i was 2.
            ("main.b.own[2]", "30"),
            ("main.b.own[3]", "0"),
            // REF= into refs[3] (a null refs[3] would fault) while Bump made i 4.
            ("main.seen", "77"),
            // The FOR counter a[4], its end Bump() = 5: the counter ends past it at 6.
            ("main.a[4]", "6"),
            ("main.a[5]", "0"),
            // The counter c[5] stays c[5] while the body moves i from 5 to 8.
            ("main.c[5]", "4"),
            // The function's output into a[8], i 9 when it ends.
            ("main.a[8]", "109"),
            ("main.a[9]", "0"),
            ("GVL.i", "9"),
        ],
    );
}

#[test]
fn lower_and_upper_bound_of_an_element_check_its_index() {
    let source = "PROGRAM main VAR arrs : ARRAY[0..2] OF ARRAY[-1..4] OF INT; i : INT := 1; lo : DINT; hi : DINT; END_VAR
         lo := LOWER_BOUND(arrs[i], 1);
         hi := UPPER_BOUND(arrs[i], 1);
         END_PROGRAM";
    let s = run(source, 1);
    check(&s, &[("main.lo", "-1"), ("main.hi", "4")]);
    for (line, call) in [(2, "LOWER_BOUND"), (3, "UPPER_BOUND")] {
        let other = if call == "LOWER_BOUND" {
            "UPPER_BOUND"
        } else {
            "LOWER_BOUND"
        };
        // Only this line's index is bad: the other reads arrs[0].
        let bad = source
            .replace(&format!("{call}(arrs[i]"), &format!("{call}(arrs[i + 5]"))
            .replace(&format!("{other}(arrs[i]"), &format!("{other}(arrs[0]"));
        let s = run(&bad, 1);
        let fault = only_fault(&s);
        assert_eq!(
            fault.kind,
            FaultKind::IndexOutOfBounds {
                index: 6,
                low: 0,
                high: 2
            },
            "{call}"
        );
        assert_eq!(fault.line, Some(line), "{call}");
    }
}

/// The loops of POU `main` in `source`: the instructions from each backward jump's target to
/// the jump.
fn loops_of(source: &str) -> Vec<Vec<Instr>> {
    let image = compile(source);
    let Some(main) = image.pous.iter().find(|p| p.name == "main") else {
        panic!("no POU 'main'");
    };
    main.code
        .iter()
        .enumerate()
        .filter_map(|(at, instr)| match instr {
            Instr::Jump { target } if *target as usize <= at => {
                Some(main.code[*target as usize..=at].to_vec())
            }
            _ => None,
        })
        .collect()
}

#[test]
fn a_for_loop_with_a_constant_step_has_the_shape_whose_element_checks_the_native_engine_hoists() {
    // `jit::translate::counted` (docs/native-engine.md §5.3) recognises this shape: at the
    // loop's start the counter compared with the end (Gt counting up, Lt counting down) and
    // a JumpIf out, before the backward jump the step added to the counter. A change of
    // the compiler's FOR loop that this test sees leaves those loops checked at every access.
    for (source, upward) in [
        (
            "PROGRAM main VAR a : ARRAY[1..10] OF DINT; i, n : DINT; END_VAR
             n := 10;
             FOR i := 1 TO n DO a[i] := a[i] + i; END_FOR
             END_PROGRAM",
            true,
        ),
        (
            "PROGRAM main VAR a : ARRAY[1..10] OF INT; i : INT; END_VAR
             FOR i := 10 TO 1 BY -3 DO a[i] := i; END_FOR
             END_PROGRAM",
            false,
        ),
    ] {
        let loops = loops_of(source);
        let [body] = &loops[..] else {
            panic!("one loop: {loops:?}")
        };
        let Instr::Compare { op, a: counter, .. } = body[0] else {
            panic!("the test first: {body:?}")
        };
        let expected = if upward {
            program_image::CompareOp::Gt
        } else {
            program_image::CompareOp::Lt
        };
        assert_eq!(op, expected);
        assert!(matches!(body[1], Instr::JumpIf { .. }), "{body:?}");
        let increment = &body[body.len() - 2];
        assert!(
            matches!(
                increment,
                Instr::Binary { op: program_image::BinaryOp::Add, dst, a, .. }
                    if *dst == counter && *a == counter
            ),
            "{body:?}"
        );
        assert!(
            body.iter().any(|instr| matches!(
                instr,
                Instr::LoadElement { index, .. } | Instr::StoreElement { index, .. }
                    if *index == counter
            )),
            "{body:?}"
        );
    }
}

#[test]
fn counted_for_loops_over_arrays_fault_at_the_interpreters_line_and_index() {
    // Under the native engine each loop's index checks are made once before it; a loop that
    // would leave its array runs its checked copy and stops at the same line, index and
    // memory as the interpreter (`run` compares both engines after every cycle).
    let source = "PROGRAM main VAR a : ARRAY[1..10] OF DINT; i, j, n, sum : DINT; END_VAR
         n := 10;
         FOR j := 1 TO 3 DO FOR i := 1 TO n DO a[i] := a[i] + i; END_FOR END_FOR
         FOR i := 10 TO 1 BY -2 DO sum := sum + a[i]; END_FOR
         END_PROGRAM";
    let s = run(source, 2);
    assert!(s.faults().is_empty(), "{:?}", s.faults());
    assert_eq!(value(&s, "main.a[7]"), "42");
    assert_eq!(value(&s, "main.sum"), "270");
    assert_eq!(value(&s, "main.i"), "0");
    for (loop_text, index, at) in [
        ("FOR i := 1 TO n DO", 11, "main.a[10]"),
        ("FOR i := n - 1 TO 0 BY -1 DO", 0, "main.a[1]"),
    ] {
        let source = format!(
            "PROGRAM main VAR a : ARRAY[1..10] OF DINT; i, n : DINT; END_VAR
             n := 11;
             {loop_text}
                 a[i] := a[i] + i;
             END_FOR
             END_PROGRAM"
        );
        let s = run(&source, 1);
        let fault = only_fault(&s);
        assert_eq!(
            fault.kind,
            FaultKind::IndexOutOfBounds {
                index,
                low: 1,
                high: 10
            },
            "{loop_text}"
        );
        assert_eq!(
            (fault.pou.as_str(), fault.line),
            ("main", Some(4)),
            "{loop_text}"
        );
        assert_eq!(value(&s, "main.i"), index.to_string(), "{loop_text}");
        // The element next to the bound was reached before the fault.
        assert_ne!(value(&s, at), "0", "{loop_text}");
    }
}
