//! The checker's type of every expression of a body, which the code generator reads.

use std::collections::HashMap;

use rustc_hash::FxHashMap;

use super::ty::Type;
use crate::syntax::{SyntaxKind, SyntaxNode};

/// The type of each expression of one body, by the expression's kind and byte range.
///
/// The key is the node's kind and range rather than the node itself: a `SyntaxNode` held as a
/// key keeps its cursor allocated and hashes through a pointer chase, which made typing and
/// reading a large lowered body (10,000 LD networks) cost more than checking it; the key is
/// hashed with Fx rather than SipHash, as nothing here comes from a peer. No two expression
/// nodes of one tree have the same kind and range, so the key is exact.
#[derive(Debug, Default)]
pub(crate) struct ExpressionTypes {
    /// The types, by [`key`].
    types: FxHashMap<(SyntaxKind, u32, u32), Type>,
}

impl ExpressionTypes {
    /// Records the type of `node`.
    pub(crate) fn insert(&mut self, node: &SyntaxNode, ty: Type) {
        self.types.insert(key(node), ty);
    }

    /// The type recorded for `node`, if it was checked.
    pub(crate) fn get(&self, node: &SyntaxNode) -> Option<&Type> {
        self.types.get(&key(node))
    }
}

/// The kind and byte range of `node`.
fn key(node: &SyntaxNode) -> (SyntaxKind, u32, u32) {
    let range = node.text_range();
    (node.kind(), range.start().into(), range.end().into())
}

/// The tree and expression types of each body the checker checked, by the body's file, kept
/// for the code generator so a body is parsed and typed once per compile.
#[derive(Debug, Default)]
pub(crate) struct CheckedBodies {
    /// The tree's root and its types, by the body's (`.st`) file.
    bodies: HashMap<std::path::PathBuf, (SyntaxNode, ExpressionTypes)>,
}

impl CheckedBodies {
    /// Keeps the checked tree `root` of the body in `file` with its types.
    pub(crate) fn keep(
        &mut self,
        file: &std::path::Path,
        root: SyntaxNode,
        types: ExpressionTypes,
    ) {
        self.bodies.insert(file.to_owned(), (root, types));
    }

    /// Takes the tree and types of the body in `file` whose text is `text`; `None` when the
    /// checker did not check that text (the caller parses and types it itself).
    pub(crate) fn take(
        &mut self,
        file: &std::path::Path,
        text: &str,
    ) -> Option<(SyntaxNode, ExpressionTypes)> {
        let (root, types) = self.bodies.remove(file)?;
        (usize::from(root.text_range().len()) == text.len()).then_some((root, types))
    }
}
