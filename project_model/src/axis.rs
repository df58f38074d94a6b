//! Motion axes of the device tree.

use serde::{Deserialize, Serialize};

/// A motion axis, referenced from programs as an `AXIS_REF`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct Axis {
    /// The axis name, which is also the name of its `AXIS_REF` global.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// What drives the axis.
    #[serde(default)]
    pub kind: AxisKind,
    /// The name of the task whose cycle updates the axis.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub task: String,
    /// The user unit, such as `mm` or `deg`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub unit: String,
    /// Modulo period in user units for a rotary axis; `None` for a linear (finite) axis.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::option::of(crate::arb::finite())")
    )]
    pub modulo_period: Option<f64>,
    /// Software position limits.
    #[serde(default)]
    pub software_limits: SoftwareLimits,
    /// Dynamic limits.
    pub limits: AxisLimits,
    /// Conversion between drive increments and user units.
    pub scaling: AxisScaling,
}

/// What drives an axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum AxisKind {
    /// A virtual axis computed by the runtime's motion kernel.
    #[default]
    Virtual,
}

/// Software position limits of a linear axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct SoftwareLimits {
    /// Whether the limits are checked.
    pub enabled: bool,
    /// The negative limit in user units.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub min: f64,
    /// The positive limit in user units.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub max: f64,
}

/// Dynamic limits of an axis, in user units per second, per second², per second³.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct AxisLimits {
    /// Maximum velocity.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub velocity: f64,
    /// Maximum acceleration.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub acceleration: f64,
    /// Maximum deceleration.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub deceleration: f64,
    /// Maximum jerk.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub jerk: f64,
}

/// `increments_per_unit = numerator / denominator`, as drive scaling is written in CODESYS.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct AxisScaling {
    /// Drive increments per `denominator` user units.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub numerator: f64,
    /// User units per `numerator` increments.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::finite()"))]
    pub denominator: f64,
}

impl Default for AxisScaling {
    fn default() -> Self {
        Self {
            numerator: 1.0,
            denominator: 1.0,
        }
    }
}
