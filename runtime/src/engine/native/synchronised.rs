//! The adapters of the synchronised blocks: cam selection and coupling, gearing, phasing, and
//! the tappet blocks, which work on a master and a slave, a cam table or an MC_CamIn's tappets.

use motion::fb::get_tappet_value::GetTappetValue;
use motion::fb::{
    CamIn, CamOut, CamRegister, CamTableSelect, GearIn, GearInPos, GearOut, GetCamSlaveSetPosition,
    Phasing,
};
use motion::kernel::AxisId;
use motion::sync::{CamTableId, PhasingMode};

use super::NativeBlock;
use super::codes::{UNKNOWN_AXIS, UNKNOWN_CAM, buffer_mode, start_mode};
use super::io::Io;
use super::member::M;
use crate::engine::fault::FaultKind;

/// The length of `SMC_CamRegister.bTappet` (CODESYS `MAX_NUM_TAPPETS`).
const MAX_NUM_TAPPETS: usize = 512;

/// Writes the outputs every synchronised block has.
fn status(io: &mut Io<'_, '_>, busy: bool, error: bool, error_id: u16) -> Result<(), FaultKind> {
    io.set_bool(M::Busy, busy)?;
    io.set_bool(M::Error, error)?;
    io.set_word(M::ErrorID, error_id)
}

/// Writes `Active` and `CommandAborted` of a block that controls the slave.
fn control(io: &mut Io<'_, '_>, active: bool, aborted: bool) -> Result<(), FaultKind> {
    io.set_bool(M::Active, active)?;
    io.set_bool(M::CommandAborted, aborted)
}

/// The master and the slave, or `None` after writing the unknown-axis error.
fn axes(io: &mut Io<'_, '_>) -> Result<Option<(AxisId, AxisId)>, FaultKind> {
    match (io.axis(M::Master)?, io.axis(M::Slave)?) {
        (Some(master), Some(slave)) => Ok(Some((master, slave))),
        _ => {
            status(io, false, true, UNKNOWN_AXIS)?;
            Ok(None)
        }
    }
}

/// The slave alone, or `None` after writing the unknown-axis error.
fn slave(io: &mut Io<'_, '_>) -> Result<Option<AxisId>, FaultKind> {
    match io.axis(M::Slave)? {
        Some(slave) => Ok(Some(slave)),
        None => {
            status(io, false, true, UNKNOWN_AXIS)?;
            Ok(None)
        }
    }
}

