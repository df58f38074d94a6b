//! The form each call runs (`docs/debugging.md` §3, "Cost"): only a POU the debugger watches
//! runs the debug form, yet a halt in it shows its callers that ran the light form with their
//! call sites; steps out of it and over its end land in such a caller, which goes on in the
//! debug form; flow recording of one POU works while its caller runs light; a breakpoint set
//! during a halt takes effect at its POU's next call, in the same cycle; a task interrupted
//! by a task of higher priority that halts shows its whole stack while it waits.

use std::sync::atomic::AtomicBool;

use program_image::{Instr, ProgramImage};
use runtime::engine::{
    BreakpointSpec, Engine, EngineView, HaltReason, Preempt, Preemption, StepKind, TaskClock,
};

use super::{compile, line_in, line_of, spec_at, statement};

const SOURCE: &str = "
FUNCTION Clamp : INT
VAR_INPUT v : INT; END_VAR
IF v > 100 THEN
    Clamp := 100;
ELSE
    Clamp := v;
END_IF;
END_FUNCTION

FUNCTION Tick : INT
VAR_INPUT v : INT; END_VAR
Tick := v + 1;
END_FUNCTION

FUNCTION Sum : INT
VAR_INPUT v : INT; END_VAR
VAR i : INT; END_VAR
Sum := 0;
FOR i := 1 TO 3 DO
    Sum := Sum + v;
END_FOR;
END_FUNCTION

PROGRAM Main
VAR n : INT; r : INT; END_VAR
n := n + 1;
r := Tick(n);
r := Clamp(r) + 1;
n := n + 0;
r := Sum(r);
END_PROGRAM
";

/// The source line where `text` starts in [`SOURCE`].
fn line(text: &str) -> u32 {
    line_in(SOURCE, text)
}

/// A breakpoint, halting always, on the statement of `pou` that starts with `text`.
fn spec(image: &ProgramImage, pou: &str, text: &str) -> BreakpointSpec {
    spec_at(image, pou, line(text))
}

/// What the hook does at a halt.
enum Then {
    Step(StepKind),
    Continue,
    /// Sets this breakpoint, then continues.
    Set(BreakpointSpec),
}

/// One halt: why, and the stack innermost first as (POU, source line).
#[derive(Debug)]
struct Seen {
    reason: HaltReason,
    frames: Vec<(String, u32)>,
}

struct Halts {
    then: Vec<Then>,
    seen: Vec<Seen>,
}

