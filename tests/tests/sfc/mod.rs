//! Textual SFC compiled and run cycle after cycle, against tables written by hand in
//! `docs/sfc-semantics.md` (§ "Qualifier tables").
//!
//! Every chart is the body of a program `main` that first counts the cycle and writes `|k ` into
//! a log; each action of the chart appends its name (IEC actions add `f` when they run with
//! `Q` FALSE, their final or pulse call). The whole log is the cycle-by-cycle table. Cycles are
//! 10 ms apart; the transition fired in cycle `k` activates its steps in cycle `k + 1`.

use runtime::simulation::Simulation;

use super::{check, run, value};

/// An inline IEC action that logs `Name ` while its Q is TRUE and `Namef ` otherwise.
fn iec_action(name: &str) -> String {
    format!(
        "ACTION {name}: IF _{name}._x THEN log := CONCAT(log, '{name} '); ELSE log := CONCAT(log, '{name}f '); END_IF; END_ACTION\n"
    )
}

/// An inline action (entry, main or exit) that logs its name.
fn plain_action(name: &str) -> String {
    format!("ACTION {name}: log := CONCAT(log, '{name} '); END_ACTION\n")
}

/// Runs `chart` (with the IEC actions `iec` and plain actions `plain`) in `main` for `cycles`.
fn run_chart(
    variables: &str,
    before: &str,
    chart: &str,
    iec: &[&str],
    plain: &[&str],
    cycles: u64,
) -> Simulation {
    let mut actions = String::new();
    for name in iec {
        actions.push_str(&iec_action(name));
    }
    for name in plain {
        actions.push_str(&plain_action(name));
    }
    let source = format!(
        "PROGRAM main VAR cycle : INT; log : STRING(250); {variables} END_VAR
         cycle := cycle + 1; log := CONCAT(log, CONCAT('|', CONCAT(INT_TO_STRING(cycle), ' ')));
         {before}
         {chart}
         {actions}
         END_PROGRAM"
    );
    run(&source, cycles)
}

fn log_of(simulation: &Simulation) -> String {
    let text = value(simulation, "main.log");
    text.trim_matches('\'').trim_end().to_owned()
}

/// S0 → (cycle 2) S1 with `association` → (cycle `leave`) S2 → (cycle 9) S3 with `A(R)`.
fn qualifier_log(association: &str, leave: u32, cycles: u64) -> String {
    let chart = format!(
        "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO S1 := cycle = 2; END_TRANSITION
         STEP S1: {association}; END_STEP
         TRANSITION FROM S1 TO S2 := cycle = {leave}; END_TRANSITION
         STEP S2: END_STEP
         TRANSITION FROM S2 TO S3 := cycle = 9; END_TRANSITION
         STEP S3: A(R); END_STEP"
    );
    let s = run_chart("tDelay : TIME := T#20ms;", "", &chart, &["A"], &[], cycles);
    check(&s, &[]);
    log_of(&s)
}

#[test]
fn n_runs_while_the_step_is_active_and_once_more_with_q_false() {
    assert_eq!(qualifier_log("A(N)", 5, 7), "|1 |2 |3 A |4 A |5 A |6 Af |7");
}

#[test]
fn l_runs_for_its_time_or_until_the_step_ends() {
    // The timer starts in cycle 3 (20 ms) and is done at 40 ms, cycle 5.
    assert_eq!(
        qualifier_log("A(L, T#20ms)", 7, 8),
        "|1 |2 |3 A |4 A |5 Af |6 |7 |8"
    );
    // The step ends (cycle 4) before the 50 ms are over.
    assert_eq!(
        qualifier_log("A(L, T#50ms)", 4, 7),
        "|1 |2 |3 A |4 A |5 Af |6 |7"
    );
}

#[test]
fn d_starts_after_its_delay_only_while_the_step_is_still_active() {
    assert_eq!(
        qualifier_log("A(D, T#20ms)", 7, 9),
        "|1 |2 |3 |4 |5 A |6 A |7 A |8 Af |9"
    );
    // A duration in a variable, read while the step is active.
    assert_eq!(
        qualifier_log("A(D, tDelay)", 7, 9),
        "|1 |2 |3 |4 |5 A |6 A |7 A |8 Af |9"
    );
    // The step ends before the delay: the action never runs.
    assert_eq!(
        qualifier_log("A(D, T#50ms)", 4, 8),
        "|1 |2 |3 |4 |5 |6 |7 |8"
    );
}

