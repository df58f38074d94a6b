//! MC_DigitalCamSwitch with the switch table of the digest's T12 (PLCopen Fig. 37–39, Omron
//! manual example): modulo axis of period 5000.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::sync::modulo;
use common::{powered, snap};
use motion::axis::Direction;
use motion::fb::{CamSwitch, CamSwitchMode, DigitalCamSwitch, SwitchDirection, TrackOptions};
use motion::kernel::{AxisId, BufferMode, Dynamics, Kernel, MotionRequest};

fn switch(
    track_number: u16,
    first: f64,
    last: f64,
    axis_direction: SwitchDirection,
    cam_switch_mode: CamSwitchMode,
    duration_s: f64,
) -> CamSwitch {
    CamSwitch {
        track_number,
        first_on_position: first,
        last_on_position: last,
        axis_direction,
        cam_switch_mode,
        duration_s,
    }
}

/// Switch01 .. Switch04 of T12.
fn t12_switches() -> Vec<CamSwitch> {
    use CamSwitchMode::{Position, Time};
    use SwitchDirection::{Both, Negative, Positive};
    vec![
        switch(1, 2000.0, 3000.0, Positive, Position, 0.0),
        switch(1, 2500.0, 3000.0, Negative, Position, 0.0),
        switch(1, 4000.0, 1000.0, Both, Position, 0.0),
        switch(2, 3000.0, 0.0, Both, Time, 1.35),
    ]
}

fn run_velocity(kernel: &mut Kernel, axis: AxisId, velocity: f64) {
    kernel
        .issue(
            axis,
            MotionRequest::Velocity {
                direction: if velocity < 0.0 {
                    Direction::Negative
                } else {
                    Direction::Positive
                },
                dynamics: Dynamics {
                    velocity: velocity.abs(),
                    acceleration: 100_000.0,
                    deceleration: 100_000.0,
                    jerk: 0.0,
                },
                jog: false,
            },
            BufferMode::Aborting,
        )
        .unwrap();
}

/// Runs the axis at `velocity` for `seconds` with a 2 ms task and checks track 1 against
/// `expected_track1(position)` away from the edges; returns the track 2 on-times in seconds and
/// the positions where they started.
fn run(
    switches: &mut DigitalCamSwitch,
    velocity: f64,
    seconds: f64,
    expected_track1: impl Fn(f64) -> bool,
) -> Vec<(f64, f64)> {
    let (mut kernel, axis) = powered(modulo(5000.0));
    kernel.set_position(axis, 1500.0, false).unwrap();
    run_velocity(&mut kernel, axis, velocity);
    let dt_s = 0.002;
    kernel.advance(axis, dt_s).unwrap();
    let mut pulses: Vec<(f64, f64)> = Vec::new();
    let mut track2_since: Option<(f64, f64)> = None;
    for _ in 0..(seconds / dt_s) as usize {
        switches.call(&kernel, axis);
        assert!(switches.in_operation, "{:?}", switches.error_cause);
        let position = snap(&kernel, axis).set_position;
        let now = kernel.axis_time_s(axis).unwrap();
        let near_edge = [0.0, 1000.0, 2000.0, 2500.0, 3000.0, 4000.0, 5000.0]
            .iter()
            .any(|edge| (position - edge).abs() < 1e-6);
        if !near_edge {
            assert_eq!(
                switches.outputs[1],
                expected_track1(position),
                "track 1 at {position}"
            );
        }
        match (switches.outputs[2], track2_since) {
            (true, None) => track2_since = Some((now, position)),
            (false, Some((since, at))) => {
                pulses.push((now - since, at));
                track2_since = None;
            }
            _ => {}
        }
        kernel.advance(axis, dt_s).unwrap();
    }
    pulses
}

fn t12_instance() -> DigitalCamSwitch {
    let mut instance = DigitalCamSwitch::default();
    instance.enable = true;
    instance.switches = t12_switches();
    instance
}

