//! The worked examples of the PLCopen/SoftMotion digest (§3 T5, T6, T7) and the table exports.

use crate::cam::{
    ContinuityChecks, ContinuityQuantity, KeyPoint, MotionLaw, Periodicity, PointCam,
    PointInterpolation, Segment, SegmentedCam,
};
use crate::curve::CamCurve;

#[track_caller]
fn assert_close(actual: f64, expected: f64, tolerance: f64) {
    assert!(
        (actual - expected).abs() <= tolerance,
        "{actual} differs from {expected} by more than {tolerance}"
    );
}

#[test]
fn the_codesys_default_cam_gives_the_t5_positions_and_velocities() {
    let cam = SegmentedCam::codesys_default();
    assert_eq!(cam.master_range(), (0.0, 360.0));
    // (X, Y, dY/dX) with None where the digest gives no value.
    let expected: [(f64, f64, Option<f64>); 9] = [
        (30.0, 7.8515625, Some(0.68359375)),
        (60.0, 41.25, Some(1.4375)),
        (90.0, 85.4296875, None),
        (120.0, 120.0, Some(1.0)),
        (180.0, 180.0, Some(1.0)),
        (270.0, 274.5703125, None),
        (300.0, 318.75, None),
        (330.0, 352.1484375, None),
        (360.0, 360.0, Some(0.0)),
    ];
    for (master, position, velocity) in expected {
        let sample = cam.sample(master);
        assert_close(sample.position, position, 1e-9);
        if let Some(velocity) = velocity {
            assert_close(sample.velocity, velocity, 1e-9);
        }
    }
    // The middle segment degenerates to a line of slope 1.
    assert_close(cam.sample(180.0).acceleration, 0.0, 1e-9);
    assert_close(cam.sample(150.0).position, 150.0, 1e-9);
}

#[test]
fn the_default_cam_at_master_100_is_the_t7_start_position() {
    let sample = SegmentedCam::codesys_default().sample(100.0);
    assert_close(sample.position, 98.379_629_629_629_6, 1e-9);
    assert_close(sample.velocity, 1.215_277_8, 1e-7);
}

#[test]
fn a_3_4_5_polynomial_over_360_with_stroke_180_gives_the_t6_values() {
    let cam = SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![Segment::new(MotionLaw::Poly5, KeyPoint::rest(360.0, 180.0))],
    )
    .unwrap();
    for (master, position) in [
        (45.0, 2.889404),
        (90.0, 18.632812),
        (180.0, 90.0),
        (270.0, 161.367188),
        (360.0, 180.0),
    ] {
        assert_close(cam.sample(master).position, position, 1e-6);
    }
    assert_close(cam.sample(90.0).velocity, 0.527344, 1e-6);
    assert_close(cam.sample(180.0).velocity, 0.9375, 1e-12);
}

#[test]
fn masters_outside_the_range_are_clamped_to_its_ends() {
    let cam = SegmentedCam::codesys_default();
    assert_eq!(cam.sample(-50.0), cam.sample(0.0));
    assert_eq!(cam.sample(1000.0), cam.sample(360.0));
    assert_close(cam.sample(1000.0).position, 360.0, 1e-12);
}

#[test]
fn the_default_cam_exports_its_key_points_as_xyva() {
    let cam = SegmentedCam::codesys_default();
    assert_eq!(cam.start(), &KeyPoint::rest(0.0, 0.0));
    assert_eq!(cam.segments().len(), 3);
    let masters: Vec<f64> = cam.key_points().map(|point| point.master).collect();
    assert_eq!(masters, [0.0, 120.0, 240.0, 360.0]);
    let points = cam.xyva_points().unwrap();
    let expected = [
        (0.0, 0.0, 0.0),
        (120.0, 120.0, 1.0),
        (240.0, 240.0, 1.0),
        (360.0, 360.0, 0.0),
    ];
    assert_eq!(points.len(), expected.len());
    for (point, (master, slave, velocity)) in points.iter().zip(expected) {
        assert_close(point.master, master, 1e-12);
        assert_close(point.slave, slave, 1e-9);
        assert_close(point.velocity, velocity, 1e-9);
        assert_close(point.acceleration, 0.0, 1e-9);
    }
}

#[test]
fn the_xyva_table_of_a_poly5_cam_reproduces_the_cam() {
    let cam = SegmentedCam::codesys_default();
    let table = PointCam::new(cam.xyva_points().unwrap(), PointInterpolation::Quintic).unwrap();
    for step in 0..=720 {
        let master = step as f64 * 0.5;
        let (expected, actual) = (cam.sample(master), table.sample(master));
        assert_close(actual.position, expected.position, 1e-9);
        assert_close(actual.velocity, expected.velocity, 1e-9);
        assert_close(actual.acceleration, expected.acceleration, 1e-9);
    }
}

