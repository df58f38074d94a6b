//! A property test of PLCopen general rule 2 under random programs: on every FB instance and
//! at every call, `Busy`, `Done`, `Error` and `CommandAborted` exclude each other (MC_Stop may
//! show `Done` with `Busy` while it holds the lock), `Active` implies `Busy`, one of them is TRUE
//! while `Execute` is TRUE, and a final output shown with `Execute` FALSE lasts one call.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use motion::axis::{AxisConfig, Direction};
use motion::fb::{
    Halt, Home, Jog, MoveAbsolute, MoveAdditive, MoveRelative, MoveVelocity, Reset, SetPosition,
    Stop,
};
use motion::kernel::{BufferMode, Kernel};
use proptest::prelude::*;

const DT_S: f64 = 0.002;

/// The outputs of one Execute-type call, as the checks need them.
#[derive(Clone, Copy, Debug, Default)]
struct Seen {
    execute: bool,
    busy: bool,
    active: bool,
    done: bool,
    error: bool,
    error_id: u16,
    aborted: bool,
}

/// What one program cycle does: which `Execute` inputs are TRUE and what else happens.
#[derive(Clone, Copy, Debug)]
struct Step {
    executes: u16,
    jog: u8,
    event: u8,
}

fn steps() -> impl Strategy<Value = Vec<Step>> {
    prop::collection::vec(
        (any::<u16>(), 0u8..4, 0u8..40).prop_map(|(executes, jog, event)| Step {
            executes,
            jog,
            event,
        }),
        1..400,
    )
}

#[track_caller]
fn check(name: &str, now: Seen, before: Seen, stop_lock: bool) {
    let terminal = [now.done, now.error, now.aborted]
        .iter()
        .filter(|flag| **flag)
        .count();
    let with_busy = terminal + usize::from(now.busy);
    if stop_lock && now.busy && now.done {
        assert!(!now.error && !now.aborted, "{name}: {now:?}");
    } else {
        assert!(with_busy <= 1, "{name}: {now:?}");
    }
    if now.active {
        assert!(
            now.busy && !now.done && !now.error && !now.aborted,
            "{name}: {now:?}"
        );
    }
    if now.execute {
        assert!(
            with_busy >= 1,
            "{name}: Execute TRUE without an output: {now:?}"
        );
    }
    assert_eq!(now.error, now.error_id != 0, "{name}: {now:?}");
    let before_terminal = before.done || before.error || before.aborted;
    if !now.execute && !before.execute && before_terminal && !before.busy {
        assert!(
            !now.done && !now.error && !now.aborted,
            "{name}: shown longer than one call: {before:?} then {now:?}"
        );
    }
}

