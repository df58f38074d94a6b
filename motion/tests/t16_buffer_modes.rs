//! PLCopen Appendix A (digest T16): two MC_MoveAbsolute on one axis, Aborting against Buffered.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{DT_S, powered, roomy_linear, snap};
use motion::axis::AxisState;
use motion::fb::MoveAbsolute;
use motion::kernel::BufferMode;

fn move_to(position: f64, velocity: f64, buffer_mode: BufferMode) -> MoveAbsolute {
    let mut fb = MoveAbsolute::default();
    fb.position = position;
    fb.velocity = velocity;
    fb.acceleration = 100.0;
    fb.deceleration = 100.0;
    fb.buffer_mode = buffer_mode;
    fb
}

#[test]
fn an_aborting_second_move_takes_over_at_once_without_stopping() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb1 = move_to(1000.0, 100.0, BufferMode::Aborting);
    let mut fb2 = move_to(2000.0, 200.0, BufferMode::Aborting);
    fb1.execute = true;
    for cycle in 0..20_000 {
        fb2.execute = cycle >= 3000;
        fb1.call(&mut kernel, axis);
        fb2.call(&mut kernel, axis);
        if cycle == 3000 {
            assert!(
                fb2.busy && fb2.active,
                "FB2 takes over in the call of its edge"
            );
        }
        if cycle > 3000 {
            assert!(fb1.command_aborted && !fb1.done && !fb1.busy);
        }
        if (3000..7000).contains(&cycle) {
            assert!(
                snap(&kernel, axis).set_velocity > 0.0,
                "no stop between the moves"
            );
        }
        kernel.advance(axis, DT_S).unwrap();
    }
    fb2.call(&mut kernel, axis);
    assert!(fb2.done);
    assert_eq!(snap(&kernel, axis).set_position, 2000.0);
}

#[test]
fn a_buffered_second_move_starts_the_cycle_after_the_first_reaches_rest_at_its_target() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb1 = move_to(1000.0, 100.0, BufferMode::Aborting);
    let mut fb2 = move_to(2000.0, 200.0, BufferMode::Buffered);
    fb1.execute = true;
    let mut fb1_done_cycle = None;
    for cycle in 0..20_000 {
        fb2.execute = cycle >= 3000;
        fb1.call(&mut kernel, axis);
        fb2.call(&mut kernel, axis);
        let snapshot = snap(&kernel, axis);
        if fb1.done && fb1_done_cycle.is_none() {
            fb1_done_cycle = Some(cycle);
            // The last cycle ended FB1 at rest on its target and handed the axis to FB2.
            assert_eq!(snapshot.set_position, 1000.0);
            assert_eq!(snapshot.set_velocity, 0.0);
            assert!(fb2.active && fb2.busy);
            assert_eq!(snapshot.state, AxisState::DiscreteMotion);
        }
        if (3000..20_000).contains(&cycle) && fb1_done_cycle.is_none() {
            assert!(fb2.busy && !fb2.active, "FB2 waits in the buffer");
            assert!(fb1.busy && fb1.active);
        }
        if fb1_done_cycle.map(|done| done + 1) == Some(cycle) {
            assert!(
                snapshot.set_position > 1000.0,
                "FB2 moves from the next cycle on"
            );
        }
        kernel.advance(axis, DT_S).unwrap();
    }
    assert!(fb1_done_cycle.is_some());
    fb2.call(&mut kernel, axis);
    assert!(fb2.done);
    assert_eq!(snap(&kernel, axis).set_position, 2000.0);
    assert_eq!(kernel.state(axis).unwrap(), AxisState::Standstill);
}

#[test]
fn a_buffered_move_after_move_velocity_starts_once_the_velocity_is_reached() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut velocity = motion::fb::MoveVelocity::default();
    velocity.velocity = 100.0;
    velocity.acceleration = 100.0;
    velocity.deceleration = 100.0;
    velocity.direction = motion::axis::Direction::Positive;
    velocity.execute = true;
    let mut fb2 = move_to(500.0, 100.0, BufferMode::Buffered);
    fb2.execute = true;
    velocity.call(&mut kernel, axis);
    fb2.call(&mut kernel, axis);
    assert!(fb2.busy && !fb2.active);
    for _ in 0..20_000 {
        velocity.call(&mut kernel, axis);
        fb2.call(&mut kernel, axis);
        kernel.advance(axis, DT_S).unwrap();
    }
    velocity.call(&mut kernel, axis);
    fb2.call(&mut kernel, axis);
    assert!(velocity.command_aborted);
    assert!(fb2.done);
    assert_eq!(snap(&kernel, axis).set_position, 500.0);
}

