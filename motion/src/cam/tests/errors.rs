//! Bad input: every error names what is wrong in the words of the cam table.

use crate::cam::{
    CamError, KeyPoint, MotionLaw, PointCam, PointInterpolation, Segment, SegmentedCam,
    sample_points,
};
use crate::curve::CamPoint;

fn three_segments(middle: Segment) -> Result<SegmentedCam, CamError> {
    SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(120.0, 100.0, 1.0, 0.0)),
            middle,
            Segment::new(MotionLaw::Poly5, KeyPoint::rest(360.0, 360.0)),
        ],
    )
}

#[track_caller]
fn assert_message(result: Result<impl std::fmt::Debug, CamError>, expected: &str) {
    match result {
        Ok(value) => panic!("expected the error \"{expected}\", got {value:?}"),
        Err(error) => assert_eq!(error.to_string(), expected),
    }
}

#[test]
fn a_rest_in_rest_law_between_different_velocities_is_refused() {
    let result = SegmentedCam::new(
        KeyPoint::rest(0.0, 0.0),
        vec![
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(120.0, 100.0, 1.0, 0.0)),
            Segment::new(MotionLaw::Line, KeyPoint::xyva(130.0, 110.0, 1.0, 0.0)),
            Segment::new(MotionLaw::ModifiedSine, KeyPoint::rest(240.0, 200.0)),
        ],
    );
    assert_message(
        result,
        "segment 3 (ModifiedSine, 130..240): the law cannot start at velocity 1 and end at velocity 0; use Poly5",
    );
}

#[test]
fn a_rest_in_rest_law_with_an_acceleration_at_an_end_is_refused() {
    let result = three_segments(Segment::new(
        MotionLaw::Cycloid,
        KeyPoint::xyva(240.0, 250.0, 1.0, 0.5),
    ));
    assert_message(
        result,
        "segment 2 (Cycloid, 120..240): the law needs acceleration 0 at both ends but has 0 at the start and 0.5 at the end; use Poly5",
    );
}

#[test]
fn a_segment_that_does_not_advance_the_master_is_refused() {
    for end_master in [120.0, 100.0] {
        let result = three_segments(Segment::new(
            MotionLaw::Poly5,
            KeyPoint::xyva(end_master, 150.0, 1.0, 0.0),
        ));
        assert_message(
            result,
            &format!(
                "segment 2 (Poly5, 120..{end_master}): the master position must increase along the segment"
            ),
        );
    }
}

#[test]
fn non_finite_key_point_values_are_refused_with_the_key_point_and_field() {
    let result = three_segments(Segment::new(
        MotionLaw::Poly5,
        KeyPoint::xyva(240.0, 200.0, f64::NAN, 0.0),
    ));
    assert_message(result, "key point 3: the velocity is not a finite number");
    let result = SegmentedCam::new(
        KeyPoint::rest(f64::INFINITY, 0.0),
        vec![Segment::new(MotionLaw::Line, KeyPoint::rest(10.0, 1.0))],
    );
    assert_message(
        result,
        "key point 1: the master position is not a finite number",
    );
}

#[test]
fn lambda_is_refused_rather_than_ignored() {
    let mut segment = Segment::new(
        MotionLaw::ModifiedSine,
        KeyPoint::xyva(240.0, 220.0, 1.0, 0.0),
    );
    segment.lambda = Some(0.3);
    assert_message(
        three_segments(segment),
        "segment 2 (ModifiedSine, 120..240): the inflection parameter lambda = 0.3 is not supported; clear it to use the classic modified sine with inflections at 1/8 and 7/8",
    );
    segment.law = MotionLaw::Poly5;
    assert_message(
        three_segments(segment),
        "segment 2 (Poly5, 120..240): lambda applies to ModifiedSine segments only; clear it",
    );
}

#[test]
fn a_cam_without_segments_is_refused() {
    assert_message(
        SegmentedCam::new(KeyPoint::rest(0.0, 0.0), Vec::new()),
        "the cam has no segment; add at least one segment after the start point",
    );
}

#[test]
fn xyva_export_refuses_laws_other_than_line_and_poly5() {
    let cam = three_segments(Segment::new(
        MotionLaw::Poly7,
        KeyPoint::xyva(240.0, 220.0, 1.0, 0.0),
    ))
    .unwrap();
    assert_message(
        cam.xyva_points(),
        "segment 2 (Poly7, 120..240): the XYVA format holds only Line and Poly5 segments; compile the cam as segments or as a table",
    );
    let lines = three_segments(Segment::new(
        MotionLaw::Line,
        KeyPoint::xyva(240.0, 220.0, 1.0, 0.0),
    ))
    .unwrap();
    assert_eq!(lines.xyva_points().unwrap().len(), 4);
}

#[test]
fn a_table_needs_two_elements() {
    let cam = SegmentedCam::codesys_default();
    assert_message(
        cam.sample_points(1),
        "a table needs at least 2 elements, including both ends, not 1",
    );
    assert_message(
        sample_points(&cam, 0),
        "a table needs at least 2 elements, including both ends, not 0",
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
fn point_tables_refuse_bad_rows_naming_the_row() {
    let interpolation = PointInterpolation::Cubic;
    assert_message(
        PointCam::new(vec![row(0.0, 0.0)], interpolation),
        "the point table has 1 row(s); it needs at least two",
    );
    assert_message(
        PointCam::new(
            vec![row(0.0, 0.0), row(10.0, 1.0), row(10.0, 2.0)],
            interpolation,
        ),
        "row 3: master position 10 repeats the one of row 2; master positions must strictly increase",
    );
    assert_message(
        PointCam::new(
            vec![row(0.0, 0.0), row(10.0, 1.0), row(5.0, 2.0)],
            interpolation,
        ),
        "row 3: master position 5 is below 10 of row 2; master positions must strictly increase",
    );
    let mut bad = row(20.0, 2.0);
    bad.acceleration = f64::NEG_INFINITY;
    assert_message(
        PointCam::new(vec![row(0.0, 0.0), row(10.0, 1.0), bad], interpolation),
        "row 3: the acceleration is not a finite number",
    );
    assert_message(
        PointCam::new(vec![row(0.0, f64::NAN), row(10.0, 1.0)], interpolation),
        "row 1: the slave position is not a finite number",
    );
}
