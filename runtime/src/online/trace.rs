//! The trace recorder: samples places at the end of every n-th cycle of one task into a ring,
//! with an optional trigger and a pre-trigger part.

use std::collections::VecDeque;

pub use online_protocol::TraceState;
use online_protocol::{Place, TraceConfig, TriggerKind};

/// The most bytes a trace's ring may hold (samples × their size with cycle and time).
pub const MAX_TRACE_BYTES: u64 = 32 * 1024 * 1024;

/// One sample: the cycle it was taken at and the places' bytes in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sample {
    /// The task's cycle count at the sample.
    pub cycle: u64,
    /// The task clock at the start of the sample's cycle.
    pub time_ns: u64,
    /// The values of the configured places, in order.
    pub values: Vec<u8>,
}

/// The recorder; lives in the scheduler's thread, is reset by a download, never saved.
#[derive(Debug)]
pub struct Trace {
    config: Option<TraceConfig>,
    state: TraceState,
    ring: VecDeque<Sample>,
    /// The index in `ring` of the sample at the trigger.
    trigger_index: Option<usize>,
    /// Cycles of the traced task seen since arming.
    cycles_seen: u64,
    /// The trigger's value at the previous sample.
    previous_trigger: Option<bool>,
    /// Samples still to record after the trigger.
    remaining: u32,
}

impl Default for Trace {
    fn default() -> Self {
        Self {
            config: None,
            state: TraceState::Unconfigured,
            ring: VecDeque::new(),
            trigger_index: None,
            cycles_seen: 0,
            previous_trigger: None,
            remaining: 0,
        }
    }
}

impl Trace {
    /// The bytes of one sample's values under `config`.
    pub fn sample_bytes(config: &TraceConfig) -> usize {
        config
            .places
            .iter()
            .map(|place| usize::from(place.size))
            .sum()
    }

    /// The configuration, armed or not.
    pub fn config(&self) -> Option<&TraceConfig> {
        self.config.as_ref()
    }

    /// The configuration, when it is configured and not armed yet.
    pub fn pending_config(&self) -> Option<&TraceConfig> {
        match self.state {
            TraceState::Configured => self.config.as_ref(),
            _ => None,
        }
    }

    /// Replaces the configuration (whose places the caller has checked) and drops the samples.
    pub fn configure(&mut self, config: TraceConfig) {
        *self = Self {
            config: Some(config),
            state: TraceState::Configured,
            ..Self::default()
        };
    }

    /// Forgets the configuration and the samples (after a download, whose places differ).
    pub fn unconfigure(&mut self) {
        *self = Self::default();
    }

    /// Moves the trace's places to their variables' places after an online change, as
    /// `moved` gives them, and goes on recording; when one is gone or changed type (`moved`
    /// gives `None`), forgets the trace as a download does. Returns whether it was removed.
    pub fn follow(&mut self, moved: impl Fn(Place) -> Option<Place>) -> bool {
        let Some(config) = self.config.as_mut() else {
            return false;
        };
        let places: Option<Vec<Place>> = config.places.iter().map(|&place| moved(place)).collect();
        let trigger = match config.trigger {
            TriggerKind::None => Some(config.trigger_place),
            _ => moved(config.trigger_place),
        };
        match (places, trigger) {
            (Some(places), Some(trigger)) => {
                config.places = places;
                config.trigger_place = trigger;
                false
            }
            _ => {
                self.unconfigure();
                true
            }
        }
    }

    /// Drops the samples and starts recording; false without a configuration.
    pub fn arm(&mut self) -> bool {
        let Some(config) = self.config.take() else {
            return false;
        };
        self.configure(config);
        self.state = TraceState::Armed;
        true
    }

    /// The state, the samples recorded, and the index of the trigger's sample.
    pub fn status(&self) -> (TraceState, u32, Option<u32>) {
        (
            self.state,
            u32::try_from(self.ring.len()).unwrap_or(u32::MAX),
            self.trigger_index
                .map(|index| u32::try_from(index).unwrap_or(u32::MAX)),
        )
    }

    /// The recorded samples, oldest first.
    pub fn samples(&self) -> impl Iterator<Item = &Sample> {
        self.ring.iter()
    }

    /// The configured task, if the recorder is recording.
    pub fn recording_task(&self) -> Option<usize> {
        match self.state {
            TraceState::Armed | TraceState::Triggered => {
                self.config.as_ref().map(|config| usize::from(config.task))
            }
            _ => None,
        }
    }

