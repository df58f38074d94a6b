//! The kernel's synchronised-motion services: registering cams, MC_CamTableSelect,
//! SMC_GetCamSlaveSetPosition, decoupling, MC_Phasing and what FBs read about a coupling.

use std::sync::Arc;

use crate::axis::{Profile, ProfileLimits};
use crate::curve::CamCurve;
use crate::kernel::axis_runtime::{Running, Source};
use crate::kernel::cams::StoredCam;
use crate::kernel::coupling_checks::{check_finite, check_scaling};
use crate::kernel::validation::check_magnitude;
use crate::kernel::{AxisId, CommandId, CommandStatus, Dynamics, Kernel, MotionError};
use crate::sync::{
    CamCoupling, CamId, CamSelection, CamSlaveValues, CamTableId, CouplingKind, CouplingStatus,
    MasterView, PhaseRun, PhasingMode,
};
use crate::tappet::{TappetError, TappetEvaluator, TappetTrack};

/// Which couplings a decoupling FB ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decoupling {
    /// MC_CamOut ends MC_CamIn.
    CamOut,
    /// MC_GearOut ends MC_GearIn and MC_GearInPos.
    GearOut,
}

impl Decoupling {
    fn fb_name(self) -> &'static str {
        match self {
            Self::CamOut => "MC_CamOut",
            Self::GearOut => "MC_GearOut",
        }
    }

    fn ends(self, kind: CouplingKind) -> bool {
        match self {
            Self::CamOut => kind == CouplingKind::Cam,
            Self::GearOut => matches!(kind, CouplingKind::Gear | CouplingKind::GearInPos),
        }
    }
}

impl Kernel {
    /// Registers a cam with its tappet tracks (when the image loads) and returns its id. The
    /// kernel owns the curve; couplings refer to it by id, so `advance` never copies it.
    ///
    /// Fails when the master range is not finite and increasing, or a tappet track is invalid.
    pub fn add_cam(
        &mut self,
        curve: Box<dyn CamCurve + Send + Sync>,
        tracks: Vec<TappetTrack>,
    ) -> Result<CamId, TappetError> {
        let (start, end) = curve.master_range();
        // The evaluator validates the range and every track exactly as it will run them.
        TappetEvaluator::new(start, end, true, tracks.clone())?;
        self.cams.cams.push(StoredCam {
            curve: Arc::from(curve),
            tracks,
        });
        Ok(CamId(self.cams.cams.len() - 1))
    }

    /// The curve of cam `id`.
    pub fn cam(&self, id: CamId) -> Result<&(dyn CamCurve + Send + Sync), MotionError> {
        Ok(self.cams.cam(id)?.curve.as_ref())
    }

    /// The tappet tracks of cam `id`.
    pub fn cam_tracks(&self, id: CamId) -> Result<&[TappetTrack], MotionError> {
        Ok(&self.cams.cam(id)?.tracks)
    }

    /// MC_CamTableSelect: selects `selection.cam` for its master and slave and returns the
    /// `CamTableID`. Passing the id an instance got before (`previous`) refreshes that
    /// selection instead of making a new one, so re-executing an instance does not grow the
    /// kernel. Couplings already running keep the selection they started with.
    pub fn select_cam(
        &mut self,
        selection: CamSelection,
        previous: Option<CamTableId>,
    ) -> Result<CamTableId, MotionError> {
        self.axis(selection.master)?;
        self.axis(selection.slave)?;
        if selection.master == selection.slave {
            return Err(MotionError::MasterIsSlave);
        }
        self.cams.cam(selection.cam)?;
        Ok(self.cams.select(selection, previous))
    }

    /// The selection behind a `CamTableID`.
    pub fn cam_selection(&self, id: CamTableId) -> Result<CamSelection, MotionError> {
        self.cams.selection(id)
    }

    /// The values a slave reads from `axis` as its master.
    pub(crate) fn master_view(&self, axis: AxisId) -> Result<MasterView, MotionError> {
        Ok(self.axis(axis)?.master_view())
    }

    /// The sum of the cycle intervals `axis` was advanced by: the time base of tappets and cam
    /// switches on it.
    pub fn axis_time_s(&self, axis: AxisId) -> Result<f64, MotionError> {
        Ok(self.axis(axis)?.time_s)
    }

    /// The coupling that drives `slave`, if one does.
    pub fn coupling_status(&self, slave: AxisId) -> Result<Option<CouplingStatus>, MotionError> {
        let runtime = self.axis(slave)?;
        Ok(match runtime.running {
            Some(Running {
                id,
                source: Source::Coupled(coupling),
                ..
            }) => Some(coupling.status(id)),
            _ => None,
        })
    }

