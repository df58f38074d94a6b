//! Reading and writing a native block's instance by member name, and following its VAR_IN_OUT
//! pointers to the axes.

use std::collections::HashMap;

use motion::kernel::AxisId;
use program_image::{Member, ProgramImage, StructKind, TypeDef};

use super::member::M;
use super::state::MotionState;
use crate::engine::exec::{ABSOLUTE, Addr, Exec, INSTANCE};
use crate::engine::fault::FaultKind;

/// The byte offsets of an instance's members, resolved at load for every member the adapters
/// use ([`M`]); `None` for a member the block does not have.
#[derive(Clone, Debug)]
pub(super) struct Members {
    offsets: [Option<u32>; M::ALL.len()],
}

impl Members {
    /// The members of a function block's instance type.
    pub(super) fn of(members: &[Member]) -> Self {
        Self {
            offsets: M::ALL.map(|wanted| {
                let name = wanted.name();
                members
                    .iter()
                    .find(|member| member.name == name)
                    .or_else(|| members.iter().find(|m| m.name.eq_ignore_ascii_case(name)))
                    .map(|member| member.offset)
            }),
        }
    }

    /// The offset of `field` in the image's structure `ty` (`AXIS_REF.nAxisId`), if the image
    /// has that structure.
    pub(super) fn field_offset(image: &ProgramImage, ty: &str, field: &str) -> Option<u32> {
        image.types.iter().find_map(|candidate| match candidate {
            TypeDef::Struct {
                name,
                kind: StructKind::Struct,
                members,
                ..
            } if name == ty => members
                .iter()
                .find(|member| member.name.eq_ignore_ascii_case(field))
                .map(|member| member.offset),
            _ => None,
        })
    }

    fn offset(&self, name: M) -> Result<u32, FaultKind> {
        self.offsets[name as usize].ok_or_else(|| {
            FaultKind::Internal(format!(
                "a native function block has no member '{}' (the image and the runtime disagree about the motion library)",
                name.name()
            ))
        })
    }
}

/// Offsets of the library structures' fields a native block reads or writes through its
/// members; `None` when the image has no such structure (no block that uses it).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct LibraryOffsets {
    /// `AXIS_REF.nAxisId`.
    pub(super) axis_id: Option<u32>,
    /// `MC_CAM_REF.nCamId`.
    pub(super) cam_id: Option<u32>,
    /// `MC_CAM_ID.nCamId`, `nSelection`, `bPeriodic`, `bMasterAbsolute`, `bSlaveAbsolute`.
    pub(super) selection: Option<[u32; 5]>,
    /// `SMC_TappetData.nCoupling`.
    pub(super) coupling: Option<u32>,
    /// The switch, track and output structures of MC_DigitalCamSwitch.
    pub(super) switches: Option<SwitchLayout>,
}

/// Where MC_DigitalCamSwitch finds its switches, track options and outputs.
#[derive(Clone, Copy, Debug)]
pub(super) struct SwitchLayout {
    /// `MC_CAMSWITCH_REF`: its size, `NumberOfSwitches`, `Switch`.
    pub(super) switches_size: u32,
    pub(super) count: u32,
    pub(super) switch: u32,
    /// `MC_CAMSWITCH_TR`: its size (the array's stride) and its members.
    pub(super) switch_size: u32,
    pub(super) track_number: u32,
    pub(super) first_on: u32,
    pub(super) last_on: u32,
    pub(super) direction: u32,
    pub(super) mode: u32,
    pub(super) duration: u32,
    /// `MC_TRACK_REF`: its size and `Track`; `MC_TRACK_TR`: its size and members.
    pub(super) tracks_size: u32,
    pub(super) track: u32,
    pub(super) track_size: u32,
    pub(super) on_compensation: u32,
    pub(super) off_compensation: u32,
    pub(super) hysteresis: u32,
    /// `MC_OUTPUT_REF`: its size and `Output`.
    pub(super) outputs_size: u32,
    pub(super) output: u32,
}

impl SwitchLayout {
    fn of(image: &ProgramImage) -> Option<Self> {
        let (switches_size, switches) = structure(image, "MC_CAMSWITCH_REF")?;
        let (switch_size, switch) = structure(image, "MC_CAMSWITCH_TR")?;
        let (tracks_size, tracks) = structure(image, "MC_TRACK_REF")?;
        let (track_size, track) = structure(image, "MC_TRACK_TR")?;
        let (outputs_size, outputs) = structure(image, "MC_OUTPUT_REF")?;
        let at =
            |members: &HashMap<String, u32>, name: &str| members.get(&name.to_lowercase()).copied();
        Some(Self {
            switches_size,
            count: at(&switches, "NumberOfSwitches")?,
            switch: at(&switches, "Switch")?,
            switch_size,
            track_number: at(&switch, "TrackNumber")?,
            first_on: at(&switch, "FirstOnPosition")?,
            last_on: at(&switch, "LastOnPosition")?,
            direction: at(&switch, "AxisDirection")?,
            mode: at(&switch, "CamSwitchMode")?,
            duration: at(&switch, "Duration")?,
            tracks_size,
            track: at(&tracks, "Track")?,
            track_size,
            on_compensation: at(&track, "OnCompensation")?,
            off_compensation: at(&track, "OffCompensation")?,
            hysteresis: at(&track, "Hysteresis")?,
            outputs_size,
            output: at(&outputs, "Output")?,
        })
    }
}

