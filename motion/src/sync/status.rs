//! What a runtime or an FB reads about a running coupling.

use crate::kernel::CommandId;

/// Which FB made a coupling.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CouplingKind {
    /// MC_CamIn.
    Cam,
    /// MC_GearIn.
    Gear,
    /// MC_GearInPos.
    GearInPos,
}

/// The state of the coupling that drives a slave, as of its last `advance`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CouplingStatus {
    /// The command of the FB that made the coupling.
    pub command: Option<CommandId>,
    /// The kind of coupling.
    pub kind: CouplingKind,
    /// Whether the first `advance` has computed the coupling yet.
    pub started: bool,
    /// `InSync` / `InGear`: the slave follows the coupling exactly (ramp-in done, gear
    /// velocity reached, sync position met).
    pub in_sync: bool,
    /// MC_GearInPos `StartSync`: the master has passed the start of the synchronisation.
    pub start_sync: bool,
    /// MC_CamIn `EndOfProfile`: for a periodic cam TRUE only after the `advance` in which the
    /// cam master coordinate wrapped (either way); for a non-periodic cam TRUE from the
    /// `advance` that reached the end of the profile on.
    pub end_of_profile: bool,
    /// Whether the cam is periodic (gears count as periodic: they have no profile end).
    pub periodic: bool,
    /// The cam master coordinate X = MasterScaling·M + MasterOffset, in the cam's master range.
    pub cam_master: f64,
    /// How many times the cam master coordinate wrapped since the start, forward minus
    /// backward; a change of one between two readings is a wrap the tappets continue across.
    pub period_index: i64,
    /// The velocity of the cam master coordinate in cam units per second.
    pub cam_master_velocity: f64,
    /// The phase shift of MC_Phasing in force, in master units (positive: the slave lags).
    pub phase_shift: f64,
    /// The cam of a cam coupling, so a runtime can show the coupling on that cam.
    pub cam: Option<super::CamId>,
}
