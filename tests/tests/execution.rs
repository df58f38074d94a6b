//! End-to-end execution: Structured Text compiled into an image and run in the runtime's
//! engine on a simulated clock, every construct checked by the values it leaves.

// The helpers below are test code too: a failure should stop the test where it happens.
#![allow(clippy::expect_used, clippy::unwrap_used)]

/// The CODESYS and iec-strict dialects on each case where they differ.
mod dialect;
/// LD and FBD bodies compiled and run, element by element and against the ST a user writes.
mod ladder;
mod sfc;
/// SFC charts of the graphical model lowered into textual SFC and run.
mod sfc_chart;

/// CFC charts compiled and run: execution order, feedback, marks, structures, EN/ENO, jumps.
mod cfc;

/// The engine's debugger: breakpoints, the call stack and steps.
mod debugging;

/// PLCopen XML files imported and their ST part checked.
mod plcopen_import;

/// Instruction List bodies compiled and run, Beremiz's IL counter against its ST twin.
mod instruction_list;

/// Bits and parts reached through pointers, references and properties; E0134.
mod places;

/// Array elements and string characters by a variable index: the fused instructions and the
/// pointer path, their values and their faults.
mod elements;

/// Every standard function and function block compiled, run and checked against its value.
mod standard_library;

/// Every fault of the native engine's checks, under both engines, with its task and line.
mod native_faults;

/// Random well-typed programs run under both engines and compared cycle by cycle.
mod native_differential;

use program_image::ProgramImage;
use runtime::simulation::Simulation;

/// Compiles one source file, panicking with the compiler's message when it does not.
#[track_caller]
fn compile(source: &str) -> ProgramImage {
    let project = compiler::SourceProject::new(source);
    assert!(
        project.parse.errors().is_empty(),
        "syntax errors: {:?}",
        project.parse.errors()
    );
    match compiler::compile_source(&project, "test.st") {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found.iter().map(|d| d.diagnostic.message.clone()).collect();
            panic!("the source does not check: {errors:#?}")
        }
        Err(error) => panic!("the source does not compile: {error}"),
    }
}

/// Runs `cycles` cycles and returns the simulation.
#[track_caller]
fn run(source: &str, cycles: u64) -> Simulation {
    let image = compile(source);
    // Every image the compiler writes survives its own encoding.
    let decoded = ProgramImage::decode(&image.encode()).expect("the image decodes");
    assert_eq!(decoded, image);
    simulate(image, cycles)
}

/// Runs `image` for `cycles` periods of its fastest task under both engines, compared after
/// every period (`runtime::differential::run_both`, `docs/native-engine.md` §11.1), and
/// returns the native engine's simulation; every POU must run natively.
#[track_caller]
fn simulate(image: ProgramImage, cycles: u64) -> Simulation {
    simulate_with(image, cycles, |_, _| {})
}

/// [`simulate`] with `writes(n, engine)` before period `n` (from 1) in both engines.
#[track_caller]
fn simulate_with(
    image: ProgramImage,
    cycles: u64,
    writes: impl FnMut(u64, &mut runtime::engine::Engine),
) -> Simulation {
    runtime::differential::run_both(image, cycles, writes)
        .unwrap_or_else(|difference| panic!("the engines differ: {difference}"))
}

/// The value of `path` as an IEC literal.
#[track_caller]
fn value(simulation: &Simulation, path: &str) -> String {
    runtime::value::read(simulation.engine(), path)
        .unwrap_or_else(|e| panic!("{path}: {e}"))
        .to_string()
}

#[track_caller]
fn check(simulation: &Simulation, expected: &[(&str, &str)]) {
    assert!(
        simulation.faults().is_empty(),
        "faults: {:?}",
        simulation.faults()
    );
    for (path, want) in expected {
        assert_eq!(value(simulation, path), *want, "{path}");
    }
}

#[test]
fn integer_arithmetic_wraps_in_the_type_of_the_expression() {
    let s = run(
        "PROGRAM main VAR a : INT := 32767; b : INT; c : DINT; d : SINT := -128; e : UINT; m : INT; q : DINT; END_VAR
         b := a + 1; c := 7 / 2; d := -d; e := 0; e := e - 1; m := -7 MOD 3; q := -7 / 2;
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.b", "-32768"),
            ("main.c", "3"),
            ("main.d", "-128"),
            ("main.e", "65535"),
            ("main.m", "-1"),
            ("main.q", "-3"),
        ],
    );
}

#[test]
fn reals_booleans_and_comparisons() {
    let s = run(
        "PROGRAM main VAR r : REAL := 1.5; l : LREAL; b1 : BOOL := TRUE; b2 : BOOL; b3 : BOOL; x : BOOL; y : BOOL; z : BOOL; END_VAR
         l := r * 2.0 + 0.25; b2 := NOT b1; b3 := b1 XOR b2; x := r > 1.0 AND l < 3.5; y := r = 1.5; z := b1 AND_THEN (r <> 1.5);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.l", "3.25"),
            ("main.b2", "FALSE"),
            ("main.b3", "TRUE"),
            ("main.x", "TRUE"),
            ("main.y", "TRUE"),
            ("main.z", "FALSE"),
        ],
    );
}