macro_rules! seen {
    ($fb:expr, $execute:expr) => {
        Seen {
            execute: $execute,
            busy: $fb.busy,
            active: false,
            done: $fb.done,
            error: $fb.error,
            error_id: $fb.error_id,
            aborted: false,
        }
    };
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn the_outputs_of_every_instance_exclude_each_other(program in steps(), modulo in any::<bool>()) {
        let mut config = AxisConfig::linear(1000.0, 20_000.0, 20_000.0);
        if modulo {
            config.modulo_period = Some(10.0);
        }
        let mut kernel = Kernel::new();
        let axis = kernel.add_axis(config).unwrap();
        kernel.power(axis, true).unwrap();

        let mut absolute = MoveAbsolute::default();
        absolute.position = 3.0;
        absolute.direction = Direction::Positive;
        let mut relative = MoveRelative::default();
        relative.distance = -2.0;
        relative.buffer_mode = BufferMode::Buffered;
        let mut additive = MoveAdditive::default();
        additive.distance = 1.5;
        for (velocity, acceleration, deceleration) in [
            (&mut absolute.velocity, &mut absolute.acceleration, &mut absolute.deceleration),
            (&mut relative.velocity, &mut relative.acceleration, &mut relative.deceleration),
            (&mut additive.velocity, &mut additive.acceleration, &mut additive.deceleration),
        ] {
            *velocity = 200.0;
            *acceleration = 10_000.0;
            *deceleration = 10_000.0;
        }
        let mut velocity = MoveVelocity::default();
        velocity.velocity = 50.0;
        velocity.acceleration = 10_000.0;
        velocity.deceleration = 10_000.0;
        velocity.direction = Direction::Negative;
        let mut halt = Halt::default();
        halt.deceleration = 5000.0;
        halt.buffer_mode = BufferMode::Buffered;
        let mut stop = Stop::default();
        stop.deceleration = 20_000.0;
        let mut home = Home::default();
        home.position = 1.0;
        let mut reset = Reset::default();
        let mut set = SetPosition::default();
        set.position = 0.5;
        let mut jog = Jog::default();
        jog.velocity = 30.0;
        jog.acceleration = 10_000.0;
        jog.deceleration = 10_000.0;

        let mut before = [Seen::default(); 9];
        for step in program {
            match step.event {
                0 => kernel.inject_error(axis, 77).unwrap(),
                1 => { kernel.power(axis, false).unwrap(); }
                _ => { kernel.power(axis, true).unwrap(); }
            }
            let bit = |index: u16| step.executes & (1 << index) != 0;
            absolute.execute = bit(0);
            relative.execute = bit(1);
            additive.execute = bit(2);
            velocity.execute = bit(3);
            halt.execute = bit(4);
            // MC_Stop and MC_Home are triggered less often, or the axis would rarely move.
            stop.execute = bit(5) && bit(6) && bit(7);
            home.execute = bit(8) && bit(9);
            reset.execute = bit(10);
            set.execute = bit(11) && bit(12);
            jog.jog_forward = step.jog & 1 != 0;
            jog.jog_backward = step.jog & 2 != 0;

            absolute.call(&mut kernel, axis);
            relative.call(&mut kernel, axis);
            additive.call(&mut kernel, axis);
            velocity.call(&mut kernel, axis);
            halt.call(&mut kernel, axis);
            stop.call(&mut kernel, axis);
            home.call(&mut kernel, axis);
            reset.call(&mut kernel, axis);
            set.call(&mut kernel, axis);
            jog.call(&mut kernel, axis);

            let now = [
                Seen { active: absolute.active, aborted: absolute.command_aborted, ..seen!(absolute, absolute.execute) },
                Seen { active: relative.active, aborted: relative.command_aborted, ..seen!(relative, relative.execute) },
                Seen { active: additive.active, aborted: additive.command_aborted, ..seen!(additive, additive.execute) },
                Seen {
                    execute: velocity.execute,
                    busy: velocity.busy,
                    active: velocity.active,
                    done: false,
                    error: velocity.error,
                    error_id: velocity.error_id,
                    aborted: velocity.command_aborted,
                },
                Seen { active: halt.active, aborted: halt.command_aborted, ..seen!(halt, halt.execute) },
                Seen { aborted: stop.command_aborted, ..seen!(stop, stop.execute) },
                Seen { active: home.active, aborted: home.command_aborted, ..seen!(home, home.execute) },
                seen!(reset, reset.execute),
                seen!(set, set.execute),
            ];
            let names = ["MC_MoveAbsolute", "MC_MoveRelative", "MC_MoveAdditive", "MC_MoveVelocity",
                "MC_Halt", "MC_Stop", "MC_Home", "MC_Reset", "MC_SetPosition"];
            for index in 0..now.len() {
                check(names[index], now[index], before[index], index == 5);
            }
            if velocity.in_velocity {
                prop_assert!(velocity.busy && velocity.active);
            }
            let jog_now = Seen {
                execute: jog.jog_forward || jog.jog_backward,
                busy: jog.busy,
                active: false,
                done: jog.done,
                error: jog.error,
                error_id: jog.error_id,
                aborted: jog.command_aborted,
            };
            let jog_outputs = [jog_now.busy, jog_now.done, jog_now.error, jog_now.aborted];
            prop_assert!(jog_outputs.iter().filter(|flag| **flag).count() <= 1, "MC_Jog: {:?}", jog_now);
            prop_assert_eq!(jog_now.error, jog_now.error_id != 0);
            before = now;

            kernel.advance(axis, DT_S).unwrap();
            // At most one command per instance is recorded (MC_Jog's own, plus a buffered
            // predecessor handed over), so the registry stays bounded.
            prop_assert!(kernel.recorded_commands() <= 12, "{} commands recorded", kernel.recorded_commands());
        }
    }
}
