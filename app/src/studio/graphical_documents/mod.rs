//! The documents that hold LD and FBD bodies: one `editor::DiagramEditor` per body, fed every
//! frame with the model's networks, the live check's findings at their elements and, while
//! logged in, the power flow and values read through the lowering's probes; each change goes
//! to the model as one `Edit::SpliceNetworks` undo step. The CFC and SFC bodies have their
//! chart editors (`editor::CfcEditor`, `editor::SfcEditor`) fed the same way, each change one
//! `Edit::ReplaceChart` undo step.

mod body;
mod breakpoints;
mod chart_body;
mod chart_documents;
mod chart_online;
mod chart_texts;
mod diagnostics;
mod documents;
mod online_values;
mod power;
mod probe_paths;
mod services;
mod texts;

pub(crate) use body::{GraphicalShown, graphical_body_ui};
pub(crate) use chart_body::{ChartShown, cfc_body_ui, sfc_body_ui};
pub use documents::GraphicalDocuments;

use breakpoints::{body_marks, focused_place, toggle_breakpoint};
