//! One axis inside the kernel: its set values, its PLCopen state and the motion source that
//! drives it.

use crate::axis::direction::modulo_distances;
use crate::axis::{AxisConfig, AxisState, Direction, Overrides, Profile, ProfileLimits};
use crate::kernel::registry::Registry;
use crate::kernel::{
    BufferMode, CommandId, CommandStatus, Dynamics, MotionError, MotionRequest, PositionTarget,
};

/// What produces the set values of an axis while it moves. Every kind of motion is one variant;
/// synchronised motion (a slave following a master through a cam or a gear) is added as one more
/// variant whose set point the kernel computes from the master's snapshot each cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
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
}

impl Running {
    fn new(name: &'static str, source: Source, profile: Profile, origin: f64) -> Self {
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
        }
    }

    /// The profile limits of a command's dynamics under the overrides in force.
    fn limits(&self, dynamics: Dynamics) -> ProfileLimits {
        let jerk = if dynamics.jerk > 0.0 {
            dynamics.jerk
        } else {
            self.config.max_jerk
        };
        ProfileLimits {
            velocity: dynamics.velocity.abs() * self.overrides.velocity,
            acceleration: dynamics.acceleration * self.overrides.acceleration,
            deceleration: dynamics.deceleration * self.overrides.acceleration,
            jerk: jerk * self.overrides.jerk,
        }
    }

    /// The limits of a stop ramp: MC_Stop and the error stop ignore the overrides.
    pub(crate) fn stop_limits(&self, deceleration: f64, jerk: f64) -> ProfileLimits {
        ProfileLimits {
            velocity: self.config.max_velocity,
            acceleration: deceleration,
            deceleration,
            jerk: if jerk > 0.0 {
                jerk
            } else {
                self.config.max_jerk
            },
        }
    }

    /// A profile over `distance` that passes its end with `end_speed`, or a hold at rest while
    /// the velocity override is 0.
    fn position_profile(
        &self,
        distance: f64,
        dynamics: Dynamics,
        end_speed: f64,
    ) -> (Profile, bool) {
        let limits = self.limits(dynamics);
        if limits.velocity > 0.0 {
            let profile = Profile::to_position_blending(
                distance,
                self.velocity,
                self.acceleration,
                limits,
                end_speed,
            );
            (profile, false)
        } else {
            let profile = Profile::to_velocity(0.0, self.velocity, self.acceleration, limits);
            (profile, true)
        }
    }

    /// The displacement still to cover to the last commanded target while in DiscreteMotion.
    fn distance_to_commanded(&self) -> f64 {
        if let Some(running) = &self.running
            && let Source::Position { .. } = running.source
        {
            return running.distance - running.displacement;
        }
        match self.config.modulo_period {
            Some(period) => {
                let (forward, backward) = modulo_distances(
                    self.position,
                    self.config.wrap(self.commanded_position),
                    period,
                );
                if forward <= -backward {
                    forward
                } else {
                    backward
                }
            }
            None => self.commanded_position - self.position,
        }
    }

    /// The signed travel to an absolute target from `from` at `velocity`, and the wrapped
    /// target.
    fn absolute_travel(
        &self,
        from: f64,
        velocity: f64,
        position: f64,
        direction: Direction,
        dynamics: Dynamics,
    ) -> (f64, f64) {
        let Some(period) = self.config.modulo_period else {
            return (position - from, position);
        };
        let target = self.config.wrap(position);
        let (forward, backward) = modulo_distances(from, target, period);
        let shortest = if forward <= -backward {
            forward
        } else {
            backward
        };
        let travel = match direction {
            Direction::Positive => forward,
            Direction::Negative => backward,
            Direction::Shortest => shortest,
            Direction::Current if velocity > 0.0 => forward,
            Direction::Current if velocity < 0.0 => backward,
            Direction::Current => shortest,
            Direction::Fastest => {
                let limits = self.limits(dynamics);
                let duration_s =
                    |travel: f64| Profile::to_position(travel, velocity, 0.0, limits).duration_s();
                if limits.velocity <= 0.0 || duration_s(forward) <= duration_s(backward) {
                    forward
                } else {
                    backward
                }
            }
        };
        (travel, target)
    }

    /// Plans a request from the axis's current state without changing the axis.
    pub(crate) fn plan(&self, request: MotionRequest) -> Result<Running, MotionError> {
        self.plan_motion(request).map(|mut running| {
            running.request = Some(request);
            running
        })
    }

    fn plan_motion(&self, request: MotionRequest) -> Result<Running, MotionError> {
        let name = request.fb_name();
        match request {
            MotionRequest::Position { target, dynamics } => {
                let (travel, target) = match target {
                    PositionTarget::Absolute {
                        position,
                        direction,
                    } => self.absolute_travel(
                        self.position,
                        self.velocity,
                        position,
                        direction,
                        dynamics,
                    ),
                    PositionTarget::Relative { distance } => {
                        (distance, self.config.wrap(self.position + distance))
                    }
                    PositionTarget::Additive { distance } => {
                        if self.state == AxisState::DiscreteMotion {
                            let travel = self.distance_to_commanded() + distance;
                            (travel, self.config.wrap(self.commanded_position + distance))
                        } else {
                            (distance, self.config.wrap(self.position + distance))
                        }
                    }
                };
                if let Some(limits) = self.config.active_software_limits()
                    && !(limits.min..=limits.max).contains(&target)
                {
                    return Err(MotionError::OutsideSoftwareLimits {
                        target,
                        min: limits.min,
                        max: limits.max,
                    });
                }
                let (profile, paused) = self.position_profile(travel, dynamics, 0.0);
                let mut running = Running::new(
                    name,
                    Source::Position { target, dynamics },
                    profile,
                    self.position,
                );
                running.distance = travel;
                running.paused = paused;
                Ok(running)
            }
            MotionRequest::Velocity {
                direction,
                dynamics,
                ..
            } => {
                let sign = match direction {
                    Direction::Positive => 1.0,
                    Direction::Negative => -1.0,
                    Direction::Current if self.velocity < 0.0 => -1.0,
                    Direction::Current => 1.0,
                    Direction::Shortest | Direction::Fastest => {
                        return Err(MotionError::InvalidParameter {
                            input: "Direction",
                            value: f64::from(direction.code()),
                            reason: "MC_MoveVelocity moves positive (1), negative (-1) or in the current direction (2)",
                        });
                    }
                };
                let velocity = sign * dynamics.velocity;
                let limits = self.limits(dynamics);
                let profile = Profile::to_velocity(
                    velocity * self.overrides.velocity,
                    self.velocity,
                    self.acceleration,
                    limits,
                );
                Ok(Running::new(
                    name,
                    Source::Velocity { velocity, dynamics },
                    profile,
                    self.position,
                ))
            }
            MotionRequest::Halt { dynamics } => {
                let mut limits = self.limits(dynamics);
                limits.acceleration = limits.deceleration;
                let profile = Profile::to_velocity(0.0, self.velocity, self.acceleration, limits);
                Ok(Running::new(
                    name,
                    Source::Halt { dynamics },
                    profile,
                    self.position,
                ))
            }
        }
    }

    /// Lets the running position move pass its target with the speed `mode` asks for, so the
    /// buffered `next` command takes over without a stop. The speed is 0 when `next` goes the
    /// other way, and no higher than `next` can brake from within its own distance. After
    /// MC_MoveVelocity or MC_Halt, and before MC_MoveVelocity or MC_Halt, a blending command
    /// acts like a buffered one.
    pub(crate) fn blend_into(&mut self, next: MotionRequest, mode: BufferMode) {
        let Some(running) = self.running else {
            return;
        };
        let Source::Position { target, dynamics } = running.source else {
            return;
        };
        let MotionRequest::Position {
            target: next_target,
            dynamics: next_dynamics,
        } = next
        else {
            return;
        };
        let direction = running.distance.signum();
        let previous_speed = dynamics.velocity.abs() * self.overrides.velocity;
        let next_limits = self.limits(next_dynamics);
        let next_travel = match next_target {
            PositionTarget::Relative { distance } | PositionTarget::Additive { distance } => {
                distance
            }
            PositionTarget::Absolute {
                position,
                direction: way,
            } => {
                let velocity = direction * previous_speed;
                self.absolute_travel(target, velocity, position, way, next_dynamics)
                    .0
            }
        };
        let wanted = match mode {
            BufferMode::Aborting | BufferMode::Buffered => 0.0,
            BufferMode::BlendingLow => previous_speed.min(next_limits.velocity),
            BufferMode::BlendingPrevious => previous_speed,
            BufferMode::BlendingNext => next_limits.velocity,
            BufferMode::BlendingHigh => previous_speed.max(next_limits.velocity),
        };
        let end_speed = if next_travel * direction > 0.0 {
            next_limits.stoppable_speed(wanted, next_travel.abs())
        } else {
            0.0
        };
        if end_speed != running.end_speed {
            if let Some(running) = &mut self.running {
                running.end_speed = end_speed;
            }
            self.replan();
        }
    }

    /// Plans an MC_Stop ramp.
    pub(crate) fn plan_stop(&self, deceleration: f64, jerk: f64) -> Running {
        let limits = self.stop_limits(deceleration, jerk);
        let profile = Profile::to_velocity(0.0, self.velocity, self.acceleration, limits);
        Running::new(
            "MC_Stop",
            Source::Stop { held: true },
            profile,
            self.position,
        )
    }

    /// Plans MC_Home on a virtual axis.
    pub(crate) fn plan_home(&self, position: f64) -> Running {
        Running::new(
            "MC_Home",
            Source::Home { position },
            Profile::at_rest(),
            self.position,
        )
    }

    /// Ends the running and the buffered command with `status`, as when another command takes
    /// over or the power goes off.
    pub(crate) fn end_commands(&mut self, status: CommandStatus, registry: &mut Registry) {
        if let Some(running) = self.running.take()
            && let Some(id) = running.id
        {
            registry.set(id, status);
        }
        if let Some((id, _)) = self.buffered.take() {
            registry.set(id, status);
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
        };
        if let Source::Position { target, .. } = running.source {
            self.commanded_position = target;
        }
        self.running = Some(running);
    }

    /// Integrates one cycle of `dt_s` seconds.
    pub(crate) fn advance(&mut self, dt_s: f64, registry: &mut Registry) {
        let Some(running) = &mut self.running else {
            return;
        };
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
            self.finish(registry);
        }
        self.check_software_limits(registry);
    }

    /// Moves the running motion on by `dt_s` and takes its set values.
    fn integrate(&mut self, dt_s: f64) {
        let Some(running) = &mut self.running else {
            return;
        };
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
            Source::Home { .. } => {}
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

    /// ContinuousUpdate: applies new inputs to the command `id`, running or buffered. A running
    /// position move keeps its start: a new `Distance` counts from where MC_MoveRelative started
    /// (from the target MC_MoveAdditive added to), a new `Position` is the new target. Inputs that
    /// cannot be applied end the command in Error and the axis brakes as MC_Halt would.
    pub(crate) fn update(
        &mut self,
        id: CommandId,
        request: MotionRequest,
        registry: &mut Registry,
    ) {
        if let Some((buffered_id, buffered_request)) = &mut self.buffered
            && *buffered_id == id
        {
            *buffered_request = request;
            return;
        }
        let Some(running) = self.running else {
            return;
        };
        if running.id != Some(id) || running.request == Some(request) {
            return;
        }
        let updated = match (running.source, request) {
            (Source::Position { .. }, MotionRequest::Position { target, dynamics }) => {
                self.update_position(running, target, dynamics)
            }
            (Source::Velocity { velocity, .. }, MotionRequest::Velocity { .. }) => {
                self.plan(request).map(|mut next| {
                    next.id = running.id;
                    next.request = Some(request);
                    if let Source::Velocity { velocity: new, .. } = next.source {
                        if new == velocity {
                            next.reached = running.reached;
                        } else {
                            registry.set(id, CommandStatus::Active { reached: false });
                        }
                    }
                    next
                })
            }
            _ => return,
        };
        match updated {
            Ok(next) => {
                if let Source::Position { target, .. } = next.source {
                    self.commanded_position = target;
                }
                self.running = Some(next);
            }
            Err(error) => self.fail_running(error, registry),
        }
    }

    /// The running position move replanned for a new target or new dynamics.
    fn update_position(
        &self,
        running: Running,
        target: PositionTarget,
        dynamics: Dynamics,
    ) -> Result<Running, MotionError> {
        let travelled = running.travelled_before + running.displacement;
        let planned_total = running.travelled_before + running.distance;
        let total = match target {
            PositionTarget::Relative { distance } => distance,
            PositionTarget::Additive { distance } => {
                let previous = match running.request {
                    Some(MotionRequest::Position {
                        target: PositionTarget::Additive { distance: previous },
                        ..
                    }) => previous,
                    _ => 0.0,
                };
                planned_total - previous + distance
            }
            PositionTarget::Absolute {
                position,
                direction,
            } => {
                let (remaining, _) = self.absolute_travel(
                    self.position,
                    self.velocity,
                    position,
                    direction,
                    dynamics,
                );
                travelled + remaining
            }
        };
        let remaining = total - travelled;
        let new_target = match target {
            PositionTarget::Absolute { position, .. } => self.config.wrap(position),
            PositionTarget::Relative { .. } | PositionTarget::Additive { .. } => {
                self.config.wrap(self.position + remaining)
            }
        };
        if let Some(limits) = self.config.active_software_limits()
            && !(limits.min..=limits.max).contains(&new_target)
        {
            return Err(MotionError::OutsideSoftwareLimits {
                target: new_target,
                min: limits.min,
                max: limits.max,
            });
        }
        let (profile, paused) = self.position_profile(remaining, dynamics, running.end_speed);
        Ok(Running {
            source: Source::Position {
                target: new_target,
                dynamics,
            },
            profile,
            paused,
            distance: remaining,
            origin: self.position,
            elapsed_s: 0.0,
            displacement: 0.0,
            travelled_before: travelled,
            request: Some(MotionRequest::Position { target, dynamics }),
            ..running
        })
    }

    /// Ends the running command in Error; a moving axis brakes with the command's deceleration
    /// (or the axis's, when the command has none), as MC_Halt would.
    pub(crate) fn fail_running(&mut self, error: MotionError, registry: &mut Registry) {
        let deceleration = match self.running.map(|running| running.source) {
            Some(
                Source::Position { dynamics, .. }
                | Source::Velocity { dynamics, .. }
                | Source::Halt { dynamics },
            ) => dynamics.deceleration,
            _ => self.config.max_deceleration,
        };
        if let Some(running) = self.running.take()
            && let Some(id) = running.id
        {
            registry.set(id, CommandStatus::Error(error));
        }
        if let Some((id, _)) = self.buffered.take() {
            registry.set(id, CommandStatus::Aborted);
        }
        if self.velocity == 0.0 && self.acceleration == 0.0 {
            self.state = AxisState::Standstill;
            return;
        }
        let dynamics = Dynamics {
            velocity: self.config.max_velocity,
            acceleration: deceleration,
            deceleration,
            jerk: 0.0,
        };
        if let Ok(halt) = self.plan(MotionRequest::Halt { dynamics }) {
            self.install(halt);
        }
    }

    /// Replans the running motion from the current set values, after the overrides changed.
    pub(crate) fn replan(&mut self) {
        let Some(running) = self.running else {
            return;
        };
        let (profile, paused, distance) = match running.source {
            Source::Position { dynamics, .. } => {
                let remaining = running.distance - running.displacement;
                let (profile, paused) =
                    self.position_profile(remaining, dynamics, running.end_speed);
                (profile, paused, remaining)
            }
            Source::Velocity { velocity, dynamics } => {
                let limits = self.limits(dynamics);
                let profile = Profile::to_velocity(
                    velocity * self.overrides.velocity,
                    self.velocity,
                    self.acceleration,
                    limits,
                );
                (profile, false, 0.0)
            }
            Source::Halt { dynamics } => {
                let mut limits = self.limits(dynamics);
                limits.acceleration = limits.deceleration;
                let profile = Profile::to_velocity(0.0, self.velocity, self.acceleration, limits);
                (profile, false, 0.0)
            }
            Source::Stop { .. } | Source::ErrorRamp | Source::Home { .. } => return,
        };
        self.running = Some(Running {
            profile,
            paused,
            distance,
            origin: self.position,
            elapsed_s: 0.0,
            displacement: 0.0,
            travelled_before: running.travelled_before + running.displacement,
            // A velocity command keeps InVelocity once reached; the cruise resumes when the
            // new ramp ends.
            reached: false,
            ..running
        });
    }
}
