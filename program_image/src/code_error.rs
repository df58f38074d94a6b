//! Why the verifier refuses the code of a POU or of a breakpoint condition
//! (`docs/program-image.md` §7.2). The image's verification shows it after the POU's name, a
//! refused condition as the reason of its instruction, so the text stays as the verifier has
//! always written it.

use crate::code::{Operand, StdFunction};
use crate::elementary::Elementary;

/// Why the code of one POU is refused.
#[derive(Debug, thiserror::Error)]
pub(crate) enum CodeError {
    /// The POU's frame is larger than the stack.
    #[error("its frame of {frame_bytes} bytes exceeds the stack")]
    FrameExceedsStack {
        /// The frame's size in bytes.
        frame_bytes: u32,
    },
    /// A run of the frame's initial values reaches past the frame.
    #[error("an initial value lies outside its frame")]
    InitialOutsideFrame,
    /// An entry of the line table names a source file the image does not have.
    #[error("its line table names an unknown file")]
    UnknownLineFile,
    /// One instruction is refused.
    #[error("instruction {instruction}: {fault}")]
    Instruction {
        /// The instruction's index in the code.
        instruction: usize,
        /// What is wrong with it.
        fault: InstructionFault,
    },
}

impl CodeError {
    /// The index of the instruction refused (0 when the refusal names none) and the reason
    /// without it, as a refused breakpoint condition reports them.
    pub(crate) fn into_instruction_reason(self) -> (usize, String) {
        match self {
            Self::Instruction { instruction, fault } => (instruction, fault.to_string()),
            other => (0, other.to_string()),
        }
    }
}

/// What is wrong with one instruction.
#[derive(Debug, thiserror::Error)]
pub(crate) enum InstructionFault {
    /// An operand reaches past its region.
    #[error("operand {operand:?} of {size_bytes} bytes is outside its region")]
    OperandOutside {
        /// The operand.
        operand: Operand,
        /// The bytes the instruction reads or writes there.
        size_bytes: u64,
    },
    /// A jump past the end of the code.
    #[error("jump target {target} is outside the code")]
    JumpOutside {
        /// The target instruction's index.
        target: u32,
    },
    /// A call of a POU index the image does not have.
    #[error("calls POU {pou}, which does not exist")]
    UnknownPou {
        /// The POU's index.
        pou: u32,
    },
    /// A bit number past the width of its type.
    #[error("bit {bit} of a {}", ty.name())]
    BitOutside {
        /// The bit number.
        bit: u8,
        /// The type the bit is taken from.
        ty: Elementary,
    },
    /// An array access on an array of no elements.
    #[error("an array of no elements")]
    EmptyArray,
    /// An array index of a type that is not an integer.
    #[error("an index of type {}, which is not an integer", index_ty.name())]
    IndexNotInteger {
        /// The index's type.
        index_ty: Elementary,
    },
    /// The value accessed does not fit inside one element.
    #[error(
        "a {} at offset {offset} does not fit an element of {stride} bytes",
        ty.name()
    )]
    ElementTooSmall {
        /// The value's type.
        ty: Elementary,
        /// Its offset in the element, in bytes.
        offset: u32,
        /// The element's size in bytes.
        stride: u32,
    },
    /// An array larger than any region can be.
    #[error("the array {array:?} of {count} elements of {stride} bytes is larger than any region")]
    ArrayTooLarge {
        /// The array operand.
        array: Operand,
        /// Its number of elements.
        count: u64,
        /// The element's size in bytes.
        stride: u32,
    },
    /// A function call of a POU that is not a function or method.
    #[error("calls '{callee}' as a function")]
    NotAFunction {
        /// The POU called.
        callee: String,
    },
    /// A block call of a POU that is not a program, function block or action.
    #[error("calls '{callee}' as a block")]
    NotABlock {
        /// The POU called.
        callee: String,
    },
    /// A virtual call's table names a POU that is not a method.
    #[error("'{callee}' is not a method")]
    NotAMethod {
        /// The POU named.
        callee: String,
    },
    /// A parameter transfer reaches past the callee's frame.
    #[error("a parameter lies outside the frame of '{callee}'")]
    ParameterOutsideFrame {
        /// The POU called.
        callee: String,
    },
    /// A string function whose destination is of the wrong kind (integer or string).
    #[error("{function:?} gives the wrong kind of result")]
    WrongResultKind {
        /// The string function.
        function: StdFunction,
    },
    /// An open array access with no or more than eight indices.
    #[error("an open array of {dimensions} dimensions")]
    OpenArrayDimensions {
        /// The number of indices given.
        dimensions: usize,
    },
}
