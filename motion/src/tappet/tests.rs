//! Scenario tests of the tappet evaluator with the worked examples of the CODESYS digest.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use super::*;

fn tappet(position: f64, on_positive: TappetAction, on_negative: TappetAction) -> Tappet {
    Tappet {
        position,
        on_positive,
        on_negative,
    }
}

/// A master that the tests move cycle by cycle, telling the evaluator each step.
struct Master {
    evaluator: TappetEvaluator,
    position: f64,
    now_s: f64,
}

impl Master {
    fn new(evaluator: TappetEvaluator, position: f64) -> Self {
        Self {
            evaluator,
            position,
            now_s: 0.0,
        }
    }

    /// Moves to `position` without a wrap in `dt_s` at `velocity`, returning the switches.
    fn move_to(&mut self, position: f64, velocity: f64, dt_s: f64) -> Vec<TappetSwitch> {
        self.step(position, MasterWrap::None, velocity, dt_s)
    }

    fn step(
        &mut self,
        position: f64,
        wrap: MasterWrap,
        velocity: f64,
        dt_s: f64,
    ) -> Vec<TappetSwitch> {
        self.now_s += dt_s;
        let cycle = TappetCycle {
            prev_master: self.position,
            master: position,
            wrap,
            master_velocity: velocity,
            now_s: self.now_s,
        };
        self.position = position;
        self.evaluator.evaluate(&cycle).to_vec()
    }

    fn output(&self, track_id: u16) -> bool {
        self.evaluator.output(track_id).unwrap()
    }
}

/// T8: the first cycle index in which track 1 switches on, for a tappet at 50.1 (positive pass
/// ON), task cycle 4 ms, master at 100 u/s from 0, with the given dead-time compensation.
fn t8_switch_cycle(dead_time_s: f64) -> usize {
    let mut track = TappetTrack::new(1, vec![tappet(50.1, TappetAction::On, TappetAction::None)]);
    track.dead_time_s = dead_time_s;
    let evaluator = TappetEvaluator::new(0.0, 1000.0, false, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 0.0);
    for cycle in 1..400 {
        // The position is computed from the cycle count so no rounding accumulates.
        master.move_to(cycle as f64 * 0.4, 100.0, 0.004);
        if master.output(1) {
            return cycle;
        }
    }
    panic!("the tappet never switched");
}

#[test]
fn t8_dead_time_compensation_switches_earlier_or_later_by_velocity_times_time() {
    // Without compensation: the first cycle with master ≥ 50.1 is cycle 126 (master 50.4).
    assert_eq!(t8_switch_cycle(0.0), 126);
    // +0.02 s at 100 u/s: the first cycle with master ≥ 50.1 − 2 = 48.1 is cycle 121 (48.4).
    assert_eq!(t8_switch_cycle(0.02), 121);
    // −0.02 s: 0.02 / 0.004 = 5 task cycles after the master reached the tappet.
    assert_eq!(t8_switch_cycle(-0.02), 126 + 5);
}

#[test]
fn t9_tappets_at_600_on_and_1800_off_act_on_positive_passes_only() {
    let track = TappetTrack::new(
        1,
        vec![
            tappet(600.0, TappetAction::On, TappetAction::None),
            tappet(1800.0, TappetAction::Off, TappetAction::None),
        ],
    );
    let evaluator = TappetEvaluator::new(0.0, 3600.0, true, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 0.0);
    for step in 1..=240 {
        let position = f64::from(step) * 10.0;
        master.move_to(position, 1000.0, 0.01);
        let expected = (600.0..1800.0).contains(&position);
        assert_eq!(master.output(1), expected, "forward at {position}");
    }
    for step in (0..240).rev() {
        let position = f64::from(step) * 10.0;
        let switches = master.move_to(position, -1000.0, 0.01);
        assert!(switches.is_empty(), "backward at {position}: {switches:?}");
        assert!(!master.output(1), "backward at {position}");
    }
}

