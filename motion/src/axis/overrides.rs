//! The override factors of an axis (MC_SetOverride).

/// Factors the commanded dynamics of an axis are multiplied with. They stay in force until
/// changed and apply to discrete and continuous motion, not to MC_Stop or the error stop ramp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overrides {
    /// `VelFactor`, 0.0 ..= 1.0; 0.0 holds the axis at rest without finishing its command.
    pub velocity: f64,
    /// `AccFactor`, above 0.0 up to 1.0; applies to acceleration and deceleration.
    pub acceleration: f64,
    /// `JerkFactor`, above 0.0 up to 1.0.
    pub jerk: f64,
}

impl Default for Overrides {
    fn default() -> Self {
        Self {
            velocity: 1.0,
            acceleration: 1.0,
            jerk: 1.0,
        }
    }
}
