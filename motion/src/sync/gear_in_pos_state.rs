//! The state of an MC_GearInPos coupling and its step per cycle.

use crate::cam::polynomial::{Boundary, Polynomial};
use crate::sync::{GearInPosCoupling, MasterView, SeenMaster, SlaveSet, SlaveView};

/// Where MC_GearInPos is.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Phase {
    /// Waiting for the master to cross `MasterSyncPosition − MasterStartDistance`; the slave
    /// keeps the velocity it had. `remaining` is the master distance still to go.
    Waiting { remaining: f64 },
    /// Following the generated sync cam: `travelled` master units since the start of sync,
    /// from slave position `origin`.
    Syncing {
        /// Master distance since StartSync.
        travelled: f64,
        /// The slave position at StartSync.
        origin: f64,
        /// The Poly5 from (0, origin-relative 0) to (MasterStartDistance, slave distance).
        curve: Polynomial<6>,
    },
    /// In sync: the slave moves `ratio` times the master displacement.
    Geared,
}

/// A running MC_GearInPos.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct GearInPosState {
    /// The MC_GearInPos inputs.
    pub(crate) inputs: GearInPosCoupling,
    phase: Phase,
}

/// The master distance from `position` to the next crossing of `target` in the positive
/// direction: on a modulo master the next image of the target at or ahead of the position,
/// on a linear master the plain difference (negative when the target lies behind).
fn distance_ahead(position: f64, target: f64, period: Option<f64>) -> f64 {
    match period {
        Some(period) => (target - position).rem_euclid(period),
        None => target - position,
    }
}

impl GearInPosState {
    /// Starts waiting for the master; `None` when a linear master has already passed the start
    /// of the synchronisation.
    pub(crate) fn start(inputs: GearInPosCoupling, master: &MasterView) -> Option<Self> {
        let start = inputs.master_sync_position - inputs.master_start_distance;
        let remaining = distance_ahead(master.position, start, master.period);
        (remaining >= 0.0).then_some(Self {
            inputs,
            phase: Phase::Waiting { remaining },
        })
    }

    /// Whether the master has passed the start of the synchronisation (`StartSync`).
    pub(crate) fn start_sync(&self) -> bool {
        !matches!(self.phase, Phase::Waiting { .. })
    }

    /// Whether the slave is in sync (`InSync`).
    pub(crate) fn in_sync(&self) -> bool {
        self.phase == Phase::Geared
    }

    /// The sync cam from the slave's values at StartSync to the sync position with slope
    /// `ratio`; the slave distance is the image of the sync position closest to what the gear
    /// would cover over the start distance, so the slave goes forward through a modulo wrap
    /// when that is nearer the geared motion.
    fn sync_curve(&self, slave: &SlaveView, master_velocity: f64) -> Polynomial<6> {
        let ratio = self.inputs.ratio();
        let length = self.inputs.master_start_distance;
        let direct = self.inputs.slave_sync_position - slave.position;
        let distance = match slave.period {
            Some(period) => {
                let geared = ratio * length;
                direct + period * ((geared - direct) / period).round()
            }
            None => direct,
        };
        let start_slope = if master_velocity.abs() > f64::EPSILON {
            slave.velocity / master_velocity
        } else {
            0.0
        };
        let start = Boundary {
            position: 0.0,
            velocity: start_slope,
            acceleration: 0.0,
            jerk: 0.0,
        };
        let end = Boundary {
            position: distance,
            velocity: ratio,
            acceleration: 0.0,
            jerk: 0.0,
        };
        Polynomial::hermite(3, start, end, length)
    }

    /// The sync cam's values `travelled` master units after StartSync.
    fn on_curve(
        &self,
        curve: &Polynomial<6>,
        origin: f64,
        travelled: f64,
        seen: SeenMaster,
    ) -> SlaveSet {
        let length = self.inputs.master_start_distance;
        let sample = curve.evaluate(travelled.max(0.0) / length, 1.0 / length);
        SlaveSet {
            position: origin + sample.position,
            velocity: sample.velocity * seen.velocity,
            acceleration: sample.acceleration * seen.velocity * seen.velocity
                + sample.velocity * seen.acceleration,
        }
    }

    /// Moves the coupling on by one cycle; `slave` holds the slave's values before it.
    pub(crate) fn step(&mut self, slave: &SlaveView, seen: SeenMaster, dt_s: f64) -> SlaveSet {
        let ratio = self.inputs.ratio();
        let length = self.inputs.master_start_distance;
        match self.phase {
            Phase::Waiting { remaining } => {
                let remaining = remaining - seen.displacement;
                if remaining > 0.0 {
                    self.phase = Phase::Waiting { remaining };
                    return SlaveSet {
                        position: slave.position + slave.velocity * dt_s,
                        velocity: slave.velocity,
                        acceleration: 0.0,
                    };
                }
                let curve = self.sync_curve(slave, seen.velocity);
                self.phase = Phase::Syncing {
                    travelled: 0.0,
                    origin: slave.position,
                    curve,
                };
                // The master passed the start by `-remaining` in this cycle already.
                self.step(
                    slave,
                    SeenMaster {
                        displacement: -remaining,
                        ..seen
                    },
                    dt_s,
                )
            }
            Phase::Syncing {
                travelled,
                origin,
                curve,
            } => {
                let travelled = travelled + seen.displacement;
                if travelled >= length {
                    self.phase = Phase::Geared;
                    let end = self.on_curve(&curve, origin, length, seen);
                    return SlaveSet {
                        position: end.position + ratio * (travelled - length),
                        velocity: ratio * seen.velocity,
                        acceleration: ratio * seen.acceleration,
                    };
                }
                self.phase = Phase::Syncing {
                    travelled,
                    origin,
                    curve,
                };
                self.on_curve(&curve, origin, travelled, seen)
            }
            Phase::Geared => SlaveSet {
                position: slave.position + ratio * seen.displacement,
                velocity: ratio * seen.velocity,
                acceleration: ratio * seen.acceleration,
            },
        }
    }
}