impl Preempt for Halts {
    fn preempt(&mut self, _engine: EngineView<'_>) {}

    fn halt(&mut self, mut engine: EngineView<'_>, task: usize) {
        let image = engine.image().clone();
        let state = engine.debug().task(task).expect("the task exists");
        let halt = *state.halt().expect("the task is halted");
        assert_eq!(state.stack().count(), usize::from(halt.depth));
        // Every frame but the innermost stands at the call of the next one.
        for caller in state.stack().skip(1) {
            let instr = &image.pous[caller.pou as usize].code[caller.instruction as usize];
            assert!(
                matches!(
                    instr,
                    Instr::CallFunction { .. }
                        | Instr::CallBlock { .. }
                        | Instr::CallVirtual { .. }
                ),
                "{caller:?} stands at {instr:?}"
            );
        }
        let frames = state
            .stack()
            .map(|frame| {
                (
                    image.pous[frame.pou as usize].name.clone(),
                    line_of(&image, frame.pou, frame.instruction),
                )
            })
            .collect();
        self.seen.push(Seen {
            reason: halt.reason,
            frames,
        });
        let then = if self.then.is_empty() {
            Then::Continue
        } else {
            self.then.remove(0)
        };
        match then {
            Then::Step(kind) => engine.debug_mut().step(task, kind).expect("it steps"),
            Then::Continue => engine.debug_mut().continue_task(task).expect("it goes on"),
            Then::Set(spec) => {
                engine.set_breakpoint(spec).expect("set");
                engine.debug_mut().continue_task(task).expect("it goes on");
            }
        }
    }
}

fn engine() -> (Engine, ProgramImage) {
    let image = compile(SOURCE);
    let mut engine = Engine::new(image.clone()).expect("the image loads");
    engine.debug_mut().begin_session();
    (engine, image)
}

/// Runs `cycles` cycles with `then` done at the halts, and returns what was seen.
fn run(engine: &mut Engine, then: Vec<Then>, cycles: u64) -> Vec<Seen> {
    let mut hook = Halts {
        then,
        seen: Vec::new(),
    };
    let due = AtomicBool::new(false);
    for cycle in 0..cycles {
        let preemption = Preemption {
            due: &due,
            hook: &mut hook,
        };
        engine
            .view()
            .run_cycle(0, 0, TaskClock::Simulated, cycle, Some(preemption))
            .expect("no fault");
    }
    hook.seen
}

fn at(pou: &str, text: &str) -> (String, u32) {
    (pou.to_owned(), line(text))
}

#[test]
fn a_breakpoint_in_a_function_called_from_a_plain_program_shows_the_program_at_its_call() {
    let (mut engine, image) = engine();
    let (id, _) = engine
        .view()
        .set_breakpoint(spec(&image, "Clamp", "IF v > 100 THEN"))
        .expect("set");
    let seen = run(&mut engine, vec![Then::Continue], 1);
    assert_eq!(seen.len(), 1, "{seen:#?}");
    assert_eq!(seen[0].reason, HaltReason::Breakpoint(id));
    assert_eq!(
        seen[0].frames,
        vec![
            at("Clamp", "IF v > 100 THEN"),
            at("Main", "r := Clamp(r) + 1;")
        ]
    );
}

#[test]
fn step_out_of_a_function_lands_at_the_plain_callers_next_statement() {
    let (mut engine, image) = engine();
    engine
        .view()
        .set_breakpoint(spec(&image, "Clamp", "IF v > 100 THEN"))
        .expect("set");
    let seen = run(
        &mut engine,
        vec![Then::Step(StepKind::Out), Then::Continue],
        1,
    );
    let frames: Vec<_> = seen.iter().map(|s| s.frames.clone()).collect();
    assert_eq!(
        frames,
        vec![
            vec![
                at("Clamp", "IF v > 100 THEN"),
                at("Main", "r := Clamp(r) + 1;")
            ],
            vec![at("Main", "n := n + 0;")],
        ]
    );
    assert_eq!(seen[1].reason, HaltReason::Step);
}

#[test]
fn step_over_the_last_statement_of_a_function_lands_in_the_caller_which_then_steps_into() {
    let (mut engine, image) = engine();
    engine
        .view()
        .set_breakpoint(spec(&image, "Tick", "Tick := v + 1;"))
        .expect("set");
    let seen = run(
        &mut engine,
        vec![
            Then::Step(StepKind::Over),
            Then::Step(StepKind::Into),
            Then::Continue,
        ],
        1,
    );
    let frames: Vec<_> = seen.iter().map(|s| s.frames.clone()).collect();
    assert_eq!(
        frames,
        vec![
            vec![at("Tick", "Tick := v + 1;"), at("Main", "r := Tick(n);")],
            vec![at("Main", "r := Clamp(r) + 1;")],
            vec![
                at("Clamp", "IF v > 100 THEN"),
                at("Main", "r := Clamp(r) + 1;")
            ],
        ]
    );
}

#[test]
fn flow_recording_of_a_function_marks_its_branch_while_its_caller_runs_light() {
    let (mut engine, image) = engine();
    let clamp = statement(&image, "Clamp", line("IF v > 100 THEN")).0;
    engine
        .debug_mut()
        .configure_flow(0, &[(clamp, 0)])
        .expect("configured");
    let seen = run(&mut engine, Vec::new(), 2);
    assert!(seen.is_empty(), "nothing halts: {seen:#?}");
    let (task, track) = engine.debug().flow().entry(0).expect("recording");
    assert_eq!(task, 0);
    assert_eq!(track.last_cycle, 2);
    // The line-table entries whose bits are set: n is small, so the ELSE branch ran.
    let lines = &image.pous[clamp as usize].lines;
    let ran: Vec<u32> = (0..lines.len())
        .filter(|&entry| track.last[entry / 8] & (1 << (entry % 8)) != 0)
        .map(|entry| lines[entry].line)
        .collect();
    assert!(ran.contains(&line("IF v > 100 THEN")), "{ran:?}");
    assert!(ran.contains(&line("Clamp := v;")), "{ran:?}");
    assert!(!ran.contains(&line("Clamp := 100;")), "{ran:?}");
}

#[test]
fn a_breakpoint_set_during_a_halt_halts_at_its_functions_next_call_in_the_same_cycle() {
    let (mut engine, image) = engine();
    engine
        .view()
        .set_breakpoint(spec(&image, "Tick", "Tick := v + 1;"))
        .expect("set");
    let later = spec(&image, "Clamp", "IF v > 100 THEN");
    let seen = run(&mut engine, vec![Then::Set(later), Then::Continue], 1);
    let frames: Vec<_> = seen.iter().map(|s| s.frames.clone()).collect();
    assert_eq!(
        frames,
        vec![
            vec![at("Tick", "Tick := v + 1;"), at("Main", "r := Tick(n);")],
            vec![
                at("Clamp", "IF v > 100 THEN"),
                at("Main", "r := Clamp(r) + 1;")
            ],
        ]
    );
    assert!(matches!(seen[1].reason, HaltReason::Breakpoint(_)));
}

/// Task 1's halts: what task 0, waiting beneath, shows then.
struct Urgent {
    /// Task 0's stack at each halt, innermost first: POU name and instruction.
    waiting: Vec<Vec<(String, u32)>>,
}

impl Preempt for Urgent {
    fn preempt(&mut self, _engine: EngineView<'_>) {}

    fn halt(&mut self, mut engine: EngineView<'_>, task: usize) {
        assert_eq!(task, 1);
        let image = engine.image().clone();
        let debug = engine.debug();
        assert!(debug.waiting(0), "task 0 waits beneath task 1");
        let state = debug.task(0).expect("task 0 exists");
        self.waiting.push(
            state
                .stack()
                .map(|frame| {
                    (
                        image.pous[frame.pou as usize].name.clone(),
                        frame.instruction,
                    )
                })
                .collect(),
        );
        engine.debug_mut().continue_task(1).expect("it goes on");
    }
}

/// Task 0's interruptions: once it is in `Sum`, task 1's cycle runs on top of it.
struct Interrupts<'a> {
    due: &'a AtomicBool,
    urgent: Urgent,
}

impl Preempt for Interrupts<'_> {
    fn preempt(&mut self, mut engine: EngineView<'_>) {
        let image = engine.image().clone();
        let in_sum = engine
            .debug()
            .task(0)
            .and_then(|state| state.stack().next())
            .is_some_and(|top| image.pous[top.pou as usize].name == "Sum");
        if !in_sum {
            return;
        }
        self.due.store(false, std::sync::atomic::Ordering::Relaxed);
        let never = AtomicBool::new(false);
        let preemption = Preemption {
            due: &never,
            hook: &mut self.urgent,
        };
        engine
            .run_cycle(1, 0, TaskClock::Simulated, 0, Some(preemption))
            .expect("no fault");
    }
}

