//! How an axis plans its motion: turning a request into a profile from the axis's current set
//! values, replanning when overrides or inputs change, and the blending of buffered moves.

use crate::axis::direction::modulo_distances;
use crate::axis::{AxisState, Direction, Profile, ProfileLimits};
use crate::kernel::axis_runtime::{AxisRuntime, Running, Source, end_phasing};
use crate::kernel::coupling::{Coupling, CouplingMode};
use crate::kernel::registry::Registry;
use crate::kernel::{
    BufferMode, CommandId, CommandStatus, Dynamics, MotionError, MotionRequest, PositionTarget,
};

impl AxisRuntime {
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
            recovery_jerk: self.config.max_jerk,
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
            recovery_jerk: self.config.max_jerk,
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
            MotionRequest::Cam {
                master,
                mut coupling,
            } => {
                // As for single-axis motion, a jerk of 0 uses the axis's jerk limit.
                if coupling.jerk == 0.0 {
                    coupling.jerk = self.config.max_jerk;
                }
                Ok(self.coupled(name, master.0, CouplingMode::PendingCam(coupling)))
            }
            MotionRequest::Gear {
                master,
                mut coupling,
            } => {
                if coupling.jerk == 0.0 {
                    coupling.jerk = self.config.max_jerk;
                }
                Ok(self.coupled(name, master.0, CouplingMode::PendingGear(coupling)))
            }
            MotionRequest::GearInPos { master, coupling } => {
                Ok(self.coupled(name, master.0, CouplingMode::PendingGearInPos(coupling)))
            }
        }
    }

    /// A coupling that starts at the next `advance`.
    fn coupled(&self, name: &'static str, master: usize, mode: CouplingMode) -> Running {
        Running::new(
            name,
            Source::Coupled(Coupling::pending(master, mode)),
            Profile::at_rest(),
            self.position,
        )
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
        if let Some(running) = self.running.take() {
            if let Some(id) = running.id {
                registry.set(id, CommandStatus::Error(error));
            }
            end_phasing(&running, CommandStatus::Aborted, registry);
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
            // Overrides do not act on a coupled slave (PLCopen MC_SetOverride).
            Source::Stop { .. } | Source::ErrorRamp | Source::Home { .. } | Source::Coupled(_) => {
                return;
            }
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