    /// SMC_GetCamSlaveSetPosition: the slave set values MC_CamIn would command first with
    /// `coupling` for the master's and the slave's current values (the MC_CamIn formula,
    /// without ramp-in). Nothing moves.
    pub fn cam_slave_values(
        &self,
        master: AxisId,
        slave: AxisId,
        coupling: &CamCoupling,
    ) -> Result<CamSlaveValues, MotionError> {
        let selection = self.cams.selection(coupling.cam_table)?;
        if selection.master != master || selection.slave != slave {
            return Err(MotionError::UnknownCamTable(coupling.cam_table.0));
        }
        check_scaling("MasterScaling", coupling.master_scaling)?;
        check_scaling("SlaveScaling", coupling.slave_scaling)?;
        check_finite("MasterOffset", coupling.master_offset)?;
        check_finite("SlaveOffset", coupling.slave_offset)?;
        let curve = self.cams.cam(selection.cam)?.curve.as_ref();
        let master_view = self.master_view(master)?;
        let slave_position = self.axis(slave)?.position;
        let set = crate::sync::cam_start_values(
            curve,
            coupling,
            &selection,
            &master_view,
            slave_position,
        )?;
        Ok(CamSlaveValues {
            position: set.position,
            velocity: set.velocity,
            acceleration: set.acceleration,
        })
    }

    /// MC_CamOut / MC_GearOut: ends the coupling that drives `slave`; the slave keeps its
    /// velocity in ContinuousMotion, with no command controlling it. The coupling's command
    /// ends as Done and a phase change under way as Aborted.
    pub fn decouple(&mut self, slave: AxisId, decoupling: Decoupling) -> Result<(), MotionError> {
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(slave.0)
            .ok_or(MotionError::UnknownAxis(slave.0))?;
        let not_coupled = MotionError::NotCoupled {
            command: decoupling.fb_name(),
        };
        let Some(running) = runtime.running else {
            return Err(not_coupled);
        };
        let Source::Coupled(coupling) = running.source else {
            return Err(not_coupled);
        };
        if !decoupling.ends(coupling.kind()) {
            return Err(not_coupled);
        }
        if let Some(id) = running.id {
            registry.set(id, CommandStatus::Done);
        }
        if let Some(run) = coupling.phase.run {
            registry.set(run.id, CommandStatus::Aborted);
        }
        let velocity = runtime.velocity;
        let config = runtime.config;
        let dynamics = Dynamics {
            velocity: velocity.abs(),
            acceleration: config.max_acceleration,
            deceleration: config.max_deceleration,
            jerk: 0.0,
        };
        let limits = ProfileLimits {
            velocity: config.max_velocity.max(velocity.abs()),
            acceleration: config.max_acceleration,
            deceleration: config.max_deceleration,
            jerk: config.max_jerk,
            recovery_jerk: config.max_jerk,
        };
        let mut free = Running::new(
            decoupling.fb_name(),
            Source::Velocity { velocity, dynamics },
            Profile::to_velocity(velocity, velocity, 0.0, limits),
            runtime.position,
        );
        free.reached = true;
        runtime.acceleration = 0.0;
        runtime.running = None;
        runtime.install(free);
        Ok(())
    }

    /// MC_PhasingAbsolute / MC_PhasingRelative: changes the phase shift of the master that
    /// `slave` sees (positive: the slave lags) with a position profile of the shift within
    /// `dynamics`. The master's values do not change. A phase change under way is aborted.
    pub fn phase(
        &mut self,
        master: AxisId,
        slave: AxisId,
        mode: PhasingMode,
        phase_shift: f64,
        dynamics: Dynamics,
    ) -> Result<CommandId, MotionError> {
        self.axis(master)?;
        check_finite("PhaseShift", phase_shift)?;
        for (input, value) in [
            ("Velocity", dynamics.velocity),
            ("Acceleration", dynamics.acceleration),
            ("Deceleration", dynamics.deceleration),
        ] {
            check_magnitude(input, value, f64::INFINITY, false)?;
        }
        crate::kernel::validation::check_jerk(dynamics.jerk, 0.0)?;
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(slave.0)
            .ok_or(MotionError::UnknownAxis(slave.0))?;
        let not_coupled = MotionError::NotCoupled {
            command: "MC_Phasing",
        };
        let Some(running) = &mut runtime.running else {
            return Err(not_coupled);
        };
        let Source::Coupled(coupling) = &mut running.source else {
            return Err(not_coupled);
        };
        if coupling.master != master.0 {
            return Err(not_coupled);
        }
        let phase = &mut coupling.phase;
        let target = match mode {
            PhasingMode::Absolute => phase_shift,
            PhasingMode::Relative => phase.shift + phase_shift,
        };
        let limits = ProfileLimits {
            velocity: dynamics.velocity,
            acceleration: dynamics.acceleration,
            deceleration: dynamics.deceleration,
            jerk: dynamics.jerk,
            recovery_jerk: dynamics.jerk,
        };
        if let Some(previous) = phase.run.take() {
            registry.set(previous.id, CommandStatus::Aborted);
        }
        let id = registry.issue(CommandStatus::Active { reached: false });
        phase.run = Some(PhaseRun {
            id,
            origin: phase.shift,
            profile: Profile::to_position(
                target - phase.shift,
                phase.velocity,
                phase.acceleration,
                limits,
            ),
            elapsed_s: 0.0,
        });
        Ok(id)
    }
}
