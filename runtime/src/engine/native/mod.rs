//! The library function blocks the runtime runs natively (`docs/motion.md` §3–4): an image's
//! `Native { block }` instruction becomes a call of the block's adapter, which reads the
//! instance's inputs by member name, calls the `motion` function block kept for that instance,
//! and writes its outputs back.

mod cam_switch;
mod cams;
mod codes;
mod fast_hash;
mod io;
mod member;
mod single_axis;
mod state;
mod synchronised;

use program_image::{ProgramImage, StructKind, TypeDef};

use super::exec::Exec;
use super::fault::FaultKind;
use super::lower::{Flow, Op};

pub use state::MotionLoadError;
pub(crate) use state::MotionState;

use io::{Io, LibraryOffsets, Members};

/// The native blocks this runtime has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum NativeBlock {
    Power,
    Home,
    Stop,
    Halt,
    Reset,
    MoveAbsolute,
    MoveRelative,
    MoveAdditive,
    MoveVelocity,
    Jog,
    SetPosition,
    SetOverride,
    ReadActualPosition,
    ReadActualVelocity,
    ReadStatus,
    ReadAxisError,
    CamTableSelect,
    CamIn,
    CamOut,
    GearIn,
    GearOut,
    GearInPos,
    Phasing,
    CamRegister,
    GetTappetValue,
    GetCamSlaveSetPosition,
    DigitalCamSwitch,
}

impl NativeBlock {
    /// The block called `name` (any case).
    fn from_name(name: &str) -> Option<Self> {
        Some(match name.to_ascii_uppercase().as_str() {
            "MC_POWER" => Self::Power,
            "MC_HOME" => Self::Home,
            "MC_STOP" => Self::Stop,
            "MC_HALT" => Self::Halt,
            "MC_RESET" => Self::Reset,
            "MC_MOVEABSOLUTE" => Self::MoveAbsolute,
            "MC_MOVERELATIVE" => Self::MoveRelative,
            "MC_MOVEADDITIVE" => Self::MoveAdditive,
            "MC_MOVEVELOCITY" => Self::MoveVelocity,
            "MC_JOG" => Self::Jog,
            "MC_SETPOSITION" => Self::SetPosition,
            "MC_SETOVERRIDE" => Self::SetOverride,
            "MC_READACTUALPOSITION" => Self::ReadActualPosition,
            "MC_READACTUALVELOCITY" => Self::ReadActualVelocity,
            "MC_READSTATUS" => Self::ReadStatus,
            "MC_READAXISERROR" => Self::ReadAxisError,
            "MC_CAMTABLESELECT" => Self::CamTableSelect,
            "MC_CAMIN" => Self::CamIn,
            "MC_CAMOUT" => Self::CamOut,
            "MC_GEARIN" => Self::GearIn,
            "MC_GEAROUT" => Self::GearOut,
            "MC_GEARINPOS" => Self::GearInPos,
            "MC_PHASING" => Self::Phasing,
            "SMC_CAMREGISTER" => Self::CamRegister,
            "SMC_GETTAPPETVALUE" => Self::GetTappetValue,
            "SMC_GETCAMSLAVESETPOSITION" => Self::GetCamSlaveSetPosition,
            "MC_DIGITALCAMSWITCH" => Self::DigitalCamSwitch,
            _ => return None,
        })
    }

    /// Whether the block works on a master and a slave, a cam or a coupling rather than on
    /// one `Axis`.
    fn is_synchronised(self) -> bool {
        matches!(
            self,
            Self::CamTableSelect
                | Self::CamIn
                | Self::CamOut
                | Self::GearIn
                | Self::GearOut
                | Self::GearInPos
                | Self::Phasing
                | Self::CamRegister
                | Self::GetTappetValue
                | Self::GetCamSlaveSetPosition
        )
    }
}

/// The instruction that runs native block `block` on the instance of the function block
/// `pou`, whose members are found in the image's type table.
pub(crate) fn lower(block: &str, pou: &str, image: &ProgramImage) -> Result<Op, String> {
    let native = NativeBlock::from_name(block)
        .ok_or_else(|| format!("this runtime has no native function block '{block}'"))?;
    let members = image
        .types
        .iter()
        .find_map(|ty| match ty {
            TypeDef::Struct {
                name,
                kind: StructKind::FunctionBlock,
                members,
                ..
            } if name == pou => Some(Members::of(members)),
            _ => None,
        })
        .ok_or_else(|| format!("the instance type of '{pou}' is missing"))?;
    let library = LibraryOffsets::of(image);
    Ok(Box::new(move |x: &mut Exec<'_>| {
        call(x, native, &members, library).map_err(Box::new)?;
        Ok(Flow::Next)
    }))
}

/// One call of `native` on the current instance.
fn call(
    x: &mut Exec<'_>,
    native: NativeBlock,
    members: &Members,
    library: LibraryOffsets,
) -> Result<(), FaultKind> {
    let mut io = Io::new(x, members, library);
    let instance = io.instance();
    if native == NativeBlock::DigitalCamSwitch {
        cam_switch::call(&mut io, instance)
    } else if native.is_synchronised() {
        synchronised::call(&mut io, native, instance)
    } else {
        single_axis::call(&mut io, native, instance)
    }
}
