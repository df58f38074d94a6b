//! The diagram canvas and the combined LD/FBD editor.

mod ld_layout;
mod placed;

pub use ld_layout::ld_layout;
pub use placed::{
    InsertPoint, InsertTarget, NetworkLayout, PinMark, PlacedElement, Power, Shape, Wire,
};
