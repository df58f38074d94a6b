//! The online change benchmark of issue 17: an online change of the 50,000-line project
//! completes in under 1 s with no missed cycle of a 10 ms task.
//!
//! The project is the one `compiler/benches/check.rs` checks (the same generator), with a
//! program `Main` that counts its cycles and calls an instance of every function block from a
//! 10 ms task. The runtime is assembled as `rivet-runtime` does it (scheduler, Modbus server
//! and online services on 127.0.0.1); the change edits one function block's expression and
//! adds a variable to it (so every instance grows and everything behind them moves), and goes
//! through the real `online::Client`: transfer, check, details, apply; then back again, six
//! changes in all. A trace of the cycle counter at every cycle of the 10 ms task gives the
//! start delays during each change and outside them; the scheduler's statistics give the
//! missed cycles. A full download and start of the same image, measured in the same run, is the
//! reference.
//!
//! `cargo bench -p tests --bench online_change_report`. Not run in CI: its figures depend on
//! the machine.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::time::{Duration, Instant};

use online::{Client, TraceConfig, Trigger};
use runtime::scheduler::{Scheduler, SchedulerOptions};

mod bench_runtime;
mod large_project;

use large_project::{EDITED, INTERVAL_US, image, source};

/// The password the runtime is given, so that every changing request carries a token.
const PASSWORD: &str = "online-change-benchmark";
/// The samples the trace keeps: 20 s of the 10 ms task, more than the change takes.
const TRACE_SAMPLES: u32 = 2000;
/// Online changes measured: the edit, its undoing, and so on.
const ROUNDS: usize = 6;
/// How long the program runs before a measurement, so the task's timing has settled.
const SETTLE: Duration = Duration::from_millis(500);

fn main() {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap();
    runtime.block_on(bench());
}

/// Milliseconds of a duration, for the tables.
fn ms(duration: Duration) -> f64 {
    duration.as_secs_f64() * 1e3
}

/// Arms a trace of `Main.n` at every cycle of the task; returns the traced place.
async fn arm_trace(client: &mut Client) -> Vec<online::Place> {
    let counter = client.resolve("Main.n").await.unwrap().place;
    let places = vec![counter];
    client
        .trace_configure(&TraceConfig {
            task: 0,
            every: 1,
            samples: TRACE_SAMPLES,
            pretrigger_percent: 0,
            trigger: Trigger::None,
            places: places.clone(),
        })
        .await
        .unwrap();
    client.trace_arm().await.unwrap();
    places
}

/// The cycle counter `Main.n` now.
async fn counter(client: &mut Client) -> u32 {
    let place = client.resolve("Main.n").await.unwrap().place;
    let snapshot = client.read(&[place]).await.unwrap();
    let bytes: [u8; 4] = snapshot.values[0].0.clone().try_into().unwrap();
    u32::from_le_bytes(bytes)
}

/// The start delays the trace of `Main.n` recorded: for each start-to-start interval, the
/// counter's value at its end and how much longer than the task's interval it was.
async fn start_delays(
    client: &mut Client,
    places: &[online::Place],
) -> (Vec<(u32, Duration)>, u64) {
    let samples = client.trace_upload(places, |_| {}).await.unwrap();
    let interval = Duration::from_micros(u64::from(INTERVAL_US));
    let mut gaps = 0;
    let mut delays = Vec::new();
    for pair in samples.windows(2) {
        if pair[1].cycle != pair[0].cycle + 1 {
            gaps += 1;
        }
        let between = Duration::from_nanos(pair[1].time_ns.saturating_sub(pair[0].time_ns));
        let value: [u8; 4] = pair[1].values[0].clone().try_into().unwrap();
        delays.push((u32::from_le_bytes(value), between.saturating_sub(interval)));
    }
    (delays, gaps)
}

/// One online change's figures.
struct Round {
    total: Duration,
    transfer: Duration,
    check: Duration,
    details: Duration,
    apply: Duration,
    switch: Duration,
    missed: u64,
    /// The counter's values when the change began and when it had ended.
    counted: (u32, u32),
    changed: Vec<String>,
    found: String,
}

/// An online change to `image` through `client`, phase by phase.
async fn online_change(client: &mut Client, scheduler: &Scheduler, image: &[u8]) -> Round {
    let before = scheduler.status().tasks[0].clone();
    let count_before = counter(client).await;
    let began = Instant::now();
    let transfer = client.transfer(image, |_, _| {}).await.unwrap();
    let transferred = began.elapsed();
    let check = client.online_change_check(transfer).await.unwrap();
    let checked = began.elapsed();
    let details = client.online_change_details(transfer).await.unwrap();
    let listed = began.elapsed();
    assert!(check.possible, "the change is possible: {}", check.why);
    let applied = client.online_change_apply(transfer).await.unwrap();
    let total = began.elapsed();
    let count_after = counter(client).await;
    // The next cycle's start is in the statistics once it ran.
    tokio::time::sleep(Duration::from_micros(2 * u64::from(INTERVAL_US))).await;
    let after = scheduler.status().tasks[0].clone();
    assert!(!after.faulted, "the task did not fault");
    Round {
        total,
        transfer: transferred,
        check: checked - transferred,
        details: listed - checked,
        apply: total - listed,
        switch: Duration::from_micros(u64::from(applied.switch_us)),
        missed: after.missed_cycles - before.missed_cycles,
        counted: (count_before, count_after),
        changed: details
            .iter()
            .filter(|detail| detail.kind == 0)
            .map(|detail| detail.name.clone())
            .collect(),
        found: format!(
            "{} carried, {} added, {} removed, {} reinitialised, {} details",
            check.carried,
            check.added,
            check.removed,
            check.reinitialised,
            details.len()
        ),
    }
}