#[test]
fn the_lc1200_conversion_and_bit_vectors_hold_in_compiled_code() {
    let s = run(
        "PROGRAM main VAR a : INT; b : SINT; w : WORD; w2 : WORD; t : DINT; r : REAL; bt : BYTE; bo : BOOL; END_VAR
         a := REAL_TO_INT(-1.5); b := INT_TO_SINT(4223); w := ROR(WORD#16#45, 2); w2 := SHL(WORD#16#1, 4);
         t := TRUNC(-2.7); r := DINT_TO_REAL(7) / 2.0; bt := WORD_TO_BYTE(16#1234); bo := INT_TO_BOOL(300);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.a", "-2"),
            ("main.b", "127"),
            ("main.w", "16401"),
            ("main.w2", "16"),
            ("main.t", "-2"),
            ("main.r", "3.5"),
            ("main.bt", "52"),
            ("main.bo", "TRUE"),
        ],
    );
}

#[test]
fn if_case_and_loops_take_the_right_branches() {
    let s = run(
        "PROGRAM main VAR i : INT; n : INT; k : INT; w : INT; r : INT; c1 : INT; c2 : INT; c3 : INT; sum : INT; odd : INT; END_VAR
         IF n > 0 THEN k := 1; ELSIF n = 0 THEN k := 2; ELSE k := 3; END_IF;
         CASE 7 OF 1, 2: c1 := 1; 5..8: c1 := 2; ELSE c1 := 3; END_CASE;
         CASE 42 OF 1: c2 := 1; ELSE c2 := 9; END_CASE;
         CASE k OF 2: c3 := 20; 3: c3 := 30; END_CASE;
         FOR i := 10 TO 1 BY -3 DO sum := sum + i; END_FOR;
         FOR n := 1 TO 100 DO IF n MOD 2 = 0 THEN CONTINUE; END_IF; odd := odd + 1; IF n >= 9 THEN EXIT; END_IF; END_FOR;
         WHILE w < 5 DO w := w + 2; END_WHILE;
         REPEAT r := r + 10; UNTIL r >= 25 END_REPEAT;
         END_PROGRAM",
        1,
    );
    // FOR leaves the variable at the first value past the end: 10, 7, 4, 1, then -2.
    check(
        &s,
        &[
            ("main.k", "2"),
            ("main.c1", "2"),
            ("main.c2", "9"),
            ("main.c3", "20"),
            ("main.sum", "22"),
            ("main.i", "-2"),
            ("main.odd", "5"),
            ("main.n", "9"),
            ("main.w", "6"),
            ("main.r", "30"),
        ],
    );
}

#[test]
fn functions_take_inputs_in_outs_and_outputs_and_may_recurse() {
    let s = run(
        "FUNCTION Fact : DINT VAR_INPUT n : DINT; END_VAR IF n <= 1 THEN Fact := 1; RETURN; END_IF; Fact := n * Fact(n - 1); END_FUNCTION
         FUNCTION Swap : BOOL VAR_IN_OUT a, b : INT; END_VAR VAR t : INT; END_VAR t := a; a := b; b := t; Swap := TRUE; END_FUNCTION
         FUNCTION Split : INT VAR_INPUT x : INT; END_VAR VAR_OUTPUT hi, lo : INT; END_VAR hi := x / 100; lo := x MOD 100; Split := hi + lo; END_FUNCTION
         FUNCTION Counter : INT VAR n : INT := 5; END_VAR n := n + 1; Counter := n; END_FUNCTION
         PROGRAM main VAR f : DINT; x : INT := 1; y : INT := 2; ok : BOOL; h : INT; l : INT; s : INT; c : INT; END_VAR
         f := Fact(10); ok := Swap(x, y); s := Split(1234, hi => h, lo => l); c := Counter(); c := Counter();
         END_PROGRAM",
        1,
    );
    // A function's variables start from their initial values at every call.
    check(
        &s,
        &[
            ("main.f", "3628800"),
            ("main.x", "2"),
            ("main.y", "1"),
            ("main.ok", "TRUE"),
            ("main.h", "12"),
            ("main.l", "34"),
            ("main.s", "46"),
            ("main.c", "6"),
        ],
    );
}

#[test]
fn function_blocks_keep_their_state_with_methods_and_actions() {
    let s = run(
        "FUNCTION_BLOCK FB_Acc VAR_INPUT step : INT := 1; END_VAR VAR_OUTPUT total : INT; END_VAR VAR calls : INT; END_VAR
         total := total + step; calls := calls + 1;
         METHOD Reset : BOOL VAR_INPUT target : INT; END_VAR total := target; Reset := TRUE; END_METHOD
         ACTION Double: total := total * 2; END_ACTION
         END_FUNCTION_BLOCK
         PROGRAM main VAR a : FB_Acc; b : FB_Acc; t : INT; r : BOOL; END_VAR
         a(); a(step := 5); b(step := 2, total => t);
         END_PROGRAM",
        3,
    );
    // Inputs keep their last value: after `a(step := 5)` a bare `a()` adds 5 too.
    check(
        &s,
        &[
            ("main.a.total", "26"),
            ("main.a.calls", "6"),
            ("main.b.total", "6"),
            ("main.t", "6"),
        ],
    );
}

#[test]
fn methods_and_actions_run_on_their_instance() {
    let s = run(
        "FUNCTION_BLOCK FB_Acc VAR_OUTPUT total : INT; END_VAR
         METHOD Add : INT VAR_INPUT n : INT; END_VAR total := total + n; Add := total; END_METHOD
         ACTION Double: total := total * 2; END_ACTION
         END_FUNCTION_BLOCK
         PROGRAM main VAR a : FB_Acc; r : INT; END_VAR
         r := a.Add(3); a.Double(); r := a.Add(1);
         END_PROGRAM",
        1,
    );
    check(&s, &[("main.a.total", "7"), ("main.r", "7")]);
}

#[test]
fn structures_enumerations_and_arrays_are_laid_out_and_initialised() {
    let s = run(
        "TYPE E_Mode : (Idle, Run := 5, Stop); END_TYPE
         TYPE ST_Point : STRUCT x : INT := 3; y : REAL; END_STRUCT END_TYPE
         TYPE ST_Line : STRUCT a : ST_Point; b : ST_Point := (x := 7, y := 1.5); END_STRUCT END_TYPE
         PROGRAM main VAR m : E_Mode; n : E_Mode := E_Mode.Stop; l : ST_Line; arr : ARRAY[1..5] OF INT := [1, 2, 3(9)];
         grid : ARRAY[0..2, 0..3] OF DINT; pts : ARRAY[1..3] OF ST_Point; i : INT; j : INT; total : DINT; isRun : BOOL; END_VAR
         l.a.y := l.b.y * 2.0; m := Run; isRun := m = E_Mode.Run;
         FOR i := 0 TO 2 DO FOR j := 0 TO 3 DO grid[i, j] := i * 10 + j; END_FOR; END_FOR;
         total := grid[2, 3] + grid[1, 0]; pts[2].x := arr[5] + arr[1]; arr[i] := 42;
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.m", "Run"),
            ("main.n", "Stop"),
            ("main.l.a.x", "3"),
            ("main.l.b.x", "7"),
            ("main.l.a.y", "3"),
            ("main.arr", "[1, 2, 42, 9, 9]"),
            ("main.grid[2, 1]", "21"),
            ("main.total", "33"),
            ("main.pts[2].x", "10"),
            ("main.pts[1].x", "3"),
            ("main.isRun", "TRUE"),
        ],
    );
}

