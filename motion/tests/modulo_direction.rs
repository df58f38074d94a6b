//! MC_MoveAbsolute on a modulo axis: `Direction` decides which way round the axis goes.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, assert_close, powered, snap};
use motion::axis::{AxisConfig, Direction};
use motion::fb::{MoveAbsolute, MoveVelocity, SetPosition};
use motion::kernel::{AxisId, Kernel};

const PERIOD: f64 = 360.0;

fn rotary() -> (Kernel, AxisId) {
    let mut config = AxisConfig::linear(1000.0, 100.0, 100.0);
    config.modulo_period = Some(PERIOD);
    powered(config)
}

/// The signed change between two wrapped positions, assuming less than half a turn per cycle.
fn unwrapped_step(from: f64, to: f64) -> f64 {
    let step = (to - from).rem_euclid(PERIOD);
    if step > PERIOD / 2.0 {
        step - PERIOD
    } else {
        step
    }
}

/// Moves from `start` at rest to `target` and returns the travelled distance and the final
/// position.
fn travel(start: f64, target: f64, direction: Direction) -> (f64, f64) {
    let (mut kernel, axis) = rotary();
    let mut set = SetPosition::default();
    set.position = start;
    set.execute = true;
    set.call(&mut kernel, axis);
    assert!(set.done);
    let mut absolute = MoveAbsolute::default();
    absolute.position = target;
    absolute.velocity = 100.0;
    absolute.acceleration = 100.0;
    absolute.deceleration = 100.0;
    absolute.direction = direction;
    absolute.execute = true;
    let mut travelled = 0.0;
    let mut position = snap(&kernel, axis).set_position;
    for _ in 0..60_000 {
        absolute.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
        let now = snap(&kernel, axis).set_position;
        assert!((0.0..PERIOD).contains(&now), "{now} is not wrapped");
        travelled += unwrapped_step(position, now);
        position = now;
    }
    absolute.call(&mut kernel, axis);
    assert!(absolute.done, "{direction:?} did not finish");
    (travelled, position)
}

#[test]
fn from_350_to_10_each_direction_takes_its_way_round() {
    let cases = [
        (Direction::Positive, 20.0),
        (Direction::Negative, -340.0),
        (Direction::Shortest, 20.0),
        (Direction::Current, 20.0),
        (Direction::Fastest, 20.0),
    ];
    for (direction, expected) in cases {
        let (travelled, end) = travel(350.0, 10.0, direction);
        assert!(
            (travelled - expected).abs() < 1e-6,
            "{direction:?}: travelled {travelled}"
        );
        assert_eq!(end, 10.0, "{direction:?}");
    }
}

#[test]
fn from_10_to_350_shortest_goes_backwards() {
    let (travelled, end) = travel(10.0, 350.0, Direction::Shortest);
    assert!((travelled + 20.0).abs() < 1e-6);
    assert_eq!(end, 350.0);
}

#[test]
fn a_target_outside_the_period_is_wrapped() {
    let (travelled, end) = travel(350.0, 370.0, Direction::Positive);
    assert!((travelled - 20.0).abs() < 1e-6);
    assert_eq!(end, 10.0);
}

/// Moves the axis negative at 100 u/s for 2 s, then to the position `ahead` units ahead in
/// the positive direction; returns the travelled distance.
fn travel_while_moving_negative(ahead: f64, direction: Direction) -> f64 {
    let (mut kernel, axis) = rotary();
    let mut velocity = MoveVelocity::default();
    velocity.velocity = 100.0;
    velocity.acceleration = 100.0;
    velocity.deceleration = 100.0;
    velocity.direction = Direction::Negative;
    velocity.execute = true;
    for _ in 0..2000 {
        velocity.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    let start = snap(&kernel, axis).set_position;
    let target = (start + ahead).rem_euclid(PERIOD);
    let mut absolute = MoveAbsolute::default();
    absolute.position = target;
    absolute.velocity = 100.0;
    absolute.acceleration = 100.0;
    absolute.deceleration = 100.0;
    absolute.direction = direction;
    absolute.execute = true;
    let mut position = start;
    let mut travelled = 0.0;
    for _ in 0..20_000 {
        absolute.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
        let now = snap(&kernel, axis).set_position;
        travelled += unwrapped_step(position, now);
        position = now;
    }
    absolute.call(&mut kernel, axis);
    assert!(absolute.done);
    assert_close(position, target);
    travelled
}

#[test]
fn current_keeps_the_direction_of_motion() {
    let travelled = travel_while_moving_negative(20.0, Direction::Current);
    assert!((travelled + 340.0).abs() < 1e-6, "travelled {travelled}");
}

#[test]
fn fastest_weighs_the_reversal_against_the_longer_way() {
    // 20 u ahead: braking (1 s, 50 u) and coming back 70 u takes 2.2 s, going 340 u on takes
    // 3.9 s, so the axis reverses.
    let travelled = travel_while_moving_negative(20.0, Direction::Fastest);
    assert!((travelled - 20.0).abs() < 1e-6, "travelled {travelled}");
    // 150 u ahead: reversing takes 1 s + 2.5 s, going 210 u on takes 2.6 s, so the axis keeps
    // its direction although the positive way is shorter.
    let travelled = travel_while_moving_negative(150.0, Direction::Fastest);
    assert!((travelled + 210.0).abs() < 1e-6, "travelled {travelled}");
    let travelled = travel_while_moving_negative(150.0, Direction::Shortest);
    assert!((travelled - 150.0).abs() < 1e-6, "travelled {travelled}");
}

#[test]
fn move_velocity_refuses_the_shortest_direction() {
    let (mut kernel, axis) = rotary();
    let mut velocity = MoveVelocity::default();
    velocity.velocity = 10.0;
    velocity.acceleration = 10.0;
    velocity.deceleration = 10.0;
    velocity.direction = Direction::Shortest;
    velocity.execute = true;
    velocity.call(&mut kernel, axis);
    assert!(velocity.error && velocity.error_id == 4);
}
