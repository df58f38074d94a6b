//! A switch of a track output that happened in a cycle.

use super::PassDirection;

/// Why a track output switched.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SwitchCause {
    /// The master passed a tappet.
    Pass {
        /// The tappet's index in its track's `tappets`.
        tappet_index: usize,
        /// The direction of the pass.
        direction: PassDirection,
    },
    /// The time of a timed switch ran out.
    TimeElapsed,
}

/// One switch of a track output in the current cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TappetSwitch {
    /// The track whose output switched.
    pub track_id: u16,
    /// What made it switch.
    pub cause: SwitchCause,
    /// The output after the switch.
    pub output: bool,
}
