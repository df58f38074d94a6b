//! How long one cam evaluation takes: a 2048-segment Poly5 cam and 2048-point tables with each
//! interpolation, sampled at master positions in random order (the binary search's worst case)
//! and in ascending order (a master that advances each task cycle).
//!
//! Criterion reports the time of one batch of `MASTERS_PER_BATCH` evaluations and, from the
//! throughput, evaluations per second. After it, a plain timing loop prints the nanoseconds per
//! master position of every case, the figure the cam kernel's budget is stated in.

use std::hint::black_box;
use std::time::Instant;

use criterion::{BenchmarkId, Criterion, Throughput};
use motion::cam::{KeyPoint, MotionLaw, PointCam, PointInterpolation, Segment, SegmentedCam};
use motion::curve::{CamCurve, CamPoint};

/// The number of segments of the segmented cam and of points of the tables.
const ELEMENTS: usize = 2048;

/// Master positions evaluated per measured batch.
const MASTERS_PER_BATCH: usize = 4096;

/// The master span of one segment or table interval.
const SEGMENT_LENGTH: f64 = 0.5;

fn segmented_cam() -> SegmentedCam {
    // A slave that rises and falls with varying velocities, so no segment is a trivial line.
    let segments = (1..=ELEMENTS)
        .map(|index| {
            let master = index as f64 * SEGMENT_LENGTH;
            let phase = index as f64 * 0.37;
            let end = KeyPoint::xyva(master, 10.0 * phase.sin(), phase.cos(), 0.1 * phase.sin());
            Segment::new(MotionLaw::Poly5, end)
        })
        .collect();
    match SegmentedCam::new(KeyPoint::rest(0.0, 0.0), segments) {
        Ok(cam) => cam,
        Err(error) => panic!("the benchmark cam is invalid: {error}"),
    }
}

fn point_cam(source: &SegmentedCam, interpolation: PointInterpolation) -> PointCam {
    let points: Vec<CamPoint> = match source.sample_points(ELEMENTS) {
        Ok(points) => points,
        Err(error) => panic!("the benchmark table cannot be sampled: {error}"),
    };
    match PointCam::new(points, interpolation) {
        Ok(cam) => cam,
        Err(error) => panic!("the benchmark table is invalid: {error}"),
    }
}

/// Master positions spread over the cam in a scrambled order, from a fixed linear congruential
/// sequence so every run measures the same positions.
fn random_masters(range: (f64, f64)) -> Vec<f64> {
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    (0..MASTERS_PER_BATCH)
        .map(|_| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let fraction = (state >> 11) as f64 / (1_u64 << 53) as f64;
            range.0 + fraction * (range.1 - range.0)
        })
        .collect()
}

fn ascending_masters(range: (f64, f64)) -> Vec<f64> {
    let step = (range.1 - range.0) / MASTERS_PER_BATCH as f64;
    (0..MASTERS_PER_BATCH)
        .map(|index| range.0 + step * index as f64)
        .collect()
}

fn evaluate_all(curve: &dyn CamCurve, masters: &[f64]) -> f64 {
    masters
        .iter()
        .map(|&master| curve.sample(black_box(master)).position)
        .sum()
}

/// The cams under test with their names.
fn curves() -> Vec<(&'static str, Box<dyn CamCurve>)> {
    let segmented = segmented_cam();
    vec![
        (
            "table_linear",
            Box::new(point_cam(&segmented, PointInterpolation::Linear)),
        ),
        (
            "table_cubic",
            Box::new(point_cam(&segmented, PointInterpolation::Cubic)),
        ),
        (
            "table_quintic",
            Box::new(point_cam(&segmented, PointInterpolation::Quintic)),
        ),
        ("poly5_segments", Box::new(segmented)),
    ]
}

/// The master orders under test with their names.
fn orders(range: (f64, f64)) -> [(&'static str, Vec<f64>); 2] {
    [
        ("random", random_masters(range)),
        ("ascending", ascending_masters(range)),
    ]
}

fn cam_evaluation(criterion: &mut Criterion, curves: &[(&'static str, Box<dyn CamCurve>)]) {
    let mut group = criterion.benchmark_group("cam_sample_2048");
    group.throughput(Throughput::Elements(MASTERS_PER_BATCH as u64));
    for (name, curve) in curves {
        for (order, masters) in orders(curve.master_range()) {
            group.bench_with_input(
                BenchmarkId::new(*name, order),
                &masters,
                |bencher, masters| {
                    bencher.iter(|| evaluate_all(curve.as_ref(), masters));
                },
            );
        }
    }
    group.finish();
}

/// Prints the nanoseconds per master position of every case, from the best of several timed
/// runs of many batches (the best run is the one least disturbed by other work on the machine).
#[allow(
    clippy::print_stdout,
    reason = "the figures are the benchmark's output"
)]
fn print_ns_per_master(curves: &[(&'static str, Box<dyn CamCurve>)]) {
    const BATCHES_PER_RUN: usize = 50;
    const RUNS: usize = 5;
    for (name, curve) in curves {
        for (order, masters) in orders(curve.master_range()) {
            let mut best_ns = f64::INFINITY;
            for _ in 0..RUNS {
                let started = Instant::now();
                for _ in 0..BATCHES_PER_RUN {
                    black_box(evaluate_all(curve.as_ref(), &masters));
                }
                let elapsed_ns = started.elapsed().as_secs_f64() * 1e9;
                best_ns = best_ns.min(elapsed_ns / (BATCHES_PER_RUN * masters.len()) as f64);
            }
            println!("cam_sample_2048/{name}/{order}: {best_ns:.1} ns per master position");
        }
    }
}

fn main() {
    let curves = curves();
    let mut criterion = Criterion::default().configure_from_args();
    cam_evaluation(&mut criterion, &curves);
    criterion.final_summary();
    print_ns_per_master(&curves);
}