/// The size and the member offsets (by lower-case name) of the image's structure `ty`.
fn structure(image: &ProgramImage, ty: &str) -> Option<(u32, HashMap<String, u32>)> {
    image.types.iter().find_map(|candidate| match candidate {
        TypeDef::Struct {
            name,
            kind: StructKind::Struct,
            size,
            members,
        } if name == ty => Some((
            *size,
            members
                .iter()
                .map(|member| (member.name.to_lowercase(), member.offset))
                .collect(),
        )),
        _ => None,
    })
}

impl LibraryOffsets {
    /// The offsets in `image`'s type table.
    pub(super) fn of(image: &ProgramImage) -> Self {
        let field = |ty: &str, name: &str| Members::field_offset(image, ty, name);
        let selection = [
            "nCamId",
            "nSelection",
            "bPeriodic",
            "bMasterAbsolute",
            "bSlaveAbsolute",
        ]
        .map(|name| field("MC_CAM_ID", name));
        Self {
            axis_id: field("AXIS_REF", "nAxisId"),
            cam_id: field("MC_CAM_REF", "nCamId"),
            selection: match selection {
                [Some(a), Some(b), Some(c), Some(d), Some(e)] => Some([a, b, c, d, e]),
                _ => None,
            },
            coupling: field("SMC_TappetData", "nCoupling"),
            switches: SwitchLayout::of(image),
        }
    }
}

/// A library structure the image lacks although a native block needs it.
fn missing(what: &str) -> FaultKind {
    FaultKind::Internal(format!("the image has no {what} for its motion blocks"))
}

/// One native call's view of its instance.
pub(super) struct Io<'x, 'a> {
    x: &'x mut Exec<'a>,
    members: &'x Members,
    library: LibraryOffsets,
}

impl<'x, 'a> Io<'x, 'a> {
    /// A view of the current instance of `x`.
    pub(super) fn new(x: &'x mut Exec<'a>, members: &'x Members, library: LibraryOffsets) -> Self {
        Self {
            x,
            members,
            library,
        }
    }

    /// The absolute offset of the current instance.
    pub(super) fn instance(&self) -> usize {
        self.x.bases[usize::from(INSTANCE)]
    }

    fn absolute(at: usize) -> Addr {
        Addr {
            base: ABSOLUTE,
            offset: at as u32,
        }
    }

    /// A DINT member.
    pub(super) fn dint(&self, name: M) -> Result<i32, FaultKind> {
        self.x.get::<i32>(self.addr(name)?)
    }

    /// A UDINT member.
    pub(super) fn udint(&self, name: M) -> Result<u32, FaultKind> {
        self.x.get::<u32>(self.addr(name)?)
    }

    /// The absolute offset of what the VAR_IN_OUT `name` points to, checked for `size` bytes;
    /// `None` when it is not connected.
    fn target(&self, name: M, size: usize) -> Result<Option<usize>, FaultKind> {
        let pointer = self.x.get::<u64>(self.addr(name)?)?;
        if pointer == 0 {
            return Ok(None);
        }
        self.x.deref(pointer, size).map(Some)
    }

    /// The absolute offset of what the VAR_IN_OUT `name` points to, checked for `size` bytes;
    /// `None` when it is not connected.
    pub(super) fn in_out(&self, name: M, size: u32) -> Result<Option<usize>, FaultKind> {
        self.target(name, size as usize)
    }

    /// The layout of the cam switch structures.
    pub(super) fn switch_layout(&self) -> Result<SwitchLayout, FaultKind> {
        self.library
            .switches
            .ok_or_else(|| missing("MC_CAMSWITCH_REF, MC_TRACK_REF or MC_OUTPUT_REF"))
    }

    /// A value at an absolute offset.
    pub(super) fn read_at<T: crate::engine::scalar::Scalar>(
        &self,
        at: usize,
    ) -> Result<T, FaultKind> {
        self.x.get::<T>(Self::absolute(at))
    }

    /// Writes a value at an absolute offset.
    pub(super) fn write_at<T: crate::engine::scalar::Scalar>(
        &mut self,
        at: usize,
        value: T,
    ) -> Result<(), FaultKind> {
        self.x.set::<T>(Self::absolute(at), value)
    }

    /// A DWORD member.
    pub(super) fn dword(&self, name: M) -> Result<u32, FaultKind> {
        self.x.get::<u32>(self.addr(name)?)
    }

    /// The cam table (`nCamId`) the VAR_IN_OUT `name` points to; `None` when it is not
    /// connected.
    pub(super) fn cam(&self, name: M) -> Result<Option<u32>, FaultKind> {
        let offset = self.library.cam_id.ok_or_else(|| missing("MC_CAM_REF"))? as usize;
        let Some(at) = self.target(name, offset + 4)? else {
            return Ok(None);
        };
        self.x.get::<u32>(Self::absolute(at + offset)).map(Some)
    }

