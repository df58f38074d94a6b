//! Structural edits of a CFC chart: pure functions that take a [`CfcChart`] and return the new
//! chart, or a [`CfcEditError`] naming why the edit does not apply.
//!
//! The CFC editor turns every gesture into one of these and hands the result to the app as
//! `Edit::ReplaceChart`, so one gesture is one undo step. Every function keeps the chart's
//! rules (unique ids, a dense execution order over the executable elements, wires from an
//! output pin to an input pin, at most one wire per input pin).
//!
//! Decisions where CODESYS leaves room:
//! - Connecting to an input pin that is already driven **replaces** the old wire, as CODESYS
//!   does when a connection is dropped on a connected input; undo brings the old one back.
//! - A wire from an element to itself is a feedback and is allowed only on a box (which keeps
//!   its output from the previous cycle); other elements refuse it.

mod elements;
mod order;
mod pins;
mod wires;

pub use elements::{add_element, copy_elements, delete_elements, move_elements, paste_elements};
pub use order::{
    move_down, move_up, order_by_data_flow, order_by_topology, send_to_back, send_to_front,
    set_execution_order,
};
pub use pins::{
    extend_box, is_extensible, set_box_type, set_coil, set_edge, set_instance, set_members,
    set_text, toggle_negation,
};
pub use wires::{add_control_point, connect, disconnect, move_control_point, remove_control_point};

use thiserror::Error;

use crate::{CfcChart, CfcElement, ElementId, PinRef};

/// Why a CFC edit does not apply.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum CfcEditError {
    /// No element of the chart has this id.
    #[error("no element has the id {}", .0.0)]
    NoElement(ElementId),
    /// The edit needs at least one element and none was given.
    #[error("no element is selected")]
    NothingSelected,
    /// The pin is not an output pin of its element.
    #[error("element {} has no output pin '{}'", .0.element.0, .0.pin)]
    NotAnOutput(PinRef),
    /// The pin is not an input pin of its element.
    #[error("element {} has no input pin '{}'", .0.element.0, .0.pin)]
    NotAnInput(PinRef),
    /// A wire from an element to itself, on an element that cannot feed itself back.
    #[error("element {} cannot be wired to itself (only a box keeps a feedback)", .0.0)]
    SelfConnection(ElementId),
    /// No wire drives this input pin.
    #[error("no wire drives pin '{}' of element {}", .0.pin, .0.element.0)]
    NoWire(PinRef),
    /// A wire has no control point at this index.
    #[error("the wire into element {} has no control point {index}", .to.element.0)]
    NoControlPoint {
        /// The wire's driven pin.
        to: PinRef,
        /// The index asked for.
        index: usize,
    },
    /// The element does not run by itself, so it has no place in the execution order.
    #[error("element {} has no execution order (only boxes, outputs, jumps, labels, returns, composers and selectors do)", .0.0)]
    NotExecutable(ElementId),
    /// An execution order number past the last one.
    #[error("execution order {order} is out of range (the chart runs {count} elements)")]
    OrderOutOfRange {
        /// The number asked for.
        order: u32,
        /// How many elements the chart runs.
        count: u32,
    },
    /// The edit applies to another kind of element.
    #[error("{operation} does not apply to element {}", .id.0)]
    WrongKind {
        /// What was asked, such as "set the coil".
        operation: &'static str,
        /// The element.
        id: ElementId,
    },
    /// The box's type cannot take one more input.
    #[error("a {type_name} box cannot take more inputs")]
    NotExtensible {
        /// The box's type.
        type_name: String,
    },
}

/// The element `id` of `chart`.
fn element(chart: &CfcChart, id: ElementId) -> Result<&CfcElement, CfcEditError> {
    chart
        .elements
        .iter()
        .find(|element| element.id == id)
        .ok_or(CfcEditError::NoElement(id))
}

/// The element `id` of `chart`, to change.
fn element_mut(chart: &mut CfcChart, id: ElementId) -> Result<&mut CfcElement, CfcEditError> {
    chart
        .elements
        .iter_mut()
        .find(|element| element.id == id)
        .ok_or(CfcEditError::NoElement(id))
}

/// Numbers the executable elements 0 to n-1 in their current order (ties by id), closing the
/// gaps a deletion or an insertion left.
fn renumber(chart: &mut CfcChart) {
    let mut executable: Vec<(u32, ElementId)> = chart
        .elements
        .iter()
        .filter(|element| element.kind.is_executable())
        .map(|element| (element.order.unwrap_or(u32::MAX), element.id))
        .collect();
    executable.sort();
    let place: std::collections::HashMap<ElementId, u32> = executable
        .iter()
        .zip(0_u32..)
        .map(|((_, id), order)| (*id, order))
        .collect();
    for element in &mut chart.elements {
        element.order = place.get(&element.id).copied();
    }
}

#[cfg(test)]
mod tests;
