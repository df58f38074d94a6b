//! The PLCopen axis state, numbered like CODESYS `SMC_AXIS_STATE`.

use std::fmt;

/// The state of an axis in the PLCopen state diagram. The discriminants are the CODESYS
/// `SMC_AXIS_STATE` numbers, which the runtime writes into the `AXIS_REF`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(u16)]
pub enum AxisState {
    /// PLCopen `Disabled`: the power stage is off.
    #[default]
    PowerOff = 0,
    /// An axis error stopped the axis; only MC_Reset and MC_Power act.
    ErrorStop = 1,
    /// MC_Stop brakes the axis or holds it locked.
    Stopping = 2,
    /// Powered and at rest, ready for a command.
    Standstill = 3,
    /// A move with an end position (or MC_Halt) runs.
    DiscreteMotion = 4,
    /// An endless move (MC_MoveVelocity, MC_Jog) runs.
    ContinuousMotion = 5,
    /// The axis follows a master as a slave.
    SynchronizedMotion = 6,
    /// MC_Home runs.
    Homing = 7,
}

impl AxisState {
    /// The CODESYS `SMC_AXIS_STATE` number.
    #[must_use]
    pub fn code(self) -> u16 {
        self as u16
    }

    /// Whether the axis moves under a motion command in this state.
    #[must_use]
    pub fn is_moving_state(self) -> bool {
        matches!(
            self,
            Self::DiscreteMotion | Self::ContinuousMotion | Self::SynchronizedMotion
        )
    }
}

impl fmt::Display for AxisState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::PowerOff => "Disabled",
            Self::ErrorStop => "ErrorStop",
            Self::Stopping => "Stopping",
            Self::Standstill => "Standstill",
            Self::DiscreteMotion => "DiscreteMotion",
            Self::ContinuousMotion => "ContinuousMotion",
            Self::SynchronizedMotion => "SynchronizedMotion",
            Self::Homing => "Homing",
        })
    }
}
