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
    /// 10: MC_CamOut, MC_GearOut or MC_Phasing on a slave that no such coupling drives.
    #[error("{command}: the slave is not coupled by the FB it would end or shift")]
    NotCoupled {
        /// The FB that needed the coupling, such as `MC_CamOut`.
        command: &'static str,
    },
    /// 11: the master and the slave of a coupling are the same axis.
    #[error("the master and the slave must be different axes")]
    MasterIsSlave,
    /// 12: `CamTableID` names no selection of MC_CamTableSelect, or one made for other axes.
    #[error("CamTableID {0} was not selected by MC_CamTableSelect for this master and slave")]
    UnknownCamTable(u32),
    /// 13: the cam id names no cam of the kernel.
    #[error("cam {0} is not registered in the motion kernel")]
    UnknownCam(usize),
    /// 14: a non-periodic cam starts with its master coordinate outside the cam's master range.
    #[error(
        "the cam master coordinate {cam_master} at the start lies outside the cam's master range {start} .. {end}"
    )]
    MasterOutOfCamRange {
        /// The cam master coordinate X = MasterScaling·M + MasterOffset at the start.
        cam_master: f64,
        /// The first master position of the cam.
        start: f64,
        /// The last master position of the cam.
        end: f64,
    },
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
            Self::NotCoupled { .. } => 10,
            Self::MasterIsSlave => 11,
            Self::UnknownCamTable(_) => 12,
            Self::UnknownCam(_) => 13,
            Self::MasterOutOfCamRange { .. } => 14,
        }
    }
}
