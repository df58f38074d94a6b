//! The engine's debugger on compiled programs: breakpoints with their filters, conditions and
//! hit counts, the shadow call stack, and stepping into, over and out of functions and
//! methods (`docs/protocol.md` §6, `docs/debugging.md` §2–§4). A test hook stands in for the
//! scheduler: at each halt it notes where the task is and what it sees, then does the next
//! thing its script says.

use std::sync::atomic::AtomicBool;

use program_image::ProgramImage;
use runtime::engine::{
    BreakpointSpec, Engine, EngineChoice, EngineView, HaltReason, HitMode, Preempt, Preemption,
    StepKind, TaskClock,
};

use super::compile;

mod forms;
mod motion;
mod sfc;

const SOURCE: &str = "
FUNCTION Twice : INT
VAR_INPUT v : INT; END_VAR
Twice := v * 2;
END_FUNCTION

FUNCTION_BLOCK Counter
VAR_INPUT step : INT; END_VAR
VAR count : INT; END_VAR
count := count + step;
count := Twice(count) / 2;
Bump(amount := 0);
METHOD Bump : INT
VAR_INPUT amount : INT; END_VAR
count := count + amount;
Bump := count;
END_METHOD
END_FUNCTION_BLOCK

PROGRAM Main
VAR a : Counter; b : Counter; n : INT; END_VAR
a(step := 1);
b(step := 10);
n := n + 1;
END_PROGRAM
";

/// What the hook does when the task halts.
#[derive(Clone, Copy, Debug)]
enum Action {
    Step(StepKind),
    Continue,
}

/// Where a halt happened, as a user sees it.
#[derive(Clone, Debug, PartialEq)]
struct Seen {
    reason: HaltReason,
    /// The stack innermost first: POU name, source line, instance path.
    stack: Vec<(String, u32, Option<String>)>,
    /// `Main.n` at the halt.
    n: String,
}

struct Script {
    actions: Vec<Action>,
    seen: Vec<Seen>,
}

