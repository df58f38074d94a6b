//! Breakpoints on the steps of a Sequential Function Chart: a step's line is a statement start
//! of its active pass, so its breakpoint halts in the cycles the step is active and in no
//! other (`docs/debugging.md` §3).

use runtime::engine::{Engine, HaltReason, HitMode};

use super::{Script, compile, run_cycles};

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
    // Lines count from 1.
    let run_line = CHART
        .lines()
        .position(|line| line.starts_with("STEP Run"))
        .expect("the chart has the step Run") as u32
        + 1;
    let pou = image
        .pous
        .iter()
        .position(|pou| pou.name == "Main")
        .expect("Main is compiled") as u32;
    let instruction = image.pous[pou as usize]
        .lines
        .iter()
        .find(|entry| entry.line == run_line)
        .expect("the step's line starts a statement")
        .index;
    let (id, _) = engine
        .view()
        .set_breakpoint(runtime::engine::BreakpointSpec {
            pou,
            instruction,
            instance: 0,
            task: None,
            hit_mode: HitMode::Always,
            hit_target: 0,
            condition: Vec::new(),
        })
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
