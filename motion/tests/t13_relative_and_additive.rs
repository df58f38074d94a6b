//! PLCopen Fig. 19/20 (digest T13): MC_MoveRelative and MC_MoveAdditive chained and aborting.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{assert_close, powered, roomy_linear, run, snap};
use motion::fb::{MoveAdditive, MoveRelative};
use motion::kernel::{AxisId, Kernel};

/// The second FB of the examples: MC_MoveRelative or MC_MoveAdditive.
enum Second {
    Relative(MoveRelative),
    Additive(MoveAdditive),
}

impl Second {
    fn new(additive: bool) -> Self {
        if additive {
            let mut fb = MoveAdditive::default();
            fb.distance = 4000.0;
            fb.velocity = 1000.0;
            fb.acceleration = 10_000.0;
            fb.deceleration = 10_000.0;
            Self::Additive(fb)
        } else {
            let mut fb = MoveRelative::default();
            fb.distance = 4000.0;
            fb.velocity = 1000.0;
            fb.acceleration = 10_000.0;
            fb.deceleration = 10_000.0;
            Self::Relative(fb)
        }
    }

    fn call(&mut self, execute: bool, kernel: &mut Kernel, axis: AxisId) {
        match self {
            Self::Relative(fb) => {
                fb.execute = execute;
                fb.call(kernel, axis);
            }
            Self::Additive(fb) => {
                fb.execute = execute;
                fb.call(kernel, axis);
            }
        }
    }

    fn done(&self) -> bool {
        match self {
            Self::Relative(fb) => fb.done,
            Self::Additive(fb) => fb.done,
        }
    }
}

fn first() -> MoveRelative {
    let mut fb = MoveRelative::default();
    fb.execute = true;
    fb.distance = 6000.0;
    fb.velocity = 1000.0;
    fb.acceleration = 10_000.0;
    fb.deceleration = 10_000.0;
    fb
}

#[test]
fn a_second_move_triggered_by_done_of_the_first_ends_at_10000() {
    for additive in [false, true] {
        let (mut kernel, axis) = powered(roomy_linear());
        let mut fb1 = first();
        let mut fb2 = Second::new(additive);
        let mut fb1_done_seen = false;
        run(&mut kernel, axis, 12_000, |kernel, _| {
            fb1.call(kernel, axis);
            fb1_done_seen |= fb1.done;
            fb2.call(fb1.done, kernel, axis);
        });
        assert!(fb1_done_seen, "additive {additive}: FB1 never Done");
        assert!(fb2.done(), "additive {additive}: FB2 not Done");
        assert_close(snap(&kernel, axis).set_position, 10_000.0);
    }
}

#[test]
fn aborting_at_3250_gives_7250_for_relative_and_10000_for_additive() {
    for (additive, expected) in [(false, 7250.0), (true, 10_000.0)] {
        let (mut kernel, axis) = powered(roomy_linear());
        let mut fb1 = first();
        let mut fb2 = Second::new(additive);
        let mut trigger: Option<f64> = None;
        run(&mut kernel, axis, 12_000, |kernel, _| {
            fb1.call(kernel, axis);
            if trigger.is_some() {
                // From the call after FB2 took over, FB1 shows CommandAborted alone.
                assert!(fb1.command_aborted && !fb1.busy && !fb1.done && !fb1.error);
            }
            let position = snap(kernel, axis).set_position;
            if trigger.is_none() && position >= 3250.0 - 1e-6 {
                trigger = Some(position);
                // FB1 runs at constant velocity here, as in the figure.
                assert_close(snap(kernel, axis).set_velocity, 1000.0);
            }
            fb2.call(trigger.is_some(), kernel, axis);
        });
        let trigger = trigger.expect("the axis never reached 3250");
        assert_close(trigger, 3250.0);
        assert!(fb2.done());
        let end = snap(&kernel, axis).set_position;
        assert_close(end, expected);
        if !additive {
            assert_close(end, trigger + 4000.0);
        }
    }
}
