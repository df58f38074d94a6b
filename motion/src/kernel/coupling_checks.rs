//! The checks of coupling commands (MC_CamIn, MC_GearIn, MC_GearInPos) against the master,
//! the slave and the cams, made before a command may change anything.

use crate::kernel::validation::{check_jerk, check_magnitude};
use crate::kernel::{AxisId, Kernel, MotionError, MotionRequest};
use crate::sync::{CamCoupling, GearInPosState};

/// Checks that a scaling input is a finite number other than 0.
pub(crate) fn check_scaling(input: &'static str, value: f64) -> Result<(), MotionError> {
    if value.is_finite() && value != 0.0 {
        Ok(())
    } else {
        Err(MotionError::InvalidParameter {
            input,
            value,
            reason: "a scaling must be a finite number other than 0",
        })
    }
}

/// Checks that an input is a finite number.
pub(crate) fn check_finite(input: &'static str, value: f64) -> Result<(), MotionError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(MotionError::InvalidParameter {
            input,
            value,
            reason: "it must be a finite number",
        })
    }
}

/// Checks a gear ratio denominator.
pub(crate) fn check_denominator(denominator: u32) -> Result<(), MotionError> {
    if denominator == 0 {
        return Err(MotionError::InvalidParameter {
            input: "RatioDenominator",
            value: 0.0,
            reason: "the ratio denominator must be 1 or more",
        });
    }
    Ok(())
}

impl Kernel {
    /// Checks a coupling request before it may change anything.
    pub(crate) fn check_coupling(
        &self,
        slave: AxisId,
        request: MotionRequest,
    ) -> Result<(), MotionError> {
        let Some(master) = request.master() else {
            return Ok(());
        };
        self.axis(slave)?;
        let master_view = self.master_view(master)?;
        if master == slave {
            return Err(MotionError::MasterIsSlave);
        }
        let config = self.axis(slave)?.config;
        match request {
            MotionRequest::Cam { coupling, .. } => self.check_cam(slave, master, &coupling),
            MotionRequest::Gear { coupling, .. } => {
                check_denominator(coupling.ratio_denominator)?;
                check_magnitude(
                    "Acceleration",
                    coupling.acceleration,
                    config.max_acceleration,
                    false,
                )?;
                check_magnitude(
                    "Deceleration",
                    coupling.deceleration,
                    config.max_deceleration,
                    false,
                )?;
                check_jerk(coupling.jerk, config.max_jerk)
            }
            MotionRequest::GearInPos { coupling, .. } => {
                check_denominator(coupling.ratio_denominator)?;
                check_finite("MasterSyncPosition", coupling.master_sync_position)?;
                check_finite("SlaveSyncPosition", coupling.slave_sync_position)?;
                let distance = coupling.master_start_distance;
                if !(distance.is_finite() && distance > 0.0) {
                    return Err(MotionError::InvalidParameter {
                        input: "MasterStartDistance",
                        value: distance,
                        reason: "the master synchronises over a positive distance before MasterSyncPosition",
                    });
                }
                if GearInPosState::start(coupling, &master_view).is_none() {
                    return Err(MotionError::InvalidParameter {
                        input: "MasterSyncPosition",
                        value: coupling.master_sync_position,
                        reason: "the linear master has already passed MasterSyncPosition − MasterStartDistance",
                    });
                }
                Ok(())
            }
            MotionRequest::Position { .. }
            | MotionRequest::Velocity { .. }
            | MotionRequest::Halt { .. } => Ok(()),
        }
    }

    /// Checks the inputs of MC_CamIn against its selection and the master.
    fn check_cam(
        &self,
        slave: AxisId,
        master: AxisId,
        coupling: &CamCoupling,
    ) -> Result<(), MotionError> {
        let selection = self.cams.selection(coupling.cam_table)?;
        if selection.master != master || selection.slave != slave {
            return Err(MotionError::UnknownCamTable(coupling.cam_table.0));
        }
        check_scaling("MasterScaling", coupling.master_scaling)?;
        check_scaling("SlaveScaling", coupling.slave_scaling)?;
        check_finite("MasterOffset", coupling.master_offset)?;
        check_finite("SlaveOffset", coupling.slave_offset)?;
        if coupling.start_mode.ramps() {
            let config = self.axis(slave)?.config;
            check_magnitude(
                "VelocityDiff",
                coupling.velocity_diff,
                config.max_velocity,
                false,
            )?;
            check_magnitude(
                "Acceleration",
                coupling.acceleration,
                config.max_acceleration,
                false,
            )?;
            check_magnitude(
                "Deceleration",
                coupling.deceleration,
                config.max_deceleration,
                false,
            )?;
            check_jerk(coupling.jerk, config.max_jerk)?;
        }
        let curve = self.cams.cam(selection.cam)?.curve.as_ref();
        let master_view = self.master_view(master)?;
        // The same computation the first cycle makes, to refuse a master outside the range of
        // a non-periodic cam at the call instead of one cycle later.
        crate::sync::cam_start_values(curve, coupling, &selection, &master_view, 0.0).map(|_| ())
    }
}
