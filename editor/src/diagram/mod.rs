//! The diagram canvas and the combined LD/FBD editor.
//!
//! A body is a list of networks (`project_model::network`); each is laid out by a pure function
//! ([`ld_layout`], [`fbd_layout`]) into grid cells, cached until the network changes, and only
//! the networks in view are painted. Every edit is a structural operation of
//! `project_model::network_edit` on the selection and comes out as one [`DiagramChange`]; the
//! editor never changes the model itself and keeps no undo history.

mod canvas;
pub(crate) mod canvas_input;
mod canvas_paint;
pub(crate) mod clipboard;
mod commands;
mod editor;
pub(crate) mod entry;
mod fbd_layout;
pub(crate) mod field;
mod keyboard;
mod ld_layout;
pub(crate) mod measure;
mod navigate;
mod paint;
mod placed;
mod texts;
pub(crate) mod toolbox;
mod types;

pub use commands::{DiagramCommand, DiagramSelection};
pub use editor::DiagramEditor;
pub use fbd_layout::fbd_layout;
pub use ld_layout::ld_layout;
pub use placed::{
    InsertPoint, InsertTarget, NetworkLayout, PinMark, PlacedElement, Power, Shape, Wire,
};
pub use texts::DiagramTexts;
pub use toolbox::{ToolboxBlock, ToolboxItem};
pub use types::{
    BlockSignature, DiagramChange, DiagramOnline, DiagramOutput, DiagramRefusal, DiagramServices,
    DiagramView, ElementDiagnostic, InstanceDeclaration, OnlineValue, PreparedOperand,
};

#[cfg(test)]
mod tests;
