//! Point tables with each interpolation.

use crate::cam::{PointCam, PointInterpolation};
use crate::curve::{CamCurve, CamPoint};

#[track_caller]
fn assert_close(actual: f64, expected: f64, tolerance: f64) {
    assert!(
        (actual - expected).abs() <= tolerance,
        "{actual} differs from {expected} by more than {tolerance}"
    );
}

fn row(master: f64, slave: f64) -> CamPoint {
    CamPoint {
        master,
        slave,
        ..CamPoint::default()
    }
}

#[test]
fn a_linear_table_runs_straight_between_its_points() {
    let table = PointCam::new(
        vec![row(0.0, 0.0), row(10.0, 5.0), row(20.0, 1.0)],
        PointInterpolation::Linear,
    )
    .unwrap();
    let sample = table.sample(4.0);
    assert_close(sample.position, 2.0, 1e-12);
    assert_close(sample.velocity, 0.5, 1e-12);
    assert_eq!(sample.acceleration, 0.0);
    assert_close(table.sample(15.0).position, 3.0, 1e-12);
    assert_close(table.sample(15.0).velocity, -0.4, 1e-12);
    assert_eq!(table.master_range(), (0.0, 20.0));
    assert_eq!(table.sample(-3.0).position, 0.0);
    assert_close(table.sample(25.0).position, 1.0, 1e-12);
}

#[test]
fn a_cubic_table_is_the_natural_spline_through_its_points() {
    // Through (0, 0), (1, 1), (2, 0) the natural spline has M₁ = −3, so on [0, 1] it is
    // −x³/2 + 3x/2.
    let table = PointCam::new(
        vec![row(0.0, 0.0), row(1.0, 1.0), row(2.0, 0.0)],
        PointInterpolation::Cubic,
    )
    .unwrap();
    assert_close(table.sample(0.5).position, 0.6875, 1e-12);
    assert_close(table.sample(0.0).velocity, 1.5, 1e-12);
    assert_close(table.sample(1.0).position, 1.0, 1e-12);
    assert_close(table.sample(1.0).acceleration, -3.0, 1e-12);
    assert_close(table.sample(1.5).position, 0.6875, 1e-12);
    // Natural: no curvature at the ends.
    assert_close(table.sample(0.0).acceleration, 0.0, 1e-12);
    assert_close(table.sample(2.0).acceleration, 0.0, 1e-12);
}

#[test]
fn a_cubic_table_of_two_points_is_a_line() {
    let table = PointCam::new(
        vec![row(2.0, 1.0), row(6.0, 9.0)],
        PointInterpolation::Cubic,
    )
    .unwrap();
    assert_close(table.sample(3.0).position, 3.0, 1e-12);
    assert_close(table.sample(5.5).velocity, 2.0, 1e-12);
}

#[test]
fn a_quintic_table_meets_each_points_velocity_and_acceleration() {
    let points = vec![
        CamPoint {
            master: 0.0,
            slave: 0.0,
            velocity: 0.0,
            acceleration: 0.0,
        },
        CamPoint {
            master: 50.0,
            slave: 30.0,
            velocity: 0.9,
            acceleration: -0.01,
        },
        CamPoint {
            master: 90.0,
            slave: 40.0,
            velocity: 0.0,
            acceleration: 0.0,
        },
    ];
    let table = PointCam::new(points.clone(), PointInterpolation::Quintic).unwrap();
    for point in &points {
        let sample = table.sample(point.master);
        assert_close(sample.position, point.slave, 1e-9);
        assert_close(sample.velocity, point.velocity, 1e-9);
        assert_close(sample.acceleration, point.acceleration, 1e-9);
    }
    assert_eq!(table.points(), points.as_slice());
    assert_eq!(table.interpolation(), PointInterpolation::Quintic);
}
