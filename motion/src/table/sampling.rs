//! Points of a cam: equidistant samples of a curve, and the checks every exported point list
//! passes (`docs/cam-formats.md` §1.1).

use super::TableError;
use crate::curve::{CamCurve, CamPoint};

/// The most points [`sample_equidistant`] makes, far beyond any controller's table, so a
/// mistyped count fails with a message instead of exhausting memory.
pub const MAX_SAMPLES: usize = 1 << 20;

/// The most elements of a CODESYS table or XYVA array: `MC_CAM_REF.nElements` is an `INT`.
pub(crate) const CODESYS_MAX_ELEMENTS: usize = 32_767;

/// Fails when `count` exceeds `max`, the most points `system` holds in one cam table.
pub(crate) fn check_count(
    count: usize,
    max: usize,
    system: &'static str,
) -> Result<(), TableError> {
    if count > max {
        return Err(TableError::TooManyPoints { system, max, count });
    }
    Ok(())
}

/// Samples `curve` at `count` equidistant master positions, both ends of its master range
/// included: point i is at `start + i·(end − start)/(count − 1)` and the last one is exactly
/// `end`. Each point carries the slave position, dY/dX and d²Y/dX² of the curve.
///
/// Fails when `count` is below 2 or above [`MAX_SAMPLES`], when the master range is not a finite increasing range, or
/// when the curve returns a value that is not finite (naming the point).
pub fn sample_equidistant(curve: &dyn CamCurve, count: usize) -> Result<Vec<CamPoint>, TableError> {
    if count < 2 {
        return Err(TableError::TooFewPoints { count });
    }
    check_count(count, MAX_SAMPLES, "a Rivet export")?;
    let (start, end) = curve.master_range();
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(TableError::InvalidMasterRange { start, end });
    }
    let last = count - 1;
    let step = (end - start) / last as f64;
    let points: Vec<CamPoint> = (0..count)
        .map(|index| {
            // The last point is set to `end` itself so rounding in the step cannot leave it short.
            let master = if index == last {
                end
            } else {
                start + index as f64 * step
            };
            let sample = curve.sample(master);
            CamPoint {
                master,
                slave: sample.position,
                velocity: sample.velocity,
                acceleration: sample.acceleration,
            }
        })
        .collect();
    check_points(&points)?;
    Ok(points)
}

/// Checks that `points` can be exported: at least two, every value finite, the master
/// strictly increasing. The error names the first offending point by its 0-based index.
pub fn check_points(points: &[CamPoint]) -> Result<(), TableError> {
    if points.len() < 2 {
        return Err(TableError::TooFewPoints {
            count: points.len(),
        });
    }
    for (index, point) in points.iter().enumerate() {
        let fields = [
            ("master", point.master),
            ("slave", point.slave),
            ("velocity", point.velocity),
            ("acceleration", point.acceleration),
        ];
        if let Some((field, _)) = fields.iter().find(|(_, value)| !value.is_finite()) {
            return Err(TableError::NotFinite { index, field });
        }
        if index > 0 {
            let previous = points[index - 1].master;
            if point.master <= previous {
                return Err(TableError::MasterNotIncreasing {
                    index,
                    master: point.master,
                    previous,
                });
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::table::test_curve::{Line, Poly345};

    #[test]
    fn five_samples_of_the_345_polynomial_include_both_ends() {
        let points = sample_equidistant(&Poly345, 5).unwrap();
        let masters: Vec<f64> = points.iter().map(|p| p.master).collect();
        assert_eq!(masters, [0.0, 90.0, 180.0, 270.0, 360.0]);
        let slaves: Vec<f64> = points.iter().map(|p| p.slave).collect();
        assert_eq!(slaves, [0.0, 18.6328125, 90.0, 161.3671875, 180.0]);
        assert_eq!(points[1].velocity, 0.52734375);
        assert_eq!(points[2].velocity, 0.9375);
        assert_eq!(points[1].acceleration, 0.0078125);
        assert_eq!(points[3].acceleration, -0.0078125);
    }

    #[test]
    fn the_last_sample_is_exactly_the_master_end() {
        let line = Line {
            start: 0.1,
            end: 0.7,
            slope: 2.0,
        };
        let points = sample_equidistant(&line, 7).unwrap();
        assert_eq!(points[0].master, 0.1);
        assert_eq!(points[6].master, 0.7);
        assert_eq!(points.len(), 7);
    }

    #[test]
    fn fewer_than_two_samples_are_refused() {
        assert_eq!(
            sample_equidistant(&Poly345, 1),
            Err(TableError::TooFewPoints { count: 1 })
        );
        assert_eq!(
            TableError::TooFewPoints { count: 1 }.to_string(),
            "a cam table needs at least 2 points, but 1 were given"
        );
    }

    #[test]
    fn an_absurd_number_of_samples_is_refused_before_allocating() {
        assert_eq!(
            sample_equidistant(&Poly345, usize::MAX)
                .unwrap_err()
                .to_string(),
            format!(
                "a Rivet export holds at most 1048576 points in one cam table, but {} were given",
                usize::MAX
            )
        );
    }

    #[test]
    fn an_empty_master_range_is_refused() {
        let line = Line {
            start: 10.0,
            end: 10.0,
            slope: 1.0,
        };
        let error = sample_equidistant(&line, 3).unwrap_err();
        assert_eq!(
            error,
            TableError::InvalidMasterRange {
                start: 10.0,
                end: 10.0
            }
        );
        assert_eq!(
            error.to_string(),
            "the cam's master range 10 to 10 cannot be sampled: both ends must be finite numbers and the start below the end"
        );
    }

    /// A curve that has no value beyond the middle of its range.
    struct UndefinedPastMiddle;

    impl CamCurve for UndefinedPastMiddle {
        fn master_range(&self) -> (f64, f64) {
            (0.0, 4.0)
        }

        fn sample(&self, master: f64) -> crate::curve::CamSample {
            crate::curve::CamSample {
                position: 1.0,
                velocity: if master > 2.0 { f64::NAN } else { 0.0 },
                ..Default::default()
            }
        }
    }

    #[test]
    fn a_curve_returning_nan_is_refused_naming_the_point() {
        let error = sample_equidistant(&UndefinedPastMiddle, 5).unwrap_err();
        assert_eq!(
            error,
            TableError::NotFinite {
                index: 3,
                field: "velocity"
            }
        );
        assert_eq!(
            error.to_string(),
            "point 3: the velocity is not a finite number"
        );
    }

    #[test]
    fn given_points_must_increase_in_master() {
        let points = [
            CamPoint {
                master: 0.0,
                ..CamPoint::default()
            },
            CamPoint {
                master: 130.0,
                ..CamPoint::default()
            },
            CamPoint {
                master: 120.0,
                ..CamPoint::default()
            },
        ];
        let error = check_points(&points).unwrap_err();
        assert_eq!(
            error.to_string(),
            "point 2: master 120 is not greater than 130 at point 1"
        );
    }
}
