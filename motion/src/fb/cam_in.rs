//! MC_CamIn.

use crate::fb::execute::{ExecuteCore, check_axis};
use crate::fb::tappet_data::TappetData;
use crate::kernel::{AxisId, BufferMode, Kernel, MotionError, MotionRequest};
use crate::sync::{CamCoupling, CamTableId, StartMode};

/// MC_CamIn: couples the slave to the master through the cam of a `CamTableID`:
/// `X = MasterScaling·M + MasterOffset`, slave = `SlaveScaling·CAM(X) + SlaveOffset`, from
/// the slave's start position when the slave is relative (see [`StartMode`]).
///
/// The slave goes to SynchronizedMotion at the rising edge; the set values follow from the
/// next `advance`, which reads the master's values of that cycle (add the master to the kernel
/// before the slave). `InSync` is TRUE once the slave follows the cam exactly (at once, or when
/// the ramp-in compensation has ended). `Busy` stays TRUE while the coupling lasts: only
/// MC_CamOut, another command on the slave (`CommandAborted`) or an error end it, falling
/// `Execute` does not. A rising edge while busy is ignored, as for every Execute FB.
///
/// With `MasterAbsolute` the cam master coordinate starts from the master's set position,
/// otherwise from 0 (plus `MasterOffset`); a periodic cam takes it into its master range, a
/// non-periodic cam refuses a start outside the range (ErrorID 14). `SlaveOffset` applies in
/// the absolute and the relative slave mode alike (CODESYS; Delta applies it only absolute).
///
/// `EndOfProfile` of a periodic cam is TRUE for one call after each wrap of the cam master
/// coordinate (forward at the end, backward at the start); of a non-periodic cam it is TRUE
/// once the master left the range, the slave holding the end value, until `Execute` is FALSE.
///
/// The cam's tappet tracks are evaluated at every call on the cam master coordinate into
/// [`CamIn::tappets`]; a wrap at the period end is a continued motion. `TappetHysteresis`
/// other than 0 replaces the hysteresis of every track. A new rising edge restarts the
/// tappets: with the same cam and hysteresis the outputs return to their initial value where
/// the track asks for it (SMC_GetTappetValue `bSetInitValueAtReset`).
#[derive(Clone, Debug)]
pub struct CamIn {
    /// `Execute`: a rising edge couples with the inputs of that call.
    pub execute: bool,
    /// `MasterOffset` in cam master units.
    pub master_offset: f64,
    /// `SlaveOffset` in slave units.
    pub slave_offset: f64,
    /// `MasterScaling`, 1.0 by default; must not be 0.
    pub master_scaling: f64,
    /// `SlaveScaling`, 1.0 by default; must not be 0.
    pub slave_scaling: f64,
    /// `StartMode`.
    pub start_mode: StartMode,
    /// `CamTableID` from MC_CamTableSelect.
    pub cam_table_id: CamTableId,
    /// `VelocityDiff` of the ramp-in, in slave units per second.
    pub velocity_diff: f64,
    /// `Acceleration` of the ramp-in.
    pub acceleration: f64,
    /// `Deceleration` of the ramp-in.
    pub deceleration: f64,
    /// `Jerk` of the ramp-in; 0 uses the slave's jerk limit (none: trapezoid).
    pub jerk: f64,
    /// `TappetHysteresis` in cam master units; 0 keeps the tracks' own hysteresis.
    pub tappet_hysteresis: f64,
    /// `BufferMode`.
    pub buffer_mode: BufferMode,
    /// `InSync`: the slave follows the cam exactly.
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
    /// `EndOfProfile`.
    pub end_of_profile: bool,
    /// `Tappets`: the tappet outputs of the coupling's cam.
    pub tappets: TappetData,
    core: ExecuteCore,
}

impl Default for CamIn {
    fn default() -> Self {
        Self {
            execute: false,
            master_offset: 0.0,
            slave_offset: 0.0,
            master_scaling: 1.0,
            slave_scaling: 1.0,
            start_mode: StartMode::default(),
            cam_table_id: CamTableId::default(),
            velocity_diff: 0.0,
            acceleration: 0.0,
            deceleration: 0.0,
            jerk: 0.0,
            tappet_hysteresis: 0.0,
            buffer_mode: BufferMode::default(),
            in_sync: false,
            busy: false,
            active: false,
            command_aborted: false,
            error: false,
            error_id: 0,
            error_cause: None,
            end_of_profile: false,
            tappets: TappetData::default(),
            core: ExecuteCore::default(),
        }
    }
}

impl CamIn {
    /// The kernel request of the inputs of this call.
    fn request(&self, master: AxisId) -> MotionRequest {
        MotionRequest::Cam {
            master,
            coupling: CamCoupling {
                cam_table: self.cam_table_id,
                master_offset: self.master_offset,
                slave_offset: self.slave_offset,
                master_scaling: self.master_scaling,
                slave_scaling: self.slave_scaling,
                start_mode: self.start_mode,
                velocity_diff: self.velocity_diff,
                acceleration: self.acceleration,
                deceleration: self.deceleration,
                jerk: self.jerk,
            },
        }
    }

    /// One call of the instance for `master` and `slave`.
    pub fn call(&mut self, kernel: &mut Kernel, master: AxisId, slave: AxisId) {
        let request = self.request(master);
        let (cam_table, hysteresis, buffer_mode) =
            (self.cam_table_id, self.tappet_hysteresis, self.buffer_mode);
        let tappets = &mut self.tappets;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            check_axis(kernel, slave)?;
            // The tappets are prepared before the coupling is issued, so a refused hysteresis
            // refuses the coupling, and taken only once the kernel has accepted it.
            let selection = kernel.cam_selection(cam_table)?;
            let curve = kernel.cam(selection.cam)?;
            let tracks = kernel.cam_tracks(selection.cam)?;
            let prepared = tappets
                .prepare(selection.cam, curve, tracks, selection.periodic, hysteresis)
                .map_err(|_| MotionError::InvalidParameter {
                    input: "TappetHysteresis",
                    value: hysteresis,
                    reason: "the hysteresis must be 0 or more and below half the cam's master period",
                })?;
            let id = kernel.issue(slave, request, buffer_mode)?;
            tappets.begin(prepared);
            Ok(Some(id))
        });
        self.end_of_profile = false;
        if outputs.active
            && let Ok(Some(status)) = kernel.coupling_status(slave)
            && status.command == self.core.command()
            && status.started
        {
            let now_s = kernel.axis_time_s(slave).unwrap_or(0.0);
            self.tappets.evaluate(&status, now_s);
            self.end_of_profile = status.end_of_profile && (status.periodic || self.execute);
        }
        self.in_sync = outputs.active && outputs.reached;
        self.busy = outputs.busy;
        self.active = outputs.active;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
