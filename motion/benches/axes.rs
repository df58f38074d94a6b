//! One kernel cycle of 8 axes that each run a move: the cost per axis per cycle.

#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used)]

use criterion::{Criterion, criterion_group, criterion_main};
use motion::axis::AxisConfig;
use motion::kernel::{BufferMode, Dynamics, Kernel, MotionRequest, PositionTarget};
use std::hint::black_box;

const AXES: usize = 8;

/// Eight powered axes, half trapezoidal and half S-curve, each in a move long enough never to
/// end during the benchmark; half of them are modulo axes.
fn kernel_with_moving_axes() -> Kernel {
    let mut kernel = Kernel::new();
    for index in 0..AXES {
        let mut config = AxisConfig::linear(1000.0, 10_000.0, 10_000.0);
        if index % 2 == 0 {
            config.modulo_period = Some(360.0);
        }
        if index >= AXES / 2 {
            config.max_jerk = 100_000.0;
        }
        let axis = kernel.add_axis(config).unwrap();
        kernel.power(axis, true).unwrap();
        let request = MotionRequest::Position {
            target: PositionTarget::Relative { distance: 1.0e12 },
            dynamics: Dynamics {
                velocity: 1000.0,
                acceleration: 10_000.0,
                deceleration: 10_000.0,
                jerk: 0.0,
            },
        };
        kernel.issue(axis, request, BufferMode::Aborting).unwrap();
    }
    kernel
}

fn advance_all(c: &mut Criterion) {
    let mut kernel = kernel_with_moving_axes();
    // Past the acceleration phase, so the benchmark measures the steady state of a move.
    for _ in 0..1000 {
        kernel.advance_all(0.001).unwrap();
    }
    c.bench_function("advance_all, 8 axes in a move", |b| {
        b.iter(|| kernel.advance_all(black_box(0.001)).unwrap());
    });
    let mut cruising = kernel_with_moving_axes();
    for index in 0..AXES {
        let request = MotionRequest::Velocity {
            direction: motion::axis::Direction::Positive,
            dynamics: Dynamics {
                velocity: 500.0,
                acceleration: 10_000.0,
                deceleration: 10_000.0,
                jerk: 0.0,
            },
            jog: false,
        };
        let axis = motion::kernel::AxisId(index);
        cruising.issue(axis, request, BufferMode::Aborting).unwrap();
    }
    for _ in 0..1000 {
        cruising.advance_all(0.001).unwrap();
    }
    c.bench_function("advance_all, 8 axes at constant velocity", |b| {
        b.iter(|| cruising.advance_all(black_box(0.001)).unwrap());
    });
    let mut planning = kernel_with_moving_axes();
    let s_curve_axis = motion::kernel::AxisId(AXES - 1);
    let mut distance = 100.0;
    c.bench_function("issue an S-curve move while moving (planning)", |b| {
        b.iter(|| {
            distance = -distance;
            let request = MotionRequest::Position {
                target: PositionTarget::Relative { distance },
                dynamics: Dynamics {
                    velocity: 1000.0,
                    acceleration: 10_000.0,
                    deceleration: 10_000.0,
                    jerk: 50_000.0,
                },
            };
            let id = planning
                .issue(s_curve_axis, black_box(request), BufferMode::Aborting)
                .unwrap();
            planning.advance_all(0.001).unwrap();
            planning.forget(id);
        });
    });
}

criterion_group!(benches, advance_all);
criterion_main!(benches);
