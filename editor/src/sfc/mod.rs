//! The SFC editor: a structured chart laid out automatically ([`sfc_layout`]) and edited by
//! the commands of `project_model::sfc_edit` on the selection, as CODESYS's SFC editor does.
//!
//! Steps and transitions are inserted in pairs, branches around the selection, jumps at the
//! end of a branch; an edit that would break the chart's structure is refused with the rule's
//! reason. Every gesture comes out as one [`SfcChange`] holding the new chart, applied by the
//! app as `Edit::ReplaceChart`; the editor never changes the model itself. Online, active
//! steps are filled, each step shows its elapsed time, transitions their values, and the user
//! can (de)activate steps and fire transitions in tip mode through [`SfcOnlineCommand`]s.

mod canvas;
mod commands;
mod editor;
mod entry;
mod layout;
mod paint;
mod panel;
mod run;
mod texts;
mod types;

pub use commands::SfcCommand;
pub use editor::SfcEditor;
pub use layout::{ActionBox, SfcLayout, SfcLine, SfcPlaced, SfcShape, sfc_layout};
pub use texts::{SfcRefusalWords, SfcTexts};
pub use types::{SfcChange, SfcDiagnostic, SfcOnline, SfcOnlineCommand, SfcOutput, SfcStepOnline};

#[cfg(test)]
mod tests;
