//! The PLCopen state diagram with its Notes 1–6, walked through with the FBs (digest T25).

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, roomy_linear, snap};
use motion::axis::{AxisState, Direction};
use motion::fb::{Home, MoveAbsolute, MoveVelocity, Power, ReadAxisError, ReadStatus, Reset, Stop};
use motion::kernel::{AxisId, Kernel, MotionError};

/// Checks the state and that MC_ReadStatus shows it as its only flag.
#[track_caller]
fn expect_state(kernel: &Kernel, axis: AxisId, state: AxisState) {
    assert_eq!(kernel.state(axis).unwrap(), state);
    let mut status = ReadStatus {
        enable: true,
        ..ReadStatus::default()
    };
    status.call(kernel, axis);
    let flags = [
        (status.disabled, AxisState::PowerOff),
        (status.error_stop, AxisState::ErrorStop),
        (status.stopping, AxisState::Stopping),
        (status.standstill, AxisState::Standstill),
        (status.discrete_motion, AxisState::DiscreteMotion),
        (status.continuous_motion, AxisState::ContinuousMotion),
        (status.synchronized_motion, AxisState::SynchronizedMotion),
        (status.homing, AxisState::Homing),
    ];
    assert!(status.valid);
    assert_eq!(flags.iter().filter(|flag| flag.0).count(), 1);
    assert!(flags.iter().any(|flag| flag.0 && flag.1 == state));
}

fn cycles(kernel: &mut Kernel, axis: AxisId, count: usize, mut each: impl FnMut(&mut Kernel)) {
    for _ in 0..count {
        each(kernel);
        kernel.advance(axis, DT_S).unwrap();
    }
}

#[test]
fn the_state_diagram_sequence_of_the_digest() {
    let mut kernel = Kernel::new();
    let axis = kernel.add_axis(roomy_linear()).unwrap();
    expect_state(&kernel, axis, AxisState::PowerOff);
    assert_eq!(AxisState::PowerOff.code(), 0);

    let mut power = Power {
        enable: true,
        ..Power::default()
    };
    power.call(&mut kernel, axis);
    assert!(power.status && power.valid && !power.error);
    expect_state(&kernel, axis, AxisState::Standstill);

    let mut velocity = MoveVelocity::default();
    velocity.velocity = 100.0;
    velocity.acceleration = 1000.0;
    velocity.deceleration = 1000.0;
    velocity.direction = Direction::Positive;
    velocity.execute = true;
    velocity.call(&mut kernel, axis);
    expect_state(&kernel, axis, AxisState::ContinuousMotion);
    cycles(&mut kernel, axis, 50, |kernel| velocity.call(kernel, axis));

    // Note 1: an axis error takes any state to ErrorStop; the running command ends in Error.
    kernel.inject_error(axis, 42).unwrap();
    expect_state(&kernel, axis, AxisState::ErrorStop);
    velocity.call(&mut kernel, axis);
    assert!(velocity.error && !velocity.busy);
    assert_eq!(
        velocity.error_cause,
        Some(MotionError::AxisError { axis_error_id: 42 })
    );
    let mut axis_error = ReadAxisError {
        enable: true,
        ..ReadAxisError::default()
    };
    axis_error.call(&kernel, axis);
    assert_eq!(axis_error.axis_error_id, 42);

    // A motion command in ErrorStop is refused and nothing moves.
    let mut absolute = MoveAbsolute::default();
    absolute.position = 500.0;
    absolute.velocity = 100.0;
    absolute.acceleration = 1000.0;
    absolute.deceleration = 1000.0;
    absolute.execute = true;
    absolute.call(&mut kernel, axis);
    assert!(absolute.error && absolute.error_id == 2);
    expect_state(&kernel, axis, AxisState::ErrorStop);

    // Note 4: MC_Reset with the power on returns to Standstill once the error ramp is at rest.
    let mut reset = Reset::default();
    reset.execute = true;
    reset.call(&mut kernel, axis);
    assert!(reset.busy, "the error stop ramp still brakes");
    cycles(&mut kernel, axis, 200, |kernel| reset.call(kernel, axis));
    reset.call(&mut kernel, axis);
    assert!(reset.done);
    expect_state(&kernel, axis, AxisState::Standstill);
    assert_eq!(snap(&kernel, axis).set_velocity, 0.0);
    axis_error.call(&kernel, axis);
    assert_eq!(axis_error.axis_error_id, 0);

    // Note 2: MC_Power.Enable FALSE takes the axis to Disabled; Note 5 back to Standstill.
    power.enable = false;
    power.call(&mut kernel, axis);
    assert!(!power.status && !power.valid);
    expect_state(&kernel, axis, AxisState::PowerOff);
    power.enable = true;
    power.call(&mut kernel, axis);
    expect_state(&kernel, axis, AxisState::Standstill);

    // MC_Home is refused in ContinuousMotion and the state stays.
    velocity.execute = false;
    velocity.call(&mut kernel, axis);
    velocity.execute = true;
    velocity.call(&mut kernel, axis);
    expect_state(&kernel, axis, AxisState::ContinuousMotion);
    let mut home = Home::default();
    home.execute = true;
    home.call(&mut kernel, axis);
    assert!(home.error && home.error_id == 6);
    expect_state(&kernel, axis, AxisState::ContinuousMotion);

    // MC_Stop: Stopping; Note 6: Standstill once Done and Execute FALSE.
    let mut stop = Stop::default();
    stop.deceleration = 1000.0;
    stop.execute = true;
    stop.call(&mut kernel, axis);
    expect_state(&kernel, axis, AxisState::Stopping);
    cycles(&mut kernel, axis, 500, |kernel| stop.call(kernel, axis));
    stop.call(&mut kernel, axis);
    assert!(stop.done);
    expect_state(&kernel, axis, AxisState::Stopping);
    stop.execute = false;
    stop.call(&mut kernel, axis);
    expect_state(&kernel, axis, AxisState::Standstill);

    // MC_Home from Standstill passes through Homing.
    home.execute = false;
    home.call(&mut kernel, axis);
    home.position = 123.0;
    home.execute = true;
    home.call(&mut kernel, axis);
    expect_state(&kernel, axis, AxisState::Homing);
    assert!(home.busy && home.active);
    kernel.advance(axis, DT_S).unwrap();
    home.call(&mut kernel, axis);
    assert!(home.done);
    expect_state(&kernel, axis, AxisState::Standstill);
    let snapshot = snap(&kernel, axis);
    assert!(snapshot.is_homed);
    assert_eq!(snapshot.set_position, 123.0);
}

