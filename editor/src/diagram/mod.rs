//! The diagram canvas and the combined LD/FBD editor.

mod fbd_layout;
mod ld_layout;
mod placed;

pub use fbd_layout::fbd_layout;
pub use ld_layout::ld_layout;
pub use placed::{
    InsertPoint, InsertTarget, NetworkLayout, PinMark, PlacedElement, Power, Shape, Wire,
};
