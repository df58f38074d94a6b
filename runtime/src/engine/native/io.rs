//! Reading and writing a native block's instance by member name, and following its VAR_IN_OUT
//! pointers to the axes.

use std::collections::HashMap;

use motion::kernel::AxisId;
use program_image::{Member, ProgramImage, StructKind, TypeDef};

use super::state::MotionState;
use crate::engine::exec::{ABSOLUTE, Addr, Exec, INSTANCE};
use crate::engine::fault::FaultKind;

/// The byte offsets of an instance's members, by lower-case name.
#[derive(Clone, Debug)]
pub(super) struct Members {
    offsets: HashMap<String, u32>,
}

impl Members {
    /// The members of a function block's instance type.
    pub(super) fn of(_image: &ProgramImage, members: &[Member]) -> Self {
        Self {
            offsets: members
                .iter()
                .map(|member| (member.name.to_lowercase(), member.offset))
                .collect(),
        }
    }

    /// The offset of `nAxisId` in the image's `AXIS_REF`.
    pub(super) fn axis_id_offset(image: &ProgramImage) -> Option<u32> {
        image.types.iter().find_map(|ty| match ty {
            TypeDef::Struct {
                name,
                kind: StructKind::Struct,
                members,
                ..
            } if name == "AXIS_REF" => members
                .iter()
                .find(|member| member.name.eq_ignore_ascii_case("nAxisId"))
                .map(|member| member.offset),
            _ => None,
        })
    }

    fn offset(&self, name: &str) -> Result<u32, FaultKind> {
        self.offsets
            .get(&name.to_lowercase())
            .copied()
            .ok_or_else(|| {
                FaultKind::Internal(format!(
                    "a native function block has no member '{name}' (the image and the runtime disagree about the motion library)"
                ))
            })
    }
}

/// One native call's view of its instance.
pub(super) struct Io<'x, 'a> {
    x: &'x mut Exec<'a>,
    members: &'x Members,
    axis_id_offset: u32,
}

impl<'x, 'a> Io<'x, 'a> {
    /// A view of the current instance of `x`.
    pub(super) fn new(x: &'x mut Exec<'a>, members: &'x Members, axis_id_offset: u32) -> Self {
        Self {
            x,
            members,
            axis_id_offset,
        }
    }

    fn addr(&self, name: &str) -> Result<Addr, FaultKind> {
        Ok(Addr {
            base: INSTANCE,
            offset: self.members.offset(name)?,
        })
    }

    /// A BOOL member.
    pub(super) fn bool(&self, name: &str) -> Result<bool, FaultKind> {
        Ok(self.x.get::<u8>(self.addr(name)?)? != 0)
    }

    /// An LREAL member.
    pub(super) fn lreal(&self, name: &str) -> Result<f64, FaultKind> {
        self.x.get::<f64>(self.addr(name)?)
    }

    /// An INT member (the motion library's enumerations are INTs).
    pub(super) fn int(&self, name: &str) -> Result<i16, FaultKind> {
        self.x.get::<i16>(self.addr(name)?)
    }

    /// Sets a BOOL member.
    pub(super) fn set_bool(&mut self, name: &str, value: bool) -> Result<(), FaultKind> {
        let addr = self.addr(name)?;
        self.x.set::<u8>(addr, u8::from(value))
    }

    /// Sets an LREAL member.
    pub(super) fn set_lreal(&mut self, name: &str, value: f64) -> Result<(), FaultKind> {
        let addr = self.addr(name)?;
        self.x.set::<f64>(addr, value)
    }

    /// Sets a WORD member.
    pub(super) fn set_word(&mut self, name: &str, value: u16) -> Result<(), FaultKind> {
        let addr = self.addr(name)?;
        self.x.set::<u16>(addr, value)
    }

    /// The axis the VAR_IN_OUT `name` points to; `None` when it is not connected or its
    /// `nAxisId` names no axis of the image.
    pub(super) fn axis(&self, name: &str) -> Result<Option<AxisId>, FaultKind> {
        let pointer = self.x.get::<u64>(self.addr(name)?)?;
        if pointer == 0 {
            return Ok(None);
        }
        let at = self.x.deref(pointer, self.axis_id_offset as usize + 4)?;
        let id = self.x.get::<u32>(Addr {
            base: ABSOLUTE,
            offset: (at + self.axis_id_offset as usize) as u32,
        })?;
        Ok(self.x.motion.axis(id as usize))
    }

    /// The motion state of the engine.
    pub(super) fn motion(&mut self) -> &mut MotionState {
        self.x.motion
    }
}
