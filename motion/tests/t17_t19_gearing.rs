//! MC_GearIn (T17), MC_GearInPos (T18 a/b/c), MC_Phasing (T19) and MC_GearOut.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::sync::{modulo, rig, spin};
use common::{assert_close, roomy_linear, snap};
use motion::axis::AxisState;
use motion::fb::{GearIn, GearInPos, GearOut, Phasing};
use motion::kernel::{AxisId, Kernel, MotionError};
use motion::sync::PhasingMode;

/// `value` in `[-180, 180)`, the signed difference of two positions modulo 360.
fn signed_360(value: f64) -> f64 {
    (value + 180.0).rem_euclid(360.0) - 180.0
}

#[test]
fn t17_gear_in_ramps_to_ratio_times_master_velocity_without_catching_up() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    spin(&mut kernel, master, 50.0);
    kernel.advance_all(0.001).unwrap();
    let mut gear = GearIn::default();
    gear.execute = true;
    gear.ratio_numerator = 2;
    gear.ratio_denominator = 1;
    gear.acceleration = 100.0;
    gear.deceleration = 100.0;
    let mut in_gear_at = None;
    for k in 0..1500 {
        gear.call(&mut kernel, master, slave);
        if gear.in_gear && in_gear_at.is_none() {
            in_gear_at = Some(k);
            assert_close(snap(&kernel, slave).set_velocity, 100.0);
        }
        if !gear.in_gear {
            assert!(snap(&kernel, slave).set_velocity < 100.0 + 1e-9);
        }
        kernel.advance_all(0.001).unwrap();
    }
    // 0 → 100 u/s at 100 u/s² takes 1 s.
    let at = in_gear_at.unwrap();
    assert!((1000..=1002).contains(&at), "InGear at cycle {at}");
    assert_eq!(kernel.state(slave).unwrap(), AxisState::SynchronizedMotion);
    assert_eq!(kernel.state(master).unwrap(), AxisState::ContinuousMotion);
    // From then on the slave moves twice the master's displacement.
    let (m0, s0) = (
        snap(&kernel, master).set_position,
        snap(&kernel, slave).set_position,
    );
    for _ in 0..500 {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    let (m1, s1) = (
        snap(&kernel, master).set_position,
        snap(&kernel, slave).set_position,
    );
    assert_close(s1 - s0, 2.0 * (m1 - m0));
    // No catch-up: the ramp covered 50 units where the gear would have covered 100.
    let master_travel = m1 - 0.05;
    assert!((2.0 * master_travel - s1 - 50.0).abs() < 0.2, "{m1} {s1}");
    // A second rising edge while busy is ignored (CODESYS): the ratio stays 2.
    gear.execute = false;
    gear.call(&mut kernel, master, slave);
    gear.ratio_numerator = 3;
    gear.execute = true;
    for _ in 0..100 {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    assert!(gear.busy && gear.in_gear);
    assert_close(snap(&kernel, slave).set_velocity, 100.0);

    let mut out = GearOut::default();
    out.execute = true;
    out.call(&mut kernel, slave);
    assert!(out.done);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::ContinuousMotion);
    gear.call(&mut kernel, master, slave);
    assert!(!gear.busy && !gear.in_gear && !gear.command_aborted);
    kernel.advance_all(0.001).unwrap();
    assert_close(snap(&kernel, slave).set_velocity, 100.0);
}

#[test]
fn gear_errors_and_their_ids() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let mut same = GearIn::default();
    same.execute = true;
    same.acceleration = 100.0;
    same.deceleration = 100.0;
    same.call(&mut kernel, master, master);
    assert_eq!(same.error_id, 11);
    let mut zero = GearIn::default();
    zero.execute = true;
    zero.ratio_denominator = 0;
    zero.acceleration = 100.0;
    zero.deceleration = 100.0;
    zero.call(&mut kernel, master, slave);
    assert_eq!(zero.error_id, 4);
    let mut out = GearOut::default();
    out.execute = true;
    out.call(&mut kernel, slave);
    assert_eq!(
        out.error_cause,
        Some(MotionError::NotCoupled {
            command: "MC_GearOut"
        })
    );
    let mut phasing = Phasing::default();
    phasing.execute = true;
    phasing.phase_shift = 30.0;
    phasing.velocity = 10.0;
    phasing.acceleration = 100.0;
    phasing.deceleration = 100.0;
    phasing.call(&mut kernel, master, slave);
    assert_eq!(phasing.error_id, 10);
    let mut linear_past = GearInPos::default();
    linear_past.execute = true;
    linear_past.master_sync_position = 10.0;
    linear_past.master_start_distance = 50.0;
    kernel.set_position(master, 0.0, false).unwrap();
    linear_past.call(&mut kernel, master, slave);
    assert_eq!(linear_past.error_id, 4, "a linear master past MSP − MSD");
}

