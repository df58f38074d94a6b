//! The general FB rules of PLCopen §2.4.1 and the behaviour of each FB beyond the worked
//! examples.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, powered, roomy_linear, snap};
use motion::axis::{AxisConfig, AxisState, SoftwareLimits};
use motion::fb::{
    Halt, Home, Jog, MoveAbsolute, MoveAdditive, MoveRelative, MoveVelocity, Power,
    ReadActualPosition, ReadActualVelocity, SetPosition,
};
use motion::kernel::{AXIS_ERROR_SOFTWARE_LIMIT, AxisId, Kernel, MotionError};

fn relative(distance: f64) -> MoveRelative {
    let mut fb = MoveRelative::default();
    fb.distance = distance;
    fb.velocity = 100.0;
    fb.acceleration = 1000.0;
    fb.deceleration = 1000.0;
    fb
}

fn absolute(position: f64) -> MoveAbsolute {
    let mut fb = MoveAbsolute::default();
    fb.position = position;
    fb.velocity = 100.0;
    fb.acceleration = 1000.0;
    fb.deceleration = 1000.0;
    fb
}

fn limited_axis() -> (Kernel, AxisId) {
    let mut config = roomy_linear();
    config.software_limits = Some(SoftwareLimits {
        min: -100.0,
        max: 100.0,
    });
    powered(config)
}

#[test]
fn done_after_an_execute_pulse_shows_for_exactly_one_call() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = relative(10.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    fb.execute = false;
    let mut done_calls = 0;
    for _ in 0..1000 {
        kernel.advance(axis, DT_S).unwrap();
        fb.call(&mut kernel, axis);
        done_calls += usize::from(fb.done);
        assert!(!(fb.done && fb.busy));
    }
    assert_eq!(done_calls, 1);
    assert_eq!(snap(&kernel, axis).set_position, 10.0);
}

#[test]
fn done_stays_while_execute_is_true_and_resets_at_the_first_call_with_execute_false() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = relative(10.0);
    fb.execute = true;
    for _ in 0..1000 {
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert!(fb.done && !fb.busy && !fb.active);
    fb.call(&mut kernel, axis);
    assert!(fb.done);
    fb.execute = false;
    fb.call(&mut kernel, axis);
    assert!(!fb.done);
}

#[test]
fn a_rising_edge_while_busy_is_ignored() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = absolute(100.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    kernel.advance(axis, DT_S).unwrap();
    fb.execute = false;
    fb.call(&mut kernel, axis);
    kernel.advance(axis, DT_S).unwrap();
    fb.position = 200.0;
    fb.execute = true;
    for _ in 0..5000 {
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert!(fb.done);
    assert_eq!(snap(&kernel, axis).set_position, 100.0);
}

#[test]
fn a_falling_execute_does_not_stop_the_command() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = relative(50.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    fb.execute = false;
    for _ in 0..100 {
        fb.call(&mut kernel, axis);
        assert!(fb.busy && fb.active);
        kernel.advance(axis, DT_S).unwrap();
    }
    assert!(snap(&kernel, axis).set_velocity > 0.0);
}

#[test]
fn an_invalid_input_is_refused_with_its_name_and_nothing_moves() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = absolute(10.0);
    fb.velocity = 0.0;
    fb.execute = true;
    fb.call(&mut kernel, axis);
    assert!(fb.error && !fb.busy && fb.error_id == 4);
    let cause = fb.error_cause.unwrap();
    assert!(matches!(
        cause,
        MotionError::InvalidParameter {
            input: "Velocity",
            ..
        }
    ));
    assert!(cause.to_string().contains("Velocity"));
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
    // A velocity above the axis's maximum is refused too.
    let mut fast = absolute(10.0);
    fast.velocity = 1.0e9;
    fast.execute = true;
    fast.call(&mut kernel, axis);
    assert!(fast.error && fast.error_id == 4);
}

