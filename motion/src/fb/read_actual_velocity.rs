//! MC_ReadActualVelocity.

use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_ReadActualVelocity: while `Enable` is TRUE, the actual velocity at every call. With
/// `Enable` FALSE the outputs are reset except `Velocity`, which keeps its last value.
#[derive(Clone, Debug, Default)]
pub struct ReadActualVelocity {
    /// `Enable`: read while TRUE.
    pub enable: bool,
    /// `Valid`: `Velocity` is valid.
    pub valid: bool,
    /// `Busy`: the instance is enabled.
    pub busy: bool,
    /// `Error`: the axis reference is invalid.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// `Velocity`: the signed actual velocity in user units per second.
    pub velocity: f64,
}

impl ReadActualVelocity {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &Kernel, axis: AxisId) {
        let read = self.enable.then(|| kernel.snapshot(axis));
        self.busy = self.enable;
        match read {
            Some(Ok(snapshot)) => {
                self.velocity = snapshot.actual_velocity;
                self.set_error(None);
            }
            Some(Err(error)) => self.set_error(Some(error)),
            None => {
                self.busy = false;
                self.valid = false;
                self.error = false;
                self.error_id = 0;
            }
        }
    }

    fn set_error(&mut self, error: Option<MotionError>) {
        self.valid = error.is_none();
        self.error = error.is_some();
        self.error_id = error.map_or(0, |error| error.id());
    }
}