#[test]
fn strings_hold_their_declared_length() {
    let s = run(
        "PROGRAM main VAR s : STRING(5); t : STRING := 'abc'; u : STRING; n : INT; w : WSTRING := \"wide\"; p : INT; END_VAR
         s := 'truncated'; u := CONCAT(t, 'def'); n := LEN(u); p := FIND(u, 'cd'); u := REPLACE(u, 'XY', 2, 3); u := INSERT(u, '-', 1);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.s", "'trunc'"),
            ("main.n", "6"),
            ("main.p", "3"),
            ("main.u", "'a-bXYef'"),
            ("main.w", "'wide'"),
        ],
    );
}

#[test]
fn pointers_and_references_reach_their_targets() {
    let s = run(
        "PROGRAM main VAR x : INT := 5; arr : ARRAY[0..3] OF INT; p : POINTER TO INT; r : REFERENCE TO INT; y : INT; q : POINTER TO ARRAY[0..3] OF INT; END_VAR
         p := ADR(x); p^ := p^ + 1; r REF= arr[2]; r := 7; y := r + x; q := ADR(arr); q^[3] := 11;
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.x", "6"),
            ("main.arr", "[0, 0, 7, 11]"),
            ("main.y", "13"),
        ],
    );
}

#[test]
fn timers_count_simulated_time() {
    // The implicit task runs every 10 ms.
    let source = "PROGRAM main VAR tOn : TON; off : TOF; pulse : TP; start : BOOL := TRUE; cycles : INT; END_VAR
         cycles := cycles + 1;
         tOn(IN := start, PT := T#45ms); off(IN := cycles < 3, PT := T#20ms); pulse(IN := TRUE, PT := T#25ms);
         END_PROGRAM";
    let s = run(source, 4);
    // Cycles at 0, 10, 20, 30 ms: TON has seen 30 ms of its 45.
    check(
        &s,
        &[
            ("main.tOn.Q", "FALSE"),
            ("main.tOn.ET", "T#30ms"),
            ("main.off.Q", "TRUE"),
            ("main.off.ET", "T#10ms"),
            ("main.pulse.Q", "FALSE"),
            ("main.pulse.ET", "T#25ms"),
        ],
    );
    let s = run(source, 6);
    check(
        &s,
        &[
            ("main.tOn.Q", "TRUE"),
            ("main.tOn.ET", "T#45ms"),
            ("main.off.Q", "FALSE"),
            ("main.off.ET", "T#20ms"),
        ],
    );
}

#[test]
fn counters_edges_and_bistables_follow_iec() {
    let source = "PROGRAM main VAR up : CTU; down : CTD; ud : CTUD; rt : R_TRIG; ft : F_TRIG; sr : SR; rs : RS; clk : BOOL; n : INT; rises : INT; falls : INT; END_VAR
         n := n + 1; clk := NOT clk;
         up(CU := clk, PV := 3); down(CD := clk, LD := n = 1, PV := 2); ud(CU := clk, CD := FALSE, PV := 2);
         rt(CLK := clk); IF rt.Q THEN rises := rises + 1; END_IF; ft(CLK := clk); IF ft.Q THEN falls := falls + 1; END_IF;
         sr(SET1 := n = 2, RESET := n = 2); rs(SET := n = 2, RESET1 := n = 2);
         END_PROGRAM";
    let s = run(source, 7);
    check(
        &s,
        &[
            ("main.up.CV", "4"),
            ("main.up.Q", "TRUE"),
            ("main.down.CV", "-1"),
            ("main.down.Q", "TRUE"),
            ("main.ud.QU", "TRUE"),
            ("main.rises", "4"),
            ("main.falls", "3"),
            ("main.sr.Q1", "TRUE"),
            ("main.rs.Q1", "FALSE"),
        ],
    );
}

#[test]
fn located_variables_share_bytes_as_codesys_lays_them_out() {
    let s = run(
        "PROGRAM main VAR w AT %MW1 : WORD; lo AT %MB2 : BYTE; hi AT %MB3 : BYTE; bit AT %MX2.1 : BOOL; q AT %QX0.3 : BOOL; qb AT %QB0 : BYTE; d AT %MD1 : DINT; END_VAR
         w := 16#1234; q := TRUE; d := 16#01020304;
         END_PROGRAM",
        1,
    );
    // %MW1 is bytes 2..3, little-endian; %MX2.1 is bit 1 of byte 2 (0x34); %MD1 is bytes 4..7.
    check(
        &s,
        &[
            ("main.lo", "52"),
            ("main.hi", "18"),
            ("main.bit", "FALSE"),
            ("main.qb", "8"),
            ("main.d", "16909060"),
        ],
    );
    let memory = s.engine().region(program_image::Region::Memory);
    assert_eq!(&memory[2..8], &[0x34, 0x12, 0x04, 0x03, 0x02, 0x01]);
}

#[test]
fn globals_and_temporaries() {
    let s = run(
        "VAR_GLOBAL gCount : DINT := 100; gLimit : INT := 3; END_VAR
         FUNCTION_BLOCK FB_Use VAR_TEMP t : INT := 4; END_VAR VAR_OUTPUT seen : INT; END_VAR t := t + 1; seen := t; gCount := gCount + 1; END_FUNCTION_BLOCK
         PROGRAM main VAR fb : FB_Use; n : INT; END_VAR fb(); fb(); n := gLimit; END_PROGRAM",
        2,
    );
    check(
        &s,
        &[
            ("main.fb.seen", "5"),
            ("main.n", "3"),
            ("GVL.gCount", "104"),
        ],
    );
}

#[test]
fn time_and_date_arithmetic() {
    let s = run(
        "PROGRAM main VAR t : TIME := T#1s; u : TIME; d : DT := DT#2024-01-31-12:00:00; e : DT; diff : TIME; lt : LTIME; tod : TOD; END_VAR
         u := t * 3 + T#250ms; e := ADD_DT_TIME(d, T#13h); diff := SUB_DT_DT(e, d); lt := TIME_TO_LTIME(u); tod := DT_TO_TOD(e);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.u", "T#3s250ms"),
            ("main.e", "DT#2024-02-01-01:00:00"),
            ("main.diff", "T#13h"),
            ("main.lt", "LTIME#3s250ms"),
            ("main.tod", "TOD#01:00:00"),
        ],
    );
}

