//! MC_Home.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_Home on a virtual axis: from Standstill the axis passes through Homing and gets the
/// reference `Position` on the next cycle, which sets `Done`.
#[derive(Clone, Debug, Default)]
pub struct Home {
    /// `Execute`: a rising edge starts homing.
    pub execute: bool,
    /// `Position`: the position the axis has once homed, in user units.
    pub position: f64,
    /// `Done`: the command finished as commanded.
    pub done: bool,
    /// `Busy`: the command has not ended yet; keep calling the instance.
    pub busy: bool,
    /// `Active`: the command controls the axis.
    pub active: bool,
    /// `CommandAborted`: another command interrupted this one.
    pub command_aborted: bool,
    /// `Error`: the command was refused or ended in an error.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    core: ExecuteCore,
}

impl Home {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let position = self.position;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            kernel.home(axis, position).map(Some)
        });
        self.done = outputs.done();
        self.busy = outputs.busy;
        self.active = outputs.active;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
