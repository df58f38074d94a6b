//! The native engine's code size against the bytecode and its translation time for whole
//! projects (`docs/native-engine.md` §9.2, §9.3): the example project and the generated
//! 50,000-line project, printed after the workloads' table by `SCAN_SECTION=native cargo
//! bench -p tests --bench scan_report`.

use std::path::Path;

use program_image::ProgramImage;
use runtime::engine::{Engine, EngineChoice};

use crate::c_twins::code_section_bytes;
use crate::generate;

/// The lines of the generated project, as `compiler/benches/check.rs` and
/// `online_change_report` generate it.
const GENERATED_LINES: usize = 50_000;

/// How many times each project is loaded; the translation time printed is their median
/// (`docs/native-engine.md` §9.3).
const LOADS: usize = 5;

/// Prints, per project, its POUs and instructions, the bytecode, the machine code and their
/// ratio (the goal is under 10), and the translation time, the median of [`LOADS`] loads.
pub fn report() {
    println!(
        "\n| project | POUs | instructions | bytecode bytes | code bytes | code ÷ bytecode (goal < 10) | translation ms (median of {LOADS} loads) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (name, image) in [
        ("packaging_machine (example)", example()),
        ("generated 50,000 lines", generated()),
    ] {
        let bytecode = code_section_bytes(&image).unwrap_or(0);
        let pous = image.pous.len();
        let instructions: usize = image.pous.iter().map(|pou| pou.code.len()).sum();
        let mut code_bytes = 0;
        let mut times_ms = Vec::with_capacity(LOADS);
        for _ in 0..LOADS {
            let report = match Engine::with_choice(image.clone(), EngineChoice::Native) {
                Ok((_, report)) => report,
                Err(error) => panic!("the {name} image does not load: {error}"),
            };
            assert!(
                !EngineChoice::native_available() || report.fallbacks.is_empty(),
                "the {name} image does not run natively: {:?}",
                report.lines()
            );
            code_bytes = report.code_bytes;
            times_ms.push(report.translation_time.as_secs_f64() * 1000.0);
        }
        times_ms.sort_by(f64::total_cmp);
        println!(
            "| {name} | {pous} | {instructions} | {bytecode} | {code_bytes} | {:.2} | {:.1} |",
            code_bytes as f64 / bytecode.max(1) as f64,
            times_ms[LOADS / 2]
        );
    }
}

/// The example project's image (`assets/examples/packaging_machine`).
fn example() -> ProgramImage {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let project = project_model::load_project(&dir).unwrap().project;
    compiler::compile_project(&project).unwrap()
}

/// The generated 50,000 lines with a program `Main` calling an instance of every function
/// block, in a cyclic task, as `online_change_report` builds it.
fn generated() -> ProgramImage {
    let (mut source, pairs) = generate::project_source(GENERATED_LINES);
    source.push_str("PROGRAM Main\nVAR\n    n : UDINT;\n");
    for index in 0..pairs {
        source.push_str(&format!("    fb{index} : FB_Station{index};\n"));
    }
    source.push_str("END_VAR\nn := n + 1;\n");
    for index in 0..pairs {
        source.push_str(&format!(
            "fb{index}(xEnable := FALSE, iMode := {});\n",
            index % 7
        ));
    }
    source.push_str("END_PROGRAM\n");
    let mut project = compiler::SourceProject::new(&source).project;
    project.tasks = vec![project_model::Task {
        name: "Main10ms".to_owned(),
        kind: project_model::TaskKind::Cyclic {
            interval_us: 10_000,
        },
        priority: 0,
        watchdog: None,
        programs: vec!["Main".to_owned()],
    }];
    compiler::compile_project(&project).unwrap()
}
