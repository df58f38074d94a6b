//! The controller's local I/O areas.

use serde::{Deserialize, Serialize};

/// A block of the controller's process image that variables bind to with `AT` addresses.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct IoArea {
    /// A name for the block, such as `DI_16`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// Which memory area the block lies in.
    pub direction: IoDirection,
    /// The first byte of the block in its area (`%IB<start_byte>`).
    pub start_byte: u32,
    /// The size of the block in bytes.
    pub size_bytes: u32,
    /// What is wired to it.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

/// The memory area of an I/O block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(rename_all = "snake_case")]
pub enum IoDirection {
    /// Inputs, `%I`.
    Input,
    /// Outputs, `%Q`.
    Output,
    /// Marker memory, `%M`.
    Memory,
}

impl IoDirection {
    /// The address prefix letter: `I`, `Q` or `M`.
    pub fn area_letter(self) -> char {
        match self {
            Self::Input => 'I',
            Self::Output => 'Q',
            Self::Memory => 'M',
        }
    }
}
