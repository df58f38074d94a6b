//! MC_ReadStatus.

use crate::axis::AxisState;
use crate::kernel::{AxisId, Kernel};

/// MC_ReadStatus: while `Enable` is TRUE, the axis state as one-hot flags (exactly one TRUE
/// while `Valid`; all FALSE otherwise).
#[derive(Clone, Debug, Default)]
pub struct ReadStatus {
    /// `Enable`: read while TRUE.
    pub enable: bool,
    /// `Valid`: the flags are valid.
    pub valid: bool,
    /// `Busy`: the instance is enabled.
    pub busy: bool,
    /// `Error`: the axis reference is invalid.
    pub error: bool,
    /// `ErrorID`: the [`crate::kernel::MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// `ErrorStop`.
    pub error_stop: bool,
    /// `Disabled`.
    pub disabled: bool,
    /// `Stopping`.
    pub stopping: bool,
    /// `Homing`.
    pub homing: bool,
    /// `Standstill`.
    pub standstill: bool,
    /// `DiscreteMotion`.
    pub discrete_motion: bool,
    /// `ContinuousMotion`.
    pub continuous_motion: bool,
    /// `SynchronizedMotion`.
    pub synchronized_motion: bool,
}

impl ReadStatus {
    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &Kernel, axis: AxisId) {
        let read = self.enable.then(|| kernel.state(axis));
        self.busy = self.enable;
        let state = match read {
            Some(Ok(state)) => Some(state),
            _ => None,
        };
        self.valid = state.is_some();
        let error = match read {
            Some(Err(error)) => Some(error),
            _ => None,
        };
        self.error = error.is_some();
        self.error_id = error.map_or(0, |error| error.id());
        self.error_stop = state == Some(AxisState::ErrorStop);
        self.disabled = state == Some(AxisState::PowerOff);
        self.stopping = state == Some(AxisState::Stopping);
        self.homing = state == Some(AxisState::Homing);
        self.standstill = state == Some(AxisState::Standstill);
        self.discrete_motion = state == Some(AxisState::DiscreteMotion);
        self.continuous_motion = state == Some(AxisState::ContinuousMotion);
        self.synchronized_motion = state == Some(AxisState::SynchronizedMotion);
    }
}
