//! One axis inside the kernel: its set values, its PLCopen state and the motion source that
//! drives it.

use crate::axis::{AxisConfig, AxisState, Overrides, Profile};
use crate::kernel::cams::CamStore;
use crate::kernel::coupling::Coupling;
use crate::kernel::registry::Registry;
use crate::kernel::{CommandId, CommandStatus, Dynamics, MotionError, MotionRequest};
use crate::sync::{MasterView, SlaveView};

/// What `advance` needs besides the axis itself: the master's values of this cycle for a
/// coupled slave, and the kernel's cams.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SyncInputs<'a> {
    /// The master of a coupled slave, `None` otherwise.
    pub(crate) master: Option<MasterView>,
    /// The cams the kernel owns.
    pub(crate) cams: &'a CamStore,
}

/// What produces the set values of an axis while it moves. Every kind of motion is one variant;
/// synchronised motion (a slave following a master through a cam or a gear) is added as one more
/// variant whose set point the kernel computes from the master's snapshot each cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
#[allow(
    clippy::large_enum_variant,
    reason = "the running motion stays a plain copyable value so that installing and advancing \
              it never allocates; a boxed coupling would allocate and lose `Copy`"
)]
pub(crate) enum Source {
    /// Move to `target` (wrapped) and come to rest.
    Position {
        /// The absolute target, wrapped into the period on a modulo axis.
        target: f64,
        /// The dynamics, kept to replan when the overrides change.
        dynamics: Dynamics,
    },
    /// Reach the signed `velocity` and keep it.
    Velocity {
        /// The signed commanded velocity before overrides.
        velocity: f64,
        /// The dynamics, kept to replan when the overrides change.
        dynamics: Dynamics,
    },
    /// MC_Halt: brake to rest.
    Halt {
        /// The dynamics, kept to replan when the overrides change.
        dynamics: Dynamics,
    },
    /// MC_Stop: brake to rest and hold the lock while `held`.
    Stop {
        /// Whether MC_Stop.Execute is still TRUE.
        held: bool,
    },
    /// The ramp down after an axis error.
    ErrorRamp,
    /// MC_Home on a virtual axis: the position is set on the next cycle.
    Home {
        /// The position the reference gets.
        position: f64,
    },
    /// A slave following a master (MC_CamIn, MC_GearIn, MC_GearInPos).
    Coupled(Coupling),
}

/// The motion that controls an axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Running {
    /// The command behind it; the error ramp has none.
    pub(crate) id: Option<CommandId>,
    /// The FB name shown as the axis's active command.
    pub(crate) name: &'static str,
    pub(crate) source: Source,
    pub(crate) profile: Profile,
    /// The set position when the profile started; positions are `origin + displacement`.
    pub(crate) origin: f64,
    /// The displacement a position move has to cover from `origin` to its target.
    pub(crate) distance: f64,
    pub(crate) elapsed_s: f64,
    /// The displacement sampled at the last cycle.
    pub(crate) displacement: f64,
    /// Whether a velocity command has reached its velocity, or MC_Stop has reached rest.
    pub(crate) reached: bool,
    /// Whether a position move is held at rest by a velocity override of 0.
    pub(crate) paused: bool,
    /// The speed a position move passes its target with, for a blending successor; 0 to stop.
    pub(crate) end_speed: f64,
    /// The displacement a position move covered under its earlier profiles (before a replan).
    pub(crate) travelled_before: f64,
    /// The request the motion came from, for ContinuousUpdate.
    pub(crate) request: Option<MotionRequest>,
}

/// An axis with its set values and what controls it.
#[derive(Clone, Debug)]
pub(crate) struct AxisRuntime {
    pub(crate) config: AxisConfig,
    pub(crate) state: AxisState,
    pub(crate) powered: bool,
    pub(crate) axis_error_id: u16,
    pub(crate) homed: bool,
    pub(crate) position: f64,
    pub(crate) velocity: f64,
    pub(crate) acceleration: f64,
    pub(crate) commanded_position: f64,
    pub(crate) overrides: Overrides,
    pub(crate) running: Option<Running>,
    pub(crate) buffered: Option<(CommandId, MotionRequest)>,
    pub(crate) pending_reset: Option<CommandId>,
    /// The sum of the cycle intervals the axis was advanced by, the time base of its tappets
    /// and cam switches.
    pub(crate) time_s: f64,
}

