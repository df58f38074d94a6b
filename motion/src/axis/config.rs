//! The configuration of a virtual axis, mirroring the project's axis model without depending on
//! it: the runtime copies the project's values into an [`AxisConfig`] when it loads the image.

use thiserror::Error;

/// Software position limits of a linear axis, in user units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SoftwareLimits {
    /// The negative limit; a target below it is refused.
    pub min: f64,
    /// The positive limit; a target above it is refused.
    pub max: f64,
}

/// The configuration of one virtual axis. It lives as long as the kernel's axis and is not
/// changed while the axis runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisConfig {
    /// The modulo period in user units of a rotary axis (positions wrap into `[0, period)`);
    /// `None` for a linear axis.
    pub modulo_period: Option<f64>,
    /// The software limits of a linear axis; `None` when they are not checked. Ignored on a
    /// modulo axis.
    pub software_limits: Option<SoftwareLimits>,
    /// The highest velocity a command may ask for, in user units per second.
    pub max_velocity: f64,
    /// The highest acceleration a command may ask for, in user units per second².
    pub max_acceleration: f64,
    /// The highest deceleration a command may ask for, in user units per second²; the error
    /// stop ramp also uses it.
    pub max_deceleration: f64,
    /// The highest jerk in user units per second³; 0 means the axis has no jerk limit, so a
    /// command with jerk 0 runs a trapezoidal profile.
    pub max_jerk: f64,
}

/// A configuration value that a kernel cannot run an axis with.
#[derive(Clone, Copy, Debug, PartialEq, Error)]
pub enum ConfigError {
    /// The modulo period is zero, negative or not a number.
    #[error("the modulo period {0} must be a positive number of user units")]
    ModuloPeriod(f64),
    /// The software limits are not a range.
    #[error("the software limit minimum {min} must be below the maximum {max}")]
    SoftwareLimits {
        /// The configured minimum.
        min: f64,
        /// The configured maximum.
        max: f64,
    },
    /// A dynamic limit is zero, negative or not a number.
    #[error("the axis limit {field} = {value} must be a positive number")]
    DynamicLimit {
        /// The name of the limit, such as `max_velocity`.
        field: &'static str,
        /// The configured value.
        value: f64,
    },
}

impl AxisConfig {
    /// A linear axis without software limits and with the given dynamic limits.
    #[must_use]
    pub fn linear(max_velocity: f64, max_acceleration: f64, max_deceleration: f64) -> Self {
        Self {
            modulo_period: None,
            software_limits: None,
            max_velocity,
            max_acceleration,
            max_deceleration,
            max_jerk: 0.0,
        }
    }

    /// Checks that the kernel can run an axis with this configuration.
    pub fn validate(&self) -> Result<(), ConfigError> {
        if let Some(period) = self.modulo_period
            && !(period.is_finite() && period > 0.0)
        {
            return Err(ConfigError::ModuloPeriod(period));
        }
        if let Some(limits) = self.software_limits
            && !(limits.min.is_finite() && limits.max.is_finite() && limits.min < limits.max)
        {
            return Err(ConfigError::SoftwareLimits {
                min: limits.min,
                max: limits.max,
            });
        }
        for (field, value) in [
            ("max_velocity", self.max_velocity),
            ("max_acceleration", self.max_acceleration),
            ("max_deceleration", self.max_deceleration),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ConfigError::DynamicLimit { field, value });
            }
        }
        if !(self.max_jerk.is_finite() && self.max_jerk >= 0.0) {
            return Err(ConfigError::DynamicLimit {
                field: "max_jerk",
                value: self.max_jerk,
            });
        }
        Ok(())
    }

    /// `position` wrapped into `[0, period)` on a modulo axis, unchanged on a linear axis.
    #[must_use]
    pub fn wrap(&self, position: f64) -> f64 {
        match self.modulo_period {
            Some(period) => {
                let wrapped = position.rem_euclid(period);
                // `rem_euclid` can round up to the period itself for tiny negative inputs.
                if wrapped >= period { 0.0 } else { wrapped }
            }
            None => position,
        }
    }

    /// The software limits that apply: those of a linear axis, none on a modulo axis.
    #[must_use]
    pub fn active_software_limits(&self) -> Option<SoftwareLimits> {
        match self.modulo_period {
            Some(_) => None,
            None => self.software_limits,
        }
    }
}