#[test]
fn a_reset_with_the_power_off_goes_to_disabled() {
    let mut kernel = Kernel::new();
    let axis = kernel.add_axis(roomy_linear()).unwrap();
    kernel.power(axis, true).unwrap();
    kernel.inject_error(axis, 7).unwrap();
    expect_state(&kernel, axis, AxisState::ErrorStop);
    // Switching the power off does not leave ErrorStop (Note 2 needs no axis error).
    kernel.power(axis, false).unwrap();
    expect_state(&kernel, axis, AxisState::ErrorStop);
    // Note 3: MC_Reset with Status FALSE goes to Disabled.
    let mut reset = Reset::default();
    reset.execute = true;
    reset.call(&mut kernel, axis);
    assert!(reset.done);
    expect_state(&kernel, axis, AxisState::PowerOff);
}

#[test]
fn commands_on_a_disabled_axis_are_refused_with_not_powered() {
    let mut kernel = Kernel::new();
    let axis = kernel.add_axis(roomy_linear()).unwrap();
    let mut absolute = MoveAbsolute::default();
    absolute.position = 10.0;
    absolute.velocity = 1.0;
    absolute.acceleration = 1.0;
    absolute.deceleration = 1.0;
    absolute.execute = true;
    absolute.call(&mut kernel, axis);
    assert!(absolute.error && absolute.error_id == 1);
    let mut stop = Stop::default();
    stop.deceleration = 1.0;
    stop.execute = true;
    stop.call(&mut kernel, axis);
    assert!(stop.error && stop.error_id == 1);
    expect_state(&kernel, axis, AxisState::PowerOff);
}

#[test]
fn switching_the_power_off_aborts_the_running_command() {
    let mut kernel = Kernel::new();
    let axis = kernel.add_axis(roomy_linear()).unwrap();
    kernel.power(axis, true).unwrap();
    let mut absolute = MoveAbsolute::default();
    absolute.position = 1000.0;
    absolute.velocity = 100.0;
    absolute.acceleration = 100.0;
    absolute.deceleration = 100.0;
    absolute.execute = true;
    absolute.call(&mut kernel, axis);
    cycles(&mut kernel, axis, 100, |kernel| absolute.call(kernel, axis));
    kernel.power(axis, false).unwrap();
    absolute.call(&mut kernel, axis);
    assert!(absolute.command_aborted);
    expect_state(&kernel, axis, AxisState::PowerOff);
    assert_eq!(snap(&kernel, axis).set_velocity, 0.0);
}

#[test]
fn a_reset_waiting_for_the_error_ramp_finishes_when_the_power_goes_off() {
    let mut kernel = Kernel::new();
    let axis = kernel.add_axis(roomy_linear()).unwrap();
    kernel.power(axis, true).unwrap();
    let mut velocity = MoveVelocity::default();
    velocity.velocity = 1000.0;
    velocity.acceleration = 10_000.0;
    velocity.deceleration = 10_000.0;
    velocity.direction = Direction::Positive;
    velocity.execute = true;
    cycles(&mut kernel, axis, 500, |kernel| velocity.call(kernel, axis));
    kernel.inject_error(axis, 3).unwrap();
    let mut reset = Reset::default();
    reset.execute = true;
    reset.call(&mut kernel, axis);
    assert!(reset.busy);
    kernel.power(axis, false).unwrap();
    reset.call(&mut kernel, axis);
    assert!(reset.done && !reset.busy);
    expect_state(&kernel, axis, AxisState::PowerOff);
}