#[test]
fn p_p1_and_p0_pulse_on_the_edges_of_the_step() {
    assert_eq!(qualifier_log("A(P)", 5, 7), "|1 |2 |3 A |4 Af |5 |6 |7");
    assert_eq!(qualifier_log("A(P1)", 5, 7), "|1 |2 |3 Af |4 |5 |6 |7");
    assert_eq!(qualifier_log("A(P0)", 5, 7), "|1 |2 |3 |4 |5 |6 Af |7");
}

#[test]
fn s_stays_set_after_the_step_until_r() {
    assert_eq!(
        qualifier_log("A(S)", 4, 12),
        "|1 |2 |3 A |4 A |5 A |6 A |7 A |8 A |9 A |10 Af |11 |12"
    );
}

#[test]
fn sd_ds_and_sl_store_with_their_delays_and_limits() {
    // SD: latched in cycle 3, on after 20 ms even though the step ended in cycle 3, until R.
    assert_eq!(
        qualifier_log("A(SD, T#20ms)", 3, 11),
        "|1 |2 |3 |4 |5 A |6 A |7 A |8 A |9 A |10 Af |11"
    );
    // SD reset by R before its delay is over: never on.
    assert_eq!(
        qualifier_log("A(SD, T#100ms)", 3, 12),
        "|1 |2 |3 |4 |5 |6 |7 |8 |9 |10 |11 |12"
    );
    // DS: the delay elapses while the step is active (cycle 5), then stored until R.
    assert_eq!(
        qualifier_log("A(DS, T#20ms)", 6, 11),
        "|1 |2 |3 |4 |5 A |6 A |7 A |8 A |9 A |10 Af |11"
    );
    // DS: the step ends first, so nothing is stored.
    assert_eq!(
        qualifier_log("A(DS, T#20ms)", 4, 8),
        "|1 |2 |3 |4 |5 |6 |7 |8"
    );
    // SL: on from activation for its time, even after the step ended.
    assert_eq!(
        qualifier_log("A(SL, T#50ms)", 3, 10),
        "|1 |2 |3 A |4 A |5 A |6 A |7 A |8 Af |9 |10"
    );
    // SL cut short by R.
    assert_eq!(
        qualifier_log("A(SL, T#1s)", 3, 11),
        "|1 |2 |3 A |4 A |5 A |6 A |7 A |8 A |9 A |10 Af |11"
    );
}

#[test]
fn an_indicator_and_a_boolean_action_follow_q() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO S1 := cycle = 2; END_TRANSITION
         STEP S1: A(L, T#20ms, lamp); valve(N); END_STEP
         TRANSITION FROM S1 TO S0 := cycle = 6; END_TRANSITION";
    let vars = "lamp : BOOL; valve : BOOL; lamps : STRING(40); valves : STRING(40);";
    let after = "";
    let probe = |cycles| {
        let s = run_chart(vars, after, chart, &["A"], &[], cycles);
        check(&s, &[]);
        (value(&s, "main.lamp"), value(&s, "main.valve"))
    };
    assert_eq!(probe(2), ("FALSE".into(), "FALSE".into()));
    assert_eq!(probe(3), ("TRUE".into(), "TRUE".into()));
    assert_eq!(probe(5), ("FALSE".into(), "TRUE".into()));
    assert_eq!(probe(7), ("FALSE".into(), "FALSE".into()));
}

#[test]
fn an_action_of_two_active_steps_runs_once_per_cycle_and_finals_come_first() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO (S1, S2) := cycle = 2; END_TRANSITION
         STEP S1: A(N); B(N); END_STEP
         STEP S2: A(N); END_STEP
         TRANSITION FROM S1 TO S3 := cycle = 4; END_TRANSITION
         STEP S3: END_STEP
         TRANSITION FROM (S2, S3) TO S4 := TRUE; END_TRANSITION
         STEP S4: A(N); END_STEP";
    let s = run_chart("", "", chart, &["A", "B"], &[], 7);
    check(&s, &[]);
    // A in cycle 5 stays on through S2; B's final call comes before A's run; S4 joins in 6.
    assert_eq!(log_of(&s), "|1 |2 |3 A B |4 A B |5 Bf A |6 A |7 A");
}

#[test]
fn alternative_branches_take_the_first_true_transition_by_text_order_or_priority() {
    let chart = |priority: &str| {
        format!(
            "INITIAL_STEP S0: END_STEP
             TRANSITION FROM S0 TO Left := TRUE; END_TRANSITION
             TRANSITION {priority} FROM S0 TO Right := TRUE; END_TRANSITION
             STEP Left: END_STEP
             STEP Right: END_STEP"
        )
    };
    let s = run_chart("", "", &chart(""), &[], &[], 3);
    check(&s, &[("main.Left.x", "TRUE"), ("main.Right.x", "FALSE")]);
    let s = run_chart("", "", &chart("(PRIORITY := 1)"), &[], &[], 3);
    check(&s, &[("main.Left.x", "FALSE"), ("main.Right.x", "TRUE")]);
}

