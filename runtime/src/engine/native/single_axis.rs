//! The adapters of the single-axis blocks: each reads its inputs, calls the `motion` block kept
//! for the instance, and writes its outputs.

use motion::fb::{
    Halt, Home, Jog, MoveAbsolute, MoveAdditive, MoveRelative, MoveVelocity, Power,
    ReadActualPosition, ReadActualVelocity, ReadAxisError, ReadStatus, Reset, SetOverride,
    SetPosition, Stop,
};
use motion::kernel::Kernel;

use super::NativeBlock;
use super::blocks::Kept;
use super::codes::{UNKNOWN_AXIS, buffer_mode, direction};
use super::io::Io;
use super::member::M;
use crate::engine::fault::FaultKind;

/// The status outputs most blocks share; `None` for an output the block does not have.
struct Status {
    done: Option<(M, bool)>,
    busy: Option<bool>,
    active: Option<bool>,
    command_aborted: Option<bool>,
    error: bool,
    error_id: u16,
}

impl Status {
    fn write(&self, io: &mut Io<'_, '_>) -> Result<(), FaultKind> {
        if let Some((name, value)) = self.done {
            io.set_bool(name, value)?;
        }
        if let Some(busy) = self.busy {
            io.set_bool(M::Busy, busy)?;
        }
        if let Some(active) = self.active {
            io.set_bool(M::Active, active)?;
        }
        if let Some(aborted) = self.command_aborted {
            io.set_bool(M::CommandAborted, aborted)?;
        }
        io.set_bool(M::Error, self.error)?;
        io.set_word(M::ErrorID, self.error_id)
    }
}

/// A block's status outputs as the library names them.
trait Report {
    fn report(&self) -> Status;
}

/// `Report` for blocks with the outputs of a buffered command (`done`, Busy, Active,
/// CommandAborted, Error, ErrorID), `done` being the field and member of its Done output.
macro_rules! report_full {
    ($($block:ty => $done:ident $member:ident),* $(,)?) => {$(
        impl Report for $block {
            fn report(&self) -> Status {
                Status {
                    done: Some((M::$member, self.$done)),
                    busy: Some(self.busy),
                    active: Some(self.active),
                    command_aborted: Some(self.command_aborted),
                    error: self.error,
                    error_id: self.error_id,
                }
            }
        }
    )*};
}

/// `Report` for blocks with a Done-like output, Busy, Error and ErrorID only.
macro_rules! report_simple {
    ($($block:ty => $done:ident $member:ident),* $(,)?) => {$(
        impl Report for $block {
            fn report(&self) -> Status {
                Status {
                    done: Some((M::$member, self.$done)),
                    busy: Some(self.busy),
                    active: None,
                    command_aborted: None,
                    error: self.error,
                    error_id: self.error_id,
                }
            }
        }
    )*};
}

report_full!(
    Home => done Done,
    Halt => done Done,
    MoveAbsolute => done Done,
    MoveRelative => done Done,
    MoveAdditive => done Done,
    MoveVelocity => in_velocity InVelocity,
);
report_simple!(
    Reset => done Done,
    SetPosition => done Done,
    SetOverride => enabled Enabled,
    ReadActualPosition => valid Valid,
    ReadActualVelocity => valid Valid,
    ReadAxisError => valid Valid,
    ReadStatus => valid Valid,
);

impl Report for Power {
    fn report(&self) -> Status {
        Status {
            done: Some((M::Status, self.status)),
            busy: Some(false),
            active: None,
            command_aborted: None,
            error: self.error,
            error_id: self.error_id,
        }
    }
}

/// Stop and Jog have CommandAborted but no Active.
macro_rules! report_without_active {
    ($($block:ty),*) => {$(
        impl Report for $block {
            fn report(&self) -> Status {
                Status {
                    done: Some((M::Done, self.done)),
                    busy: Some(self.busy),
                    active: None,
                    command_aborted: Some(self.command_aborted),
                    error: self.error,
                    error_id: self.error_id,
                }
            }
        }
    )*};
}

report_without_active!(Stop, Jog);