#[test]
fn a_division_by_zero_stops_the_task_with_the_pou_and_line() {
    let s = run(
        "FUNCTION_BLOCK FB_Div VAR_INPUT d : INT; END_VAR VAR_OUTPUT q : INT; END_VAR
q := 10 / d;
END_FUNCTION_BLOCK
PROGRAM main VAR fb : FB_Div; n : INT; END_VAR
n := n + 1;
fb(d := 0);
END_PROGRAM",
        5,
    );
    let [fault] = s.faults() else {
        panic!("one fault: {:?}", s.faults())
    };
    assert_eq!(fault.kind, runtime::engine::FaultKind::DivisionByZero);
    assert_eq!(fault.pou, "FB_Div");
    assert_eq!(
        (fault.file.as_deref(), fault.line),
        (Some("test.st"), Some(2))
    );
    // The task stopped at its first cycle; nothing after the fault ran again.
    assert_eq!(value(&s, "main.n"), "1");
}

/// CODESYS's index access to a STRING gives the byte at the index, counted from 0, and to a
/// WSTRING the word (https://content.helpme-codesys.com/en/CODESYS%20Development%20System/_cds_datatype_pointer.html);
/// the terminator's place is inside the bounds, one past it is a fault.
#[test]
fn an_index_into_a_string_reads_and_writes_its_characters_from_0() {
    let s = run(
        "PROGRAM main VAR s : STRING(4) := 'abcd'; w : WSTRING(3) := \"xyz\"; first : BYTE; last : BYTE; after : BYTE; wide : WORD; i : INT := 4; END_VAR
first := s[0]; last := s[3]; after := s[i]; wide := w[2]; s[1] := 66;
END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.first", "97"),
            ("main.last", "100"),
            ("main.after", "0"),
            ("main.wide", "122"),
            ("main.s", "'aBcd'"),
        ],
    );
    let s = run(
        "PROGRAM main VAR s : STRING(4); b : BYTE; i : INT := 5; END_VAR b := s[i]; END_PROGRAM",
        1,
    );
    assert!(
        matches!(
            s.faults()[0].kind,
            runtime::engine::FaultKind::IndexOutOfBounds {
                index: 5,
                low: 0,
                high: 4
            }
        ),
        "{:?}",
        s.faults()
    );
}

