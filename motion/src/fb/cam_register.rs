//! SMC_CamRegister.

use crate::axis::AxisState;
use crate::kernel::{AxisId, Kernel, MotionError};
use crate::sync::CamId;
use crate::tappet::{MasterWrap, TappetCycle, TappetEvaluator};

/// SMC_CamRegister: the tappets of a cam on a master without a slave (a cam switch controller).
///
/// While `Enable` is TRUE the cam master coordinate `X = MasterScaling·M + MasterOffset` of the
/// master's set position is followed from call to call (a modulo master is unwrapped) and taken
/// periodically into the cam's master range; the tappets are evaluated on it with the wrap at
/// the period end as a continued motion. `TappetHysteresis` and `DeadTimeCompensation` other
/// than 0 replace the values of every track. The outputs are per track ID ([`CamRegister::tappet`],
/// `bTappet` indexed by track ID as the digest recommends). `EndOfProfile` is TRUE for one call
/// each time X passes the period end (or, backwards, the start). A rising `Enable`, or a change
/// of the cam or of those two inputs, builds the evaluator anew with the tracks' initial values.
/// Errors: unknown master or cam, master not powered or in ErrorStop, scaling 0 or offsets not
/// finite, a hysteresis of half the period or more.
#[derive(Clone, Debug)]
pub struct CamRegister {
    /// `Enable`: evaluate while TRUE.
    pub enable: bool,
    /// `MasterOffset` in cam master units.
    pub master_offset: f64,
    /// `MasterScaling`, 1.0 by default; must not be 0.
    pub master_scaling: f64,
    /// `TappetHysteresis` in cam master units; 0 keeps the tracks' own.
    pub tappet_hysteresis: f64,
    /// `DeadTimeCompensation` in seconds, signed; 0 keeps the tracks' own.
    pub dead_time_compensation_s: f64,
    /// `Busy`: the tappets are evaluated.
    pub busy: bool,
    /// `Error`: see the type's documentation.
    pub error: bool,
    /// `ErrorID`: the [`MotionError::id`] of the error, 0 without error.
    pub error_id: u16,
    /// The error behind `ErrorID`, for a readable message.
    pub error_cause: Option<MotionError>,
    /// `EndOfProfile`: X passed the period end in this call.
    pub end_of_profile: bool,
    /// The evaluator and what it was built for.
    evaluator: Option<TappetEvaluator>,
    built_for: Option<(CamId, u64, u64)>,
    /// The unwrapped master position at the last call.
    master_unwrapped: f64,
    /// The master's set position at the last call.
    last_master: f64,
    /// The period index of X at the last call.
    last_index: Option<i64>,
    /// X at the last call.
    last_x: f64,
}

impl Default for CamRegister {
    fn default() -> Self {
        Self {
            enable: false,
            master_offset: 0.0,
            master_scaling: 1.0,
            tappet_hysteresis: 0.0,
            dead_time_compensation_s: 0.0,
            busy: false,
            error: false,
            error_id: 0,
            error_cause: None,
            end_of_profile: false,
            evaluator: None,
            built_for: None,
            master_unwrapped: 0.0,
            last_master: 0.0,
            last_index: None,
            last_x: 0.0,
        }
    }
}

impl CamRegister {
    /// The output of track `track_id`, `None` before the first evaluation or without such a
    /// track.
    #[must_use]
    pub fn tappet(&self, track_id: u16) -> Option<bool> {
        self.evaluator.as_ref()?.output(track_id)
    }

