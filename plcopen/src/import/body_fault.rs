//! Why a graphical body did not become part of the project: an error in the document, or a
//! form this part of the import leaves to another.

use super::converter::Place;
use super::error::ImportErrorKind;

/// What stopped the conversion of one body.
#[derive(Clone, Debug)]
pub(super) enum BodyFault {
    /// The body is sound but holds something this import does not convert yet; the POU is
    /// reported not converted with this reason (a full sentence without the final period).
    NotConverted(String),
    /// The body is wrong: an `ImportError` of `kind` at the element `place`.
    Error(Place, ImportErrorKind),
}

/// The place of the object `element` with `local_id` in the body at `body_path`.
pub(super) fn object_place(
    body_path: &str,
    element: &str,
    local_id: u64,
    line: u32,
    column: u32,
) -> Place {
    Place {
        path: format!("{body_path}/{element}[@localId='{local_id}']"),
        line,
        column,
    }
}
