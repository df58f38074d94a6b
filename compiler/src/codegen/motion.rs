//! The project's axes and cam tables in the image (`docs/motion.md`): an `AXIS_REF` global per
//! axis, an `MC_CAM_REF` global per cam, the motion section the runtime builds its kernel from,
//! and the library function blocks that run natively.

use std::collections::HashSet;

use program_image::motion::{
    AxisDef, CamDef, CamProfileDef, InterpolationDef, KeyPointDef, LawDef, MotionSection, PointDef,
    SegmentDef, TappetActionDef, TappetDef, TrackDef,
};
use program_image::{InitRun, Operand, Region, Symbol, SymbolFlags};
use project_model::{
    CamKeyPoint, CamProfile, CamTable, MotionLaw, Object, PointInterpolation, Project, TappetAction,
};

use super::body::{Gen, Place, Typed};
use super::error::Within;
use super::layout::Layouts;
use crate::library::{AXIS_REF, CAM_REF, is_native_block};
use crate::sema::ty::Type;

/// Where the axes' and cams' globals went, and the section describing them.
pub(crate) struct DeviceGlobals {
    /// By lower-case name.
    pub(crate) places: Vec<(String, Typed)>,
    /// The motion section; `None` when the project has neither axes nor cams.
    pub(crate) section: Option<MotionSection>,
}

/// Lays out the axes and cams of `project` with `allocate` (data-region offset of a value of
/// the given size and alignment), pushing their initial values and symbols.
pub(crate) fn device_globals(
    project: &Project,
    layouts: &mut Layouts<'_, '_>,
    allocate: &mut dyn FnMut(u32, u32) -> u32,
    runs: &mut Vec<InitRun>,
    symbols: &mut Vec<Symbol>,
) -> Gen<DeviceGlobals> {
    let cams: Vec<&CamTable> = project
        .application
        .objects()
        .into_iter()
        .filter_map(|object| match object {
            Object::CamTable(cam) => Some(cam),
            _ => None,
        })
        .collect();
    if project.axes.is_empty() && cams.is_empty() {
        return Ok(DeviceGlobals {
            places: Vec::new(),
            section: None,
        });
    }
    let mut places = Vec::new();
    let mut place = |name: &str, ty: &str, init: String| -> Gen<u32> {
        let ty = Type::Named(ty.to_owned());
        let lay = layouts
            .of(&ty)
            .map_err(|e| e.within(Within::Declaration(name.to_owned())))?;
        let bytes = layouts
            .initial_bytes(&lay, Some(&init))
            .map_err(|e| e.within(Within::Declaration(name.to_owned())))?;
        let offset = allocate(lay.size, lay.align);
        runs.push(InitRun { offset, bytes });
        symbols.push(Symbol {
            path: name.to_owned(),
            ty: lay.id,
            region: Region::Data,
            offset,
            bit: None,
            flags: SymbolFlags(SymbolFlags::GLOBAL),
        });
        places.push((
            name.to_lowercase(),
            Typed {
                place: Place::Direct(Operand::Global(offset)),
                ty,
                lay,
            },
        ));
        Ok(offset)
    };
    let mut section = MotionSection::default();
    for (index, axis) in project.axes.iter().enumerate() {
        let task = if project.tasks.is_empty() {
            0
        } else {
            project
                .tasks
                .iter()
                .position(|task| task.name.eq_ignore_ascii_case(&axis.task))
                .ok_or_else(|| {
                    format!(
                        "axis '{}' is updated by task '{}', which is not in the task configuration",
                        axis.name, axis.task
                    )
                })?
        };
        let period = axis.modulo_period.unwrap_or(0.0);
        let offset = place(
            &axis.name,
            AXIS_REF,
            format!("(nAxisId := {index}, fPositionPeriod := {period:?})"),
        )?;
        let limits = &axis.software_limits;
        section.axes.push(AxisDef {
            name: axis.name.clone(),
            task: task as u32,
            offset,
            modulo_period: axis.modulo_period,
            software_limits: limits.enabled.then_some((limits.min, limits.max)),
            max_velocity: axis.limits.velocity,
            max_acceleration: axis.limits.acceleration,
            max_deceleration: axis.limits.deceleration,
            max_jerk: axis.limits.jerk,
        });
    }
    for (index, cam) in cams.iter().enumerate() {
        let (elements, profile) = profile_def(&cam.profile);
        let tappets: usize = cam.tracks.iter().map(|track| track.tappets.len()).sum();
        let offset = place(
            &cam.name,
            CAM_REF,
            format!(
                "(nCamId := {index}, xStart := {:?}, xEnd := {:?}, nElements := {elements}, nTappets := {tappets})",
                cam.master.start, cam.master.end
            ),
        )?;
        section.cams.push(CamDef {
            name: cam.name.clone(),
            offset,
            profile,
            tracks: cam
                .tracks
                .iter()
                .map(|track| TrackDef {
                    id: track.id,
                    dead_time_us: track.dead_time_us,
                    hysteresis: track.hysteresis,
                    tappets: track
                        .tappets
                        .iter()
                        .map(|tappet| TappetDef {
                            position: tappet.position,
                            on_positive: action_def(tappet.on_positive),
                            on_negative: action_def(tappet.on_negative),
                        })
                        .collect(),
                })
                .collect(),
        });
    }
    Ok(DeviceGlobals {
        places,
        section: Some(section),
    })
}

