//! A cam made of segments with a motion law each, chained from a start key point.

use crate::cam::continuity::{self, ContinuityChecks, ContinuityWarning, Joint, Periodicity};
use crate::cam::error::CamError;
use crate::cam::key_point::KeyPoint;
use crate::cam::law::MotionLaw;
use crate::cam::sampling;
use crate::cam::segment::Segment;
use crate::cam::segment_bounds::SegmentBounds;
use crate::cam::segment_curve::SegmentCurve;
use crate::curve::{CamCurve, CamPoint, CamSample};

/// A cam made of segments chained from a start key point, each following its motion law to
/// its end key point (the CODESYS "Segments" compile format and the project model's
/// `CamProfile::Segments`). Built once and validated; evaluating it does not allocate.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentedCam {
    /// The first key point, at the master start.
    start: KeyPoint,
    /// The segments as given.
    segments: Vec<Segment>,
    /// The segments solved for evaluation, in the same order.
    curves: Vec<SegmentCurve>,
    /// The start master of every segment, for the binary search of `sample`.
    start_masters: Vec<f64>,
}

impl SegmentedCam {
    /// Validates the key points and segments and solves every segment.
    ///
    /// Fails on the first segment that has a non-finite value, does not advance the master,
    /// sets λ, or asks a rest-in-rest law for boundary values it cannot meet.
    pub fn new(start: KeyPoint, segments: Vec<Segment>) -> Result<Self, CamError> {
        if let Some(field) = start.non_finite_field() {
            return Err(CamError::NonFiniteKeyPoint {
                key_point: 1,
                field,
            });
        }
        if segments.is_empty() {
            return Err(CamError::NoSegments);
        }
        let mut curves = Vec::with_capacity(segments.len());
        let mut from = start;
        for (index, segment) in segments.iter().enumerate() {
            curves.push(SegmentCurve::new(index + 1, &from, segment)?);
            from = segment.end;
        }
        let start_masters = curves.iter().map(|curve| curve.start_master).collect();
        Ok(Self {
            start,
            segments,
            curves,
            start_masters,
        })
    }

    /// The cam a new CODESYS cam object starts with: three Poly5 segments through the (X, Y, V,
    /// A) points (0, 0, 0, 0), (120, 120, 1, 0), (240, 240, 1, 0) and (360, 360, 0, 0).
    pub fn codesys_default() -> Self {
        let segments = vec![
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(120.0, 120.0, 1.0, 0.0)),
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(240.0, 240.0, 1.0, 0.0)),
            Segment::new(MotionLaw::Poly5, KeyPoint::xyva(360.0, 360.0, 0.0, 0.0)),
        ];
        match Self::new(KeyPoint::rest(0.0, 0.0), segments) {
            Ok(cam) => cam,
            // Poly5 meets any finite boundary values over a positive master range, and a test
            // builds this cam, so the error arm is never taken.
            Err(error) => unreachable!("the CODESYS default cam is invalid: {error}"),
        }
    }

    /// The start key point.
    pub fn start(&self) -> &KeyPoint {
        &self.start
    }

    /// The segments, in master order.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// The key points: the start point, then the end point of every segment.
    pub fn key_points(&self) -> impl Iterator<Item = &KeyPoint> {
        std::iter::once(&self.start).chain(self.segments.iter().map(|segment| &segment.end))
    }

    /// The derived values of every segment (min and max position, max |velocity| and max
    /// |acceleration| with respect to the master), in segment order.
    pub fn segment_bounds(&self) -> Vec<SegmentBounds> {
        self.curves
            .iter()
            .map(|curve| SegmentBounds::scan(|u| curve.evaluate(u)))
            .collect()
    }

    /// The cam in the XYVA format: one point per key point with the slave's velocity and
    /// acceleration there, which consecutive quintics join again.
    ///
    /// CODESYS allows the format only for cams of Line and Poly5 segments; any other law is an
    /// error naming its segment. Velocity and acceleration are taken from the curve itself, so a
    /// Line segment contributes its slope whatever its key points say. A point cannot hold a
    /// kink: where the velocity jumps (a Line beside a Poly5 of another end velocity), the point
    /// takes the values of the segment that starts there, and the last point those of the end
    /// of the last segment; check the continuity first to know whether that loses anything.
    pub fn xyva_points(&self) -> Result<Vec<CamPoint>, CamError> {
        for (index, (segment, curve)) in self.segments.iter().zip(&self.curves).enumerate() {
            if !matches!(segment.law, MotionLaw::Line | MotionLaw::Poly5) {
                return Err(CamError::LawNotInXyva {
                    segment: index + 1,
                    law: segment.law,
                    start_master: curve.start_master,
                    end_master: curve.end_master,
                });
            }
        }
        let mut points = Vec::with_capacity(self.curves.len() + 1);
        for curve in &self.curves {
            points.push(point(curve.start_master, curve.evaluate(0.0)));
        }
        if let Some(last) = self.curves.last() {
            points.push(point(last.end_master, last.evaluate(1.0)));
        }
        Ok(points)
    }

    /// `elements` equidistant samples over the master range, both ends included, with the
    /// slave's velocity and acceleration, for the 1-D and 2-D table formats.
    pub fn sample_points(&self, elements: usize) -> Result<Vec<CamPoint>, CamError> {
        sampling::sample_points(self, elements)
    }

    /// The discontinuities at the joints between segments (and, for a periodic cam, between
    /// the end and the start) among the quantities `checks` selects.
    pub fn check_continuity(
        &self,
        checks: ContinuityChecks,
        periodicity: Periodicity,
    ) -> Vec<ContinuityWarning> {
        let joints = self
            .curves
            .windows(2)
            .enumerate()
            .map(|(index, pair)| Joint {
                key_point: index + 2,
                master: pair[1].start_master,
                left: pair[0].evaluate(1.0),
                right: pair[1].evaluate(0.0),
            });
        let (first, last) = match (self.curves.first(), self.curves.last()) {
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

impl CamCurve for SegmentedCam {
    fn master_range(&self) -> (f64, f64) {
        let end = self
            .curves
            .last()
            .map_or(self.start.master, |curve| curve.end_master);
        (self.start.master, end)
    }

    #[inline]
    fn sample(&self, master: f64) -> CamSample {
        // The segment is the last one starting at or before `master`; a master below the
        // range falls to the first segment, which clamps it.
        let index = self
            .start_masters
            .partition_point(|&start| start <= master)
            .saturating_sub(1);
        match self.curves.get(index) {
            Some(curve) => curve.sample(master),
            None => CamSample::default(),
        }
    }
}

fn point(master: f64, sample: CamSample) -> CamPoint {
    CamPoint {
        master,
        slave: sample.position,
        velocity: sample.velocity,
        acceleration: sample.acceleration,
    }
}
