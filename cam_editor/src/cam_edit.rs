//! Changes to a cam as whole new cams: each function returns the changed cam only when it is
//! still valid, so the editor can refuse a change in place and the project keeps its cam.

use motion::curve::CamCurve as _;
use project_model::{
    CamKeyPoint, CamProfile, CamSegment, CamTable, CamTablePoint, MotionLaw, TappetAction,
};
use thiserror::Error;

use crate::convert::{ConvertError, curve_of};

/// Why a change to a cam was refused.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum CamEditError {
    /// The changed cam would not be valid; the message names the segment or row.
    #[error(transparent)]
    Invalid(#[from] ConvertError),
    /// The first and the last key point hold the master range and cannot be deleted.
    #[error("key point {key_point} is an end of the cam and cannot be deleted")]
    EndPoint {
        /// The 1-based key point.
        key_point: usize,
    },
    /// A point table keeps at least two rows.
    #[error("row {row} cannot be deleted: a point table needs at least two rows")]
    TooFewRows {
        /// The 1-based row.
        row: usize,
    },
    /// The key point, row or segment does not exist.
    #[error("the cam has no {what} {number}")]
    NoSuch {
        /// "key point", "row" or "segment".
        what: &'static str,
        /// The 1-based number asked for.
        number: usize,
    },
}

/// The key points of a cam, the start point first: for a point table its rows, with velocity,
/// acceleration and jerk zero.
pub(crate) fn key_points(cam: &CamTable) -> Vec<CamKeyPoint> {
    match &cam.profile {
        CamProfile::Segments { start, segments } => std::iter::once(*start)
            .chain(segments.iter().map(|segment| segment.end))
            .collect(),
        CamProfile::Points { points, .. } => points
            .iter()
            .map(|point| CamKeyPoint {
                master: point.master,
                slave: point.slave,
                ..CamKeyPoint::default()
            })
            .collect(),
    }
}

/// `cam` with key point (or row) `index` (0-based, 0 the start) replaced by `point`.
///
/// The master range follows the first and the last key point. With smooth transition, editing
/// one end of a segmented cam sets the other end's velocity, acceleration and jerk to match
/// and its slave position to the same value, or to one a whole number of slave periods away.
pub fn set_key_point(
    cam: &CamTable,
    index: usize,
    point: CamKeyPoint,
) -> Result<CamTable, CamEditError> {
    let mut changed = cam.clone();
    let count = key_points(cam).len();
    if index >= count {
        return Err(CamEditError::NoSuch {
            what: "key point",
            number: index + 1,
        });
    }
    let last = count - 1;
    let smooth = cam.period.smooth_transition;
    let slave_period = cam
        .period
        .slave_period
        .filter(|p| p.is_finite() && *p != 0.0);
    match &mut changed.profile {
        CamProfile::Segments { start, segments } => {
            let matched = |other: &CamKeyPoint| CamKeyPoint {
                master: other.master,
                slave: match slave_period {
                    Some(period) => {
                        point.slave - period * ((point.slave - other.slave) / period).round()
                    }
                    None => point.slave,
                },
                velocity: point.velocity,
                acceleration: point.acceleration,
                jerk: point.jerk,
            };
            if index == 0 {
                *start = point;
                if smooth && let Some(end) = segments.last_mut() {
                    end.end = matched(&end.end);
                }
            } else {
                segments[index - 1].end = point;
                if smooth && index == last {
                    *start = matched(start);
                }
            }
        }
        CamProfile::Points { points, .. } => {
            points[index] = CamTablePoint {
                master: point.master,
                slave: point.slave,
            };
        }
    }
    fit_master_range(&mut changed);
    curve_of(&changed)?;
    Ok(changed)
}

/// `cam` with a key point inserted in the middle of segment (or between rows) `segment`
/// (0-based), on the curve: position and derivatives are those of the curve there, so the
/// shape does not change. Both halves keep the segment's law when it allows the new point's
/// values, and become Poly5 (Poly7 stays Poly7) when it does not.
pub fn insert_key_point(cam: &CamTable, segment: usize) -> Result<CamTable, CamEditError> {
    let curve = curve_of(cam)?;
    let points = key_points(cam);
    let (Some(from), Some(to)) = (points.get(segment), points.get(segment + 1)) else {
        return Err(CamEditError::NoSuch {
            what: "segment",
            number: segment + 1,
        });
    };
    let master = 0.5 * (from.master + to.master);
    // The sample just left of the middle is of the segment being split, whatever the
    // curve's convention at joints.
    let sample = curve.sample(master);
    let middle = CamKeyPoint {
        master,
        slave: sample.position,
        velocity: sample.velocity,
        acceleration: sample.acceleration,
        jerk: sample.jerk,
    };
    let mut changed = cam.clone();
    match &mut changed.profile {
        CamProfile::Segments { segments, .. } => {
            let old = segments[segment].clone();
            let first = CamSegment {
                end: middle,
                ..old.clone()
            };
            segments.insert(segment, first);
            if curve_of(&changed).is_err() {
                let law = if old.law == MotionLaw::Poly7 {
                    MotionLaw::Poly7
                } else {
                    MotionLaw::Poly5
                };
                if let CamProfile::Segments { segments, .. } = &mut changed.profile {
                    for half in &mut segments[segment..=segment + 1] {
                        half.law = law;
                        half.lambda = None;
                    }
                }
            }
        }
        CamProfile::Points { points, .. } => {
            points.insert(
                segment + 1,
                CamTablePoint {
                    master,
                    slave: sample.position,
                },
            );
        }
    }
    curve_of(&changed)?;
    Ok(changed)
}