#[test]
fn parallel_branches_converge_when_every_branch_is_done_and_jumps_go_back() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO (P1, Q1) := TRUE; END_TRANSITION
         STEP P1: END_STEP
         TRANSITION FROM P1 TO P2 := cycle = 3; END_TRANSITION
         STEP P2: END_STEP
         STEP Q1: END_STEP
         TRANSITION FROM Q1 TO Q2 := cycle = 5; END_TRANSITION
         STEP Q2: END_STEP
         TRANSITION FROM (P2, Q2) TO S0 := TRUE; END_TRANSITION";
    let vars = "seen : STRING(120);";
    // Each cycle notes the active steps, as the chart left them before it runs again.
    let before = "IF S0.x THEN seen := CONCAT(seen, '0'); END_IF; IF P1.x THEN seen := CONCAT(seen, 'p'); END_IF;
        IF P2.x THEN seen := CONCAT(seen, 'P'); END_IF; IF Q1.x THEN seen := CONCAT(seen, 'q'); END_IF;
        IF Q2.x THEN seen := CONCAT(seen, 'Q'); END_IF; seen := CONCAT(seen, ' ');";
    let s = run_chart(vars, before, chart, &[], &[], 9);
    check(&s, &[]);
    // Cycle 1 sees nothing yet; S0 fires in 1, P1 and Q1 run 2–3, P2 waits for Q2 (6), the
    // join fires in 6, and S0 is back in 7 (and leaves again at once).
    assert_eq!(value(&s, "main.seen"), "' 0 pq pq Pq Pq PQ 0 pq '");
}

#[test]
fn entry_main_and_exit_actions_run_in_codesys_order() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO S1 := cycle = 2; END_TRANSITION
         STEP S1 (ENTRY := En1, MAIN := Ma1, EXIT := Ex1): A(N); END_STEP
         TRANSITION FROM S1 TO S2 := cycle = 4; END_TRANSITION
         STEP S2 (MAIN := Ma2, ENTRY := En2): END_STEP";
    let s = run_chart(
        "",
        "",
        chart,
        &["A"],
        &["En1", "Ma1", "Ex1", "En2", "Ma2"],
        6,
    );
    check(&s, &[]);
    assert_eq!(
        log_of(&s),
        "|1 |2 |3 En1 Ma1 A |4 Ma1 A |5 Ex1 En2 Ma2 Af |6 Ma2"
    );
}

#[test]
fn min_time_holds_a_step_and_max_time_raises_sfc_error() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO S1 := cycle = 2; END_TRANSITION
         STEP S1 (MIN_TIME := T#30ms, MAX_TIME := tMax): END_STEP
         TRANSITION FROM S1 TO S2 := leave; END_TRANSITION
         STEP S2: END_STEP";
    let vars = "tMax : TIME := T#50ms; leave : BOOL; SFCError : BOOL; SFCErrorStep : STRING; SFCErrorPOU : STRING; SFCEnableLimit : BOOL := TRUE; SFCQuitError : BOOL;";
    // `leave` is TRUE from the start; S1 is active from cycle 3 (t = 10 ms) and may leave once
    // t reaches 30 ms, in cycle 5, so S2 is active in cycle 6.
    let s = run_chart(vars, "leave := TRUE;", chart, &[], &[], 5);
    check(&s, &[("main.S1.x", "TRUE"), ("main.S1._x", "FALSE")]);
    let s = run_chart(vars, "leave := TRUE;", chart, &[], &[], 6);
    check(
        &s,
        &[
            ("main.S2.x", "TRUE"),
            ("main.S1.t", "T#30ms"),
            ("main.SFCError", "FALSE"),
        ],
    );
    // Staying: t is 50 ms in cycle 7 and exceeds it in cycle 8 (60 ms).
    let s = run_chart(vars, "", chart, &[], &[], 7);
    check(&s, &[("main.SFCError", "FALSE"), ("main.S1.t", "T#50ms")]);
    let s = run_chart(vars, "", chart, &[], &[], 8);
    check(
        &s,
        &[
            ("main.SFCError", "TRUE"),
            ("main.SFCErrorStep", "'S1'"),
            ("main.SFCErrorPOU", "'main'"),
        ],
    );
    // Without SFCEnableLimit the time is not watched.
    let s = run_chart(vars, "SFCEnableLimit := FALSE;", chart, &[], &[], 9);
    check(&s, &[("main.SFCError", "FALSE")]);
    // SFCQuitError (cycles 9–10) clears the error and the names and holds the chart; on its falling edge
    // (cycle 11) the time of the active step restarts, so S1 is 10 ms old in cycle 12 and the
    // error comes back only after another 50 ms.
    let quit = "SFCQuitError := cycle >= 9 AND cycle <= 10;";
    let s = run_chart(vars, quit, chart, &[], &[], 10);
    check(
        &s,
        &[("main.SFCError", "FALSE"), ("main.SFCErrorStep", "''")],
    );
    let s = run_chart(vars, quit, chart, &[], &[], 12);
    check(&s, &[("main.SFCError", "FALSE"), ("main.S1.t", "T#10ms")]);
}