#[test]
fn a_second_buffered_command_while_one_waits_is_refused() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb1 = move_to(1000.0, 100.0, BufferMode::Aborting);
    let mut fb2 = move_to(2000.0, 100.0, BufferMode::Buffered);
    let mut fb3 = move_to(3000.0, 100.0, BufferMode::Buffered);
    for fb in [&mut fb1, &mut fb2, &mut fb3] {
        fb.execute = true;
        fb.call(&mut kernel, axis);
    }
    assert!(fb1.active && fb2.busy && !fb2.active);
    assert!(fb3.error && fb3.error_id == 7);
}

/// Runs FB1 to 1000 at `v1` with FB2 to `target2` at `v2` buffered in `mode` from the start;
/// returns the velocity when FB1 shows Done, the lowest velocity between 500 and 1500, and
/// checks that FB2 ends exactly on its target.
fn blend(v1: f64, v2: f64, target2: f64, mode: BufferMode) -> (f64, f64) {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut fb1 = move_to(1000.0, v1, BufferMode::Aborting);
    let mut fb2 = move_to(target2, v2, mode);
    fb1.execute = true;
    fb2.execute = true;
    let mut at_done = None;
    let mut lowest = f64::INFINITY;
    for _ in 0..60_000 {
        fb1.call(&mut kernel, axis);
        fb2.call(&mut kernel, axis);
        let snapshot = snap(&kernel, axis);
        if fb1.done && at_done.is_none() {
            at_done = Some(snapshot.set_velocity);
            assert!(fb2.active);
        }
        if (500.0..1500.0).contains(&snapshot.set_position) {
            lowest = lowest.min(snapshot.set_velocity);
        }
        kernel.advance(axis, DT_S).unwrap();
    }
    fb2.call(&mut kernel, axis);
    assert!(fb2.done, "{mode:?}: FB2 not done");
    assert_eq!(snap(&kernel, axis).set_position, target2);
    (at_done.expect("FB1 never Done"), lowest)
}

#[test]
fn the_blending_modes_pass_the_first_target_at_their_velocity_without_stopping() {
    for (v1, v2) in [(100.0, 50.0), (50.0, 100.0)] {
        let cases = [
            (BufferMode::BlendingLow, f64::min(v1, v2)),
            (BufferMode::BlendingPrevious, v1),
            (BufferMode::BlendingNext, v2),
            (BufferMode::BlendingHigh, f64::max(v1, v2)),
        ];
        for (mode, expected) in cases {
            let (at_done, lowest) = blend(v1, v2, 2000.0, mode);
            // FB2 has already run the rest of the cycle in which FB1 reached its target, at
            // most 1 ms at 100 u/s².
            assert!(
                (at_done - expected).abs() <= 0.1 + 1e-9,
                "{mode:?} {v1}/{v2}: {at_done} instead of {expected}"
            );
            assert!(
                lowest >= f64::min(v1, v2) - 1e-9,
                "{mode:?} {v1}/{v2}: slowed to {lowest}"
            );
        }
    }
}

#[test]
fn blending_into_a_move_that_turns_back_stops_at_the_first_target() {
    let (at_done, _) = blend(100.0, 100.0, 500.0, BufferMode::BlendingHigh);
    assert_eq!(at_done, 0.0);
}

#[test]
fn blending_into_a_short_move_passes_the_target_only_as_fast_as_the_move_can_stop() {
    // FB2 covers 12.5 u; braking from 50 u/s at 100 u/s² takes 12.5 u, so 50 u/s is the most.
    let (at_done, _) = blend(100.0, 100.0, 1012.5, BufferMode::BlendingHigh);
    assert!((at_done - 50.0).abs() <= 0.1 + 1e-9, "{at_done}");
}

#[test]
fn a_blending_move_after_move_velocity_takes_over_at_its_velocity_without_stopping() {
    let (mut kernel, axis) = powered(roomy_linear());
    let mut velocity = motion::fb::MoveVelocity::default();
    velocity.velocity = 80.0;
    velocity.acceleration = 100.0;
    velocity.deceleration = 100.0;
    velocity.direction = motion::axis::Direction::Positive;
    velocity.execute = true;
    let mut fb2 = move_to(1000.0, 100.0, BufferMode::BlendingLow);
    fb2.execute = true;
    velocity.call(&mut kernel, axis);
    fb2.call(&mut kernel, axis);
    let mut at_takeover = None;
    for _ in 0..20_000 {
        velocity.call(&mut kernel, axis);
        fb2.call(&mut kernel, axis);
        if fb2.active && at_takeover.is_none() {
            at_takeover = Some(snap(&kernel, axis).set_velocity);
        }
        kernel.advance(axis, DT_S).unwrap();
    }
    fb2.call(&mut kernel, axis);
    assert!(fb2.done);
    // As BlendingPrevious: the move starts from the velocity MC_MoveVelocity reached.
    assert_eq!(at_takeover, Some(80.0));
    assert_eq!(snap(&kernel, axis).set_position, 1000.0);
}
