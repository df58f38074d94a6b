//! The native engine's translation time on the 50,000-line project (`docs/native-engine.md`
//! §9.3): the project of `large_project` compiled once, then loaded [`LOADS`] times with
//! `EngineChoice::Native`, and the median of the wall time `Engine::with_choice` reports for
//! the translation and the module's finalisation printed with the image's POU and instruction
//! counts, its bytecode and its machine code bytes (§9.2).

use std::time::Duration;

use runtime::engine::{Engine, EngineChoice};

use crate::c_twins::code_section_bytes;
use crate::large_project;

/// Loads timed; the median is reported.
const LOADS: usize = 5;

/// Prints the translation time table.
pub fn report() {
    let (source, _) = large_project::source(false);
    let image = large_project::compiled(&source);
    let instructions: usize = image.pous.iter().map(|pou| pou.code.len()).sum();
    let bytecode = code_section_bytes(&image);
    let mut times: Vec<Duration> = Vec::with_capacity(LOADS);
    let mut last = None;
    for _ in 0..LOADS {
        let (engine, report) = Engine::with_choice(image.clone(), EngineChoice::Native)
            .expect("the 50,000-line project loads");
        times.push(report.translation_time);
        // Dropped here, as a replaced image is, so every load starts from the same memory.
        drop(engine);
        last = Some(report);
    }
    times.sort();
    let median_ms = times[LOADS / 2].as_secs_f64() * 1000.0;
    let report = last.expect("at least one load");
    if let Some(reason) = &report.unavailable {
        println!("\nNo machine code for the 50,000-line project: {reason}");
        return;
    }
    let native_pous = report.pous - report.fallbacks.len();
    let (bytecode_text, ratio) = match bytecode {
        Some(bytes) => (
            bytes.to_string(),
            format!("{:.1}", report.code_bytes as f64 / bytes as f64),
        ),
        None => ("–".to_owned(), "–".to_owned()),
    };
    println!(
        "\nTranslation of the 50,000-line project (median of {LOADS} loads inside Engine::with_choice, goal under 1 s):\n"
    );
    println!(
        "| POUs | POUs with machine code | instructions | bytecode bytes | translation ms | code bytes | code ÷ bytecode |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|");
    println!(
        "| {} | {native_pous} | {instructions} | {bytecode_text} | {median_ms:.0} | {} | {ratio} |",
        report.pous, report.code_bytes
    );
    for fallback in &report.fallbacks {
        println!("fallback: {fallback:?}");
    }
}
