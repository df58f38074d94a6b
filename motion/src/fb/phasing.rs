//! MC_PhasingAbsolute and MC_PhasingRelative.

use crate::fb::execute::ExecuteCore;
use crate::kernel::{AxisId, Dynamics, Kernel, MotionError};
use crate::sync::PhasingMode;

/// MC_PhasingAbsolute / MC_PhasingRelative (chosen by `mode`): shifts the master position the
/// coupled slave sees, smoothly within `Velocity`, `Acceleration`, `Deceleration` and `Jerk`
/// (a position profile of the shift). A positive shift makes the slave lag (CODESYS); the
/// master's own values never change. The shift stays in force until another phasing command
/// or the end of the coupling. Relative adds to the shift in force at the rising edge.
/// `Done` when the shift is reached; a new phasing command on the slave aborts a running one;
/// the end of the coupling aborts it too. Without a coupling to `master` the instance reports
/// [`MotionError::NotCoupled`].
#[derive(Clone, Debug, Default)]
pub struct Phasing {
    /// `Execute`: a rising edge starts the phase change.
    pub execute: bool,
    /// Absolute (MC_PhasingAbsolute) or relative (MC_PhasingRelative).
    pub mode: PhasingMode,
    /// `PhaseShift` in master units.
    pub phase_shift: f64,
    /// `Velocity` of the shift, master units per second.
    pub velocity: f64,
    /// `Acceleration` of the shift.
    pub acceleration: f64,
    /// `Deceleration` of the shift.
    pub deceleration: f64,
    /// `Jerk` of the shift; 0 for a trapezoid.
    pub jerk: f64,
    /// `Done`: the shift is reached.
    pub done: bool,
    /// `Busy`: the phase change has not ended.
    pub busy: bool,
    /// `Active`: the phase change runs.
    pub active: bool,
    /// `CommandAborted`: another phasing command or the end of the coupling interrupted it.
    pub command_aborted: bool,
    /// `Error`: the command was refused.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    /// `AbsolutePhaseShift`: the shift in force while the slave is coupled.
    pub absolute_phase_shift: f64,
    /// `CoveredPhaseShift`: the shift this command has covered so far.
    pub covered_phase_shift: f64,
    /// The shift when this instance's command started.
    start_shift: f64,
    core: ExecuteCore,
}

impl Phasing {
    /// One call of the instance for `master` and `slave`.
    pub fn call(&mut self, kernel: &mut Kernel, master: AxisId, slave: AxisId) {
        let dynamics = Dynamics {
            velocity: self.velocity,
            acceleration: self.acceleration,
            deceleration: self.deceleration,
            jerk: self.jerk,
        };
        let (mode, phase_shift) = (self.mode, self.phase_shift);
        let mut start_shift = None;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            if let Ok(Some(status)) = kernel.coupling_status(slave) {
                start_shift = Some(status.phase_shift);
            }
            kernel
                .phase(master, slave, mode, phase_shift, dynamics)
                .map(Some)
        });
        if let Some(shift) = start_shift {
            self.start_shift = shift;
        }
        if let Ok(Some(status)) = kernel.coupling_status(slave) {
            self.absolute_phase_shift = status.phase_shift;
            if outputs.busy || outputs.done() {
                self.covered_phase_shift = status.phase_shift - self.start_shift;
            }
        }
        self.done = outputs.done();
        self.busy = outputs.busy;
        self.active = outputs.active;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
