//! One task cycle of a virtual master and eight slaves cammed to it through 2048-point cams
//! with tappets: the eight MC_CamIn calls (tappets included) and the kernel's `advance_all`.

#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used)]

use criterion::{Criterion, criterion_group, criterion_main};
use motion::axis::{AxisConfig, Direction};
use motion::cam::{PointCam, PointInterpolation};
use motion::curve::CamPoint;
use motion::fb::{CamIn, CamTableSelect};
use motion::kernel::{AxisId, BufferMode, Dynamics, Kernel, MotionRequest};
use motion::tappet::{Tappet, TappetAction, TappetTrack};
use std::hint::black_box;

const SLAVES: usize = 8;

/// A 2048-point cubic-spline cam over 0..360 with two tracks of two tappets each.
fn cam(kernel: &mut Kernel, phase: f64) -> motion::sync::CamId {
    let points: Vec<CamPoint> = (0..2048)
        .map(|index| {
            let master = 360.0 * index as f64 / 2047.0;
            CamPoint {
                master,
                slave: 90.0 * (1.0 - (master + phase).to_radians().cos()),
                ..CamPoint::default()
            }
        })
        .collect();
    let tappet = |position: f64, on_positive| Tappet {
        position,
        on_positive,
        on_negative: TappetAction::None,
    };
    let tracks = vec![
        TappetTrack::new(
            1,
            vec![
                tappet(90.0, TappetAction::On),
                tappet(270.0, TappetAction::Off),
            ],
        ),
        TappetTrack::new(
            2,
            vec![
                tappet(45.0, TappetAction::Invert),
                tappet(180.0, TappetAction::Invert),
            ],
        ),
    ];
    let curve = PointCam::new(points, PointInterpolation::Cubic).unwrap();
    kernel.add_cam(Box::new(curve), tracks).unwrap()
}

fn rig() -> (Kernel, AxisId, Vec<(AxisId, CamIn)>) {
    let mut kernel = Kernel::new();
    let mut config = AxisConfig::linear(10_000.0, 100_000.0, 100_000.0);
    config.modulo_period = Some(360.0);
    let master = kernel.add_axis(config).unwrap();
    kernel.power(master, true).unwrap();
    let mut slaves = Vec::new();
    for index in 0..SLAVES {
        let slave = kernel.add_axis(config).unwrap();
        kernel.power(slave, true).unwrap();
        let cam = cam(&mut kernel, index as f64 * 10.0);
        let mut select = CamTableSelect::default();
        select.execute = true;
        select.cam_table = cam;
        select.periodic = true;
        select.master_absolute = true;
        select.slave_absolute = true;
        select.call(&mut kernel, master, slave);
        let mut coupling = CamIn::default();
        coupling.execute = true;
        coupling.cam_table_id = select.cam_table_id;
        slaves.push((slave, coupling));
    }
    let request = MotionRequest::Velocity {
        direction: Direction::Positive,
        dynamics: Dynamics {
            velocity: 720.0,
            acceleration: 10_000.0,
            deceleration: 10_000.0,
            jerk: 0.0,
        },
        jog: false,
    };
    kernel.issue(master, request, BufferMode::Aborting).unwrap();
    (kernel, master, slaves)
}

fn cycle(kernel: &mut Kernel, master: AxisId, slaves: &mut [(AxisId, CamIn)]) {
    for (slave, coupling) in slaves.iter_mut() {
        coupling.call(kernel, master, *slave);
    }
    kernel.advance_all(black_box(0.001)).unwrap();
}

fn camming(c: &mut Criterion) {
    let (mut kernel, master, mut slaves) = rig();
    for _ in 0..1000 {
        cycle(&mut kernel, master, &mut slaves);
    }
    assert!(slaves.iter().all(|(_, coupling)| coupling.in_sync));
    c.bench_function(
        "cycle, 1 master + 8 cam slaves (2048 points, tappets)",
        |b| b.iter(|| cycle(&mut kernel, master, &mut slaves)),
    );
}

criterion_group!(benches, camming);
criterion_main!(benches);
