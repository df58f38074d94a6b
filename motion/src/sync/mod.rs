//! Synchronised motion: the maths of a slave coupled to a master through a cam (MC_CamIn), a
//! gear (MC_GearIn), a gear that meets a position (MC_GearInPos), and the phase shift of the
//! master seen by the slave (MC_Phasing).
//!
//! The kernel owns the state of each coupling inside the slave's running motion and calls the
//! `step` functions of this module once per cycle from `advance`, with the master's values of
//! that cycle. Everything here is plain copyable data: stepping a coupling never allocates.
//!
//! The master seen by a slave is the master's set position, unwrapped across the modulo period
//! (a master moves less than half its period per cycle), minus the phase shift of MC_Phasing.

mod cam_coupling;
mod cam_state;
mod gear_coupling;
mod gear_in_pos_state;
mod gear_state;
mod master;
mod phase;
mod selection;
mod status;

pub use cam_coupling::{CamCoupling, CamSlaveValues, StartMode};
pub use gear_coupling::{GearCoupling, GearInPosCoupling};
pub use phase::PhasingMode;
pub use selection::{CamId, CamSelection, CamTableId};
pub use status::{CouplingKind, CouplingStatus};

pub(crate) use cam_state::{CamState, start_values as cam_start_values};
pub(crate) use gear_in_pos_state::GearInPosState;
pub(crate) use gear_state::GearState;
pub(crate) use master::{MasterView, SeenMaster, SlaveSet, SlaveView, wrap_signed};
pub(crate) use phase::{PhaseRun, PhaseState};