#[test]
fn t12_positive_motion() {
    let mut instance = t12_instance();
    let pulses = run(&mut instance, 1000.0, 12.0, |position| {
        (2000.0..3000.0).contains(&position) || !(1000.0..4000.0).contains(&position)
    });
    // Track 2 is on for 1350 ms from crossing 3000, twice in 12 s from 1500 at 1000 u/s.
    assert_eq!(pulses.len(), 2, "{pulses:?}");
    for (duration, at) in pulses {
        assert!((duration - 1.35).abs() < 0.0021, "{duration}");
        assert!((3000.0..3002.0 + 1e-6).contains(&at), "{at}");
    }
}

#[test]
fn t12_negative_motion() {
    let mut instance = t12_instance();
    let pulses = run(&mut instance, -1000.0, 12.0, |position| {
        (position > 2500.0 && position <= 3000.0) || position > 4000.0 || position <= 1000.0
    });
    assert_eq!(pulses.len(), 2, "{pulses:?}");
    for (duration, at) in pulses {
        assert!((duration - 1.35).abs() < 0.0021, "{duration}");
        assert!((2998.0 - 1e-6..=3000.0).contains(&at), "{at}");
    }
}

#[test]
fn t12_compensation_switches_on_125_ms_early_and_off_250_ms_late() {
    let mut instance = DigitalCamSwitch::default();
    instance.enable = true;
    instance.switches = vec![t12_switches()[0]];
    instance.track_options[1] = TrackOptions {
        on_compensation_s: -0.125,
        off_compensation_s: 0.25,
        hysteresis: 0.0,
    };
    // At 1000 u/s: on from 2000 − 125 = 1875, off from 3000 + 250 = 3250.
    run(&mut instance, 1000.0, 8.0, |position| {
        (1875.0..3250.0).contains(&position)
    });
}

#[test]
fn the_enable_mask_and_disabling_and_invalid_switches() {
    let (mut kernel, axis) = powered(modulo(5000.0));
    kernel.set_position(axis, 2200.0, false).unwrap();
    let mut instance = t12_instance();
    instance.call(&kernel, axis);
    assert!(instance.outputs[1]);
    instance.enable_mask = 0b100;
    instance.call(&kernel, axis);
    assert!(!instance.outputs[1], "bit 1 clear turns track 1 off");
    instance.enable_mask = u16::MAX;
    instance.call(&kernel, axis);
    instance.enable = false;
    instance.call(&kernel, axis);
    assert!(instance.outputs[1] && !instance.in_operation && !instance.busy);

    instance.enable = true;
    instance.switches[0].track_number = 16;
    instance.call(&kernel, axis);
    assert!(instance.error && !instance.in_operation);
    assert_eq!(instance.error_id, 4);
    instance.switches = t12_switches();
    instance.switches[2].first_on_position = 5000.0;
    instance.call(&kernel, axis);
    assert!(instance.error);
    instance.switches = t12_switches();
    instance.track_options[0].on_compensation_s = -1.5;
    instance.call(&kernel, axis);
    assert!(instance.error);
}

#[test]
fn hysteresis_keeps_jitter_at_an_edge_from_chattering() {
    for (hysteresis, expected_changes) in [(0.0, 4), (5.0, 1)] {
        let (mut kernel, axis) = powered(modulo(5000.0));
        kernel.set_position(axis, 1999.5, false).unwrap();
        let mut instance = DigitalCamSwitch::default();
        instance.enable = true;
        instance.switches = vec![switch(
            0,
            2000.0,
            3000.0,
            SwitchDirection::Both,
            CamSwitchMode::Position,
            0.0,
        )];
        instance.track_options[0].hysteresis = hysteresis;
        let mut changes = 0;
        let mut previous = false;
        // At 100 u/s (reversals take 2 ms): up to about 2000.6, back to about 1999.6, up and
        // back again, less than 1 unit either side of the edge at 2000.
        for (velocity, cycles) in [(100.0, 12), (-100.0, 12), (100.0, 12), (-100.0, 12)] {
            run_velocity(&mut kernel, axis, velocity);
            for _ in 0..cycles {
                kernel.advance(axis, 0.001).unwrap();
                instance.call(&kernel, axis);
                if instance.outputs[0] != previous {
                    changes += 1;
                    previous = instance.outputs[0];
                }
            }
        }
        assert_eq!(changes, expected_changes, "hysteresis {hysteresis}");
    }
}
