//! The C twins of the scan workloads and the `SCAN_SECTION=native` table
//! (`docs/native-engine.md` §11.3).
//!
//! Each `<name>.c` beside this file does what one cycle of the workload `<name>` does, on a
//! struct laid out as the program's instance, with ST's semantics kept (wrapping DINTs, strings
//! cut to their capacity), and times itself as `median_ns` times the engines (`timing.h`). The
//! bench compiles every twin twice, with `-O2` and with `-O2 -fno-tree-vectorize` (gcc 12
//! vectorises the array loop at `-O2`; Cranelift does not vectorise), runs it, checks the value
//! it printed against the interpreter's after three cycles, and prints one table with the
//! interpreter's and the native engine's times.

use std::ffi::OsString;
use std::io::ErrorKind;
use std::path::{Path, PathBuf};
use std::process::Command;

use runtime::value::{self, Value};

use runtime::engine::EngineChoice;

use crate::workloads::{compile, engine, engine_with, instructions, workloads};

/// The workloads that have a C twin (`<name>.c` beside this file).
pub const NAMES: [&str; 6] = ["array_loop", "dint", "real", "bool", "fb_calls", "strings"];

/// The workloads whose goal is native ÷ C `-O2` ≤ 2 (§11.3), read against the scalar twin
/// where gcc vectorises (§13, question 1).
const GOAL_WORKLOADS: [&str; 3] = ["array_loop", "dint", "real"];

/// The optimisation flags a twin is built with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Optimisation {
    /// `-O2`, as a C programmer builds.
    O2,
    /// `-O2 -fno-tree-vectorize`: scalar code, what a translator without vectorisation can
    /// be compared with.
    O2Scalar,
}

impl Optimisation {
    /// The compiler's flags. Every build keeps floating-point contraction off: ST has no fused
    /// multiply-add (§6.1), and gcc would fuse `a * b + c` on a machine that has one.
    fn flags(self) -> &'static [&'static str] {
        match self {
            Self::O2 => &["-O2", "-ffp-contract=off"],
            Self::O2Scalar => &["-O2", "-fno-tree-vectorize", "-ffp-contract=off"],
        }
    }

    fn suffix(self) -> &'static str {
        match self {
            Self::O2 => "o2",
            Self::O2Scalar => "o2-scalar",
        }
    }
}

/// What a twin printed.
#[derive(Clone, Copy, Debug)]
pub struct TwinRun {
    /// The median time of one cycle.
    pub ns_per_cycle: f64,
    /// The checked variable after three cycles, as an integer (a BOOL as 0 or 1, a REAL as
    /// its IEEE bits).
    pub check: i64,
}

/// The C compiler and a temporary folder for the twins it builds; the folder goes with it.
pub struct TwinBuilder {
    compiler: OsString,
    folder: tempfile::TempDir,
}

impl TwinBuilder {
    /// The compiler named by `RIVET_CC`, or `gcc`. A compiler that cannot be started stops
    /// the bench with a message saying so.
    pub fn new() -> Self {
        let compiler = std::env::var_os("RIVET_CC").unwrap_or_else(|| OsString::from("gcc"));
        match Command::new(&compiler).arg("--version").output() {
            Ok(output) if output.status.success() => {}
            Ok(output) => stop(&format!(
                "the C compiler {compiler:?} (RIVET_CC, default gcc) fails to run: {}",
                String::from_utf8_lossy(&output.stderr)
            )),
            Err(error) if error.kind() == ErrorKind::NotFound => stop(&format!(
                "the C compiler {compiler:?} was not found: install gcc, or set RIVET_CC to a C compiler"
            )),
            Err(error) => stop(&format!(
                "the C compiler {compiler:?} cannot be started: {error}"
            )),
        }
        let folder = match tempfile::tempdir() {
            Ok(folder) => folder,
            Err(error) => stop(&format!("no temporary folder for the C twins: {error}")),
        };
        Self { compiler, folder }
    }

    /// Builds the twin of workload `name` with `optimisation` and returns the program.
    pub fn build(&self, name: &str, optimisation: Optimisation) -> PathBuf {
        let source = twins_folder().join(format!("{name}.c"));
        let program = self
            .folder
            .path()
            .join(format!("{name}-{}", optimisation.suffix()));
        let output = Command::new(&self.compiler)
            .args(optimisation.flags())
            .arg("-I")
            .arg(twins_folder())
            .arg("-o")
            .arg(&program)
            .arg(&source)
            .output();
        match output {
            Ok(output) if output.status.success() => program,
            Ok(output) => stop(&format!(
                "{} does not compile with {:?} {}:\n{}",
                source.display(),
                self.compiler,
                optimisation.flags().join(" "),
                String::from_utf8_lossy(&output.stderr)
            )),
            Err(error) => stop(&format!("{:?} cannot be started: {error}", self.compiler)),
        }
    }
}

/// Runs a built twin and reads its line of JSON.
pub fn run(program: &Path) -> TwinRun {
    let output = match Command::new(program).output() {
        Ok(output) if output.status.success() => output,
        Ok(output) => stop(&format!("{} failed: {}", program.display(), output.status)),
        Err(error) => stop(&format!("{} cannot be started: {error}", program.display())),
    };
    let text = String::from_utf8_lossy(&output.stdout);
    let line = text.lines().last().unwrap_or_default();
    let json: serde_json::Value = match serde_json::from_str(line) {
        Ok(json) => json,
        Err(error) => stop(&format!(
            "{} printed {line:?}, not a line of JSON: {error}",
            program.display()
        )),
    };
    let (Some(ns_per_cycle), Some(check)) = (json["ns_per_cycle"].as_f64(), json["check"].as_i64())
    else {
        stop(&format!(
            "{} printed {line}, without a number ns_per_cycle and an integer check",
            program.display()
        ))
    };
    TwinRun {
        ns_per_cycle,
        check,
    }
}