async fn bench() {
    let started = Instant::now();
    let (old_source, pairs) = source(false);
    let (new_source, _) = source(true);
    let lines = new_source.lines().count();
    let old_image = image(&old_source);
    let new_image = image(&new_source);
    let compile = started.elapsed() / 2;
    println!(
        "online change: project of {lines} lines, {} POUs; images {:.2} MB and {:.2} MB (each compiled in about {:.0} ms); a 10 ms task calls `Main`; {} processors, load average {}",
        pairs * 2 + 1,
        old_image.len() as f64 / 1e6,
        new_image.len() as f64 / 1e6,
        ms(compile),
        std::thread::available_parallelism().map_or(0, usize::from),
        load_average()
    );

    let (address, scheduler) = bench_runtime::start(SchedulerOptions::default(), PASSWORD).await;
    let (mut client, _) = Client::connect(address, Some(PASSWORD)).await.unwrap();

    // The reference: a full download and start of the old image, phase by phase.
    let began = Instant::now();
    let transfer = client.transfer(&old_image, |_, _| {}).await.unwrap();
    let transferred = began.elapsed();
    client.commit(transfer, false).await.unwrap();
    let committed = began.elapsed();
    client.start().await.unwrap();
    let download = began.elapsed();
    println!("| full download + start (reference) | total | transfer | commit (load) | start |");
    println!(
        "| | {:.1} ms | {:.1} ms | {:.1} ms | {:.1} ms |",
        ms(download),
        ms(transferred),
        ms(committed - transferred),
        ms(download - committed)
    );

    tokio::time::sleep(SETTLE).await;
    let places = arm_trace(&mut client).await;
    tokio::time::sleep(SETTLE).await;

    // Changes back and forth: the edit and its undoing (a variable removed), each an online
    // change of the whole project.
    let mut rounds = Vec::new();
    for round in 0..ROUNDS {
        let image = if round % 2 == 0 {
            &new_image
        } else {
            &old_image
        };
        rounds.push(online_change(&mut client, &scheduler, image).await);
        tokio::time::sleep(SETTLE).await;
    }
    let (delays, gaps) = start_delays(&mut client, &places).await;
    let status = scheduler.status().tasks[0].clone();

    println!(
        "| online change | total (target < 1000 ms) | transfer | check | details | apply | switch (`switch_us`) | missed cycles (target 0) | start delay max during the change | POUs changed | what the check found |"
    );
    for (index, round) in rounds.iter().enumerate() {
        let during = delays
            .iter()
            .filter(|(count, _)| (round.counted.0..=round.counted.1 + 1).contains(count))
            .map(|(_, delay)| *delay)
            .max()
            .unwrap_or_default();
        println!(
            "| {} | {:.1} ms | {:.1} ms | {:.1} ms | {:.1} ms | {:.1} ms | {:.3} ms | {} | {:.3} ms | {:?} | {} |",
            if index % 2 == 0 { "edit" } else { "undo" },
            ms(round.total),
            ms(round.transfer),
            ms(round.check),
            ms(round.details),
            ms(round.apply),
            ms(round.switch),
            round.missed,
            ms(during),
            round.changed,
            round.found
        );
    }
    let mut totals: Vec<Duration> = rounds.iter().map(|round| round.total).collect();
    totals.sort();
    let outside = delays
        .iter()
        .filter(|(count, _)| {
            !rounds
                .iter()
                .any(|round| (round.counted.0..=round.counted.1 + 1).contains(count))
        })
        .map(|(_, delay)| *delay)
        .max()
        .unwrap_or_default();
    println!(
        "| summary | median total {:.1} ms, max {:.1} ms | 10 ms task: {} cycles, missed {} in all, trace of {} intervals with {gaps} gaps, start delay max outside the changes {:.3} ms | load average now {} |",
        ms(totals[totals.len() / 2]),
        ms(totals[totals.len() - 1]),
        status.cycles,
        status.missed_cycles,
        delays.len(),
        ms(outside),
        load_average()
    );
    for round in &rounds {
        // The counter went on from its value, and only the edited block is listed changed
        // (its undoing changes the same block back), though every POU behind its instances
        // has other addresses.
        assert!(round.counted.1 > round.counted.0);
        assert_eq!(round.changed, [EDITED]);
    }
}

/// The machine's load averages over 1, 5 and 15 minutes (/proc/loadavg): on a machine busy
/// with other work the task waits for a processor, which the figures must show.
fn load_average() -> String {
    let text = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    text.split_whitespace()
        .take(3)
        .collect::<Vec<_>>()
        .join(" ")
}
