//! From the project model's cam table to a `motion` curve, and its continuity check.

use motion::cam::{
    CamError, ContinuityChecks, ContinuityWarning, KeyPoint, MotionLaw, Periodicity, PointCam,
    PointInterpolation, Segment, SegmentBounds, SegmentedCam,
};
use motion::curve::{CamCurve, CamPoint, CamSample};
use project_model::{CamKeyPoint, CamProfile, CamTable};
use thiserror::Error;

/// A cam table's curve: the segments with their laws, or the interpolated point table.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    /// A cam of segments between key points.
    Segmented(SegmentedCam),
    /// A point table.
    Points(PointCam),
}

/// Why a cam table has no curve. The message names the cam and, through motion's
/// [`CamError`], the 1-based segment, key point or row that is wrong.
#[derive(Clone, Debug, Error, PartialEq)]
#[error("cam {cam}: {source}")]
pub struct ConvertError {
    /// The cam's name.
    pub cam: String,
    /// What is wrong, naming the segment, key point or row.
    #[source]
    pub source: CamError,
}

/// The curve of `cam`, validated: master positions increasing, every value finite, every
/// segment's boundary values possible for its law.
pub fn curve_of(cam: &CamTable) -> Result<Curve, ConvertError> {
    let wrap = |source| ConvertError {
        cam: cam.name.clone(),
        source,
    };
    match &cam.profile {
        CamProfile::Segments { start, segments } => {
            let segments = segments
                .iter()
                .map(|segment| Segment {
                    law: law_of(segment.law),
                    lambda: segment.lambda,
                    end: key_point_of(&segment.end),
                })
                .collect();
            SegmentedCam::new(key_point_of(start), segments)
                .map(Curve::Segmented)
                .map_err(wrap)
        }
        CamProfile::Points {
            interpolation,
            points,
        } => {
            let points = points
                .iter()
                .map(|point| CamPoint {
                    master: point.master,
                    slave: point.slave,
                    velocity: 0.0,
                    acceleration: 0.0,
                })
                .collect();
            let interpolation = match interpolation {
                project_model::PointInterpolation::Linear => PointInterpolation::Linear,
                project_model::PointInterpolation::Cubic => PointInterpolation::Cubic,
            };
            PointCam::new(points, interpolation)
                .map(Curve::Points)
                .map_err(wrap)
        }
    }
}

/// The discontinuities of `cam` among the quantities its `continuity` flags select. A cam with
/// smooth transition runs periodically, so its end is compared with its start, its slave
/// positions modulo the slave period if one is set.
pub fn continuity_warnings(cam: &CamTable) -> Result<Vec<ContinuityWarning>, ConvertError> {
    Ok(curve_of(cam)?.check_continuity(cam))
}

impl Curve {
    /// The continuity warnings of this curve under `cam`'s continuity flags and period.
    pub fn check_continuity(&self, cam: &CamTable) -> Vec<ContinuityWarning> {
        let checks = ContinuityChecks {
            position: cam.continuity.position,
            velocity: cam.continuity.velocity,
            acceleration: cam.continuity.acceleration,
            jerk: cam.continuity.jerk,
        };
        // CODESYS's slave period is "only effective with smooth transition", and smooth
        // transition is what makes the end join the start.
        let periodicity = if cam.period.smooth_transition {
            Periodicity::Periodic {
                slave_period: cam.period.slave_period,
            }
        } else {
            Periodicity::NonPeriodic
        };
        match self {
            Curve::Segmented(curve) => curve.check_continuity(checks, periodicity),
            Curve::Points(curve) => curve.check_continuity(checks, periodicity),
        }
    }

    /// The master positions of the key points (segmented cam) or rows (point table).
    pub fn key_masters(&self) -> Vec<f64> {
        match self {
            Curve::Segmented(curve) => curve.key_points().map(|point| point.master).collect(),
            Curve::Points(curve) => curve.points().iter().map(|point| point.master).collect(),
        }
    }

    /// The read-only values of every segment (segmented cam), empty for a point table.
    pub fn segment_bounds(&self) -> Vec<SegmentBounds> {
        match self {
            Curve::Segmented(curve) => curve.segment_bounds(),
            Curve::Points(_) => Vec::new(),
        }
    }
}

impl CamCurve for Curve {
    fn master_range(&self) -> (f64, f64) {
        match self {
            Curve::Segmented(curve) => curve.master_range(),
            Curve::Points(curve) => curve.master_range(),
        }
    }