/// What a T18 run saw: the unwrapped master at StartSync and at InSync, and the slave at InSync.
#[derive(Debug)]
struct SyncRun {
    start_sync_master: f64,
    in_sync_master: f64,
    in_sync_slave: f64,
    slave_went_backward: bool,
    slave_wrapped: bool,
}

/// Runs MC_GearInPos with ratio 1 between modulo-360 axes, master at 50 u/s from 0.
fn t18_run(master_sync: f64, start_distance: f64, slave_sync: f64, slave_start: f64) -> SyncRun {
    let (mut kernel, master, slave) = rig(modulo(360.0), modulo(360.0));
    kernel.set_position(slave, slave_start, false).unwrap();
    let mut gear = GearInPos::default();
    gear.execute = true;
    gear.master_sync_position = master_sync;
    gear.master_start_distance = start_distance;
    gear.slave_sync_position = slave_sync;
    spin(&mut kernel, master, 50.0);
    let mut run = SyncRun {
        start_sync_master: f64::NAN,
        in_sync_master: f64::NAN,
        in_sync_slave: f64::NAN,
        slave_went_backward: false,
        slave_wrapped: false,
    };
    let (mut unwrapped, mut last) = (0.0, 0.0);
    let mut last_slave = slave_start;
    for _ in 0..30_000 {
        gear.call(&mut kernel, master, slave);
        assert!(gear.busy, "{:?}", gear.error_cause);
        let position = snap(&kernel, master).set_position;
        unwrapped += signed_360(position - last);
        last = position;
        let slave_position = snap(&kernel, slave).set_position;
        if signed_360(slave_position - last_slave) < -1e-9 {
            run.slave_went_backward = true;
        }
        if slave_position < last_slave - 180.0 {
            run.slave_wrapped = true;
        }
        last_slave = slave_position;
        if gear.start_sync && run.start_sync_master.is_nan() {
            run.start_sync_master = unwrapped;
        }
        if gear.in_sync {
            run.in_sync_master = unwrapped;
            run.in_sync_slave = slave_position;
            assert!(gear.start_sync);
            assert_eq!(kernel.state(slave).unwrap(), AxisState::SynchronizedMotion);
            return run;
        }
        kernel.advance_all(0.001).unwrap();
    }
    panic!("never in sync: {run:?}");
}

#[track_caller]
fn assert_reached(at: f64, expected: f64) {
    // The FB shows a crossing at the first call after the 1 ms cycle (0.05 master units) that
    // reached the position.
    assert!(
        at >= expected - 1e-6 && at < expected + 0.05 + 1e-6,
        "at {at}, expected {expected}"
    );
}

#[test]
fn t18a_start_sync_at_230_in_sync_at_280_with_the_slave_at_60() {
    let run = t18_run(280.0, 50.0, 60.0, 0.0);
    assert_reached(run.start_sync_master, 230.0);
    assert_reached(run.in_sync_master, 280.0);
    assert!(
        (run.in_sync_slave - (60.0 + run.in_sync_master - 280.0)).abs() < 1e-6,
        "{run:?}"
    );
}

#[test]
fn t18b_a_start_distance_above_the_period_starts_in_the_previous_revolution() {
    let run = t18_run(300.0, 370.0, 60.0, 0.0);
    // Start at 300 − 370 = −70, i.e. 290 of the revolution before the one that syncs at 300.
    assert_reached(run.start_sync_master, 290.0);
    assert_reached(run.in_sync_master, 660.0);
    assert!(
        (run.in_sync_slave - (60.0 + run.in_sync_master - 660.0)).abs() < 1e-6,
        "{run:?}"
    );
}

