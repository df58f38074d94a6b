//! The motion laws: boundary values, derivatives, VDI 2143 characteristic values, and segments
//! built from them with general boundary values.

use std::f64::consts::PI;

use crate::cam::{KeyPoint, MotionLaw, Segment, SegmentedCam};
use crate::curve::{CamCurve, CamSample};

/// Points of the scans that find the peaks of the derivatives.
const SCAN_POINTS: usize = 200_000;

#[track_caller]
fn assert_close(actual: f64, expected: f64, tolerance: f64) {
    assert!(
        (actual - expected).abs() <= tolerance,
        "{actual} differs from {expected} by more than {tolerance}"
    );
}

/// The peaks of |f′|, |f″|, |f‴| and |f′·f″| found by sampling the law.
fn scanned_peaks(law: MotionLaw) -> [f64; 4] {
    let mut peaks = [0.0_f64; 4];
    for step in 0..=SCAN_POINTS {
        let f = law.normalised(step as f64 / SCAN_POINTS as f64);
        let values = [
            f.velocity,
            f.acceleration,
            f.jerk,
            f.velocity * f.acceleration,
        ];
        for (peak, value) in peaks.iter_mut().zip(values) {
            *peak = peak.max(value.abs());
        }
    }
    peaks
}

#[test]
fn every_law_goes_from_0_to_1() {
    for law in MotionLaw::ALL {
        assert_close(law.normalised(0.0).position, 0.0, 1e-12);
        assert_close(law.normalised(1.0).position, 1.0, 1e-12);
        assert_close(law.normalised(0.5).position, 0.5, 1e-12);
    }
}

#[test]
fn the_rest_in_rest_laws_start_and_end_at_rest() {
    for law in MotionLaw::ALL {
        if law == MotionLaw::Line {
            continue;
        }
        for u in [0.0, 1.0] {
            let f = law.normalised(u);
            assert_close(f.velocity, 0.0, 1e-9);
            let acceleration_is_zero = !matches!(law, MotionLaw::Poly3 | MotionLaw::SimpleHarmonic);
            if acceleration_is_zero {
                assert_close(f.acceleration, 0.0, 1e-9);
            }
            if law == MotionLaw::Poly7 {
                assert_close(f.jerk, 0.0, 1e-9);
            }
        }
    }
}

#[test]
fn each_derivative_of_every_law_is_the_slope_of_the_one_below() {
    let step = 1e-6;
    for law in MotionLaw::ALL {
        for index in 1..200 {
            let u = index as f64 / 200.0 + 0.0013;
            let (below, above) = (law.normalised(u - step), law.normalised(u + step));
            let f = law.normalised(u);
            let slope = |pick: fn(&CamSample) -> f64| (pick(&above) - pick(&below)) / (2.0 * step);
            let scale = law.characteristic_values();
            assert_close(slope(|s| s.position), f.velocity, 1e-6 * scale.cv);
            assert_close(
                slope(|s| s.velocity),
                f.acceleration,
                1e-6 * scale.ca_inside.max(1.0),
            );
            // The modified laws' jerk has no jump inside their pieces; the points above avoid
            // the piece borders by the 0.0013 offset.
            assert_close(
                slope(|s| s.acceleration),
                f.jerk,
                1e-5 * scale.cj_inside.max(1.0),
            );
        }
    }
}

#[test]
// The table holds the printed figures, 6.283 for 2π among them, not the constants.
#[allow(clippy::approx_constant)]
fn scanned_peaks_match_the_vdi_2143_values_of_peers_5_1() {
    // (law, Cv, Ca, Cj or Cj inside the interval, Cmv, half a unit of the last printed digit of
    // each value in the table of docs peers.md §5.1).
    let table: [(MotionLaw, [(f64, f64); 4]); 7] = [
        (
            MotionLaw::Poly5,
            [(1.875, 5e-4), (5.774, 5e-4), (60.0, 5e-2), (6.69, 5e-3)],
        ),
        (
            MotionLaw::Poly7,
            [(2.1875, 5e-5), (7.513, 5e-4), (52.5, 5e-2), (10.75, 5e-3)],
        ),
        (
            MotionLaw::Cycloid,
            [(2.000, 5e-4), (6.283, 5e-4), (39.48, 5e-3), (8.16, 5e-3)],
        ),
        (
            MotionLaw::InclinedSine,
            [(2.000, 5e-4), (6.283, 5e-4), (39.48, 5e-3), (8.16, 5e-3)],
        ),
        (
            MotionLaw::ModifiedSine,
            [(1.760, 5e-4), (5.528, 5e-4), (69.5, 5e-2), (5.46, 5e-3)],
        ),
        (
            MotionLaw::ModifiedTrapezoid,
            [(2.000, 5e-4), (4.888, 5e-4), (61.4, 5e-2), (8.09, 5e-3)],
        ),
        (
            MotionLaw::SimpleHarmonic,
            [(1.571, 5e-4), (4.935, 5e-4), (15.5, 5e-2), (3.88, 5e-3)],
        ),
    ];
    for (law, expected) in table {
        let peaks = scanned_peaks(law);
        for ((peak, (value, half_digit)), name) in
            peaks.iter().zip(expected).zip(["Cv", "Ca", "Cj", "Cmv"])
        {
            assert!(
                (peak - value).abs() <= half_digit.max(1e-3 * value),
                "{law} {name}: scanned {peak}, table {value}"
            );
        }
    }
}