#[test]
fn an_index_out_of_bounds_and_runaway_recursion_are_faults_not_crashes() {
    let s = run(
        "PROGRAM main VAR a : ARRAY[1..3] OF INT; i : INT := 4; END_VAR a[i] := 1; END_PROGRAM",
        1,
    );
    assert!(matches!(
        s.faults()[0].kind,
        runtime::engine::FaultKind::IndexOutOfBounds {
            index: 4,
            low: 1,
            high: 3
        }
    ));
    let s = run(
        "FUNCTION Down : DINT VAR_INPUT n : DINT; END_VAR Down := Down(n + 1); END_FUNCTION
         PROGRAM main VAR x : DINT; END_VAR x := Down(0); END_PROGRAM",
        1,
    );
    assert_eq!(
        s.faults()[0].kind,
        runtime::engine::FaultKind::StackOverflow
    );
    let s = run(
        "PROGRAM main VAR p : POINTER TO INT; x : INT; END_VAR x := p^; END_PROGRAM",
        1,
    );
    assert_eq!(s.faults()[0].kind, runtime::engine::FaultKind::NullPointer);
}

#[test]
fn an_endless_loop_trips_the_watchdog_and_other_tasks_keep_running() {
    let source = compiler::SourceProject::new(
        "PROGRAM hang VAR n : DINT; END_VAR WHILE TRUE DO n := n + 1; END_WHILE; END_PROGRAM
         PROGRAM tick VAR n : DINT; END_VAR n := n + 1; END_PROGRAM",
    );
    let mut project = source.project.clone();
    let task = |name: &str, program: &str, watchdog_us: u32| project_model::Task {
        name: name.to_owned(),
        kind: project_model::TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority: 1,
        watchdog: Some(project_model::Watchdog {
            time_us: watchdog_us,
            sensitivity: 1,
        }),
        programs: vec![program.to_owned()],
    };
    project.tasks = vec![task("Slow", "hang", 20_000), task("Fast", "tick", 100_000)];
    let image = compiler::compile_project(&project).expect("compiles");
    let mut simulation = Simulation::new(image).unwrap();
    simulation.run(5);
    let [fault] = simulation.faults() else {
        panic!("one fault")
    };
    assert_eq!(fault.task, "Slow");
    assert!(matches!(
        fault.kind,
        runtime::engine::FaultKind::Watchdog { .. }
    ));
    assert_eq!(value(&simulation, "tick.n"), "5");
}

#[test]
fn properties_and_this_reach_the_instance() {
    let s = run(
        "FUNCTION_BLOCK FB_Box VAR mValue : INT; END_VAR VAR_OUTPUT doubled : INT; END_VAR
         PROPERTY Value : INT
         GET Value := mValue; END_GET
         SET mValue := Value * 2; END_SET
         END_PROPERTY
         METHOD Grow : INT THIS^.mValue := THIS^.mValue + 1; doubled := Value; Grow := doubled; END_METHOD
         END_FUNCTION_BLOCK
         PROGRAM main VAR b : FB_Box; v : INT; g : INT; END_VAR b.Value := 5; v := b.Value; g := b.Grow(); END_PROGRAM",
        1,
    );
    check(
        &s,
        &[("main.v", "10"), ("main.g", "11"), ("main.b.doubled", "11")],
    );
}

