//! The checker's type of every expression of a body, which the code generator reads.

use std::collections::HashMap;

use super::ty::Type;
use crate::syntax::{SyntaxKind, SyntaxNode};

/// The type of each expression of one body, by the expression's kind and byte range.
///
/// The key is the node's kind and range rather than the node itself: a `SyntaxNode` held as a
/// key keeps its cursor allocated and hashes through a pointer chase, which made typing and
/// reading a large lowered body (10,000 LD networks) cost more than checking it. No two
/// expression nodes of one tree have the same kind and range, so the key is exact. The
/// entries are found through their start offset, as a table indexed by offset with a short
/// chain of the expressions starting there (`a` and `a AND b` start together): no hashing,
/// and the code generator, which reads them in text order, walks the table in order.
#[derive(Debug, Default)]
pub(crate) struct ExpressionTypes {
    /// By start offset, 1 + the index in `entries` of the last expression recorded there; 0
    /// for none.
    first: Vec<u32>,
    /// Every recorded expression, each linking to the one recorded before it at its start.
    entries: Vec<Entry>,
}

/// One recorded expression.
#[derive(Debug)]
struct Entry {
    /// The end offset.
    end: u32,
    /// The node's kind.
    kind: SyntaxKind,
    /// 1 + the index of the previous entry with the same start; 0 for none.
    next: u32,
    /// The type.
    ty: Type,
}

impl ExpressionTypes {
    /// Records the type of `node`; a node recorded again gets the later type.
    pub(crate) fn insert(&mut self, node: &SyntaxNode, ty: Type) {
        let (kind, start, end) = key(node);
        let start = start as usize;
        if start >= self.first.len() {
            self.first.resize(start + 1, 0);
        }
        self.entries.push(Entry {
            end,
            kind,
            next: self.first[start],
            ty,
        });
        // A body's text is far below 4 GiB, as every offset of the tree is a u32.
        self.first[start] = u32::try_from(self.entries.len()).unwrap_or(u32::MAX);
    }

    /// The type recorded for `node`, if it was checked.
    pub(crate) fn get(&self, node: &SyntaxNode) -> Option<&Type> {
        let (kind, start, end) = key(node);
        let mut at = *self.first.get(start as usize)?;
        while let Some(entry) = at
            .checked_sub(1)
            .and_then(|index| self.entries.get(index as usize))
        {
            if entry.end == end && entry.kind == kind {
                return Some(&entry.ty);
            }
            at = entry.next;
        }
        None
    }
}

/// The kind, start and end of `node`.
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::ast::AstNode;
    use crate::syntax::parse_statements;

    #[test]
    fn each_expression_gets_its_own_type_also_where_several_start_together() {
        let root = parse_statements("x := a AND b;").syntax();
        let expressions: Vec<SyntaxNode> = root
            .descendants()
            .filter(|node| crate::syntax::ast::Expr::can_cast(node.kind()))
            .collect();
        let mut types = ExpressionTypes::default();
        for (at, node) in expressions.iter().enumerate() {
            types.insert(node, Type::IntLiteral(Some(at as i128)));
        }
        for (at, node) in expressions.iter().enumerate() {
            assert_eq!(types.get(node), Some(&Type::IntLiteral(Some(at as i128))));
        }
        types.insert(&expressions[0], Type::BOOL);
        assert_eq!(types.get(&expressions[0]), Some(&Type::BOOL));
        assert_eq!(types.get(&root), None);
    }
}
