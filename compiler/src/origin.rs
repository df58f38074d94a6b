//! Where a piece of a body comes from, so what the compiler reports maps back to what the user
//! wrote or drew (ARCHITECTURE.md, "Bodies and their origins").

use std::ops::Range;

/// Where a piece of a body comes from: what a code generation error (and, through their text
/// ranges, a diagnostic, a line-table entry or a value probe) points back to.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Origin {
    /// A byte range of a Structured Text body's text.
    Text {
        /// The bytes, from the start of the body's text.
        range: Range<usize>,
    },
}

impl Origin {
    /// The origin of the syntax node `node` of an ST body: its own text range.
    pub(crate) fn of_node(node: &crate::syntax::SyntaxNode) -> Self {
        let range = node.text_range();
        Self::Text {
            range: usize::from(range.start())..usize::from(range.end()),
        }
    }
}
