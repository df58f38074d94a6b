//! The typed layer over the lossless tree: one wrapper per node kind with named accessors, as
//! rust-analyzer's `ast` does.
//!
//! The checker and the code generator read bodies through these wrappers only, so what a node
//! holds (which child is the condition, which token the operator) is written down once, here,
//! next to the grammar that builds it. Every accessor returns an `Option` (or an iterator) and
//! never panics: on broken input a missing part is `None`.

mod declarations;
mod expressions;
mod items;
mod nodes;
mod statements;
mod support;

pub use declarations::{InitValue, TypeExpr};
pub use expressions::{ArgKind, Expr};
pub use items::{Item, PouMember};
pub use nodes::*;
pub use statements::{CaseLabel, Stmt};
pub use support::AstChildren;

use super::{SyntaxKind, SyntaxNode};

/// A typed view of a node of one kind (or, for an enum, of one of several kinds).
pub trait AstNode: Sized {
    /// Whether a node of `kind` can be viewed as this type.
    fn can_cast(kind: SyntaxKind) -> bool;
    /// The typed view of `node`, if it has a kind this type stands for.
    fn cast(node: SyntaxNode) -> Option<Self>;
    /// The node under the view.
    fn syntax(&self) -> &SyntaxNode;
}

#[cfg(test)]
mod declaration_tests;
#[cfg(test)]
mod tests;
