//! The documents that hold LD and FBD bodies: one `editor::DiagramEditor` per body, fed every
//! frame with the model's networks, the live check's findings at their elements and, while
//! logged in, the power flow and values read through the lowering's probes; each change goes
//! to the model as one `Edit::SpliceNetworks` undo step.

mod body;
mod diagnostics;
mod documents;
mod online_values;
mod power;
mod probe_paths;
mod services;
mod texts;

pub(crate) use body::{GraphicalShown, graphical_body_ui};
pub use documents::GraphicalDocuments;