#[test]
fn t18c_a_slave_past_the_sync_position_goes_forward_through_the_wrap() {
    let run = t18_run(300.0, 50.0, 60.0, 200.0);
    assert_reached(run.start_sync_master, 250.0);
    assert_reached(run.in_sync_master, 300.0);
    assert!(
        (run.in_sync_slave - (60.0 + run.in_sync_master - 300.0)).abs() < 1e-6,
        "{run:?}"
    );
    assert!(!run.slave_went_backward && run.slave_wrapped, "{run:?}");
}

/// Runs `phasing` to its end on a 1:1 gear, master at 50 u/s, and returns the change of the
/// slave's lag behind the master and the covered shift.
fn phase(
    kernel: &mut Kernel,
    gear: &mut GearIn,
    master: AxisId,
    slave: AxisId,
    mode: PhasingMode,
    shift: f64,
) -> (f64, f64) {
    let lag = |kernel: &Kernel| {
        signed_360(snap(kernel, master).set_position - snap(kernel, slave).set_position)
    };
    let before = lag(kernel);
    let mut phasing = Phasing::default();
    phasing.execute = true;
    phasing.mode = mode;
    phasing.phase_shift = shift;
    phasing.velocity = 20.0;
    phasing.acceleration = 100.0;
    phasing.deceleration = 100.0;
    let start = kernel.axis_time_s(master).unwrap();
    let start_position = snap(kernel, master).set_position;
    for _ in 0..10_000 {
        gear.call(kernel, master, slave);
        phasing.call(kernel, master, slave);
        assert!(!phasing.error, "{:?}", phasing.error_cause);
        // The master's set values do not change while the slave phases.
        let master_snap = snap(kernel, master);
        assert_close(master_snap.set_velocity, 50.0);
        let elapsed = kernel.axis_time_s(master).unwrap() - start;
        let expected = (start_position + 50.0 * elapsed).rem_euclid(360.0);
        assert!(signed_360(master_snap.set_position - expected).abs() < 1e-6);
        if phasing.done {
            return (lag(kernel) - before, phasing.covered_phase_shift);
        }
        kernel.advance_all(0.001).unwrap();
    }
    panic!("the phasing never finished");
}

#[test]
fn t19_phasing_shifts_the_master_seen_by_the_slave() {
    let (mut kernel, master, slave) = rig(modulo(360.0), modulo(360.0));
    spin(&mut kernel, master, 50.0);
    kernel.advance_all(0.001).unwrap();
    let mut gear = GearIn::default();
    gear.execute = true;
    gear.acceleration = 1000.0;
    gear.deceleration = 1000.0;
    for _ in 0..200 {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    assert!(gear.in_gear);
    let (lag, covered) = phase(
        &mut kernel,
        &mut gear,
        master,
        slave,
        PhasingMode::Absolute,
        30.0,
    );
    assert!((lag - 30.0).abs() < 1e-6, "slave trails by 30 more: {lag}");
    assert!((covered - 30.0).abs() < 1e-6);
    let (first, covered_first) = phase(
        &mut kernel,
        &mut gear,
        master,
        slave,
        PhasingMode::Relative,
        30.0,
    );
    let (second, covered_second) = phase(
        &mut kernel,
        &mut gear,
        master,
        slave,
        PhasingMode::Relative,
        30.0,
    );
    assert!((first - 30.0).abs() < 1e-6 && (second - 30.0).abs() < 1e-6);
    assert!((covered_first - 30.0).abs() < 1e-6 && (covered_second - 30.0).abs() < 1e-6);
    let status = kernel.coupling_status(slave).unwrap().unwrap();
    assert_close(status.phase_shift, 90.0);
    let (back, _) = phase(
        &mut kernel,
        &mut gear,
        master,
        slave,
        PhasingMode::Absolute,
        30.0,
    );
    assert!((back + 60.0).abs() < 1e-6, "{back}");
    assert_close(
        kernel.coupling_status(slave).unwrap().unwrap().phase_shift,
        30.0,
    );
    assert!(gear.busy && gear.in_gear);
}

#[test]
fn a_jerk_limited_gear_in_keeps_acceleration_and_jerk_within_their_limits() {
    let mut slave_config = roomy_linear();
    slave_config.max_jerk = 2000.0;
    let (mut kernel, master, slave) = rig(roomy_linear(), slave_config);
    spin(&mut kernel, master, 50.0);
    kernel.advance_all(0.001).unwrap();
    let mut gear = GearIn::default();
    gear.execute = true;
    gear.acceleration = 100.0;
    gear.deceleration = 100.0;
    let mut previous_acceleration = 0.0;
    let mut highest = 0.0_f64;
    for _ in 0..2000 {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
        let acceleration = snap(&kernel, slave).set_acceleration;
        highest = highest.max(acceleration.abs());
        assert!(acceleration.abs() <= 100.0 + 1e-9, "{acceleration}");
        assert!(
            (acceleration - previous_acceleration).abs() <= 2000.0 * 0.001 + 1e-9,
            "jerk: {previous_acceleration} → {acceleration}"
        );
        previous_acceleration = acceleration;
    }
    assert!(
        highest > 99.0,
        "the ramp reaches its acceleration: {highest}"
    );
    assert!(gear.in_gear);
    assert_close(snap(&kernel, slave).set_velocity, 50.0);
}

#[test]
fn gear_in_slows_a_faster_slave_with_its_deceleration() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    spin(&mut kernel, master, 20.0);
    spin(&mut kernel, slave, 100.0);
    kernel.advance_all(0.001).unwrap();
    let mut gear = GearIn::default();
    gear.execute = true;
    gear.acceleration = 1.0;
    gear.deceleration = 400.0;
    let mut cycles = 0;
    while !gear.in_gear {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
        cycles += 1;
        assert!(cycles < 1000, "never in gear");
    }
    // 100 → 20 u/s at 400 u/s² takes 0.2 s.
    assert!((200..=202).contains(&cycles), "{cycles}");
    assert_close(snap(&kernel, slave).set_velocity, 20.0);
}

