//! MC_Reset.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_Reset: acknowledge the axis error. From ErrorStop the axis goes to Standstill when
/// powered, Disabled otherwise, once the error stop ramp has reached rest; in other states it
/// finishes at once and changes nothing. It does not touch the outputs of other instances.
#[derive(Clone, Debug, Default)]
pub struct Reset {
    /// `Execute`: a rising edge starts the reset.
    pub execute: bool,
    /// `Done`: the axis is in Standstill or Disabled.
    pub done: bool,
    /// `Busy`: the error stop ramp is still braking.
    pub busy: bool,
    /// `Error`: the command was refused.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    core: ExecuteCore,
}

impl Reset {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let outputs = self
            .core
            .call(self.execute, kernel, |kernel| kernel.reset(axis).map(Some));
        self.done = outputs.done();
        // A second reset replacing this one counts as a success of the acknowledgement.
        self.done |= outputs.command_aborted();
        self.busy = outputs.busy;
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
