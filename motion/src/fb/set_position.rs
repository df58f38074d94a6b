//! MC_SetPosition.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_SetPosition: give the set position a new value without motion, in Standstill or
/// Disabled. It finishes in the call of the rising edge.
#[derive(Clone, Debug, Default)]
pub struct SetPosition {
    /// `Execute`: a rising edge sets the position.
    pub execute: bool,
    /// `Position`: the new position, or the shift when `relative`, in user units.
    pub position: f64,
    /// `Relative`: shift the position by `position` instead of setting it.
    pub relative: bool,
    /// `Done`: the position is set.
    pub done: bool,
    /// `Busy`: never TRUE after the call; the command finishes at once.
    pub busy: bool,
    /// `Error`: the command was refused.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    core: ExecuteCore,
}

impl SetPosition {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let (position, relative) = (self.position, self.relative);
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            kernel.set_position(axis, position, relative).map(|()| None)
        });
        self.done = outputs.done();
        self.busy = outputs.busy;
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
