//! The paths of section 14 turned into places in the program's memory at load, with the type
//! checks of `docs/modbus-master.md` §5.2 that need the image's symbols and types.
//!
//! The image names variables by path so that the section does not change when a variable moves;
//! the scheduler copies by place, resolved here once per load (and again at an online change
//! that keeps the master running).

use program_image::modbus_master::{DeviceDef, Direction, MasterSection};
use program_image::{Elementary, ProgramImage, Region, SymbolFlags, TypeDef, TypeId};

use super::resolve_problem::ResolveProblem;
use super::status::{STATUS_BYTES, STATUS_MEMBERS, STATUS_TYPE_NAME};
use crate::value::{self, Place};

/// Where a bound variable's bytes are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BytePlace {
    /// The region.
    pub region: Region,
    /// The first byte in the region.
    pub offset: usize,
    /// How many bytes.
    pub bytes: usize,
    /// For a located BOOL, its bit within its byte (the other bits are left alone).
    pub bit: Option<u8>,
}

/// A channel's places.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChannelPlaces {
    /// The bound variable.
    pub variable: BytePlace,
    /// Whether the channel reads (the scheduler copies into the variable) or writes (out of it).
    pub direction: Direction,
    /// Its error flag, a BOOL.
    pub error_flag: Option<BytePlace>,
}

/// A device's places, and the task whose cycles copy them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DevicePlaces {
    /// The I/O task's index in the image's task table.
    pub task: usize,
    /// The channels in the project's order.
    pub channels: Vec<ChannelPlaces>,
    /// The distinct trigger variables (BOOLs) in the order they first appear.
    pub triggers: Vec<BytePlace>,
    /// The `MODBUS_DEVICE_STATUS` variable.
    pub status: Option<BytePlace>,
}

/// Why the section's paths do not fit the program: the image is refused with the device, the
/// channel's number (from 1) and the field.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
#[error("the image is inconsistent: Modbus device '{device}'{channel}, field {field}: {problem}")]
pub struct ResolveError {
    /// The device's name.
    pub device: String,
    /// `, channel N (path)` or nothing for a device's own field.
    pub channel: String,
    /// The field: `variable`, `error_flag`, `trigger`, `status`, `task`.
    pub field: &'static str,
    /// What is wrong.
    pub problem: ResolveProblem,
}

/// Resolves every device of `section` in `image`.
pub fn resolve_section(
    image: &ProgramImage,
    section: &MasterSection,
) -> Result<Vec<DevicePlaces>, ResolveError> {
    // Only constants are refused as targets: their paths, lowered once for every path asked.
    let constants: Vec<(String, Region)> = image
        .symbols
        .iter()
        .filter(|symbol| symbol.flags.has(SymbolFlags::CONSTANT))
        .map(|symbol| (symbol.path.to_ascii_lowercase(), symbol.region))
        .collect();
    let image = Resolving { image, constants };
    section
        .devices
        .iter()
        .map(|device| resolve_device(&image, device))
        .collect()
}

/// The image being resolved, with its constants' paths in lower case.
struct Resolving<'i> {
    /// The image.
    image: &'i ProgramImage,
    /// Each `CONSTANT` symbol's path in lower case, and its region.
    constants: Vec<(String, Region)>,
}

