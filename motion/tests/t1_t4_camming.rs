//! MC_CamTableSelect + MC_CamIn: the digest's worked examples T1–T4 with their numbers.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::sync::{add, cam_in, line, rig, rise_return, select, spin};
use common::{assert_close, roomy_linear, snap};
use motion::fb::CamIn;
use motion::kernel::{AxisId, Kernel};
use motion::sync::StartMode;

/// One task cycle: the CamIn call, then the kernel advances every axis.
fn cycle(kernel: &mut Kernel, cam: &mut CamIn, master: AxisId, slave: AxisId, dt_s: f64) {
    cam.call(kernel, master, slave);
    kernel.advance_all(dt_s).unwrap();
}

#[test]
fn t1_a_periodic_cam_wraps_with_the_remainder_and_pulses_end_of_profile_once() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, line(360.0), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, false, true);
    spin(&mut kernel, master, 100.0);
    kernel.advance_all(0.002).unwrap();
    assert_close(snap(&kernel, master).set_velocity, 100.0);
    // Relative master: the cam starts at X = MasterOffset; two cycles of 0.2 later X = 359.99.
    let mut coupling = cam_in(&selection);
    coupling.master_offset = 359.59;
    let dt_s = 0.002;
    let mut seen = Vec::new();
    for _ in 0..5 {
        cycle(&mut kernel, &mut coupling, master, slave, dt_s);
        let status = kernel.coupling_status(slave).unwrap().unwrap();
        coupling.call(&mut kernel, master, slave);
        seen.push((status.cam_master, coupling.end_of_profile));
    }
    // seen[k] is after the k-th advance of the coupling (k = 0 starts it at 359.59).
    assert_close(seen[0].0, 359.59);
    assert_close(seen[2].0, 359.99);
    assert!(!seen[2].1);
    assert!((seen[3].0 - 0.19).abs() < 1e-9, "{seen:?}");
    assert!(seen[3].1, "EndOfProfile in the cycle of the wrap: {seen:?}");
    assert!(!seen[4].1, "EndOfProfile is a one-cycle pulse: {seen:?}");
    assert!(coupling.busy && coupling.in_sync);
}

#[test]
fn t2_a_non_periodic_cam_holds_its_end_and_end_of_profile_stays_until_execute_falls() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, rise_return(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, false, false, true);
    let mut coupling = cam_in(&selection);
    spin(&mut kernel, master, 360.0);
    let mut ended_at = None;
    for k in 0..1500 {
        cycle(&mut kernel, &mut coupling, master, slave, 0.001);
        if coupling.end_of_profile && ended_at.is_none() {
            ended_at = Some(k);
        }
        if let Some(at) = ended_at {
            assert!(
                coupling.end_of_profile,
                "EndOfProfile stays TRUE (cycle {k}, from {at})"
            );
        }
    }
    // 360 master units at 360 u/s: the profile ends after about one second.
    let at = ended_at.unwrap();
    assert!((995..=1005).contains(&at), "ended at cycle {at}");
    let slave_snap = snap(&kernel, slave);
    assert_close(slave_snap.set_position, 0.0);
    assert_close(slave_snap.set_velocity, 0.0);
    assert_eq!(
        slave_snap.state.code(),
        6,
        "the slave stays in SynchronizedMotion"
    );
    coupling.execute = false;
    cycle(&mut kernel, &mut coupling, master, slave, 0.001);
    assert!(!coupling.end_of_profile);
    assert!(coupling.busy, "falling Execute does not end the coupling");
}

#[test]
fn a_periodic_cam_runs_backwards_with_the_master_and_pulses_at_the_start() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, rise_return(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, false, true);
    let mut coupling = cam_in(&selection);
    coupling.master_offset = 10.0;
    spin(&mut kernel, master, 0.0);
    kernel
        .issue(
            master,
            motion::kernel::MotionRequest::Velocity {
                direction: motion::axis::Direction::Negative,
                dynamics: motion::kernel::Dynamics {
                    velocity: 100.0,
                    acceleration: 100_000.0,
                    deceleration: 100_000.0,
                    jerk: 0.0,
                },
                jog: false,
            },
            motion::kernel::BufferMode::Aborting,
        )
        .unwrap();
    let mut pulses = Vec::new();
    for k in 0..200 {
        cycle(&mut kernel, &mut coupling, master, slave, 0.001);
        if coupling.end_of_profile {
            pulses.push(k);
        }
    }
    // X starts at 10 and falls at 100 u/s: it passes the start after 0.1 s and wraps to 360;
    // the FB call of the next cycle shows the pulse.
    assert_eq!(pulses.len(), 1, "{pulses:?}");
    assert!((100..=103).contains(&pulses[0]), "{pulses:?}");
    let status = kernel.coupling_status(slave).unwrap().unwrap();
    assert_eq!(status.period_index, -1);
    assert!(status.cam_master > 345.0 && status.cam_master < 355.0);
    let expected = rise_return_at(status.cam_master);
    assert_close(snap(&kernel, slave).set_position, expected);
}

