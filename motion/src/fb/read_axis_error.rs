//! MC_ReadAxisError.

use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_ReadAxisError: while `Enable` is TRUE, the pending axis error at every call.
#[derive(Clone, Debug, Default)]
pub struct ReadAxisError {
    /// `Enable`: read while TRUE.
    pub enable: bool,
    /// `Valid`: `AxisErrorID` is valid.
    pub valid: bool,
    /// `Busy`: the instance is enabled.
    pub busy: bool,
    /// `Error`: the axis reference is invalid.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the FB's own error, 0 without error.
    pub error_id: u16,
    /// `AxisErrorID`: the pending axis error, 0 when there is none.
    pub axis_error_id: u16,
}

impl ReadAxisError {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &Kernel, axis: AxisId) {
        let read: Option<Result<u16, MotionError>> = self
            .enable
            .then(|| kernel.snapshot(axis).map(|snapshot| snapshot.axis_error_id));
        self.busy = self.enable;
        self.valid = matches!(read, Some(Ok(_)));
        let error = match read {
            Some(Err(error)) => Some(error),
            _ => None,
        };
        self.error = error.is_some();
        self.error_id = error.map_or(0, |error| error.id());
        self.axis_error_id = match read {
            Some(Ok(id)) => id,
            _ => 0,
        };
    }
}
