//! `advance` on eight camming slaves with tappets does not grow memory in steady state.
//!
//! The kernel keeps every coupling as a plain value and the tappet evaluators reuse their
//! buffers, so a long run must not grow the process. This file holds a single test so that no
//! other test allocates in the same process while it measures.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::sync::{cam_in, modulo, rig, select, spin};
use motion::cam::{PointCam, PointInterpolation};
use motion::curve::CamPoint;
use motion::fb::CamIn;
use motion::tappet::{Tappet, TappetAction, TappetTrack};

/// The resident set size of this process in pages, from `/proc/self/statm`.
fn resident_pages() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    statm.split_whitespace().nth(1)?.parse().ok()
}

#[test]
fn eight_camming_slaves_run_without_growing_memory() {
    let (mut kernel, master, first_slave) = rig(modulo(360.0), modulo(360.0));
    let mut slaves = vec![first_slave];
    for _ in 1..8 {
        let slave = kernel.add_axis(modulo(360.0)).unwrap();
        kernel.power(slave, true).unwrap();
        slaves.push(slave);
    }
    let points: Vec<CamPoint> = (0..2048)
        .map(|index| {
            let master = 360.0 * index as f64 / 2047.0;
            CamPoint {
                master,
                slave: 90.0 * (1.0 - (master.to_radians()).cos()),
                ..CamPoint::default()
            }
        })
        .collect();
    let track = TappetTrack::new(
        1,
        vec![
            Tappet {
                position: 90.0,
                on_positive: TappetAction::On,
                on_negative: TappetAction::Off,
            },
            Tappet {
                position: 270.0,
                on_positive: TappetAction::Off,
                on_negative: TappetAction::On,
            },
        ],
    );
    let mut couplings: Vec<CamIn> = Vec::new();
    for &slave in &slaves {
        let curve = PointCam::new(points.clone(), PointInterpolation::Cubic).unwrap();
        let cam = kernel
            .add_cam(Box::new(curve), vec![track.clone()])
            .unwrap();
        let selection = select(&mut kernel, master, slave, cam, true, true, true);
        couplings.push(cam_in(&selection));
    }
    spin(&mut kernel, master, 720.0);
    let mut run = |cycles: usize, kernel: &mut motion::kernel::Kernel| {
        for _ in 0..cycles {
            for (coupling, &slave) in couplings.iter_mut().zip(&slaves) {
                coupling.call(kernel, master, slave);
            }
            kernel.advance_all(0.001).unwrap();
        }
    };
    run(10_000, &mut kernel);
    let commands = kernel.recorded_commands();
    let before = resident_pages();
    run(300_000, &mut kernel);
    let after = resident_pages();
    assert_eq!(kernel.recorded_commands(), commands);
    for &slave in &slaves {
        assert!(kernel.coupling_status(slave).unwrap().unwrap().in_sync);
    }
    // 2.4 million slave cycles: a single leaked allocation per cycle would add tens of MB.
    if let (Some(before), Some(after)) = (before, after) {
        let grown_pages = after.saturating_sub(before);
        assert!(grown_pages < 256, "grew by {grown_pages} pages");
    }
}
