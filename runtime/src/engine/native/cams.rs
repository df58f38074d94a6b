//! The image's cam tables as `motion` curves and tappet tracks.

use motion::cam::{KeyPoint, MotionLaw, PointCam, PointInterpolation, Segment, SegmentedCam};
use motion::curve::{CamCurve, CamPoint};
use motion::tappet::{Tappet, TappetAction, TappetTrack};
use program_image::motion::{
    CamDef, CamProfileDef, InterpolationDef, KeyPointDef, LawDef, TappetActionDef,
};

/// The curve of `cam`, or why it cannot be evaluated (a segment or row named by the message).
pub(super) fn curve_of(cam: &CamDef) -> Result<Box<dyn CamCurve + Send + Sync>, String> {
    let curve: Box<dyn CamCurve + Send + Sync> = match &cam.profile {
        CamProfileDef::Segments { start, segments } => {
            let segments = segments
                .iter()
                .map(|segment| Segment {
                    law: law(segment.law),
                    lambda: None,
                    end: key_point(&segment.end),
                })
                .collect();
            Box::new(SegmentedCam::new(key_point(start), segments).map_err(|e| e.to_string())?)
        }
        CamProfileDef::Points {
            interpolation,
            points,
        } => {
            let points = points
                .iter()
                .map(|point| CamPoint {
                    master: point.master,
                    slave: point.slave,
                    ..CamPoint::default()
                })
                .collect();
            let interpolation = match interpolation {
                InterpolationDef::Linear => PointInterpolation::Linear,
                InterpolationDef::Cubic => PointInterpolation::Cubic,
            };
            Box::new(PointCam::new(points, interpolation).map_err(|e| e.to_string())?)
        }
    };
    Ok(curve)
}

/// The tappet tracks of `cam`.
pub(super) fn tracks_of(cam: &CamDef) -> Vec<TappetTrack> {
    cam.tracks
        .iter()
        .map(|track| {
            let tappets = track
                .tappets
                .iter()
                .map(|tappet| Tappet {
                    position: tappet.position,
                    on_positive: action(tappet.on_positive),
                    on_negative: action(tappet.on_negative),
                })
                .collect();
            TappetTrack {
                hysteresis: track.hysteresis,
                dead_time_s: f64::from(track.dead_time_us) / 1e6,
                ..TappetTrack::new(track.id, tappets)
            }
        })
        .collect()
}

fn key_point(point: &KeyPointDef) -> KeyPoint {
    KeyPoint {
        master: point.master,
        slave: point.slave,
        velocity: point.velocity,
        acceleration: point.acceleration,
        jerk: point.jerk,
    }
}

fn law(law: LawDef) -> MotionLaw {
    match law {
        LawDef::Line => MotionLaw::Line,
        LawDef::Poly3 => MotionLaw::Poly3,
        LawDef::Poly5 => MotionLaw::Poly5,
        LawDef::Poly7 => MotionLaw::Poly7,
        LawDef::ModifiedSine => MotionLaw::ModifiedSine,
        LawDef::ModifiedTrapezoid => MotionLaw::ModifiedTrapezoid,
        LawDef::Cycloid => MotionLaw::Cycloid,
        LawDef::SimpleHarmonic => MotionLaw::SimpleHarmonic,
        LawDef::InclinedSine => MotionLaw::InclinedSine,
    }
}

fn action(action: TappetActionDef) -> TappetAction {
    match action {
        TappetActionDef::None => TappetAction::None,
        TappetActionDef::On => TappetAction::On,
        TappetActionDef::Off => TappetAction::Off,
        TappetActionDef::Invert => TappetAction::Invert,
        TappetActionDef::TimedOn { duration_us } => TappetAction::TimedOn {
            duration_s: f64::from(duration_us) / 1e6,
        },
    }
}