impl Running {
    pub(crate) fn new(name: &'static str, source: Source, profile: Profile, origin: f64) -> Self {
        Self {
            id: None,
            name,
            source,
            profile,
            origin,
            distance: 0.0,
            elapsed_s: 0.0,
            displacement: 0.0,
            reached: false,
            paused: false,
            end_speed: 0.0,
            travelled_before: 0.0,
            request: None,
        }
    }
}

impl AxisRuntime {
    pub(crate) fn new(config: AxisConfig) -> Self {
        Self {
            config,
            state: AxisState::PowerOff,
            powered: false,
            axis_error_id: 0,
            homed: false,
            position: 0.0,
            velocity: 0.0,
            acceleration: 0.0,
            commanded_position: 0.0,
            overrides: Overrides::default(),
            running: None,
            buffered: None,
            pending_reset: None,
            time_s: 0.0,
        }
    }

    /// Ends the running and the buffered command with `status`, as when another command takes
    /// over or the power goes off.
    pub(crate) fn end_commands(&mut self, status: CommandStatus, registry: &mut Registry) {
        if let Some(running) = self.running.take() {
            if let Some(id) = running.id {
                registry.set(id, status);
            }
            end_phasing(&running, status, registry);
        }
        if let Some((id, _)) = self.buffered.take() {
            registry.set(id, status);
        }
    }

    /// The master a coupled slave follows.
    pub(crate) fn coupled_master(&self) -> Option<usize> {
        match &self.running {
            Some(Running {
                source: Source::Coupled(coupling),
                ..
            }) => Some(coupling.master),
            _ => None,
        }
    }

    /// The values a slave of this axis reads as its master.
    pub(crate) fn master_view(&self) -> MasterView {
        MasterView {
            position: self.position,
            velocity: self.velocity,
            acceleration: self.acceleration,
            period: self.config.modulo_period,
        }
    }

    /// Lets a planned motion control the axis and sets the state it belongs to.
    pub(crate) fn install(&mut self, running: Running) {
        self.state = match running.source {
            Source::Position { .. } | Source::Halt { .. } => AxisState::DiscreteMotion,
            Source::Velocity { .. } => AxisState::ContinuousMotion,
            Source::Stop { .. } => AxisState::Stopping,
            Source::ErrorRamp => AxisState::ErrorStop,
            Source::Home { .. } => AxisState::Homing,
            Source::Coupled(_) => AxisState::SynchronizedMotion,
        };
        if let Source::Position { target, .. } = running.source {
            self.commanded_position = target;
        }
        self.running = Some(running);
    }

    /// Integrates one cycle of `dt_s` seconds.
    pub(crate) fn advance(&mut self, dt_s: f64, registry: &mut Registry, sync: SyncInputs<'_>) {
        self.time_s += dt_s;
        let Some(running) = &mut self.running else {
            return;
        };
        if let Source::Coupled(_) = running.source {
            self.advance_coupled(dt_s, registry, sync);
            self.check_software_limits(registry);
            return;
        }
        if let Source::Home { position } = running.source {
            let id = running.id;
            self.running = None;
            self.position = self.config.wrap(position);
            self.commanded_position = self.position;
            self.homed = true;
            self.state = AxisState::Standstill;
            if let Some(id) = id {
                registry.set(id, CommandStatus::Done);
            }
            return;
        }
        self.integrate(dt_s);
        // The elapsed time is a sum of cycle intervals, which rounds; a profile that ends within
        // a millionth of a cycle of now has ended now, not one cycle later.
        if let Some(running) = &self.running
            && running.elapsed_s >= running.profile.duration_s() - dt_s * 1e-6
        {
            // A motion that has settled (cruising at its velocity, held by MC_Stop or by a
            // velocity override of 0) has nothing left to finish until something changes.
            let settled = match running.source {
                Source::Velocity { .. } => running.reached && self.buffered.is_none(),
                Source::Stop { held } => held && running.reached,
                Source::Position { .. } => running.paused,
                _ => false,
            };
            if !settled {
                self.finish(registry);
            }
        }
        self.check_software_limits(registry);
    }

