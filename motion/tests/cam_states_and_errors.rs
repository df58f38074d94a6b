//! State transitions of coupled slaves (digest T25's synchronised part), the errors of the
//! camming FBs with their ErrorIDs, ramp-in and SMC_GetCamSlaveSetPosition (T7).

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::sync::{add, cam_in, line, modulo, rig, rise_return, select, spin};
use common::{assert_close, roomy_linear, snap};
use motion::axis::AxisState;
use motion::cam::SegmentedCam;
use motion::fb::{CamIn, CamOut, CamTableSelect, GetCamSlaveSetPosition, MoveAbsolute, Stop};
use motion::kernel::{AxisId, Kernel, MotionError};
use motion::sync::{CamTableId, StartMode};

fn cycle(kernel: &mut Kernel, cam: &mut CamIn, master: AxisId, slave: AxisId) {
    cam.call(kernel, master, slave);
    kernel.advance_all(0.001).unwrap();
}

/// A slave cammed to a master at 100 u/s through the rise-return cam, after 300 cycles.
fn running_coupling() -> (Kernel, AxisId, AxisId, CamIn) {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, rise_return(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    let mut coupling = cam_in(&selection);
    spin(&mut kernel, master, 100.0);
    for _ in 0..300 {
        cycle(&mut kernel, &mut coupling, master, slave);
    }
    (kernel, master, slave, coupling)
}

#[test]
fn cam_in_puts_the_slave_in_synchronized_motion_and_leaves_the_master_alone() {
    let (kernel, master, slave, coupling) = running_coupling();
    assert_eq!(kernel.state(slave).unwrap(), AxisState::SynchronizedMotion);
    assert_eq!(kernel.state(master).unwrap(), AxisState::ContinuousMotion);
    assert_close(snap(&kernel, master).set_velocity, 100.0);
    assert!(coupling.busy && coupling.active && coupling.in_sync);
    assert_eq!(snap(&kernel, slave).active_command, Some("MC_CamIn"));
}

#[test]
fn cam_out_leaves_the_slave_in_continuous_motion_at_its_last_velocity() {
    let (mut kernel, master, slave, mut coupling) = running_coupling();
    let before = snap(&kernel, slave);
    assert!(before.set_velocity > 10.0, "{before:?}");
    let mut out = CamOut::default();
    out.execute = true;
    out.call(&mut kernel, slave);
    assert!(out.done && !out.error);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::ContinuousMotion);
    coupling.call(&mut kernel, master, slave);
    assert!(!coupling.busy && !coupling.active && !coupling.in_sync);
    assert!(!coupling.command_aborted && !coupling.error);
    for _ in 0..100 {
        kernel.advance_all(0.001).unwrap();
    }
    let after = snap(&kernel, slave);
    assert_close(after.set_velocity, before.set_velocity);
    assert_close(
        after.set_position,
        before.set_position + before.set_velocity * 0.1,
    );
    assert_eq!(after.active_command_id, None, "no FB controls the slave");
    // A second MC_CamOut has no coupling to end.
    let mut again = CamOut::default();
    again.execute = true;
    again.call(&mut kernel, slave);
    assert!(again.error);
    assert_eq!(again.error_id, 10);
    assert!(matches!(
        again.error_cause,
        Some(MotionError::NotCoupled {
            command: "MC_CamOut"
        })
    ));
}

#[test]
fn mc_stop_on_the_slave_aborts_the_coupling() {
    let (mut kernel, master, slave, mut coupling) = running_coupling();
    let mut stop = Stop::default();
    stop.execute = true;
    stop.deceleration = 10_000.0;
    stop.call(&mut kernel, slave);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::Stopping);
    coupling.call(&mut kernel, master, slave);
    assert!(coupling.command_aborted && !coupling.busy && !coupling.in_sync);
    assert_eq!(kernel.coupling_status(slave).unwrap(), None);
}

#[test]
fn a_move_absolute_on_the_slave_aborts_the_coupling() {
    let (mut kernel, master, slave, mut coupling) = running_coupling();
    let mut mover = MoveAbsolute::default();
    mover.execute = true;
    mover.position = 0.0;
    mover.velocity = 100.0;
    mover.acceleration = 1000.0;
    mover.deceleration = 1000.0;
    mover.call(&mut kernel, slave);
    assert!(mover.busy && mover.active);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::DiscreteMotion);
    coupling.call(&mut kernel, master, slave);
    assert!(coupling.command_aborted && !coupling.busy);
}

