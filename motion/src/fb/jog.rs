//! MC_Jog.

use crate::axis::Direction;
use crate::fb::execute::Outcome;
use crate::kernel::{
    AxisId, BufferMode, CommandId, CommandStatus, Dynamics, Kernel, MotionError, MotionRequest,
};

/// What the instance is doing on the axis.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
enum JogPhase {
    #[default]
    Idle,
    /// Moving at the jog velocity in a direction (+1 or -1).
    Moving(CommandId, i8),
    /// Braking after the jog inputs were released.
    Halting(CommandId),
}

/// MC_Jog as CODESYS has it: while exactly one of `JogForward` and `JogBackward` is TRUE the
/// axis moves at `Velocity` in that direction (ContinuousMotion, like MC_MoveVelocity); when
/// both are FALSE (or both TRUE) it brakes with `Deceleration` (DiscreteMotion, like MC_Halt)
/// and `Done` turns TRUE at rest. The inputs act as levels and are read at every call.
/// A final output stays while a jog input is TRUE and shows for one call otherwise.
#[derive(Clone, Debug, Default)]
pub struct Jog {
    /// `JogForward`: move in the positive direction while TRUE.
    pub jog_forward: bool,
    /// `JogBackward`: move in the negative direction while TRUE.
    pub jog_backward: bool,
    /// `Velocity`: the jog speed in user units per second.
    pub velocity: f64,
    /// `Acceleration` in user units per second².
    pub acceleration: f64,
    /// `Deceleration` in user units per second².
    pub deceleration: f64,
    /// `Jerk` in user units per second³; 0 uses the axis's jerk limit (none: trapezoid).
    pub jerk: f64,
    /// `Done`: the axis came to rest after the jog inputs were released.
    pub done: bool,
    /// `Busy`: the instance moves or brakes the axis.
    pub busy: bool,
    /// `CommandAborted`: another command took the axis over.
    pub command_aborted: bool,
    /// `Error`: the jog was refused or ended in an error.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    phase: JogPhase,
    previous_wanted: i8,
    outcome: Outcome,
}

impl Jog {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &mut Kernel, axis: AxisId) {
        let level = self.jog_forward || self.jog_backward;
        if !level {
            self.outcome = Outcome::None;
        }
        let wanted: i8 = match (self.jog_forward, self.jog_backward) {
            (true, false) => 1,
            (false, true) => -1,
            _ => 0,
        };
        let changed = wanted != self.previous_wanted;
        self.previous_wanted = wanted;
        self.poll(kernel);
        if changed {
            self.follow(kernel, axis, wanted);
        }
        self.done = self.outcome == Outcome::Done;
        self.busy = self.phase != JogPhase::Idle;
        self.command_aborted = self.outcome == Outcome::Aborted;
        self.error_cause = match self.outcome {
            Outcome::Error(error) => Some(error),
            _ => None,
        };
        self.error = self.error_cause.is_some();
        self.error_id = self.error_cause.map_or(0, |error| error.id());
    }

    /// Reads what happened to the instance's own command since the last call.
    fn poll(&mut self, kernel: &mut Kernel) {
        let (id, halting) = match self.phase {
            JogPhase::Idle => return,
            JogPhase::Moving(id, _) => (id, false),
            JogPhase::Halting(id) => (id, true),
        };
        let outcome = match kernel.command_status(id) {
            Some(CommandStatus::Buffered | CommandStatus::Active { .. }) => return,
            Some(CommandStatus::Done) if halting => Outcome::Done,
            Some(CommandStatus::Done | CommandStatus::Aborted) | None => Outcome::Aborted,
            Some(CommandStatus::Error(error)) => Outcome::Error(error),
        };
        kernel.forget(id);
        self.phase = JogPhase::Idle;
        self.outcome = outcome;
    }

    /// Issues the command that matches the jog inputs after they changed.
    fn follow(&mut self, kernel: &mut Kernel, axis: AxisId, wanted: i8) {
        let own = match self.phase {
            JogPhase::Idle => None,
            JogPhase::Moving(id, _) | JogPhase::Halting(id) => Some(id),
        };
        let request = if wanted != 0 {
            MotionRequest::Velocity {
                direction: if wanted > 0 {
                    Direction::Positive
                } else {
                    Direction::Negative
                },
                dynamics: Dynamics {
                    velocity: self.velocity,
                    acceleration: self.acceleration,
                    deceleration: self.deceleration,
                    jerk: self.jerk,
                },
                jog: true,
            }
        } else if let JogPhase::Moving(..) = self.phase {
            MotionRequest::Halt {
                dynamics: Dynamics {
                    velocity: 0.0,
                    acceleration: self.deceleration,
                    deceleration: self.deceleration,
                    jerk: self.jerk,
                },
            }
        } else {
            return;
        };
        match kernel.issue(axis, request, BufferMode::Aborting) {
            Ok(id) => {
                // The instance's previous command was aborted by its own successor, which is
                // not an abort the user needs to see.
                if let Some(own) = own {
                    kernel.forget(own);
                }
                self.phase = if wanted != 0 {
                    JogPhase::Moving(id, wanted)
                } else {
                    JogPhase::Halting(id)
                };
                self.outcome = Outcome::None;
            }
            Err(error) => self.outcome = Outcome::Error(error),
        }
    }
}
