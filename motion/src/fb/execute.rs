//! The output rules shared by the Execute-type FBs (PLCopen general rules, §2.4.1).
//!
//! - A rising edge of `Execute` issues the command with the inputs as they are at that call.
//! - A rising edge while the instance is busy is ignored, as CODESYS does: the running command
//!   keeps its parameters and its outputs. To change parameters, wait for the command to end
//!   (or abort it with another instance) and trigger again.
//! - `Busy`, `Done`, `Error` and `CommandAborted` exclude each other; `Active` excludes `Done`,
//!   `Error` and `CommandAborted`.
//! - A falling `Execute` does not touch the command. A final output (`Done`, `Error`,
//!   `CommandAborted`) stays while `Execute` is TRUE and is reset at the first call with
//!   `Execute` FALSE after the call that showed it, so when `Execute` was already FALSE it is
//!   shown for exactly one call.
//! - `ContinuousUpdate` is read at the rising edge. When it was TRUE there, the motion inputs
//!   are compared at every call while the command runs and changes are applied to it, for as
//!   long as the input stays TRUE (FALSE freezes the last values applied).

use crate::kernel::{
    AxisId, BufferMode, CommandId, CommandStatus, Kernel, MotionError, MotionRequest,
};

/// The final outcome an instance shows.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) enum Outcome {
    /// Nothing to show.
    #[default]
    None,
    /// The command finished as commanded.
    Done,
    /// Another command interrupted it.
    Aborted,
    /// It failed or was refused.
    Error(MotionError),
}

/// The outputs an Execute-type FB derives from its command.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ExecuteOutputs {
    pub(crate) busy: bool,
    pub(crate) active: bool,
    pub(crate) reached: bool,
    pub(crate) outcome: Outcome,
}

impl ExecuteOutputs {
    pub(crate) fn done(&self) -> bool {
        self.outcome == Outcome::Done
    }

    pub(crate) fn command_aborted(&self) -> bool {
        self.outcome == Outcome::Aborted
    }

    pub(crate) fn error(&self) -> Option<MotionError> {
        match self.outcome {
            Outcome::Error(error) => Some(error),
            _ => None,
        }
    }

    pub(crate) fn error_id(&self) -> u16 {
        self.error().map_or(0, |error| error.id())
    }
}

/// The bookkeeping of an Execute-type instance: the last `Execute`, the command it follows and
/// the outcome it shows.
#[derive(Clone, Debug, Default)]
pub(crate) struct ExecuteCore {
    previous_execute: bool,
    command: Option<CommandId>,
    outcome: Outcome,
    /// `ContinuousUpdate` as it was at the rising edge.
    continuous: bool,
    /// The request last issued or applied, to see whether the inputs changed.
    last_request: Option<MotionRequest>,
}

impl ExecuteCore {
    /// One call of the instance. `issue` runs on a rising edge of `execute` when the instance
    /// is not busy; it returns the command to follow, or `None` when the command finished at
    /// once.
    pub(crate) fn call(
        &mut self,
        execute: bool,
        kernel: &mut Kernel,
        issue: impl FnOnce(&mut Kernel) -> Result<Option<CommandId>, MotionError>,
    ) -> ExecuteOutputs {
        let rising = execute && !self.previous_execute;
        self.previous_execute = execute;
        if !execute {
            self.outcome = Outcome::None;
        }
        if rising && self.command.is_none() {
            self.outcome = match issue(kernel) {
                Ok(Some(id)) => {
                    self.command = Some(id);
                    Outcome::None
                }
                Ok(None) => Outcome::Done,
                Err(error) => Outcome::Error(error),
            };
        }
        self.poll(kernel)
    }

    /// One call of a motion FB: issues `request` on a rising edge of `execute` and applies
    /// changed inputs while `ContinuousUpdate` holds (see the module documentation).
    pub(crate) fn call_motion(
        &mut self,
        execute: bool,
        continuous_update: bool,
        kernel: &mut Kernel,
        axis: AxisId,
        request: MotionRequest,
        buffer_mode: BufferMode,
    ) -> ExecuteOutputs {
        let issues = execute && !self.previous_execute && self.command.is_none();
        if !issues
            && let Some(id) = self.command
            && self.continuous
            && continuous_update
            && self.last_request != Some(request)
        {
            kernel.update(id, request);
            self.last_request = Some(request);
        }
        let outputs = self.call(execute, kernel, |kernel| {
            check_axis(kernel, axis)?;
            kernel.issue(axis, request, buffer_mode).map(Some)
        });
        if issues {
            self.continuous = continuous_update;
            self.last_request = Some(request);
        }
        outputs
    }

    /// The command the instance follows, while it is busy.
    pub(crate) fn command(&self) -> Option<CommandId> {
        self.command
    }

    /// Reads the status of the followed command and turns a final status into the outcome.
    fn poll(&mut self, kernel: &mut Kernel) -> ExecuteOutputs {
        let mut outputs = ExecuteOutputs::default();
        if let Some(id) = self.command {
            let finished = match kernel.command_status(id) {
                Some(CommandStatus::Buffered) => {
                    outputs.busy = true;
                    None
                }
                Some(CommandStatus::Active { reached }) => {
                    outputs.busy = true;
                    outputs.active = true;
                    outputs.reached = reached;
                    None
                }
                Some(CommandStatus::Done) => Some(Outcome::Done),
                // A status that vanished was dropped by someone else; the command no longer
                // controls the axis, which is what an abort means to this instance.
                Some(CommandStatus::Aborted) | None => Some(Outcome::Aborted),
                Some(CommandStatus::Error(error)) => Some(Outcome::Error(error)),
            };
            if let Some(outcome) = finished {
                kernel.forget(id);
                self.command = None;
                self.outcome = outcome;
            }
        }
        outputs.outcome = self.outcome;
        outputs
    }
}

/// Checks that `axis` exists before an FB issues a command to it.
pub(crate) fn check_axis(kernel: &Kernel, axis: AxisId) -> Result<(), MotionError> {
    kernel.state(axis).map(|_| ())
}
