//! The scan-time workloads shared by the `scan` (criterion) and `scan_report` (table) benches:
//! each is an ST program generated here, compiled and loaded into an engine, and the same
//! computation written in plain Rust as the Rust reference.

use std::hint::black_box;

use program_image::{Instr, ProgramImage};
use runtime::engine::{Engine, EngineChoice};
use runtime::value::{self, Value};

/// Statements per generated program, and iterations of the array loop.
pub const COUNT: usize = 1000;

/// Rounds of the string statements per cycle.
pub const STRING_ROUNDS: usize = 100;

/// One workload: the program and its Rust twin.
pub struct Workload {
    /// A short name for tables and criterion ids.
    pub name: &'static str,
    /// What one unit of work is: a statement, or a loop iteration.
    pub unit: &'static str,
    /// The ST source.
    pub source: String,
    /// Units of work in one cycle.
    pub units: usize,
    /// The Rust reference: one call does what one cycle does.
    pub rust: fn(&mut RustTwin),
    /// A variable whose value after a few cycles the engine and the Rust twin must agree on.
    pub check: &'static str,
}

/// The Rust reference's variables, one field per ST variable.
#[derive(Clone, Debug)]
pub struct RustTwin {
    /// BOOLs `b1` … `b5`.
    pub b: [bool; 5],
    /// DINTs `i1` … `i3`.
    pub i: [i32; 3],
    /// REALs `r1` … `r3`.
    pub r: [f32; 3],
    /// The array `a[1..1000]`.
    pub a: Vec<i32>,
    /// The `Accumulate` instances `f1` … `f4` of the FB calls workload.
    pub blocks: [Accumulate; 4],
    /// The STRING(80) `s` of the strings workload.
    pub s: String,
    /// The STRING(80) `t` of the strings workload.
    pub t: String,
    /// The DINT `n` of the strings workload.
    pub n: i32,
}

/// An instance of the FB calls workload's `Accumulate`.
#[derive(Clone, Copy, Debug)]
pub struct Accumulate {
    /// `VAR_INPUT in1`.
    pub in1: i32,
    /// `VAR_INPUT in2`.
    pub in2: i32,
    /// `VAR_OUTPUT q`, which the block also keeps as its state.
    pub q: i32,
    /// `VAR lim`, the bound above which `q` starts again from 0.
    pub lim: i32,
}

impl Accumulate {
    const NEW: Self = Self {
        in1: 0,
        in2: 0,
        q: 0,
        lim: 1_000_000,
    };

    /// `q := q + in1 * in2; IF q > lim THEN q := 0; END_IF`, wrapping as DINT does.
    fn call(&mut self) {
        self.q = self.q.wrapping_add(self.in1.wrapping_mul(self.in2));
        if self.q > self.lim {
            self.q = 0;
        }
    }
}

impl Default for RustTwin {
    fn default() -> Self {
        Self {
            b: [true, false, false, false, false],
            i: [1, 2, 0],
            r: [1.0, 2.0, 0.0],
            a: vec![0; COUNT],
            blocks: [Accumulate::NEW; 4],
            s: String::new(),
            t: STRING_T.to_owned(),
            n: 0,
        }
    }
}

const DECLARATIONS: &str = "\
PROGRAM main
VAR
    b1 : BOOL := TRUE;
    b2, b3, b4, b5 : BOOL;
    i1 : DINT := 1;
    i2 : DINT := 2;
    i3 : DINT;
    r1 : REAL := 1.0;
    r2 : REAL := 2.0;
    r3 : REAL;
    i : DINT;
    a : ARRAY[1..1000] OF DINT;
END_VAR
";

/// The BOOL statements, repeated in turn; `rust_bool` does the same in Rust.
const BOOL_STATEMENTS: [&str; 4] = [
    "b3 := b1 AND NOT b2;",
    "b4 := b3 OR b2;",
    "b5 := b4 XOR b1;",
    "b2 := b5 AND b3;",
];

const INT_STATEMENTS: [&str; 4] = [
    "i3 := i1 + i2;",
    "i2 := i3 - 7;",
    "i1 := i2 + i3;",
    "i3 := i3 - i1;",
];

