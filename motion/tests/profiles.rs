//! The profile generator through the kernel: trapezoid and S-curve respect their limits and
//! end exactly at the target, also when a move takes over a moving, accelerating axis.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, powered, snap};
use motion::axis::{AxisConfig, Profile, ProfileLimits};
use motion::kernel::{BufferMode, CommandStatus, Dynamics, MotionRequest, PositionTarget};
use proptest::prelude::*;

/// The extremes seen while an axis runs a move to its end.
struct Trace {
    end: f64,
    max_speed: f64,
    max_acceleration: f64,
    max_jerk: f64,
    max_position: f64,
    min_position: f64,
}

/// Runs a move of `distance` on a fresh axis with the jerk limit `axis_jerk` (after `lead_in` cycles of a velocity command
/// when `lead_in` > 0) and records the extremes after the move has taken over.
fn trace_move(distance: f64, dynamics: Dynamics, axis_jerk: f64, lead_in: usize) -> Trace {
    let mut config = AxisConfig::linear(1.0e6, 1.0e6, 1.0e6);
    config.max_jerk = axis_jerk;
    let (mut kernel, axis) = powered(config);
    if lead_in > 0 {
        let lead = MotionRequest::Velocity {
            direction: motion::axis::Direction::Positive,
            dynamics: Dynamics {
                velocity: dynamics.velocity,
                ..dynamics
            },
            jog: false,
        };
        kernel.issue(axis, lead, BufferMode::Aborting).unwrap();
        for _ in 0..lead_in {
            kernel.advance(axis, DT_S).unwrap();
        }
    }
    let start = snap(&kernel, axis);
    let request = MotionRequest::Position {
        target: PositionTarget::Absolute {
            position: start.set_position + distance,
            direction: motion::axis::Direction::Shortest,
        },
        dynamics,
    };
    let id = kernel.issue(axis, request, BufferMode::Aborting).unwrap();
    let target = start.set_position + distance;
    let mut trace = Trace {
        end: f64::NAN,
        max_speed: 0.0,
        max_acceleration: 0.0,
        max_jerk: 0.0,
        max_position: start.set_position,
        min_position: start.set_position,
    };
    let mut previous_acceleration = start.set_acceleration;
    for _ in 0..2_000_000 {
        kernel.advance(axis, DT_S).unwrap();
        let now = snap(&kernel, axis);
        trace.max_speed = trace.max_speed.max(now.set_velocity.abs());
        trace.max_acceleration = trace.max_acceleration.max(now.set_acceleration.abs());
        trace.max_jerk = trace
            .max_jerk
            .max((now.set_acceleration - previous_acceleration).abs() / DT_S);
        trace.max_position = trace.max_position.max(now.set_position);
        trace.min_position = trace.min_position.min(now.set_position);
        previous_acceleration = now.set_acceleration;
        if kernel.command_status(id) == Some(CommandStatus::Done) {
            trace.end = now.set_position;
            assert_eq!(now.set_velocity, 0.0);
            assert_eq!(now.set_acceleration, 0.0);
            break;
        }
    }
    assert_eq!(trace.end, target, "the move ends exactly at its target");
    trace
}

#[test]
fn an_s_curve_keeps_jerk_acceleration_and_velocity_within_the_limits() {
    let dynamics = Dynamics {
        velocity: 100.0,
        acceleration: 400.0,
        deceleration: 200.0,
        jerk: 2000.0,
    };
    for distance in [1000.0, 50.0, 5.0, 0.3, -1000.0, -7.0] {
        let trace = trace_move(distance, dynamics, 1.0e9, 0);
        assert!(
            trace.max_speed <= 100.0 * (1.0 + 1e-12),
            "{distance}: {}",
            trace.max_speed
        );
        assert!(trace.max_acceleration <= 400.0 * (1.0 + 1e-12));
        // The final cycle sets the acceleration from its last tiny value to exactly 0.
        assert!(
            trace.max_jerk <= 2000.0 * (1.0 + 1e-9),
            "{distance}: jerk {}",
            trace.max_jerk
        );
        let (low, high) = if distance > 0.0 {
            (0.0, distance)
        } else {
            (distance, 0.0)
        };
        assert!(trace.min_position >= low - 1e-9 && trace.max_position <= high + 1e-9);
    }
}

#[test]
fn an_s_curve_taking_over_an_accelerating_axis_keeps_the_jerk_limit() {
    let dynamics = Dynamics {
        velocity: 100.0,
        acceleration: 400.0,
        deceleration: 400.0,
        jerk: 2000.0,
    };
    // 150 cycles in, the velocity command is still ramping its acceleration.
    for distance in [500.0, 20.0, -30.0] {
        let trace = trace_move(distance, dynamics, 1.0e9, 150);
        assert!(
            trace.max_jerk <= 2000.0 * (1.0 + 1e-9),
            "{distance}: jerk {}",
            trace.max_jerk
        );
        assert!(trace.max_acceleration <= 400.0 * (1.0 + 1e-12));
    }
}

