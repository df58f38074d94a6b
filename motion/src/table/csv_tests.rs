//! Tests of the CSV reader: every error message, and round trips through each writer.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::*;

use super::test_curve::Poly345;
use super::*;
use crate::curve::CamPoint;

#[track_caller]
fn error_of(text: &str) -> String {
    read_points_csv(text).unwrap_err().to_string()
}

fn point(master: f64, slave: f64) -> CamPoint {
    CamPoint {
        master,
        slave,
        ..CamPoint::default()
    }
}

#[test]
fn a_minimal_file_reads_with_zero_derivatives() {
    let points = read_points_csv("master,slave\n0,0\n360,180\n").unwrap();
    assert_eq!(points, [point(0.0, 0.0), point(360.0, 180.0)]);
}

#[test]
fn comments_blank_lines_crlf_bom_blanks_and_header_case_are_accepted() {
    let text = "\u{feff}# exported by hand\r\n\r\n  MASTER , Slave , Velocity\r\n# a comment between points\r\n 0 , 1.5e1 , -.5\r\n   \r\n+90,20.,2\r\n";
    let points = read_points_csv(text).unwrap();
    assert_eq!(
        points,
        [
            CamPoint {
                master: 0.0,
                slave: 15.0,
                velocity: -0.5,
                acceleration: 0.0
            },
            CamPoint {
                master: 90.0,
                slave: 20.0,
                velocity: 2.0,
                acceleration: 0.0
            }
        ]
    );
}

#[test]
fn an_empty_file_is_refused() {
    let message = "the file is empty: it has no header line and no points";
    assert_eq!(error_of(""), message);
    assert_eq!(error_of("# only a comment\n\n   \n"), message);
}

#[test]
fn an_unknown_header_is_refused_with_its_line() {
    assert_eq!(
        error_of("# points\nx,y\n0,0\n1,1\n"),
        "line 2: the header \"x,y\" is not one of master,slave[,velocity[,acceleration]], Phase,Distance or MasterPos,SlavePos,SlaveVel,SlaveAcc"
    );
    // A file without header starts with numbers, which are not a header either.
    assert!(error_of("0,0\n1,1\n").starts_with("line 1: the header \"0,0\" is not one of"));
}

#[test]
fn a_missing_value_names_line_and_column() {
    assert_eq!(
        error_of("master,slave,velocity,acceleration\n0,0,0,0\n1,1,1\n"),
        "line 3: the value in column \"acceleration\" is missing"
    );
    assert_eq!(
        error_of("master,slave\n0,0\n5,\n"),
        "line 3: the value in column \"slave\" is missing"
    );
    assert_eq!(
        error_of("master,slave\n0\n"),
        "line 2: the value in column \"slave\" is missing"
    );
}

#[test]
fn too_many_values_are_refused() {
    assert_eq!(
        error_of("master,slave\n0,0\n1,12,5\n"),
        "line 3 has 3 values, but the header names 2 columns"
    );
}

#[test]
fn a_value_that_is_not_a_number_is_quoted() {
    assert_eq!(
        error_of("Phase,Distance\n0,0\n10,1O.5\n"),
        "line 3, column \"Distance\": \"1O.5\" is not a number (use . as the decimal point)"
    );
    assert_eq!(
        error_of("master,slave\n0,inf\n"),
        "line 2, column \"slave\": \"inf\" is not a number (use . as the decimal point)"
    );
    assert_eq!(
        error_of("master,slave\nNaN,0\n"),
        "line 2, column \"master\": \"NaN\" is not a number (use . as the decimal point)"
    );
    let long = "x".repeat(100);
    assert_eq!(
        error_of(&format!("master,slave\n0,{long}\n")),
        format!(
            "line 2, column \"slave\": \"{}…\" is not a number (use . as the decimal point)",
            "x".repeat(40)
        )
    );
}

#[test]
fn fewer_than_two_points_are_refused() {
    assert_eq!(
        error_of("master,slave\n"),
        "the file has 0 points; a cam needs at least 2"
    );
    assert_eq!(
        error_of("master,slave\n0,0\n"),
        "the file has 1 point; a cam needs at least 2"
    );
}

#[test]
fn a_master_that_does_not_increase_names_both_lines() {
    assert_eq!(
        error_of("master,slave\n0,0\n50,10\n# comment\n\n130,20\n120,30\n"),
        "line 7: master 120 is not greater than 130 on line 6"
    );
    assert_eq!(
        error_of("Phase,Distance\n0,0\n0,5\n"),
        "line 3: Phase 0 is not greater than 0 on line 2"
    );
}

#[test]
fn the_rivet_csv_round_trips() {
    let points = sample_equidistant(&Poly345, 9).unwrap();
    let text = write_points_csv(&points, CsvColumns::PositionsAndDerivatives);
    assert_eq!(read_points_csv(&text).unwrap(), points);

    let positions: Vec<CamPoint> = points.iter().map(|p| point(p.master, p.slave)).collect();
    let text = write_points_csv(&points, CsvColumns::Positions);
    assert_eq!(read_points_csv(&text).unwrap(), positions);
}

#[test]
fn the_omron_csv_round_trips() {
    let data = OmronCamData::from_curve(&Poly345, 5).unwrap();
    let points = read_points_csv(&data.csv()).unwrap();
    assert_eq!(
        points,
        [
            point(0.0, 0.0),
            point(90.0, 18.63281),
            point(180.0, 90.0),
            point(270.0, 161.3672),
            point(360.0, 180.0)
        ]
    );
}

#[test]
fn the_delta_csv_round_trips() {
    let key_points = DeltaKeyPoints::from_curve(&Poly345, 17).unwrap();
    assert_eq!(
        read_points_csv(&key_points.csv()).unwrap(),
        key_points.points()
    );
}

proptest! {
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC*") {
        let _ = read_points_csv(&text);
    }

    #[test]
    fn arbitrary_csv_like_text_never_panics(
        text in "(master,slave(,velocity(,acceleration)?)?|Phase,Distance|#.*)?(\n[-+0-9.eE,# \r]{0,20}){0,8}"
    ) {
        let _ = read_points_csv(&text);
    }

    #[test]
    fn any_finite_points_round_trip_exactly(
        steps in proptest::collection::vec(
            (1e-9f64..1e6, -1e9f64..1e9, -1e3f64..1e3, -1e3f64..1e3), 2..40),
        start in -1e6f64..1e6,
    ) {
        let mut master = start;
        let points: Vec<CamPoint> = steps
            .iter()
            .map(|&(step, slave, velocity, acceleration)| {
                master += step;
                CamPoint { master, slave, velocity, acceleration }
            })
            .collect();
        prop_assume!(points.windows(2).all(|pair| pair[0].master < pair[1].master));
        let text = write_points_csv(&points, CsvColumns::PositionsAndDerivatives);
        prop_assert_eq!(read_points_csv(&text).unwrap(), points);
    }
}