#[test]
fn t10_an_invert_tappet_on_a_modulo_master_toggles_once_per_period() {
    // Tappet at 8.0 inverting on both passes, master modulo 10 accelerating at 10 u/s² to 2 u/s.
    let track = TappetTrack::new(
        1,
        vec![tappet(8.0, TappetAction::Invert, TappetAction::Invert)],
    );
    let evaluator = TappetEvaluator::new(0.0, 10.0, true, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 0.0);
    let dt_s = 0.01;
    let mut velocity: f64 = 0.0;
    let mut toggles = Vec::new();
    for _ in 0..4000 {
        velocity = (velocity + 10.0 * dt_s).min(2.0);
        let mut position = master.position + velocity * dt_s;
        let mut wrap = MasterWrap::None;
        if position >= 10.0 {
            position -= 10.0;
            wrap = MasterWrap::Forward;
        }
        for switch in master.step(position, wrap, velocity, dt_s) {
            assert_eq!(
                switch.cause,
                SwitchCause::Pass {
                    tappet_index: 0,
                    direction: PassDirection::Positive
                }
            );
            toggles.push((master.now_s, switch.output));
        }
    }
    // The master reaches 8 at about 4.1 s (0.2 s ramp, then 7.8 at 2 u/s) and every 5 s after.
    assert_eq!(toggles.len(), 8, "{toggles:?}");
    assert!((toggles[0].0 - 4.1).abs() < 0.015, "{toggles:?}");
    for pair in toggles.windows(2) {
        assert!((pair[1].0 - pair[0].0 - 5.0).abs() < 0.015, "{toggles:?}");
        assert_ne!(pair[0].1, pair[1].1, "the output must change at each pass");
    }
}

#[test]
fn t11_the_initial_value_returns_on_restart_only_when_asked() {
    let make = |reset_to_initial: bool| {
        let mut track = TappetTrack::new(
            2,
            vec![tappet(100.0, TappetAction::Invert, TappetAction::None)],
        );
        track.initial_value = false;
        track.reset_to_initial = reset_to_initial;
        TappetEvaluator::new(0.0, 360.0, true, vec![track]).unwrap()
    };
    for reset in [true, false] {
        let mut master = Master::new(make(reset), 0.0);
        assert_eq!(master.evaluator.output(2), Some(false));
        master.move_to(150.0, 100.0, 0.01);
        assert!(master.output(2));
        master.evaluator.restart();
        assert_eq!(master.output(2), !reset, "bSetInitValueAtReset = {reset}");
    }
    let mut track = TappetTrack::new(3, Vec::new());
    track.initial_value = true;
    let evaluator = TappetEvaluator::new(0.0, 360.0, true, vec![track]).unwrap();
    assert_eq!(evaluator.outputs().collect::<Vec<_>>(), [(3, true)]);
    assert_eq!(evaluator.output(4), None);
}

#[test]
fn passes_are_half_open_at_the_tappet() {
    let track = TappetTrack::new(
        1,
        vec![tappet(100.0, TappetAction::Invert, TappetAction::Invert)],
    );
    let evaluator = TappetEvaluator::new(0.0, 360.0, true, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 90.0);
    // Reaching X exactly is a positive pass; leaving X upwards is not another one.
    assert_eq!(master.move_to(100.0, 1.0, 0.01).len(), 1);
    assert!(master.move_to(110.0, 1.0, 0.01).is_empty());
    // Going back down to X exactly is a negative pass; leaving X downwards is not another one.
    assert_eq!(master.move_to(100.0, -1.0, 0.01).len(), 1);
    assert!(master.move_to(90.0, -1.0, 0.01).is_empty());
    assert!(!master.output(1));
}

#[test]
fn tappets_at_both_ends_of_the_period_fire_once_per_forward_wrap() {
    let track = TappetTrack::new(
        1,
        vec![
            tappet(0.0, TappetAction::Invert, TappetAction::None),
            tappet(10.0, TappetAction::Invert, TappetAction::None),
            tappet(9.0, TappetAction::None, TappetAction::Invert),
        ],
    );
    let evaluator = TappetEvaluator::new(0.0, 10.0, true, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 9.9);
    let switches = master.step(0.1, MasterWrap::Forward, 2.0, 0.1);
    let indices: Vec<SwitchCause> = switches.iter().map(|s| s.cause).collect();
    assert_eq!(
        indices,
        [
            SwitchCause::Pass {
                tappet_index: 0,
                direction: PassDirection::Positive
            },
            SwitchCause::Pass {
                tappet_index: 1,
                direction: PassDirection::Positive
            }
        ]
    );
}

