//! A tappet track: the tappets that switch one BOOL, with the track's settings.

use super::TappetAction;

/// A tappet: a master position and what happens when the master passes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tappet {
    /// The master position, inside the cam's master range.
    pub position: f64,
    /// What happens when the master passes it increasing.
    pub on_positive: TappetAction,
    /// What happens when the master passes it decreasing.
    pub on_negative: TappetAction,
}

/// A track (CODESYS tappet group `iGroupID`): one BOOL output switched by its tappets.
#[derive(Clone, Debug, PartialEq)]
pub struct TappetTrack {
    /// The track ID the output is read with (`SMC_GetTappetValue.iID`).
    pub id: u16,
    /// The tappets on the track, in any order; passes in one cycle act in the order the master
    /// reaches them.
    pub tappets: Vec<Tappet>,
    /// Master distance, in master units, the master must move beyond a tappet before the
    /// opposite switch of that tappet takes effect (`TappetHysteresis`); 0 for none.
    pub hysteresis: f64,
    /// Dead-time compensation in seconds (`DeadTimeCompensation`): positive switches earlier,
    /// negative later, by this time at the current master velocity.
    pub dead_time_s: f64,
    /// The output before the first switch (`SMC_GetTappetValue.bInitValue`).
    pub initial_value: bool,
    /// Whether a restart of the coupling sets the output back to `initial_value`
    /// (`bSetInitValueAtReset`); otherwise the output keeps its value across restarts.
    pub reset_to_initial: bool,
}

impl TappetTrack {
    /// A track with the given tappets, no hysteresis, no dead-time compensation, initial
    /// value FALSE and reset to it on restart (the CODESYS defaults).
    pub fn new(id: u16, tappets: Vec<Tappet>) -> Self {
        Self {
            id,
            tappets,
            hysteresis: 0.0,
            dead_time_s: 0.0,
            initial_value: false,
            reset_to_initial: true,
        }
    }
}
