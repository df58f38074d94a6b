//! The state of an MC_CamIn coupling and its step per cycle.

use crate::axis::{Profile, ProfileLimits};
use crate::curve::CamCurve;
use crate::kernel::MotionError;
use crate::sync::{CamCoupling, CamSelection, MasterView, SeenMaster, SlaveSet, SlaveView};
use crate::sync::{StartMode, wrap_signed};

/// The ramp-in compensation: an offset added to the cam's command that a position profile
/// takes from its start value to 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RampIn {
    /// The offset at the start: the slave's position minus the cam's first command.
    offset: f64,
    /// The profile of the offset's change, which covers `-offset`.
    profile: Profile,
    /// Seconds since the start.
    elapsed_s: f64,
}

/// A running cam coupling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CamState {
    /// The MC_CamIn inputs.
    pub(crate) inputs: CamCoupling,
    /// The selection, as it was when the coupling started.
    pub(crate) selection: CamSelection,
    /// The cam's master range.
    start: f64,
    end: f64,
    /// The cam master coordinate X.
    pub(crate) cam_master: f64,
    /// Forward wraps minus backward wraps since the start.
    pub(crate) period_index: i64,
    /// Whether X wrapped in the last step.
    pub(crate) wrapped: bool,
    /// Whether a non-periodic cam has left its range, so the slave holds the end value.
    pub(crate) ended: bool,
    /// What the cam's slave values count from: 0 when absolute, the slave's start position when
    /// relative, moved on by the cam's stroke at every wrap of a relative periodic cam.
    base: f64,
    /// `SlaveScaling·(CAM(end) − CAM(start))` for a relative periodic cam, else 0.
    stroke: f64,
    /// The compensation of the start jump while it runs.
    ramp: Option<RampIn>,
    /// The velocity of the master seen by the slave in the last step.
    pub(crate) seen_velocity: f64,
}

/// The cam master coordinate at the start and, for a periodic cam, wrapped into the range.
fn start_cam_master(
    inputs: &CamCoupling,
    selection: &CamSelection,
    range: (f64, f64),
    master: &MasterView,
) -> Result<f64, MotionError> {
    let master_position = if selection.master_absolute {
        master.position
    } else {
        0.0
    };
    let x = inputs.master_scaling * master_position + inputs.master_offset;
    let (start, end) = range;
    if selection.periodic {
        let period = end - start;
        let wraps = ((x - start) / period).floor();
        Ok(x - wraps * period)
    } else if (start..=end).contains(&x) {
        Ok(x)
    } else {
        Err(MotionError::MasterOutOfCamRange {
            cam_master: x,
            start,
            end,
        })
    }
}

/// Whether the slave values count from the slave's start position (StartMode × SlaveAbsolute).
fn is_relative(inputs: &CamCoupling, selection: &CamSelection) -> bool {
    inputs.start_mode == StartMode::Relative || !selection.slave_absolute
}

/// The slave set values the cam commands at `x` for a master moving at `velocity` and
/// `acceleration`, from `base` (what MC_CamIn and SMC_GetCamSlaveSetPosition compute).
pub(crate) fn cam_command(
    curve: &dyn CamCurve,
    inputs: &CamCoupling,
    base: f64,
    x: f64,
    velocity: f64,
    acceleration: f64,
) -> SlaveSet {
    let sample = curve.sample(x);
    let x_velocity = inputs.master_scaling * velocity;
    let x_acceleration = inputs.master_scaling * acceleration;
    let scaling = inputs.slave_scaling;
    SlaveSet {
        position: base + scaling * sample.position + inputs.slave_offset,
        velocity: scaling * sample.velocity * x_velocity,
        acceleration: scaling
            * (sample.acceleration * x_velocity * x_velocity + sample.velocity * x_acceleration),
    }
}

/// SMC_GetCamSlaveSetPosition: the slave set values MC_CamIn would command first for the
/// master's and the slave's current values, without ramp-in.
pub(crate) fn start_values(
    curve: &dyn CamCurve,
    inputs: &CamCoupling,
    selection: &CamSelection,
    master: &MasterView,
    slave_position: f64,
) -> Result<SlaveSet, MotionError> {
    let x = start_cam_master(inputs, selection, curve.master_range(), master)?;
    let base = if is_relative(inputs, selection) {
        slave_position
    } else {
        0.0
    };
    Ok(cam_command(
        curve,
        inputs,
        base,
        x,
        master.velocity,
        master.acceleration,
    ))
}