/// Resolves one device's paths and checks their types.
fn resolve_device(
    resolving: &Resolving<'_>,
    device: &DeviceDef,
) -> Result<DevicePlaces, ResolveError> {
    let image = resolving.image;
    let refuse = |channel: Option<usize>, field: &'static str, problem| ResolveError {
        device: device.name.clone(),
        channel: channel.map_or_else(String::new, |index| {
            let path = device
                .channels
                .get(index)
                .map_or("", |channel| channel.variable.as_str());
            format!(", channel {} ({path})", index + 1)
        }),
        field,
        problem,
    };
    let task = device.task as usize;
    if task >= image.tasks.len() {
        return Err(refuse(None, "task", ResolveProblem::NoTask(task)));
    }
    let mut channels = Vec::with_capacity(device.channels.len());
    let mut trigger_paths: Vec<&str> = Vec::new();
    let mut triggers = Vec::new();
    for (index, channel) in device.channels.iter().enumerate() {
        let place = lookup(image, &channel.variable)
            .map_err(|problem| refuse(Some(index), "variable", problem))?;
        if channel.direction == Direction::Read {
            writable(resolving, &channel.variable, place)
                .map_err(|problem| refuse(Some(index), "variable", problem))?;
        }
        fits_channel(image, place.ty, channel.value_type, channel.count)
            .map_err(|problem| refuse(Some(index), "variable", problem))?;
        let error_flag = match &channel.error_flag {
            Some(path) => Some(
                bool_place(resolving, path, true)
                    .map_err(|problem| refuse(Some(index), "error_flag", problem))?,
            ),
            None => None,
        };
        if let program_image::modbus_master::Trigger::RisingEdge { variable } = &channel.trigger
            && !trigger_paths
                .iter()
                .any(|known| known.eq_ignore_ascii_case(variable))
        {
            trigger_paths.push(variable);
            triggers.push(
                bool_place(resolving, variable, false)
                    .map_err(|problem| refuse(Some(index), "trigger", problem))?,
            );
        }
        channels.push(ChannelPlaces {
            variable: byte_place(place, channel.value_bytes() as usize),
            direction: channel.direction,
            error_flag,
        });
    }
    let status = match &device.status {
        Some(path) => {
            let place = lookup(image, path).map_err(|problem| refuse(None, "status", problem))?;
            writable(resolving, path, place).map_err(|problem| refuse(None, "status", problem))?;
            status_fits(image, place.ty).map_err(|problem| refuse(None, "status", problem))?;
            Some(byte_place(place, STATUS_BYTES))
        }
        None => None,
    };
    Ok(DevicePlaces {
        task,
        channels,
        triggers,
        status,
    })
}

/// The place of `path`, or why there is none.
fn lookup(image: &ProgramImage, path: &str) -> Result<Place, ResolveProblem> {
    Ok(value::resolve(image, path)?)
}

/// Refuses a `CONSTANT` as the target of a read channel, a status or an error flag.
fn writable(resolving: &Resolving<'_>, path: &str, place: Place) -> Result<(), ResolveProblem> {
    let lower = path.to_ascii_lowercase();
    let constant = resolving.constants.iter().any(|(name, region)| {
        // The symbol the path starts with: its whole name, then nothing, a member or an index.
        let names_it = lower
            .strip_prefix(name.as_str())
            .is_some_and(|rest| rest.is_empty() || rest.starts_with('.') || rest.starts_with('['));
        names_it && *region == place.region
    });
    if constant {
        return Err(ResolveProblem::Constant {
            path: path.to_owned(),
        });
    }
    Ok(())
}

/// The place of a BOOL (an error flag, which must be writable, or a trigger).
fn bool_place(
    resolving: &Resolving<'_>,
    path: &str,
    written: bool,
) -> Result<BytePlace, ResolveProblem> {
    let image = resolving.image;
    let place = lookup(image, path)?;
    if written {
        writable(resolving, path, place)?;
    }
    match image.types.get(place.ty as usize) {
        Some(TypeDef::Elementary(Elementary::Bool)) => Ok(byte_place(place, 1)),
        _ => Err(ResolveProblem::NotBool {
            path: path.to_owned(),
            type_name: type_name(image, place.ty),
        }),
    }
}

fn byte_place(place: Place, bytes: usize) -> BytePlace {
    BytePlace {
        region: place.region,
        offset: place.offset as usize,
        bytes,
        bit: place.bit,
    }
}

