//! Breakpoints on the steps of a Sequential Function Chart: a step's line is a statement start
//! of its active pass, so its breakpoint halts in the cycles the step is active and in no
//! other (`docs/debugging.md` §3).

use runtime::engine::{Engine, HaltReason};

use super::{Script, compile, line_in, run_cycles, spec_at};

const CHART: &str = "
PROGRAM Main
VAR n : INT; go : BOOL; END_VAR
n := n + 1;
go := n >= 3;
INITIAL_STEP Idle:
END_STEP
TRANSITION FROM Idle TO Run := go;
END_TRANSITION
STEP Run:
END_STEP
TRANSITION FROM Run TO Idle := FALSE;
END_TRANSITION
END_PROGRAM
";

#[test]
fn a_breakpoint_on_a_step_halts_only_in_the_cycles_the_step_is_active() {
    let image = compile(CHART);
    let mut engine = Engine::new(image.clone()).expect("the image loads");
    engine.debug_mut().begin_session();
    let run_line = line_in(CHART, "STEP Run");
    let (id, _) = engine
        .view()
        .set_breakpoint(spec_at(&image, "Main", run_line))
        .expect("the breakpoint is set");
    let mut script = Script {
        actions: Vec::new(),
        seen: Vec::new(),
    };
    // `go` turns TRUE in the third cycle, whose transition activates Run for the fourth.
    run_cycles(&mut engine, &mut script, 6);
    let counts: Vec<&str> = script.seen.iter().map(|seen| seen.n.as_str()).collect();
    assert_eq!(counts, ["4", "5", "6"], "{:#?}", script.seen);
    assert!(
        script
            .seen
            .iter()
            .all(|seen| seen.reason == HaltReason::Breakpoint(id)
                && seen.stack.first().map(|frame| frame.1) == Some(run_line))
    );
}