#[test]
fn a_backward_wrap_is_a_continued_negative_motion() {
    let track = TappetTrack::new(
        1,
        vec![
            tappet(9.8, TappetAction::None, TappetAction::On),
            tappet(8.0, TappetAction::Invert, TappetAction::Invert),
        ],
    );
    let evaluator = TappetEvaluator::new(0.0, 10.0, true, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 0.5);
    let switches = master.step(9.5, MasterWrap::Backward, -2.0, 0.5);
    assert_eq!(
        switches,
        [TappetSwitch {
            track_id: 1,
            cause: SwitchCause::Pass {
                tappet_index: 0,
                direction: PassDirection::Negative
            },
            output: true
        }]
    );
}

#[test]
fn passes_in_one_cycle_act_in_the_order_the_master_reaches_them() {
    // Listed out of order on purpose: OFF at 30 must act after ON at 20 when moving up.
    let track = TappetTrack::new(
        1,
        vec![
            tappet(30.0, TappetAction::Off, TappetAction::On),
            tappet(20.0, TappetAction::On, TappetAction::Off),
        ],
    );
    let evaluator = TappetEvaluator::new(0.0, 100.0, false, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 10.0);
    let outputs: Vec<bool> = master
        .move_to(40.0, 100.0, 0.3)
        .iter()
        .map(|s| s.output)
        .collect();
    assert_eq!(outputs, [true, false]);
    assert!(!master.output(1));
    // Moving down over both: ON at 30 first, then OFF at 20.
    let outputs: Vec<bool> = master
        .move_to(10.0, -100.0, 0.3)
        .iter()
        .map(|s| s.output)
        .collect();
    assert_eq!(outputs, [true, false]);
}

fn hysteresis_master(hysteresis: f64) -> Master {
    let mut track = TappetTrack::new(
        1,
        vec![tappet(100.0, TappetAction::Invert, TappetAction::Invert)],
    );
    track.hysteresis = hysteresis;
    Master::new(
        TappetEvaluator::new(0.0, 360.0, true, vec![track]).unwrap(),
        99.0,
    )
}

#[test]
fn without_hysteresis_jitter_at_a_tappet_toggles_every_time() {
    let mut master = hysteresis_master(0.0);
    for (position, expected) in [(100.5, true), (99.8, false), (100.3, true), (99.5, false)] {
        master.move_to(position, 1.0, 0.01);
        assert_eq!(master.output(1), expected, "at {position}");
    }
}

#[test]
fn hysteresis_suppresses_jitter_and_switches_back_beyond_the_band() {
    let mut master = hysteresis_master(1.0);
    for (position, expected) in [
        (100.5, true),
        (99.8, true),
        (100.3, true),
        (99.5, true),
        (99.0, true),
        (98.9, false),
    ] {
        master.move_to(position, 1.0, 0.01);
        assert_eq!(master.output(1), expected, "at {position}");
    }
}

#[test]
fn hysteresis_ends_when_the_master_leaves_the_band_on_the_same_side() {
    let mut master = hysteresis_master(1.0);
    master.move_to(100.5, 1.0, 0.01);
    master.move_to(101.2, 1.0, 0.01);
    assert!(master.output(1));
    // Back over the tappet after leaving the band: a normal negative pass at 100.
    let switches = master.move_to(99.9, -1.0, 0.01);
    assert_eq!(switches.len(), 1);
    assert!(!master.output(1));
}

#[test]
fn a_timed_switch_stays_on_for_its_duration_and_other_actions_end_it() {
    let track = TappetTrack::new(
        1,
        vec![
            tappet(
                10.0,
                TappetAction::TimedOn { duration_s: 2.0 },
                TappetAction::None,
            ),
            tappet(50.0, TappetAction::Off, TappetAction::None),
        ],
    );
    let evaluator = TappetEvaluator::new(0.0, 100.0, false, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 0.0);
    // 5 u per 0.5 s cycle: the tappet at 10 is reached at 1.0 s, so the output is on until 3.0 s.
    let mut on_times = Vec::new();
    for cycle in 1..=8 {
        master.move_to(f64::from(cycle) * 5.0, 10.0, 0.5);
        if master.output(1) {
            on_times.push(master.now_s);
        }
    }
    assert_eq!(on_times, [1.0, 1.5, 2.0, 2.5]);
    assert_eq!(
        master.evaluator.switches(),
        [],
        "the expiry happened in an earlier cycle"
    );

    // Retriggered at 10 again after moving back, then cut short by OFF at 50.
    let mut master = Master::new(master.evaluator, 0.0);
    master.move_to(10.0, 10.0, 0.5);
    assert!(master.output(1));
    let switches = master.move_to(55.0, 10.0, 0.5);
    assert_eq!(switches.len(), 1);
    assert!(!master.output(1));
    for _ in 0..6 {
        assert!(master.move_to(55.0, 0.0, 0.5).is_empty());
    }
}

