//! Cam tables: the slave position as a function of the master position, plus tappets.

use serde::{Deserialize, Serialize};

/// A cam table object of the application.
///
/// At build time it becomes a global `MC_CAM_REF` of the same name that `MC_CamTableSelect`
/// takes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamTable {
    /// The cam's name and the name of its `MC_CAM_REF`; it is the file name, not stored in the file.
    #[serde(skip)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// What the cam is for.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
    /// The master range and unit (CODESYS default 0 to 360 degrees).
    pub master: CamRange,
    /// The slave range and unit, used for display scaling.
    pub slave: CamRange,
    /// How the end joins the start when the cam runs periodically.
    #[serde(default)]
    pub period: CamPeriod,
    /// Which joints the continuity check inspects.
    #[serde(default)]
    pub continuity: CamContinuity,
    /// The form the cam takes in the program image.
    #[serde(default)]
    pub compile_format: CamCompileFormat,
    /// The cam curve itself.
    pub profile: CamProfile,
    /// Tappet tracks, each switching one BOOL output.
    #[serde(default, rename = "track", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub tracks: Vec<TappetTrack>,
}

/// A range of positions with its unit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamRange {
    /// The first position.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub start: f64,
    /// The last position.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub end: f64,
    /// The unit, such as `deg` or `mm`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub unit: String,
}

/// Periodic behaviour of a cam, as in the CODESYS cam properties dialog.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamPeriod {
    /// Editing the end point adjusts the start point (and back) so position, velocity and
    /// acceleration match across the period.
    pub smooth_transition: bool,
    /// Start and end slave positions may differ by a multiple of this, if set.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::finite())")
    )]
    pub slave_period: Option<f64>,
}

impl Default for CamPeriod {
    fn default() -> Self {
        Self {
            smooth_transition: true,
            slave_period: None,
        }
    }
}

/// Which quantities must be continuous at segment joints; violations are reported, not blocked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamContinuity {
    /// Slave position (always on in CODESYS; a jump cannot be edited).
    pub position: bool,
    /// Slave velocity with respect to the master.
    pub velocity: bool,
    /// Slave acceleration with respect to the master.
    pub acceleration: bool,
    /// Slave jerk with respect to the master.
    pub jerk: bool,
}

impl Default for CamContinuity {
    fn default() -> Self {
        Self {
            position: true,
            velocity: true,
            acceleration: true,
            jerk: false,
        }
    }
}

/// The representation a cam is compiled to.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum CamCompileFormat {
    /// All segments with their laws (CODESYS "Segments").
    #[default]
    Segments,
    /// Points with position, velocity and acceleration joined by quintics (CODESYS XYVA).
    Xyva,
    /// `elements` equidistant slave positions (CODESYS 1-D table, Delta key points).
    Table1d {
        /// Number of table elements, both ends included.
        elements: u32,
    },
    /// `elements` master/slave pairs (CODESYS 2-D table, Omron `{Phase, Distance}` data).
    Table2d {
        /// Number of table elements, both ends included.
        elements: u32,
    },
}

/// The curve of a cam: segments between key points, or a table of points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum CamProfile {
    /// Segments with a motion law each, chained from `start`: each segment ends where the next
    /// begins, so the chain cannot have gaps.
    Segments {
        /// The first key point, at the master start.
        start: CamKeyPoint,
        /// The segments in master order; each names its end point.
        #[serde(default, rename = "segment", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
        segments: Vec<CamSegment>,
    },
    /// A point table interpolated between its points.
    Points {
        /// How values between points are computed.
        interpolation: PointInterpolation,
        /// The points in master order.
        #[serde(default, rename = "point", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
        points: Vec<CamTablePoint>,
    },
}

/// A key point of a segmented cam: position and its derivatives with respect to the master.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamKeyPoint {
    /// Master position.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub master: f64,
    /// Slave position.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub slave: f64,
    /// Slave velocity, dY/dX.
    #[serde(default)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub velocity: f64,
    /// Slave acceleration, d²Y/dX².
    #[serde(default)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub acceleration: f64,
    /// Slave jerk, d³Y/dX³ (used by Poly7 segments).
    #[serde(default)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub jerk: f64,
}

