//! Instruction List bodies compiled and run (`docs/instruction-list.md`): counting, loops by
//! conditional jumps, calls of function blocks and functions, parentheses, set and reset, and
//! Beremiz's `first_steps` counter in IL against its Structured Text twin.
//!
//! Each case declares its POUs in Structured Text and gives some of them IL bodies; the
//! implicit task runs `Main` every 10 ms.

use project_model::{Body, Object};
use runtime::simulation::Simulation;

/// Compiles `declarations` with the IL `bodies` (POU name, text) and runs `cycles` cycles.
#[track_caller]
fn run(declarations: &str, bodies: &[(&str, &str)], cycles: u64) -> Simulation {
    let built = compiler::SourceProject::new(declarations);
    assert!(
        built.parse.errors().is_empty(),
        "{:?}",
        built.parse.errors()
    );
    let mut project = built.project;
    for (pou, text) in bodies {
        match project.application.object_mut(pou) {
            Some(Object::Pou(pou)) => {
                pou.body = Body::Il {
                    text: (*text).into(),
                }
            }
            _ => panic!("no POU {pou}"),
        }
    }
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found
                .iter()
                .filter(|d| d.diagnostic.severity == compiler::Severity::Error)
                .map(|d| {
                    let text = bodies
                        .iter()
                        .find(|(pou, _)| d.file.to_string_lossy().contains(pou))
                        .map_or("", |(_, text)| text);
                    let (line, _) =
                        compiler::diagnostic::line_column(text, d.diagnostic.range.start);
                    format!("{}:{line}: {}", d.file.display(), d.diagnostic.message)
                })
                .collect();
            panic!("the IL does not check: {errors:#?}")
        }
        Err(error) => panic!("the IL does not compile: {error}"),
    };
    let simulation = crate::simulate(image, cycles);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    simulation
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
    for (path, want) in expected {
        assert_eq!(value(simulation, path), *want, "{path}");
    }
}

#[test]
fn an_il_program_counts_its_cycles() {
    let declarations = "PROGRAM Main VAR count : INT; twice : DINT; END_VAR END_PROGRAM";
    let il = "LD count\nADD 1\nST count\nMUL 2\nST twice\n";
    let s = run(declarations, &[("Main", il)], 5);
    check(&s, &[("Main.count", "5"), ("Main.twice", "10")]);
}

#[test]
fn a_conditional_jump_back_loops_until_its_condition_fails() {
    let declarations = "PROGRAM Main VAR i, sum, rounds : INT; END_VAR END_PROGRAM";
    // The sum of 1 to 10, computed again every cycle.
    let il = "
        LD 0
        ST i
        ST sum
Loop:   LD i
        ADD 1
        ST i
        ADD sum
        ST sum
        LD i
        LT 10
        JMPC Loop
        LD rounds
        ADD 1
        ST rounds
";
    let s = run(declarations, &[("Main", il)], 3);
    check(
        &s,
        &[("Main.sum", "55"), ("Main.i", "10"), ("Main.rounds", "3")],
    );
}

