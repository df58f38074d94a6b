//! MC_GearInPos.

use crate::fb::execute::{ExecuteCore, check_axis};
use crate::kernel::{AxisId, BufferMode, Kernel, MotionError, MotionRequest};
use crate::sync::GearInPosCoupling;

/// MC_GearInPos: couples the slave with a gear ratio so that it is at `SlaveSyncPosition`
/// when the master is at `MasterSyncPosition`.
///
/// Until the master (moving positive) crosses `MasterSyncPosition − MasterStartDistance`, the
/// slave keeps the velocity it had when the command took over (at rest it stays at rest).
/// There `StartSync` turns TRUE and the slave follows a generated Poly5 cam over the master
/// distance `MasterStartDistance`, from its position and velocity to `SlaveSyncPosition` with
/// slope = ratio and no acceleration; at `MasterSyncPosition` `InSync` turns TRUE and the slave
/// moves the ratio times the master's displacement. On a modulo master the start point is the
/// next crossing ahead, so a start distance above the period starts in an earlier revolution;
/// on a modulo slave the sync position is reached through the image closest to the geared
/// distance, forward through the wrap when that is nearer. A linear master already past the
/// start point is refused. The PLCopen `Velocity`, `Acceleration`, `Deceleration`, `Jerk`
/// limits, `SyncMode` and CODESYS `AvoidReversal` are not implemented.
#[derive(Clone, Debug)]
pub struct GearInPos {
    /// `Execute`: a rising edge couples with the inputs of that call.
    pub execute: bool,
    /// `RatioNumerator`, signed; 1 by default.
    pub ratio_numerator: i32,
    /// `RatioDenominator`, 1 or more; 1 by default.
    pub ratio_denominator: u32,
    /// `MasterSyncPosition`.
    pub master_sync_position: f64,
    /// `SlaveSyncPosition`.
    pub slave_sync_position: f64,
    /// `MasterStartDistance`, above 0.
    pub master_start_distance: f64,
    /// `BufferMode`.
    pub buffer_mode: BufferMode,
    /// `StartSync`: the master passed the start point; the slave synchronises.
    pub start_sync: bool,
    /// `InSync`: the slave is geared at the sync positions.
    pub in_sync: bool,
    /// `Busy`: the coupling has not ended.
    pub busy: bool,
    /// `Active`: the coupling controls the slave.
    pub active: bool,
    /// `CommandAborted`: another command took the slave.
    pub command_aborted: bool,
    /// `Error`: the coupling was refused or ended in an error.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    core: ExecuteCore,
}

impl Default for GearInPos {
    fn default() -> Self {
        Self {
            execute: false,
            ratio_numerator: 1,
            ratio_denominator: 1,
            master_sync_position: 0.0,
            slave_sync_position: 0.0,
            master_start_distance: 0.0,
            buffer_mode: BufferMode::default(),
            start_sync: false,
            in_sync: false,
            busy: false,
            active: false,
            command_aborted: false,
            error: false,
            error_id: 0,
            error_cause: None,
            core: ExecuteCore::default(),
        }
    }
}

impl GearInPos {
    /// One call of the instance for `master` and `slave`.
    pub fn call(&mut self, kernel: &mut Kernel, master: AxisId, slave: AxisId) {
        let request = MotionRequest::GearInPos {
            master,
            coupling: GearInPosCoupling {
                ratio_numerator: self.ratio_numerator,
                ratio_denominator: self.ratio_denominator,
                master_sync_position: self.master_sync_position,
                slave_sync_position: self.slave_sync_position,
                master_start_distance: self.master_start_distance,
            },
        };
        let buffer_mode = self.buffer_mode;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            check_axis(kernel, slave)?;
            kernel.issue(slave, request, buffer_mode).map(Some)
        });
        self.start_sync = outputs.active
            && matches!(
                kernel.coupling_status(slave),
                Ok(Some(status)) if status.command == self.core.command() && status.start_sync
            );
        self.in_sync = outputs.active && outputs.reached;
        self.busy = outputs.busy;
        self.active = outputs.active;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
