//! The start jitter of a fast task next to a long cycle of a slower one, without and with
//! preemption (issue 16 §2), as a table for a note: `cargo bench -p tests --bench jitter_report`.
//!
//! Runs the real `Scheduler` on a compiled program with a 2 ms task (priority 1, a counter) and
//! a 10 ms task (priority 10) whose cycle is a loop sized to about 5 ms of work on this machine,
//! for some seconds with preemption off and then on (each sleeping until a start, then spinning
//! the last 200 µs before it), and prints the 2 ms task's start jitter
//! (median, 95th and 99th percentile, maximum) from the scheduler's cycle log. The figures
//! depend on the machine and its load (printed first); nothing is asserted.
//! Both the calibration and the scheduler run the default engine (`EngineChoice::default`:
//! native on x86-64 and aarch64), so the loop is sized for the engine that is measured.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::sync::{Arc, Mutex, mpsc};
use std::time::{Duration, Instant};

use program_image::ProgramImage;
use runtime::areas::LocatedAreas;
use runtime::engine::Engine;
use runtime::scheduler::{CycleRecord, Scheduler, SchedulerOptions};

/// How long each configuration runs.
const RUN: Duration = Duration::from_secs(5);
/// The slow task's own work per cycle.
const SLOW_WORK_NS: f64 = 5_000_000.0;

/// The program: `Fast` counts, `Slow` loops `iterations` times.
fn source(iterations: u32) -> String {
    format!(
        "PROGRAM Fast
VAR
    count : DINT;
END_VAR
count := count + 1;
END_PROGRAM

PROGRAM Slow
VAR
    i : DINT;
    n : DINT := {iterations};
    acc : DINT;
END_VAR
FOR i := 1 TO n DO
    acc := acc + i MOD 7;
END_FOR
END_PROGRAM
"
    )
}

/// The image with the 2 ms task (index 0) and the 10 ms task (index 1).
fn image(iterations: u32) -> ProgramImage {
    let source = compiler::SourceProject::new(&source(iterations));
    let mut project = source.project.clone();
    let task = |name: &str, interval_us, priority, program: &str| project_model::Task {
        name: name.to_owned(),
        kind: project_model::TaskKind::Cyclic { interval_us },
        priority,
        watchdog: None,
        programs: vec![program.to_owned()],
    };
    project.tasks = vec![
        task("FastTask", 2_000, 1, "Fast"),
        task("SlowTask", 10_000, 10, "Slow"),
    ];
    compiler::compile_project(&project).unwrap()
}

/// How many loop iterations make the slow task's cycle take about [`SLOW_WORK_NS`].
fn calibrate() -> u32 {
    const PROBE: u32 = 200_000;
    let mut engine = Engine::new(image(PROBE)).unwrap();
    let fastest = (0..10)
        .map(|cycle| {
            let start = Instant::now();
            engine.run_cycle(1, 0, cycle).unwrap();
            start.elapsed().as_nanos() as f64
        })
        .fold(f64::MAX, f64::min);
    (SLOW_WORK_NS / (fastest / f64::from(PROBE))) as u32
}

/// The `p`-th percentile (0 to 100) of sorted values.
fn percentile(sorted: &[u64], p: f64) -> u64 {
    let rank = ((p / 100.0) * (sorted.len() - 1) as f64).round() as usize;
    sorted[rank.min(sorted.len() - 1)]
}

/// Runs the image for [`RUN`] and returns the cycle log.
fn run(image: &ProgramImage, preemption: bool, spin: Duration) -> Vec<CycleRecord> {
    let (log, records) = mpsc::channel();
    let options = SchedulerOptions {
        preemption,
        spin_before_start: spin,
        cycle_log: Some(log),
        ..SchedulerOptions::default()
    };
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, options).unwrap();
    scheduler.load(image.clone()).unwrap();
    scheduler.start().unwrap();
    std::thread::sleep(RUN);
    scheduler.stop().unwrap();
    scheduler.shutdown().unwrap();
    records.try_iter().collect()
}

fn main() {
    let iterations = calibrate();
    let image = image(iterations);
    println!(
        "2 ms task (priority 1) next to a 10 ms task (priority 10) looping {iterations} times \
         (about {:.1} ms of work), {} s each:\n",
        SLOW_WORK_NS / 1e6,
        RUN.as_secs()
    );
    // The figures mean little on a loaded machine; say how loaded it was.
    if let Ok(load) = std::fs::read_to_string("/proc/loadavg") {
        println!("Load average before the runs: {}\n", load.trim());
    }
    println!(
        "| preemption | 2 ms cycles | jitter p50 | jitter p95 | jitter p99 | jitter max | nested | 10 ms own cycle (mean) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let spin = Duration::from_micros(200);
    for (preemption, spin) in [
        (false, Duration::ZERO),
        (true, Duration::ZERO),
        (false, spin),
        (true, spin),
    ] {
        let records = run(&image, preemption, spin);
        let mut jitter: Vec<u64> = records
            .iter()
            .filter(|record| record.task == 0)
            .map(CycleRecord::jitter_ns)
            .collect();
        jitter.sort_unstable();
        let nested = records
            .iter()
            .filter(|record| record.task == 0 && record.interrupted.is_some())
            .count();
        let slow: Vec<u64> = records
            .iter()
            .filter(|record| record.task == 1)
            .map(CycleRecord::own_ns)
            .collect();
        let slow_mean = slow.iter().sum::<u64>() / slow.len().max(1) as u64;
        let us = |ns: u64| format!("{:.0} µs", ns as f64 / 1e3);
        println!(
            "| {}{} | {} | {} | {} | {} | {} | {} | {:.2} ms |",
            if preemption { "on" } else { "off" },
            if spin.is_zero() {
                String::new()
            } else {
                format!(", spinning {} µs", spin.as_micros())
            },
            jitter.len(),
            us(percentile(&jitter, 50.0)),
            us(percentile(&jitter, 95.0)),
            us(percentile(&jitter, 99.0)),
            us(*jitter.last().unwrap()),
            nested,
            slow_mean as f64 / 1e6
        );
    }
}