impl Preempt for Script {
    fn preempt(&mut self, _engine: EngineView<'_>) {}

    fn halt(&mut self, mut engine: EngineView<'_>, task: usize) {
        let image = engine.image().clone();
        let state = engine.debug().task(task).expect("the task exists");
        let halt = *state.halt().expect("the task is halted");
        let stack = state
            .stack()
            .map(|frame| {
                let pou = &image.pous[frame.pou as usize];
                let owner = pou.name.split('.').next().map(str::to_owned);
                let pointer = engine.pointer_value(task, frame.instance);
                (
                    pou.name.clone(),
                    line_of(&image, frame.pou, frame.instruction),
                    image.instance_path(pointer, owner.as_deref()),
                )
            })
            .collect::<Vec<_>>();
        assert_eq!(stack.len(), usize::from(halt.depth));
        let n = read_n(&image, &engine);
        self.seen.push(Seen {
            reason: halt.reason,
            stack,
            n,
        });
        let debug = engine.debug_mut();
        match self.actions.first().copied() {
            Some(Action::Step(kind)) => debug.step(task, kind).expect("the task steps"),
            Some(Action::Continue) | None => debug.continue_task(task).expect("it goes on"),
        }
        if !self.actions.is_empty() {
            self.actions.remove(0);
        }
    }
}

fn read_n(image: &ProgramImage, engine: &EngineView<'_>) -> String {
    let place = image
        .symbols
        .iter()
        .find(|s| s.path.eq_ignore_ascii_case("Main.n"))
        .expect("Main.n has a symbol");
    let data = engine.region(program_image::Region::Data);
    let at = place.offset as usize;
    i16::from_le_bytes([data[at], data[at + 1]]).to_string()
}

/// The source line of the statement that instruction `instruction` of POU `pou` is in.
fn line_of(image: &ProgramImage, pou: u32, instruction: u32) -> u32 {
    image.pous[pou as usize]
        .lines
        .iter()
        .take_while(|entry| entry.index <= instruction)
        .last()
        .map_or(0, |entry| entry.line)
}

/// The POU named `name` and the first statement start on source line `line`.
fn statement(image: &ProgramImage, name: &str, line: u32) -> (u32, u32) {
    let pou = image
        .pous
        .iter()
        .position(|p| p.name.eq_ignore_ascii_case(name))
        .unwrap_or_else(|| panic!("no POU {name}"));
    let entry = image.pous[pou]
        .lines
        .iter()
        .find(|entry| entry.line == line)
        .unwrap_or_else(|| panic!("no statement on line {line} of {name}"));
    (pou as u32, entry.index)
}

/// The source line where `text` starts in [`SOURCE`].
fn line(text: &str) -> u32 {
    line_in(SOURCE, text)
}

/// The line (from 1) where `text` starts in `source`.
fn line_in(source: &str, text: &str) -> u32 {
    let at = source
        .find(text)
        .unwrap_or_else(|| panic!("{text} is not in the source"));
    source[..at].lines().count() as u32 + u32::from(source[..at].ends_with('\n'))
}

/// A breakpoint, halting always, on the statement of `pou` that starts with `text` in
/// [`SOURCE`].
fn spec(image: &ProgramImage, pou: &str, text: &str) -> BreakpointSpec {
    spec_at(image, pou, line(text))
}

/// A breakpoint, halting always, on the first statement start of `pou` on source line `line`.
fn spec_at(image: &ProgramImage, pou: &str, line: u32) -> BreakpointSpec {
    let (pou, instruction) = statement(image, pou, line);
    BreakpointSpec {
        pou,
        instruction,
        instance: 0,
        task: None,
        hit_mode: HitMode::Always,
        hit_target: 0,
        condition: Vec::new(),
    }
}

/// The instance pointer value of `path`.
fn instance(image: &ProgramImage, path: &str) -> u64 {
    let symbol = image
        .symbols
        .iter()
        .find(|s| s.path.eq_ignore_ascii_case(path))
        .unwrap_or_else(|| panic!("no symbol {path}"));
    (1u64 << 56) | u64::from(symbol.offset)
}

fn run_cycles(engine: &mut Engine, script: &mut Script, cycles: u64) {
    let due = AtomicBool::new(false);
    for cycle in 0..cycles {
        let preemption = Preemption {
            due: &due,
            hook: script,
        };
        engine
            .view()
            .run_cycle(0, 0, TaskClock::Simulated, cycle, Some(preemption))
            .expect("no fault");
    }
}

fn engine() -> (Engine, ProgramImage) {
    let image = compile(SOURCE);
    let mut engine = Engine::new(image.clone()).expect("the image loads");
    engine.debug_mut().begin_session();
    (engine, image)
}

fn frames(seen: &Seen) -> Vec<(&str, u32)> {
    seen.stack
        .iter()
        .map(|(pou, line, _)| (pou.as_str(), *line))
        .collect()
}

#[test]
fn a_breakpoint_in_one_instance_halts_there_with_the_right_stack() {
    let (mut engine, image) = engine();
    let mut breakpoint = spec(&image, "Counter", "count := count + step;");
    breakpoint.instance = instance(&image, "Main.b");
    let (id, replaced) = engine
        .view()
        .set_breakpoint(breakpoint)
        .expect("the breakpoint is set");
    assert!(!replaced);
    let mut script = Script {
        actions: Vec::new(),
        seen: Vec::new(),
    };
    run_cycles(&mut engine, &mut script, 2);
    assert_eq!(script.seen.len(), 2, "{:#?}", script.seen);
    let first = &script.seen[0];
    assert_eq!(first.reason, HaltReason::Breakpoint(id));
    assert_eq!(
        frames(first),
        vec![
            ("Counter", line("count := count + step;")),
            ("Main", line("b(step := 10);"))
        ]
    );
    assert_eq!(first.stack[0].2.as_deref(), Some("Main.b"));
    // Halted before `n := n + 1` of the first cycle; the second halt sees the first cycle's.
    assert_eq!((first.n.as_str(), script.seen[1].n.as_str()), ("0", "1"));
    assert_eq!(engine.debug().breakpoints()[0].hits, 2);
    assert!(engine.debug().halted().is_empty());
}

#[test]
fn a_conditional_breakpoint_with_a_hit_count_halts_on_the_hit_it_names() {
    let (mut engine, image) = engine();
    let project = compiler::SourceProject::new(SOURCE);
    let condition =
        compiler::compile_source_condition(&project, "test.st", "Counter", "count >= 20")
            .expect("the condition compiles");
    let mut breakpoint = spec(&image, "Counter", "count := count + step;");
    breakpoint.condition = condition.condition.encode();
    // Before the statement in cycle k (from 0), Main.a's count is k and Main.b's 10 k: the
    // hits are Main.b's in cycles 2, 3, 4 and 5, and the third halts, with n = 4 done.
    breakpoint.hit_mode = HitMode::Equal;
    breakpoint.hit_target = 3;
    engine.view().set_breakpoint(breakpoint).expect("set");
    let mut script = Script {
        actions: Vec::new(),
        seen: Vec::new(),
    };
    run_cycles(&mut engine, &mut script, 6);
    assert_eq!(script.seen.len(), 1, "{:#?}", script.seen);
    assert_eq!(script.seen[0].stack[0].2.as_deref(), Some("Main.b"));
    assert_eq!(script.seen[0].n, "4");
    assert_eq!(engine.debug().breakpoints()[0].hits, 4);
}

#[test]
fn a_faulting_condition_halts_with_its_own_reason_and_no_fault() {
    let source = "PROGRAM Main VAR a : ARRAY[0..3] OF INT; i : INT := 7; n : INT; END_VAR
n := n + 1;
END_PROGRAM";
    let image = compile(source);
    let project = compiler::SourceProject::new(source);
    let condition = compiler::compile_source_condition(&project, "test.st", "Main", "a[i] = 0")
        .expect("the condition compiles");
    let mut engine = Engine::new(image.clone()).expect("loads");
    engine.debug_mut().begin_session();
    let (pou, instruction) = statement(&image, "Main", 2);
    let (id, _) = engine
        .view()
        .set_breakpoint(BreakpointSpec {
            pou,
            instruction,
            instance: 0,
            task: None,
            hit_mode: HitMode::Always,
            hit_target: 0,
            condition: condition.condition.encode(),
        })
        .expect("set");
    let mut script = Script {
        actions: Vec::new(),
        seen: Vec::new(),
    };
    run_cycles(&mut engine, &mut script, 1);
    assert_eq!(script.seen[0].reason, HaltReason::ConditionFaulted(id));
}

#[test]
fn steps_go_into_over_and_out_of_a_function_and_a_method() {
    let (mut engine, image) = engine();
    let mut breakpoint = spec(&image, "Counter", "count := Twice(count) / 2;");
    breakpoint.instance = instance(&image, "Main.a");
    let (id, _) = engine.view().set_breakpoint(breakpoint).expect("set");
    let mut script = Script {
        actions: vec![
            Action::Step(StepKind::Into),
            Action::Step(StepKind::Out),
            Action::Step(StepKind::Into),
            Action::Step(StepKind::Over),
            Action::Step(StepKind::Out),
            Action::Step(StepKind::Over),
            Action::Step(StepKind::Out),
            Action::Continue,
        ],
        seen: Vec::new(),
    };
    run_cycles(&mut engine, &mut script, 2);
    let seen: Vec<Vec<(&str, u32)>> = script.seen.iter().map(frames).collect();
    let main_a = ("Main", line("a(step := 1);"));
    let main_b = ("Main", line("b(step := 10);"));
    let main_n = ("Main", line("n := n + 1;"));
    let twice_call = ("Counter", line("count := Twice(count) / 2;"));
    let bump_call = ("Counter", line("Bump(amount := 0);"));
    let bump = |text| ("Counter.Bump", line(text));
    assert_eq!(
        seen,
        vec![
            // The breakpoint; step into the function.
            vec![twice_call, main_a],
            // In the function; step out.
            vec![("Twice", line("Twice := v * 2;")), twice_call, main_a],
            // In the caller after the call: the method's call; step into.
            vec![bump_call, main_a],
            // In the method; step over.
            vec![bump("count := count + amount;"), bump_call, main_a],
            // Its next statement; step out.
            vec![bump("Bump := count;"), bump_call, main_a],
            // The block's body has nothing after the call: the program's next; step over.
            vec![main_b],
            // Main.b's body ran whole; step out of the program's body.
            vec![main_n],
            // The first statement of the next cycle's program; continue.
            vec![main_a],
            // The breakpoint again.
            vec![twice_call, main_a],
        ],
        "{:#?}",
        script.seen
    );
    assert_eq!(script.seen[3].stack[0].2.as_deref(), Some("Main.a"));
    assert_eq!(script.seen[8].reason, HaltReason::Breakpoint(id));
    assert_eq!(script.seen[1].reason, HaltReason::Step);
}

#[test]
fn breakpoints_are_refused_off_statements_and_replaced_in_place_with_new_ids() {
    let (mut engine, image) = engine();
    let good = spec(&image, "Counter", "count := count + step;");
    let mut off = good.clone();
    off.instruction = 9999;
    let error = engine.view().set_breakpoint(off).expect_err("not a start");
    assert_eq!(
        error.to_string(),
        format!("instruction {} of POU 'Counter' starts no statement", 9999)
    );
    let mut no_target = good.clone();
    no_target.hit_mode = HitMode::Multiple;
    assert!(engine.view().set_breakpoint(no_target).is_err());
    let mut bad_condition = good.clone();
    bad_condition.condition = vec![0xFF, 0xFF, 0xFF];
    let error = engine
        .view()
        .set_breakpoint(bad_condition)
        .expect_err("no condition");
    assert!(error.to_string().contains("does not decode"), "{error}");
    let (first, replaced) = engine.view().set_breakpoint(good.clone()).expect("set");
    assert!(!replaced);
    let (second, replaced) = engine.view().set_breakpoint(good.clone()).expect("set");
    assert!(replaced);
    assert_ne!(first, second);
    assert_eq!(engine.debug().breakpoints().len(), 1);
    engine
        .debug_mut()
        .clear_breakpoint(second)
        .expect("cleared");
    assert!(engine.debug_mut().clear_breakpoint(second).is_err());
    for _ in 0..runtime::engine::MAX_BREAKPOINTS {
        let mut next = good.clone();
        next.instance =
            instance(&image, "Main.a") + u64::from(engine.debug().breakpoints().len() as u32) + 1;
        engine.view().set_breakpoint(next).expect("room");
    }
    let mut one_more = good;
    one_more.instance = 7;
    assert!(engine.view().set_breakpoint(one_more).is_err());
}

#[test]
fn only_the_halted_task_may_step_and_ending_the_session_lets_it_go_on() {
    let (mut engine, image) = engine();
    engine
        .view()
        .set_breakpoint(spec(&image, "Main", "n := n + 1;"))
        .expect("set");
    let error = engine
        .debug_mut()
        .step(0, StepKind::Over)
        .expect_err("not halted");
    assert_eq!(error.to_string(), "task 'MainTask' is not halted");
    struct EndsSession(u32);
    impl Preempt for EndsSession {
        fn preempt(&mut self, _engine: EngineView<'_>) {}
        fn halt(&mut self, mut engine: EngineView<'_>, task: usize) {
            self.0 += 1;
            assert!(engine.debug().is_halted(task));
            assert_eq!(engine.debug().halted(), &[task]);
            engine.debug_mut().end_session();
        }
    }
    let mut hook = EndsSession(0);
    let due = AtomicBool::new(false);
    for cycle in 0..3 {
        engine
            .view()
            .run_cycle(
                0,
                0,
                TaskClock::Simulated,
                cycle,
                Some(Preemption {
                    due: &due,
                    hook: &mut hook,
                }),
            )
            .expect("no fault");
    }
    // The session ended at the first halt: its breakpoint went with it, the cycles ran on.
    assert_eq!(hook.0, 1);
    assert!(engine.debug().breakpoints().is_empty());
    assert!(!engine.debug().active());
    assert_eq!(
        runtime::value::read(&engine, "Main.n")
            .expect("n")
            .to_string(),
        "3"
    );
}

#[test]
fn a_cycle_without_the_debugger_runs_natively_and_one_with_a_breakpoint_in_the_interpreter() {
    let image = compile(SOURCE);
    let (mut engine, report) =
        Engine::with_choice(image.clone(), EngineChoice::Native).expect("the image loads");
    if !EngineChoice::native_available() {
        // Nothing runs natively on this machine: every cycle is the interpreter's.
        assert!(!report.runs_natively());
        return;
    }
    assert!(
        report.runs_natively() && report.fallbacks.is_empty(),
        "{report:?}"
    );
    let mut script = Script {
        actions: Vec::new(),
        seen: Vec::new(),
    };
    run_cycles(&mut engine, &mut script, 2);
    let native = engine.native_entries();
    assert!(native > 0, "no cycle entered generated code");
    // With a breakpoint the debugger watches the cycle: it runs entirely in the interpreter,
    // and sees what the native cycles before it left.
    engine.debug_mut().begin_session();
    engine
        .view()
        .set_breakpoint(spec(&image, "Main", "n := n + 1;"))
        .expect("the breakpoint is set");
    run_cycles(&mut engine, &mut script, 1);
    assert_eq!(engine.native_entries(), native);
    assert_eq!(script.seen.len(), 1, "{:#?}", script.seen);
    assert_eq!(script.seen[0].n, "2");
    // Once the session ends, cycles run natively again.
    engine.debug_mut().end_session();
    run_cycles(&mut engine, &mut script, 1);
    assert!(engine.native_entries() > native);
}
