//! Helpers shared by the integration tests: a powered axis and a cycle loop.

#![allow(dead_code, clippy::unwrap_used, clippy::expect_used)]

use motion::axis::AxisConfig;
use motion::kernel::{AxisId, AxisSnapshot, Kernel};

pub mod sync;

/// The task interval of the simulations: 1 ms.
pub const DT_S: f64 = 0.001;

/// A kernel with one powered axis of `config`.
pub fn powered(config: AxisConfig) -> (Kernel, AxisId) {
    let mut kernel = Kernel::new();
    let axis = kernel.add_axis(config).unwrap();
    assert!(kernel.power(axis, true).unwrap());
    (kernel, axis)
}

/// A linear axis without software limits that allows 10 000 u/s, u/s², and no jerk limit.
pub fn roomy_linear() -> AxisConfig {
    AxisConfig::linear(10_000.0, 100_000.0, 100_000.0)
}

/// The snapshot of an axis.
pub fn snap(kernel: &Kernel, axis: AxisId) -> AxisSnapshot {
    kernel.snapshot(axis).unwrap()
}

/// Runs `cycles` task cycles: `programs` first (the FB calls), then the kernel advances.
pub fn run(
    kernel: &mut Kernel,
    axis: AxisId,
    cycles: usize,
    mut programs: impl FnMut(&mut Kernel, usize),
) {
    for cycle in 0..cycles {
        programs(kernel, cycle);
        kernel.advance(axis, DT_S).unwrap();
    }
}

/// Asserts that two positions agree to `1e-9` relative to the larger.
#[track_caller]
pub fn assert_close(actual: f64, expected: f64) {
    let scale = actual.abs().max(expected.abs()).max(1.0);
    assert!(
        (actual - expected).abs() <= 1e-9 * scale,
        "expected {expected}, got {actual}"
    );
}
