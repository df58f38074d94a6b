//! The motion kernel: the virtual axes of a runtime and the commands the motion FBs issue.
//!
//! # Cycle contract
//!
//! Each task cycle the runtime first runs the task's programs. Their FB calls issue commands
//! through the kernel; a command that is accepted changes the axis's state at once, in the same
//! call (MC_MoveVelocity puts the axis in ContinuousMotion before the call returns), and the
//! FB's outputs reflect the command status known at the call. Then the runtime calls
//! [`Kernel::advance`] for each axis of the task with the task's interval `dt_s` (or
//! [`Kernel::advance_all`]), which integrates the set values over that interval and finishes
//! commands. `Done`, `InVelocity` and the like therefore appear at the FB call of the next
//! cycle. Time only enters through `dt_s`; the kernel reads no clock, and `advance` does not
//! allocate.
//!
//! # Motion sources and synchronised motion
//!
//! What drives an axis is one value of the private `Source` enum held in the axis's running
//! motion (position move, velocity, MC_Halt, MC_Stop, error stop ramp, homing, coupling). A
//! coupled slave (MC_CamIn, MC_GearIn, MC_GearInPos) is issued through [`Kernel::issue`] as a
//! [`MotionRequest::Cam`], [`MotionRequest::Gear`] or [`MotionRequest::GearInPos`], so buffer
//! modes, command statuses, MC_Stop, ErrorStop and the FB output rules apply to it unchanged;
//! `install` puts the axis in SynchronizedMotion. A coupling starts at the first `advance`
//! after it took control (so a buffered coupling starts from the values it finds then): that
//! `advance` reads the master's set values and the slave's, and every later one computes the
//! slave's set point from the master's displacement in the cycle (see [`crate::sync`]). The
//! kernel advances axes in the order they were added, so a master added before its slave is
//! read with this cycle's values (a runtime should add masters first; otherwise the slave sees
//! the previous cycle's master). Cams are registered once with [`Kernel::add_cam`] and owned by
//! the kernel; a coupling refers to its cam by index, so the running motion stays a plain
//! copyable value and `advance` does not allocate. [`Kernel::decouple`] (MC_CamOut, MC_GearOut)
//! replaces the coupling with a velocity source at the slave's current velocity, already
//! reached, which is ContinuousMotion with no command in control. [`Kernel::phase`]
//! (MC_Phasing) runs a position profile of the phase shift inside the coupling. Overrides do not
//! act on a coupled slave. A buffered command does not wait for a coupling, which never ends by
//! itself: it takes over at once, as an aborting one would.

mod axis_planning;
mod axis_runtime;
mod cams;
pub mod command;
mod coupling;
mod coupling_checks;
pub mod error;
mod registry;
pub mod snapshot;
mod sync_api;
mod validation;

pub use command::{BufferMode, CommandId, CommandStatus, Dynamics, MotionRequest, PositionTarget};
pub use error::{AXIS_ERROR_SOFTWARE_LIMIT, MotionError};
pub use snapshot::AxisSnapshot;
pub use sync_api::Decoupling;

use crate::axis::{AxisConfig, AxisState, ConfigError, Overrides};
use axis_runtime::{AxisRuntime, Source, SyncInputs};
use cams::CamStore;
use registry::Registry;
use validation::{check_cycle, check_jerk, check_magnitude, check_position, validate_request};

/// The index of an axis in its kernel, as an `AXIS_REF` resolves to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct AxisId(pub usize);

/// The set of virtual axes of a runtime and the status of every command issued to them.
#[derive(Clone, Debug, Default)]
pub struct Kernel {
    axes: Vec<AxisRuntime>,
    registry: Registry,
    cams: CamStore,
}

impl Kernel {
    /// An empty kernel.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds an axis, powered off at position 0, and returns its id.
    pub fn add_axis(&mut self, config: AxisConfig) -> Result<AxisId, ConfigError> {
        config.validate()?;
        self.axes.push(AxisRuntime::new(config));
        Ok(AxisId(self.axes.len() - 1))
    }

    /// How many axes the kernel has.
    #[must_use]
    pub fn axis_count(&self) -> usize {
        self.axes.len()
    }

