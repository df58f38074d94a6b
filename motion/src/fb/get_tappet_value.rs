//! SMC_GetTappetValue.

use crate::fb::tappet_data::TappetData;

/// SMC_GetTappetValue: the output of track `iID` of an MC_CamIn's tappets.
///
/// At its first call for the tappets of a coupling (and again when MC_CamIn starts with
/// another cam), the track's output is set to `bInitValue` and the track is told whether a
/// restart of MC_CamIn sets it back (`bSetInitValueAtReset`); afterwards the output follows the
/// tappets. A track the cam does not have reads FALSE.
#[derive(Clone, Debug, Default)]
pub struct GetTappetValue {
    /// `iID`: the track ID.
    pub id: u16,
    /// `bInitValue`: the output before the first switch.
    pub init_value: bool,
    /// `bSetInitValueAtReset`: a restart of MC_CamIn sets the output back to `bInitValue`;
    /// otherwise it keeps its value across restarts.
    pub set_init_value_at_reset: bool,
    /// `bTappet`: the track's output.
    pub tappet: bool,
    /// The tappet generation this instance initialised, 0 before its first call.
    initialised: u64,
}

impl GetTappetValue {
    /// One call of the instance on `tappets` (`MC_CamIn.Tappets`).
    pub fn call(&mut self, tappets: &mut TappetData) {
        let generation = tappets.generation();
        if generation != self.initialised
            && let Some(evaluator) = tappets.evaluator_mut()
        {
            evaluator.set_initial_value(self.id, self.init_value, self.set_init_value_at_reset);
            self.initialised = generation;
        }
        self.tappet = tappets.output(self.id).unwrap_or(false);
    }
}