#[test]
fn a_trapezoid_never_overshoots_and_ends_exactly() {
    let dynamics = Dynamics {
        velocity: 250.0,
        acceleration: 1000.0,
        deceleration: 3000.0,
        jerk: 0.0,
    };
    for distance in [10_000.0, 12.345, 0.001, -333.3] {
        // Neither the command nor the axis limits the jerk: a trapezoid.
        let trace = trace_move(distance, dynamics, 0.0, 0);
        let (low, high) = if distance > 0.0 {
            (0.0, distance)
        } else {
            (distance, 0.0)
        };
        let tolerance = 1e-9 * distance.abs();
        assert!(
            trace.min_position >= low - tolerance,
            "{distance}: {}",
            trace.min_position
        );
        assert!(
            trace.max_position <= high + tolerance,
            "{distance}: {}",
            trace.max_position
        );
        assert!(trace.max_speed <= 250.0 * (1.0 + 1e-12));
        assert!(trace.max_acceleration <= 3000.0 * (1.0 + 1e-12));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Whatever the start, a profile to a position ends there exactly and stays within its
    /// acceleration and jerk limits once its initial acceleration has settled.
    #[test]
    fn a_position_profile_ends_exactly_and_respects_its_limits(
        distance in -1.0e4f64..1.0e4,
        velocity in -200.0f64..200.0,
        acceleration in -50.0f64..50.0,
        cruise in 1.0f64..300.0,
        accel_limit in 10.0f64..1000.0,
        decel_limit in 10.0f64..1000.0,
        jerk in prop_oneof![Just(0.0), 100.0f64..10_000.0],
    ) {
        let limits = ProfileLimits {
            velocity: cruise,
            acceleration: accel_limit,
            deceleration: decel_limit,
            jerk,
            recovery_jerk: jerk,
        };
        let profile = Profile::to_position(distance, velocity, acceleration, limits);
        let end = profile.sample(profile.duration_s());
        prop_assert_eq!(end.displacement, distance);
        prop_assert_eq!(end.velocity, 0.0);
        let just_before = profile.sample(profile.duration_s() * (1.0 - 1e-12));
        prop_assert!((just_before.displacement - distance).abs() <= 1e-6 * distance.abs().max(1.0),
            "before the end {} vs {}", just_before.displacement, distance);
        let steps = 2000;
        let bound = accel_limit.max(decel_limit).max(acceleration.abs()) * (1.0 + 1e-9);
        for step in 0..=steps {
            let time_s = profile.duration_s() * f64::from(step) / f64::from(steps);
            let sample = profile.sample(time_s);
            prop_assert!(sample.acceleration.abs() <= bound, "a = {} at {}", sample.acceleration, time_s);
            if jerk > 0.0 {
                prop_assert!(sample.jerk.abs() <= jerk * (1.0 + 1e-12));
            }
        }
    }

    /// A profile to a velocity ends at that velocity and keeps it.
    #[test]
    fn a_velocity_profile_reaches_and_keeps_its_velocity(
        target in -300.0f64..300.0,
        velocity in -300.0f64..300.0,
        acceleration in -50.0f64..50.0,
        jerk in prop_oneof![Just(0.0), 100.0f64..10_000.0],
    ) {
        let limits = ProfileLimits { velocity: 300.0, acceleration: 100.0, deceleration: 200.0, jerk, recovery_jerk: jerk };
        let profile = Profile::to_velocity(target, velocity, acceleration, limits);
        prop_assert_eq!(profile.sample(profile.duration_s()).velocity, target);
        prop_assert_eq!(profile.sample(profile.duration_s() + 10.0).velocity, target);
    }
}

/// One aborting MC_MoveAbsolute of a random program: when it is issued and what it asks for.
#[derive(Clone, Copy, Debug)]
struct RandomMove {
    after_cycles: usize,
    target: f64,
    velocity: f64,
    acceleration: f64,
    jerk: f64,
}

fn random_moves(s_curve: bool) -> impl Strategy<Value = Vec<RandomMove>> {
    let jerk = if s_curve {
        500.0f64..20_000.0
    } else {
        0.0f64..f64::MIN_POSITIVE
    };
    prop::collection::vec(
        (
            1usize..3000,
            -500.0f64..500.0,
            5.0f64..200.0,
            50.0f64..2000.0,
            jerk,
        )
            .prop_map(
                |(after_cycles, target, velocity, acceleration, jerk)| RandomMove {
                    after_cycles,
                    target,
                    velocity,
                    acceleration,
                    jerk: if jerk < 1.0 { 0.0 } else { jerk },
                },
            ),
        1..8,
    )
}

/// Runs moves that abort each other at random times; checks the limits every cycle and the
/// exact end on the last target.
fn run_random_moves(moves: &[RandomMove], axis_jerk: f64) -> Result<(), TestCaseError> {
    let max_velocity = 1000.0;
    let mut config = AxisConfig::linear(max_velocity, 5000.0, 5000.0);
    config.max_jerk = axis_jerk;
    let (mut kernel, axis) = powered(config);
    let highest_acceleration = moves.iter().map(|m| m.acceleration).fold(0.0, f64::max);
    let highest_jerk = moves.iter().map(|m| m.jerk).fold(0.0, f64::max);
    let mut previous_acceleration = 0.0;
    let mut last = None;
    for (index, one) in moves.iter().enumerate() {
        let request = MotionRequest::Position {
            target: PositionTarget::Absolute {
                position: one.target,
                direction: motion::axis::Direction::Shortest,
            },
            dynamics: Dynamics {
                velocity: one.velocity,
                acceleration: one.acceleration,
                deceleration: one.acceleration,
                jerk: one.jerk,
            },
        };
        let id = kernel.issue(axis, request, BufferMode::Aborting).unwrap();
        last = Some((id, one.target));
        let cycles = if index + 1 == moves.len() {
            400_000
        } else {
            one.after_cycles
        };
        for _ in 0..cycles {
            kernel.advance(axis, DT_S).unwrap();
            let now = snap(&kernel, axis);
            prop_assert!(now.set_acceleration.abs() <= highest_acceleration * (1.0 + 1e-9));
            prop_assert!(now.set_velocity.abs() <= max_velocity);
            if axis_jerk > 0.0 {
                let jerk = (now.set_acceleration - previous_acceleration).abs() / DT_S;
                // An acceleration above the command's limit, left by a harder aborted ramp, is
                // taken back at the axis's jerk limit; otherwise the commands' jerks hold.
                let recovering = previous_acceleration.abs() > one.acceleration * (1.0 + 1e-9);
                let jerk_limit = if recovering { axis_jerk } else { highest_jerk };
                prop_assert!(
                    jerk <= jerk_limit * (1.0 + 1e-6),
                    "jerk {} above {}",
                    jerk,
                    jerk_limit
                );
            }
            previous_acceleration = now.set_acceleration;
            if kernel.command_status(id) == Some(CommandStatus::Done) {
                break;
            }
        }
    }
    let (id, target) = last.unwrap();
    prop_assert_eq!(kernel.command_status(id), Some(CommandStatus::Done));
    prop_assert_eq!(snap(&kernel, axis).set_position, target);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// Trapezoids that abort each other at any moment keep the acceleration limit and the
    /// last one ends exactly on its target.
    #[test]
    fn aborting_trapezoids_end_exactly_on_the_last_target(moves in random_moves(false)) {
        run_random_moves(&moves, 0.0)?;
    }

    /// S-curves that abort each other at any moment, even mid-ramp, keep the jerk and
    /// acceleration limits and the last one ends exactly on its target.
    #[test]
    fn aborting_s_curves_keep_their_limits_and_end_exactly(moves in random_moves(true)) {
        run_random_moves(&moves, 50_000.0)?;
    }
}

/// Found by the property test: a gentle move (50 u/s², 500 u/s³) aborting a hard braking ramp
/// (-1248 u/s²) used to take the acceleration back at its own jerk for 2.5 s, driving the axis
/// at 1,338 u/s (above the axis's 1,000) some 23,000 units past its target.
#[test]
fn a_gentle_move_aborting_a_hard_ramp_recovers_at_the_axis_jerk() {
    let moves = [
        (
            974,
            458.60764997790784,
            59.56810981959212,
            1537.2802291576488,
            7744.290940942179,
        ),
        (
            1068,
            -373.1115490964189,
            189.9891010746828,
            243.04022716764555,
            18609.505589576394,
        ),
        (
            2288,
            456.27444640061617,
            97.70425931290978,
            1239.923728313077,
            11528.26832330948,
        ),
        (
            1439,
            355.09641279514307,
            144.89548241586243,
            1298.44252798291,
            16176.172798513806,
        ),
        (1, 297.1409824333238, 5.0, 50.0, 500.0),
    ]
    .map(
        |(after_cycles, target, velocity, acceleration, jerk)| RandomMove {
            after_cycles,
            target,
            velocity,
            acceleration,
            jerk,
        },
    );
    run_random_moves(&moves, 50_000.0).unwrap();
}