    /// Moves the running motion on by `dt_s` and takes its set values.
    fn integrate(&mut self, dt_s: f64) {
        let Some(running) = &mut self.running else {
            return;
        };
        if let Source::Coupled(_) = running.source {
            // A coupling computes its set values from its master in `advance`.
            return;
        }
        running.elapsed_s += dt_s;
        if running.reached && matches!(running.source, Source::Velocity { .. }) {
            // At constant velocity the position is integrated, so it stays exact on long runs.
            self.position = self.config.wrap(self.position + self.velocity * dt_s);
            self.acceleration = 0.0;
        } else {
            let sample = running.profile.sample(running.elapsed_s);
            running.displacement = sample.displacement;
            self.position = self.config.wrap(running.origin + sample.displacement);
            self.velocity = sample.velocity;
            self.acceleration = sample.acceleration;
        }
    }

    /// Handles the end of the running profile.
    fn finish(&mut self, registry: &mut Registry) {
        let Some(mut running) = self.running.take() else {
            return;
        };
        self.acceleration = 0.0;
        match running.source {
            Source::Position { target, .. } => {
                if running.paused {
                    self.velocity = 0.0;
                    self.running = Some(running);
                    return;
                }
                self.position = target;
                self.velocity = running.profile.end().velocity;
                // A blending successor takes over the part of the cycle after the target, so
                // the axis moves on without a gap.
                let carry_s = if self.velocity == 0.0 {
                    0.0
                } else {
                    (running.elapsed_s - running.profile.duration_s()).max(0.0)
                };
                self.complete(running.id, registry, carry_s);
            }
            Source::Halt { .. } => {
                self.velocity = 0.0;
                self.complete(running.id, registry, 0.0);
            }
            Source::Velocity { .. } => {
                self.velocity = running.profile.end().velocity;
                if !running.reached {
                    running.reached = true;
                    if let Some(id) = running.id {
                        registry.set(id, CommandStatus::Active { reached: true });
                    }
                }
                if let Some((next_id, request)) = self.buffered.take() {
                    // A velocity command counts as finished for the buffer once it is at its
                    // velocity; the buffered command takes over from there.
                    if let Some(id) = running.id {
                        registry.set(id, CommandStatus::Aborted);
                    }
                    self.start_buffered(next_id, request, registry, 0.0);
                } else {
                    self.running = Some(running);
                }
            }
            Source::Stop { held } => {
                self.velocity = 0.0;
                if held {
                    if !running.reached {
                        running.reached = true;
                        if let Some(id) = running.id {
                            registry.set(id, CommandStatus::Active { reached: true });
                        }
                    }
                    self.running = Some(running);
                } else {
                    self.state = AxisState::Standstill;
                    if let Some(id) = running.id {
                        registry.set(id, CommandStatus::Done);
                    }
                }
            }
            Source::ErrorRamp => {
                self.velocity = 0.0;
                if let Some(reset_id) = self.pending_reset.take() {
                    self.reset();
                    registry.set(reset_id, CommandStatus::Done);
                }
            }
            Source::Home { .. } | Source::Coupled(_) => {}
        }
    }

    /// Marks a discrete command Done and starts the buffered one (`carry_s` into its profile)
    /// or comes to Standstill.
    fn complete(&mut self, id: Option<CommandId>, registry: &mut Registry, carry_s: f64) {
        if let Some(id) = id {
            registry.set(id, CommandStatus::Done);
        }
        match self.buffered.take() {
            Some((next_id, request)) => self.start_buffered(next_id, request, registry, carry_s),
            None => {
                // A move that was to blend into a successor that is gone still ends at rest.
                self.velocity = 0.0;
                self.state = AxisState::Standstill;
            }
        }
    }