fn rise_return_at(x: f64) -> f64 {
    use motion::curve::CamCurve;
    rise_return().sample(x).position
}

#[test]
fn t3_slave_absolute_jumps_onto_the_cam_and_relative_counts_from_the_slave() {
    for (slave_absolute, start_mode, first, peak) in [
        (true, StartMode::Absolute, 0.0, 180.0),
        (false, StartMode::Absolute, 20.0, 200.0),
        (true, StartMode::Relative, 20.0, 200.0),
    ] {
        let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
        kernel.set_position(slave, 20.0, false).unwrap();
        let cam = add(&mut kernel, rise_return(), Vec::new());
        let selection = select(&mut kernel, master, slave, cam, true, false, slave_absolute);
        let mut coupling = cam_in(&selection);
        coupling.start_mode = start_mode;
        cycle(&mut kernel, &mut coupling, master, slave, 0.001);
        assert_close(snap(&kernel, slave).set_position, first);
        spin(&mut kernel, master, 360.0);
        let mut highest = f64::MIN;
        for _ in 0..1000 {
            cycle(&mut kernel, &mut coupling, master, slave, 0.001);
            highest = highest.max(snap(&kernel, slave).set_position);
        }
        assert!(
            (highest - peak).abs() < 1e-6,
            "peak {highest}, expected {peak}"
        );
    }
}

/// Runs the rise-return cam with the given scalings and offsets against a master at 100 u/s
/// (absolute master from 0) and returns the master positions of the EndOfProfile pulses and
/// the slave's range over the run.
fn t4_run(
    master_scaling: f64,
    slave_scaling: f64,
    master_offset: f64,
    slave_offset: f64,
    seconds: usize,
) -> (Vec<f64>, f64, f64) {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, rise_return(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    let mut coupling = cam_in(&selection);
    coupling.master_scaling = master_scaling;
    coupling.slave_scaling = slave_scaling;
    coupling.master_offset = master_offset;
    coupling.slave_offset = slave_offset;
    // The coupling starts with the master at rest at 0, then the master runs at 100 u/s.
    cycle(&mut kernel, &mut coupling, master, slave, 0.001);
    assert!(coupling.active, "{:?}", coupling.error_cause);
    spin(&mut kernel, master, 100.0);
    let mut pulses = Vec::new();
    let (mut low, mut high) = (f64::MAX, f64::MIN);
    for _ in 0..seconds * 1000 {
        cycle(&mut kernel, &mut coupling, master, slave, 0.001);
        let position = snap(&kernel, slave).set_position;
        low = low.min(position);
        high = high.max(position);
        coupling.call(&mut kernel, master, slave);
        if coupling.end_of_profile {
            pulses.push(snap(&kernel, master).set_position);
        }
    }
    (pulses, low, high)
}

#[track_caller]
fn assert_pulses(pulses: &[f64], expected: &[f64]) {
    assert!(pulses.len() >= expected.len(), "{pulses:?}");
    for (pulse, expected) in pulses.iter().zip(expected) {
        // The pulse comes in the first 1 ms cycle (0.1 master units) at or past the end.
        assert!(
            *pulse >= expected - 1e-6 && *pulse < expected + 0.1 + 1e-6,
            "{pulses:?} vs {expected}"
        );
    }
}

#[test]
fn t4_scalings_and_offsets() {
    let (pulses, low, high) = t4_run(1.0, 1.0, 0.0, 0.0, 8);
    assert_pulses(&pulses, &[360.0, 720.0]);
    assert!(
        low.abs() < 1e-6 && (high - 180.0).abs() < 1e-6,
        "{low}..{high}"
    );

    let (_, low, high) = t4_run(1.0, 2.0, 0.0, 0.0, 4);
    assert!(
        low.abs() < 1e-6 && (high - 360.0).abs() < 1e-6,
        "{low}..{high}"
    );
    let (_, low, high) = t4_run(1.0, 0.5, 0.0, 0.0, 4);
    assert!(
        low.abs() < 1e-6 && (high - 90.0).abs() < 1e-6,
        "{low}..{high}"
    );

    let (pulses, _, _) = t4_run(2.0, 1.0, 0.0, 0.0, 4);
    assert_pulses(&pulses, &[180.0, 360.0]);
    let (pulses, _, _) = t4_run(0.5, 1.0, 0.0, 0.0, 15);
    assert_pulses(&pulses, &[720.0, 1440.0]);

    let (pulses, low, high) = t4_run(1.0, 1.0, 20.0, 30.0, 8);
    assert_pulses(&pulses, &[340.0, 700.0]);
    assert!(
        (low - 30.0).abs() < 1e-6 && (high - 210.0).abs() < 1e-6,
        "{low}..{high}"
    );
}
