//! The CFC editor: elements placed freely on a grid, wires routed around them, and the
//! execution order shown and changed as in CODESYS.
//!
//! The chart is `project_model::CfcChart`; every gesture is one structural edit of
//! `project_model::cfc_edit` and comes out as one [`CfcChange`] holding the whole new chart,
//! which the app applies as `Edit::ReplaceChart`; the editor keeps no undo history. Element
//! sizes come from their texts ([`geometry`]), wires from a pure router ([`router`]) that is
//! run again for the wires of the elements being dragged only.

mod canvas;
mod editor;
mod entry;
pub mod geometry;
mod menu;
mod paint;
mod placing;
pub mod router;
mod texts;
mod toolbox;
mod types;

pub use editor::{CfcEditor, CfcSelection};
pub use texts::CfcTexts;
pub use types::{
    CfcChange, CfcDiagnostic, CfcOrderCommand, CfcOutput, CfcRefusal, CfcTool, VariableDragPayload,
};

#[cfg(test)]
mod tests;
