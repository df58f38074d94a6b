//! SMC_GetCamSlaveSetPosition.

use crate::kernel::{AxisId, Kernel, MotionError};
use crate::sync::{CamCoupling, CamTableId};

/// SMC_GetCamSlaveSetPosition: while `Enable` is TRUE, the slave position, velocity and
/// acceleration MC_CamIn would command first with these inputs for the master's and the
/// slave's current values — the MC_CamIn formula `SlaveScaling·CAM(MasterScaling·M +
/// MasterOffset) + SlaveOffset` (the digest's different manual formula agrees for unit
/// scalings). Nothing moves; meant to be read once to start the slave where the cam begins.
#[derive(Clone, Debug)]
pub struct GetCamSlaveSetPosition {
    /// `Enable`: compute while TRUE.
    pub enable: bool,
    /// `MasterOffset`.
    pub master_offset: f64,
    /// `SlaveOffset`.
    pub slave_offset: f64,
    /// `MasterScaling`, 1.0 by default.
    pub master_scaling: f64,
    /// `SlaveScaling`, 1.0 by default.
    pub slave_scaling: f64,
    /// `CamTableID` from MC_CamTableSelect.
    pub cam_table_id: CamTableId,
    /// `fStartPosition`.
    pub start_position: f64,
    /// `fStartVelocity`, slave units per second.
    pub start_velocity: f64,
    /// `fStartAcceleration`, slave units per second².
    pub start_acceleration: f64,
    /// `Busy`: the instance is enabled.
    pub busy: bool,
    /// `Error`: the inputs are invalid.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
}

impl Default for GetCamSlaveSetPosition {
    fn default() -> Self {
        Self {
            enable: false,
            master_offset: 0.0,
            slave_offset: 0.0,
            master_scaling: 1.0,
            slave_scaling: 1.0,
            cam_table_id: CamTableId::default(),
            start_position: 0.0,
            start_velocity: 0.0,
            start_acceleration: 0.0,
            busy: false,
            error: false,
            error_id: 0,
            error_cause: None,
        }
    }
}

impl GetCamSlaveSetPosition {
    /// One call of the instance for `master` and `slave`.
    pub fn call(&mut self, kernel: &Kernel, master: AxisId, slave: AxisId) {
        self.busy = self.enable;
        self.error_cause = None;
        if self.enable {
            let coupling = CamCoupling {
                cam_table: self.cam_table_id,
                master_offset: self.master_offset,
                slave_offset: self.slave_offset,
                master_scaling: self.master_scaling,
                slave_scaling: self.slave_scaling,
                ..CamCoupling::default()
            };
            match kernel.cam_slave_values(master, slave, &coupling) {
                Ok(values) => {
                    self.start_position = values.position;
                    self.start_velocity = values.velocity;
                    self.start_acceleration = values.acceleration;
                }
                Err(error) => self.error_cause = Some(error),
            }
        }
        self.error = self.error_cause.is_some();
        self.error_id = self.error_cause.map_or(0, |error| error.id());
    }
}