/// Calls the block kept for `instance` with `call` (which sets its inputs and calls it), writes
/// its status outputs and returns what `after` takes from it for the block's other outputs.
fn run<T: Kept + Report, R>(
    io: &mut Io<'_, '_>,
    instance: usize,
    call: impl FnOnce(&mut Kernel, &mut T),
    after: impl FnOnce(&T) -> R,
) -> Result<R, FaultKind> {
    let (status, rest) = {
        let (kernel, fb) = io.motion().block::<T>(instance);
        call(kernel, fb);
        (fb.report(), after(fb))
    };
    status.write(io)?;
    Ok(rest)
}

/// Runs `native` on the instance at `instance`.
pub(super) fn call(
    io: &mut Io<'_, '_>,
    native: NativeBlock,
    instance: usize,
) -> Result<(), FaultKind> {
    let Some(axis) = io.axis(M::Axis)? else {
        // Not connected, or an AXIS_REF that names no axis of this image.
        return Status {
            done: None,
            busy: Some(false),
            active: None,
            command_aborted: None,
            error: true,
            error_id: UNKNOWN_AXIS,
        }
        .write(io);
    };
    match native {
        NativeBlock::Power => {
            let enable = io.bool(M::Enable)?;
            let powered = run(
                io,
                instance,
                |kernel, fb: &mut Power| {
                    fb.enable = enable;
                    fb.call(kernel, axis);
                },
                |fb| fb.status,
            )?;
            io.set_bool(M::bRegulatorRealState, powered)?;
            io.set_bool(M::bDriveStartRealState, powered)
        }
        NativeBlock::Home => {
            let (execute, position) = (io.bool(M::Execute)?, io.lreal(M::Position)?);
            let set = |kernel: &mut Kernel, fb: &mut Home| {
                (fb.execute, fb.position) = (execute, position);
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::Stop => {
            let inputs = (
                io.bool(M::Execute)?,
                io.lreal(M::Deceleration)?,
                io.lreal(M::Jerk)?,
            );
            let set = |kernel: &mut Kernel, fb: &mut Stop| {
                (fb.execute, fb.deceleration, fb.jerk) = inputs;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::Halt => {
            let inputs = (
                io.bool(M::Execute)?,
                io.lreal(M::Deceleration)?,
                io.lreal(M::Jerk)?,
                buffer_mode(io.int(M::BufferMode)?),
            );
            let set = |kernel: &mut Kernel, fb: &mut Halt| {
                (fb.execute, fb.deceleration, fb.jerk, fb.buffer_mode) = inputs;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::Reset => {
            let execute = io.bool(M::Execute)?;
            let set = |kernel: &mut Kernel, fb: &mut Reset| {
                fb.execute = execute;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::MoveAbsolute => {
            let inputs = (
                io.bool(M::Execute)?,
                io.bool(M::ContinuousUpdate)?,
                io.lreal(M::Position)?,
                direction(io.int(M::Direction)?),
                buffer_mode(io.int(M::BufferMode)?),
            );
            let dynamics = dynamics(io)?;
            let set = |kernel: &mut Kernel, fb: &mut MoveAbsolute| {
                let (execute, update, position, direction, mode) = inputs;
                (fb.execute, fb.continuous_update, fb.position) = (execute, update, position);
                (fb.direction, fb.buffer_mode) = (direction, mode);
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = dynamics;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::MoveRelative | NativeBlock::MoveAdditive => {
            let inputs = (
                io.bool(M::Execute)?,
                io.bool(M::ContinuousUpdate)?,
                io.lreal(M::Distance)?,
                buffer_mode(io.int(M::BufferMode)?),
            );
            let dynamics = dynamics(io)?;
            // The two blocks have the same inputs; they differ in what the distance adds to.
            macro_rules! set {
                ($block:ty) => {
                    |kernel: &mut Kernel, fb: &mut $block| {
                        (
                            fb.execute,
                            fb.continuous_update,
                            fb.distance,
                            fb.buffer_mode,
                        ) = inputs;
                        (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = dynamics;
                        fb.call(kernel, axis);
                    }
                };
            }
            if native == NativeBlock::MoveRelative {
                run(io, instance, set!(MoveRelative), ignore)
            } else {
                run(io, instance, set!(MoveAdditive), ignore)
            }
        }
        NativeBlock::MoveVelocity => {
            let inputs = (
                io.bool(M::Execute)?,
                io.bool(M::ContinuousUpdate)?,
                direction(io.int(M::Direction)?),
                buffer_mode(io.int(M::BufferMode)?),
            );
            let dynamics = dynamics(io)?;
            let set = |kernel: &mut Kernel, fb: &mut MoveVelocity| {
                (
                    fb.execute,
                    fb.continuous_update,
                    fb.direction,
                    fb.buffer_mode,
                ) = inputs;
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = dynamics;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::Jog => {
            let jog = (io.bool(M::JogForward)?, io.bool(M::JogBackward)?);
            let dynamics = dynamics(io)?;
            let set = |kernel: &mut Kernel, fb: &mut Jog| {
                (fb.jog_forward, fb.jog_backward) = jog;
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = dynamics;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::SetPosition => {
            let inputs = (
                io.bool(M::Execute)?,
                io.lreal(M::Position)?,
                io.bool(M::Relative)?,
            );
            let set = |kernel: &mut Kernel, fb: &mut SetPosition| {
                (fb.execute, fb.position, fb.relative) = inputs;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::SetOverride => {
            let inputs = (
                io.bool(M::Enable)?,
                io.lreal(M::VelFactor)?,
                io.lreal(M::AccFactor)?,
                io.lreal(M::JerkFactor)?,
            );
            let set = |kernel: &mut Kernel, fb: &mut SetOverride| {
                (fb.enable, fb.vel_factor, fb.acc_factor, fb.jerk_factor) = inputs;
                fb.call(kernel, axis);
            };
            run(io, instance, set, ignore)
        }
        NativeBlock::ReadActualPosition => {
            let enable = io.bool(M::Enable)?;
            let set = |kernel: &mut Kernel, fb: &mut ReadActualPosition| {
                fb.enable = enable;
                fb.call(kernel, axis);
            };
            let position = run(io, instance, set, |fb| fb.position)?;
            io.set_lreal(M::Position, position)
        }
        NativeBlock::ReadActualVelocity => {
            let enable = io.bool(M::Enable)?;
            let set = |kernel: &mut Kernel, fb: &mut ReadActualVelocity| {
                fb.enable = enable;
                fb.call(kernel, axis);
            };
            let velocity = run(io, instance, set, |fb| fb.velocity)?;
            io.set_lreal(M::Velocity, velocity)
        }
        NativeBlock::ReadAxisError => {
            let enable = io.bool(M::Enable)?;
            let set = |kernel: &mut Kernel, fb: &mut ReadAxisError| {
                fb.enable = enable;
                fb.call(kernel, axis);
            };
            let axis_error = run(io, instance, set, |fb| fb.axis_error_id)?;
            io.set_word(M::AxisErrorID, axis_error)
        }
        NativeBlock::ReadStatus => {
            let enable = io.bool(M::Enable)?;
            let set = |kernel: &mut Kernel, fb: &mut ReadStatus| {
                fb.enable = enable;
                fb.call(kernel, axis);
            };
            let states = run(io, instance, set, |fb| {
                [
                    (M::ErrorStop, fb.error_stop),
                    (M::Disabled, fb.disabled),
                    (M::Stopping, fb.stopping),
                    (M::Homing, fb.homing),
                    (M::Standstill, fb.standstill),
                    (M::DiscreteMotion, fb.discrete_motion),
                    (M::ContinuousMotion, fb.continuous_motion),
                    (M::SynchronizedMotion, fb.synchronized_motion),
                ]
            })?;
            for (name, value) in states {
                io.set_bool(name, value)?;
            }
            Ok(())
        }
        other => Err(FaultKind::Internal(format!(
            "{other:?} is not a single-axis block"
        ))),
    }
}

/// For a block whose outputs are all status outputs.
fn ignore<T>(_: &T) {}

/// `Velocity`, `Acceleration`, `Deceleration`, `Jerk`.
fn dynamics(io: &Io<'_, '_>) -> Result<(f64, f64, f64, f64), FaultKind> {
    Ok((
        io.lreal(M::Velocity)?,
        io.lreal(M::Acceleration)?,
        io.lreal(M::Deceleration)?,
        io.lreal(M::Jerk)?,
    ))
}
