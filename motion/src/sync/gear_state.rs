//! The state of an MC_GearIn coupling and its step per cycle.

use crate::axis::{Profile, ProfileLimits};
use crate::sync::{GearCoupling, SeenMaster, SlaveSet, SlaveView};

/// A running gear: the slave moves `ratio` times the master's displacement plus a velocity
/// difference that a profile takes from its start value to 0 (the gear-in ramp). Distance
/// lost during the ramp is not caught up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct GearState {
    /// The MC_GearIn inputs.
    pub(crate) inputs: GearCoupling,
    /// The profile of the velocity difference to the geared velocity.
    ramp: Profile,
    /// Seconds since the start.
    elapsed_s: f64,
    /// Whether the ramp has ended (`InGear`).
    pub(crate) in_gear: bool,
}

impl GearState {
    /// Starts gearing a slave moving at `slave.velocity` to a master at `master_velocity`.
    pub(crate) fn start(inputs: GearCoupling, master_velocity: f64, slave: &SlaveView) -> Self {
        let geared = inputs.ratio() * master_velocity;
        let difference = slave.velocity - geared;
        // The slave speeds up when the geared velocity is above its own, so the ramp is
        // limited by Acceleration; otherwise it slows down and Deceleration limits it.
        let limit = if geared.abs() > slave.velocity.abs() {
            inputs.acceleration
        } else {
            inputs.deceleration
        };
        let limits = ProfileLimits {
            velocity: f64::INFINITY,
            acceleration: limit,
            deceleration: limit,
            jerk: inputs.jerk,
            // The ramp starts at zero acceleration, so there is nothing to recover.
            recovery_jerk: inputs.jerk,
        };
        let ramp = Profile::to_velocity(0.0, difference, 0.0, limits);
        Self {
            inputs,
            ramp,
            elapsed_s: 0.0,
            in_gear: difference == 0.0,
        }
    }

    /// Moves the gear on by one cycle; `slave_position` is the slave's set position before it.
    pub(crate) fn step(&mut self, slave_position: f64, seen: SeenMaster, dt_s: f64) -> SlaveSet {
        let ratio = self.inputs.ratio();
        let mut set = SlaveSet {
            position: slave_position + ratio * seen.displacement,
            velocity: ratio * seen.velocity,
            acceleration: ratio * seen.acceleration,
        };
        if !self.in_gear {
            let before = self.ramp.sample(self.elapsed_s);
            self.elapsed_s += dt_s;
            if self.elapsed_s >= self.ramp.duration_s() - dt_s * 1e-6 {
                let end = self.ramp.end();
                set.position += end.displacement - before.displacement;
                self.in_gear = true;
            } else {
                let sample = self.ramp.sample(self.elapsed_s);
                set.position += sample.displacement - before.displacement;
                set.velocity += sample.velocity;
                set.acceleration += sample.acceleration;
            }
        }
        set
    }
}