const REAL_STATEMENTS: [&str; 4] = [
    "r3 := r1 * 1.5 + r2;",
    "r1 := r3 * 0.25 - r2;",
    "r2 := r1 * 0.5 + 0.125;",
    "r3 := r3 - r1;",
];

/// The function block of the FB calls workload, and the program calling it: two inputs, an
/// output and a state, as `docs/native-engine.md` §11.3 describes it.
const FB_DECLARATIONS: &str = "\
FUNCTION_BLOCK Accumulate
VAR_INPUT
    in1 : DINT;
    in2 : DINT;
END_VAR
VAR_OUTPUT
    q : DINT;
END_VAR
VAR
    lim : DINT := 1000000;
END_VAR
q := q + in1 * in2;
IF q > lim THEN
    q := 0;
END_IF
END_FUNCTION_BLOCK

PROGRAM main
VAR
    f1, f2, f3, f4 : Accumulate;
    i1 : DINT := 1;
    i2 : DINT := 2;
    i3 : DINT;
END_VAR
";

/// The calls, repeated in turn; `rust_fb_calls` does the same in Rust.
const FB_CALL_STATEMENTS: [&str; 4] = [
    "f1(in1 := i1, in2 := 3, q => i2);",
    "f2(in1 := i2, in2 := 5, q => i3);",
    "f3(in1 := i3, in2 := -7, q => i1);",
    "f4(in1 := i1, in2 := i2, q => i3);",
];

/// The initial value of the strings workload's `t`: its first five characters hold a '1', so
/// every round's FIND finds one and `n` moves on.
const STRING_T: &str = "Cell1 packaging line";

/// One round of the strings workload; `rust_strings` does the same in Rust.
const STRING_STATEMENTS: [&str; 2] = [
    "s := CONCAT(LEFT(t, 5), DINT_TO_STRING(n));",
    "n := n + FIND(s, '1');",
];

fn strings_program() -> String {
    let mut source = format!(
        "PROGRAM main\nVAR\n    s : STRING(80);\n    t : STRING(80) := '{STRING_T}';\n    n : DINT;\nEND_VAR\n"
    );
    for _ in 0..STRING_ROUNDS {
        for line in STRING_STATEMENTS {
            source.push_str(line);
            source.push('\n');
        }
    }
    source.push_str("END_PROGRAM\n");
    source
}

fn program(statements: &[&str]) -> String {
    program_with(DECLARATIONS, statements)
}

/// `declarations`, then `COUNT` statements taken from `statements` in turn.
fn program_with(declarations: &str, statements: &[&str]) -> String {
    let mut source = String::from(declarations);
    for line in statements.iter().cycle().take(COUNT) {
        source.push_str(line);
        source.push('\n');
    }
    source.push_str("END_PROGRAM\n");
    source
}

fn rust_bool(n: &mut RustTwin) {
    for _ in 0..COUNT / 4 {
        let b = black_box(&mut n.b);
        b[2] = b[0] & !b[1];
        b[3] = b[2] | b[1];
        b[4] = b[3] ^ b[0];
        b[1] = b[4] & b[2];
    }
}

fn rust_int(n: &mut RustTwin) {
    for _ in 0..COUNT / 4 {
        let i = black_box(&mut n.i);
        i[2] = i[0].wrapping_add(i[1]);
        i[1] = i[2].wrapping_sub(7);
        i[0] = i[1].wrapping_add(i[2]);
        i[2] = i[2].wrapping_sub(i[0]);
    }
}

fn rust_real(n: &mut RustTwin) {
    for _ in 0..COUNT / 4 {
        let r = black_box(&mut n.r);
        r[2] = r[0] * 1.5 + r[1];
        r[0] = r[2] * 0.25 - r[1];
        r[1] = r[0] * 0.5 + 0.125;
        r[2] -= r[0];
    }
}

fn rust_fb_calls(n: &mut RustTwin) {
    for _ in 0..COUNT / 4 {
        let (i, f) = black_box((&mut n.i, &mut n.blocks));
        f[0].in1 = i[0];
        f[0].in2 = 3;
        f[0].call();
        i[1] = f[0].q;
        f[1].in1 = i[1];
        f[1].in2 = 5;
        f[1].call();
        i[2] = f[1].q;
        f[2].in1 = i[2];
        f[2].in2 = -7;
        f[2].call();
        i[0] = f[2].q;
        f[3].in1 = i[0];
        f[3].in2 = i[1];
        f[3].call();
        i[2] = f[3].q;
    }
}