    fn axis(&self, axis: AxisId) -> Result<&AxisRuntime, MotionError> {
        self.axes
            .get(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))
    }

    fn axis_mut(&mut self, axis: AxisId) -> Result<&mut AxisRuntime, MotionError> {
        self.axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))
    }

    /// The configuration of an axis.
    pub fn config(&self, axis: AxisId) -> Result<AxisConfig, MotionError> {
        Ok(self.axis(axis)?.config)
    }

    /// The PLCopen state of an axis.
    pub fn state(&self, axis: AxisId) -> Result<AxisState, MotionError> {
        Ok(self.axis(axis)?.state)
    }

    /// The values the runtime mirrors into the axis's `AXIS_REF`.
    pub fn snapshot(&self, axis: AxisId) -> Result<AxisSnapshot, MotionError> {
        let runtime = self.axis(axis)?;
        Ok(AxisSnapshot {
            state: runtime.state,
            powered: runtime.powered,
            set_position: runtime.position,
            actual_position: runtime.position,
            set_velocity: runtime.velocity,
            actual_velocity: runtime.velocity,
            set_acceleration: runtime.acceleration,
            error: runtime.axis_error_id != 0,
            axis_error_id: runtime.axis_error_id,
            is_homed: runtime.homed,
            modulo_period: runtime.config.modulo_period.unwrap_or(0.0),
            overrides: runtime.overrides,
            active_command: runtime.running.map(|running| running.name),
            active_command_id: runtime.running.and_then(|running| running.id),
            commanded_position: runtime.commanded_position,
        })
    }

    /// The status of a command, `None` once the FB forgot it.
    #[must_use]
    pub fn command_status(&self, id: CommandId) -> Option<CommandStatus> {
        self.registry.get(id)
    }

    /// Drops a command's status; FBs call it after reading a final status.
    pub fn forget(&mut self, id: CommandId) {
        self.registry.forget(id);
    }

    /// How many command statuses the kernel holds (for tests of the registry's bound).
    #[must_use]
    pub fn recorded_commands(&self) -> usize {
        self.registry.len()
    }

    /// MC_Power: switches the power stage of an axis on or off and returns `Status`.
    /// Switching on takes a Disabled axis to Standstill (Note 5); switching off takes any state
    /// but ErrorStop to Disabled (Note 2), stops the axis at once and aborts its commands.
    pub fn power(&mut self, axis: AxisId, enable: bool) -> Result<bool, MotionError> {
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))?;
        if enable {
            runtime.powered = true;
            if runtime.state == AxisState::PowerOff {
                runtime.state = AxisState::Standstill;
            }
        } else if runtime.powered {
            runtime.powered = false;
            runtime.end_commands(CommandStatus::Aborted, registry);
            runtime.velocity = 0.0;
            runtime.acceleration = 0.0;
            if runtime.state != AxisState::ErrorStop {
                runtime.state = AxisState::PowerOff;
            }
            // A reset that waited for the error stop ramp finds the axis at rest now, and with
            // the power off it leads to Disabled (Note 3).
            if let Some(reset_id) = runtime.pending_reset.take() {
                runtime.reset();
                registry.set(reset_id, CommandStatus::Done);
            }
        }
        Ok(runtime.powered)
    }

    /// Refuses a motion command in a state that does not accept it (§1.2): the FB instance gets
    /// the error and the axis state stays as it is.
    fn check_accepts_motion(
        runtime: &AxisRuntime,
        command: &'static str,
    ) -> Result<(), MotionError> {
        match runtime.state {
            AxisState::PowerOff => Err(MotionError::NotPowered),
            AxisState::ErrorStop => Err(MotionError::AxisInErrorStop),
            AxisState::Stopping => Err(MotionError::AxisStopping),
            AxisState::Homing => Err(MotionError::IllegalState {
                command,
                state: runtime.state,
            }),
            AxisState::Standstill
            | AxisState::DiscreteMotion
            | AxisState::ContinuousMotion
            | AxisState::SynchronizedMotion => Ok(()),
        }
    }

    /// Issues a motion command (MC_MoveAbsolute, MC_MoveRelative, MC_MoveAdditive,
    /// MC_MoveVelocity, MC_Jog, MC_Halt). With [`BufferMode::Aborting`], or when nothing runs,
    /// it takes control at once and aborts what ran; with the other modes it waits until the
    /// running command has finished (the blending modes replan a running position move so that
    /// it passes its target at the blending velocity). The buffer holds one command. A refused
    /// command changes nothing.
    pub fn issue(
        &mut self,
        axis: AxisId,
        request: MotionRequest,
        buffer_mode: BufferMode,
    ) -> Result<CommandId, MotionError> {
        self.check_coupling(axis, request)?;
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))?;
        Self::check_accepts_motion(runtime, request.fb_name())?;
        validate_request(runtime.config, request)?;
        let waits = buffer_mode.waits()
            && runtime.running.is_some_and(|running| {
                matches!(
                    running.source,
                    Source::Position { .. } | Source::Velocity { .. } | Source::Halt { .. }
                )
            });
        if waits {
            if runtime.buffered.is_some() {
                return Err(MotionError::BufferFull);
            }
            let id = registry.issue(CommandStatus::Buffered);
            runtime.buffered = Some((id, request));
            runtime.blend_into(request, buffer_mode);
            return Ok(id);
        }
        let mut running = runtime.plan(request)?;
        let id = registry.issue(CommandStatus::Active { reached: false });
        running.id = Some(id);
        runtime.end_commands(CommandStatus::Aborted, registry);
        runtime.install(running);
        Ok(id)
    }

    /// ContinuousUpdate: applies changed inputs to a running or buffered command. Inputs
    /// that are refused end the command in Error (its FB shows the reason) and a moving axis
    /// brakes as MC_Halt would. A command that no longer runs is left alone.
    pub fn update(&mut self, id: CommandId, request: MotionRequest) {
        let Self { axes, registry, .. } = self;
        let Some(runtime) = axes.iter_mut().find(|runtime| {
            runtime
                .running
                .is_some_and(|running| running.id == Some(id))
                || runtime.buffered.is_some_and(|(buffered, _)| buffered == id)
        }) else {
            return;
        };
        let accepted = Self::check_accepts_motion(runtime, request.fb_name())
            .and_then(|()| validate_request(runtime.config, request));
        match accepted {
            Ok(()) => runtime.update(id, request, registry),
            Err(error) => {
                if runtime.buffered.is_some_and(|(buffered, _)| buffered == id) {
                    runtime.buffered = None;
                    registry.set(id, CommandStatus::Error(error));
                } else {
                    runtime.fail_running(error, registry);
                }
            }
        }
    }

    /// MC_Stop: aborts every command on the axis and brakes it with `deceleration` and `jerk`
    /// (0 = the axis's jerk limit); the axis stays in Stopping until the stop has reached rest
    /// and [`Kernel::release_stop`] was called (Note 6).
    pub fn stop(
        &mut self,
        axis: AxisId,
        deceleration: f64,
        jerk: f64,
    ) -> Result<CommandId, MotionError> {
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))?;
        match runtime.state {
            AxisState::PowerOff => return Err(MotionError::NotPowered),
            AxisState::ErrorStop => return Err(MotionError::AxisInErrorStop),
            _ => {}
        }
        let config = runtime.config;
        check_magnitude("Deceleration", deceleration, config.max_deceleration, false)?;
        check_jerk(jerk, config.max_jerk)?;
        let mut running = runtime.plan_stop(deceleration, jerk);
        let id = registry.issue(CommandStatus::Active { reached: false });
        running.id = Some(id);
        runtime.end_commands(CommandStatus::Aborted, registry);
        runtime.install(running);
        Ok(id)
    }

    /// MC_Stop.Execute went FALSE: the axis leaves Stopping as soon as it is at rest.
    pub fn release_stop(&mut self, id: CommandId) {
        let Self { axes, registry, .. } = self;
        for runtime in axes.iter_mut() {
            let Some(running) = &mut runtime.running else {
                continue;
            };
            if running.id != Some(id) {
                continue;
            }
            if let Source::Stop { held } = &mut running.source {
                *held = false;
                if running.reached {
                    runtime.running = None;
                    runtime.state = AxisState::Standstill;
                    registry.set(id, CommandStatus::Done);
                }
            }
            return;
        }
    }

    /// MC_Home on a virtual axis: from Standstill the axis goes to Homing at once and gets the
    /// reference `position` on the next cycle, which finishes the command.
    pub fn home(&mut self, axis: AxisId, position: f64) -> Result<CommandId, MotionError> {
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))?;
        match runtime.state {
            AxisState::Standstill => {}
            AxisState::PowerOff => return Err(MotionError::NotPowered),
            AxisState::ErrorStop => return Err(MotionError::AxisInErrorStop),
            AxisState::Stopping => return Err(MotionError::AxisStopping),
            state => {
                return Err(MotionError::IllegalState {
                    command: "MC_Home",
                    state,
                });
            }
        }
        check_position(runtime.config, "Position", position)?;
        let mut running = runtime.plan_home(position);
        let id = registry.issue(CommandStatus::Active { reached: false });
        running.id = Some(id);
        runtime.install(running);
        Ok(id)
    }

    /// MC_Reset: in ErrorStop clears the axis error and goes to Standstill (power on) or
    /// Disabled (power off), once the error stop ramp has reached rest; in any other state it
    /// finishes at once without changing anything.
    pub fn reset(&mut self, axis: AxisId) -> Result<CommandId, MotionError> {
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))?;
        if runtime.state != AxisState::ErrorStop {
            return Ok(registry.issue(CommandStatus::Done));
        }
        if runtime.running.is_some() {
            if let Some(previous) = runtime.pending_reset.take() {
                registry.set(previous, CommandStatus::Aborted);
            }
            let id = registry.issue(CommandStatus::Active { reached: false });
            runtime.pending_reset = Some(id);
            return Ok(id);
        }
        runtime.reset();
        Ok(registry.issue(CommandStatus::Done))
    }

    /// MC_SetPosition: gives the set position the value `position` (or shifts it by `position`
    /// when `relative`) at once, in Standstill or Disabled; the move that ended last is taken as
    /// reaching the new position, so MC_MoveAdditive adds to it.
    pub fn set_position(
        &mut self,
        axis: AxisId,
        position: f64,
        relative: bool,
    ) -> Result<(), MotionError> {
        let runtime = self.axis_mut(axis)?;
        match runtime.state {
            AxisState::Standstill | AxisState::PowerOff => {}
            state => {
                return Err(MotionError::IllegalState {
                    command: "MC_SetPosition",
                    state,
                });
            }
        }
        let new_position = if relative {
            runtime.position + position
        } else {
            position
        };
        check_position(runtime.config, "Position", new_position)?;
        runtime.position = runtime.config.wrap(new_position);
        runtime.commanded_position = runtime.position;
        runtime.homed = true;
        Ok(())
    }

    /// MC_SetOverride: sets the override factors and replans the running motion with them.
    /// `velocity` must lie in 0.0 ..= 1.0, `acceleration` and `jerk` in 0.0 (excluded) ..= 1.0;
    /// refused factors change nothing.
    pub fn set_override(&mut self, axis: AxisId, overrides: Overrides) -> Result<(), MotionError> {
        let runtime = self.axis_mut(axis)?;
        let checks = [
            ("VelFactor", overrides.velocity, true),
            ("AccFactor", overrides.acceleration, false),
            ("JerkFactor", overrides.jerk, false),
        ];
        for (input, value, zero_allowed) in checks {
            let low_ok = if zero_allowed {
                value >= 0.0
            } else {
                value > 0.0
            };
            if !(value.is_finite() && low_ok && value <= 1.0) {
                return Err(MotionError::InvalidParameter {
                    input,
                    value,
                    reason: if zero_allowed {
                        "an override factor lies in 0.0 .. 1.0"
                    } else {
                        "an override factor lies above 0.0, up to 1.0"
                    },
                });
            }
        }
        if runtime.overrides != overrides {
            runtime.overrides = overrides;
            runtime.replan();
        }
        Ok(())
    }

    /// Raises an axis error, as a drive or limit fault would: every command on the axis ends
    /// in Error and the axis brakes to rest in ErrorStop (Note 1). `axis_error_id` must not be 0.
    pub fn inject_error(&mut self, axis: AxisId, axis_error_id: u16) -> Result<(), MotionError> {
        let Self { axes, registry, .. } = self;
        let runtime = axes
            .get_mut(axis.0)
            .ok_or(MotionError::UnknownAxis(axis.0))?;
        if axis_error_id == 0 {
            return Err(MotionError::InvalidParameter {
                input: "axis_error_id",
                value: 0.0,
                reason: "0 means no error; an axis error id is 1 or more",
            });
        }
        runtime.raise_error(axis_error_id, registry);
        Ok(())
    }

    /// Integrates one cycle of `dt_s` seconds on one axis.
    pub fn advance(&mut self, axis: AxisId, dt_s: f64) -> Result<(), MotionError> {
        check_cycle(dt_s)?;
        if axis.0 >= self.axes.len() {
            return Err(MotionError::UnknownAxis(axis.0));
        }
        self.advance_index(axis.0, dt_s);
        Ok(())
    }

    /// Integrates one cycle of `dt_s` seconds on every axis, in the order they were added.
    pub fn advance_all(&mut self, dt_s: f64) -> Result<(), MotionError> {
        check_cycle(dt_s)?;
        for index in 0..self.axes.len() {
            self.advance_index(index, dt_s);
        }
        Ok(())
    }

    /// Integrates one cycle on the axis at `index`, giving a coupled slave its master's values.
    fn advance_index(&mut self, index: usize, dt_s: f64) {
        let Self {
            axes,
            registry,
            cams,
        } = self;
        let master = axes
            .get(index)
            .and_then(AxisRuntime::coupled_master)
            .and_then(|master| axes.get(master))
            .map(AxisRuntime::master_view);
        if let Some(runtime) = axes.get_mut(index) {
            runtime.advance(dt_s, registry, SyncInputs { master, cams });
        }
    }
}
