//! Properties of random valid Poly5 chains.

use proptest::prelude::*;

use crate::cam::{
    ContinuityChecks, KeyPoint, MotionLaw, Periodicity, PointCam, PointInterpolation, Segment,
    SegmentedCam,
};
use crate::curve::CamCurve;

/// A Poly5 chain of 1 to 8 segments with random spans, strokes, velocities and accelerations.
fn poly5_chain() -> impl Strategy<Value = SegmentedCam> {
    let start = (
        -100.0..100.0_f64,
        -100.0..100.0_f64,
        -3.0..3.0_f64,
        -0.5..0.5_f64,
    );
    let segment = (
        0.5..100.0_f64,
        -100.0..100.0_f64,
        -3.0..3.0_f64,
        -0.5..0.5_f64,
    );
    (start, prop::collection::vec(segment, 1..=8)).prop_map(|(start, segments)| {
        let start = KeyPoint::xyva(start.0, start.1, start.2, start.3);
        let mut master = start.master;
        let segments = segments
            .into_iter()
            .map(|(span, slave, velocity, acceleration)| {
                master += span;
                Segment::new(
                    MotionLaw::Poly5,
                    KeyPoint::xyva(master, slave, velocity, acceleration),
                )
            })
            .collect();
        SegmentedCam::new(start, segments).unwrap()
    })
}

proptest! {
    #[test]
    fn a_small_master_step_gives_a_small_slave_change(
        cam in poly5_chain(),
        fraction in 0.0..1.0_f64,
    ) {
        let (start, end) = cam.master_range();
        let master = start + fraction * (end - start);
        let step = 1e-7 * (end - start);
        let fastest = cam
            .segment_bounds()
            .iter()
            .map(|bounds| bounds.max_abs_velocity)
            .fold(0.0, f64::max);
        let change = (cam.sample(master + step).position - cam.sample(master).position).abs();
        // The mean value theorem bounds the change by the largest velocity times the step;
        // the small margin absorbs rounding in the positions.
        prop_assert!(
            change <= fastest * step * 1.001 + 1e-9,
            "change {change} over {step} with largest velocity {fastest}"
        );
    }

    #[test]
    fn a_poly5_chain_is_continuous_up_to_acceleration(cam in poly5_chain()) {
        let warnings = cam.check_continuity(ContinuityChecks::default(), Periodicity::NonPeriodic);
        prop_assert!(warnings.is_empty(), "{warnings:?}");
    }

    #[test]
    fn sampled_tables_are_monotonic_in_master_and_build(
        cam in poly5_chain(),
        elements in 2..600_usize,
    ) {
        let points = cam.sample_points(elements).unwrap();
        prop_assert_eq!(points.len(), elements);
        prop_assert_eq!(points[0].master, cam.master_range().0);
        prop_assert_eq!(points[elements - 1].master, cam.master_range().1);
        prop_assert!(points.windows(2).all(|pair| pair[0].master < pair[1].master));
        for interpolation in [
            PointInterpolation::Linear,
            PointInterpolation::Cubic,
            PointInterpolation::Quintic,
        ] {
            let table = PointCam::new(points.clone(), interpolation);
            prop_assert!(table.is_ok(), "{:?}", table.err());
        }
        // The quintic table goes through the cam's samples with their derivatives.
        let table = PointCam::new(points.clone(), PointInterpolation::Quintic).unwrap();
        for point in &points {
            let sample = table.sample(point.master);
            prop_assert!((sample.position - point.slave).abs() <= 1e-9 * point.slave.abs().max(1.0));
        }
    }
}
