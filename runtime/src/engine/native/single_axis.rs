//! The adapters of the single-axis blocks: each reads its inputs, calls the `motion` block kept
//! for the instance, and writes its outputs.

use motion::fb::{
    Halt, Home, Jog, MoveAbsolute, MoveAdditive, MoveRelative, MoveVelocity, Power,
    ReadActualPosition, ReadActualVelocity, ReadAxisError, ReadStatus, Reset, SetOverride,
    SetPosition, Stop,
};
use motion::kernel::AxisId;

use super::NativeBlock;
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
        NativeBlock::Power => power(io, axis, instance),
        NativeBlock::Home => {
            let (execute, position) = (io.bool(M::Execute)?, io.lreal(M::Position)?);
            let status = {
                let (kernel, fb) = io.motion().block::<Home>(instance);
                fb.execute = execute;
                fb.position = position;
                fb.call(kernel, axis);
                full(
                    M::Done,
                    fb.done,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            status.write(io)
        }
        NativeBlock::Stop => {
            let inputs = (
                io.bool(M::Execute)?,
                io.lreal(M::Deceleration)?,
                io.lreal(M::Jerk)?,
            );
            let status = {
                let (kernel, fb) = io.motion().block::<Stop>(instance);
                (fb.execute, fb.deceleration, fb.jerk) = inputs;
                fb.call(kernel, axis);
                Status {
                    done: Some((M::Done, fb.done)),
                    busy: Some(fb.busy),
                    active: None,
                    command_aborted: Some(fb.command_aborted),
                    error: fb.error,
                    error_id: fb.error_id,
                }
            };
            status.write(io)
        }
        NativeBlock::Halt => {
            let inputs = (
                io.bool(M::Execute)?,
                io.lreal(M::Deceleration)?,
                io.lreal(M::Jerk)?,
                buffer_mode(io.int(M::BufferMode)?),
            );
            let status = {
                let (kernel, fb) = io.motion().block::<Halt>(instance);
                (fb.execute, fb.deceleration, fb.jerk, fb.buffer_mode) = inputs;
                fb.call(kernel, axis);
                full(
                    M::Done,
                    fb.done,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            status.write(io)
        }
        NativeBlock::Reset => {
            let execute = io.bool(M::Execute)?;
            let status = {
                let (kernel, fb) = io.motion().block::<Reset>(instance);
                fb.execute = execute;
                fb.call(kernel, axis);
                simple(M::Done, fb.done, fb.busy, fb.error, fb.error_id)
            };
            status.write(io)
        }
        NativeBlock::MoveAbsolute => {
            let inputs = (
                io.bool(M::Execute)?,
                io.bool(M::ContinuousUpdate)?,
                io.lreal(M::Position)?,
                direction(io.int(M::Direction)?),
                buffer_mode(io.int(M::BufferMode)?),
            );
            let (v, a, d, j) = dynamics(io)?;
            let status = {
                let (kernel, fb) = io.motion().block::<MoveAbsolute>(instance);
                (
                    fb.execute,
                    fb.continuous_update,
                    fb.position,
                    fb.direction,
                    fb.buffer_mode,
                ) = inputs;
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = (v, a, d, j);
                fb.call(kernel, axis);
                full(
                    M::Done,
                    fb.done,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            status.write(io)
        }
        NativeBlock::MoveRelative | NativeBlock::MoveAdditive => {
            let inputs = (
                io.bool(M::Execute)?,
                io.bool(M::ContinuousUpdate)?,
                io.lreal(M::Distance)?,
                dynamics(io)?,
                buffer_mode(io.int(M::BufferMode)?),
            );
            let (execute, update, distance, (v, a, d, j), mode) = inputs;
            let status = if native == NativeBlock::MoveRelative {
                let (kernel, fb) = io.motion().block::<MoveRelative>(instance);
                (
                    fb.execute,
                    fb.continuous_update,
                    fb.distance,
                    fb.buffer_mode,
                ) = (execute, update, distance, mode);
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = (v, a, d, j);
                fb.call(kernel, axis);
                full(
                    M::Done,
                    fb.done,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            } else {
                let (kernel, fb) = io.motion().block::<MoveAdditive>(instance);
                (
                    fb.execute,
                    fb.continuous_update,
                    fb.distance,
                    fb.buffer_mode,
                ) = (execute, update, distance, mode);
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = (v, a, d, j);
                fb.call(kernel, axis);
                full(
                    M::Done,
                    fb.done,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            status.write(io)
        }
        NativeBlock::MoveVelocity => {
            let inputs = (
                io.bool(M::Execute)?,
                io.bool(M::ContinuousUpdate)?,
                dynamics(io)?,
                direction(io.int(M::Direction)?),
                buffer_mode(io.int(M::BufferMode)?),
            );
            let (execute, update, (v, a, d, j), dir, mode) = inputs;
            let status = {
                let (kernel, fb) = io.motion().block::<MoveVelocity>(instance);
                (
                    fb.execute,
                    fb.continuous_update,
                    fb.direction,
                    fb.buffer_mode,
                ) = (execute, update, dir, mode);
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = (v, a, d, j);
                fb.call(kernel, axis);
                full(
                    M::InVelocity,
                    fb.in_velocity,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            status.write(io)
        }
        NativeBlock::Jog => {
            let (forward, backward) = (io.bool(M::JogForward)?, io.bool(M::JogBackward)?);
            let (v, a, d, j) = dynamics(io)?;
            let status = {
                let (kernel, fb) = io.motion().block::<Jog>(instance);
                (fb.jog_forward, fb.jog_backward) = (forward, backward);
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = (v, a, d, j);
                fb.call(kernel, axis);
                Status {
                    done: Some((M::Done, fb.done)),
                    busy: Some(fb.busy),
                    active: None,
                    command_aborted: Some(fb.command_aborted),
                    error: fb.error,
                    error_id: fb.error_id,
                }
            };
            status.write(io)
        }
        NativeBlock::SetPosition => {
            let inputs = (
                io.bool(M::Execute)?,
                io.lreal(M::Position)?,
                io.bool(M::Relative)?,
            );
            let status = {
                let (kernel, fb) = io.motion().block::<SetPosition>(instance);
                (fb.execute, fb.position, fb.relative) = inputs;
                fb.call(kernel, axis);
                simple(M::Done, fb.done, fb.busy, fb.error, fb.error_id)
            };
            status.write(io)
        }
        NativeBlock::SetOverride => {
            let inputs = (
                io.bool(M::Enable)?,
                io.lreal(M::VelFactor)?,
                io.lreal(M::AccFactor)?,
                io.lreal(M::JerkFactor)?,
            );
            let status = {
                let (kernel, fb) = io.motion().block::<SetOverride>(instance);
                (fb.enable, fb.vel_factor, fb.acc_factor, fb.jerk_factor) = inputs;
                fb.call(kernel, axis);
                simple(M::Enabled, fb.enabled, fb.busy, fb.error, fb.error_id)
            };
            status.write(io)
        }
        NativeBlock::ReadActualPosition => {
            let enable = io.bool(M::Enable)?;
            let (status, position) = {
                let (kernel, fb) = io.motion().block::<ReadActualPosition>(instance);
                fb.enable = enable;
                fb.call(kernel, axis);
                (
                    simple(M::Valid, fb.valid, fb.busy, fb.error, fb.error_id),
                    fb.position,
                )
            };
            status.write(io)?;
            io.set_lreal(M::Position, position)
        }
        NativeBlock::ReadActualVelocity => {
            let enable = io.bool(M::Enable)?;
            let (status, velocity) = {
                let (kernel, fb) = io.motion().block::<ReadActualVelocity>(instance);
                fb.enable = enable;
                fb.call(kernel, axis);
                (
                    simple(M::Valid, fb.valid, fb.busy, fb.error, fb.error_id),
                    fb.velocity,
                )
            };
            status.write(io)?;
            io.set_lreal(M::Velocity, velocity)
        }
        NativeBlock::ReadAxisError => {
            let enable = io.bool(M::Enable)?;
            let (status, axis_error) = {
                let (kernel, fb) = io.motion().block::<ReadAxisError>(instance);
                fb.enable = enable;
                fb.call(kernel, axis);
                (
                    simple(M::Valid, fb.valid, fb.busy, fb.error, fb.error_id),
                    fb.axis_error_id,
                )
            };
            status.write(io)?;
            io.set_word(M::AxisErrorID, axis_error)
        }
        NativeBlock::ReadStatus => {
            let enable = io.bool(M::Enable)?;
            let (status, states) = {
                let (kernel, fb) = io.motion().block::<ReadStatus>(instance);
                fb.enable = enable;
                fb.call(kernel, axis);
                let states = [
                    (M::ErrorStop, fb.error_stop),
                    (M::Disabled, fb.disabled),
                    (M::Stopping, fb.stopping),
                    (M::Homing, fb.homing),
                    (M::Standstill, fb.standstill),
                    (M::DiscreteMotion, fb.discrete_motion),
                    (M::ContinuousMotion, fb.continuous_motion),
                    (M::SynchronizedMotion, fb.synchronized_motion),
                ];
                (
                    simple(M::Valid, fb.valid, fb.busy, fb.error, fb.error_id),
                    states,
                )
            };
            status.write(io)?;
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

fn power(io: &mut Io<'_, '_>, axis: AxisId, instance: usize) -> Result<(), FaultKind> {
    let enable = io.bool(M::Enable)?;
    let (status, powered) = {
        let (kernel, fb) = io.motion().block::<Power>(instance);
        fb.enable = enable;
        fb.call(kernel, axis);
        (
            simple(M::Status, fb.status, false, fb.error, fb.error_id),
            fb.status,
        )
    };
    status.write(io)?;
    io.set_bool(M::bRegulatorRealState, powered)?;
    io.set_bool(M::bDriveStartRealState, powered)
}

/// `Velocity`, `Acceleration`, `Deceleration`, `Jerk`.
fn dynamics(io: &Io<'_, '_>) -> Result<(f64, f64, f64, f64), FaultKind> {
    Ok((
        io.lreal(M::Velocity)?,
        io.lreal(M::Acceleration)?,
        io.lreal(M::Deceleration)?,
        io.lreal(M::Jerk)?,
    ))
}

/// The outputs of a buffered motion block.
fn full(
    done_name: M,
    done: bool,
    busy: bool,
    active: bool,
    command_aborted: bool,
    error: bool,
    error_id: u16,
) -> Status {
    Status {
        done: Some((done_name, done)),
        busy: Some(busy),
        active: Some(active),
        command_aborted: Some(command_aborted),
        error,
        error_id,
    }
}

/// The outputs of a block without Active and CommandAborted.
fn simple(done_name: M, done: bool, busy: bool, error: bool, error_id: u16) -> Status {
    Status {
        done: Some((done_name, done)),
        busy: Some(busy),
        active: None,
        command_aborted: None,
        error,
        error_id,
    }
}
