//! One track while the evaluator runs: its output, its running timed switch, the hysteresis
//! of each tappet and the dead-time shift of the previous cycle.

use super::{PassDirection, SwitchCause, TappetAction, TappetSwitch, TappetTrack};

/// A tappet that switched recently: the opposite switch waits until the master is more than the
/// hysteresis away from `image`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Hold {
    /// The direction of the switch that set the hold.
    direction: PassDirection,
    /// Where the tappet was passed, in the unwrapped coordinate of the current cycle.
    image: f64,
}

/// The geometry of the cam master coordinate the tappets live on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct MasterAxis {
    /// The master period (end − start).
    pub(crate) period: f64,
    /// Whether the tappets repeat every period.
    pub(crate) periodic: bool,
}

/// The motion of the compensated coordinate in one cycle, from `from` to `to`, in the frame of
/// the previous master coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Motion {
    /// Where the compensated coordinate was.
    pub(crate) from: f64,
    /// Where it is now.
    pub(crate) to: f64,
}

/// A tappet action due in this cycle, at `distance` along the motion.
struct Firing {
    /// Distance from the start of the motion, to act in the order the master reaches tappets.
    distance: f64,
    /// The tappet's index in the track.
    tappet_index: usize,
    /// The direction of the pass.
    direction: PassDirection,
    /// What to do.
    action: TappetAction,
}

/// A track with everything the evaluator keeps about it between cycles.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TrackState {
    /// The configuration.
    pub(crate) track: TappetTrack,
    /// The BOOL output.
    pub(crate) output: bool,
    /// When a running timed switch ends, in seconds.
    off_at_s: Option<f64>,
    /// The dead-time shift v·t of the previous cycle; `None` before the first cycle.
    pub(crate) last_shift: Option<f64>,
    /// The hold of each tappet, by index.
    holds: Vec<Option<Hold>>,
}

impl TrackState {
    /// A track before its first cycle, with its initial output.
    pub(crate) fn new(track: TappetTrack) -> Self {
        let holds = vec![None; track.tappets.len()];
        Self {
            output: track.initial_value,
            off_at_s: None,
            last_shift: None,
            holds,
            track,
        }
    }

    /// Forgets the motion so far (a restart or a jump): no holds, no previous shift.
    pub(crate) fn forget_motion(&mut self) {
        self.holds.iter_mut().for_each(|hold| *hold = None);
        self.last_shift = None;
    }

    /// A restart of the coupling: the output goes back to its initial value if the track says
    /// so (and a running timed switch with it), and the motion is forgotten.
    pub(crate) fn restart(&mut self) {
        if self.track.reset_to_initial {
            self.output = self.track.initial_value;
            self.off_at_s = None;
        }
        self.forget_motion();
    }

    /// Ends a timed switch whose time is up at `now_s`.
    pub(crate) fn expire_timer(&mut self, now_s: f64, switches: &mut Vec<TappetSwitch>) {
        if self.off_at_s.is_some_and(|off_at_s| now_s >= off_at_s) {
            self.off_at_s = None;
            self.output = false;
            switches.push(TappetSwitch {
                track_id: self.track.id,
                cause: SwitchCause::TimeElapsed,
                output: false,
            });
        }
    }

    /// Applies every pass of `motion` in the order the master reaches the tappets, then moves
    /// the holds by `frame_shift` into the frame of the next cycle.
    pub(crate) fn apply_motion(
        &mut self,
        axis: MasterAxis,
        motion: Motion,
        frame_shift: f64,
        now_s: f64,
        switches: &mut Vec<TappetSwitch>,
    ) {
        let mut firings = Vec::new();
        if motion.to != motion.from {
            let direction = if motion.to > motion.from {
                PassDirection::Positive
            } else {
                PassDirection::Negative
            };
            for tappet_index in 0..self.track.tappets.len() {
                self.tappet_firings(axis, motion, direction, tappet_index, &mut firings);
            }
        }
        firings.sort_by(|a, b| {
            a.distance
                .total_cmp(&b.distance)
                .then(a.tappet_index.cmp(&b.tappet_index))
        });
        for firing in firings {
            self.act(firing.action, now_s);
            switches.push(TappetSwitch {
                track_id: self.track.id,
                cause: SwitchCause::Pass {
                    tappet_index: firing.tappet_index,
                    direction: firing.direction,
                },
                output: self.output,
            });
        }
        for hold in self.holds.iter_mut().flatten() {
            hold.image -= frame_shift;
        }
    }

