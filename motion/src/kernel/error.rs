//! Why a motion command was refused or ended in an error, with stable numbers for `ErrorID`.

use thiserror::Error;

use crate::axis::AxisState;

/// The axis error id the kernel raises itself when a linear axis's set position leaves its
/// software limits while moving (for instance under MC_MoveVelocity).
pub const AXIS_ERROR_SOFTWARE_LIMIT: u16 = 5;

/// An error of one function block instance. [`MotionError::id`] is the number the runtime
/// shows in the FB's `ErrorID`; the numbers are stable and documented on each variant.
#[derive(Clone, Copy, Debug, PartialEq, Error)]
pub enum MotionError {
    /// 1: the axis is not powered (MC_Power.Enable is FALSE).
    #[error("the axis is not powered: switch it on with MC_Power first")]
    NotPowered,
    /// 2: the axis is in ErrorStop.
    #[error("the axis is in ErrorStop: acknowledge the axis error with MC_Reset first")]
    AxisInErrorStop,
    /// 3: MC_Stop holds the axis in Stopping.
    #[error("the axis is locked by MC_Stop: set MC_Stop.Execute to FALSE first")]
    AxisStopping,
    /// 4: an input of the FB has a value the command cannot run with.
    #[error("input {input} = {value} is invalid: {reason}")]
    InvalidParameter {
        /// The PLCopen name of the input, such as `Velocity`.
        input: &'static str,
        /// The value the FB was called with.
        value: f64,
        /// What the input must be.
        reason: &'static str,
    },
    /// 5: the target position lies outside the software limits of a linear axis.
    #[error("target position {target} lies outside the software limits {min} .. {max}")]
    OutsideSoftwareLimits {
        /// The refused target position.
        target: f64,
        /// The negative software limit.
        min: f64,
        /// The positive software limit.
        max: f64,
    },
    /// 6: the command is not allowed in the axis's current state.
    #[error("{command} is not allowed while the axis is in {state}")]
    IllegalState {
        /// The FB that issued the command, such as `MC_Home`.
        command: &'static str,
        /// The state the axis was in.
        state: AxisState,
    },
    /// 7: a buffered command is already waiting on the axis (the buffer holds one).
    #[error("another buffered command is already waiting on the axis")]
    BufferFull,
    /// 8: an axis error stopped the axis while the command controlled it.
    #[error("axis error {axis_error_id} stopped the axis")]
    AxisError {
        /// The axis error id, as MC_ReadAxisError shows it.
        axis_error_id: u16,
    },
    /// 9: the axis reference does not name an axis of the kernel.
    #[error("axis {0} does not exist in the motion kernel")]
    UnknownAxis(usize),
}

impl MotionError {
    /// The stable `ErrorID` number of this error.
    #[must_use]
    pub fn id(&self) -> u16 {
        match self {
            Self::NotPowered => 1,
            Self::AxisInErrorStop => 2,
            Self::AxisStopping => 3,
            Self::InvalidParameter { .. } => 4,
            Self::OutsideSoftwareLimits { .. } => 5,
            Self::IllegalState { .. } => 6,
            Self::BufferFull => 7,
            Self::AxisError { .. } => 8,
            Self::UnknownAxis(_) => 9,
        }
    }
}