    /// Called at the end of each cycle of the traced task: takes a sample every n-th cycle,
    /// reading places with `read`.
    pub fn end_of_cycle(&mut self, cycle: u64, time_ns: u64, read: impl Fn(Place) -> Vec<u8>) {
        let Some(config) = &self.config else {
            return;
        };
        if !matches!(self.state, TraceState::Armed | TraceState::Triggered) {
            return;
        }
        self.cycles_seen += 1;
        if !(self.cycles_seen - 1).is_multiple_of(u64::from(config.every)) {
            return;
        }
        let values = config
            .places
            .iter()
            .flat_map(|&place| read(place))
            .collect();
        let sample = Sample {
            cycle,
            time_ns,
            values,
        };
        let samples = config.samples as usize;
        if self.state == TraceState::Triggered {
            self.ring.push_back(sample);
            self.remaining = self.remaining.saturating_sub(1);
            if self.remaining == 0 {
                self.state = TraceState::Complete;
            }
            return;
        }
        if config.trigger == TriggerKind::None {
            self.ring.push_back(sample);
            if self.ring.len() >= samples {
                self.state = TraceState::Complete;
            }
            return;
        }
        // At least the trigger's own sample comes after the pre-trigger part.
        let pre = (samples * usize::from(config.pretrigger) / 100).min(samples - 1);
        let level = read(config.trigger_place).iter().any(|&byte| byte != 0);
        let fired = match config.trigger {
            TriggerKind::None => false,
            TriggerKind::Rising => self.previous_trigger == Some(false) && level,
            TriggerKind::Falling => self.previous_trigger == Some(true) && !level,
            TriggerKind::WhileTrue => level,
        };
        self.previous_trigger = Some(level);
        if fired {
            self.trigger_index = Some(self.ring.len());
            self.ring.push_back(sample);
            self.remaining = (samples - pre - 1) as u32;
            self.state = if self.remaining == 0 {
                TraceState::Complete
            } else {
                TraceState::Triggered
            };
            return;
        }
        self.ring.push_back(sample);
        while self.ring.len() > pre {
            self.ring.pop_front();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const VALUE: Place = Place {
        region: 0,
        offset: 0,
        bit: None,
        size: 1,
    };
    const TRIGGER: Place = Place {
        region: 0,
        offset: 1,
        bit: None,
        size: 1,
    };

    fn config(trigger: TriggerKind, samples: u32, pretrigger: u8, every: u16) -> TraceConfig {
        TraceConfig {
            task: 0,
            every,
            samples,
            pretrigger,
            trigger,
            trigger_place: TRIGGER,
            places: vec![VALUE],
        }
    }

    /// Runs cycles 1..=`cycles` where the value is the cycle and the trigger is set from
    /// cycle `trigger_from` to `trigger_to`.
    fn run(trace: &mut Trace, cycles: u64, trigger_from: u64, trigger_to: u64) {
        for cycle in 1..=cycles {
            let set = (trigger_from..=trigger_to).contains(&cycle);
            trace.end_of_cycle(cycle, cycle * 10, |place| {
                if place == TRIGGER {
                    vec![u8::from(set)]
                } else {
                    vec![cycle as u8]
                }
            });
        }
    }

    fn cycles(trace: &Trace) -> Vec<u64> {
        trace.samples().map(|sample| sample.cycle).collect()
    }

    #[test]
    fn after_an_online_change_the_trace_follows_its_places_or_is_removed() {
        let mut trace = Trace::default();
        trace.configure(config(TriggerKind::Rising, 4, 50, 1));
        assert!(trace.arm());
        run(&mut trace, 2, 9, 9);
        let moved = |place: Place| {
            Some(Place {
                offset: place.offset + 100,
                ..place
            })
        };
        assert!(!trace.follow(moved));
        let config = trace.config().unwrap();
        assert_eq!(
            (config.places[0].offset, config.trigger_place.offset),
            (100, 101)
        );
        // Still armed, with the samples taken before the change.
        assert_eq!(trace.status().0, TraceState::Armed);
        assert_eq!(cycles(&trace), [1, 2]);

        let trigger_gone = |place: Place| (place.offset != 101).then_some(place);
        assert!(trace.follow(trigger_gone));
        assert_eq!(trace.status().0, TraceState::Unconfigured);
    }

    #[test]
    fn without_a_trigger_every_nth_cycle_is_sampled_until_complete() {
        let mut trace = Trace::default();
        trace.configure(config(TriggerKind::None, 4, 50, 3));
        run(&mut trace, 5, 0, 0);
        assert_eq!(trace.status().0, TraceState::Configured);
        assert!(trace.arm());
        run(&mut trace, 20, 0, 0);
        assert_eq!(cycles(&trace), [1, 4, 7, 10]);
        assert_eq!(trace.status(), (TraceState::Complete, 4, None));
    }

    #[test]
    fn a_rising_trigger_keeps_the_pretrigger_part_and_stops_after_the_rest() {
        let mut trace = Trace::default();
        trace.configure(config(TriggerKind::Rising, 10, 30, 1));
        trace.arm();
        run(&mut trace, 50, 20, 50);
        assert_eq!(cycles(&trace), (17..=26).collect::<Vec<_>>());
        assert_eq!(trace.status(), (TraceState::Complete, 10, Some(3)));
    }

    #[test]
    fn a_trigger_set_from_the_start_is_no_rising_edge_but_a_level() {
        let mut rising = Trace::default();
        rising.configure(config(TriggerKind::Rising, 4, 0, 1));
        rising.arm();
        run(&mut rising, 10, 1, 10);
        assert_eq!(rising.status(), (TraceState::Armed, 0, None));

        let mut level = Trace::default();
        level.configure(config(TriggerKind::WhileTrue, 4, 50, 1));
        level.arm();
        run(&mut level, 10, 3, 10);
        assert_eq!(cycles(&level), [1, 2, 3, 4]);
        assert_eq!(level.status(), (TraceState::Complete, 4, Some(2)));
    }

    #[test]
    fn a_falling_trigger_fires_when_the_place_goes_false() {
        let mut trace = Trace::default();
        trace.configure(config(TriggerKind::Falling, 3, 100, 1));
        trace.arm();
        run(&mut trace, 10, 1, 5);
        // 100 % before the trigger still records the trigger's own sample.
        assert_eq!(cycles(&trace), [4, 5, 6]);
        assert_eq!(trace.status(), (TraceState::Complete, 3, Some(2)));
    }
}
