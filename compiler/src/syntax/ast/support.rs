//! Helpers the accessors share: finding children by type and tokens by kind.

use std::marker::PhantomData;

use super::AstNode;
use crate::syntax::{SyntaxKind, SyntaxNode, SyntaxToken};

/// The children of a node that are of type `N`, in source order.
#[derive(Clone, Debug)]
pub struct AstChildren<N> {
    inner: rowan::SyntaxNodeChildren<crate::syntax::StLanguage>,
    marker: PhantomData<N>,
}

impl<N: AstNode> Iterator for AstChildren<N> {
    type Item = N;

    fn next(&mut self) -> Option<N> {
        self.inner.by_ref().find_map(N::cast)
    }
}

impl<N: AstNode> AstChildren<N> {
    /// The children of `parent` of type `N`, for a view that gathers several node types of
    /// its own (as the outline does).
    pub(crate) fn new(parent: &SyntaxNode) -> Self {
        children(parent)
    }
}

/// The children of `parent` of type `N`.
pub(super) fn children<N: AstNode>(parent: &SyntaxNode) -> AstChildren<N> {
    AstChildren {
        inner: parent.children(),
        marker: PhantomData,
    }
}

/// The first child of `parent` of type `N`.
pub(super) fn child<N: AstNode>(parent: &SyntaxNode) -> Option<N> {
    children(parent).next()
}

/// The `n`-th child node of `parent` (0-based, whatever its kind), as `N` if it is one.
///
/// Used where the grammar puts nodes of the same type side by side (the two operands of a
/// binary expression): the position is what tells them apart.
pub(super) fn nth_node<N: AstNode>(parent: &SyntaxNode, n: usize) -> Option<N> {
    parent.children().nth(n).and_then(N::cast)
}

/// The tokens directly in `parent`, without trivia.
pub(super) fn tokens(parent: &SyntaxNode) -> impl Iterator<Item = SyntaxToken> + use<> {
    parent
        .children_with_tokens()
        .filter_map(|element| element.into_token())
        .filter(|token| !token.kind().is_trivia())
}

/// The first token of `kind` directly in `parent`.
pub(super) fn token(parent: &SyntaxNode, kind: SyntaxKind) -> Option<SyntaxToken> {
    tokens(parent).find(|token| token.kind() == kind)
}

/// The node of type `N` that comes right after the first token of `kind` in `parent`,
/// trivia aside; `None` when something else (or nothing) follows the token, or there is no
/// such token. With `kind` `None`, the node right after the first token of `parent`.
pub(super) fn node_after<N: AstNode>(parent: &SyntaxNode, kind: Option<SyntaxKind>) -> Option<N> {
    let mut elements = parent
        .children_with_tokens()
        .filter(|element| !element.kind().is_trivia());
    match kind {
        Some(kind) => {
            elements.find(|element| element.as_token().is_some_and(|t| t.kind() == kind))?
        }
        None => elements.find(|element| element.as_token().is_some())?,
    };
    elements.next()?.into_node().and_then(N::cast)
}

/// The trimmed text of a node, as names are compared and shown.
pub(super) fn trimmed_text(node: &SyntaxNode) -> String {
    node.text().to_string().trim().to_owned()
}
