//! Rivet's document editors: the Structured Text editor, the LD, FBD, CFC and SFC canvases and
//! the variable declaration table.
//!
//! Editors draw from the project model and never change it while drawing: they emit edits that
//! the app applies after the frame. They see the compiler only through its `ide` facade.
//!
//! Today the crate offers the read-only [`CodeView`] with lexical highlighting of Structured
//! Text, which the studio uses to show POUs, global variable lists and data types; the
//! [`VariableTable`] that edits declarations in place; and the I/O mapping view
//! ([`io_mapping_ui`]) that lists each channel of the controller's I/O areas and of the Modbus
//! TCP devices with the variables bound to it.

mod code_view;
mod io_mapping;
mod st_highlight;
mod variable_table;

pub use code_view::CodeView;
pub use io_mapping::{IoMappingOutput, io_mapping_ui};
pub use st_highlight::{TokenClass, classify_tokens};
pub use variable_table::{VariableTable, VariableTableOutput, overlap_warnings};