    /// Lets the buffered command take control, `carry_s` seconds into its profile.
    fn start_buffered(
        &mut self,
        id: CommandId,
        request: MotionRequest,
        registry: &mut Registry,
        carry_s: f64,
    ) {
        match self.plan(request) {
            Ok(mut running) => {
                running.id = Some(id);
                registry.set(id, CommandStatus::Active { reached: false });
                self.install(running);
                if carry_s > 0.0 {
                    self.integrate(carry_s);
                }
            }
            Err(error) => {
                registry.set(id, CommandStatus::Error(error));
                if self.velocity == 0.0 {
                    self.state = AxisState::Standstill;
                } else {
                    // The move before blended into this one and passed its target moving, so
                    // the axis brakes at its configured deceleration, as MC_Halt would.
                    let dynamics = Dynamics {
                        velocity: self.config.max_velocity,
                        acceleration: self.config.max_deceleration,
                        deceleration: self.config.max_deceleration,
                        jerk: 0.0,
                    };
                    if let Ok(halt) = self.plan(MotionRequest::Halt { dynamics }) {
                        self.install(halt);
                    }
                }
            }
        }
    }

    /// One cycle of a coupled slave: the coupling computes the set values from the master's.
    fn advance_coupled(&mut self, dt_s: f64, registry: &mut Registry, sync: SyncInputs<'_>) {
        let slave = SlaveView {
            position: self.position,
            velocity: self.velocity,
            period: self.config.modulo_period,
        };
        let Some(running) = &mut self.running else {
            return;
        };
        let Source::Coupled(coupling) = &mut running.source else {
            return;
        };
        let Some(master) = sync.master else {
            return;
        };
        running.elapsed_s += dt_s;
        match coupling.step(dt_s, &master, &slave, sync.cams) {
            Ok(step) => {
                self.position = self.config.wrap(step.set.position);
                self.velocity = step.set.velocity;
                self.acceleration = step.set.acceleration;
                if let Some(id) = step.phase_done {
                    registry.set(id, CommandStatus::Done);
                }
                if step.in_sync && !running.reached {
                    running.reached = true;
                    if let Some(id) = running.id {
                        registry.set(id, CommandStatus::Active { reached: true });
                    }
                }
            }
            Err(error) => self.fail_running(error, registry),
        }
    }

    /// Clears the axis error and goes to Standstill or Disabled (Notes 3 and 4).
    pub(crate) fn reset(&mut self) {
        self.axis_error_id = 0;
        self.velocity = 0.0;
        self.acceleration = 0.0;
        self.state = if self.powered {
            AxisState::Standstill
        } else {
            AxisState::PowerOff
        };
    }

    fn check_software_limits(&mut self, registry: &mut Registry) {
        if self.state == AxisState::ErrorStop {
            return;
        }
        if let Some(limits) = self.config.active_software_limits()
            && !(limits.min..=limits.max).contains(&self.position)
        {
            self.raise_error(crate::kernel::AXIS_ERROR_SOFTWARE_LIMIT, registry);
        }
    }

    /// An axis error: every command on the axis ends in Error and the axis brakes in ErrorStop.
    pub(crate) fn raise_error(&mut self, axis_error_id: u16, registry: &mut Registry) {
        if self.state == AxisState::ErrorStop && self.axis_error_id != 0 {
            return;
        }
        self.axis_error_id = axis_error_id;
        let error = CommandStatus::Error(MotionError::AxisError { axis_error_id });
        self.end_commands(error, registry);
        self.state = AxisState::ErrorStop;
        if self.powered && (self.velocity != 0.0 || self.acceleration != 0.0) {
            let limits = self.stop_limits(self.config.max_deceleration, self.config.max_jerk);
            let profile = Profile::to_velocity(0.0, self.velocity, self.acceleration, limits);
            self.running = Some(Running::new(
                "error stop",
                Source::ErrorRamp,
                profile,
                self.position,
            ));
        } else {
            self.velocity = 0.0;
            self.acceleration = 0.0;
        }
    }
}

/// Ends the MC_Phasing command running on a coupling that ends with `status`.
pub(crate) fn end_phasing(running: &Running, status: CommandStatus, registry: &mut Registry) {
    if let Source::Coupled(coupling) = running.source
        && let Some(run) = coupling.phase.run
    {
        registry.set(run.id, status);
    }
}
