//! What the debugger costs a cycle (issue 17: with no breakpoint set, within 2% of a cycle
//! without it; `docs/debugging.md` §3): a call-heavy program, a function block calling a
//! function and one of its methods in a loop on four instances, run four ways in the same
//! run: no debug session, a session with no breakpoint, a breakpoint in a POU that is never
//! called, and a breakpoint whose condition is FALSE in the function called most.

use std::hint::black_box;

use program_image::ProgramImage;
use runtime::engine::{BreakpointSpec, Engine, HitMode};

/// The program: per cycle 4 instances × 50 iterations, each a function call, a method call
/// and three statements besides the loop's test.
const SOURCE: &str = "
FUNCTION Scale : DINT
VAR_INPUT x : DINT; k : DINT; END_VAR
Scale := x * k + 1;
END_FUNCTION

FUNCTION Unused : DINT
VAR_INPUT x : DINT; END_VAR
Unused := x + 1;
END_FUNCTION

FUNCTION_BLOCK Acc
VAR_INPUT step : DINT; END_VAR
VAR total : DINT; i : DINT; END_VAR
FOR i := 1 TO 50 DO
    total := total + Scale(x := i, k := step);
    total := Fold(v := total);
    total := total MOD 100000;
END_FOR;
METHOD Fold : DINT
VAR_INPUT v : DINT; END_VAR
Fold := v - v / 7;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM main
VAR acc1, acc2, acc3, acc4 : Acc; n : DINT; END_VAR
acc1(step := 1);
acc2(step := 2);
acc3(step := 3);
acc4(step := 4);
n := n + 1;
END_PROGRAM
";

/// One way of running the program.
#[derive(Clone, Copy, Debug)]
enum Way {
    NoSession,
    SessionWithoutBreakpoints,
    BreakpointNotCalled,
    FalseConditionInCalledFunction,
}

impl Way {
    const ALL: [Way; 4] = [
        Way::NoSession,
        Way::SessionWithoutBreakpoints,
        Way::BreakpointNotCalled,
        Way::FalseConditionInCalledFunction,
    ];

    fn label(self) -> &'static str {
        match self {
            Way::NoSession => "no debug session",
            Way::SessionWithoutBreakpoints => "session, no breakpoint",
            Way::BreakpointNotCalled => "breakpoint in a POU not called",
            Way::FalseConditionInCalledFunction => "FALSE condition in the called function",
        }
    }
}

/// A breakpoint on the first statement of `pou`, with `condition` (encoded) if any.
fn breakpoint(image: &ProgramImage, pou: &str, condition: Vec<u8>) -> BreakpointSpec {
    let index = image
        .pous
        .iter()
        .position(|p| p.name.eq_ignore_ascii_case(pou))
        .unwrap_or_else(|| panic!("no POU {pou}"));
    BreakpointSpec {
        pou: index as u32,
        instruction: image.pous[index].lines[0].index,
        instance: 0,
        task: None,
        hit_mode: HitMode::Always,
        hit_target: 0,
        condition,
    }
}

/// The engine running the program `way`, after a few cycles.
fn engine(way: Way) -> Engine {
    let project = compiler::SourceProject::new(SOURCE);
    let image = compiler::compile_source(&project, "debugger.st").expect("the program compiles");
    // The interpreter, as the debugger's cost is measured against it; a cycle without a
    // session would run natively by default (docs/native-engine.md §1.3).
    let (mut engine, _) =
        Engine::with_choice(image.clone(), runtime::engine::EngineChoice::Interpreter)
            .expect("the image loads");
    match way {
        Way::NoSession => {}
        Way::SessionWithoutBreakpoints => engine.debug_mut().begin_session(),
        Way::BreakpointNotCalled => {
            engine.debug_mut().begin_session();
            let spec = breakpoint(&image, "Unused", Vec::new());
            engine.view().set_breakpoint(spec).expect("set");
        }
        Way::FalseConditionInCalledFunction => {
            engine.debug_mut().begin_session();
            let condition =
                compiler::compile_source_condition(&project, "debugger.st", "Scale", "x < 0")
                    .expect("the condition compiles");
            let spec = breakpoint(&image, "Scale", condition.condition.encode());
            engine.view().set_breakpoint(spec).expect("set");
        }
    }
    for cycle in 0..3 {
        engine.run_cycle(0, 0, cycle).expect("no fault");
    }
    engine
}

/// Prints ns/cycle of each way and its ratio to the first; each is the best median of three
/// rounds taken in turn, so a busy moment of the machine weighs on no way alone.
pub fn report(median_ns: &dyn Fn(&mut dyn FnMut()) -> f64) {
    let mut engines: Vec<Engine> = Way::ALL.iter().map(|&way| engine(way)).collect();
    let mut best = [f64::INFINITY; 4];
    for _round in 0..3 {
        for (index, engine) in engines.iter_mut().enumerate() {
            let mut cycle = 3;
            let ns = median_ns(&mut || {
                cycle += 1;
                black_box(engine.run_cycle(0, 0, cycle)).ok();
            });
            best[index] = best[index].min(ns);
        }
    }
    // The condition is FALSE, so no way halts or counts a hit.
    let hits = engines[3].debug().breakpoints()[0].hits;
    assert_eq!(hits, 0, "the condition is never TRUE");
    println!(
        "\nDebugger cost, call-heavy program (per cycle 4 instances × 50 iterations of a function call, a method call and 6 statement starts):\n"
    );
    println!("| way | ns/cycle | ratio to no session |");
    println!("|---|---:|---:|");
    for (way, ns) in Way::ALL.iter().zip(best) {
        println!("| {} | {ns:.0} | {:.3} |", way.label(), ns / best[0]);
    }
}