/// The characters a STRING(80) holds: CONCAT's result is cut to them.
const STRING_CAPACITY: usize = 80;

fn rust_strings(n: &mut RustTwin) {
    for _ in 0..STRING_ROUNDS {
        let state = black_box(&mut *n);
        // The workload's strings are ASCII, so characters and bytes are the same.
        let head: String = state.t.chars().take(5).collect();
        let mut s = head + &state.n.to_string();
        s.truncate(STRING_CAPACITY);
        let found = s.find('1').map_or(0, |at| at as i32 + 1);
        state.s = s;
        state.n = state.n.wrapping_add(found);
    }
}

fn rust_array(n: &mut RustTwin) {
    let a = black_box(&mut n.a);
    for (index, element) in a.iter_mut().enumerate() {
        *element = element.wrapping_add(index as i32 + 1);
    }
}

/// A ring of `COUNT` steps, the one in the middle active, each step's action counting into
/// `n`; the transitions' condition stays FALSE. An SFC must cost only what its active step
/// does, not what its 1,000 steps hold.
fn sfc_chart() -> String {
    let mut source = String::from("PROGRAM main\nVAR\n    n : DINT;\n    go : BOOL;\nEND_VAR\n");
    for step in 1..=COUNT {
        let keyword = if step == COUNT / 2 {
            "INITIAL_STEP"
        } else {
            "STEP"
        };
        let next = step % COUNT + 1;
        source.push_str(&format!(
            "{keyword} S{step}: A{step}(N); END_STEP\nTRANSITION FROM S{step} TO S{next} := go; END_TRANSITION\n"
        ));
    }
    for step in 1..=COUNT {
        source.push_str(&format!("ACTION A{step}: n := n + 1; END_ACTION\n"));
    }
    source.push_str("END_PROGRAM\n");
    source
}

/// The same sequence as [`sfc_chart`] written as the CASE state machine a user would write
/// in ST: the reference the chart is measured against.
fn case_machine() -> String {
    let mut source = format!(
        "PROGRAM main\nVAR\n    n : DINT;\n    go : BOOL;\n    state : DINT := {};\nEND_VAR\nCASE state OF\n",
        COUNT / 2
    );
    for step in 1..=COUNT {
        let next = step % COUNT + 1;
        source.push_str(&format!(
            "{step}: n := n + 1; IF go THEN state := {next}; END_IF\n"
        ));
    }
    source.push_str("END_CASE\nEND_PROGRAM\n");
    source
}

fn rust_step(n: &mut RustTwin) {
    let i = black_box(&mut n.i);
    i[0] = i[0].wrapping_add(1);
}

fn rust_empty(n: &mut RustTwin) {
    black_box(n);
}

/// Every workload, the empty program first (the fixed cost of a cycle).
pub fn workloads() -> Vec<Workload> {
    vec![
        Workload {
            name: "empty",
            unit: "cycle",
            source: format!("{DECLARATIONS}END_PROGRAM\n"),
            units: 1,
            rust: rust_empty,
            check: "main.b1",
        },
        Workload {
            name: "bool",
            unit: "statement",
            source: program(&BOOL_STATEMENTS),
            units: COUNT,
            rust: rust_bool,
            // b4 turns TRUE in the first round; b2 stays FALSE throughout, and would pass for
            // a twin that does nothing.
            check: "main.b4",
        },
        Workload {
            name: "dint",
            unit: "statement",
            source: program(&INT_STATEMENTS),
            units: COUNT,
            rust: rust_int,
            check: "main.i3",
        },
        Workload {
            name: "real",
            unit: "statement",
            source: program(&REAL_STATEMENTS),
            units: COUNT,
            rust: rust_real,
            check: "main.r3",
        },
        Workload {
            name: "array_loop",
            unit: "iteration",
            source: format!(
                "{DECLARATIONS}FOR i := 1 TO {COUNT} DO\n    a[i] := a[i] + i;\nEND_FOR\nEND_PROGRAM\n"
            ),
            units: COUNT,
            rust: rust_array,
            check: "main.a[1000]",
        },
        Workload {
            name: "fb_calls",
            unit: "call",
            source: program_with(FB_DECLARATIONS, &FB_CALL_STATEMENTS),
            units: COUNT,
            rust: rust_fb_calls,
            check: "main.i3",
        },
        Workload {
            name: "strings",
            unit: "round",
            source: strings_program(),
            units: STRING_ROUNDS,
            rust: rust_strings,
            check: "main.n",
        },
        Workload {
            name: "sfc_1000_steps",
            unit: "cycle",
            source: sfc_chart(),
            units: 1,
            rust: rust_step,
            check: "main.n",
        },
        Workload {
            name: "case_1000_states",
            unit: "cycle",
            source: case_machine(),
            units: 1,
            rust: rust_step,
            check: "main.n",
        },
    ]
}

