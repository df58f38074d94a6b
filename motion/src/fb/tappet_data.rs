//! SMC_TappetData: the tappet outputs of a coupling, as MC_CamIn hands them to
//! SMC_GetTappetValue.

use crate::curve::CamCurve;
use crate::sync::{CamId, CouplingStatus};
use crate::tappet::{
    MasterWrap, TappetCycle, TappetError, TappetEvaluator, TappetSwitch, TappetTrack,
};

/// What a coupling about to start does with its tappets.
#[derive(Clone, Debug)]
pub(crate) enum PreparedTappets {
    /// Restart the evaluator the data already has.
    Restart,
    /// Replace it by a new one built for the given cam, periodicity and hysteresis.
    New(Box<TappetEvaluator>, (CamId, bool, u64)),
}

/// `SMC_TappetData`: the tappet evaluator of one MC_CamIn instance. MC_CamIn evaluates it at
/// every call on the cam master coordinate of its coupling, with the wrap of the coordinate
/// at the period end taken as a continued motion; read it with [`TappetData::output`] or
/// through SMC_GetTappetValue.
#[derive(Clone, Debug, Default)]
pub struct TappetData {
    /// The evaluator, once a coupling has started.
    evaluator: Option<TappetEvaluator>,
    /// The cam and the hysteresis the evaluator was built for, to reuse it on a restart.
    built_for: Option<(CamId, bool, u64)>,
    /// Counts the evaluators built, so SMC_GetTappetValue sees a new one.
    generation: u64,
    /// The cam master coordinate and period index at the last evaluation.
    last: Option<(f64, i64)>,
}

impl TappetData {
    /// The output of track `track_id`, `None` without such a track or before the first
    /// coupling.
    #[must_use]
    pub fn output(&self, track_id: u16) -> Option<bool> {
        self.evaluator.as_ref()?.output(track_id)
    }

    /// Every track's ID and output in the order of the cam's tracks.
    pub fn outputs(&self) -> impl Iterator<Item = (u16, bool)> + '_ {
        self.evaluator.iter().flat_map(TappetEvaluator::outputs)
    }

    /// The switches of the last evaluation.
    #[must_use]
    pub fn switches(&self) -> &[TappetSwitch] {
        self.evaluator
            .as_ref()
            .map_or(&[], TappetEvaluator::switches)
    }

    /// How many evaluators were built so far; it changes when a coupling starts with another
    /// cam or another hysteresis, not when the same one restarts.
    #[must_use]
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// The evaluator, for SMC_GetTappetValue.
    pub(crate) fn evaluator_mut(&mut self) -> Option<&mut TappetEvaluator> {
        self.evaluator.as_mut()
    }

    /// Prepares the tappets of a coupling about to start: the same cam, periodicity and
    /// hysteresis restart the evaluator in place, anything else builds a new one. Nothing
    /// changes until [`TappetData::begin`] takes the result, so a refused coupling leaves the
    /// tappets as they were. A `hysteresis` other than 0 replaces the hysteresis of every track.
    pub(crate) fn prepare(
        &self,
        cam: CamId,
        curve: &dyn CamCurve,
        tracks: &[TappetTrack],
        periodic: bool,
        hysteresis: f64,
    ) -> Result<PreparedTappets, TappetError> {
        let key = (cam, periodic, hysteresis.to_bits());
        if self.built_for == Some(key) && self.evaluator.is_some() {
            return Ok(PreparedTappets::Restart);
        }
        let (start, end) = curve.master_range();
        let tracks = tracks
            .iter()
            .map(|track| {
                let mut track = track.clone();
                if hysteresis != 0.0 {
                    track.hysteresis = hysteresis;
                }
                track
            })
            .collect();
        let evaluator = TappetEvaluator::new(start, end, periodic, tracks)?;
        Ok(PreparedTappets::New(Box::new(evaluator), key))
    }

    /// A coupling started (MC_CamIn executed): takes what [`TappetData::prepare`] made. A
    /// restart sets the outputs back to their initial value where the track asks for it.
    pub(crate) fn begin(&mut self, prepared: PreparedTappets) {
        self.last = None;
        match prepared {
            PreparedTappets::Restart => {
                if let Some(evaluator) = &mut self.evaluator {
                    evaluator.restart();
                }
            }
            PreparedTappets::New(evaluator, key) => {
                self.evaluator = Some(*evaluator);
                self.built_for = Some(key);
                self.generation += 1;
            }
        }
    }

    /// Evaluates the motion of the cam master coordinate since the last evaluation.
    pub(crate) fn evaluate(&mut self, status: &CouplingStatus, now_s: f64) {
        let Some(evaluator) = &mut self.evaluator else {
            return;
        };
        let current = (status.cam_master, status.period_index);
        let (prev_master, wrap) = match self.last {
            None => (status.cam_master, MasterWrap::None),
            Some((previous, index)) => match status.period_index - index {
                0 => (previous, MasterWrap::None),
                1 => (previous, MasterWrap::Forward),
                -1 => (previous, MasterWrap::Backward),
                // More than one period since the last evaluation is a jump: nothing fires.
                _ => (f64::NAN, MasterWrap::None),
            },
        };
        self.last = Some(current);
        evaluator.evaluate(&TappetCycle {
            prev_master,
            master: status.cam_master,
            wrap,
            master_velocity: status.cam_master_velocity,
            now_s,
        });
    }
}