#[test]
fn a_task_waiting_beneath_a_halted_task_of_higher_priority_shows_its_whole_stack() {
    let mut image = compile(SOURCE);
    // A second task, of higher priority, runs the same program.
    let mut urgent = image.tasks[0].clone();
    urgent.name = "Urgent".to_owned();
    urgent.priority = image.tasks[0].priority.saturating_sub(1);
    image.tasks[0].priority = urgent.priority + 1;
    image.tasks.push(urgent);
    let mut engine = Engine::new(image.clone()).expect("the image loads");
    engine.debug_mut().begin_session();
    // Only task 1 halts there: task 0 keeps its stack because task 1 may halt above it.
    let mut only_urgent = spec(&image, "Tick", "Tick := v + 1;");
    only_urgent.task = Some(1);
    engine.view().set_breakpoint(only_urgent).expect("set");
    // Task 0 is due to be interrupted at every safe point until it is in `Sum`'s loop.
    let due = AtomicBool::new(true);
    let mut interrupts = Interrupts {
        due: &due,
        urgent: Urgent {
            waiting: Vec::new(),
        },
    };
    let preemption = Preemption {
        due: &due,
        hook: &mut interrupts,
    };
    engine
        .view()
        .run_cycle(0, 0, TaskClock::Simulated, 0, Some(preemption))
        .expect("no fault");
    let waiting = &interrupts.urgent.waiting;
    assert_eq!(waiting.len(), 1, "{waiting:?}");
    let names: Vec<&str> = waiting[0].iter().map(|(name, _)| name.as_str()).collect();
    assert_eq!(names, ["Sum", "Main"]);
    let sum = statement(&image, "Sum", line("Sum := 0;")).0 as usize;
    let main = statement(&image, "Main", line("r := Sum(r);"));
    // Sum stands at the backward jump where it was interrupted, Main at its call of Sum.
    assert!(matches!(
        image.pous[sum].code[waiting[0][0].1 as usize],
        Instr::Jump { .. } | Instr::JumpIf { .. } | Instr::JumpIfNot { .. }
    ));
    assert_eq!(
        line_of(&image, main.0, waiting[0][1].1),
        line("r := Sum(r);")
    );
    assert!(matches!(
        image.pous[main.0 as usize].code[waiting[0][1].1 as usize],
        Instr::CallFunction { .. }
    ));
}