#[test]
fn the_errors_of_the_camming_fbs_and_their_ids() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, rise_return(), Vec::new());

    // MC_CamTableSelect with the master as slave.
    let mut same = CamTableSelect::default();
    same.execute = true;
    same.cam_table = cam;
    same.call(&mut kernel, master, master);
    assert!(same.error && !same.done);
    assert_eq!(same.error_id, 11);
    assert_eq!(same.error_cause, Some(MotionError::MasterIsSlave));
    assert_eq!(same.cam_table_id, CamTableId(0));

    // MC_CamIn with a CamTableID that was never selected.
    let mut unselected = CamIn::default();
    unselected.execute = true;
    unselected.call(&mut kernel, master, slave);
    assert!(unselected.error && !unselected.busy);
    assert_eq!(unselected.error_id, 12);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::Standstill);

    // MC_CamIn with a scaling of 0.
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    for (master_scaling, slave_scaling, input) in
        [(0.0, 1.0, "MasterScaling"), (1.0, 0.0, "SlaveScaling")]
    {
        let mut zero = cam_in(&selection);
        zero.master_scaling = master_scaling;
        zero.slave_scaling = slave_scaling;
        zero.call(&mut kernel, master, slave);
        assert!(zero.error);
        assert_eq!(zero.error_id, 4);
        assert!(
            matches!(zero.error_cause, Some(MotionError::InvalidParameter { input: name, .. }) if name == input)
        );
    }

    // MC_CamIn on the selection with the axes swapped.
    let mut swapped = cam_in(&selection);
    swapped.call(&mut kernel, slave, master);
    assert_eq!(swapped.error_id, 12);

    // A non-periodic cam with the absolute master outside its range.
    kernel.set_position(master, 400.0, false).unwrap();
    let once = select(&mut kernel, master, slave, cam, false, true, true);
    let mut outside = cam_in(&once);
    outside.call(&mut kernel, master, slave);
    assert_eq!(outside.error_id, 14);

    // MC_CamOut without a coupling.
    let mut out = CamOut::default();
    out.execute = true;
    out.call(&mut kernel, slave);
    assert_eq!(out.error_id, 10);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::Standstill);
}

#[test]
fn ramp_in_removes_the_start_jump_within_its_limits() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    kernel.set_position(slave, 20.0, false).unwrap();
    let cam = add(&mut kernel, rise_return(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, false, true);
    let mut coupling = cam_in(&selection);
    coupling.start_mode = StartMode::RampIn;
    coupling.velocity_diff = 50.0;
    coupling.acceleration = 500.0;
    coupling.deceleration = 500.0;
    spin(&mut kernel, master, 36.0);
    let mut previous = snap(&kernel, slave);
    let mut synced_at = None;
    for k in 0..3000 {
        cycle(&mut kernel, &mut coupling, master, slave);
        let now = snap(&kernel, slave);
        // No jump: each step stays within what the cam (at most 1.875·36 u/s for the Poly5
        // rise of 180 over 180) and the compensation (50 u/s) move in 1 ms.
        let step = (now.set_position - previous.set_position).abs();
        assert!(
            step <= (1.875 * 36.0 + 50.0) * 0.001 + 1e-9,
            "jump {step} at {k}"
        );
        previous = now;
        coupling.call(&mut kernel, master, slave);
        if coupling.in_sync && synced_at.is_none() {
            synced_at = Some(k);
        }
    }
    // 20 units at 50 u/s with 500 u/s² ramps take about 0.5 s.
    let at = synced_at.unwrap();
    assert!((400..=700).contains(&at), "in sync at cycle {at}");
    use motion::curve::CamCurve;
    let x = kernel.coupling_status(slave).unwrap().unwrap().cam_master;
    assert_close(
        snap(&kernel, slave).set_position,
        rise_return().sample(x).position,
    );
}