    /// Every track's ID and output, in the order of the cam's tracks.
    pub fn tappets(&self) -> impl Iterator<Item = (u16, bool)> + '_ {
        self.evaluator.iter().flat_map(TappetEvaluator::outputs)
    }

    /// One call of the instance for `master` and the cam `cam`.
    pub fn call(&mut self, kernel: &Kernel, master: AxisId, cam: CamId) {
        self.end_of_profile = false;
        if !self.enable {
            self.busy = false;
            self.set_error(None);
            self.built_for = None;
            self.last_index = None;
            return;
        }
        let result = self.evaluate(kernel, master, cam);
        self.busy = result.is_ok();
        self.set_error(result.err());
    }

    fn set_error(&mut self, error: Option<MotionError>) {
        self.error = error.is_some();
        self.error_id = error.map_or(0, |error| error.id());
        self.error_cause = error;
    }

    fn evaluate(&mut self, kernel: &Kernel, master: AxisId, cam: CamId) -> Result<(), MotionError> {
        let snapshot = kernel.snapshot(master)?;
        match snapshot.state {
            AxisState::PowerOff => return Err(MotionError::NotPowered),
            AxisState::ErrorStop => return Err(MotionError::AxisInErrorStop),
            _ => {}
        }
        let scaling = self.master_scaling;
        if !(scaling.is_finite() && scaling != 0.0) {
            return Err(MotionError::InvalidParameter {
                input: "MasterScaling",
                value: scaling,
                reason: "a scaling must be a finite number other than 0",
            });
        }
        if !self.master_offset.is_finite() {
            return Err(MotionError::InvalidParameter {
                input: "MasterOffset",
                value: self.master_offset,
                reason: "it must be a finite number",
            });
        }
        let curve = kernel.cam(cam)?;
        let (start, end) = curve.master_range();
        let key = (
            cam,
            self.tappet_hysteresis.to_bits(),
            self.dead_time_compensation_s.to_bits(),
        );
        if self.built_for != Some(key) || self.evaluator.is_none() {
            let tracks = kernel
                .cam_tracks(cam)?
                .iter()
                .map(|track| {
                    let mut track = track.clone();
                    if self.tappet_hysteresis != 0.0 {
                        track.hysteresis = self.tappet_hysteresis;
                    }
                    if self.dead_time_compensation_s != 0.0 {
                        track.dead_time_s = self.dead_time_compensation_s;
                    }
                    track
                })
                .collect();
            let evaluator = TappetEvaluator::new(start, end, true, tracks).map_err(|_| {
                MotionError::InvalidParameter {
                    input: "TappetHysteresis",
                    value: self.tappet_hysteresis,
                    reason: "the hysteresis must be 0 or more and below half the cam's master period",
                }
            })?;
            self.evaluator = Some(evaluator);
            self.built_for = Some(key);
            self.last_index = None;
        }
        let position = snapshot.set_position;
        if self.last_index.is_none() {
            self.master_unwrapped = position;
        } else {
            let mut difference = position - self.last_master;
            if snapshot.modulo_period > 0.0 {
                difference = crate::sync::wrap_signed(difference, snapshot.modulo_period);
            }
            self.master_unwrapped += difference;
        }
        self.last_master = position;
        let period = end - start;
        let raw = scaling * self.master_unwrapped + self.master_offset;
        let wraps = ((raw - start) / period).floor();
        let x = raw - wraps * period;
        // The saturating cast only matters for masters beyond 2^63 periods.
        let index = wraps as i64;
        let now_s = kernel.axis_time_s(master)?;
        let (prev_master, wrap) = match self.last_index {
            None => (x, MasterWrap::None),
            Some(last) => match index - last {
                0 => (self.last_x, MasterWrap::None),
                1 => (self.last_x, MasterWrap::Forward),
                -1 => (self.last_x, MasterWrap::Backward),
                _ => (f64::NAN, MasterWrap::None),
            },
        };
        self.end_of_profile = self.last_index.is_some_and(|last| last != index);
        self.last_index = Some(index);
        self.last_x = x;
        if let Some(evaluator) = &mut self.evaluator {
            evaluator.evaluate(&TappetCycle {
                prev_master,
                master: x,
                wrap,
                master_velocity: scaling * snapshot.set_velocity,
                now_s,
            });
        }
        Ok(())
    }
}
