//! Classes of tokens for highlighting, from the syntax tree: unlike a lexer, the tree tells a
//! type name from a variable name and a called function from a variable.

use std::ops::Range;

use crate::syntax::SyntaxKind::*;
use crate::syntax::{SyntaxToken, parse};

/// A highlighted range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SemanticToken {
    /// The bytes.
    pub range: Range<usize>,
    /// What they are.
    pub class: SemanticClass,
}

/// Highlighting classes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)] // The names say what they colour.
pub enum SemanticClass {
    Keyword,
    Type,
    Variable,
    Function,
    Number,
    String,
    Comment,
    Pragma,
    Address,
    Operator,
}

/// The semantic tokens of a source text, in order; plain punctuation and spaces are left out.
pub fn semantic_tokens(text: &str) -> Vec<SemanticToken> {
    parse(text)
        .syntax()
        .descendants_with_tokens()
        .filter_map(|element| element.into_token())
        .filter_map(|token| {
            let class = class_of(&token)?;
            let range = token.text_range();
            Some(SemanticToken {
                range: usize::from(range.start())..usize::from(range.end()),
                class,
            })
        })
        .collect()
}

fn class_of(token: &SyntaxToken) -> Option<SemanticClass> {
    let kind = token.kind();
    Some(match kind {
        LINE_COMMENT | BLOCK_COMMENT => SemanticClass::Comment,
        PRAGMA => SemanticClass::Pragma,
        INT_NUMBER | REAL_NUMBER | TIME_LITERAL | DATE_LITERAL | TRUE | FALSE => {
            SemanticClass::Number
        }
        STRING | WSTRING => SemanticClass::String,
        DIRECT_ADDRESS => SemanticClass::Address,
        AND | OR | XOR | NOT | MOD | AND_THEN | OR_ELSE => SemanticClass::Operator,
        ASSIGN | OUTPUT_ASSIGN | QUESTION_ASSIGN | EQ | NEQ | LT | LE | GT | GE | PLUS | MINUS
        | STAR | SLASH | POWER | AMP | CARET => SemanticClass::Operator,
        IDENT => {
            let parent = token.parent()?;
            match parent.kind() {
                NAME_REF
                    if parent.ancestors().any(|a| {
                        matches!(
                            a.kind(),
                            NAMED_TYPE
                                | STRING_TYPE
                                | RETURN_TYPE
                                | EXTENDS_CLAUSE
                                | IMPLEMENTS_CLAUSE
                        )
                    }) =>
                {
                    SemanticClass::Type
                }
                TYPED_LITERAL => SemanticClass::Type,
                NAME if parent.parent().is_some_and(|p| p.kind() == TYPE_DEFINITION) => {
                    SemanticClass::Type
                }
                NAME if parent
                    .parent()
                    .is_some_and(|p| matches!(p.kind(), POU | METHOD_DECL | ACTION_DECL)) =>
                {
                    SemanticClass::Function
                }
                NAME_EXPR if parent.parent().is_some_and(|p| p.kind() == CALL_EXPR) => {
                    SemanticClass::Function
                }
                _ => SemanticClass::Variable,
            }
        }
        _ if kind.is_keyword() => SemanticClass::Keyword,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn types_variables_and_calls_are_told_apart() {
        let text = "PROGRAM P VAR t : TON; x : INT := INT#5; END_VAR t(IN := x > 0); x := ABS(x); END_PROGRAM";
        let tokens = semantic_tokens(text);
        let class_of_text = |needle: &str, nth: usize| {
            let start = text.match_indices(needle).nth(nth).map(|(i, _)| i);
            tokens
                .iter()
                .find(|t| Some(t.range.start) == start)
                .map(|t| t.class)
        };
        assert_eq!(class_of_text("TON", 0), Some(SemanticClass::Type));
        assert_eq!(class_of_text("t", 0), Some(SemanticClass::Variable));
        // Without the semantic model a called instance looks like a called function.
        assert_eq!(class_of_text("t", 1), Some(SemanticClass::Function));
        assert_eq!(class_of_text("ABS", 0), Some(SemanticClass::Function));
        assert_eq!(class_of_text("PROGRAM", 0), Some(SemanticClass::Keyword));
        assert_eq!(class_of_text("P", 1), Some(SemanticClass::Function));
        assert_eq!(class_of_text("5", 0), Some(SemanticClass::Number));
    }
}
