//! The motion section (`docs/motion.md` §3): the project's axes and cam tables, as the runtime's
//! motion kernel needs them. Plain data mirroring the project model, which this crate may not
//! depend on.

use serde::{Deserialize, Serialize};

/// The axes and cam tables of a project.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MotionSection {
    /// The axes, in device-tree order; `AXIS_REF.nAxisId` indexes this list.
    pub axes: Vec<AxisDef>,
    /// The cam tables; `MC_CAM_REF.nCamId` indexes this list.
    pub cams: Vec<CamDef>,
}

/// One axis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AxisDef {
    /// The axis's name, also the path of its `AXIS_REF`.
    pub name: String,
    /// The index of the task whose cycle advances the axis.
    pub task: u32,
    /// The data-region offset of its `AXIS_REF`.
    pub offset: u32,
    /// The modulo period of a rotary axis; `None` for a linear axis.
    pub modulo_period: Option<f64>,
    /// The software limits (minimum, maximum) when they are enabled.
    pub software_limits: Option<(f64, f64)>,
    /// Maximum velocity in units per second.
    pub max_velocity: f64,
    /// Maximum acceleration in units per second².
    pub max_acceleration: f64,
    /// Maximum deceleration in units per second².
    pub max_deceleration: f64,
    /// Maximum jerk in units per second³ (0: no jerk limit).
    pub max_jerk: f64,
}

/// One cam table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CamDef {
    /// The cam's name, also the path of its `MC_CAM_REF`.
    pub name: String,
    /// The data-region offset of its `MC_CAM_REF`.
    pub offset: u32,
    /// The curve.
    pub profile: CamProfileDef,
    /// The tappet tracks.
    pub tracks: Vec<TrackDef>,
}

/// A cam curve: segments between key points, or a table of points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum CamProfileDef {
    /// Segments chained from `start`, each ending at its own key point.
    Segments {
        /// The first key point.
        start: KeyPointDef,
        /// The segments in master order.
        segments: Vec<SegmentDef>,
    },
    /// Points joined by `interpolation`.
    Points {
        /// How values between points are computed.
        interpolation: InterpolationDef,
        /// The points in master order.
        points: Vec<PointDef>,
    },
}

/// A key point: master position, slave position and the slave's derivatives with respect to
/// the master.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct KeyPointDef {
    /// Master position.
    pub master: f64,
    /// Slave position.
    pub slave: f64,
    /// dY/dX.
    pub velocity: f64,
    /// d²Y/dX².
    pub acceleration: f64,
    /// d³Y/dX³.
    pub jerk: f64,
}

/// A segment ending at `end`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SegmentDef {
    /// The motion law.
    pub law: LawDef,
    /// The key point it ends at.
    pub end: KeyPointDef,
}

/// Motion laws, in the order of `project_model::MotionLaw`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum LawDef {
    /// Straight line.
    Line,
    /// Cubic polynomial.
    Poly3,
    /// Quintic polynomial.
    Poly5,
    /// Seventh-degree polynomial.
    Poly7,
    /// Modified sine.
    ModifiedSine,
    /// Modified trapezoid.
    ModifiedTrapezoid,
    /// Cycloid.
    Cycloid,
    /// Simple harmonic.
    SimpleHarmonic,
    /// Inclined sine.
    InclinedSine,
}

/// Interpolation between the points of a table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum InterpolationDef {
    /// Straight lines.
    Linear,
    /// A cubic spline through the points.
    Cubic,
}

/// A point of a table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PointDef {
    /// Master position.
    pub master: f64,
    /// Slave position.
    pub slave: f64,
}

/// A tappet track: one BOOL switched by its tappets.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TrackDef {
    /// The track ID (`SMC_GetTappetValue.iID`).
    pub id: u16,
    /// Dead-time compensation in microseconds; positive switches earlier.
    pub dead_time_us: i32,
    /// Hysteresis in master units.
    pub hysteresis: f64,
    /// The tappets.
    pub tappets: Vec<TappetDef>,
}

/// A tappet.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TappetDef {
    /// The master position.
    pub position: f64,
    /// The action when the master passes it increasing.
    pub on_positive: TappetActionDef,
    /// The action when the master passes it decreasing.
    pub on_negative: TappetActionDef,
}

/// What a tappet does to its track's output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum TappetActionDef {
    /// Nothing.
    None,
    /// On.
    On,
    /// Off.
    Off,
    /// Invert.
    Invert,
    /// On for a time.
    TimedOn {
        /// How long, in microseconds.
        duration_us: u32,
    },
}
