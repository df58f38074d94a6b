//! Properties of cam couplings under random master motion: an absolute periodic cam always
//! commands `SlaveScaling·CAM(X) + SlaveOffset` with `X = MasterScaling·M + MasterOffset`
//! taken into the period, whatever way and however often the master crosses the period ends,
//! and each period end the cam master crosses is one EndOfProfile pulse.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::roomy_linear;
use common::sync::{add, cam_in, rig, rise_return, select};
use motion::axis::Direction;
use motion::curve::CamCurve;
use motion::kernel::{BufferMode, Dynamics, MotionRequest};
use proptest::prelude::*;

/// A master velocity held for some cycles.
#[derive(Clone, Copy, Debug)]
struct Leg {
    velocity: f64,
    cycles: usize,
}

fn legs() -> impl Strategy<Value = Vec<Leg>> {
    prop::collection::vec(
        (-2000.0..2000.0_f64, 1..400_usize).prop_map(|(velocity, cycles)| Leg { velocity, cycles }),
        1..8,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn an_absolute_periodic_cam_follows_the_master_through_any_motion(
        legs in legs(),
        master_scaling in prop_oneof![Just(1.0), 0.25..4.0_f64],
        slave_scaling in prop_oneof![Just(1.0), -3.0..3.0_f64],
        master_offset in -500.0..500.0_f64,
        slave_offset in -100.0..100.0_f64,
    ) {
        prop_assume!(slave_scaling.abs() > 1e-3);
        let (mut kernel, master, slave) = rig(roomy_linear(), roomy_linear());
        let cam = add(&mut kernel, rise_return(), Vec::new());
        let selection = select(&mut kernel, master, slave, cam, true, true, true);
        let mut coupling = cam_in(&selection);
        coupling.master_scaling = master_scaling;
        coupling.slave_scaling = slave_scaling;
        coupling.master_offset = master_offset;
        coupling.slave_offset = slave_offset;
        let curve = rise_return();
        let x_of = |m: f64| master_scaling * m + master_offset;
        let mut pulses = 0_i64;
        let mut crossings = 0_i64;
        let mut last_index: Option<i64> = None;
        for leg in legs {
            kernel
                .issue(
                    master,
                    MotionRequest::Velocity {
                        direction: if leg.velocity < 0.0 { Direction::Negative } else { Direction::Positive },
                        dynamics: Dynamics {
                            velocity: leg.velocity.abs(),
                            acceleration: 50_000.0,
                            deceleration: 50_000.0,
                            jerk: 0.0,
                        },
                        jog: false,
                    },
                    BufferMode::Aborting,
                )
                .unwrap();
            for _ in 0..leg.cycles {
                coupling.call(&mut kernel, master, slave);
                if coupling.end_of_profile {
                    pulses += 1;
                }
                kernel.advance_all(0.001).unwrap();
                let m = kernel.snapshot(master).unwrap().set_position;
                let x = x_of(m);
                let index = (x / 360.0).floor() as i64;
                if let Some(last) = last_index {
                    crossings += (index - last).abs();
                }
                last_index = Some(index);
                let expected = slave_scaling * curve.sample(x - 360.0 * index as f64).position + slave_offset;
                let actual = kernel.snapshot(slave).unwrap().set_position;
                prop_assert!((actual - expected).abs() < 1e-6 * (1.0 + slave_scaling.abs()),
                    "master {m}, x {x}: slave {actual}, expected {expected}");
                let status = kernel.coupling_status(slave).unwrap().unwrap();
                prop_assert!((status.cam_master - (x - 360.0 * index as f64)).abs() < 1e-6
                    || (status.cam_master - (x - 360.0 * index as f64)).abs() > 360.0 - 1e-6);
            }
        }
        // The last advance's pulse is shown by a further call.
        coupling.call(&mut kernel, master, slave);
        if coupling.end_of_profile {
            pulses += 1;
        }
        // The first advance starts the coupling without a crossing of its own.
        prop_assert!((pulses - crossings).abs() <= 1, "{pulses} pulses, {crossings} crossings");
    }
}