#[test]
fn strings_compare_by_their_characters() {
    let s = run(
        "PROGRAM main VAR a : STRING := 'abc'; b : STRING(10) := 'abd'; eq : BOOL; lt : BOOL; ne : BOOL; ge : BOOL; END_VAR
         eq := a = 'abc'; lt := a < b; ne := a <> b; ge := b >= 'abd';
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.eq", "TRUE"),
            ("main.lt", "TRUE"),
            ("main.ne", "TRUE"),
            ("main.ge", "TRUE"),
        ],
    );
}

#[test]
fn text_bcd_and_partial_access_conversions() {
    let s = run(
        "PROGRAM main VAR t : STRING; n : INT; r : REAL; w : WORD; b : INT; d : DWORD := 16#11223344; hi : BYTE; bit : BOOL; x : DINT; tt : STRING; END_VAR
         t := INT_TO_STRING(-42); n := STRING_TO_INT('123'); r := STRING_TO_REAL('2.5'); w := INT_TO_BCD(1234); b := BCD_TO_INT(16#0099);
         hi := d.%B3; bit := d.%X2; d.%X0 := TRUE; x := TO_DINT(n); tt := TIME_TO_STRING(T#1m30s);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.t", "'-42'"),
            ("main.n", "123"),
            ("main.r", "2.5"),
            ("main.w", "4660"),
            ("main.b", "99"),
            ("main.hi", "17"),
            ("main.bit", "TRUE"),
            ("main.d", "287454021"),
            ("main.x", "123"),
            ("main.tt", "'T#1m30s'"),
        ],
    );
}

#[test]
fn jumps_and_enable_inputs_steer_execution() {
    let s = run(
        "FUNCTION Twice : INT VAR_INPUT x : INT; END_VAR Twice := x * 2; END_FUNCTION
         PROGRAM main VAR n : INT; a : INT; b : INT := 7; ok1 : BOOL; ok2 : BOOL := TRUE; END_VAR
         again: n := n + 1; IF n < 5 THEN JMP again; END_IF; JMP done; n := 100;
         done: a := Twice(EN := TRUE, x := 4, ENO => ok1); b := Twice(EN := n > 10, x := 4, ENO => ok2);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.n", "5"),
            ("main.a", "8"),
            ("main.ok1", "TRUE"),
            ("main.b", "0"),
            ("main.ok2", "FALSE"),
        ],
    );
}

#[test]
fn static_variables_are_shared_by_every_instance_and_call() {
    let s = run(
        "FUNCTION_BLOCK FB_Count VAR_STAT shared : INT; END_VAR VAR own : INT; END_VAR VAR_OUTPUT seen : INT; END_VAR
         shared := shared + 1; own := own + 1; seen := shared * 10 + own; END_FUNCTION_BLOCK
         FUNCTION Calls : INT VAR_STAT n : INT; END_VAR n := n + 1; Calls := n; END_FUNCTION
         PROGRAM main VAR a : FB_Count; b : FB_Count; c : INT; END_VAR a(); b(); c := Calls(); c := Calls(); END_PROGRAM",
        2,
    );
    check(
        &s,
        &[
            ("main.a.seen", "32"),
            ("main.b.seen", "42"),
            ("main.c", "4"),
            ("FB_Count.shared", "4"),
        ],
    );
}

#[test]
fn methods_called_through_an_interface_run_the_instance_s_own() {
    let s = run(
        "INTERFACE I_Shape METHOD Area : REAL VAR_INPUT scale : REAL; END_VAR END_METHOD END_INTERFACE
         FUNCTION_BLOCK FB_Square IMPLEMENTS I_Shape VAR_INPUT side : REAL; END_VAR
         METHOD Area : REAL VAR_INPUT scale : REAL; END_VAR VAR tmp : REAL; END_VAR tmp := side * side; Area := tmp * scale; END_METHOD
         END_FUNCTION_BLOCK
         FUNCTION_BLOCK FB_Circle IMPLEMENTS I_Shape VAR_INPUT r : REAL; END_VAR
         METHOD Area : REAL VAR_INPUT scale : REAL; END_VAR Area := 3.0 * r * r * scale; END_METHOD
         END_FUNCTION_BLOCK
         PROGRAM main VAR sq : FB_Square := (side := 2.0); ci : FB_Circle := (r := 1.0); shapes : ARRAY[1..2] OF I_Shape; total : REAL; i : INT; none : I_Shape; empty : BOOL; END_VAR
         shapes[1] := sq; shapes[2] := ci; total := 0.0;
         FOR i := 1 TO 2 DO total := total + shapes[i].Area(scale := 10.0); END_FOR;
         empty := none = 0;
         END_PROGRAM",
        1,
    );
    check(&s, &[("main.total", "70"), ("main.empty", "TRUE")]);
    let s = run(
        "INTERFACE I_Run METHOD Go : BOOL END_METHOD END_INTERFACE
         PROGRAM main VAR none : I_Run; ok : BOOL; END_VAR ok := none.Go(); END_PROGRAM",
        1,
    );
    assert_eq!(s.faults()[0].kind, runtime::engine::FaultKind::NullPointer);
}

