//! The inputs of MC_CamIn as the kernel receives them.

use crate::sync::CamTableId;

/// `MC_StartMode`: how the slave gets onto the cam at the start of the coupling.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum StartMode {
    /// 0: the cam's slave values are absolute when the selection says `SlaveAbsolute`,
    /// relative to the slave's start position otherwise; the slave jumps onto the cam.
    #[default]
    Absolute,
    /// 1: the cam's slave values count from the slave's position at the start.
    Relative,
    /// 2: like `Absolute`, and a compensating motion within `VelocityDiff`, `Acceleration`,
    /// `Deceleration` and `Jerk` removes the start jump, the shortest way on a modulo slave.
    RampIn,
    /// 3: like `RampIn`, compensating only in the positive direction on a modulo slave.
    RampInPositive,
    /// 4: like `RampIn`, compensating only in the negative direction on a modulo slave.
    RampInNegative,
}

impl StartMode {
    /// The CODESYS `MC_StartMode` number.
    #[must_use]
    pub fn code(self) -> u16 {
        match self {
            Self::Absolute => 0,
            Self::Relative => 1,
            Self::RampIn => 2,
            Self::RampInPositive => 3,
            Self::RampInNegative => 4,
        }
    }

    /// Whether the mode removes the start jump with a compensating motion.
    #[must_use]
    pub fn ramps(self) -> bool {
        matches!(
            self,
            Self::RampIn | Self::RampInPositive | Self::RampInNegative
        )
    }
}

/// The inputs of MC_CamIn sampled at its rising edge:
/// `X = MasterScaling·M + MasterOffset`, `Y = SlaveScaling·CAM(X) + SlaveOffset`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CamCoupling {
    /// `CamTableID`: the selection made by MC_CamTableSelect.
    pub cam_table: CamTableId,
    /// `MasterOffset` in cam master units.
    pub master_offset: f64,
    /// `SlaveOffset` in slave units.
    pub slave_offset: f64,
    /// `MasterScaling`: not 0; above 1 the cam runs faster.
    pub master_scaling: f64,
    /// `SlaveScaling`: not 0; above 1 the slave stroke grows.
    pub slave_scaling: f64,
    /// `StartMode`.
    pub start_mode: StartMode,
    /// `VelocityDiff`: the highest speed of the ramp-in compensation, in slave units per s.
    pub velocity_diff: f64,
    /// `Acceleration` of the ramp-in compensation.
    pub acceleration: f64,
    /// `Deceleration` of the ramp-in compensation.
    pub deceleration: f64,
    /// `Jerk` of the ramp-in compensation; 0 uses the slave's jerk limit (none: trapezoid).
    pub jerk: f64,
}

impl Default for CamCoupling {
    fn default() -> Self {
        Self {
            cam_table: CamTableId::default(),
            master_offset: 0.0,
            slave_offset: 0.0,
            master_scaling: 1.0,
            slave_scaling: 1.0,
            start_mode: StartMode::default(),
            velocity_diff: 0.0,
            acceleration: 0.0,
            deceleration: 0.0,
            jerk: 0.0,
        }
    }
}

/// The slave set values a cam commands at one master position
/// (SMC_GetCamSlaveSetPosition's `fStartPosition`, `fStartVelocity`, `fStartAcceleration`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CamSlaveValues {
    /// The slave set position.
    pub position: f64,
    /// The slave set velocity in slave units per second.
    pub velocity: f64,
    /// The slave set acceleration in slave units per second².
    pub acceleration: f64,
}
