//! MC_Power.

use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_Power: switch the power stage on while `Enable` is TRUE. Level-sensitive: `Status` and
/// `Valid` are refreshed at every call; with `Enable` FALSE the power is off and `Valid`,
/// `Error` and `ErrorID` are reset.
#[derive(Clone, Debug, Default)]
pub struct Power {
    /// `Enable`: power on while TRUE.
    pub enable: bool,
    /// `Status`: the power stage is on.
    pub status: bool,
    /// `Valid`: the outputs are valid (`Enable` TRUE and no error).
    pub valid: bool,
    /// `Error`: the axis reference is invalid.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
}

impl Power {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        match kernel.power(axis, self.enable) {
            Ok(status) => {
                self.status = status;
                self.valid = self.enable;
                self.error = false;
                self.error_cause = None;
            }
            Err(error) => {
                self.status = false;
                self.valid = false;
                self.error = self.enable;
                self.error_cause = self.enable.then_some(error);
            }
        }
        self.error_id = self.error_cause.map_or(0, |error| error.id());
    }
}