#[test]
fn sample_points_spaces_elements_evenly_and_includes_both_ends() {
    let cam = SegmentedCam::codesys_default();
    let points = cam.sample_points(13).unwrap();
    assert_eq!(points.len(), 13);
    for (index, point) in points.iter().enumerate() {
        assert_close(point.master, 30.0 * index as f64, 1e-12);
        let sample = cam.sample(point.master);
        assert_eq!(point.slave, sample.position);
        assert_eq!(point.velocity, sample.velocity);
        assert_eq!(point.acceleration, sample.acceleration);
    }
    assert_close(points[1].slave, 7.8515625, 1e-9);
    assert_eq!(points[12].master, 360.0);
}

#[test]
fn segment_bounds_give_the_extremes_of_each_segment() {
    let cam = SegmentedCam::codesys_default();
    let bounds = cam.segment_bounds();
    assert_eq!(bounds.len(), 3);
    // Segment 1 rises from 0 to 120 at slope 0 → 1; its Poly5 overshoots the line's slope.
    assert_close(bounds[0].min_position, 0.0, 1e-9);
    assert_close(bounds[0].max_position, 120.0, 1e-9);
    // The middle segment is a line of slope 1.
    assert_close(bounds[1].min_position, 120.0, 1e-9);
    assert_close(bounds[1].max_position, 240.0, 1e-9);
    assert_close(bounds[1].max_abs_velocity, 1.0, 1e-9);
    assert_close(bounds[1].max_abs_acceleration, 0.0, 1e-9);
    // A dense scan of the first segment must not find anything beyond the bounds.
    let (mut max_velocity, mut max_acceleration) = (0.0_f64, 0.0_f64);
    for step in 0..=120_000 {
        let sample = cam.sample(step as f64 * 0.001);
        max_velocity = max_velocity.max(sample.velocity.abs());
        max_acceleration = max_acceleration.max(sample.acceleration.abs());
    }
    assert_close(bounds[0].max_abs_velocity, max_velocity, 1e-6);
    assert_close(bounds[0].max_abs_acceleration, max_acceleration, 1e-6);
    assert!(bounds[0].max_abs_velocity > 1.4375);
}

#[test]
fn a_rising_and_falling_segment_reports_its_peak_position() {
    // A Poly3 from rest at 0 with slope 2 back to 0 with slope −2 peaks inside the segment.
    let cam = SegmentedCam::new(
        KeyPoint::xyva(0.0, 0.0, 2.0, 0.0),
        vec![Segment::new(
            MotionLaw::Poly3,
            KeyPoint::xyva(10.0, 0.0, -2.0, 0.0),
        )],
    )
    .unwrap();
    // y = 20u(1 − u) in u = x/10 peaks at u = 1/2 with 5.
    let bounds = cam.segment_bounds()[0];
    assert_close(bounds.max_position, 5.0, 1e-9);
    assert_close(bounds.min_position, 0.0, 1e-12);
    assert_close(bounds.max_abs_velocity, 2.0, 1e-9);
    assert_close(bounds.max_abs_acceleration, 0.4, 1e-9);
}

#[test]
fn the_default_cam_is_continuous_up_to_acceleration_but_not_in_jerk() {
    let cam = SegmentedCam::codesys_default();
    assert!(
        cam.check_continuity(ContinuityChecks::default(), Periodicity::NonPeriodic)
            .is_empty()
    );
    let all = ContinuityChecks {
        jerk: true,
        ..ContinuityChecks::default()
    };
    let warnings = cam.check_continuity(all, Periodicity::NonPeriodic);
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert!(
        warnings
            .iter()
            .all(|warning| warning.quantity == ContinuityQuantity::Jerk)
    );
    assert_eq!(warnings[0].joint, 2);
    assert_eq!(warnings[0].master, 120.0);
    assert_eq!(warnings[1].joint, 3);
    // The Poly5 ends with a jerk; the line that follows has none.
    assert_close(warnings[0].right, 0.0, 1e-12);
    assert!(warnings[0].left.abs() > 1e-4);
}

