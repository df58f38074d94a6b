//! The motion source of a coupled slave: which master it follows, through what, and the phase
//! shift of the master it sees.

use crate::kernel::CommandId;
use crate::kernel::MotionError;
use crate::kernel::cams::CamStore;
use crate::sync::{
    CamCoupling, CamState, CouplingKind, CouplingStatus, GearCoupling, GearInPosCoupling,
    GearInPosState, GearState, MasterView, PhaseState, SeenMaster, SlaveSet, SlaveView,
};

/// What a coupling does, before and after its first cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum CouplingMode {
    /// Issued (or started from the buffer) but not computed yet: the first `advance` reads the
    /// master and the slave and starts it, so a buffered coupling starts from the values it
    /// finds then.
    PendingCam(CamCoupling),
    /// MC_GearIn before its first cycle.
    PendingGear(GearCoupling),
    /// MC_GearInPos before its first cycle.
    PendingGearInPos(GearInPosCoupling),
    /// A running cam.
    Cam(CamState),
    /// A running gear.
    Gear(GearState),
    /// A running MC_GearInPos.
    GearInPos(GearInPosState),
}

/// The result of one cycle of a coupling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CouplingStep {
    /// The slave's new set values (position not wrapped yet).
    pub(crate) set: SlaveSet,
    /// Whether the slave is in sync after the cycle.
    pub(crate) in_sync: bool,
    /// An MC_Phasing command that finished in the cycle.
    pub(crate) phase_done: Option<CommandId>,
}

/// A slave coupled to a master.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Coupling {
    /// The master axis's index.
    pub(crate) master: usize,
    /// What the coupling does.
    pub(crate) mode: CouplingMode,
    /// The master's position at the last cycle, to measure its displacement.
    last_master: f64,
    /// The phase shift at the last cycle, to measure its change.
    last_shift: f64,
    /// The phase shift of MC_Phasing.
    pub(crate) phase: PhaseState,
}

impl Coupling {
    /// A coupling to `master` that starts at the next cycle.
    pub(crate) fn pending(master: usize, mode: CouplingMode) -> Self {
        Self {
            master,
            mode,
            last_master: 0.0,
            last_shift: 0.0,
            phase: PhaseState::default(),
        }
    }

    /// The FB behind the coupling.
    pub(crate) fn kind(&self) -> CouplingKind {
        match self.mode {
            CouplingMode::PendingCam(_) | CouplingMode::Cam(_) => CouplingKind::Cam,
            CouplingMode::PendingGear(_) | CouplingMode::Gear(_) => CouplingKind::Gear,
            CouplingMode::PendingGearInPos(_) | CouplingMode::GearInPos(_) => {
                CouplingKind::GearInPos
            }
        }
    }

    /// Whether the slave follows the coupling exactly.
    pub(crate) fn in_sync(&self) -> bool {
        match &self.mode {
            CouplingMode::Cam(state) => state.in_sync(),
            CouplingMode::Gear(state) => state.in_gear,
            CouplingMode::GearInPos(state) => state.in_sync(),
            _ => false,
        }
    }

    /// The status a runtime or an FB reads.
    pub(crate) fn status(&self, command: Option<CommandId>) -> CouplingStatus {
        let mut status = CouplingStatus {
            command,
            kind: self.kind(),
            started: !matches!(
                self.mode,
                CouplingMode::PendingCam(_)
                    | CouplingMode::PendingGear(_)
                    | CouplingMode::PendingGearInPos(_)
            ),
            in_sync: self.in_sync(),
            start_sync: false,
            end_of_profile: false,
            periodic: true,
            cam_master: 0.0,
            period_index: 0,
            cam_master_velocity: 0.0,
            phase_shift: self.phase.shift,
            cam: None,
        };
        match &self.mode {
            CouplingMode::Cam(state) => {
                status.periodic = state.selection.periodic;
                status.end_of_profile = if state.selection.periodic {
                    state.wrapped
                } else {
                    state.ended
                };
                status.cam_master = state.cam_master;
                status.cam = Some(state.selection.cam);
                status.period_index = state.period_index;
                status.cam_master_velocity = if state.ended {
                    0.0
                } else {
                    state.inputs.master_scaling * state.seen_velocity
                };
            }
            CouplingMode::GearInPos(state) => status.start_sync = state.start_sync(),
            _ => {}
        }
        status
    }

