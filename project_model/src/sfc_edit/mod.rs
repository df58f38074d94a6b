//! Structural edits of an SFC chart, the operations behind every gesture of the SFC editor.
//!
//! Each edit is a pure function from a chart to a new chart or a typed refusal
//! ([`SfcEditError`]) naming the rule it would break: the result of every edit is checked
//! against the structural rules of `sfc.rs` ([`check_structure`]), so no edit can produce a
//! chart that cannot be drawn or saved. New elements take the ids after the chart's highest
//! one, and new steps the first free name `Step<n>` (case-insensitive, macro steps included).
//! The initial step is always the first node of the main sequence: inserting before it makes
//! the new step the initial one.

mod clipboard;
mod delete;
mod error;
mod insert;
mod properties;
mod shape;
mod walk;

pub use clipboard::{copy_nodes, paste_after};
pub use delete::delete_nodes;
pub use error::{SfcEditError, SfcRule};
pub use insert::{
    add_branch, insert_alternative_branch, insert_jump_after, insert_macro_step_after,
    insert_parallel_branch, insert_step_transition_after, insert_step_transition_before,
    wrap_in_macro,
};
pub use properties::{
    StepProperties, add_association, move_association, remove_association, rename_step,
    set_association, set_jump_target, set_step_properties, set_transition_condition,
    set_transition_priority,
};
pub use shape::check_structure;
pub use walk::{find_node, max_sfc_id, step_names};

#[cfg(test)]
mod tests;