/// The library function blocks the project declares variables of (`MC_Power`, or
/// `ARRAY[1..4] OF MC_MoveAbsolute`), in lower case: only those go into the image.
pub(crate) fn used_library_blocks(project: &Project) -> HashSet<String> {
    let mut used = HashSet::new();
    for object in project.application.objects() {
        let variables: Vec<&project_model::Variable> = match object {
            Object::Pou(pou) => pou
                .variables
                .iter()
                .chain(pou.methods.iter().flat_map(|m| &m.variables))
                .collect(),
            Object::Gvl(gvl) => gvl.variables.iter().collect(),
            _ => continue,
        };
        for variable in variables {
            let words = variable
                .ty
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'));
            for word in words.filter(|word| is_native_block(word)) {
                used.insert(word.to_lowercase());
            }
        }
    }
    used
}

fn profile_def(profile: &CamProfile) -> (usize, CamProfileDef) {
    match profile {
        CamProfile::Segments { start, segments } => (
            segments.len(),
            CamProfileDef::Segments {
                start: key_point(start),
                segments: segments
                    .iter()
                    .map(|segment| SegmentDef {
                        law: law_def(segment.law),
                        end: key_point(&segment.end),
                    })
                    .collect(),
            },
        ),
        CamProfile::Points {
            interpolation,
            points,
        } => (
            points.len(),
            CamProfileDef::Points {
                interpolation: match interpolation {
                    PointInterpolation::Linear => InterpolationDef::Linear,
                    PointInterpolation::Cubic => InterpolationDef::Cubic,
                },
                points: points
                    .iter()
                    .map(|point| PointDef {
                        master: point.master,
                        slave: point.slave,
                    })
                    .collect(),
            },
        ),
    }
}

fn key_point(point: &CamKeyPoint) -> KeyPointDef {
    KeyPointDef {
        master: point.master,
        slave: point.slave,
        velocity: point.velocity,
        acceleration: point.acceleration,
        jerk: point.jerk,
    }
}

fn law_def(law: MotionLaw) -> LawDef {
    match law {
        MotionLaw::Line => LawDef::Line,
        MotionLaw::Poly3 => LawDef::Poly3,
        MotionLaw::Poly5 => LawDef::Poly5,
        MotionLaw::Poly7 => LawDef::Poly7,
        MotionLaw::ModifiedSine => LawDef::ModifiedSine,
        MotionLaw::ModifiedTrapezoid => LawDef::ModifiedTrapezoid,
        MotionLaw::Cycloid => LawDef::Cycloid,
        MotionLaw::SimpleHarmonic => LawDef::SimpleHarmonic,
        MotionLaw::InclinedSine => LawDef::InclinedSine,
    }
}

fn action_def(action: TappetAction) -> TappetActionDef {
    match action {
        TappetAction::None => TappetActionDef::None,
        TappetAction::On => TappetActionDef::On,
        TappetAction::Off => TappetActionDef::Off,
        TappetAction::Invert => TappetActionDef::Invert,
        TappetAction::TimedOn { duration_us } => TappetActionDef::TimedOn { duration_us },
    }
}
