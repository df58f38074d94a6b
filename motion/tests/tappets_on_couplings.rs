//! Tappets of a coupling's cam (T10), SMC_GetTappetValue (T11) and SMC_CamRegister (T21).

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::sync::{add, cam_in, line, modulo, rig, select};
use common::{roomy_linear, snap};
use motion::fb::{CamIn, CamOut, CamRegister, GetTappetValue, MoveVelocity};
use motion::kernel::Kernel;
use motion::tappet::{Tappet, TappetAction, TappetTrack};

fn invert_track(id: u16, position: f64) -> TappetTrack {
    TappetTrack::new(
        id,
        vec![Tappet {
            position,
            on_positive: TappetAction::Invert,
            on_negative: TappetAction::Invert,
        }],
    )
}

#[test]
fn t10_an_invert_tappet_toggles_once_per_period_of_a_modulo_master() {
    // Virtual master modulo 10 moved by MC_MoveVelocity at 2 u/s (acc/dec 10), cam 0..10
    // periodic with MasterAbsolute, tappet at 8 inverting on both passes.
    let (mut kernel, master, slave) = rig(modulo(10.0), roomy_linear());
    let cam = add(&mut kernel, line(10.0), vec![invert_track(1, 8.0)]);
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    let mut coupling = cam_in(&selection);
    let mut drive = MoveVelocity::default();
    drive.execute = true;
    drive.velocity = 2.0;
    drive.acceleration = 10.0;
    drive.deceleration = 10.0;
    drive.direction = motion::axis::Direction::Positive;
    let dt_s = 0.004;
    let mut toggles = Vec::new();
    let mut previous = false;
    for k in 0..10_000 {
        drive.call(&mut kernel, master);
        coupling.call(&mut kernel, master, slave);
        let output = coupling.tappets.output(1).unwrap();
        if output != previous {
            toggles.push(k as f64 * dt_s);
            previous = output;
        }
        kernel.advance_all(dt_s).unwrap();
    }
    assert!(coupling.busy, "{:?}", coupling.error_cause);
    // 40 s: the master reaches 8 at about 4.1 s and every 5 s after, one toggle each time.
    assert_eq!(toggles.len(), 8, "{toggles:?}");
    assert!((toggles[0] - 4.1).abs() < 0.02, "{toggles:?}");
    for pair in toggles.windows(2) {
        assert!((pair[1] - pair[0] - 5.0).abs() < 0.01, "{toggles:?}");
    }
}

/// A coupling whose track 2 inverts at 100, run until the output has toggled to TRUE, then
/// decoupled and started again; returns `bTappet` after the restart.
fn t11_after_restart(set_init_value_at_reset: bool) -> (bool, bool, bool) {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, line(360.0), vec![invert_track(2, 100.0)]);
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    let mut coupling = cam_in(&selection);
    let mut value = GetTappetValue::default();
    value.id = 2;
    value.init_value = false;
    value.set_init_value_at_reset = set_init_value_at_reset;
    common::sync::spin(&mut kernel, master, 100.0);
    let mut first = None;
    for _ in 0..1500 {
        coupling.call(&mut kernel, master, slave);
        value.call(&mut coupling.tappets);
        first.get_or_insert(value.tappet);
        kernel.advance_all(0.001).unwrap();
    }
    coupling.call(&mut kernel, master, slave);
    value.call(&mut coupling.tappets);
    let toggled = value.tappet;
    let mut out = CamOut::default();
    out.execute = true;
    out.call(&mut kernel, slave);
    coupling.execute = false;
    coupling.call(&mut kernel, master, slave);
    coupling.execute = true;
    coupling.call(&mut kernel, master, slave);
    assert!(coupling.busy, "{:?}", coupling.error_cause);
    value.call(&mut coupling.tappets);
    (first.unwrap(), toggled, value.tappet)
}

#[test]
fn t11_get_tappet_value_returns_to_its_initial_value_only_when_asked() {
    // The master passes 100 at 1 s: the output is TRUE after 1.5 s.
    assert_eq!(t11_after_restart(true), (false, true, false));
    assert_eq!(t11_after_restart(false), (false, true, true));
}

