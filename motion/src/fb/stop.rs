//! MC_Stop.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Kernel, MotionError};

/// MC_Stop: abort every command on the axis and brake to rest; the axis stays in Stopping,
/// locked against other motion commands, until it is at rest and `Execute` is FALSE (Note 6).
///
/// As PLCopen's exception to the exclusivity rule, `Done` turns TRUE at rest while `Busy`
/// stays TRUE as long as `Execute` holds the lock. At the call where `Execute` is FALSE and the
/// axis is at rest the lock is released: `Busy` goes FALSE and `Done` shows for that one call.
#[derive(Clone, Debug, Default)]
pub struct Stop {
    /// `Execute`: a rising edge starts the stop; TRUE keeps the axis locked.
    pub execute: bool,
    /// `Deceleration` in user units per second².
    pub deceleration: f64,
    /// `Jerk` in user units per second³; 0 uses the axis's jerk limit (none: trapezoid).
    pub jerk: f64,
    /// `Done`: the axis is at rest.
    pub done: bool,
    /// `Busy`: the stop has not ended yet or still holds the lock.
    pub busy: bool,
    /// `CommandAborted`: another MC_Stop or the power going off interrupted this one.
    pub command_aborted: bool,
    /// `Error`: the command was refused or ended in an error.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    core: ExecuteCore,
}

impl Stop {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        if !self.execute
            && let Some(id) = self.core.command()
        {
            kernel.release_stop(id);
        }
        let (deceleration, jerk) = (self.deceleration, self.jerk);
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            kernel.stop(axis, deceleration, jerk).map(Some)
        });
        self.done = outputs.done() || (outputs.busy && outputs.reached);
        self.busy = outputs.busy;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
