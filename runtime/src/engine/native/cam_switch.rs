//! The adapter of MC_DigitalCamSwitch: its switches, track options and outputs are structures
//! the program passes by VAR_IN_OUT, read and written through the image's type table.

use motion::fb::{
    CAM_SWITCH_TRACKS, CamSwitch, CamSwitchMode, DigitalCamSwitch, SwitchDirection, TrackOptions,
};

use super::codes::{INVALID_INPUT, UNKNOWN_AXIS};
use super::io::Io;
use super::member::M;
use crate::engine::fault::FaultKind;

/// Runs MC_DigitalCamSwitch on the instance at `instance`.
pub(super) fn call(io: &mut Io<'_, '_>, instance: usize) -> Result<(), FaultKind> {
    let layout = io.switch_layout()?;
    let (Some(axis), Some(switches_at), Some(tracks_at), Some(outputs_at)) = (
        io.axis(M::Axis)?,
        io.in_out(M::Switches, layout.switches_size)?,
        io.in_out(M::TrackOptions, layout.tracks_size)?,
        io.in_out(M::Outputs, layout.outputs_size)?,
    ) else {
        return write_status(io, false, true, UNKNOWN_AXIS);
    };
    let enable = io.bool(M::Enable)?;
    let enable_mask = (io.dword(M::EnableMask)? & 0xFFFF) as u16;
    let declared = io.read_at::<u16>(switches_at + layout.count as usize)?;
    // The structure holds 64 switches: more than that would read past it.
    let capacity = (layout.switches_size - layout.switch) / layout.switch_size.max(1);
    if u32::from(declared) > capacity {
        return write_status(io, false, true, INVALID_INPUT);
    }
    let mut switches = Vec::with_capacity(usize::from(declared));
    for index in 0..usize::from(declared) {
        let at = switches_at + (layout.switch + index as u32 * layout.switch_size) as usize;
        let track = io.read_at::<i16>(at + layout.track_number as usize)?;
        switches.push(CamSwitch {
            // A negative track number is refused by the block like any track out of range.
            track_number: u16::try_from(track).unwrap_or(u16::MAX),
            first_on_position: io.read_at::<f64>(at + layout.first_on as usize)?,
            last_on_position: io.read_at::<f64>(at + layout.last_on as usize)?,
            axis_direction: match io.read_at::<i16>(at + layout.direction as usize)? {
                1 => SwitchDirection::Positive,
                2 => SwitchDirection::Negative,
                _ => SwitchDirection::Both,
            },
            cam_switch_mode: match io.read_at::<i16>(at + layout.mode as usize)? {
                1 => CamSwitchMode::Time,
                _ => CamSwitchMode::Position,
            },
            duration_s: f64::from(io.read_at::<i32>(at + layout.duration as usize)?) / 1e3,
        });
    }
    let mut options = [TrackOptions::default(); CAM_SWITCH_TRACKS];
    for (index, option) in options.iter_mut().enumerate() {
        let at = tracks_at + (layout.track + index as u32 * layout.track_size) as usize;
        let milliseconds = |offset: u32| -> Result<f64, FaultKind> {
            Ok(f64::from(io.read_at::<i32>(at + offset as usize)?) / 1e3)
        };
        *option = TrackOptions {
            on_compensation_s: milliseconds(layout.on_compensation)?,
            off_compensation_s: milliseconds(layout.off_compensation)?,
            hysteresis: io.read_at::<f64>(at + layout.hysteresis as usize)?,
        };
    }
    let (outputs, status) = {
        let motion = io.motion();
        let mut fb = motion.take::<DigitalCamSwitch>(instance);
        fb.enable = enable;
        fb.enable_mask = enable_mask;
        fb.switches = switches;
        fb.track_options = options;
        fb.call(motion.kernel(), axis);
        let result = (
            fb.outputs,
            (fb.in_operation, fb.busy, fb.error, fb.error_id),
        );
        motion.put(instance, fb);
        result
    };
    for (track, on) in outputs.iter().enumerate() {
        io.write_at::<u8>(outputs_at + layout.output as usize + track, u8::from(*on))?;
    }
    io.set_bool(M::InOperation, status.0)?;
    write_status(io, status.1, status.2, status.3)
}

fn write_status(
    io: &mut Io<'_, '_>,
    busy: bool,
    error: bool,
    error_id: u16,
) -> Result<(), FaultKind> {
    if error {
        io.set_bool(M::InOperation, false)?;
    }
    io.set_bool(M::Busy, busy)?;
    io.set_bool(M::Error, error)?;
    io.set_word(M::ErrorID, error_id)
}
