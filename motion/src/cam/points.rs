//! A cam given as a table of points, interpolated between them.

use crate::cam::continuity::{self, ContinuityChecks, ContinuityWarning, Joint, Periodicity};
use crate::cam::error::CamError;
use crate::cam::interpolation::PointInterpolation;
use crate::cam::polynomial::{Boundary, Polynomial};
use crate::cam::sampling;
use crate::cam::spline;
use crate::curve::{CamCurve, CamPoint, CamSample};

/// A cam given as a table of points with strictly increasing master positions, interpolated
/// between them (CODESYS 1-D, 2-D and XYVA tables, Omron cam data, Delta key points). Built once
/// and validated; evaluating it does not allocate.
#[derive(Clone, Debug, PartialEq)]
pub struct PointCam {
    /// The points as given.
    points: Vec<CamPoint>,
    /// How values between the points are computed.
    interpolation: PointInterpolation,
    /// The start master of every interval, for the binary search of `sample`.
    start_masters: Vec<f64>,
    /// The intervals between consecutive points, solved for evaluation.
    intervals: Vec<Interval>,
}

/// One interval between two consecutive points, as a polynomial in its normalised master.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Interval {
    /// The master position of the interval's first point.
    start_master: f64,
    /// 1 / the interval's master length.
    inv_dx: f64,
    /// The slave over u ∈ [0, 1].
    polynomial: Polynomial<6>,
}

impl PointCam {
    /// Validates the table and solves the interpolation.
    ///
    /// Fails when there are fewer than two rows, when a row holds a value that is not a finite
    /// number, or when a row's master position is not above the previous row's; errors name
    /// the 1-based row.
    pub fn new(points: Vec<CamPoint>, interpolation: PointInterpolation) -> Result<Self, CamError> {
        if points.len() < 2 {
            return Err(CamError::TooFewRows { rows: points.len() });
        }
        for (index, point) in points.iter().enumerate() {
            let row = index + 1;
            let fields = [
                ("master position", point.master),
                ("slave position", point.slave),
                ("velocity", point.velocity),
                ("acceleration", point.acceleration),
            ];
            if let Some((field, _)) = fields.into_iter().find(|(_, value)| !value.is_finite()) {
                return Err(CamError::NonFiniteRow { row, field });
            }
            if index == 0 {
                continue;
            }
            let previous_master = points[index - 1].master;
            if point.master == previous_master {
                return Err(CamError::RepeatedMaster {
                    row,
                    previous_row: row - 1,
                    master: point.master,
                });
            }
            // The master span must also be finite, or the interval's reciprocal length is zero.
            if point.master < previous_master || !(point.master - previous_master).is_finite() {
                return Err(CamError::MasterDecreasing {
                    row,
                    previous_row: row - 1,
                    master: point.master,
                    previous_master,
                });
            }
        }
        let slopes = match interpolation {
            PointInterpolation::Cubic => spline::natural_slopes(&points),
            PointInterpolation::Linear | PointInterpolation::Quintic => Vec::new(),
        };
        let intervals: Vec<Interval> = points
            .windows(2)
            .enumerate()
            .map(|(index, pair)| {
                let (from, to) = (pair[0], pair[1]);
                let dx = to.master - from.master;
                let polynomial = match interpolation {
                    PointInterpolation::Linear => Polynomial::line(from.slave, to.slave),
                    PointInterpolation::Cubic => Polynomial::hermite(
                        2,
                        boundary(from.slave, slopes[index], 0.0),
                        boundary(to.slave, slopes[index + 1], 0.0),
                        dx,
                    ),
                    PointInterpolation::Quintic => Polynomial::hermite(
                        3,
                        boundary(from.slave, from.velocity, from.acceleration),
                        boundary(to.slave, to.velocity, to.acceleration),
                        dx,
                    ),
                };
                Interval {
                    start_master: from.master,
                    inv_dx: 1.0 / dx,
                    polynomial,
                }
            })
            .collect();
        let start_masters = intervals
            .iter()
            .map(|interval| interval.start_master)
            .collect();
        Ok(Self {
            points,
            interpolation,
            start_masters,
            intervals,
        })
    }

    /// The points, in master order.
    pub fn points(&self) -> &[CamPoint] {
        &self.points
    }

    /// How values between the points are computed.
    pub fn interpolation(&self) -> PointInterpolation {
        self.interpolation
    }

    /// `elements` equidistant samples over the master range, both ends included.
    pub fn sample_points(&self, elements: usize) -> Result<Vec<CamPoint>, CamError> {
        sampling::sample_points(self, elements)
    }

    /// The discontinuities at the inner points (and, for a periodic cam, between the last point
    /// and the first) among the quantities `checks` selects; warnings name the 1-based row.
    pub fn check_continuity(
        &self,
        checks: ContinuityChecks,
        periodicity: Periodicity,
    ) -> Vec<ContinuityWarning> {
        let joints = self
            .intervals
            .windows(2)
            .enumerate()
            .map(|(index, pair)| Joint {
                key_point: index + 2,
                master: pair[1].start_master,
                left: pair[0].evaluate(1.0),
                right: pair[1].evaluate(0.0),
            });
        let (first, last) = match (self.intervals.first(), self.intervals.last()) {
            (Some(first), Some(last)) => (first.evaluate(0.0), last.evaluate(1.0)),
            _ => return Vec::new(),
        };
        continuity::check(
            joints,
            first,
            last,
            self.master_range(),
            checks,
            periodicity,
        )
    }
}

impl Interval {
    #[inline]
    fn evaluate(&self, u: f64) -> CamSample {
        self.polynomial.evaluate(u, self.inv_dx)
    }
}

impl CamCurve for PointCam {
    fn master_range(&self) -> (f64, f64) {
        let first = self.points.first().map_or(0.0, |point| point.master);
        let last = self.points.last().map_or(first, |point| point.master);
        (first, last)
    }

    #[inline]
    fn sample(&self, master: f64) -> CamSample {
        let index = self
            .start_masters
            .partition_point(|&start| start <= master)
            .saturating_sub(1);
        match self.intervals.get(index) {
            Some(interval) => interval
                .evaluate(((master - interval.start_master) * interval.inv_dx).clamp(0.0, 1.0)),
            None => CamSample::default(),
        }
    }
}

fn boundary(position: f64, velocity: f64, acceleration: f64) -> Boundary {
    Boundary {
        position,
        velocity,
        acceleration,
        jerk: 0.0,
    }
}
