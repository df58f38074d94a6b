//! ContinuousUpdate (PLCopen §2.4.6) and MC_SetOverride through its FB.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, assert_close, powered, roomy_linear, snap};
use motion::axis::{AxisConfig, AxisState, Direction, SoftwareLimits};
use motion::fb::{MoveAbsolute, MoveAdditive, MoveRelative, MoveVelocity, SetOverride};

#[test]
fn a_new_position_applies_to_the_running_move_with_continuous_update() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = MoveAbsolute::default();
    fb.position = 1000.0;
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.continuous_update = true;
    fb.execute = true;
    for cycle in 0..30_000 {
        if cycle == 2000 {
            fb.position = 400.0;
            fb.velocity = 50.0;
        }
        fb.call(&mut kernel, axis);
        if cycle == 2001 {
            assert!(fb.busy && fb.active, "the same command goes on");
        }
        kernel.advance(axis, DT_S).unwrap();
        if cycle > 3500 {
            assert!(snap(&kernel, axis).set_velocity <= 50.0 + 1e-9);
        }
    }
    fb.call(&mut kernel, axis);
    assert!(fb.done);
    assert_eq!(snap(&kernel, axis).set_position, 400.0);
}

#[test]
fn without_continuous_update_later_inputs_are_ignored() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = MoveAbsolute::default();
    fb.position = 1000.0;
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.execute = true;
    for cycle in 0..30_000 {
        if cycle == 2000 {
            fb.position = 400.0;
        }
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    assert_eq!(snap(&kernel, axis).set_position, 1000.0);
}

#[test]
fn a_new_distance_counts_from_where_the_relative_move_started() {
    let (mut kernel, axis) = powered(roomy_linear());
    kernel.set_position(axis, 100.0, false).unwrap();
    let mut fb = MoveRelative::default();
    fb.distance = 1000.0;
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.continuous_update = true;
    fb.execute = true;
    for cycle in 0..30_000 {
        if cycle == 3000 {
            fb.distance = 500.0;
        }
        if cycle == 4000 {
            // FALSE freezes the values applied so far.
            fb.continuous_update = false;
            fb.distance = 10.0;
        }
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert!(fb.done);
    assert_close(snap(&kernel, axis).set_position, 600.0);
}

#[test]
fn a_new_additive_distance_replaces_the_one_added_before() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut first = MoveAbsolute::default();
    first.position = 1000.0;
    first.velocity = 100.0;
    first.acceleration = 100.0;
    first.deceleration = 100.0;
    first.execute = true;
    first.call(&mut kernel, axis);
    for _ in 0..2000 {
        kernel.advance(axis, DT_S).unwrap();
    }
    let mut additive = MoveAdditive::default();
    additive.distance = 500.0;
    additive.velocity = 100.0;
    additive.acceleration = 100.0;
    additive.deceleration = 100.0;
    additive.continuous_update = true;
    additive.execute = true;
    for cycle in 0..30_000 {
        if cycle == 1000 {
            additive.distance = 200.0;
        }
        additive.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    additive.call(&mut kernel, axis);
    assert!(additive.done);
    assert_close(snap(&kernel, axis).set_position, 1200.0);
}

#[test]
fn a_refused_update_ends_the_command_in_error_and_brakes_the_axis() {
    let mut config = roomy_linear();
    config.software_limits = Some(SoftwareLimits {
        min: -10.0,
        max: 2000.0,
    });
    let (mut kernel, axis) = powered(config);
    let mut fb = MoveAbsolute::default();
    fb.position = 1000.0;
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.continuous_update = true;
    fb.execute = true;
    for _ in 0..2000 {
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.position = 5000.0;
    fb.call(&mut kernel, axis);
    assert!(fb.error && fb.error_id == 5 && !fb.busy);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::DiscreteMotion);
    for _ in 0..2000 {
        kernel.advance(axis, DT_S).unwrap();
    }
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
    assert!(snap(&kernel, axis).set_position < 1000.0);
}

#[test]
fn a_new_velocity_applies_and_in_velocity_waits_for_it() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = MoveVelocity::default();
    fb.velocity = 100.0;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.direction = Direction::Positive;
    fb.continuous_update = true;
    fb.execute = true;
    for _ in 0..1500 {
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert!(fb.in_velocity);
    fb.velocity = 20.0;
    fb.call(&mut kernel, axis);
    assert!(!fb.in_velocity && fb.busy);
    for _ in 0..1000 {
        kernel.advance(axis, DT_S).unwrap();
        fb.call(&mut kernel, axis);
    }
    assert!(fb.in_velocity);
    assert_eq!(snap(&kernel, axis).set_velocity, 20.0);
}

#[test]
fn set_override_applies_its_factors_while_enabled_and_keeps_them_after() {
    let config = AxisConfig::linear(1000.0, 1000.0, 1000.0);
    let (mut kernel, axis) = powered(config);
    let mut velocity = MoveVelocity::default();
    velocity.velocity = 100.0;
    velocity.acceleration = 1000.0;
    velocity.deceleration = 1000.0;
    velocity.direction = Direction::Positive;
    velocity.execute = true;
    let mut over = SetOverride {
        enable: true,
        vel_factor: 0.25,
        ..SetOverride::default()
    };
    for _ in 0..1000 {
        velocity.call(&mut kernel, axis);
        over.call(&mut kernel, axis);
        assert!(over.enabled && !over.error);
        kernel.advance(axis, DT_S).unwrap();
    }
    assert_close(snap(&kernel, axis).set_velocity, 25.0);
    over.enable = false;
    over.call(&mut kernel, axis);
    assert!(!over.enabled && !over.busy);
    assert_eq!(snap(&kernel, axis).overrides.velocity, 0.25);
    over.enable = true;
    over.acc_factor = 0.0;
    over.call(&mut kernel, axis);
    assert!(over.error && over.error_id == 4 && !over.enabled);
    assert_eq!(snap(&kernel, axis).overrides.acceleration, 1.0);
}
