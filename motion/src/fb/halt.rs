//! MC_Halt.

use crate::fb::execute::{ExecuteCore, check_axis};
use crate::kernel::{AxisId, BufferMode, Dynamics, Kernel, MotionError, MotionRequest};

/// MC_Halt: brake to rest under normal conditions. The axis is in DiscreteMotion until rest,
/// then Standstill; unlike MC_Stop another motion command may abort it while it brakes.
#[derive(Clone, Debug, Default)]
pub struct Halt {
    /// `Execute`: a rising edge starts the command with the inputs of that call.
    pub execute: bool,
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

impl Halt {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let request = MotionRequest::Halt {
            dynamics: Dynamics {
                velocity: 0.0,
                acceleration: self.deceleration,
                deceleration: self.deceleration,
                jerk: self.jerk,
            },
        };
        let buffer_mode = self.buffer_mode;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            check_axis(kernel, axis)?;
            kernel.issue(axis, request, buffer_mode).map(Some)
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