    /// One cycle of `dt_s` with the master's values of this cycle.
    pub(crate) fn step(
        &mut self,
        dt_s: f64,
        master: &MasterView,
        slave: &SlaveView,
        cams: &CamStore,
    ) -> Result<CouplingStep, MotionError> {
        let phase_done = self.phase.advance(dt_s);
        let set = match self.mode {
            CouplingMode::PendingCam(inputs) => {
                let selection = cams.selection(inputs.cam_table)?;
                let cam = cams.cam(selection.cam)?;
                let (mut state, set) =
                    CamState::start(inputs, selection, cam.curve.as_ref(), master, slave)?;
                state.seen_velocity = master.velocity;
                self.mode = CouplingMode::Cam(state);
                self.begin(master);
                set
            }
            CouplingMode::PendingGear(inputs) => {
                self.mode = CouplingMode::Gear(GearState::start(inputs, master.velocity, slave));
                self.begin(master);
                // The master moved in this cycle before the coupling saw it; at constant
                // velocity that is velocity·dt, which the first step takes as its motion.
                self.step_running(dt_s, estimated_first(master, dt_s), slave, cams)?
            }
            CouplingMode::PendingGearInPos(inputs) => {
                let state = GearInPosState::start(inputs, master).ok_or(
                    MotionError::InvalidParameter {
                        input: "MasterSyncPosition",
                        value: inputs.master_sync_position,
                        reason: "the linear master has already passed MasterSyncPosition − MasterStartDistance",
                    },
                )?;
                self.mode = CouplingMode::GearInPos(state);
                self.begin(master);
                // The distance to the start point was measured from the master's position of
                // this cycle, so the first step has no master motion left to take.
                let seen = SeenMaster {
                    displacement: 0.0,
                    ..estimated_first(master, dt_s)
                };
                self.step_running(dt_s, seen, slave, cams)?
            }
            _ => {
                let displacement = master.displacement_from(self.last_master);
                self.last_master = master.position;
                let shift_change = self.phase.shift - self.last_shift;
                self.last_shift = self.phase.shift;
                let seen = SeenMaster {
                    displacement: displacement - shift_change,
                    velocity: master.velocity - self.phase.velocity,
                    acceleration: master.acceleration - self.phase.acceleration,
                };
                self.step_running(dt_s, seen, slave, cams)?
            }
        };
        Ok(CouplingStep {
            set,
            in_sync: self.in_sync(),
            phase_done,
        })
    }

    /// Takes the master's position as the reference of the next cycle's displacement.
    fn begin(&mut self, master: &MasterView) {
        self.last_master = master.position;
        self.last_shift = self.phase.shift;
    }

    /// One cycle of a started coupling.
    fn step_running(
        &mut self,
        dt_s: f64,
        seen: SeenMaster,
        slave: &SlaveView,
        cams: &CamStore,
    ) -> Result<SlaveSet, MotionError> {
        Ok(match &mut self.mode {
            CouplingMode::Cam(state) => {
                let cam = cams.cam(state.selection.cam)?;
                state.seen_velocity = seen.velocity;
                state.step(cam.curve.as_ref(), seen, dt_s)
            }
            CouplingMode::Gear(state) => state.step(slave.position, seen, dt_s),
            CouplingMode::GearInPos(state) => state.step(slave, seen, dt_s),
            CouplingMode::PendingCam(_)
            | CouplingMode::PendingGear(_)
            | CouplingMode::PendingGearInPos(_) => SlaveSet {
                position: slave.position,
                velocity: slave.velocity,
                acceleration: 0.0,
            },
        })
    }
}

/// The master's motion in the cycle a gear starts, taken as its velocity times the cycle.
fn estimated_first(master: &MasterView, dt_s: f64) -> SeenMaster {
    SeenMaster {
        displacement: master.velocity * dt_s,
        velocity: master.velocity,
        acceleration: master.acceleration,
    }
}