/// Runs `native` on the instance at `instance`.
pub(super) fn call(
    io: &mut Io<'_, '_>,
    native: NativeBlock,
    instance: usize,
) -> Result<(), FaultKind> {
    match native {
        NativeBlock::CamTableSelect => cam_table_select(io, instance),
        NativeBlock::CamIn => cam_in(io, instance),
        NativeBlock::CamOut | NativeBlock::GearOut => {
            let Some(slave) = slave(io)? else {
                return Ok(());
            };
            let execute = io.bool(M::Execute)?;
            let (done, busy, error, error_id) = if native == NativeBlock::CamOut {
                let (kernel, fb) = io.motion().block::<CamOut>(instance);
                fb.execute = execute;
                fb.call(kernel, slave);
                (fb.done, fb.busy, fb.error, fb.error_id)
            } else {
                let (kernel, fb) = io.motion().block::<GearOut>(instance);
                fb.execute = execute;
                fb.call(kernel, slave);
                (fb.done, fb.busy, fb.error, fb.error_id)
            };
            io.set_bool(M::Done, done)?;
            status(io, busy, error, error_id)
        }
        NativeBlock::GearIn => {
            let Some((master, slave)) = axes(io)? else {
                return Ok(());
            };
            let execute = io.bool(M::Execute)?;
            let ratio = (io.dint(M::RatioNumerator)?, io.udint(M::RatioDenominator)?);
            let dynamics = (
                io.lreal(M::Acceleration)?,
                io.lreal(M::Deceleration)?,
                io.lreal(M::Jerk)?,
            );
            let mode = buffer_mode(io.int(M::BufferMode)?);
            let outputs = {
                let (kernel, fb) = io.motion().block::<GearIn>(instance);
                fb.execute = execute;
                (fb.ratio_numerator, fb.ratio_denominator) = ratio;
                (fb.acceleration, fb.deceleration, fb.jerk) = dynamics;
                fb.buffer_mode = mode;
                fb.call(kernel, master, slave);
                (
                    fb.in_gear,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            io.set_bool(M::InGear, outputs.0)?;
            control(io, outputs.2, outputs.3)?;
            status(io, outputs.1, outputs.4, outputs.5)
        }
        NativeBlock::GearInPos => {
            let Some((master, slave)) = axes(io)? else {
                return Ok(());
            };
            let execute = io.bool(M::Execute)?;
            let numerator = io.dint(M::RatioNumerator)?;
            // A negative denominator is no ratio: 0 makes the block refuse it.
            let denominator = u32::try_from(io.dint(M::RatioDenominator)?).unwrap_or(0);
            let positions = (
                io.lreal(M::MasterSyncPosition)?,
                io.lreal(M::SlaveSyncPosition)?,
                io.lreal(M::MasterStartDistance)?,
            );
            let mode = buffer_mode(io.int(M::BufferMode)?);
            let outputs = {
                let (kernel, fb) = io.motion().block::<GearInPos>(instance);
                fb.execute = execute;
                (fb.ratio_numerator, fb.ratio_denominator) = (numerator, denominator);
                (
                    fb.master_sync_position,
                    fb.slave_sync_position,
                    fb.master_start_distance,
                ) = positions;
                fb.buffer_mode = mode;
                fb.call(kernel, master, slave);
                (
                    fb.start_sync,
                    fb.in_sync,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            io.set_bool(M::StartSync, outputs.0)?;
            io.set_bool(M::InSync, outputs.1)?;
            control(io, outputs.3, outputs.4)?;
            status(io, outputs.2, outputs.5, outputs.6)
        }
        NativeBlock::Phasing => {
            let Some((master, slave)) = axes(io)? else {
                return Ok(());
            };
            let execute = io.bool(M::Execute)?;
            let shift = io.lreal(M::PhaseShift)?;
            let dynamics = (
                io.lreal(M::Velocity)?,
                io.lreal(M::Acceleration)?,
                io.lreal(M::Deceleration)?,
                io.lreal(M::Jerk)?,
            );
            let outputs = {
                let (kernel, fb) = io.motion().block::<Phasing>(instance);
                fb.execute = execute;
                // CODESYS's MC_Phasing sets the phase shift absolutely.
                fb.mode = PhasingMode::Absolute;
                fb.phase_shift = shift;
                (fb.velocity, fb.acceleration, fb.deceleration, fb.jerk) = dynamics;
                fb.call(kernel, master, slave);
                (
                    fb.done,
                    fb.busy,
                    fb.active,
                    fb.command_aborted,
                    fb.error,
                    fb.error_id,
                )
            };
            io.set_bool(M::Done, outputs.0)?;
            control(io, outputs.2, outputs.3)?;
            status(io, outputs.1, outputs.4, outputs.5)
        }
        NativeBlock::CamRegister => cam_register(io, instance),
        NativeBlock::GetTappetValue => get_tappet_value(io, instance),
        NativeBlock::GetCamSlaveSetPosition => {
            let Some((master, slave)) = axes(io)? else {
                return Ok(());
            };
            let enable = io.bool(M::Enable)?;
            let scaling = (
                io.lreal(M::MasterOffset)?,
                io.lreal(M::SlaveOffset)?,
                io.lreal(M::MasterScaling)?,
                io.lreal(M::SlaveScaling)?,
            );
            let selection = CamTableId(io.selection(M::CamTableID)?);
            let outputs = {
                let (kernel, fb) = io.motion().block::<GetCamSlaveSetPosition>(instance);
                fb.enable = enable;
                (
                    fb.master_offset,
                    fb.slave_offset,
                    fb.master_scaling,
                    fb.slave_scaling,
                ) = scaling;
                fb.cam_table_id = selection;
                fb.call(kernel, master, slave);
                (
                    fb.start_position,
                    fb.start_velocity,
                    fb.start_acceleration,
                    fb.busy,
                    fb.error,
                    fb.error_id,
                )
            };
            io.set_lreal(M::fStartPosition, outputs.0)?;
            io.set_lreal(M::fStartVelocity, outputs.1)?;
            io.set_lreal(M::fStartAcceleration, outputs.2)?;
            status(io, outputs.3, outputs.4, outputs.5)
        }
        other => Err(FaultKind::Internal(format!(
            "{other:?} is not a synchronised block"
        ))),
    }
}

fn cam_table_select(io: &mut Io<'_, '_>, instance: usize) -> Result<(), FaultKind> {
    let Some((master, slave)) = axes(io)? else {
        return Ok(());
    };
    let Some((cam_ref, cam)) = io
        .cam(M::CamTable)?
        .and_then(|id| io.motion().cam(id).map(|cam| (id, cam)))
    else {
        io.set_bool(M::Done, false)?;
        return status(io, false, true, UNKNOWN_CAM);
    };
    let execute = io.bool(M::Execute)?;
    let options = [
        io.bool(M::Periodic)?,
        io.bool(M::MasterAbsolute)?,
        io.bool(M::SlaveAbsolute)?,
    ];
    let outputs = {
        let (kernel, fb) = io.motion().block::<CamTableSelect>(instance);
        fb.execute = execute;
        fb.cam_table = cam;
        [fb.periodic, fb.master_absolute, fb.slave_absolute] = options;
        fb.call(kernel, master, slave);
        (fb.done, fb.busy, fb.error, fb.error_id, fb.cam_table_id)
    };
    io.set_bool(M::Done, outputs.0)?;
    io.set_selection(M::CamTableID, cam_ref, outputs.4.0, options)?;
    status(io, outputs.1, outputs.2, outputs.3)
}

fn cam_in(io: &mut Io<'_, '_>, instance: usize) -> Result<(), FaultKind> {
    let Some((master, slave)) = axes(io)? else {
        return Ok(());
    };
    let execute = io.bool(M::Execute)?;
    let placement = (
        io.lreal(M::MasterOffset)?,
        io.lreal(M::SlaveOffset)?,
        io.lreal(M::MasterScaling)?,
        io.lreal(M::SlaveScaling)?,
    );
    let start = start_mode(io.int(M::StartMode)?);
    let selection = CamTableId(io.selection(M::CamTableID)?);
    let ramp = (
        io.lreal(M::VelocityDiff)?,
        io.lreal(M::Acceleration)?,
        io.lreal(M::Deceleration)?,
        io.lreal(M::Jerk)?,
    );
    let hysteresis = io.lreal(M::TappetHysteresis)?;
    let mode = buffer_mode(io.int(M::BufferMode)?);
    let outputs = {
        let (kernel, fb) = io.motion().block::<CamIn>(instance);
        fb.execute = execute;
        (
            fb.master_offset,
            fb.slave_offset,
            fb.master_scaling,
            fb.slave_scaling,
        ) = placement;
        fb.start_mode = start;
        fb.cam_table_id = selection;
        (fb.velocity_diff, fb.acceleration, fb.deceleration, fb.jerk) = ramp;
        fb.tappet_hysteresis = hysteresis;
        fb.buffer_mode = mode;
        fb.call(kernel, master, slave);
        (
            fb.in_sync,
            fb.busy,
            fb.active,
            fb.command_aborted,
            fb.error,
            fb.error_id,
            fb.end_of_profile,
        )
    };
    io.set_bool(M::InSync, outputs.0)?;
    io.set_bool(M::EndOfProfile, outputs.6)?;
    io.set_coupling(M::Tappets)?;
    control(io, outputs.2, outputs.3)?;
    status(io, outputs.1, outputs.4, outputs.5)
}

fn cam_register(io: &mut Io<'_, '_>, instance: usize) -> Result<(), FaultKind> {
    let Some(master) = io.axis(M::Master)? else {
        io.set_bool(M::EndOfProfile, false)?;
        return status(io, false, true, UNKNOWN_AXIS);
    };
    let Some(cam) = io.cam(M::CamTable)?.and_then(|id| io.motion().cam(id)) else {
        io.set_bool(M::EndOfProfile, false)?;
        return status(io, false, true, UNKNOWN_CAM);
    };
    let inputs = (
        io.bool(M::Enable)?,
        io.lreal(M::MasterOffset)?,
        io.lreal(M::MasterScaling)?,
        io.lreal(M::TappetHysteresis)?,
        io.lreal(M::DeadTimeCompensation)?,
    );
    let (outputs, tappets) = {
        let (kernel, fb) = io.motion().block::<CamRegister>(instance);
        (
            fb.enable,
            fb.master_offset,
            fb.master_scaling,
            fb.tappet_hysteresis,
            fb.dead_time_compensation_s,
        ) = inputs;
        fb.call(kernel, master, cam);
        let tappets: Vec<(u16, bool)> = fb.tappets().collect();
        ((fb.busy, fb.error, fb.error_id, fb.end_of_profile), tappets)
    };
    for (track, value) in tappets {
        io.set_array_bool(M::bTappet, MAX_NUM_TAPPETS, usize::from(track), value)?;
    }
    io.set_bool(M::EndOfProfile, outputs.3)?;
    status(io, outputs.0, outputs.1, outputs.2)
}

fn get_tappet_value(io: &mut Io<'_, '_>, instance: usize) -> Result<(), FaultKind> {
    let coupling = io.coupling(M::Tappets)?;
    let id = u16::try_from(io.int(M::iID)?).unwrap_or(0);
    let init = (io.bool(M::bInitValue)?, io.bool(M::bSetInitValueAtReset)?);
    let motion = io.motion();
    let mut fb = motion.take::<GetTappetValue>(instance);
    fb.id = id;
    (fb.init_value, fb.set_init_value_at_reset) = init;
    // The tappets live in the MC_CamIn whose instance filled `Tappets`; before that MC_CamIn
    // ran, the block shows its initial value.
    match coupling.and_then(|at| motion.cam_in(at)) {
        Some(cam_in) => fb.call(&mut cam_in.tappets),
        None => fb.tappet = fb.init_value,
    }
    let value = fb.tappet;
    motion.put(instance, fb);
    io.set_bool(M::bTappet, value)
}
