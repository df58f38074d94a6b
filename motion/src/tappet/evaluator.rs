//! The tappet evaluator of one cam.

use super::track_state::{MasterAxis, Motion, TrackState};
use super::{MasterWrap, TappetAction, TappetCycle, TappetError, TappetSwitch, TappetTrack};

/// Evaluates the tappet tracks of one cam once per task cycle and keeps one BOOL per track.
#[derive(Clone, Debug, PartialEq)]
pub struct TappetEvaluator {
    /// The master period and whether the tappets repeat.
    axis: MasterAxis,
    /// The tracks in the order given.
    tracks: Vec<TrackState>,
    /// The switches of the last evaluated cycle.
    switches: Vec<TappetSwitch>,
}

impl TappetEvaluator {
    /// An evaluator for tappets on the master range `master_start..=master_end`, repeating every
    /// period if `periodic`. Each output starts at its track's initial value.
    ///
    /// Fails naming the track and tappet when a track ID repeats, a tappet lies outside the
    /// range, a hysteresis is negative or not below half the period, a dead time is not finite
    /// or a timed switch does not last a positive time.
    pub fn new(
        master_start: f64,
        master_end: f64,
        periodic: bool,
        tracks: Vec<TappetTrack>,
    ) -> Result<Self, TappetError> {
        if !(master_start.is_finite() && master_end.is_finite() && master_start < master_end) {
            return Err(TappetError::InvalidMasterRange {
                start: master_start,
                end: master_end,
            });
        }
        let period = master_end - master_start;
        for (index, track) in tracks.iter().enumerate() {
            if tracks[..index].iter().any(|other| other.id == track.id) {
                return Err(TappetError::DuplicateTrack { id: track.id });
            }
            check_track(track, master_start, master_end)?;
        }
        Ok(Self {
            axis: MasterAxis { period, periodic },
            tracks: tracks.into_iter().map(TrackState::new).collect(),
            switches: Vec::new(),
        })
    }

    /// Evaluates one task cycle and returns the switches that happened in it, in track order
    /// and, within a track, in the order the master reached the tappets.
    ///
    /// A cycle whose values are not finite, or that moves the compensated coordinate by more
    /// than one master period, is a jump (such as `MC_SetPosition`): no tappet fires and the
    /// hysteresis is forgotten. Timed switches still run out.
    pub fn evaluate(&mut self, cycle: &TappetCycle) -> &[TappetSwitch] {
        self.switches.clear();
        let wrap_offset = match cycle.wrap {
            MasterWrap::None => 0.0,
            MasterWrap::Forward => self.axis.period,
            MasterWrap::Backward => -self.axis.period,
        };
        let inputs_finite = [cycle.prev_master, cycle.master, cycle.master_velocity]
            .iter()
            .all(|value| value.is_finite());
        for state in &mut self.tracks {
            state.expire_timer(cycle.now_s, &mut self.switches);
            let shift = cycle.master_velocity * state.track.dead_time_s;
            if !inputs_finite || !shift.is_finite() {
                state.forget_motion();
                continue;
            }
            let previous_shift = state.last_shift.unwrap_or(shift);
            // The motion is unwrapped into the frame of the previous coordinate, so a wrap at the
            // period end is one continued motion, never a pass in the other direction.
            let motion = Motion {
                from: cycle.prev_master + previous_shift,
                to: cycle.master + wrap_offset + shift,
            };
            if (motion.to - motion.from).abs() > self.axis.period {
                state.forget_motion();
                state.last_shift = Some(shift);
                continue;
            }
            state.last_shift = Some(shift);
            state.apply_motion(
                self.axis,
                motion,
                wrap_offset,
                cycle.now_s,
                &mut self.switches,
            );
        }
        &self.switches
    }

    /// The output of track `track_id` (`SMC_GetTappetValue.bTappet`), or `None` if there is no
    /// such track.
    pub fn output(&self, track_id: u16) -> Option<bool> {
        self.tracks
            .iter()
            .find(|state| state.track.id == track_id)
            .map(|state| state.output)
    }

    /// Every track's ID and output, in the order the tracks were given.
    pub fn outputs(&self) -> impl Iterator<Item = (u16, bool)> + '_ {
        self.tracks
            .iter()
            .map(|state| (state.track.id, state.output))
    }

    /// Sets the initial value of track `track_id` and whether a restart returns to it
    /// (`SMC_GetTappetValue.bInitValue` and `bSetInitValueAtReset`), and sets the track's output
    /// to that value now, as the first call of SMC_GetTappetValue does. Returns FALSE when
    /// there is no such track.
    pub fn set_initial_value(
        &mut self,
        track_id: u16,
        initial_value: bool,
        reset_to_initial: bool,
    ) -> bool {
        match self
            .tracks
            .iter_mut()
            .find(|state| state.track.id == track_id)
        {
            Some(state) => {
                state.track.initial_value = initial_value;
                state.track.reset_to_initial = reset_to_initial;
                state.output = initial_value;
                true
            }
            None => false,
        }
    }

    /// The switches of the last evaluated cycle.
    pub fn switches(&self) -> &[TappetSwitch] {
        &self.switches
    }

    /// A restart of the coupling (`MC_CamIn` executed again): tracks that reset to their initial
    /// value do so, the others keep their output; hysteresis and the previous cycle are
    /// forgotten.
    pub fn restart(&mut self) {
        self.switches.clear();
        self.tracks.iter_mut().for_each(TrackState::restart);
    }
}

/// Checks one track's settings against the master range.
fn check_track(track: &TappetTrack, start: f64, end: f64) -> Result<(), TappetError> {
    let half_period = (end - start) / 2.0;
    if !(track.hysteresis >= 0.0 && track.hysteresis < half_period) {
        return Err(TappetError::InvalidHysteresis {
            track: track.id,
            hysteresis: track.hysteresis,
            half_period,
        });
    }
    if !track.dead_time_s.is_finite() {
        return Err(TappetError::InvalidDeadTime {
            track: track.id,
            dead_time_s: track.dead_time_s,
        });
    }
    for (index, tappet) in track.tappets.iter().enumerate() {
        let row = index + 1;
        if !(tappet.position >= start && tappet.position <= end) {
            return Err(TappetError::TappetOutsideRange {
                track: track.id,
                row,
                position: tappet.position,
                start,
                end,
            });
        }
        for action in [tappet.on_positive, tappet.on_negative] {
            if let TappetAction::TimedOn { duration_s } = action
                && !(duration_s.is_finite() && duration_s > 0.0)
            {
                return Err(TappetError::InvalidDuration {
                    track: track.id,
                    row,
                    duration_s,
                });
            }
        }
    }
    Ok(())
}