#[test]
fn line_segments_beside_poly_segments_produce_velocity_kinks() {
    // Dwell, Poly5 rise to constant velocity 1, then a Line of slope 2: the Poly5 ends at the
    // velocity its key point names, but the Line's slope is its chord.
    let cam = SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(100.0, 50.0, 1.0, 0.0)),
            Segment::new(MotionLaw::Line, KeyPoint::xyva(200.0, 250.0, 1.0, 0.0)),
            Segment::new(MotionLaw::Poly5, KeyPoint::rest(300.0, 300.0)),
        ],
    )
    .unwrap();
    let warnings = cam.check_continuity(ContinuityChecks::default(), Periodicity::NonPeriodic);
    let velocity: Vec<_> = warnings
        .iter()
        .filter(|warning| warning.quantity == ContinuityQuantity::Velocity)
        .collect();
    assert_eq!(velocity.len(), 2, "{warnings:?}");
    assert_eq!((velocity[0].joint, velocity[0].master), (2, 100.0));
    assert_close(velocity[0].left, 1.0, 1e-9);
    assert_close(velocity[0].right, 2.0, 1e-9);
    assert_eq!((velocity[1].joint, velocity[1].master), (3, 200.0));
    assert_close(velocity[1].left, 2.0, 1e-9);
    assert_close(velocity[1].right, 1.0, 1e-9);
    assert!(
        warnings
            .iter()
            .all(|warning| warning.quantity != ContinuityQuantity::Position)
    );
    // Without the velocity and acceleration checks, as for a line-only cam in CODESYS, nothing
    // is reported.
    let positions_only = ContinuityChecks {
        velocity: false,
        acceleration: false,
        ..ContinuityChecks::default()
    };
    assert!(
        cam.check_continuity(positions_only, Periodicity::NonPeriodic)
            .is_empty()
    );
}

#[test]
fn a_periodic_cam_compares_its_end_with_its_start_modulo_the_slave_period() {
    let cam = SegmentedCam::codesys_default();
    // 0 → 360 is a jump for a plain periodic cam but one turn of a 360° slave.
    let jumps = cam.check_continuity(
        ContinuityChecks::default(),
        Periodicity::Periodic { slave_period: None },
    );
    assert_eq!(jumps.len(), 1, "{jumps:?}");
    assert_eq!(jumps[0].quantity, ContinuityQuantity::Position);
    assert_eq!((jumps[0].joint, jumps[0].master), (1, 0.0));
    assert_close(jumps[0].left, 360.0, 1e-9);
    assert_close(jumps[0].right, 0.0, 1e-9);
    // 360 is one turn of a 360° slave and two of a 180° one.
    for slave_period in [360.0, 180.0] {
        let warnings = cam.check_continuity(
            ContinuityChecks::default(),
            Periodicity::Periodic {
                slave_period: Some(slave_period),
            },
        );
        assert!(warnings.is_empty(), "{slave_period}: {warnings:?}");
    }
    let wrong_period = cam.check_continuity(
        ContinuityChecks::default(),
        Periodicity::Periodic {
            slave_period: Some(250.0),
        },
    );
    assert_eq!(wrong_period.len(), 1);
}

#[test]
fn a_periodic_cam_reports_a_velocity_mismatch_across_the_period() {
    let cam = SegmentedCam::new(
        KeyPoint::xyva(0.0, 0.0, 1.0, 0.0),
        vec![Segment::new(MotionLaw::Poly5, KeyPoint::rest(360.0, 0.0))],
    )
    .unwrap();
    let warnings = cam.check_continuity(
        ContinuityChecks::default(),
        Periodicity::Periodic { slave_period: None },
    );
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(warnings[0].quantity, ContinuityQuantity::Velocity);
    assert_close(warnings[0].left, 0.0, 1e-12);
    assert_close(warnings[0].right, 1.0, 1e-12);
}

#[test]
fn tables_of_c2_continuous_cams_are_continuous_up_to_acceleration() {
    let cam = SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(90.0, 40.0, 0.8, -0.01)),
            Segment::new(MotionLaw::Poly7, KeyPoint::xyva(200.0, 100.0, 0.2, 0.0)),
            Segment::new(MotionLaw::Poly5, KeyPoint::rest(360.0, 0.0)),
        ],
    )
    .unwrap();
    assert!(
        cam.check_continuity(ContinuityChecks::default(), Periodicity::NonPeriodic)
            .is_empty()
    );
    let points = cam.sample_points(257).unwrap();
    for interpolation in [PointInterpolation::Cubic, PointInterpolation::Quintic] {
        let table = PointCam::new(points.clone(), interpolation).unwrap();
        let warnings =
            table.check_continuity(ContinuityChecks::default(), Periodicity::NonPeriodic);
        assert!(warnings.is_empty(), "{interpolation:?}: {warnings:?}");
    }
    // A linear table of the same points has kinks at its inner rows: the velocity is the
    // chord slope, which changes from interval to interval.
    let linear = PointCam::new(points, PointInterpolation::Linear).unwrap();
    let warnings = linear.check_continuity(ContinuityChecks::default(), Periodicity::NonPeriodic);
    assert!(
        warnings
            .iter()
            .any(|warning| warning.quantity == ContinuityQuantity::Velocity && warning.joint == 2),
        "{warnings:?}"
    );
}