#[test]
fn array_bounds_may_name_local_constants() {
    let s = run(
        "FUNCTION_BLOCK FB_Buf VAR CONSTANT N : INT := 3; END_VAR VAR data : ARRAY[1..N] OF INT; END_VAR VAR_OUTPUT last : INT; END_VAR
         data[N] := N * 2; last := data[N]; END_FUNCTION_BLOCK
         FUNCTION Sum3 : INT VAR CONSTANT M : INT := 2; END_VAR VAR v : ARRAY[0..M] OF INT := [1, 2, 3]; i : INT; END_VAR
         FOR i := 0 TO M DO Sum3 := Sum3 + v[i]; END_FOR; END_FUNCTION
         PROGRAM main VAR b : FB_Buf; s : INT; END_VAR b(); s := Sum3(); END_PROGRAM",
        1,
    );
    check(&s, &[("main.b.last", "6"), ("main.s", "6")]);
}

#[test]
fn open_arrays_take_any_length_with_their_bounds() {
    let s = run(
        "FUNCTION SumAll : DINT VAR_IN_OUT values : ARRAY[*] OF INT; END_VAR VAR i : DINT; END_VAR
         FOR i := LOWER_BOUND(values, 1) TO UPPER_BOUND(values, 1) DO SumAll := SumAll + values[i]; values[i] := 0; END_FOR; END_FUNCTION
         FUNCTION Corner : INT VAR_IN_OUT grid : ARRAY[*, *] OF INT; END_VAR Corner := grid[UPPER_BOUND(grid, 1), UPPER_BOUND(grid, 2)]; END_FUNCTION
         FUNCTION_BLOCK FB_Pick VAR_IN_OUT data : ARRAY[*] OF INT; END_VAR VAR_INPUT pos : DINT; END_VAR VAR_OUTPUT picked : INT; END_VAR picked := data[pos]; END_FUNCTION_BLOCK
         PROGRAM main VAR a : ARRAY[1..4] OF INT := [1, 2, 3, 4]; b : ARRAY[-2..0] OF INT := [10, 20, 30]; g : ARRAY[0..1, 5..7] OF INT;
         sa : DINT; sb : DINT; c : INT; p : FB_Pick; n : INT; END_VAR
         g[1, 7] := 99; sa := SumAll(a); sb := SumAll(b); c := Corner(g); p(data := b, pos := -1); n := a[2];
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.sa", "10"),
            ("main.sb", "60"),
            ("main.c", "99"),
            ("main.p.picked", "0"),
            ("main.n", "0"),
        ],
    );
    let s = run(
        "FUNCTION Get : INT VAR_IN_OUT v : ARRAY[*] OF INT; END_VAR VAR_INPUT i : DINT; END_VAR Get := v[i]; END_FUNCTION
         PROGRAM main VAR a : ARRAY[1..3] OF INT; x : INT; END_VAR x := Get(a, 4); END_PROGRAM",
        1,
    );
    assert!(matches!(
        s.faults()[0].kind,
        runtime::engine::FaultKind::IndexOutOfBounds {
            index: 4,
            low: 1,
            high: 3
        }
    ));
}

#[test]
fn a_textual_sfc_chart_steps_through_its_transitions() {
    let source = "FUNCTION_BLOCK FB_Seq VAR_INPUT go : BOOL; END_VAR VAR_OUTPUT filled : INT; pulses : INT; held : INT; phase : INT; atIdle : BOOL; atDone : BOOL; valve : BOOL; END_VAR
         atIdle := Idle.X; atDone := Done.X;
         INITIAL_STEP Idle: Mark(N); END_STEP
         TRANSITION FROM Idle TO Fill := go; END_TRANSITION
         STEP Fill: Count(N); Once(P); Hold(S); valve(N); END_STEP
         TRANSITION FROM Fill TO Done := Fill.T >= T#30ms; END_TRANSITION
         STEP Done: Hold(R); END_STEP
         TRANSITION FROM Done TO Idle := NOT go; END_TRANSITION
         ACTION Mark: phase := 0; END_ACTION
         ACTION Count: filled := filled + 1; phase := 1; END_ACTION
         ACTION Once: pulses := pulses + 1; END_ACTION
         ACTION Hold: held := held + 1; END_ACTION
         END_FUNCTION_BLOCK
         PROGRAM main VAR seq : FB_Seq; n : INT; idle : BOOL; done : BOOL; END_VAR
         n := n + 1; seq(go := n >= 2, atIdle => idle, atDone => done);
         END_PROGRAM";
    // 10 ms cycles: Idle at 1, go from 2 (Fill acts from cycle 3), Fill for 30 ms, then Done;
    // `idle` and `done` read `x` before the chart runs, and `x` takes the transitions' `_x`
    // when the chart runs (CODESYS), so they show the steps of the previous cycle. Count (N),
    // Once (P) and Hold (S, then R) each get IEC's final call after deactivation.
    let s = run(source, 3);
    check(
        &s,
        &[
            ("main.seq.phase", "1"),
            ("main.seq.filled", "1"),
            ("main.seq.pulses", "1"),
            ("main.idle", "TRUE"),
        ],
    );
    let s = run(source, 8);
    // Fill became active at 10 ms, so its T reaches 30 ms in the cycle at 40 ms (its third).
    check(
        &s,
        &[
            ("main.seq.filled", "4"),
            ("main.seq.pulses", "2"),
            ("main.done", "TRUE"),
            ("main.seq.held", "4"),
            ("main.seq.Done.X", "TRUE"),
            ("main.seq.Fill.X", "FALSE"),
            ("main.seq.Done.T", "T#30ms"),
        ],
    );
}

