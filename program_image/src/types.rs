//! The type table: what the online side needs to name members and elements and to show values.

use serde::{Deserialize, Serialize};

use crate::Elementary;

/// Index of a type in [`crate::ProgramImage::types`].
pub type TypeId = u32;

/// One entry of the type table (`docs/program-image.md` §4).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum TypeDef {
    /// An elementary type.
    Elementary(Elementary),
    /// `STRING(length)`: `length + 1` bytes, zero-terminated.
    String {
        /// The maximum number of characters.
        length: u32,
    },
    /// `WSTRING(length)`: `2 * (length + 1)` bytes of UTF-16 code units, zero-terminated.
    WString {
        /// The maximum number of characters.
        length: u32,
    },
    /// An array, dense, first dimension outermost.
    Array {
        /// The element type.
        element: TypeId,
        /// Bounds per dimension, inclusive.
        dims: Vec<(i64, i64)>,
    },
    /// A structure or an instance (FB, program): named members at offsets.
    Struct {
        /// The declared name.
        name: String,
        /// What kind of composite this is.
        kind: StructKind,
        /// The size in bytes.
        size: u32,
        /// The members in declaration order.
        members: Vec<Member>,
    },
    /// An enumeration stored as its base integer type.
    Enum {
        /// The declared name.
        name: String,
        /// The integer type it is stored as.
        base: Elementary,
        /// The values by name.
        values: Vec<(String, i64)>,
    },
    /// `POINTER TO`, `REFERENCE TO` or a `VAR_IN_OUT`: an 8-byte pointer value (§5.2).
    Pointer {
        /// The target type; `None` for an untyped pointer.
        target: Option<TypeId>,
        /// Whether it is a reference (used as its target) rather than a pointer.
        reference: bool,
    },
    /// A variable of an interface type: 16 bytes, a pointer to the instance (§5.2) and the
    /// POU index of the instance's function block (its class), which selects the methods.
    Interface {
        /// The interface's name.
        name: String,
    },
    /// A VAR_IN_OUT of an array with open bounds (`ARRAY[*] OF T`): a descriptor of
    /// `8 + 16 * rank` bytes, the pointer to the caller's array, then each dimension's low and
    /// high bound as `i64`.
    OpenArray {
        /// The element type.
        element: TypeId,
        /// The number of dimensions.
        rank: u32,
    },
}

/// What a [`TypeDef::Struct`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum StructKind {
    /// A `STRUCT` data type.
    Struct,
    /// A function block instance.
    FunctionBlock,
    /// A program instance.
    Program,
}

/// A member of a structure or instance.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Member {
    /// The declared name.
    pub name: String,
    /// Its type.
    pub ty: TypeId,
    /// Byte offset from the start of the structure.
    pub offset: u32,
    /// For a located member, where it really lives; the offset is then meaningless.
    pub located: Option<crate::Located>,
    /// The `VAR_*` section flags of [`crate::SymbolFlags`].
    pub flags: u16,
}

impl TypeDef {
    /// The size in bytes of a value of this type, given the table for the types it refers to.
    pub fn size_bytes(&self, table: &[TypeDef]) -> u64 {
        self.size_with(table, 0)
    }

    fn size_with(&self, table: &[TypeDef], depth: u32) -> u64 {
        match self {
            Self::Elementary(e) => u64::from(e.size_bytes()),
            Self::String { length } => u64::from(*length) + 1,
            Self::WString { length } => 2 * (u64::from(*length) + 1),
            Self::Array { element, dims } => {
                // Depth is bounded by the verifier, which refuses cycles; this guard keeps a
                // hostile table from recursing without end before it is verified.
                if depth > 64 {
                    return 0;
                }
                let count = dims.iter().fold(1u64, |count, (low, high)| {
                    count.saturating_mul(high.saturating_sub(*low).saturating_add(1).max(0) as u64)
                });
                let element = table
                    .get(*element as usize)
                    .map_or(0, |t| t.size_with(table, depth + 1));
                count.saturating_mul(element)
            }
            Self::Struct { size, .. } => u64::from(*size),
            Self::Enum { base, .. } => u64::from(base.size_bytes()),
            Self::Pointer { .. } => 8,
            Self::Interface { .. } => 16,
            Self::OpenArray { rank, .. } => 8 + 16 * u64::from(*rank),
        }
    }
}
