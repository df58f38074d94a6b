//! The document outline: POUs, their members and declarations, types, steps.

use std::ops::Range;

use super::trimmed_range;
use crate::syntax::SyntaxKind::*;
use crate::syntax::ast::{
    ActionDecl, AstChildren, AstNode, ConfigurationDecl, InterfaceDecl, MethodDecl, Pou,
    PropertyDecl, StepDecl, TransitionDecl, TypeDefinition, VarDecl,
};
use crate::syntax::{SyntaxKind, SyntaxNode, parse};

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
    for entry in AstChildren::<Entry>::new(node) {
        match entry {
            // Declarations inside sections and lists belong to the enclosing entry.
            Entry::Container(container) => items.extend(items_in(&container)),
            declared => items.extend(item(&declared)),
        }
    }
    items
}

/// A node the outline lists, or one whose entries belong to the enclosing entry.
enum Entry {
    Pou(Pou),
    Interface(InterfaceDecl),
    Method(MethodDecl),
    Property(PropertyDecl),
    Action(ActionDecl),
    Type(TypeDefinition),
    Variable(VarDecl),
    Step(StepDecl),
    Transition(TransitionDecl),
    Configuration(ConfigurationDecl),
    /// A variable section, global list, statement list, `TYPE` block or resource.
    Container(SyntaxNode),
}

impl AstNode for Entry {
    fn can_cast(kind: SyntaxKind) -> bool {
        matches!(
            kind,
            POU | INTERFACE_DECL
                | METHOD_DECL
                | PROPERTY_DECL
                | ACTION_DECL
                | TYPE_DEFINITION
                | VAR_DECL
                | STEP_DECL
                | TRANSITION_DECL
                | CONFIGURATION_DECL
                | VAR_BLOCK
                | GLOBAL_VAR_LIST
                | STATEMENT_LIST
                | TYPE_DECL
                | RESOURCE_DECL
        )
    }

    fn cast(node: SyntaxNode) -> Option<Self> {
        Some(match node.kind() {
            POU => Self::Pou(Pou::cast(node)?),
            INTERFACE_DECL => Self::Interface(InterfaceDecl::cast(node)?),
            METHOD_DECL => Self::Method(MethodDecl::cast(node)?),
            PROPERTY_DECL => Self::Property(PropertyDecl::cast(node)?),
            ACTION_DECL => Self::Action(ActionDecl::cast(node)?),
            TYPE_DEFINITION => Self::Type(TypeDefinition::cast(node)?),
            VAR_DECL => Self::Variable(VarDecl::cast(node)?),
            STEP_DECL => Self::Step(StepDecl::cast(node)?),
            TRANSITION_DECL => Self::Transition(TransitionDecl::cast(node)?),
            CONFIGURATION_DECL => Self::Configuration(ConfigurationDecl::cast(node)?),
            kind if Self::can_cast(kind) => Self::Container(node),
            _ => return None,
        })
    }

    fn syntax(&self) -> &SyntaxNode {
        match self {
            Self::Pou(node) => node.syntax(),
            Self::Interface(node) => node.syntax(),
            Self::Method(node) => node.syntax(),
            Self::Property(node) => node.syntax(),
            Self::Action(node) => node.syntax(),
            Self::Type(node) => node.syntax(),
            Self::Variable(node) => node.syntax(),
            Self::Step(node) => node.syntax(),
            Self::Transition(node) => node.syntax(),
            Self::Configuration(node) => node.syntax(),
            Self::Container(node) => node,
        }
    }
}

/// The outline entry of a declared thing, with its kind and name; `None` for a container or
/// a declaration without a name.
fn item(entry: &Entry) -> Option<OutlineItem> {
    let (kind, name) = match entry {
        Entry::Pou(pou) => {
            let kind = match pou.keyword().map(|keyword| keyword.kind()) {
                Some(FUNCTION_BLOCK) => OutlineKind::FunctionBlock,
                Some(FUNCTION) => OutlineKind::Function,
                _ => OutlineKind::Program,
            };
            (kind, pou.name())
        }
        Entry::Interface(interface) => (OutlineKind::Interface, interface.name()),
        Entry::Method(method) => (OutlineKind::Method, method.name()),
        Entry::Property(property) => (OutlineKind::Property, property.name()),
        Entry::Action(action) => (OutlineKind::Action, action.name()),
        Entry::Type(definition) => (OutlineKind::Type, definition.name()),
        Entry::Variable(declaration) => (OutlineKind::Variable, declaration.names().next()),
        Entry::Step(step) => (OutlineKind::Step, step.name()),
        Entry::Transition(transition) => (OutlineKind::Transition, transition.name()),
        Entry::Configuration(configuration) => (OutlineKind::Configuration, configuration.name()),
        Entry::Container(_) => return None,
    };
    let name = name?;
    let node = entry.syntax();
    let children = if kind == OutlineKind::Variable {
        Vec::new()
    } else {
        items_in(node)
    };
    Some(OutlineItem {
        name: name.text(),
        kind,
        range: trimmed_range(node),
        name_range: trimmed_range(name.syntax()),
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
