//! The string functions of the standard library as engine instructions.

use program_image::StdFunction;

use super::exec::Addr;
use super::lower::Op;

/// The instruction for a string function.
pub(crate) fn lower(
    function: StdFunction,
    _wide: bool,
    _dst: (Addr, u32),
    _args: Vec<(Addr, u32)>,
) -> Result<Op, String> {
    Err(format!(
        "the string function {function:?} is not available in this runtime"
    ))
}
