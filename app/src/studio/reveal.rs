//! Where to put the caret when a document opens.

use std::ops::Range;

use project_model::{ElementId, TextTarget};

/// Where to put the caret in a document.
#[derive(Clone, Debug, PartialEq)]
pub enum Reveal {
    /// A byte range of a body.
    Body(TextTarget, Range<usize>),
    /// A network of an LD or FBD body, and one of its elements.
    Element {
        /// Which body.
        target: TextTarget,
        /// The network's index, from 0.
        network: usize,
        /// The element, or `None` for the network itself.
        element: Option<ElementId>,
    },
    /// The declaration of a name in the document's (or its method's) declarations.
    Declaration {
        /// The method or property that declares it, if not the POU itself.
        container: Option<String>,
        /// The declared name.
        name: String,
    },
}