    fn sample(&self, master: f64) -> CamSample {
        match self {
            Curve::Segmented(curve) => curve.sample(master),
            Curve::Points(curve) => curve.sample(master),
        }
    }
}

/// The motion crate's law of a model law; the two enums mirror each other.
pub(crate) fn law_of(law: project_model::MotionLaw) -> MotionLaw {
    use project_model::MotionLaw as Model;
    match law {
        Model::Line => MotionLaw::Line,
        Model::Poly3 => MotionLaw::Poly3,
        Model::Poly5 => MotionLaw::Poly5,
        Model::Poly7 => MotionLaw::Poly7,
        Model::ModifiedSine => MotionLaw::ModifiedSine,
        Model::ModifiedTrapezoid => MotionLaw::ModifiedTrapezoid,
        Model::Cycloid => MotionLaw::Cycloid,
        Model::SimpleHarmonic => MotionLaw::SimpleHarmonic,
        Model::InclinedSine => MotionLaw::InclinedSine,
    }
}

fn key_point_of(point: &CamKeyPoint) -> KeyPoint {
    KeyPoint {
        master: point.master,
        slave: point.slave,
        velocity: point.velocity,
        acceleration: point.acceleration,
        jerk: point.jerk,
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use motion::cam::ContinuityQuantity;
    use project_model::{CamSegment, CamTablePoint};

    #[test]
    fn the_codesys_default_converts_and_samples_its_key_points() {
        let cam = CamTable::codesys_default("Cam");
        let curve = curve_of(&cam).unwrap();
        assert_eq!(curve.master_range(), (0.0, 360.0));
        assert_eq!(curve.key_masters(), [0.0, 120.0, 240.0, 360.0]);
        let at = curve.sample(120.0);
        assert!((at.position - 120.0).abs() < 1e-9);
        assert!((at.velocity - 1.0).abs() < 1e-9);
        assert_eq!(curve.segment_bounds().len(), 3);
    }

    #[test]
    fn a_backwards_segment_is_refused_naming_the_segment() {
        let mut cam = CamTable::codesys_default("Knife");
        if let CamProfile::Segments { segments, .. } = &mut cam.profile {
            segments[1].end.master = 100.0;
        }
        let error = curve_of(&cam).unwrap_err().to_string();
        assert!(
            error.starts_with("cam Knife: segment 2 (Poly5, 120..100)"),
            "{error}"
        );
        assert!(error.contains("must increase"), "{error}");
    }

    #[test]
    fn a_rest_law_with_different_velocities_names_its_segment() {
        let mut cam = CamTable::codesys_default("Cam");
        if let CamProfile::Segments { segments, .. } = &mut cam.profile {
            segments[0] = CamSegment {
                law: project_model::MotionLaw::Cycloid,
                ..segments[0].clone()
            };
        }
        let error = curve_of(&cam).unwrap_err().to_string();
        assert!(error.contains("segment 1 (Cycloid"), "{error}");
        assert!(
            error.contains("velocity 0 and end at velocity 1"),
            "{error}"
        );
    }

    #[test]
    fn a_point_table_with_a_repeated_master_names_the_row() {
        let mut cam = CamTable::codesys_default("Table");
        cam.profile = CamProfile::Points {
            interpolation: project_model::PointInterpolation::Linear,
            points: vec![
                CamTablePoint {
                    master: 0.0,
                    slave: 0.0,
                },
                CamTablePoint {
                    master: 10.0,
                    slave: 1.0,
                },
                CamTablePoint {
                    master: 10.0,
                    slave: 2.0,
                },
            ],
        };
        let error = curve_of(&cam).unwrap_err().to_string();
        assert!(
            error.contains("row 3: master position 10 repeats"),
            "{error}"
        );
    }

    #[test]
    fn a_periodic_cam_compares_its_end_with_its_start_modulo_the_slave_period() {
        let mut cam = CamTable::codesys_default("Cam");
        if let CamProfile::Segments { segments, .. } = &mut cam.profile {
            segments[2].end.slave = 720.0;
        }
        cam.period.smooth_transition = true;
        cam.period.slave_period = None;
        let warnings = continuity_warnings(&cam).unwrap();
        assert!(
            warnings
                .iter()
                .any(|w| w.joint == 1 && w.quantity == ContinuityQuantity::Position),
            "{warnings:?}"
        );
        cam.period.slave_period = Some(360.0);
        assert_eq!(continuity_warnings(&cam).unwrap(), []);
        cam.period.slave_period = None;
        cam.period.smooth_transition = false;
        assert_eq!(continuity_warnings(&cam).unwrap(), []);
    }
}
