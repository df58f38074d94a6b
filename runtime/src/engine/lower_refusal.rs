//! Why an instruction of a verified image cannot be lowered: an operation on a type it does
//! not apply to, or a native block or string call the runtime cannot run. Its text is the
//! reason [`super::lower::LowerError`] and a refused breakpoint condition show.

use program_image::{BinaryOp, Elementary, StdFunction, UnaryOp};

/// Why one instruction cannot be lowered.
#[derive(Debug, thiserror::Error)]
pub(crate) enum LowerRefusal {
    /// Negation, absolute value or arithmetic on a type without numbers (BOOL).
    #[error("arithmetic on {}", ty.name())]
    Arithmetic {
        /// The operand type.
        ty: Elementary,
    },
    /// A unary operation on a type it does not apply to.
    #[error("{op:?} on {}", ty.name())]
    Unary {
        /// The operation.
        op: UnaryOp,
        /// The operand type.
        ty: Elementary,
    },
    /// A binary operation on a type it does not apply to.
    #[error("{op:?} on {}", ty.name())]
    Binary {
        /// The operation.
        op: BinaryOp,
        /// The operand type.
        ty: Elementary,
    },
    /// A native block met where its function block's instance type is not known (a
    /// breakpoint condition).
    #[error("the native block '{block}' needs its function block's instance type")]
    NativeWithoutInstance {
        /// The native block's name.
        block: String,
    },
    /// A native block this runtime does not have.
    #[error("this runtime has no native function block '{block}'")]
    UnknownNativeBlock {
        /// The native block's name.
        block: String,
    },
    /// The function block of a native block has no instance type in the image.
    #[error("the instance type of '{pou}' is missing")]
    MissingInstanceType {
        /// The function block's name.
        pou: String,
    },
    /// A string function called with arguments of the wrong number or kind.
    #[error("{function:?} has the wrong arguments")]
    StringArguments {
        /// The string function.
        function: StdFunction,
    },
}