/// One segment of a cam, from the previous key point to `end`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamSegment {
    /// The motion law between the two key points.
    pub law: MotionLaw,
    /// The inflection parameter λ (0 to 1) of a modified sine, if not the classic law.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::finite())")
    )]
    pub lambda: Option<f64>,
    /// The key point the segment ends at.
    pub end: CamKeyPoint,
}

/// Motion laws of cam segments, with VDI 2143 names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum MotionLaw {
    /// Straight line: constant velocity.
    Line,
    /// Cubic polynomial matching position and velocity at both ends.
    Poly3,
    /// Quintic polynomial matching position, velocity and acceleration (3-4-5 rest to rest).
    Poly5,
    /// Seventh-degree polynomial also matching jerk (4-5-6-7 rest to rest).
    Poly7,
    /// Modified sine.
    ModifiedSine,
    /// Modified trapezoid (acceleration).
    ModifiedTrapezoid,
    /// Cycloid.
    Cycloid,
    /// Simple harmonic (cosine).
    SimpleHarmonic,
    /// Inclined sine (Bestehorn).
    InclinedSine,
}

/// One point of a point table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct CamTablePoint {
    /// Master position (Omron: phase).
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub master: f64,
    /// Slave position (Omron: distance).
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub slave: f64,
}

/// Interpolation between the points of a point table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum PointInterpolation {
    /// Straight lines between points (CODESYS quality 1, Omron linear).
    #[default]
    Linear,
    /// Cubic splines through the points (CODESYS quality 3).
    Cubic,
}

/// A tappet track: one BOOL switched by the tappets on it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct TappetTrack {
    /// The track ID (CODESYS `iGroupID`), which indexes the tappet outputs.
    pub id: u16,
    /// A name shown in the tappet editor.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub name: String,
    /// Dead-time compensation in microseconds (CODESYS `DeadTimeCompensation`): a positive
    /// value switches earlier by the distance the master travels in that time, to make up for
    /// the actuator's delay; a negative value switches later.
    #[serde(default, skip_serializing_if = "is_zero_i32")]
    pub dead_time_us: i32,
    /// Master distance the direction must reverse by before a negative pass counts.
    #[serde(default, skip_serializing_if = "is_zero_f64")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub hysteresis: f64,
    /// The tappets on this track.
    #[serde(default, rename = "tappet", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub tappets: Vec<Tappet>,
}

/// A tappet: a master position where the track's output changes.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Tappet {
    /// The master position.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub position: f64,
    /// What happens when the master passes it increasing.
    pub on_positive: TappetAction,
    /// What happens when the master passes it decreasing.
    pub on_negative: TappetAction,
}

/// What a tappet does to its track's output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum TappetAction {
    /// Nothing.
    None,
    /// Switch the output on.
    On,
    /// Switch the output off.
    Off,
    /// Invert the output.
    Invert,
    /// Switch the output on for a time (a Rivet extension after PLCopen's time-based cam switch).
    TimedOn {
        /// How long the output stays on, in microseconds.
        duration_us: u32,
    },
}

fn is_zero_i32(value: &i32) -> bool {
    *value == 0
}

fn is_zero_f64(value: &f64) -> bool {
    *value == 0.0
}

impl CamTable {
    /// The cam CODESYS creates for "Add cam": master and slave 0 to 360 with three Poly5
    /// segments through (0,0), (120,120), (240,240) and (360,360), velocity 1 at the inner points.
    pub fn codesys_default(name: impl Into<String>) -> Self {
        let point = |x: f64, v: f64| CamKeyPoint {
            master: x,
            slave: x,
            velocity: v,
            ..CamKeyPoint::default()
        };
        let segment = |end| CamSegment {
            law: MotionLaw::Poly5,
            lambda: None,
            end,
        };
        Self {
            name: name.into(),
            comment: String::new(),
            master: CamRange {
                start: 0.0,
                end: 360.0,
                unit: "deg".into(),
            },
            slave: CamRange {
                start: 0.0,
                end: 360.0,
                unit: "deg".into(),
            },
            period: CamPeriod::default(),
            continuity: CamContinuity::default(),
            compile_format: CamCompileFormat::default(),
            profile: CamProfile::Segments {
                start: point(0.0, 0.0),
                segments: vec![
                    segment(point(120.0, 1.0)),
                    segment(point(240.0, 1.0)),
                    segment(point(360.0, 0.0)),
                ],
            },
            tracks: Vec::new(),
        }
    }
}