#[test]
fn ramp_in_positive_on_a_modulo_slave_compensates_forward() {
    let (mut kernel, master, slave) = rig(roomy_linear(), modulo(360.0));
    kernel.set_position(slave, 20.0, false).unwrap();
    let cam = add(&mut kernel, line(360.0), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    let mut coupling = cam_in(&selection);
    coupling.start_mode = StartMode::RampInPositive;
    coupling.velocity_diff = 500.0;
    coupling.acceleration = 5000.0;
    coupling.deceleration = 5000.0;
    // Master at rest at 0: the cam commands 0, the slave at 20 goes forward 340 to reach it.
    for _ in 0..2000 {
        cycle(&mut kernel, &mut coupling, master, slave);
        assert!(snap(&kernel, slave).set_velocity >= -1e-9);
    }
    assert!(coupling.in_sync);
    assert!(snap(&kernel, slave).set_position.abs() < 1e-6);
}

#[test]
fn t7_get_cam_slave_set_position_of_the_codesys_default_cam() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, SegmentedCam::codesys_default(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, false, true);
    spin(&mut kernel, master, 100.0);
    kernel.advance_all(0.001).unwrap();
    let mut get = GetCamSlaveSetPosition {
        enable: true,
        master_offset: 100.0,
        cam_table_id: selection.cam_table_id,
        ..GetCamSlaveSetPosition::default()
    };
    get.call(&kernel, master, slave);
    assert!(get.busy && !get.error, "{:?}", get.error_cause);
    assert!(
        (get.start_position - 98.379_629_6).abs() < 1e-6,
        "{}",
        get.start_position
    );
    assert!(
        (get.start_velocity - 121.527_78).abs() < 1e-4,
        "{}",
        get.start_velocity
    );

    // MC_CamIn's first command in absolute mode with the master at rest at 0 is the same.
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, SegmentedCam::codesys_default(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    get.cam_table_id = selection.cam_table_id;
    get.call(&kernel, master, slave);
    let mut coupling = cam_in(&selection);
    coupling.master_offset = 100.0;
    cycle(&mut kernel, &mut coupling, master, slave);
    assert_close(snap(&kernel, slave).set_position, get.start_position);
    assert_close(get.start_velocity, 0.0);

    get.enable = false;
    get.call(&kernel, master, slave);
    assert!(!get.busy && !get.error);
    get.enable = true;
    get.master_scaling = 0.0;
    get.call(&kernel, master, slave);
    assert_eq!(get.error_id, 4);
}

#[test]
fn a_buffered_cam_in_starts_when_the_move_before_it_ends() {
    let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
    let cam = add(&mut kernel, line(360.0), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, true, false);
    let mut mover = MoveAbsolute::default();
    mover.execute = true;
    mover.position = 50.0;
    mover.velocity = 500.0;
    mover.acceleration = 10_000.0;
    mover.deceleration = 10_000.0;
    mover.call(&mut kernel, slave);
    let mut coupling = cam_in(&selection);
    coupling.buffer_mode = motion::kernel::BufferMode::Buffered;
    spin(&mut kernel, master, 100.0);
    cycle(&mut kernel, &mut coupling, master, slave);
    assert!(coupling.busy && !coupling.active, "waits in the buffer");
    let mut started = None;
    for k in 0..1000 {
        mover.call(&mut kernel, slave);
        cycle(&mut kernel, &mut coupling, master, slave);
        if coupling.active && started.is_none() {
            started = Some(k);
            assert!(mover.done);
            // The coupling started in this cycle's advance from the slave at rest at 50:
            // relative slave, absolute master, line cam, so slave = 50 + master.
            let master_position = snap(&kernel, master).set_position;
            assert_close(snap(&kernel, slave).set_position, 50.0 + master_position);
        }
    }
    // The move of 50 at 500 u/s with 10 000 u/s² takes 0.15 s.
    let at = started.unwrap();
    assert!((140..=160).contains(&at), "started at cycle {at}");
    // Relative slave on a line cam: from 50, the slave follows the master's displacement.
    assert!(coupling.in_sync);
    assert_close(snap(&kernel, slave).set_velocity, 100.0);
}

#[test]
fn an_axis_error_on_the_slave_ends_the_coupling_in_error() {
    let (mut kernel, master, slave, mut coupling) = running_coupling();
    kernel.inject_error(slave, 42).unwrap();
    coupling.call(&mut kernel, master, slave);
    assert!(coupling.error && !coupling.busy);
    assert_eq!(coupling.error_id, 8);
    assert_eq!(kernel.state(slave).unwrap(), AxisState::ErrorStop);
    assert_eq!(kernel.state(master).unwrap(), AxisState::ContinuousMotion);
}

#[test]
fn a_slave_leaving_its_software_limits_stops_in_error() {
    let mut limited = roomy_linear();
    limited.software_limits = Some(motion::axis::SoftwareLimits {
        min: -10.0,
        max: 100.0,
    });
    let (mut kernel, master, slave) = rig(roomy_linear(), limited);
    let cam = add(&mut kernel, rise_return(), Vec::new());
    let selection = select(&mut kernel, master, slave, cam, true, true, true);
    let mut coupling = cam_in(&selection);
    spin(&mut kernel, master, 360.0);
    for _ in 0..1000 {
        cycle(&mut kernel, &mut coupling, master, slave);
    }
    assert_eq!(kernel.state(slave).unwrap(), AxisState::ErrorStop);
    assert!(coupling.error);
    assert_eq!(
        coupling.error_cause,
        Some(MotionError::AxisError {
            axis_error_id: motion::kernel::AXIS_ERROR_SOFTWARE_LIMIT
        })
    );
}
