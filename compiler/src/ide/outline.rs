//! The document outline: POUs, their members and declarations, types, steps.

use std::ops::Range;

use super::trimmed_range;
use crate::declaration_parts::first_keyword;
use crate::syntax::SyntaxKind::*;
use crate::syntax::{SyntaxNode, parse};

/// An entry of the outline.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutlineItem {
    /// The declared name.
    pub name: String,
    /// What it is.
    pub kind: OutlineKind,
    /// The whole declaration.
    pub range: Range<usize>,
    /// The name itself, where the cursor goes when the entry is picked.
    pub name_range: Range<usize>,
    /// Entries declared inside it.
    pub children: Vec<OutlineItem>,
}

/// Kinds of outline entries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // The names are the IEC constructs.
pub enum OutlineKind {
    Program,
    FunctionBlock,
    Function,
    Interface,
    Method,
    Property,
    Action,
    Type,
    Variable,
    Step,
    Transition,
    Configuration,
}

/// The outline of a source text, in source order.
pub fn outline(text: &str) -> Vec<OutlineItem> {
    items_in(&parse(text).syntax())
}

fn items_in(node: &SyntaxNode) -> Vec<OutlineItem> {
    let mut items = Vec::new();
    for child in node.children() {
        match item_kind(&child) {
            Some(kind) => {
                if let Some(item) = item(&child, kind) {
                    items.push(item);
                }
            }
            // Declarations inside sections and lists belong to the enclosing entry.
            None if matches!(
                child.kind(),
                VAR_BLOCK | GLOBAL_VAR_LIST | STATEMENT_LIST | TYPE_DECL | RESOURCE_DECL
            ) =>
            {
                items.extend(items_in(&child));
            }
            None => {}
        }
    }
    items
}

fn item_kind(node: &SyntaxNode) -> Option<OutlineKind> {
    Some(match node.kind() {
        POU => match first_keyword(node) {
            Some(FUNCTION_BLOCK) => OutlineKind::FunctionBlock,
            Some(FUNCTION) => OutlineKind::Function,
            _ => OutlineKind::Program,
        },
        INTERFACE_DECL => OutlineKind::Interface,
        METHOD_DECL => OutlineKind::Method,
        PROPERTY_DECL => OutlineKind::Property,
        ACTION_DECL => OutlineKind::Action,
        TYPE_DEFINITION => OutlineKind::Type,
        VAR_DECL => OutlineKind::Variable,
        STEP_DECL => OutlineKind::Step,
        TRANSITION_DECL => OutlineKind::Transition,
        CONFIGURATION_DECL => OutlineKind::Configuration,
        _ => return None,
    })
}

fn item(node: &SyntaxNode, kind: OutlineKind) -> Option<OutlineItem> {
    let name_node = node.descendants().find(|child| {
        child.kind() == NAME
            && child
                .parent()
                .is_some_and(|p| p == *node || p.kind() == VAR_NAME_LIST)
    })?;
    let name = name_node.text().to_string().trim().to_owned();
    let children = if kind == OutlineKind::Variable {
        Vec::new()
    } else {
        items_in(node)
    };
    Some(OutlineItem {
        name,
        kind,
        range: trimmed_range(node),
        name_range: trimmed_range(&name_node),
        children,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(items: &[OutlineItem]) -> Vec<String> {
        items
            .iter()
            .map(|item| {
                let children = shape(&item.children);
                if children.is_empty() {
                    format!("{:?} {}", item.kind, item.name)
                } else {
                    format!("{:?} {} [{}]", item.kind, item.name, children.join(", "))
                }
            })
            .collect()
    }

    #[test]
    fn the_outline_lists_pous_members_variables_and_types() {
        let text = "TYPE E : (A, B); END_TYPE\n\
                    FUNCTION_BLOCK FB VAR_INPUT x, y : INT; END_VAR z := x;\n\
                    METHOD Reset : BOOL VAR t : INT; END_VAR END_METHOD\n\
                    END_FUNCTION_BLOCK\n\
                    PROGRAM P INITIAL_STEP S0: END_STEP END_PROGRAM";
        assert_eq!(
            shape(&outline(text)),
            vec![
                "Type E",
                "FunctionBlock FB [Variable x, Method Reset [Variable t]]",
                "Program P [Step S0]",
            ]
        );
        let fb = &outline(text)[1];
        assert_eq!(&text[fb.name_range.clone()], "FB");
        assert!(
            text[fb.range.clone()].starts_with("FUNCTION_BLOCK")
                && text[fb.range.clone()].ends_with("END_FUNCTION_BLOCK")
        );
    }
}