/// The value of the checked variable in the Rust twin.
fn rust_value(workload: &Workload, n: &RustTwin) -> Value {
    use program_image::Elementary as E;
    match workload.name {
        "bool" => Value::Bool(n.b[3]),
        "dint" => Value::Int(i128::from(n.i[2]), E::Dint),
        "real" => Value::Real(f64::from(n.r[2]), E::Real),
        "array_loop" => Value::Int(i128::from(n.a[COUNT - 1]), E::Dint),
        "fb_calls" => Value::Int(i128::from(n.i[2]), E::Dint),
        "strings" => Value::Int(i128::from(n.n), E::Dint),
        // The Rust twin's step counter starts from the `i1` of the other workloads.
        "sfc_1000_steps" | "case_1000_states" => Value::Int(i128::from(n.i[0] - 1), E::Dint),
        _ => Value::Bool(n.b[0]),
    }
}

/// The workload compiled to an image.
pub fn compile(workload: &Workload) -> ProgramImage {
    let source = compiler::SourceProject::new(&workload.source);
    match compiler::compile_source(&source, "bench.st") {
        Ok(image) => image,
        Err(error) => panic!("the {} workload does not compile: {error:?}", workload.name),
    }
}

/// The instructions of the program body, without the final `Return`.
pub fn instructions(image: &ProgramImage) -> usize {
    image
        .pous
        .iter()
        .filter(|pou| pou.name.eq_ignore_ascii_case("main"))
        .map(|pou| {
            pou.code
                .iter()
                .filter(|instr| !matches!(instr, Instr::Return))
                .count()
        })
        .sum()
}

/// A loaded interpreter, after checking that a few cycles compute what the Rust twin
/// computes.
pub fn engine(workload: &Workload) -> Engine {
    engine_with(workload, EngineChoice::Interpreter)
}

/// A loaded engine of the kind `choice` names, after checking that a few cycles compute what
/// the Rust twin computes; the native engine must translate every POU.
pub fn engine_with(workload: &Workload, choice: EngineChoice) -> Engine {
    let image = compile(workload);
    let load = |image| match Engine::with_choice(image, choice) {
        Ok((engine, report)) => {
            if choice == EngineChoice::Native
                && EngineChoice::native_available()
                && !(report.runs_natively() && report.fallbacks.is_empty())
            {
                panic!(
                    "the {} workload does not run natively: {}; {:?}",
                    workload.name,
                    report.summary(),
                    report.lines()
                );
            }
            engine
        }
        Err(error) => panic!("the {} workload does not load: {error}", workload.name),
    };
    let mut engine = load(image.clone());
    let mut rust = RustTwin::default();
    for cycle in 0..3 {
        if let Err(fault) = engine.run_cycle(0, 0, cycle) {
            panic!("the {} workload faults: {fault}", workload.name);
        }
        (workload.rust)(&mut rust);
    }
    let engine_value = value::read(&engine, workload.check);
    let rust_value = rust_value(workload, &rust);
    assert_eq!(
        engine_value.as_ref().ok(),
        Some(&rust_value),
        "the engine and the Rust twin of {} disagree",
        workload.name
    );
    let mut fresh = load(image);
    // Warm the engine up so the first measured cycle is like the others.
    for cycle in 0..3 {
        let _ = fresh.run_cycle(0, 0, cycle);
    }
    fresh
}
