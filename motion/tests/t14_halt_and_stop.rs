//! PLCopen Fig. 17 and the MC_Stop rules (digest T14): MC_Halt can be aborted by another motion
//! command, MC_Stop locks the axis until its `Execute` is FALSE.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, assert_close, powered, roomy_linear, snap};
use motion::axis::{AxisState, Direction};
use motion::fb::{Halt, MoveVelocity, Stop};
use motion::kernel::{AxisId, Kernel, MotionError};

fn move_velocity() -> MoveVelocity {
    let mut fb = MoveVelocity::default();
    fb.velocity = 50.0;
    fb.acceleration = 10.0;
    fb.deceleration = 10.0;
    fb.jerk = 0.0;
    fb.direction = Direction::Positive;
    fb
}

/// Runs the axis up to 50 u/s with `fb` and returns the kernel.
fn at_speed(fb: &mut MoveVelocity) -> (Kernel, AxisId) {
    let (mut kernel, axis) = powered(roomy_linear());
    fb.execute = true;
    for _ in 0..6000 {
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert!(fb.in_velocity && fb.busy && fb.active);
    assert_close(snap(&kernel, axis).set_velocity, 50.0);
    (kernel, axis)
}

#[test]
fn a_halt_aborted_by_move_velocity_re_accelerates_without_reaching_standstill() {
    let mut velocity = move_velocity();
    let (mut kernel, axis) = at_speed(&mut velocity);
    let mut halt = Halt::default();
    halt.deceleration = 5.0;
    halt.execute = true;
    halt.call(&mut kernel, axis);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::DiscreteMotion);
    velocity.execute = false;
    for cycle in 0..8000 {
        // After 2 s of braking at 5 u/s² (v = 40) the program triggers MC_MoveVelocity again.
        velocity.execute = cycle >= 2000;
        velocity.call(&mut kernel, axis);
        halt.call(&mut kernel, axis);
        if cycle == 1999 {
            // 1999 cycles of braking at 5 u/s² since the halt.
            assert_close(snap(&kernel, axis).set_velocity, 50.0 - 5.0 * 1.999);
            assert!(halt.busy && halt.active);
        }
        if cycle >= 2000 {
            assert!(halt.command_aborted && !halt.busy && !halt.done);
            assert_eq!(kernel.state(axis).unwrap(), AxisState::ContinuousMotion);
        }
        let snapshot = snap(&kernel, axis);
        assert_ne!(snapshot.state, AxisState::Standstill);
        assert!(
            snapshot.set_velocity > 39.0,
            "cycle {cycle}: v = {}",
            snapshot.set_velocity
        );
        kernel.advance(axis, DT_S).unwrap();
    }
    velocity.call(&mut kernel, axis);
    assert!(velocity.in_velocity);
    assert_close(snap(&kernel, axis).set_velocity, 50.0);
}

#[test]
fn a_stop_refuses_move_velocity_and_holds_stopping_until_execute_is_false() {
    let mut velocity = move_velocity();
    let (mut kernel, axis) = at_speed(&mut velocity);
    let mut stop = Stop::default();
    stop.deceleration = 5.0;
    stop.execute = true;
    stop.call(&mut kernel, axis);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Stopping);
    velocity.call(&mut kernel, axis);
    assert!(velocity.command_aborted);
    velocity.execute = false;
    let mut done_at = None;
    for cycle in 0..12_000 {
        velocity.execute = cycle >= 2000;
        velocity.call(&mut kernel, axis);
        stop.call(&mut kernel, axis);
        if cycle >= 2000 {
            assert!(velocity.error && !velocity.busy);
            assert_eq!(velocity.error_cause, Some(MotionError::AxisStopping));
            assert_eq!(velocity.error_id, 3);
        }
        if stop.done && done_at.is_none() {
            done_at = Some(cycle);
        }
        assert_eq!(kernel.state(axis).unwrap(), AxisState::Stopping);
        assert!(stop.busy, "MC_Stop holds the lock while Execute is TRUE");
        kernel.advance(axis, DT_S).unwrap();
    }
    // Braking from 50 u/s at 5 u/s² takes 10 s; Done shows at the call after the last cycle.
    assert_eq!(done_at, Some(10_000));
    assert_eq!(snap(&kernel, axis).set_velocity, 0.0);
    stop.execute = false;
    stop.call(&mut kernel, axis);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
    assert!(stop.done && !stop.busy);
    stop.call(&mut kernel, axis);
    assert!(!stop.done, "Done shows for one call once Execute is FALSE");
}

#[test]
fn a_stop_released_early_goes_to_standstill_when_it_reaches_rest() {
    let mut velocity = move_velocity();
    let (mut kernel, axis) = at_speed(&mut velocity);
    let mut stop = Stop::default();
    stop.deceleration = 50.0;
    stop.execute = true;
    stop.call(&mut kernel, axis);
    kernel.advance(axis, DT_S).unwrap();
    stop.execute = false;
    let mut done_calls = 0;
    for _ in 0..2000 {
        stop.call(&mut kernel, axis);
        if stop.done {
            done_calls += 1;
            assert!(!stop.busy);
        }
        kernel.advance(axis, DT_S).unwrap();
    }
    assert_eq!(done_calls, 1);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
}
