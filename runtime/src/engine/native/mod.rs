//! The library function blocks the runtime runs natively (`docs/motion.md` §3–4): an image's
//! `Native { block }` instruction becomes a call of the block's adapter, which reads the
//! instance's inputs by member name, calls the `motion` function block kept for that instance,
//! and writes its outputs back.

mod blocks;
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
use super::lower_refusal::LowerRefusal;

use blocks::{Adapter, NativeBlock};
pub use state::MotionLoadError;
pub(crate) use state::MotionState;

use io::{Io, LibraryOffsets, Members};

/// The instruction that runs native block `block` on the instance of the function block
/// `pou`, whose members are found in the image's type table.
pub(crate) fn lower(block: &str, pou: &str, image: &ProgramImage) -> Result<Op, LowerRefusal> {
    let native = NativeBlock::from_name(block).ok_or_else(|| LowerRefusal::UnknownNativeBlock {
        block: block.to_owned(),
    })?;
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
        .ok_or_else(|| LowerRefusal::MissingInstanceType {
            pou: pou.to_owned(),
        })?;
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
    match native.adapter() {
        Adapter::SingleAxis => single_axis::call(&mut io, native, instance),
        Adapter::Synchronised => synchronised::call(&mut io, native, instance),
        Adapter::CamSwitch => cam_switch::call(&mut io, instance),
    }
}