/// A checked value as the twins print it: integers as they are, a BOOL as 0 or 1, a REAL as
/// its IEEE bits; `None` for other values.
pub fn as_twin_integer(value: &Value) -> Option<i64> {
    use program_image::Elementary as E;
    match value {
        Value::Bool(b) => Some(i64::from(*b)),
        Value::Int(v, _) => i64::try_from(*v).ok(),
        Value::Real(v, E::Real) => Some(i64::from((*v as f32).to_bits())),
        Value::Real(v, _) => Some(v.to_bits() as i64),
        _ => None,
    }
}

/// The `SCAN_SECTION=native` table: per workload with a twin, the interpreter's, the native
/// engine's and the twins' time per cycle with their ratios and the goal, then per image the
/// bytecode, the native engine's translation time and its code bytes.
pub fn report(median_ns: &dyn Fn(&mut dyn FnMut()) -> f64) {
    let builder = TwinBuilder::new();
    let mut sizes = Vec::new();
    println!(
        "\nNative engine and C twins (ns per cycle; C built with {:?}, RIVET_CC overrides gcc):\n",
        builder.compiler
    );
    println!(
        "| workload | interpreter | native | C -O2 | C -O2 -fno-tree-vectorize | interpreter ÷ C -O2 | interpreter ÷ C scalar | native ÷ C -O2 | native ÷ C scalar | goal native ÷ C -O2 ≤ 2 |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|");
    for workload in workloads()
        .into_iter()
        .filter(|workload| NAMES.contains(&workload.name))
    {
        let image = compile(&workload);
        let mut interpreter = engine(&workload);
        // `engine` has run three cycles: the value the twins must have printed.
        let checked = value::read(&interpreter, workload.check)
            .ok()
            .as_ref()
            .and_then(as_twin_integer);
        let twins = [Optimisation::O2, Optimisation::O2Scalar].map(|optimisation| {
            let twin = run(&builder.build(workload.name, optimisation));
            if checked != Some(twin.check) {
                stop(&format!(
                    "the C twin of {} ({}) computes {} after three cycles, the interpreter {checked:?}",
                    workload.name,
                    optimisation.flags().join(" "),
                    twin.check
                ));
            }
            twin
        });
        let mut cycle = 3;
        let interpreter_ns = median_ns(&mut || {
            cycle += 1;
            std::hint::black_box(interpreter.run_cycle(0, 0, cycle)).ok();
        });
        let mut native = engine_with(&workload, EngineChoice::Native);
        let mut native_cycle = 3;
        let native_ns = median_ns(&mut || {
            native_cycle += 1;
            std::hint::black_box(native.run_cycle(0, 0, native_cycle)).ok();
        });
        let [o2, scalar] = twins.map(|twin| twin.ns_per_cycle.max(f64::MIN_POSITIVE));
        let goal = if !GOAL_WORKLOADS.contains(&workload.name) {
            ""
        } else if native_ns / o2 <= 2.0 {
            "met"
        } else if native_ns / scalar <= 2.0 {
            // gcc vectorises at -O2 where Cranelift emits scalar code; the goal is read
            // against the scalar twin then (`docs/native-engine.md` §13, question 1).
            "met against the scalar twin (vectorised: not met)"
        } else {
            "not met"
        };
        println!(
            "| {} | {interpreter_ns:.0} | {native_ns:.0} | {o2:.1} | {scalar:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {goal} |",
            workload.name,
            interpreter_ns / o2,
            interpreter_ns / scalar,
            native_ns / o2,
            native_ns / scalar,
        );
        let report = native.native_report();
        sizes.push((
            workload.name,
            instructions(&image),
            code_section_bytes(&image),
            report.translation_time.as_secs_f64() * 1000.0,
            report.code_bytes,
        ));
    }
    println!(
        "\n| workload | instructions in main | bytecode bytes | translation ms | code bytes | code ÷ bytecode (goal < 10) |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for (name, instructions, bytecode, translation_ms, code_bytes) in sizes {
        let ratio = bytecode.map_or_else(
            || "–".to_owned(),
            |bytes| format!("{:.2}", code_bytes as f64 / bytes.max(1) as f64),
        );
        let bytecode = bytecode.map_or_else(|| "–".to_owned(), |bytes| bytes.to_string());
        println!(
            "| {name} | {instructions} | {bytecode} | {translation_ms:.1} | {code_bytes} | {ratio} |"
        );
    }
}

/// The size of the encoded image's code section payload (section 5, `docs/program-image.md`
/// §3), the "bytecode" of `docs/native-engine.md` §9.2.
pub fn code_section_bytes(image: &program_image::ProgramImage) -> Option<usize> {
    const CODE_SECTION: u16 = 5;
    let bytes = image.encode();
    // The header: magic (8), version (2), flags (2), section count (4).
    let count = u32::from_le_bytes(bytes.get(12..16)?.try_into().ok()?);
    let mut at = 16;
    for _ in 0..count {
        let id = u16::from_le_bytes(bytes.get(at..at + 2)?.try_into().ok()?);
        let length = u32::from_le_bytes(bytes.get(at + 4..at + 8)?.try_into().ok()?) as usize;
        if id == CODE_SECTION {
            return Some(length);
        }
        at += 8 + length;
    }
    None
}

/// The folder of the twins' sources.
fn twins_folder() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/c_twins")
}

/// Stops the bench with `message`: a twin that cannot be built, run or trusted leaves no
/// figure worth printing.
fn stop(message: &str) -> ! {
    eprintln!("scan_report: {message}");
    std::process::exit(2)
}