#[test]
fn an_error_after_an_execute_pulse_shows_for_exactly_one_call() {
    let (mut kernel, axis) = limited_axis();
    let mut fb = absolute(500.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    assert!(fb.error);
    fb.execute = false;
    fb.call(&mut kernel, axis);
    assert!(!fb.error && fb.error_id == 0);
}

#[test]
fn a_target_outside_the_software_limits_is_refused_without_motion() {
    let (mut kernel, axis) = limited_axis();
    let mut fb = absolute(150.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    assert!(fb.error && fb.error_id == 5);
    let mut rel = relative(-101.0);
    rel.execute = true;
    rel.call(&mut kernel, axis);
    assert!(rel.error && rel.error_id == 5);
    kernel.advance(axis, DT_S).unwrap();
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
    assert_eq!(snap(&kernel, axis).set_position, 0.0);
}

#[test]
fn a_refused_aborting_command_leaves_the_running_one_in_control() {
    let (mut kernel, axis) = limited_axis();
    let mut first = absolute(90.0);
    first.execute = true;
    first.call(&mut kernel, axis);
    kernel.advance(axis, DT_S).unwrap();
    let mut second = absolute(150.0);
    second.execute = true;
    second.call(&mut kernel, axis);
    assert!(second.error);
    for _ in 0..3000 {
        first.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    first.call(&mut kernel, axis);
    assert!(first.done);
    assert_eq!(snap(&kernel, axis).set_position, 90.0);
}

#[test]
fn running_into_a_software_limit_is_an_axis_error() {
    let (mut kernel, axis) = limited_axis();
    let mut fb = MoveVelocity::default();
    fb.velocity = 100.0;
    fb.acceleration = 1000.0;
    fb.deceleration = 1000.0;
    fb.direction = motion::axis::Direction::Positive;
    fb.execute = true;
    for _ in 0..3000 {
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    fb.call(&mut kernel, axis);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::ErrorStop);
    let snapshot = snap(&kernel, axis);
    assert_eq!(snapshot.axis_error_id, AXIS_ERROR_SOFTWARE_LIMIT);
    assert_eq!(snapshot.set_velocity, 0.0);
    assert!(fb.error && fb.error_id == 8);
}

#[test]
fn move_additive_from_standstill_adds_to_the_set_position_after_a_halt() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut first = absolute(1000.0);
    first.execute = true;
    first.call(&mut kernel, axis);
    for _ in 0..500 {
        kernel.advance(axis, DT_S).unwrap();
    }
    let mut halt = Halt::default();
    halt.deceleration = 1000.0;
    halt.execute = true;
    halt.call(&mut kernel, axis);
    for _ in 0..500 {
        halt.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    halt.call(&mut kernel, axis);
    assert!(halt.done);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
    let stopped_at = snap(&kernel, axis).set_position;
    let mut additive = MoveAdditive::default();
    additive.distance = 10.0;
    additive.velocity = 100.0;
    additive.acceleration = 1000.0;
    additive.deceleration = 1000.0;
    additive.execute = true;
    for _ in 0..1000 {
        additive.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    additive.call(&mut kernel, axis);
    assert!(additive.done);
    assert_eq!(snap(&kernel, axis).set_position, stopped_at + 10.0);
}

#[test]
fn set_position_finishes_at_once_in_standstill_and_is_refused_while_moving() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut set = SetPosition::default();
    set.position = 42.0;
    set.execute = true;
    set.call(&mut kernel, axis);
    assert!(set.done && !set.busy);
    assert_eq!(snap(&kernel, axis).set_position, 42.0);
    set.execute = false;
    set.call(&mut kernel, axis);
    set.position = -2.0;
    set.relative = true;
    set.execute = true;
    set.call(&mut kernel, axis);
    assert_eq!(snap(&kernel, axis).set_position, 40.0);
    let mut fb = relative(100.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    set.execute = false;
    set.call(&mut kernel, axis);
    set.execute = true;
    set.call(&mut kernel, axis);
    assert!(set.error && set.error_id == 6);
}

#[test]
fn home_outside_the_software_limits_is_refused() {
    let (mut kernel, axis) = limited_axis();
    let mut home = Home::default();
    home.position = 1000.0;
    home.execute = true;
    home.call(&mut kernel, axis);
    assert!(home.error && home.error_id == 5);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
}

#[test]
fn jog_moves_while_held_brakes_when_released_and_shows_done_once() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut jog = Jog::default();
    jog.velocity = 50.0;
    jog.acceleration = 500.0;
    jog.deceleration = 500.0;
    jog.jog_forward = true;
    for _ in 0..500 {
        jog.call(&mut kernel, axis);
        assert!(jog.busy && !jog.done);
        kernel.advance(axis, DT_S).unwrap();
    }
    assert_eq!(kernel.state(axis).unwrap(), AxisState::ContinuousMotion);
    assert_eq!(snap(&kernel, axis).set_velocity, 50.0);
    assert_eq!(snap(&kernel, axis).active_command, Some("MC_Jog"));
    // Switching to backward reverses without a stop in between.
    jog.jog_forward = false;
    jog.jog_backward = true;
    for _ in 0..500 {
        jog.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    assert_eq!(snap(&kernel, axis).set_velocity, -50.0);
    jog.jog_backward = false;
    jog.call(&mut kernel, axis);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::DiscreteMotion);
    let mut done_calls = 0;
    for _ in 0..500 {
        kernel.advance(axis, DT_S).unwrap();
        jog.call(&mut kernel, axis);
        done_calls += usize::from(jog.done);
        assert!(!(jog.done && jog.busy));
    }
    assert_eq!(done_calls, 1);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
    assert!(!jog.command_aborted && !jog.error);
}

#[test]
fn jog_taken_over_by_another_command_shows_command_aborted() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut jog = Jog::default();
    jog.velocity = 50.0;
    jog.acceleration = 500.0;
    jog.deceleration = 500.0;
    jog.jog_forward = true;
    jog.call(&mut kernel, axis);
    kernel.advance(axis, DT_S).unwrap();
    let mut fb = absolute(0.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    jog.call(&mut kernel, axis);
    assert!(jog.command_aborted && !jog.busy);
}

#[test]
fn the_read_fbs_are_valid_while_enabled_and_report_an_unknown_axis() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = relative(100.0);
    fb.execute = true;
    fb.call(&mut kernel, axis);
    for _ in 0..200 {
        kernel.advance(axis, DT_S).unwrap();
    }
    let mut position = ReadActualPosition::default();
    let mut velocity = ReadActualVelocity::default();
    position.enable = true;
    velocity.enable = true;
    position.call(&kernel, axis);
    velocity.call(&kernel, axis);
    assert!(position.valid && !position.error && position.busy);
    assert_eq!(position.position, snap(&kernel, axis).actual_position);
    assert_eq!(velocity.velocity, 100.0);
    position.enable = false;
    position.call(&kernel, axis);
    assert!(!position.valid && !position.busy);
    let unknown = AxisId(9);
    position.enable = true;
    position.call(&kernel, unknown);
    assert!(position.error && !position.valid && position.error_id == 9);
    let mut power = Power {
        enable: true,
        ..Power::default()
    };
    power.call(&mut kernel, unknown);
    assert!(power.error && !power.valid && !power.status);
    power.enable = false;
    power.call(&mut kernel, unknown);
    assert!(!power.error && power.error_id == 0);
}

#[test]
fn a_configuration_without_limits_is_refused() {
    let mut kernel = Kernel::new();
    let refused = kernel.add_axis(AxisConfig::linear(0.0, 1.0, 1.0));
    assert!(refused.unwrap_err().to_string().contains("max_velocity"));
    let mut config = AxisConfig::linear(1.0, 1.0, 1.0);
    config.modulo_period = Some(-1.0);
    assert!(kernel.add_axis(config).is_err());
}

#[test]
fn finished_commands_do_not_pile_up_in_the_kernel() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb = relative(1.0);
    for cycle in 0..20_000 {
        fb.execute = cycle % 100 < 50;
        fb.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    assert!(kernel.recorded_commands() <= 1);
    assert!(snap(&kernel, axis).set_position >= 199.0);
}
