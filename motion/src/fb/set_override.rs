//! MC_SetOverride.

use crate::axis::Overrides;
use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_SetOverride: while `Enable` is TRUE the factors are applied at every call (a change acts
/// on the running motion at once); when `Enable` goes FALSE the last factors stay in force.
/// Refused factors (`VelFactor` outside 0.0 ..= 1.0, `AccFactor` or `JerkFactor` outside
/// 0.0 (excluded) ..= 1.0) set `Error` and leave the factors in force unchanged.
#[derive(Clone, Debug)]
pub struct SetOverride {
    /// `Enable`: apply the factors while TRUE.
    pub enable: bool,
    /// `VelFactor`, 1.0 by default.
    pub vel_factor: f64,
    /// `AccFactor`, for acceleration and deceleration, 1.0 by default.
    pub acc_factor: f64,
    /// `JerkFactor`, 1.0 by default.
    pub jerk_factor: f64,
    /// `Enabled`: the factors of this call are in force.
    pub enabled: bool,
    /// `Busy`: the instance is enabled.
    pub busy: bool,
    /// `Error`: the factors were refused or the axis reference is invalid.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
}

impl Default for SetOverride {
    fn default() -> Self {
        Self {
            enable: false,
            vel_factor: 1.0,
            acc_factor: 1.0,
            jerk_factor: 1.0,
            enabled: false,
            busy: false,
            error: false,
            error_id: 0,
            error_cause: None,
        }
    }
}

impl SetOverride {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let result = self.enable.then(|| {
            kernel.set_override(
                axis,
                Overrides {
                    velocity: self.vel_factor,
                    acceleration: self.acc_factor,
                    jerk: self.jerk_factor,
                },
            )
        });
        self.busy = self.enable;
        self.enabled = matches!(result, Some(Ok(())));
        self.error_cause = match result {
            Some(Err(error)) => Some(error),
            _ => None,
        };
        self.error = self.error_cause.is_some();
        self.error_id = self.error_cause.map_or(0, |error| error.id());
    }
}