/// `cam` without the inner key point (or row) `index` (0-based): the two segments around it
/// become one, with the law of the first, ending where the second ended.
pub fn delete_key_point(cam: &CamTable, index: usize) -> Result<CamTable, CamEditError> {
    let count = key_points(cam).len();
    let mut changed = cam.clone();
    match &mut changed.profile {
        CamProfile::Segments { segments, .. } => {
            if index >= count {
                return Err(CamEditError::NoSuch {
                    what: "key point",
                    number: index + 1,
                });
            }
            if index == 0 || index == count - 1 {
                return Err(CamEditError::EndPoint {
                    key_point: index + 1,
                });
            }
            let second = segments.remove(index);
            segments[index - 1].end = second.end;
        }
        CamProfile::Points { points, .. } => {
            if index >= count {
                return Err(CamEditError::NoSuch {
                    what: "row",
                    number: index + 1,
                });
            }
            if count <= 2 {
                return Err(CamEditError::TooFewRows { row: index + 1 });
            }
            points.remove(index);
        }
    }
    fit_master_range(&mut changed);
    curve_of(&changed)?;
    Ok(changed)
}

/// `cam` with segment `segment` (0-based) following `law`.
pub fn set_law(cam: &CamTable, segment: usize, law: MotionLaw) -> Result<CamTable, CamEditError> {
    let mut changed = cam.clone();
    let CamProfile::Segments { segments, .. } = &mut changed.profile else {
        return Err(CamEditError::NoSuch {
            what: "segment",
            number: segment + 1,
        });
    };
    let Some(target) = segments.get_mut(segment) else {
        return Err(CamEditError::NoSuch {
            what: "segment",
            number: segment + 1,
        });
    };
    target.law = law;
    if law != MotionLaw::ModifiedSine {
        target.lambda = None;
    }
    curve_of(&changed)?;
    Ok(changed)
}

/// The pass action a click on a tappet's end switches to: None, On, Off, Invert, and round
/// again. A timed action counts as On.
pub fn next_action(action: TappetAction) -> TappetAction {
    match action {
        TappetAction::None => TappetAction::On,
        TappetAction::On | TappetAction::TimedOn { .. } => TappetAction::Off,
        TappetAction::Off => TappetAction::Invert,
        TappetAction::Invert => TappetAction::None,
    }
}

/// Makes the master range that of the first and the last key point, which are the cam's
/// master start and end (the first and last rows of the CODESYS cam table).
pub(crate) fn fit_master_range(cam: &mut CamTable) {
    let points = key_points(cam);
    if let (Some(first), Some(last)) = (points.first(), points.last()) {
        cam.master.start = first.master;
        cam.master.end = last.master;
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    #[test]
    fn inserting_splits_a_segment_on_the_curve_and_deleting_merges_it_back() {
        let cam = CamTable::codesys_default("Cam");
        let inserted = insert_key_point(&cam, 0).unwrap();
        let points = key_points(&inserted);
        assert_eq!(points.len(), 5);
        assert_eq!(points[1].master, 60.0);
        // The default's first segment is a Poly5 from rest to velocity 1; its middle is on it.
        let before = curve_of(&cam).unwrap().sample(60.0).position;
        assert!((points[1].slave - before).abs() < 1e-9);
        let deleted = delete_key_point(&inserted, 1).unwrap();
        assert_eq!(key_points(&deleted), key_points(&cam));
    }

    #[test]
    fn the_ends_cannot_be_deleted() {
        let cam = CamTable::codesys_default("Cam");
        assert_eq!(
            delete_key_point(&cam, 3).unwrap_err(),
            CamEditError::EndPoint { key_point: 4 }
        );
    }

    #[test]
    fn smooth_transition_matches_the_start_to_an_edited_end() {
        let mut cam = CamTable::codesys_default("Cam");
        cam.period.slave_period = Some(360.0);
        let end = CamKeyPoint {
            master: 360.0,
            slave: 360.0,
            velocity: 0.5,
            ..CamKeyPoint::default()
        };
        let changed = set_key_point(&cam, 3, end).unwrap();
        let start = key_points(&changed)[0];
        assert_eq!((start.slave, start.velocity), (0.0, 0.5));
    }

    #[test]
    fn actions_cycle_through_the_four_codesys_actions() {
        let mut action = TappetAction::None;
        let mut seen = Vec::new();
        for _ in 0..4 {
            action = next_action(action);
            seen.push(action);
        }
        assert_eq!(
            seen,
            [
                TappetAction::On,
                TappetAction::Off,
                TappetAction::Invert,
                TappetAction::None
            ]
        );
    }
}
