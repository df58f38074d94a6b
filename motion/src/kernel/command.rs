//! Commands as the kernel records them: an id for the FB instance that issued the command, its
//! status, and the parameters the profile generator needs.

use crate::axis::Direction;
use crate::kernel::{AxisId, MotionError};
use crate::sync::{CamCoupling, GearCoupling, GearInPosCoupling};

/// The id the kernel gives a command; the FB instance keeps it to learn what happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CommandId(pub u64);

/// What happened to a command so far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CommandStatus {
    /// Waiting in the buffer for the command before it to finish.
    Buffered,
    /// Controlling the axis. `reached` is TRUE once a velocity command is at its velocity
    /// (`InVelocity`) or an MC_Stop has brought the axis to rest while it still holds the lock.
    Active {
        /// Whether the commanded velocity (or rest, for MC_Stop) has been reached.
        reached: bool,
    },
    /// Finished as commanded.
    Done,
    /// Interrupted by another command or by switching the power off.
    Aborted,
    /// Ended by an error.
    Error(MotionError),
}

impl CommandStatus {
    /// Whether the command has ended, so its status will not change again.
    #[must_use]
    pub fn is_terminal(&self) -> bool {
        matches!(self, Self::Done | Self::Aborted | Self::Error(_))
    }
}

/// `MC_BUFFER_MODE`: when a new motion command takes over from the one running.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum BufferMode {
    /// Abort the running command at once (default).
    #[default]
    Aborting,
    /// Start when the running command has finished (at rest at its target, or at its velocity
    /// for MC_MoveVelocity).
    Buffered,
    /// Start at the end of the running position move without stopping, passing its target
    /// with the lower of both commanded velocities.
    BlendingLow,
    /// Like [`BufferMode::BlendingLow`], with the velocity of the running move.
    BlendingPrevious,
    /// Like [`BufferMode::BlendingLow`], with the velocity of the new move.
    BlendingNext,
    /// Like [`BufferMode::BlendingLow`], with the higher of both commanded velocities.
    BlendingHigh,
}

impl BufferMode {
    /// Whether the new command waits for the running one instead of aborting it.
    #[must_use]
    pub fn waits(self) -> bool {
        self != Self::Aborting
    }

    /// The CODESYS `MC_BUFFER_MODE` number.
    #[must_use]
    pub fn code(self) -> u16 {
        match self {
            Self::Aborting => 0,
            Self::Buffered => 1,
            Self::BlendingLow => 2,
            Self::BlendingPrevious => 3,
            Self::BlendingNext => 4,
            Self::BlendingHigh => 5,
        }
    }
}

/// The dynamic inputs of a motion FB, magnitudes in user units per s, s², s³.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dynamics {
    /// `Velocity`: the highest speed of the move.
    pub velocity: f64,
    /// `Acceleration`.
    pub acceleration: f64,
    /// `Deceleration`.
    pub deceleration: f64,
    /// `Jerk`; 0 uses the axis's jerk limit, or a trapezoidal profile if the axis has none.
    pub jerk: f64,
}

/// How the target of a position command is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PositionTarget {
    /// MC_MoveAbsolute: an absolute position and, on a modulo axis, the way round.
    Absolute {
        /// The target position.
        position: f64,
        /// Which way round a modulo axis goes.
        direction: Direction,
    },
    /// MC_MoveRelative: a distance from the set position when the command starts.
    Relative {
        /// The signed distance.
        distance: f64,
    },
    /// MC_MoveAdditive: a distance added to the last commanded target position in
    /// DiscreteMotion, to the set position otherwise.
    Additive {
        /// The signed distance.
        distance: f64,
    },
}

/// What a command asks the axis to do; the kernel turns it into a motion source when it takes
/// control of the axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MotionRequest {
    /// Move to a position and come to rest there.
    Position {
        /// Where to go.
        target: PositionTarget,
        /// The dynamic inputs.
        dynamics: Dynamics,
    },
    /// Reach a velocity and keep it.
    Velocity {
        /// `Direction`: positive, negative or current (the direction the axis moves in, positive
        /// at rest); the shortest and fastest ways are refused.
        direction: Direction,
        /// The dynamic inputs; `velocity` may be signed and is multiplied by the direction's
        /// sign, so a negative velocity in the negative direction moves positive.
        dynamics: Dynamics,
        /// Whether the FB that issued it is MC_Jog, for the description in the `AXIS_REF`.
        jog: bool,
    },
    /// MC_Halt: brake to rest, abortable.
    Halt {
        /// The deceleration and jerk inputs.
        dynamics: Dynamics,
    },
    /// MC_CamIn: follow `master` through a selected cam.
    Cam {
        /// The master axis; it must be the one the cam selection was made for.
        master: AxisId,
        /// The MC_CamIn inputs.
        coupling: CamCoupling,
    },
    /// MC_GearIn: follow `master` with a gear ratio.
    Gear {
        /// The master axis.
        master: AxisId,
        /// The MC_GearIn inputs.
        coupling: GearCoupling,
    },
    /// MC_GearInPos: follow `master` with a gear ratio, in sync at given positions.
    GearInPos {
        /// The master axis.
        master: AxisId,
        /// The MC_GearInPos inputs.
        coupling: GearInPosCoupling,
    },
}

impl MotionRequest {
    /// The name of the FB behind the request, shown as the axis's active command.
    #[must_use]
    pub fn fb_name(&self) -> &'static str {
        match self {
            Self::Position { target, .. } => match target {
                PositionTarget::Absolute { .. } => "MC_MoveAbsolute",
                PositionTarget::Relative { .. } => "MC_MoveRelative",
                PositionTarget::Additive { .. } => "MC_MoveAdditive",
            },
            Self::Velocity { jog: true, .. } => "MC_Jog",
            Self::Velocity { .. } => "MC_MoveVelocity",
            Self::Halt { .. } => "MC_Halt",
            Self::Cam { .. } => "MC_CamIn",
            Self::Gear { .. } => "MC_GearIn",
            Self::GearInPos { .. } => "MC_GearInPos",
        }
    }

    /// The master of a coupling request, `None` for single-axis motion.
    #[must_use]
    pub fn master(&self) -> Option<AxisId> {
        match self {
            Self::Cam { master, .. }
            | Self::Gear { master, .. }
            | Self::GearInPos { master, .. } => Some(*master),
            Self::Position { .. } | Self::Velocity { .. } | Self::Halt { .. } => None,
        }
    }
}
