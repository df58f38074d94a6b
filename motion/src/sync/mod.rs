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
//!
//! # How a runtime drives it
//!
//! When the image loads: add the axes, masters before their slaves
//! ([`crate::kernel::Kernel::add_axis`]), and register every cam with its tappet tracks
//! ([`crate::kernel::Kernel::add_cam`], which returns the [`CamId`] that `MC_CAM_REF` maps to).
//!
//! Every task cycle:
//! 1. Run the programs. Their FB calls (`crate::fb::CamTableSelect`, `CamIn`, `GearIn`, …) issue
//!    and follow commands through the kernel, as the single-axis FBs do. An MC_CamIn call also
//!    evaluates the tappets of its coupling for the master motion of the previous `advance`
//!    and shows `EndOfProfile`; read the tappet outputs from `CamIn::tappets` (or through
//!    `crate::fb::GetTappetValue` called after the MC_CamIn). SMC_CamRegister and
//!    MC_DigitalCamSwitch read the axis's set values at their call.
//! 2. Call [`crate::kernel::Kernel::advance_all`] with the task interval (or `advance` per axis
//!    in the order the axes were added). A slave's set point is computed from its master's values
//!    of the same cycle when the master was added first.
//!
//! Like `Done` of a single-axis FB, `InSync`, `EndOfProfile` and the tappet outputs therefore
//! appear at the FB call that follows the `advance` that produced them. A runtime that mirrors
//! couplings into an online view reads [`crate::kernel::Kernel::coupling_status`] after
//! `advance`.

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
