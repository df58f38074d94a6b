//! MC_DigitalCamSwitch.

use crate::fb::cam_switch::{CamSwitch, CamSwitchMode, TrackOptions};
use crate::kernel::{AxisId, Kernel, MotionError};
use crate::sync::wrap_signed;

/// How many tracks (outputs) a cam switch has, as on Omron NJ/NX.
pub const CAM_SWITCH_TRACKS: usize = 16;

/// The state of one switch between calls.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct SwitchState {
    /// Whether the switch is on.
    on: bool,
    /// Where the switch last changed, for the hysteresis.
    changed_at: Option<f64>,
    /// When a timed switch goes off, in seconds of the axis's time.
    off_at_s: Option<f64>,
}

/// MC_DigitalCamSwitch (PLCopen, Omron NJ/NX): software cam switches on an axis's set position.
///
/// Each switch drives one track: in position mode it is on inside its window
/// (`FirstOnPosition` .. `LastOnPosition`, half-open at the edge where the output goes off, and
/// spanning the wrap on a modulo axis when First > Last); in time mode it turns on when the
/// axis crosses `FirstOnPosition` and stays on for `Duration`. A switch acts only while the
/// axis moves in its `AxisDirection` (at rest the last direction counts). Per track,
/// `OnCompensation` and `OffCompensation` move the on and off edges by that time at the current
/// velocity (−125 ms switches on 125 ms before the edge is reached), and `Hysteresis` keeps jitter
/// at an edge from chattering. A track's output is the OR of its switches, and FALSE when its
/// `EnableMask` bit (bit i = track i) is clear. With `Enable` FALSE the outputs keep their last
/// values. Time comes from the axis's time ([`Kernel::axis_time_s`]).
#[derive(Clone, Debug)]
pub struct DigitalCamSwitch {
    /// `Enable`: evaluate while TRUE.
    pub enable: bool,
    /// `Switches`.
    pub switches: Vec<CamSwitch>,
    /// `TrackOptions`, by track number.
    pub track_options: [TrackOptions; CAM_SWITCH_TRACKS],
    /// `EnableMask`: bit i enables track i; all tracks by default.
    pub enable_mask: u16,
    /// `Outputs`, by track number.
    pub outputs: [bool; CAM_SWITCH_TRACKS],
    /// `InOperation`: the outputs are valid.
    pub in_operation: bool,
    /// `Busy`: the instance is enabled.
    pub busy: bool,
    /// `Error`: a switch or a track option is invalid, or the axis reference is.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    states: Vec<SwitchState>,
    /// The set position at the last call.
    last_position: Option<f64>,
    /// The direction of motion in force, +1 or −1.
    direction: f64,
    /// Where the axis started to move against `direction`, for the hysteresis.
    reversal_at: Option<f64>,
}

impl Default for DigitalCamSwitch {
    fn default() -> Self {
        Self {
            enable: false,
            switches: Vec::new(),
            track_options: [TrackOptions::default(); CAM_SWITCH_TRACKS],
            enable_mask: u16::MAX,
            outputs: [false; CAM_SWITCH_TRACKS],
            in_operation: false,
            busy: false,
            error: false,
            error_id: 0,
            error_cause: None,
            states: Vec::new(),
            last_position: None,
            direction: 1.0,
            reversal_at: None,
        }
    }
}

/// An invalid-input error naming the structure member.
fn invalid(input: &'static str, value: f64, reason: &'static str) -> MotionError {
    MotionError::InvalidParameter {
        input,
        value,
        reason,
    }
}

/// The distance from `from` to `to`, the shortest way round on a modulo axis.
fn distance(from: f64, to: f64, period: Option<f64>) -> f64 {
    match period {
        Some(period) => wrap_signed(to - from, period),
        None => to - from,
    }
}

impl DigitalCamSwitch {
    /// Checks the switches and the track options.
    fn validate(&self, period: Option<f64>) -> Result<(), MotionError> {
        for options in &self.track_options {
            for (input, value) in [
                ("OnCompensation", options.on_compensation_s),
                ("OffCompensation", options.off_compensation_s),
            ] {
                if !(value.is_finite() && value.abs() <= 1.0) {
                    return Err(invalid(input, value, "a compensation lies in −1 s ..= 1 s"));
                }
            }
            if !(options.hysteresis.is_finite() && options.hysteresis >= 0.0) {
                return Err(invalid(
                    "Hysteresis",
                    options.hysteresis,
                    "the hysteresis is 0 or more",
                ));
            }
        }
        for switch in &self.switches {
            if usize::from(switch.track_number) >= CAM_SWITCH_TRACKS {
                return Err(invalid(
                    "TrackNumber",
                    f64::from(switch.track_number),
                    "track numbers are 0 ..= 15",
                ));
            }
            for (input, value) in [
                ("FirstOnPosition", switch.first_on_position),
                ("LastOnPosition", switch.last_on_position),
            ] {
                let inside = match period {
                    Some(period) => (0.0..period).contains(&value),
                    None => value.is_finite(),
                };
                if !inside {
                    return Err(invalid(
                        input,
                        value,
                        "a switch position is finite, and within the period on a modulo axis",
                    ));
                }
            }
            if switch.cam_switch_mode == CamSwitchMode::Position
                && period.is_none()
                && switch.last_on_position < switch.first_on_position
            {
                return Err(invalid(
                    "LastOnPosition",
                    switch.last_on_position,
                    "on a linear axis the window ends at or after FirstOnPosition",
                ));
            }
            if !(switch.duration_s.is_finite() && switch.duration_s >= 0.0) {
                return Err(invalid(
                    "Duration",
                    switch.duration_s,
                    "the duration is 0 s or more",
                ));
            }
        }
        Ok(())
    }

