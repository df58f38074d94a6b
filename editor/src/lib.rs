//! Rivet's document editors: the Structured Text editor, the LD, FBD, CFC and SFC canvases and
//! the variable declaration table.
//!
//! Editors draw from the project model and never change it while drawing: they emit edits that
//! the app applies after the frame. They see the compiler only through its `ide` facade.
//!
//! Today the crate offers the read-only [`CodeView`] with lexical highlighting of Structured
//! Text, which the studio uses to show POUs, global variable lists and data types.

mod code_view;
mod st_highlight;

pub use code_view::CodeView;
pub use st_highlight::{TokenClass, classify_tokens};
