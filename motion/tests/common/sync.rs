//! Helpers of the synchronised-motion tests: a powered master and slave, the digest's cams,
//! a master at constant velocity.

use motion::axis::{AxisConfig, Direction};
use motion::cam::{KeyPoint, MotionLaw, Segment, SegmentedCam};
use motion::fb::{CamIn, CamTableSelect};
use motion::kernel::{AxisId, BufferMode, Dynamics, Kernel, MotionRequest};
use motion::sync::CamId;
use motion::tappet::TappetTrack;

/// A modulo axis with the given period and roomy limits.
pub fn modulo(period: f64) -> AxisConfig {
    AxisConfig {
        modulo_period: Some(period),
        ..super::roomy_linear()
    }
}

/// A kernel with a powered master (added first) and a powered slave.
pub fn rig(master: AxisConfig, slave: AxisConfig) -> (Kernel, AxisId, AxisId) {
    let mut kernel = Kernel::new();
    let master = kernel.add_axis(master).unwrap();
    let slave = kernel.add_axis(slave).unwrap();
    kernel.power(master, true).unwrap();
    kernel.power(slave, true).unwrap();
    (kernel, master, slave)
}

/// The T3/T4 cam: master 0..360, slave rising 0 → 180 over 0..180 and returning to 0, both
/// Poly5 rest in rest.
pub fn rise_return() -> SegmentedCam {
    SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![
            Segment::new(MotionLaw::Poly5, KeyPoint::rest(180.0, 180.0)),
            Segment::new(MotionLaw::Poly5, KeyPoint::rest(360.0, 0.0)),
        ],
    )
    .unwrap()
}

/// A straight-line cam from (0, 0) to (`period`, `period`).
pub fn line(period: f64) -> SegmentedCam {
    SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![Segment::new(
            MotionLaw::Line,
            KeyPoint::rest(period, period),
        )],
    )
    .unwrap()
}

/// Registers `cam` with `tracks`.
pub fn add(kernel: &mut Kernel, cam: SegmentedCam, tracks: Vec<TappetTrack>) -> CamId {
    kernel.add_cam(Box::new(cam), tracks).unwrap()
}

/// Starts the master at `velocity` (reached within one cycle of 1 ms).
pub fn spin(kernel: &mut Kernel, master: AxisId, velocity: f64) {
    kernel
        .issue(
            master,
            MotionRequest::Velocity {
                direction: Direction::Positive,
                dynamics: Dynamics {
                    velocity,
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

/// Selects `cam` with the given options and returns the finished instance.
pub fn select(
    kernel: &mut Kernel,
    master: AxisId,
    slave: AxisId,
    cam: CamId,
    periodic: bool,
    master_absolute: bool,
    slave_absolute: bool,
) -> CamTableSelect {
    let mut select = CamTableSelect::default();
    select.execute = true;
    select.cam_table = cam;
    select.periodic = periodic;
    select.master_absolute = master_absolute;
    select.slave_absolute = slave_absolute;
    select.call(kernel, master, slave);
    assert!(select.done, "{:?}", select.error_cause);
    select
}

/// A CamIn on the selection of `select`, executed.
pub fn cam_in(select: &CamTableSelect) -> CamIn {
    let mut cam_in = CamIn::default();
    cam_in.execute = true;
    cam_in.cam_table_id = select.cam_table_id;
    cam_in
}
