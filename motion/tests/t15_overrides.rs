//! PLCopen Fig. 36 (digest T15): override factors act on the running motion at once.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, assert_close, powered, roomy_linear, snap};
use motion::axis::{AxisState, Direction, Overrides};
use motion::fb::{MoveAbsolute, MoveVelocity};
use motion::kernel::{AxisId, Kernel, MotionError};

fn factors(velocity: f64, acceleration: f64) -> Overrides {
    Overrides {
        velocity,
        acceleration,
        jerk: 1.0,
    }
}

fn cycles(kernel: &mut Kernel, axis: AxisId, fb: &mut MoveVelocity, count: usize) {
    for _ in 0..count {
        fb.call(kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
}

#[test]
fn velocity_and_acceleration_factors_reshape_a_running_move_velocity() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = MoveVelocity::default();
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.direction = Direction::Positive;
    fb.execute = true;
    cycles(&mut kernel, axis, &mut fb, 1500);
    assert_close(snap(&kernel, axis).set_velocity, 100.0);

    // VelFactor 0.5: down to 50 u/s at the full deceleration, 0.5 s.
    kernel.set_override(axis, factors(0.5, 1.0)).unwrap();
    cycles(&mut kernel, axis, &mut fb, 250);
    assert_close(snap(&kernel, axis).set_velocity, 75.0);
    cycles(&mut kernel, axis, &mut fb, 250);
    assert_close(snap(&kernel, axis).set_velocity, 50.0);
    assert!(fb.in_velocity, "InVelocity stays once reached");

    // AccFactor 0.5, then VelFactor 1.0: back to 100 u/s at half the acceleration, 1 s.
    kernel.set_override(axis, factors(0.5, 0.5)).unwrap();
    kernel.set_override(axis, factors(1.0, 0.5)).unwrap();
    cycles(&mut kernel, axis, &mut fb, 500);
    assert_close(snap(&kernel, axis).set_velocity, 75.0);
    cycles(&mut kernel, axis, &mut fb, 500);
    assert_close(snap(&kernel, axis).set_velocity, 100.0);

    // VelFactor 0: to rest at the full deceleration, 1 s, and the state is not Standstill.
    kernel.set_override(axis, factors(0.0, 1.0)).unwrap();
    cycles(&mut kernel, axis, &mut fb, 1000);
    assert_eq!(snap(&kernel, axis).set_velocity, 0.0);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::ContinuousMotion);
    assert!(fb.busy && fb.active);

    // AccFactor 0 is refused and the factors stay.
    let refused = kernel.set_override(axis, factors(1.0, 0.0));
    assert!(matches!(
        refused,
        Err(MotionError::InvalidParameter {
            input: "AccFactor",
            ..
        })
    ));
    assert_eq!(snap(&kernel, axis).overrides, factors(0.0, 1.0));
}

#[test]
fn a_move_held_by_a_zero_velocity_factor_resumes_and_ends_exactly() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = MoveAbsolute::default();
    fb.position = 1000.0;
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.execute = true;
    for cycle in 0..30_000 {
        if cycle == 3000 {
            kernel.set_override(axis, factors(0.0, 1.0)).unwrap();
        }
        if cycle == 6000 {
            assert_eq!(snap(&kernel, axis).set_velocity, 0.0);
            assert!(fb.busy && !fb.done, "a held move is not finished");
            kernel.set_override(axis, factors(1.0, 1.0)).unwrap();
        }
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert!(fb.done);
    assert_eq!(snap(&kernel, axis).set_position, 1000.0);
}