#[test]
fn a_jump_of_more_than_a_period_fires_nothing() {
    let track = TappetTrack::new(
        1,
        vec![tappet(5.0, TappetAction::Invert, TappetAction::Invert)],
    );
    let evaluator = TappetEvaluator::new(0.0, 10.0, true, vec![track]).unwrap();
    let mut master = Master::new(evaluator, 1.0);
    assert!(master.move_to(1.0e6, 0.0, 0.01).is_empty());
    assert!(master.move_to(f64::NAN, 0.0, 0.01).is_empty());
    master.position = 1.0;
    assert_eq!(master.move_to(6.0, 0.0, 0.01).len(), 1);
}

#[test]
fn invalid_configurations_are_refused_naming_track_and_tappet() {
    let on = TappetAction::On;
    let error = |start: f64, end: f64, tracks: Vec<TappetTrack>| {
        TappetEvaluator::new(start, end, true, tracks)
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        error(360.0, 0.0, Vec::new()),
        "the cam's master range 360 to 0 is not usable for tappets: both ends must be finite and the start below the end"
    );
    assert_eq!(
        error(
            0.0,
            360.0,
            vec![
                TappetTrack::new(2, Vec::new()),
                TappetTrack::new(2, Vec::new())
            ]
        ),
        "track 2 is defined twice; each track ID switches one output"
    );
    let outside = TappetTrack::new(2, vec![tappet(10.0, on, on), tappet(400.0, on, on)]);
    assert_eq!(
        error(0.0, 360.0, vec![outside]),
        "track 2, tappet 2: position 400 is outside the master range 0 to 360"
    );
    let mut wide = TappetTrack::new(3, Vec::new());
    wide.hysteresis = 180.0;
    assert_eq!(
        error(0.0, 360.0, vec![wide]),
        "track 3: the hysteresis 180 must be 0 or more and less than half the master period (180)"
    );
    let mut dead = TappetTrack::new(4, Vec::new());
    dead.dead_time_s = f64::INFINITY;
    assert_eq!(
        error(0.0, 360.0, vec![dead]),
        "track 4: the dead-time compensation inf s is not a finite number of seconds"
    );
    let timed = TappetTrack::new(
        5,
        vec![tappet(
            1.0,
            TappetAction::None,
            TappetAction::TimedOn { duration_s: 0.0 },
        )],
    );
    assert_eq!(
        error(0.0, 360.0, vec![timed]),
        "track 5, tappet 1: the timed switch lasts 0 s; it must last a positive, finite number of seconds"
    );
}

proptest::proptest! {
    /// On a modulo master moving back and forth with wraps in both directions, an invert tappet
    /// without hysteresis toggles exactly once per crossing of its position, so its output tells
    /// whether the unwrapped master crossed the tappet an odd number of times.
    #[test]
    fn an_invert_tappet_tracks_the_crossings_of_the_unwrapped_master(
        steps in proptest::collection::vec(-4.9f64..4.9, 1..200),
        start in 0.0f64..10.0,
    ) {
        let track = TappetTrack::new(1, vec![tappet(8.0, TappetAction::Invert, TappetAction::Invert)]);
        let evaluator = TappetEvaluator::new(0.0, 10.0, true, vec![track]).unwrap();
        let mut master = Master::new(evaluator, start);
        let mut unwrapped = start;
        let crossings_below = |u: f64| ((u - 8.0) / 10.0).floor();
        for step in steps {
            let next = unwrapped + step;
            let wrap = match (next / 10.0).floor().total_cmp(&(unwrapped / 10.0).floor()) {
                std::cmp::Ordering::Greater => MasterWrap::Forward,
                std::cmp::Ordering::Less => MasterWrap::Backward,
                std::cmp::Ordering::Equal => MasterWrap::None,
            };
            unwrapped = next;
            master.step(unwrapped.rem_euclid(10.0), wrap, step / 0.01, 0.01);
            let crossings = crossings_below(unwrapped) - crossings_below(start);
            proptest::prop_assert_eq!(master.output(1), crossings.rem_euclid(2.0) == 1.0);
        }
    }
}
