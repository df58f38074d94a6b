//! MC_GearIn.

use crate::fb::execute::{ExecuteCore, check_axis};
use crate::kernel::{AxisId, BufferMode, Kernel, MotionError, MotionRequest};
use crate::sync::GearCoupling;

/// MC_GearIn: the slave ramps from its velocity to `RatioNumerator / RatioDenominator` times
/// the master's velocity, the velocity difference limited by `Acceleration` (speeding up) or
/// `Deceleration` (slowing down) and `Jerk`; `InGear` turns TRUE when it is reached, and from
/// then on the slave moves the ratio times the master's displacement. Distance lost during the
/// ramp is not caught up. A rising edge while busy is ignored (CODESYS): to change the ratio,
/// end the coupling or issue MC_GearIn from another instance, which takes over without a jump.
#[derive(Clone, Debug)]
pub struct GearIn {
    /// `Execute`: a rising edge couples with the inputs of that call.
    pub execute: bool,
    /// `RatioNumerator`, signed; 1 by default.
    pub ratio_numerator: i32,
    /// `RatioDenominator`, 1 or more; 1 by default.
    pub ratio_denominator: u32,
    /// `Acceleration` of the ramp, in slave units per second².
    pub acceleration: f64,
    /// `Deceleration` of the ramp, in slave units per second².
    pub deceleration: f64,
    /// `Jerk` of the ramp; 0 uses the slave's jerk limit (none: trapezoid).
    pub jerk: f64,
    /// `BufferMode`.
    pub buffer_mode: BufferMode,
    /// `InGear`: the slave moves at the geared velocity.
    pub in_gear: bool,
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

impl Default for GearIn {
    fn default() -> Self {
        Self {
            execute: false,
            ratio_numerator: 1,
            ratio_denominator: 1,
            acceleration: 0.0,
            deceleration: 0.0,
            jerk: 0.0,
            buffer_mode: BufferMode::default(),
            in_gear: false,
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

impl GearIn {
    /// One call of the instance for `master` and `slave`.
    pub fn call(&mut self, kernel: &mut Kernel, master: AxisId, slave: AxisId) {
        let request = MotionRequest::Gear {
            master,
            coupling: GearCoupling {
                ratio_numerator: self.ratio_numerator,
                ratio_denominator: self.ratio_denominator,
                acceleration: self.acceleration,
                deceleration: self.deceleration,
                jerk: self.jerk,
            },
        };
        let buffer_mode = self.buffer_mode;
        let outputs = self.core.call(self.execute, kernel, |kernel| {
            check_axis(kernel, slave)?;
            kernel.issue(slave, request, buffer_mode).map(Some)
        });
        self.in_gear = outputs.active && outputs.reached;
        self.busy = outputs.busy;
        self.active = outputs.active;
        self.command_aborted = outputs.command_aborted();
        self.error = outputs.error().is_some();
        self.error_id = outputs.error_id();
        self.error_cause = outputs.error();
    }
}
