//! What the runtime mirrors into an axis's `AXIS_REF` variable every cycle.

use crate::axis::{AxisState, Overrides};
use crate::kernel::CommandId;

/// A copy of an axis's observable values after a cycle. On a virtual axis the actual values
/// equal the set values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AxisSnapshot {
    /// The PLCopen state; [`AxisState::code`] gives the `SMC_AXIS_STATE` number.
    pub state: AxisState,
    /// Whether the power stage is on (`MC_Power.Status`).
    pub powered: bool,
    /// The set position in user units (wrapped into the period on a modulo axis).
    pub set_position: f64,
    /// The actual position; equal to the set position on a virtual axis.
    pub actual_position: f64,
    /// The set velocity in user units per second.
    pub set_velocity: f64,
    /// The actual velocity; equal to the set velocity on a virtual axis.
    pub actual_velocity: f64,
    /// The set acceleration in user units per second².
    pub set_acceleration: f64,
    /// Whether an axis error is pending (the axis is in ErrorStop).
    pub error: bool,
    /// The pending axis error id, 0 when there is none.
    pub axis_error_id: u16,
    /// Whether MC_Home or MC_SetPosition has given the axis a reference.
    pub is_homed: bool,
    /// The modulo period (`fPositionPeriod`), 0 for a linear axis.
    pub modulo_period: f64,
    /// The override factors in force.
    pub overrides: Overrides,
    /// The FB whose command controls the axis, such as `MC_MoveAbsolute`, if any.
    pub active_command: Option<&'static str>,
    /// The id of the command that controls the axis, if any.
    pub active_command_id: Option<CommandId>,
    /// The last commanded target position, which MC_MoveAdditive adds to.
    pub commanded_position: f64,
}
