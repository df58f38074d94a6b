//! The scan-time workloads shared by the `scan` (criterion) and `scan_report` (table) benches:
//! each is an ST program generated here, compiled and loaded into an engine, and the same
//! computation written in plain Rust as the native reference.

use std::hint::black_box;

use program_image::{Instr, ProgramImage};
use runtime::engine::Engine;
use runtime::value::{self, Value};

/// Statements per generated program, and iterations of the array loop.
pub const COUNT: usize = 1000;

/// One workload: the program and its native twin.
pub struct Workload {
    /// A short name for tables and criterion ids.
    pub name: &'static str,
    /// What one unit of work is: a statement, or a loop iteration.
    pub unit: &'static str,
    /// The ST source.
    pub source: String,
    /// Units of work in one cycle.
    pub units: usize,
    /// The native reference: one call does what one cycle does.
    pub native: fn(&mut Native),
    /// A variable whose value after a few cycles the engine and the native twin must agree on.
    pub check: &'static str,
}

/// The native reference's variables, one field per ST variable.
#[derive(Clone, Debug)]
pub struct Native {
    /// BOOLs `b1` … `b5`.
    pub b: [bool; 5],
    /// DINTs `i1` … `i3`.
    pub i: [i32; 3],
    /// REALs `r1` … `r3`.
    pub r: [f32; 3],
    /// The array `a[1..1000]`.
    pub a: Vec<i32>,
}

impl Default for Native {
    fn default() -> Self {
        Self {
            b: [true, false, false, false, false],
            i: [1, 2, 0],
            r: [1.0, 2.0, 0.0],
            a: vec![0; COUNT],
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

/// The BOOL statements, repeated in turn; `native_bool` does the same in Rust.
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

fn program(statements: &[&str]) -> String {
    let mut source = String::from(DECLARATIONS);
    for line in statements.iter().cycle().take(COUNT) {
        source.push_str(line);
        source.push('\n');
    }
    source.push_str("END_PROGRAM\n");
    source
}

fn native_bool(n: &mut Native) {
    for _ in 0..COUNT / 4 {
        let b = black_box(&mut n.b);
        b[2] = b[0] & !b[1];
        b[3] = b[2] | b[1];
        b[4] = b[3] ^ b[0];
        b[1] = b[4] & b[2];
    }
}

fn native_int(n: &mut Native) {
    for _ in 0..COUNT / 4 {
        let i = black_box(&mut n.i);
        i[2] = i[0].wrapping_add(i[1]);
        i[1] = i[2].wrapping_sub(7);
        i[0] = i[1].wrapping_add(i[2]);
        i[2] = i[2].wrapping_sub(i[0]);
    }
}

fn native_real(n: &mut Native) {
    for _ in 0..COUNT / 4 {
        let r = black_box(&mut n.r);
        r[2] = r[0] * 1.5 + r[1];
        r[0] = r[2] * 0.25 - r[1];
        r[1] = r[0] * 0.5 + 0.125;
        r[2] -= r[0];
    }
}

fn native_array(n: &mut Native) {
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

fn native_step(n: &mut Native) {
    let i = black_box(&mut n.i);
    i[0] = i[0].wrapping_add(1);
}

fn native_empty(n: &mut Native) {
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
            native: native_empty,
            check: "main.b1",
        },
        Workload {
            name: "bool",
            unit: "statement",
            source: program(&BOOL_STATEMENTS),
            units: COUNT,
            native: native_bool,
            check: "main.b2",
        },
        Workload {
            name: "dint",
            unit: "statement",
            source: program(&INT_STATEMENTS),
            units: COUNT,
            native: native_int,
            check: "main.i3",
        },
        Workload {
            name: "real",
            unit: "statement",
            source: program(&REAL_STATEMENTS),
            units: COUNT,
            native: native_real,
            check: "main.r3",
        },
        Workload {
            name: "array_loop",
            unit: "iteration",
            source: format!(
                "{DECLARATIONS}FOR i := 1 TO {COUNT} DO\n    a[i] := a[i] + i;\nEND_FOR\nEND_PROGRAM\n"
            ),
            units: COUNT,
            native: native_array,
            check: "main.a[1000]",
        },
        Workload {
            name: "sfc_1000_steps",
            unit: "cycle",
            source: sfc_chart(),
            units: 1,
            native: native_step,
            check: "main.n",
        },
        Workload {
            name: "case_1000_states",
            unit: "cycle",
            source: case_machine(),
            units: 1,
            native: native_step,
            check: "main.n",
        },
    ]
}

/// The value of the checked variable in the native twin.
fn native_value(workload: &Workload, n: &Native) -> Value {
    use program_image::Elementary as E;
    match workload.name {
        "bool" => Value::Bool(n.b[1]),
        "dint" => Value::Int(i128::from(n.i[2]), E::Dint),
        "real" => Value::Real(f64::from(n.r[2]), E::Real),
        "array_loop" => Value::Int(i128::from(n.a[COUNT - 1]), E::Dint),
        // The native step counter starts from the `i1` of the other workloads.
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

/// A loaded engine, after checking that a few cycles compute what the native twin computes.
pub fn engine(workload: &Workload) -> Engine {
    let image = compile(workload);
    let mut engine = match Engine::new(image.clone()) {
        Ok(engine) => engine,
        Err(error) => panic!("the {} workload does not load: {error}", workload.name),
    };
    let mut native = Native::default();
    for cycle in 0..3 {
        if let Err(fault) = engine.run_cycle(0, 0, cycle) {
            panic!("the {} workload faults: {fault}", workload.name);
        }
        (workload.native)(&mut native);
    }
    let engine_value = value::read(&engine, workload.check);
    let native_value = native_value(workload, &native);
    assert_eq!(
        engine_value.as_ref().ok(),
        Some(&native_value),
        "the engine and the native twin of {} disagree",
        workload.name
    );
    let mut fresh = match Engine::new(image) {
        Ok(engine) => engine,
        Err(error) => panic!("the {} workload does not load: {error}", workload.name),
    };
    // Warm the engine up so the first measured cycle is like the others.
    for cycle in 0..3 {
        let _ = fresh.run_cycle(0, 0, cycle);
    }
    fresh
}
