//! The native engine on whole projects (`docs/native-engine.md` §9.2, §9.3): the example
//! project and the 50,000-line project of `large_project`, each compiled once and then loaded
//! [`LOADS`] times with `EngineChoice::Native`. Printed per project: its POUs (and how many got
//! machine code), its instructions, the bytecode, the machine code, their ratio and the median
//! of the wall time `Engine::with_choice` reports for the translation and the module's
//! finalisation. `SCAN_SECTION=native` prints it after the workloads' table,
//! `SCAN_SECTION=translation` alone.

use std::path::Path;
use std::time::Duration;

use program_image::ProgramImage;
use runtime::engine::{Engine, EngineChoice};

use crate::c_twins::code_section_bytes;
use crate::large_project;

/// Loads timed per project; the median is reported.
const LOADS: usize = 5;

/// Prints, per project, its size in POUs, instructions and bytecode, its machine code and the
/// ratio (the goal is under 10), and the median translation time (the goal is under 1 s for
/// the 50,000-line project).
pub fn report() {
    println!(
        "\nThe native engine on whole projects (translation: median of {LOADS} loads inside Engine::with_choice):\n"
    );
    println!(
        "| project | POUs | POUs with machine code | instructions | bytecode bytes | code bytes | code ÷ bytecode (goal < 10) | translation ms (goal < 1000) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let (source, _) = large_project::source(false);
    for (name, image) in [
        ("packaging_machine (example)", example()),
        ("generated 50,000 lines", large_project::compiled(&source)),
    ] {
        project_row(name, &image);
    }
}

/// Loads `image` [`LOADS`] times and prints its row.
fn project_row(name: &str, image: &ProgramImage) {
    let instructions: usize = image.pous.iter().map(|pou| pou.code.len()).sum();
    let bytecode = code_section_bytes(image);
    let mut times: Vec<Duration> = Vec::with_capacity(LOADS);
    let mut last = None;
    for _ in 0..LOADS {
        let (engine, report) = match Engine::with_choice(image.clone(), EngineChoice::Native) {
            Ok(loaded) => loaded,
            Err(error) => panic!("the {name} image does not load: {error}"),
        };
        times.push(report.translation_time);
        // Dropped here, as a replaced image is, so every load starts from the same memory.
        drop(engine);
        last = Some(report);
    }
    times.sort();
    let median_ms = times[LOADS / 2].as_secs_f64() * 1000.0;
    let Some(report) = last else {
        return;
    };
    if let Some(reason) = &report.unavailable {
        println!("| {name} | no machine code: {reason} |");
        return;
    }
    assert!(
        report.fallbacks.is_empty(),
        "the {name} image does not run natively: {:?}",
        report.lines()
    );
    let native_pous = report.pous - report.fallbacks.len();
    let (bytecode_text, ratio) = match bytecode {
        Some(bytes) => (
            bytes.to_string(),
            format!("{:.2}", report.code_bytes as f64 / bytes.max(1) as f64),
        ),
        None => ("–".to_owned(), "–".to_owned()),
    };
    println!(
        "| {name} | {} | {native_pous} | {instructions} | {bytecode_text} | {} | {ratio} | {median_ms:.0} |",
        report.pous, report.code_bytes
    );
}

/// The example project's image (`assets/examples/packaging_machine`).
fn example() -> ProgramImage {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let project = project_model::load_project(&dir)
        .expect("the example project loads")
        .project;
    compiler::compile_project(&project).expect("the example project compiles")
}