#[test]
fn sfc_init_reset_and_pause_control_the_chart() {
    let chart = "INITIAL_STEP S0: A(N); END_STEP
         TRANSITION FROM S0 TO S1 := TRUE; END_TRANSITION
         STEP S1: END_STEP
         TRANSITION FROM S1 TO S2 := TRUE; END_TRANSITION
         STEP S2: END_STEP";
    let vars = "SFCInit : BOOL; SFCReset : BOOL; SFCPause : BOOL;";
    // SFCPause in cycles 2–3 holds S1 (active from cycle 2).
    let s = run_chart(
        vars,
        "SFCPause := cycle >= 2 AND cycle <= 3;",
        chart,
        &["A"],
        &[],
        4,
    );
    check(&s, &[]);
    assert_eq!(log_of(&s), "|1 A |2 |3 |4 Af");
    // SFCInit in cycles 4–5: back to S0, whose actions do not run while it is TRUE.
    let s = run_chart(
        vars,
        "SFCInit := cycle >= 4 AND cycle <= 5;",
        chart,
        &["A"],
        &[],
        7,
    );
    check(&s, &[("main.S0.x", "FALSE"), ("main.S1.x", "TRUE")]);
    assert_eq!(log_of(&s), "|1 A |2 Af |3 |4 |5 |6 A |7 Af");
    // The initial step's entry action runs once SFCInit is released.
    let entry = "INITIAL_STEP S0 (ENTRY := In0): END_STEP
         TRANSITION FROM S0 TO S1 := cycle = 2; END_TRANSITION
         STEP S1: END_STEP";
    let s = run_chart(
        vars,
        "SFCInit := cycle >= 4 AND cycle <= 5;",
        entry,
        &[],
        &["In0"],
        7,
    );
    check(&s, &[("main.S0.x", "TRUE")]);
    assert_eq!(log_of(&s), "|1 In0 |2 |3 |4 |5 |6 In0 |7");
    // SFCReset in cycle 4: back to S0, which runs in the same cycle.
    let s = run_chart(vars, "SFCReset := cycle = 4;", chart, &["A"], &[], 5);
    check(&s, &[]);
    assert_eq!(log_of(&s), "|1 A |2 Af |3 |4 A |5 Af");
}

#[test]
fn sfc_trans_and_sfc_current_step_report_the_chart() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO (Left, Right) := cycle = 2; END_TRANSITION
         STEP Left: END_STEP
         STEP Right: END_STEP";
    let vars = "SFCTrans : BOOL; SFCCurrentStep : STRING;";
    let s = run_chart(vars, "", chart, &[], &[], 2);
    check(
        &s,
        &[("main.SFCTrans", "TRUE"), ("main.SFCCurrentStep", "'S0'")],
    );
    // With parallel branches the step named is the rightmost, the last in text order.
    let s = run_chart(vars, "", chart, &[], &[], 3);
    check(
        &s,
        &[
            ("main.SFCTrans", "FALSE"),
            ("main.SFCCurrentStep", "'Right'"),
        ],
    );
}

#[test]
fn tip_mode_fires_transitions_only_on_a_rising_edge_of_sfc_tip() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION FROM S0 TO S1 := TRUE; END_TRANSITION
         STEP S1: END_STEP
         TRANSITION FROM S1 TO S2 := FALSE; END_TRANSITION
         STEP S2: END_STEP";
    let vars = "SFCTip : BOOL; SFCTipMode : BOOL := TRUE;";
    let tip = "SFCTip := cycle >= 3 AND cycle <= 5 OR cycle = 7;";
    let s = run_chart(vars, tip, chart, &[], &[], 3);
    check(&s, &[("main.S0.x", "TRUE")]);
    // The edge in cycle 3 fires S0 → S1; SFCTip held TRUE fires nothing more; the edge in
    // cycle 7 fires S1 → S2 although its condition is FALSE.
    let s = run_chart(vars, tip, chart, &[], &[], 7);
    check(&s, &[("main.S1.x", "TRUE"), ("main.S1._x", "FALSE")]);
    let s = run_chart(vars, tip, chart, &[], &[], 8);
    check(&s, &[("main.S2.x", "TRUE")]);
}