/// Whether a variable of type `ty` holds `count` values of `value_type` (§2.2: the elementary
/// type, or the bit string of its size for an unsigned channel; an array of exactly `count`
/// such elements for more than one).
fn fits_channel(
    image: &ProgramImage,
    ty: TypeId,
    value_type: Elementary,
    count: u16,
) -> Result<(), ResolveProblem> {
    let element = if count > 1 {
        match image.types.get(ty as usize) {
            Some(TypeDef::Array { element, dims })
                if dims.len() == 1
                    && dims[0].1.saturating_sub(dims[0].0).saturating_add(1)
                        == i64::from(count) =>
            {
                *element
            }
            _ => {
                return Err(ResolveProblem::NotAnArrayOfCount {
                    count,
                    value_type,
                    type_name: type_name(image, ty),
                });
            }
        }
    } else {
        ty
    };
    let fits = match image.types.get(element as usize) {
        Some(TypeDef::Elementary(found)) => {
            *found == value_type
                || matches!(
                    (value_type, found),
                    (Elementary::Uint, Elementary::Word)
                        | (Elementary::Udint, Elementary::Dword)
                        | (Elementary::Ulint, Elementary::Lword)
                )
        }
        _ => false,
    };
    if fits {
        Ok(())
    } else {
        Err(ResolveProblem::ElementType {
            value_type,
            type_name: type_name(image, element),
        })
    }
}

/// Whether type `ty` is the `MODBUS_DEVICE_STATUS` of §3.1: a structure of that name with its
/// members, their types and their offsets.
fn status_fits(image: &ProgramImage, ty: TypeId) -> Result<(), ResolveProblem> {
    let Some(TypeDef::Struct {
        name,
        size,
        members,
        ..
    }) = image.types.get(ty as usize)
    else {
        return Err(ResolveProblem::StatusNotStruct {
            type_name: type_name(image, ty),
        });
    };
    if !name.eq_ignore_ascii_case(STATUS_TYPE_NAME) || *size as usize != STATUS_BYTES {
        return Err(ResolveProblem::StatusOtherStruct { name: name.clone() });
    }
    for (expected, offset, elementary) in STATUS_MEMBERS {
        let Some(member) = members
            .iter()
            .find(|member| member.name.eq_ignore_ascii_case(expected))
        else {
            return Err(ResolveProblem::StatusMemberMissing { member: expected });
        };
        let ty_fits = match image.types.get(member.ty as usize) {
            Some(TypeDef::Elementary(found)) => found.size_bytes() == elementary.size_bytes(),
            // eLastError is the enumeration MB_ErrorCodes, stored as a USINT.
            Some(TypeDef::Enum { base, .. }) => base.size_bytes() == elementary.size_bytes(),
            _ => false,
        };
        if member.offset != offset || !ty_fits || member.located.is_some() {
            return Err(ResolveProblem::StatusMemberMisplaced {
                member: expected,
                elementary,
                offset,
            });
        }
    }
    Ok(())
}

/// A type's name for a message.
fn type_name(image: &ProgramImage, ty: TypeId) -> String {
    match image.types.get(ty as usize) {
        Some(TypeDef::Elementary(elementary)) => elementary.name().to_owned(),
        Some(TypeDef::Struct { name, .. } | TypeDef::Enum { name, .. }) => name.clone(),
        Some(TypeDef::Array { element, dims }) => {
            let bounds: Vec<String> = dims
                .iter()
                .map(|(low, high)| format!("{low}..{high}"))
                .collect();
            format!(
                "ARRAY[{}] OF {}",
                bounds.join(","),
                type_name(image, *element)
            )
        }
        Some(TypeDef::String { .. }) => "STRING".to_owned(),
        Some(TypeDef::WString { .. }) => "WSTRING".to_owned(),
        Some(_) => "a pointer or interface".to_owned(),
        None => format!("unknown type {ty}"),
    }
}

#[cfg(test)]
#[path = "resolve_tests.rs"]
mod tests;