    /// The selection of the `MC_CAM_ID` member `name`.
    pub(super) fn selection(&self, name: M) -> Result<u32, FaultKind> {
        let fields = self.library.selection.ok_or_else(|| missing("MC_CAM_ID"))?;
        let base = self.addr(name)?;
        self.x.get::<u32>(Addr {
            base: base.base,
            offset: base.offset + fields[1],
        })
    }

    /// Writes the `MC_CAM_ID` member `name`: the cam, the selection and its three options.
    pub(super) fn set_selection(
        &mut self,
        name: M,
        cam: u32,
        selection: u32,
        options: [bool; 3],
    ) -> Result<(), FaultKind> {
        let fields = self.library.selection.ok_or_else(|| missing("MC_CAM_ID"))?;
        let base = self.addr(name)?;
        let at = |field: u32| Addr {
            base: base.base,
            offset: base.offset + field,
        };
        self.x.set::<u32>(at(fields[0]), cam)?;
        self.x.set::<u32>(at(fields[1]), selection)?;
        for (field, value) in fields[2..].iter().zip(options) {
            self.x.set::<u8>(at(*field), u8::from(value))?;
        }
        Ok(())
    }

    /// The coupling of the `SMC_TappetData` member `name`: the absolute offset of the MC_CamIn
    /// instance that filled it, if any.
    pub(super) fn coupling(&self, name: M) -> Result<Option<usize>, FaultKind> {
        let field = self
            .library
            .coupling
            .ok_or_else(|| missing("SMC_TappetData"))?;
        let base = self.addr(name)?;
        let value = self.x.get::<u32>(Addr {
            base: base.base,
            offset: base.offset + field,
        })?;
        Ok(value.checked_sub(1).map(|at| at as usize))
    }

    /// Fills the `SMC_TappetData` member `name` with the current instance, an MC_CamIn.
    pub(super) fn set_coupling(&mut self, name: M) -> Result<(), FaultKind> {
        let field = self
            .library
            .coupling
            .ok_or_else(|| missing("SMC_TappetData"))?;
        let base = self.addr(name)?;
        let value = self.instance() as u32 + 1;
        self.x.set::<u32>(
            Addr {
                base: base.base,
                offset: base.offset + field,
            },
            value,
        )
    }

    /// Writes element `index` (1-based) of the BOOL array the VAR_IN_OUT `name` points to,
    /// which has `length` elements; an index outside it is ignored.
    pub(super) fn set_array_bool(
        &mut self,
        name: M,
        length: usize,
        index: usize,
        value: bool,
    ) -> Result<(), FaultKind> {
        if index == 0 || index > length {
            return Ok(());
        }
        if let Some(at) = self.target(name, length)? {
            self.x
                .set::<u8>(Self::absolute(at + index - 1), u8::from(value))?;
        }
        Ok(())
    }

    fn addr(&self, name: M) -> Result<Addr, FaultKind> {
        Ok(Addr {
            base: INSTANCE,
            offset: self.members.offset(name)?,
        })
    }

    /// A BOOL member.
    pub(super) fn bool(&self, name: M) -> Result<bool, FaultKind> {
        Ok(self.x.get::<u8>(self.addr(name)?)? != 0)
    }

    /// An LREAL member.
    pub(super) fn lreal(&self, name: M) -> Result<f64, FaultKind> {
        self.x.get::<f64>(self.addr(name)?)
    }

    /// An INT member (the motion library's enumerations are INTs).
    pub(super) fn int(&self, name: M) -> Result<i16, FaultKind> {
        self.x.get::<i16>(self.addr(name)?)
    }

    /// Sets a BOOL member.
    pub(super) fn set_bool(&mut self, name: M, value: bool) -> Result<(), FaultKind> {
        let addr = self.addr(name)?;
        self.x.set::<u8>(addr, u8::from(value))
    }

    /// Sets an LREAL member.
    pub(super) fn set_lreal(&mut self, name: M, value: f64) -> Result<(), FaultKind> {
        let addr = self.addr(name)?;
        self.x.set::<f64>(addr, value)
    }

    /// Sets a WORD member.
    pub(super) fn set_word(&mut self, name: M, value: u16) -> Result<(), FaultKind> {
        let addr = self.addr(name)?;
        self.x.set::<u16>(addr, value)
    }

    /// The axis the VAR_IN_OUT `name` points to; `None` when it is not connected or its
    /// `nAxisId` names no axis of the image.
    pub(super) fn axis(&self, name: M) -> Result<Option<AxisId>, FaultKind> {
        let offset = self.library.axis_id.ok_or_else(|| missing("AXIS_REF"))? as usize;
        let Some(at) = self.target(name, offset + 4)? else {
            return Ok(None);
        };
        let id = self.x.get::<u32>(Self::absolute(at + offset))?;
        Ok(self.x.motion.axis(id as usize))
    }

    /// The motion state of the engine.
    pub(super) fn motion(&mut self) -> &mut MotionState {
        self.x.motion
    }
}