#[test]
fn writing_a_steps_next_flag_activates_and_deactivates_it() {
    let chart = "INITIAL_STEP S0: A(N); END_STEP
         TRANSITION FROM S0 TO S1 := FALSE; END_TRANSITION
         STEP S1: END_STEP
         STEP S2: END_STEP";
    let before = "IF cycle = 3 THEN S0._x := FALSE; S2._x := TRUE; END_IF;";
    let s = run_chart("", before, chart, &["A"], &[], 4);
    check(
        &s,
        &[
            ("main.S0.x", "FALSE"),
            ("main.S2.x", "TRUE"),
            ("main._A._x", "FALSE"),
            ("main._A.x", "FALSE"),
        ],
    );
    assert_eq!(log_of(&s), "|1 A |2 A |3 Af |4");
}

#[test]
fn another_pou_reads_and_drives_a_chart_by_its_steps_flags() {
    // `main` calls the chart's instance, then reads its steps and action flags and, in cycle
    // 4, jumps the chart from Run to Stop by writing their `_x`.
    let source = "FUNCTION_BLOCK FB_Seq
         INITIAL_STEP Idle: END_STEP
         TRANSITION FROM Idle TO Run := TRUE; END_TRANSITION
         STEP Run: Pump(N); END_STEP
         STEP Stop: END_STEP
         ACTION Pump: ; END_ACTION
         END_FUNCTION_BLOCK
         PROGRAM main VAR seq : FB_Seq; cycle : INT; running : BOOL; pumping : BOOL; runT : TIME; END_VAR
         cycle := cycle + 1;
         seq();
         running := seq.Run.x; pumping := seq._Pump._x; runT := seq.Run.t;
         IF cycle = 4 THEN seq.Run._x := FALSE; seq.Stop._x := TRUE; END_IF;
         END_PROGRAM";
    let s = run(source, 3);
    check(
        &s,
        &[
            ("main.running", "TRUE"),
            ("main.pumping", "TRUE"),
            ("main.runT", "T#20ms"),
        ],
    );
    let s = run(source, 6);
    check(
        &s,
        &[
            ("main.seq.Run.x", "FALSE"),
            ("main.seq.Stop.x", "TRUE"),
            ("main.pumping", "FALSE"),
            ("main.runT", "T#30ms"),
        ],
    );
}

#[test]
fn a_step_is_driven_by_writing_its_next_flag_by_path_as_online_services_do() {
    let chart = "INITIAL_STEP S0: A(N); END_STEP
         TRANSITION FROM S0 TO S1 := FALSE; END_TRANSITION
         STEP S1: END_STEP
         STEP S2: END_STEP";
    let mut s = run_chart("", "", chart, &["A"], &[], 2);
    // What `rivet write main.S2._x TRUE` does: the path's place in the data region.
    for (path, value) in [("main.S0._x", 0u8), ("main.S2._x", 1u8)] {
        let place = runtime::value::resolve(s.engine().image(), path)
            .unwrap_or_else(|e| panic!("{path}: {e}"));
        let offset = usize::try_from(place.offset).expect("an offset in memory");
        s.engine_mut().region_mut(place.region)[offset] = value;
    }
    s.run(2);
    check(&s, &[("main.S0.x", "FALSE"), ("main.S2.x", "TRUE")]);
    assert_eq!(log_of(&s), "|1 A |2 A |3 Af |4");
}

#[test]
fn a_transition_written_with_statements_fires_on_the_value_they_assign() {
    let chart = "INITIAL_STEP S0: END_STEP
         TRANSITION Ready FROM S0 TO S1 :
             IF cycle >= 3 THEN Ready := TRUE; END_IF;
         END_TRANSITION
         STEP S1: END_STEP
         TRANSITION Never FROM S1 TO S0 : ; END_TRANSITION";
    let s = run_chart("", "", chart, &[], &[], 3);
    check(&s, &[("main.S0.x", "TRUE"), ("main.S1._x", "TRUE")]);
    // `Never` assigns nothing, so it stays FALSE.
    let s = run_chart("", "", chart, &[], &[], 6);
    check(&s, &[("main.S1.x", "TRUE")]);
}
