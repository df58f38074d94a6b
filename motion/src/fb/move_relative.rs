//! MC_MoveRelative.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{
    AxisId, BufferMode, Dynamics, Kernel, MotionError, MotionRequest, PositionTarget,
};

/// MC_MoveRelative: move a distance from the set position at the moment the command starts.
#[derive(Clone, Debug, Default)]
pub struct MoveRelative {
    /// `Execute`: a rising edge starts the command with the inputs of that call.
    pub execute: bool,
    /// `ContinuousUpdate`: when TRUE at the rising edge, later changes of the motion inputs
    /// apply to the running command while this input stays TRUE.
    pub continuous_update: bool,
    /// `Distance`: the signed distance in user units.
    pub distance: f64,
    /// `Velocity`: the highest speed in user units per second (not necessarily reached).
    pub velocity: f64,
    /// `Acceleration` in user units per second².
    pub acceleration: f64,
    /// `Deceleration` in user units per second².
    pub deceleration: f64,
    /// `Jerk` in user units per second³; 0 uses the axis's jerk limit (none: trapezoid).
    pub jerk: f64,
    /// `BufferMode`: abort the running command or wait for it.
    pub buffer_mode: BufferMode,
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

impl MoveRelative {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let request = MotionRequest::Position {
            target: PositionTarget::Relative {
                distance: self.distance,
            },
            dynamics: Dynamics {
                velocity: self.velocity,
                acceleration: self.acceleration,
                deceleration: self.deceleration,
                jerk: self.jerk,
            },
        };
        let outputs = self.core.call_motion(
            self.execute,
            self.continuous_update,
            kernel,
            axis,
            request,
            self.buffer_mode,
        );
        self.done = outputs.done();
        self.busy = outputs.busy;
        self.active = outputs.active;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