/// Moves the master at `velocity` (signed, reached at once) for `cycles` cycles of 1 ms,
/// calling the coupling each cycle.
fn drive_master(
    kernel: &mut Kernel,
    coupling: &mut CamIn,
    master: motion::kernel::AxisId,
    slave: motion::kernel::AxisId,
    velocity: f64,
    cycles: usize,
) {
    let direction = if velocity < 0.0 {
        motion::axis::Direction::Negative
    } else {
        motion::axis::Direction::Positive
    };
    kernel
        .issue(
            master,
            motion::kernel::MotionRequest::Velocity {
                direction,
                dynamics: motion::kernel::Dynamics {
                    velocity: velocity.abs(),
                    acceleration: 100_000.0,
                    deceleration: 100_000.0,
                    jerk: 0.0,
                },
                jog: false,
            },
            motion::kernel::BufferMode::Aborting,
        )
        .unwrap();
    for _ in 0..cycles {
        coupling.call(kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    coupling.call(kernel, master, slave);
}

#[test]
fn tappet_hysteresis_of_cam_in_suppresses_jitter() {
    let mut states = Vec::new();
    for hysteresis in [0.0, 1.0] {
        let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
        let cam = add(&mut kernel, line(360.0), vec![invert_track(1, 100.0)]);
        let selection = select(&mut kernel, master, slave, cam, true, true, true);
        kernel.set_position(master, 99.0, false).unwrap();
        let mut coupling = cam_in(&selection);
        coupling.tappet_hysteresis = hysteresis;
        let mut outputs = Vec::new();
        // About 99 → 100.5 → 99.8 → 100.3 → 98.4: the master jitters over the tappet at 100 by less
        // than the hysteresis, then leaves the band below.
        for (velocity, cycles) in [(100.0, 15), (-100.0, 8), (100.0, 6), (-100.0, 20)] {
            drive_master(&mut kernel, &mut coupling, master, slave, velocity, cycles);
            outputs.push(coupling.tappets.output(1).unwrap());
        }
        let position = snap(&kernel, master).set_position;
        // The reversals take 2 ms each at 100 000 u/s², so the legs end near, not at, the
        // listed positions; the last one ends more than 1 below the tappet.
        assert!(position < 98.9 && position > 98.0, "{position}");
        states.push(outputs);
    }
    assert_eq!(states[0], [true, false, true, false]);
    assert_eq!(states[1], [true, true, true, false]);
}

#[test]
fn t21_cam_register_evaluates_tappets_on_a_master_without_slave() {
    let (mut kernel, master, _slave) = rig(roomy_linear(), roomy_linear());
    let track = TappetTrack::new(
        7,
        vec![
            Tappet {
                position: 90.0,
                on_positive: TappetAction::On,
                on_negative: TappetAction::None,
            },
            Tappet {
                position: 270.0,
                on_positive: TappetAction::Off,
                on_negative: TappetAction::None,
            },
        ],
    );
    let cam = add(&mut kernel, line(360.0), vec![track]);
    let mut register = CamRegister::default();
    register.enable = true;
    common::sync::spin(&mut kernel, master, 100.0);
    let mut pulses = Vec::new();
    let mut on_at = Vec::new();
    let mut previous = false;
    for _ in 0..8000 {
        register.call(&kernel, master, cam);
        assert!(
            register.busy && !register.error,
            "{:?}",
            register.error_cause
        );
        let position = snap(&kernel, master).set_position;
        if register.end_of_profile {
            pulses.push(position);
        }
        let output = register.tappet(7).unwrap();
        if output && !previous {
            on_at.push(position);
        }
        previous = output;
        kernel.advance_all(0.001).unwrap();
    }
    // EndOfProfile in the cycle the master position reaches 360 (and 720 …).
    assert_eq!(pulses.len(), 2, "{pulses:?}");
    assert!(pulses[0] >= 360.0 && pulses[0] < 360.1 + 1e-9, "{pulses:?}");
    assert!(pulses[1] >= 720.0 && pulses[1] < 720.1 + 1e-9, "{pulses:?}");
    assert_eq!(on_at.len(), 2, "{on_at:?}");
    assert!(on_at[1] >= 450.0 && on_at[1] < 450.1 + 1e-9, "{on_at:?}");
    assert_eq!(register.tappets().count(), 1);

    // Scaling 0 is an error; disabling clears it.
    register.master_scaling = 0.0;
    register.call(&kernel, master, cam);
    assert!(register.error && !register.busy);
    assert_eq!(register.error_id, 4);
    register.enable = false;
    register.call(&kernel, master, cam);
    assert!(!register.error && !register.busy);
}