#[test]
fn cal_runs_timers_and_counters_with_arguments_or_inputs_set_before() {
    let declarations = "PROGRAM Main
        VAR t : TON; ctr : CTU; pulse, done, reached : BOOL; cv : INT; END_VAR
        END_PROGRAM";
    let il = "
CAL t(IN := TRUE, PT := T#45ms)
LD t.Q
ST done
LDN pulse
ST pulse
ST ctr.CU
LD 3
ST ctr.PV
CAL ctr
LD ctr.Q
ST reached
LD ctr.CV
ST cv
";
    // Cycles at 0, 10, 20, 30 ms: the timer has seen 30 ms of its 45; the pulse rose twice.
    let s = run(declarations, &[("Main", il)], 4);
    check(
        &s,
        &[
            ("Main.done", "FALSE"),
            ("Main.cv", "2"),
            ("Main.reached", "FALSE"),
        ],
    );
    let s = run(declarations, &[("Main", il)], 6);
    check(
        &s,
        &[
            ("Main.done", "TRUE"),
            ("Main.cv", "3"),
            ("Main.reached", "TRUE"),
        ],
    );
}

#[test]
fn functions_written_in_il_and_standard_functions_take_the_current_result_first() {
    let declarations = "FUNCTION Twice : INT VAR_INPUT v : INT; END_VAR END_FUNCTION
        PROGRAM Main VAR x : INT := 7; y, z, w : INT; END_VAR END_PROGRAM";
    let twice = "LD v\nMUL 2\nST Twice\n";
    let main = "LD x\nTwice\nST y\nLD y\nLIMIT 0, 10\nST z\nMAX(IN1 := x, IN2 := 3)\nTwice\nST w\n";
    let s = run(declarations, &[("Twice", twice), ("Main", main)], 1);
    check(&s, &[("Main.y", "14"), ("Main.z", "10"), ("Main.w", "14")]);
}

#[test]
fn parentheses_defer_an_operation_until_their_own_result_is_computed() {
    let declarations = "PROGRAM Main
        VAR a : BOOL := TRUE; b : BOOL; c : BOOL := TRUE; q, r : BOOL; x : INT := 4; y : INT; END_VAR
        END_PROGRAM";
    let il = "
LD a
AND( b
OR c
)
ST q
LD a
ANDN(
LD b
OR c
)
ST r
LD 2
MUL( x
ADD 3
)
ST y
";
    let s = run(declarations, &[("Main", il)], 1);
    check(
        &s,
        &[("Main.q", "TRUE"), ("Main.r", "FALSE"), ("Main.y", "14")],
    );
}

#[test]
fn set_and_reset_latch_until_the_other_one_fires() {
    let declarations = "PROGRAM Main
        VAR cycles : INT; start, stop, motor, seen : BOOL; END_VAR
        END_PROGRAM";
    // Start in cycle 2, stop in cycle 4; `seen` remembers that the motor ran.
    let il = "
LD cycles
ADD 1
ST cycles
EQ 2
ST start
LD cycles
EQ 4
ST stop
LD start
S motor
LD stop
R motor
LD motor
S seen
";
    let s = run(declarations, &[("Main", il)], 3);
    check(&s, &[("Main.motor", "TRUE"), ("Main.seen", "TRUE")]);
    let s = run(declarations, &[("Main", il)], 5);
    check(&s, &[("Main.motor", "FALSE"), ("Main.seen", "TRUE")]);
}

/// Beremiz's `first_steps` (`exemples/first_steps/plc.xml`): the IL body of `CounterIL` and
/// the ST body of `CounterST`, copied as they are, with the configuration's constant.
const FIRST_STEPS: &str = "VAR_GLOBAL CONSTANT ResetCounterValue : INT := 17; END_VAR
FUNCTION_BLOCK CounterST
VAR_INPUT Reset : BOOL; END_VAR
VAR Cnt : INT; END_VAR
VAR_OUTPUT OUT : INT; END_VAR
VAR_EXTERNAL CONSTANT ResetCounterValue : INT; END_VAR
IF Reset THEN
  Cnt := ResetCounterValue;
ELSE
  Cnt := Cnt + 1;
END_IF;

Out := Cnt;
END_FUNCTION_BLOCK
FUNCTION_BLOCK CounterIL
VAR Cnt : INT; END_VAR
VAR_INPUT Reset : BOOL; END_VAR
VAR_OUTPUT OUT : INT; END_VAR
VAR_EXTERNAL CONSTANT ResetCounterValue : INT; END_VAR
END_FUNCTION_BLOCK
PROGRAM Main
VAR CounterST0 : CounterST; CounterIL0 : CounterIL; cycles : INT; reset : BOOL; st, il : INT; same : BOOL := TRUE; END_VAR
cycles := cycles + 1;
reset := cycles MOD 7 = 0;
CounterST0(Reset := reset, OUT => st);
CounterIL0(Reset := reset, OUT => il);
same := same AND st = il;
END_PROGRAM
";

const COUNTER_IL: &str = "LD Reset
JMPC ResetCnt

(* increment counter *)
LD Cnt
ADD 1
JMP QuitFb

ResetCnt:
(* reset counter *)
LD ResetCounterValue

QuitFb:
(* save results *)
ST Cnt
ST Out
";

#[test]
fn beremiz_first_steps_counter_in_il_counts_as_its_st_twin() {
    let s = run(FIRST_STEPS, &[("CounterIL", COUNTER_IL)], 10);
    // Cycles 1 to 6 count 1 to 6, cycle 7 resets to 17, cycles 8 to 10 count on to 20.
    check(
        &s,
        &[
            ("Main.same", "TRUE"),
            ("Main.il", "20"),
            ("Main.st", "20"),
            ("Main.CounterIL0.Cnt", "20"),
        ],
    );
}
