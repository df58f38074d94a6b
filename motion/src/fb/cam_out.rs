//! MC_CamOut.

use crate::fb::decouple::DecoupleCore;
use crate::kernel::{AxisId, Decoupling, Kernel, MotionError};

/// MC_CamOut: ends the MC_CamIn coupling of the slave at the rising edge. The slave keeps the
/// velocity it had, in ContinuousMotion with no FB controlling it (stop it with MC_Stop or
/// MC_Halt); the MC_CamIn instance stops being busy without `CommandAborted`. Without a cam
/// coupling the instance reports [`MotionError::NotCoupled`].
#[derive(Clone, Debug, Default)]
pub struct CamOut {
    /// `Execute`: a rising edge decouples.
    pub execute: bool,
    /// `Done`: the slave is decoupled.
    pub done: bool,
    /// `Busy`: never TRUE after a call, since decoupling happens at once.
    pub busy: bool,
    /// `Error`: there was no cam coupling to end.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    core: DecoupleCore,
}

impl CamOut {
    /// One call of the instance for `slave`.
    pub fn call(&mut self, kernel: &mut Kernel, slave: AxisId) {
        let outputs = self
            .core
            .call(self.execute, kernel, slave, Decoupling::CamOut);
        self.done = outputs.done;
        self.busy = outputs.busy;
        self.error = outputs.error.is_some();
        self.error_id = outputs.error.map_or(0, |error| error.id());
        self.error_cause = outputs.error;
    }
}
