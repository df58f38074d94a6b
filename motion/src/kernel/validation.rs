//! The checks of command inputs against each other and the axis configuration, done before a
//! command may change anything.

use crate::axis::AxisConfig;
use crate::kernel::{MotionError, MotionRequest, PositionTarget};

/// Checks the task interval handed to `advance`.
pub(crate) fn check_cycle(dt_s: f64) -> Result<(), MotionError> {
    if dt_s.is_finite() && dt_s > 0.0 {
        Ok(())
    } else {
        Err(MotionError::InvalidParameter {
            input: "dt_s",
            value: dt_s,
            reason: "the task interval is a positive number of seconds",
        })
    }
}

/// Checks a magnitude input against zero and the axis's limit.
pub(crate) fn check_magnitude(
    input: &'static str,
    value: f64,
    axis_max: f64,
    zero_allowed: bool,
) -> Result<(), MotionError> {
    let low_ok = if zero_allowed {
        value >= 0.0
    } else {
        value > 0.0
    };
    if !(value.is_finite() && low_ok) {
        return Err(MotionError::InvalidParameter {
            input,
            value,
            reason: if zero_allowed {
                "it must be a number of 0 or more"
            } else {
                "it must be a number above 0"
            },
        });
    }
    if value > axis_max {
        return Err(MotionError::InvalidParameter {
            input,
            value,
            reason: "it exceeds the axis's configured maximum",
        });
    }
    Ok(())
}

/// Checks a `Jerk` input: 0 or more, and within the axis's jerk limit when it has one.
pub(crate) fn check_jerk(jerk: f64, axis_max: f64) -> Result<(), MotionError> {
    let max = if axis_max > 0.0 {
        axis_max
    } else {
        f64::INFINITY
    };
    check_magnitude("Jerk", jerk, max, true)
}

/// Checks a position input: finite, and within the software limits of a linear axis.
pub(crate) fn check_position(
    config: AxisConfig,
    input: &'static str,
    position: f64,
) -> Result<(), MotionError> {
    if !position.is_finite() {
        return Err(MotionError::InvalidParameter {
            input,
            value: position,
            reason: "it must be a finite number",
        });
    }
    if let Some(limits) = config.active_software_limits()
        && !(limits.min..=limits.max).contains(&position)
    {
        return Err(MotionError::OutsideSoftwareLimits {
            target: position,
            min: limits.min,
            max: limits.max,
        });
    }
    Ok(())
}

/// Checks the inputs of a motion request against the axis's configured maxima.
pub(crate) fn validate_request(
    config: AxisConfig,
    request: MotionRequest,
) -> Result<(), MotionError> {
    match request {
        MotionRequest::Position { target, dynamics } => {
            let (input, value) = match target {
                PositionTarget::Absolute { position, .. } => ("Position", position),
                PositionTarget::Relative { distance } | PositionTarget::Additive { distance } => {
                    ("Distance", distance)
                }
            };
            if !value.is_finite() {
                return Err(MotionError::InvalidParameter {
                    input,
                    value,
                    reason: "it must be a finite number",
                });
            }
            check_magnitude("Velocity", dynamics.velocity, config.max_velocity, false)?;
            check_magnitude(
                "Acceleration",
                dynamics.acceleration,
                config.max_acceleration,
                false,
            )?;
            check_magnitude(
                "Deceleration",
                dynamics.deceleration,
                config.max_deceleration,
                false,
            )?;
        }
        MotionRequest::Velocity { dynamics, .. } => {
            check_magnitude(
                "Velocity",
                dynamics.velocity.abs(),
                config.max_velocity,
                true,
            )?;
            check_magnitude(
                "Acceleration",
                dynamics.acceleration,
                config.max_acceleration,
                false,
            )?;
            check_magnitude(
                "Deceleration",
                dynamics.deceleration,
                config.max_deceleration,
                false,
            )?;
        }
        MotionRequest::Halt { dynamics } => {
            check_magnitude(
                "Deceleration",
                dynamics.deceleration,
                config.max_deceleration,
                false,
            )?;
        }
        // The kernel checks couplings against the master and the cams (`check_coupling`).
        MotionRequest::Cam { .. }
        | MotionRequest::Gear { .. }
        | MotionRequest::GearInPos { .. } => {
            return Ok(());
        }
    }
    let dynamics = match request {
        MotionRequest::Position { dynamics, .. }
        | MotionRequest::Velocity { dynamics, .. }
        | MotionRequest::Halt { dynamics } => dynamics,
        MotionRequest::Cam { .. }
        | MotionRequest::Gear { .. }
        | MotionRequest::GearInPos { .. } => {
            return Ok(());
        }
    };
    check_jerk(dynamics.jerk, config.max_jerk)
}