impl CamState {
    /// Starts the coupling from the master's and the slave's current values and returns it
    /// with the slave's first set values.
    pub(crate) fn start(
        inputs: CamCoupling,
        selection: CamSelection,
        curve: &dyn CamCurve,
        master: &MasterView,
        slave: &SlaveView,
    ) -> Result<(Self, SlaveSet), MotionError> {
        let (start, end) = curve.master_range();
        let cam_master = start_cam_master(&inputs, &selection, (start, end), master)?;
        let relative = is_relative(&inputs, &selection);
        let base = if relative { slave.position } else { 0.0 };
        let stroke = if relative && selection.periodic {
            inputs.slave_scaling * (curve.sample(end).position - curve.sample(start).position)
        } else {
            0.0
        };
        let first = cam_command(
            curve,
            &inputs,
            base,
            cam_master,
            master.velocity,
            master.acceleration,
        );
        let ramp = if inputs.start_mode.ramps() {
            Self::plan_ramp(&inputs, slave, first)
        } else {
            None
        };
        let state = Self {
            inputs,
            selection,
            start,
            end,
            cam_master,
            period_index: 0,
            wrapped: false,
            ended: false,
            base,
            stroke,
            ramp,
            seen_velocity: master.velocity,
        };
        let mut set = first;
        if let Some(ramp) = &state.ramp {
            set.position += ramp.offset;
            set.velocity = slave.velocity;
            set.acceleration = 0.0;
        }
        Ok((state, set))
    }

    /// The compensation that takes the slave from where it is onto the cam's first command.
    fn plan_ramp(inputs: &CamCoupling, slave: &SlaveView, first: SlaveSet) -> Option<RampIn> {
        let difference = slave.position - first.position;
        let offset = match slave.period {
            Some(period) => match inputs.start_mode {
                // The compensation covers −offset, so a positive compensation needs an offset
                // at or below 0, a negative one an offset at or above 0.
                StartMode::RampInPositive => -(-difference).rem_euclid(period),
                StartMode::RampInNegative => difference.rem_euclid(period),
                _ => wrap_signed(difference, period),
            },
            None => difference,
        };
        let velocity_difference = slave.velocity - first.velocity;
        if offset == 0.0 && velocity_difference == 0.0 {
            return None;
        }
        let limits = ProfileLimits {
            velocity: inputs.velocity_diff,
            acceleration: inputs.acceleration,
            deceleration: inputs.deceleration,
            jerk: inputs.jerk,
            // The ramp starts at zero acceleration, so there is nothing to recover.
            recovery_jerk: inputs.jerk,
        };
        Some(RampIn {
            offset,
            profile: Profile::to_position(-offset, velocity_difference, 0.0, limits),
            elapsed_s: 0.0,
        })
    }

    /// Whether the slave follows the cam exactly (no ramp-in compensation left).
    pub(crate) fn in_sync(&self) -> bool {
        self.ramp.is_none()
    }

    /// Moves the coupling on by one cycle in which the master moved as `seen`.
    pub(crate) fn step(&mut self, curve: &dyn CamCurve, seen: SeenMaster, dt_s: f64) -> SlaveSet {
        self.wrapped = false;
        if !self.ended {
            self.cam_master += self.inputs.master_scaling * seen.displacement;
            if self.selection.periodic {
                let period = self.end - self.start;
                let wraps = ((self.cam_master - self.start) / period).floor();
                if wraps != 0.0 && wraps.is_finite() {
                    self.cam_master -= wraps * period;
                    // A wrap count fits an i64 for any master that moves less than 2^63
                    // periods, which a finite f64 displacement per cycle cannot exceed in
                    // practice; the cast saturates otherwise.
                    self.period_index = self.period_index.saturating_add(wraps as i64);
                    self.base += wraps * self.stroke;
                    self.wrapped = true;
                }
            } else if self.cam_master >= self.end {
                self.cam_master = self.end;
                self.ended = true;
            } else if self.cam_master < self.start {
                self.cam_master = self.start;
                self.ended = true;
            }
        }
        let mut set = if self.ended {
            let mut held = cam_command(curve, &self.inputs, self.base, self.cam_master, 0.0, 0.0);
            held.velocity = 0.0;
            held.acceleration = 0.0;
            held
        } else {
            cam_command(
                curve,
                &self.inputs,
                self.base,
                self.cam_master,
                seen.velocity,
                seen.acceleration,
            )
        };
        if let Some(ramp) = &mut self.ramp {
            ramp.elapsed_s += dt_s;
            if ramp.elapsed_s >= ramp.profile.duration_s() - dt_s * 1e-6 {
                self.ramp = None;
            } else {
                let sample = ramp.profile.sample(ramp.elapsed_s);
                set.position += ramp.offset + sample.displacement;
                set.velocity += sample.velocity;
                set.acceleration += sample.acceleration;
            }
        }
        set
    }
}