#[test]
fn the_lc1200_conversion_table_holds_in_compiled_code() {
    // LC1200 digest §2.5, row by row.
    let s = run(
        "PROGRAM main VAR a1 : INT; a2 : STRING; b1 : TIME; b2 : TOD; c1 : DATE; c2 : DT; d1 : BOOL; d2 : BOOL; d3 : BOOL; d4 : BOOL;
         e1 : INT; e2 : BOOL; e3 : STRING; e4 : WORD; f1 : SINT; g1 : INT; g2 : INT; g3 : INT; g4 : INT; h1 : STRING; h2 : DWORD; h3 : SINT;
         i1 : BOOL; i2 : INT; i3 : BYTE; k1 : WORD; k2 : WORD; k3 : TIME; k4 : REAL; k5 : BYTE; t1 : DINT; t2 : DINT; END_VAR
         a1 := BOOL_TO_INT(TRUE); a2 := BOOL_TO_STRING(TRUE); b1 := BOOL_TO_TIME(TRUE); b2 := BOOL_TO_TOD(TRUE);
         c1 := BOOL_TO_DATE(FALSE); c2 := BOOL_TO_DT(TRUE);
         d1 := BYTE_TO_BOOL(2#11010101); d2 := INT_TO_BOOL(0); d3 := TIME_TO_BOOL(T#5ms); d4 := STRING_TO_BOOL('TRUE');
         e1 := TO_INT(4.22); e2 := TO_BOOL(1); e3 := TO_STRING(342); e4 := TO_WORD('123');
         f1 := INT_TO_SINT(4223);
         g1 := REAL_TO_INT(1.5); g2 := REAL_TO_INT(1.4); g3 := REAL_TO_INT(-1.5); g4 := REAL_TO_INT(-1.4);
         h1 := TIME_TO_STRING(T#12ms); h2 := TIME_TO_DWORD(T#5m); h3 := TOD_TO_SINT(TOD#00:00:00.012);
         i1 := DATE_TO_BOOL(D#1970-01-01); i2 := DATE_TO_INT(D#1970-01-15); i3 := DT_TO_BYTE(DT#1970-01-15-05:05:05);
         k1 := STRING_TO_WORD('abc34'); k2 := STRING_TO_WORD('34abc'); k3 := STRING_TO_TIME('T#127ms'); k4 := STRING_TO_REAL('1.234'); k5 := STRING_TO_BYTE('500');
         t1 := TRUNC(1.9); t2 := TRUNC(-1.4);
         END_PROGRAM",
        1,
    );
    check(
        &s,
        &[
            ("main.a1", "1"),
            ("main.a2", "'TRUE'"),
            ("main.b1", "T#1ms"),
            ("main.b2", "TOD#00:00:00.001"),
            ("main.c1", "D#1970-01-01"),
            ("main.c2", "DT#1970-01-01-00:00:01"),
            ("main.d1", "TRUE"),
            ("main.d2", "FALSE"),
            ("main.d3", "TRUE"),
            ("main.d4", "TRUE"),
            ("main.e1", "4"),
            ("main.e2", "TRUE"),
            ("main.e3", "'342'"),
            ("main.e4", "123"),
            ("main.f1", "127"),
            ("main.g1", "2"),
            ("main.g2", "1"),
            ("main.g3", "-2"),
            ("main.g4", "-1"),
            ("main.h1", "'T#12ms'"),
            ("main.h2", "300000"),
            ("main.h3", "12"),
            ("main.i1", "FALSE"),
            ("main.i2", "29952"),
            ("main.i3", "129"),
            ("main.k1", "0"),
            ("main.k2", "34"),
            ("main.k3", "T#127ms"),
            ("main.k4", "1.234"),
            ("main.k5", "244"),
            ("main.t1", "1"),
            ("main.t2", "-1"),
        ],
    );
}

#[test]
fn arrays_larger_than_memory_are_refused_not_crashed_on() {
    let source = compiler::SourceProject::new(
        "PROGRAM main VAR a : ARRAY[-9223372036854775807..9223372036854775807] OF BYTE; END_VAR a[0] := 1; END_PROGRAM",
    );
    let error = compiler::compile_source(&source, "big.st")
        .unwrap_err()
        .to_string();
    assert!(error.contains("larger than a memory region"), "{error}");
}