#[test]
fn the_characteristic_constants_agree_with_the_scanned_peaks() {
    for law in MotionLaw::ALL {
        let values = law.characteristic_values();
        let peaks = scanned_peaks(law);
        let constants = [values.cv, values.ca_inside, values.cj_inside];
        for ((constant, peak), name) in constants.iter().zip(peaks).zip(["Cv", "Ca", "Cj"]) {
            assert!(
                (constant - peak).abs() <= 1e-3 * peak.max(1.0),
                "{law} {name}: constant {constant}, scanned {peak}"
            );
        }
        if values.cmv.is_finite() {
            assert!(
                (values.cmv - peaks[3]).abs() <= 1e-3 * peaks[3],
                "{law} Cmv: constant {}, scanned {}",
                values.cmv,
                peaks[3]
            );
        }
    }
}

#[test]
fn a_value_is_infinite_exactly_where_the_derivative_below_jumps_against_a_dwell() {
    for law in MotionLaw::ALL {
        let values = law.characteristic_values();
        let (start, end) = (law.normalised(0.0), law.normalised(1.0));
        let velocity_jumps = start.velocity.abs() > 1e-9 || end.velocity.abs() > 1e-9;
        let acceleration_jumps = start.acceleration.abs() > 1e-9 || end.acceleration.abs() > 1e-9;
        assert_eq!(values.ca.is_infinite(), velocity_jumps, "{law} Ca");
        assert_eq!(
            values.cj.is_infinite(),
            velocity_jumps || acceleration_jumps,
            "{law} Cj"
        );
        if !values.ca.is_infinite() {
            assert_eq!(values.ca, values.ca_inside, "{law}");
        }
        if !values.cj.is_infinite() {
            assert_eq!(values.cj, values.cj_inside, "{law}");
        }
    }
    // The closed forms of the simple harmonic and the cubic.
    let harmonic = MotionLaw::SimpleHarmonic.characteristic_values();
    assert_close(harmonic.cv, PI / 2.0, 1e-15);
    assert_close(harmonic.cj_inside, PI * PI * PI / 2.0, 1e-12);
    let cubic = MotionLaw::Poly3.characteristic_values();
    assert_close(cubic.cmv, 2.0 * 3.0_f64.sqrt(), 1e-12);
}

#[test]
fn the_inclined_sine_is_the_cycloid() {
    for step in 0..=100 {
        let u = step as f64 / 100.0;
        assert_eq!(
            MotionLaw::InclinedSine.normalised(u),
            MotionLaw::Cycloid.normalised(u)
        );
    }
}

/// One segment of `law` from `start` to `end`.
fn single(law: MotionLaw, start: KeyPoint, end: KeyPoint) -> SegmentedCam {
    SegmentedCam::new(start, vec![Segment::new(law, end)]).unwrap()
}

#[track_caller]
fn assert_meets(sample: CamSample, point: &KeyPoint, derivatives: usize) {
    let expected = [point.slave, point.velocity, point.acceleration, point.jerk];
    let actual = [
        sample.position,
        sample.velocity,
        sample.acceleration,
        sample.jerk,
    ];
    for (actual, expected) in actual.iter().zip(expected).take(derivatives + 1) {
        assert_close(*actual, expected, 1e-9 * expected.abs().max(1.0));
    }
}

#[test]
fn polynomial_segments_meet_general_boundary_values() {
    let start = KeyPoint {
        master: 35.0,
        slave: -12.5,
        velocity: 0.75,
        acceleration: -0.02,
        jerk: 0.0015,
    };
    let end = KeyPoint {
        master: 155.0,
        slave: 210.0,
        velocity: -1.25,
        acceleration: 0.035,
        jerk: -0.0004,
    };
    for (law, derivatives) in [
        (MotionLaw::Line, 0),
        (MotionLaw::Poly3, 1),
        (MotionLaw::Poly5, 2),
        (MotionLaw::Poly7, 3),
    ] {
        let cam = single(law, start, end);
        assert_meets(cam.sample(start.master), &start, derivatives);
        assert_meets(cam.sample(end.master), &end, derivatives);
    }
    // The line's velocity is its chord.
    let line = single(MotionLaw::Line, start, end);
    assert_close(line.sample(100.0).velocity, 222.5 / 120.0, 1e-12);
}

#[test]
fn rest_in_rest_laws_run_dwell_to_dwell_and_between_equal_velocities() {
    let shapes = [
        MotionLaw::ModifiedSine,
        MotionLaw::ModifiedTrapezoid,
        MotionLaw::Cycloid,
        MotionLaw::SimpleHarmonic,
        MotionLaw::InclinedSine,
    ];
    for law in shapes {
        // Dwell to dwell (R-R): the law scaled to a stroke of 180 over 360.
        let start = KeyPoint::rest(0.0, 10.0);
        let end = KeyPoint::rest(360.0, 190.0);
        let cam = single(law, start, end);
        let acceleration_known = law != MotionLaw::SimpleHarmonic;
        assert_meets(
            cam.sample(0.0),
            &start,
            if acceleration_known { 2 } else { 1 },
        );
        assert_meets(
            cam.sample(360.0),
            &end,
            if acceleration_known { 2 } else { 1 },
        );
        let peak = cam.segment_bounds()[0].max_abs_velocity;
        let expected = law.characteristic_values().cv * 180.0 / 360.0;
        assert_close(peak, expected, 1e-9);
        // Constant velocity to constant velocity (G-G): the law's stroke rides on the line.
        let start = KeyPoint::xyva(100.0, 0.0, 2.0, 0.0);
        let end = KeyPoint::xyva(200.0, 150.0, 2.0, 0.0);
        let cam = single(law, start, end);
        assert_meets(
            cam.sample(100.0),
            &start,
            if acceleration_known { 2 } else { 1 },
        );
        assert_meets(
            cam.sample(200.0),
            &end,
            if acceleration_known { 2 } else { 1 },
        );
        // Halfway the law has done half its stroke: 0 + 2·50 + (150 − 200)/2.
        assert_close(cam.sample(150.0).position, 75.0, 1e-9);
    }
}