    /// One call of the instance for `axis`.
    pub fn call(&mut self, kernel: &Kernel, axis: AxisId) {
        if !self.enable {
            self.busy = false;
            self.in_operation = false;
            self.set_error(None);
            self.last_position = None;
            return;
        }
        self.busy = true;
        let result = self.evaluate(kernel, axis);
        self.in_operation = result.is_ok();
        self.set_error(result.err());
    }

    fn set_error(&mut self, error: Option<MotionError>) {
        self.error = error.is_some();
        self.error_id = error.map_or(0, |error| error.id());
        self.error_cause = error;
    }

    fn evaluate(&mut self, kernel: &Kernel, axis: AxisId) -> Result<(), MotionError> {
        let snapshot = kernel.snapshot(axis)?;
        let now_s = kernel.axis_time_s(axis)?;
        let period = (snapshot.modulo_period > 0.0).then_some(snapshot.modulo_period);
        self.validate(period)?;
        if self.states.len() != self.switches.len() {
            self.states
                .resize(self.switches.len(), SwitchState::default());
        }
        let position = snapshot.set_position;
        let velocity = snapshot.set_velocity;
        let previous = self.last_position.unwrap_or(position);
        self.last_position = Some(position);
        self.follow_direction(position, velocity);
        let mut outputs = [false; CAM_SWITCH_TRACKS];
        for (switch, state) in self.switches.iter().zip(self.states.iter_mut()) {
            let track = usize::from(switch.track_number);
            let options = self.track_options[track];
            let admitted = switch.axis_direction.admits(self.direction);
            match switch.cam_switch_mode {
                CamSwitchMode::Position => {
                    let wanted = admitted
                        && in_window(switch, &options, position, velocity, self.direction, period);
                    if wanted != state.on {
                        let within_band = options.hysteresis > 0.0
                            && state.changed_at.is_some_and(|at| {
                                distance(at, position, period).abs() <= options.hysteresis
                            });
                        if !within_band {
                            state.on = wanted;
                            state.changed_at = Some(position);
                        }
                    }
                }
                CamSwitchMode::Time => {
                    let trigger = switch.first_on_position + options.on_compensation_s * velocity;
                    if admitted && crosses(previous, position, trigger, period) {
                        state.off_at_s = Some(
                            now_s - options.on_compensation_s
                                + switch.duration_s
                                + options.off_compensation_s,
                        );
                    }
                    state.on = state.off_at_s.is_some_and(|off_at_s| now_s < off_at_s);
                }
            }
            outputs[track] |= state.on;
        }
        for (track, output) in outputs.iter_mut().enumerate() {
            *output &= self.enable_mask & (1 << track) != 0;
        }
        self.outputs = outputs;
        Ok(())
    }

    /// Updates the direction of motion: it reverses when the velocity's sign is against it and
    /// the axis has moved more than the largest track hysteresis since it turned.
    fn follow_direction(&mut self, position: f64, velocity: f64) {
        if velocity == 0.0 || velocity.signum() == self.direction {
            self.reversal_at = None;
            return;
        }
        let hysteresis = self
            .track_options
            .iter()
            .map(|options| options.hysteresis)
            .fold(0.0, f64::max);
        let turned_at = *self.reversal_at.get_or_insert(position);
        if hysteresis == 0.0 || (position - turned_at).abs() > hysteresis {
            self.direction = velocity.signum();
            self.reversal_at = None;
        }
    }
}

/// Whether `position` lies in the switch's window, its edges moved by the compensations: the
/// edge where the output goes on by `OnCompensation·v`, the other by `OffCompensation·v`.
fn in_window(
    switch: &CamSwitch,
    options: &TrackOptions,
    position: f64,
    velocity: f64,
    direction: f64,
    period: Option<f64>,
) -> bool {
    let on_shift = options.on_compensation_s * velocity;
    let off_shift = options.off_compensation_s * velocity;
    let (first_shift, last_shift) = if direction > 0.0 {
        (on_shift, off_shift)
    } else {
        (off_shift, on_shift)
    };
    let first = switch.first_on_position + first_shift;
    let last = switch.last_on_position + last_shift;
    match period {
        Some(period) => {
            let length = (switch.last_on_position - switch.first_on_position).rem_euclid(period)
                + last_shift
                - first_shift;
            if length <= 0.0 {
                return false;
            }
            if length >= period {
                return true;
            }
            let offset = if direction > 0.0 {
                (position - first).rem_euclid(period)
            } else {
                (last - position).rem_euclid(period)
            };
            offset < length
        }
        None if direction > 0.0 => first <= position && position < last,
        None => first < position && position <= last,
    }
}

/// Whether the motion from `previous` to `position` (less than half a period on a modulo axis)
/// passed `point`: `previous < point ≤ position` moving up, `position ≤ point < previous` down.
fn crosses(previous: f64, position: f64, point: f64, period: Option<f64>) -> bool {
    let moved = distance(previous, position, period);
    if moved == 0.0 {
        return false;
    }
    let ahead = match period {
        Some(period) => {
            if moved > 0.0 {
                (point - previous).rem_euclid(period)
            } else {
                -(previous - point).rem_euclid(period)
            }
        }
        None => point - previous,
    };
    if moved > 0.0 {
        ahead > 0.0 && ahead <= moved
    } else {
        ahead < 0.0 && ahead >= moved
    }
}