#[test]
fn gear_out_aborts_a_running_phase_change() {
    let (mut kernel, master, slave) = rig(modulo(360.0), modulo(360.0));
    spin(&mut kernel, master, 50.0);
    kernel.advance_all(0.001).unwrap();
    let mut gear = GearIn::default();
    gear.execute = true;
    gear.acceleration = 1000.0;
    gear.deceleration = 1000.0;
    for _ in 0..100 {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    let mut phasing = Phasing::default();
    phasing.execute = true;
    phasing.phase_shift = 90.0;
    phasing.velocity = 10.0;
    phasing.acceleration = 100.0;
    phasing.deceleration = 100.0;
    for _ in 0..100 {
        phasing.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    assert!(phasing.busy && phasing.active);
    let covered = phasing.covered_phase_shift;
    assert!(covered > 0.0 && covered < 90.0, "{covered}");
    let mut out = GearOut::default();
    out.execute = true;
    out.call(&mut kernel, slave);
    phasing.call(&mut kernel, master, slave);
    assert!(phasing.command_aborted && !phasing.busy);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::ContinuousMotion);
}

#[test]
fn gear_in_pos_with_ratio_two_arrives_at_twice_the_master_velocity() {
    let (mut kernel, master, slave) = rig(modulo(360.0), modulo(360.0));
    let mut gear = GearInPos::default();
    gear.execute = true;
    gear.ratio_numerator = 2;
    gear.master_sync_position = 180.0;
    gear.master_start_distance = 90.0;
    gear.slave_sync_position = 10.0;
    spin(&mut kernel, master, 50.0);
    let mut synced = false;
    for _ in 0..10_000 {
        gear.call(&mut kernel, master, slave);
        if gear.in_sync {
            synced = true;
            break;
        }
        kernel.advance_all(0.001).unwrap();
    }
    assert!(synced);
    let master_position = snap(&kernel, master).set_position;
    let slave_snap = snap(&kernel, slave);
    assert_close(slave_snap.set_velocity, 100.0);
    assert!(
        signed_360(slave_snap.set_position - (10.0 + 2.0 * (master_position - 180.0))).abs() < 1e-6
    );
    for _ in 0..100 {
        gear.call(&mut kernel, master, slave);
        kernel.advance_all(0.001).unwrap();
    }
    assert_close(snap(&kernel, slave).set_velocity, 100.0);
    assert!(gear.in_sync && gear.start_sync && gear.busy);
}