    /// Collects the switches of one tappet during `motion` and updates its hold.
    fn tappet_firings(
        &mut self,
        axis: MasterAxis,
        motion: Motion,
        direction: PassDirection,
        tappet_index: usize,
        firings: &mut Vec<Firing>,
    ) {
        let tappet = self.track.tappets[tappet_index];
        let action = match direction {
            PassDirection::Positive => tappet.on_positive,
            PassDirection::Negative => tappet.on_negative,
        };
        let hysteresis = self.track.hysteresis;
        let sign = direction.sign();
        let beyond = |x: f64, mark: f64| sign * (x - mark) > 0.0;
        let mut from = motion.from;
        let mut hold = self.holds[tappet_index];
        // Each turn of the loop handles one event along the motion; the motion spans at most one
        // period, so a tappet has at most two images in it and the loop ends after a few turns.
        loop {
            match hold {
                Some(held) => {
                    // Passes over the held image itself are repeats of the switch and stay
                    // suppressed; what counts is leaving the hysteresis band.
                    let band_edge = held.image + sign * hysteresis;
                    if !beyond(motion.to, band_edge) {
                        break;
                    }
                    hold = None;
                    if held.direction != direction && action != TappetAction::None {
                        firings.push(Firing {
                            distance: sign * (band_edge - motion.from),
                            tappet_index,
                            direction,
                            action,
                        });
                    }
                    from = band_edge;
                }
                None => {
                    let Some(image) =
                        first_image_passed(axis, tappet.position, from, motion.to, sign)
                    else {
                        break;
                    };
                    if action != TappetAction::None {
                        firings.push(Firing {
                            distance: sign * (image - motion.from),
                            tappet_index,
                            direction,
                            action,
                        });
                        if hysteresis > 0.0 {
                            hold = Some(Hold { direction, image });
                        }
                    }
                    from = image;
                }
            }
        }
        self.holds[tappet_index] = hold;
    }

    /// Carries out one tappet action at time `now_s`.
    fn act(&mut self, action: TappetAction, now_s: f64) {
        // Only a timed switch keeps a timer running; any other action takes over the output.
        self.off_at_s = None;
        match action {
            TappetAction::None => {}
            TappetAction::On => self.output = true,
            TappetAction::Off => self.output = false,
            TappetAction::Invert => self.output = !self.output,
            TappetAction::TimedOn { duration_s } => {
                self.output = true;
                self.off_at_s = Some(now_s + duration_s);
            }
        }
    }
}

/// The first position of the tappet at `position` (or of its repetition one period away, on a
/// periodic axis) that the master passes moving from `from` to `to`: `from < X ≤ to` moving
/// up, `to ≤ X < from` moving down (`sign` −1).
fn first_image_passed(
    axis: MasterAxis,
    position: f64,
    from: f64,
    to: f64,
    sign: f64,
) -> Option<f64> {
    let passed = |image: f64| sign * (image - from) > 0.0 && sign * (to - image) >= 0.0;
    if !axis.periodic {
        return passed(position).then_some(position);
    }
    // The first repetition at or beyond `from` in the direction of motion; one more step covers
    // the case where rounding put it exactly on `from`, which does not count as passed.
    let periods = ((from - position) / axis.period).floor();
    let base = position + periods * axis.period;
    let candidates = if sign > 0.0 {
        [base, base + axis.period, base + 2.0 * axis.period]
    } else {
        [base + axis.period, base, base - axis.period]
    };
    candidates.into_iter().find(|&image| passed(image))
}
