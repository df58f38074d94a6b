//! Where to put the caret when a document opens.

use std::ops::Range;

use project_model::TextTarget;

/// Where to put the caret in a document.
#[derive(Clone, Debug, PartialEq)]
pub enum Reveal {
    /// A byte range of a body.
    Body(TextTarget, Range<usize>),
    /// The declaration of a name in the document's (or its method's) declarations.
    Declaration {
        /// The method or property that declares it, if not the POU itself.
        container: Option<String>,
        /// The declared name.
        name: String,
    },
}
