//! What is wrong with one path of section 14 when the runtime resolves it at load
//! (`docs/modbus-master.md` §5.2), the `problem` of a [`ResolveError`](super::ResolveError).

use program_image::Elementary;

use super::status::{STATUS_BYTES, STATUS_TYPE_NAME};
use crate::value::PathError;

/// Why one field of a device (its task, a channel's variable, error flag or trigger, its
/// status) does not fit the program. Its `Display` is the words a load error ends with.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum ResolveProblem {
    /// The device's I/O task is not in the image's task table.
    #[error("task {0} does not exist")]
    NoTask(usize),
    /// The path names no value of the program.
    #[error(transparent)]
    Path(#[from] PathError),
    /// The runtime would write a `CONSTANT`.
    #[error("'{path}' is a constant, which the runtime cannot write")]
    Constant {
        /// The path as the section has it.
        path: String,
    },
    /// An error flag or a trigger that is no BOOL.
    #[error("'{path}' is of type {type_name}, not BOOL")]
    NotBool {
        /// The path as the section has it.
        path: String,
        /// The variable's type, as the image names it.
        type_name: String,
    },
    /// A channel of several values whose variable is not an array of that many.
    #[error(
        "the channel has {count} {} values, but the variable is of type {type_name}: expected an ARRAY of {count} elements",
        value_type.name()
    )]
    NotAnArrayOfCount {
        /// How many values the channel holds.
        count: u16,
        /// The channel's value type.
        value_type: Elementary,
        /// The variable's type, as the image names it.
        type_name: String,
    },
    /// A channel whose variable (or its array's element) is of another type.
    #[error(
        "the channel carries {} values, but the variable's element type is {type_name}",
        value_type.name()
    )]
    ElementType {
        /// The channel's value type.
        value_type: Elementary,
        /// The variable's (or element's) type, as the image names it.
        type_name: String,
    },
    /// A status variable that is no structure.
    #[error("the status variable is of type {type_name}, not {}", STATUS_TYPE_NAME)]
    StatusNotStruct {
        /// The variable's type, as the image names it.
        type_name: String,
    },
    /// A status variable of another structure, or of the right name and another size.
    #[error(
        "the status variable is of type {name}, not {} of {} bytes",
        STATUS_TYPE_NAME,
        STATUS_BYTES
    )]
    StatusOtherStruct {
        /// The structure's name.
        name: String,
    },
    /// A status structure without one of the members the runtime writes.
    #[error("{} has no member {member}", STATUS_TYPE_NAME)]
    StatusMemberMissing {
        /// The member's name.
        member: &'static str,
    },
    /// A status member of another size, at another offset, or located.
    #[error(
        "{}.{member} is not a {} at offset {offset}",
        STATUS_TYPE_NAME,
        elementary.name()
    )]
    StatusMemberMisplaced {
        /// The member's name.
        member: &'static str,
        /// The type the runtime writes there.
        elementary: Elementary,
        /// Its offset in bytes.
        offset: u32,
    },
}
