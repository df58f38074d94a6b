//! Scan time of the runtime (issue 4: at most 10 ns per simple statement), with criterion:
//! `cargo bench -p tests --bench scan`.
//!
//! Each workload is one task cycle of a generated ST program (1000 BOOL, DINT or REAL
//! statements, or a 1000-iteration array loop) run by `runtime::engine::Engine` in the
//! interpreter (`…/runtime`) and in the native engine (`…/native`), next to the same
//! computation in plain Rust (`…/rust`). `cargo bench -p tests --bench scan_report` prints the
//! figures per statement as a table.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.
#![allow(missing_docs)] // criterion_group! writes an undocumented function.

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};

#[allow(dead_code)] // Parts used only by scan_report.
mod workloads;

use runtime::engine::EngineChoice;
use workloads::{RustTwin, engine, engine_with, workloads};

fn scan(c: &mut Criterion) {
    let mut group = c.benchmark_group("scan");
    for workload in workloads() {
        group.throughput(Throughput::Elements(workload.units as u64));
        let mut engine = engine(&workload);
        let mut cycle = 0;
        group.bench_function(format!("{}/runtime", workload.name), |b| {
            b.iter(|| {
                cycle += 1;
                engine.run_cycle(0, 0, cycle).is_ok()
            })
        });
        let mut native = engine_with(&workload, EngineChoice::Native);
        let mut cycle = 0;
        group.bench_function(format!("{}/native", workload.name), |b| {
            b.iter(|| {
                cycle += 1;
                native.run_cycle(0, 0, cycle).is_ok()
            })
        });
        let mut rust = RustTwin::default();
        group.bench_function(format!("{}/rust", workload.name), |b| {
            b.iter(|| (workload.rust)(&mut rust))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    // The machine is shared: few samples, short runs.
    config = Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    targets = scan
}
criterion_main!(benches);
