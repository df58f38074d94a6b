//! The scan-time figures as a table to paste into a note:
//! `cargo bench -p tests --bench scan_report`.
//!
//! Times one task cycle of each workload of `workloads` in the interpreter (the "runtime"
//! columns) and in the native engine, and one call of its Rust twin, with `Instant` over many
//! repetitions, takes the median of several batches, and prints nanoseconds per statement (or
//! loop iteration) and per instruction, the native engine's and the Rust figure, and the
//! interpreter's ratio to Rust. The fixed cost of a cycle (the empty program) is shown on its own line and
//! not subtracted. Then what the debugger costs a call-heavy cycle (`debugger_cost`), then the
//! engines against the workloads' C twins (`c_twins`, `docs/native-engine.md` §11.3; gcc or
//! `RIVET_CC` must be installed), then the native engine on whole projects, the example project
//! and the generated 50,000-line project: their bytecode, machine code and translation time
//! (`native_images`, §9.2, §9.3).
//!
//! `SCAN_SECTION=debugger`, `SCAN_SECTION=native` or `SCAN_SECTION=translation` prints only
//! that section.

// A bench binary: it prints its table, and says on standard error why it stopped.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::print_stdout,
    clippy::print_stderr
)]

use std::hint::black_box;
use std::time::Instant;

mod c_twins;
mod debugger_cost;
mod large_project;
mod native_images;
mod workloads;

use runtime::engine::EngineChoice;
use workloads::{RustTwin, compile, engine, engine_with, instructions, workloads};

/// Batches timed per figure; the median is reported.
const BATCHES: usize = 15;
/// Roughly how long one batch runs.
const BATCH_NS: f64 = 20_000_000.0;

/// The median time of one call of `f` in nanoseconds.
fn median_ns(mut f: impl FnMut()) -> f64 {
    // Calibrate the repetitions so a batch takes about BATCH_NS.
    let start = Instant::now();
    let mut calls = 0u64;
    while start.elapsed().as_nanos() < 5_000_000 {
        f();
        calls += 1;
    }
    let once = start.elapsed().as_nanos() as f64 / calls as f64;
    let repetitions = ((BATCH_NS / once) as u64).max(1);
    let mut times: Vec<f64> = (0..BATCHES)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..repetitions {
                f();
            }
            start.elapsed().as_nanos() as f64 / repetitions as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[BATCHES / 2]
}

fn main() {
    // `SCAN_PROFILE=dint` only runs that workload's engine for a while, for a profiler such as
    // `valgrind --tool=callgrind`.
    if let Some(name) = std::env::var_os("SCAN_PROFILE") {
        for workload in workloads().into_iter().filter(|w| name == w.name) {
            let mut engine = engine(&workload);
            for cycle in 0..2000 {
                black_box(engine.run_cycle(0, 0, cycle)).ok();
            }
        }
        return;
    }
    // `SCAN_SECTION=debugger` only measures what the debugger costs, the one figure a change
    // to the engine's debug forms moves.
    if std::env::var_os("SCAN_SECTION").is_some_and(|section| section == "debugger") {
        debugger_cost::report(&|f| median_ns(f));
        return;
    }
    // `SCAN_SECTION=translation` only loads the whole projects natively, the figures a change
    // to the translator moves (and a profiler's run).
    if std::env::var_os("SCAN_SECTION").is_some_and(|section| section == "translation") {
        native_images::report();
        return;
    }
    // `SCAN_SECTION=native` only compares the engines with the C twins.
    if std::env::var_os("SCAN_SECTION").is_some_and(|section| section == "native") {
        c_twins::report(&|f| median_ns(f));
        native_images::report();
        return;
    }
    println!(
        "| workload | unit | units/cycle | instructions/cycle | runtime ns/cycle | runtime ns/unit | runtime ns/instruction | native engine ns/unit | Rust ns/unit | runtime ÷ Rust |"
    );
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for workload in workloads() {
        let image = compile(&workload);
        let static_instructions = instructions(&image);
        let mut engine = engine(&workload);
        let mut cycle = 0;
        let runtime = median_ns(|| {
            cycle += 1;
            black_box(engine.run_cycle(0, 0, cycle)).ok();
        });
        let mut native = engine_with(&workload, EngineChoice::Native);
        let mut native_cycle = 0;
        let native_ns = median_ns(|| {
            native_cycle += 1;
            black_box(native.run_cycle(0, 0, native_cycle)).ok();
        });
        let mut rust = RustTwin::default();
        let rust_ns = median_ns(|| (workload.rust)(black_box(&mut rust)));
        // A loop runs its body's instructions once per iteration; the others run each once.
        let executed = if workload.name == "array_loop" {
            executed_loop_instructions(&image)
        } else {
            static_instructions as f64
        };
        let units = workload.units as f64;
        // A chart or a CASE runs a small part of its code per cycle, so its static size says
        // nothing of the instructions executed: those columns show the size, marked.
        // The FB calls run the block's code too, which the program's size does not count.
        let branching = workload.name.starts_with("sfc_")
            || workload.name.starts_with("case_")
            || workload.name == "fb_calls";
        let (executed_text, per_instruction) = if branching {
            (format!("{static_instructions} (static)"), "–".to_owned())
        } else {
            (
                format!("{executed}"),
                format!("{:.2}", runtime / executed.max(1.0)),
            )
        };
        println!(
            "| {} | {} | {} | {} | {:.0} | {:.2} | {} | {:.3} | {:.3} | {:.0} |",
            workload.name,
            workload.unit,
            workload.units,
            executed_text,
            runtime,
            runtime / units,
            per_instruction,
            native_ns / units,
            rust_ns / units,
            runtime / rust_ns.max(f64::MIN_POSITIVE),
        );
    }
    debugger_cost::report(&|f| median_ns(f));
    c_twins::report(&|f| median_ns(f));
    native_images::report();
    if std::env::var_os("SCAN_DUMP").is_some() {
        for workload in workloads() {
            let image = compile(&workload);
            println!("\n{}:", workload.name);
            for pou in &image.pous {
                for (index, instr) in pou.code.iter().enumerate().take(24) {
                    println!("  {} {index}: {instr:?}", pou.name);
                }
            }
        }
    }
}

/// Instructions executed by one cycle of the array loop: the code before the loop's backward
/// jump runs once, the loop from the jump's target to the jump once per iteration, less one:
/// the FOR loop tests `i > end` or `i < end` by the sign of the step, and only one of the two
/// runs.
fn executed_loop_instructions(image: &program_image::ProgramImage) -> f64 {
    use program_image::Instr;
    let Some(pou) = image
        .pous
        .iter()
        .find(|pou| pou.name.eq_ignore_ascii_case("main"))
    else {
        return 0.0;
    };
    for (index, instr) in pou.code.iter().enumerate() {
        if let Instr::Jump { target } = instr
            && (*target as usize) <= index
        {
            let body = (index - *target as usize) as f64;
            let before = *target as f64;
            return before + body * workloads::COUNT as f64;
        }
    }
    0.0
}
