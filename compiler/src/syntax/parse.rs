//! The result of parsing: a lossless tree and the problems found, and how it is built.

use rowan::{GreenNode, GreenNodeBuilder};

use super::SyntaxKind::*;
use super::grammar;
use super::lexer::{Token, tokenize};
use super::parser::{Event, Parser, TOMBSTONE};
use super::{SyntaxNode, SyntaxToken};
use crate::diagnostic::Diagnostic;

/// A parsed source text: the tree (which holds every byte of the text, whitespace and comments
/// included) and the syntax errors, in source order.
#[derive(Clone, Debug)]
pub struct Parse {
    green: GreenNode,
    errors: Vec<Diagnostic>,
}

impl Parse {
    /// The root of the tree.
    pub fn syntax(&self) -> SyntaxNode {
        SyntaxNode::new_root(self.green.clone())
    }

    /// The syntax errors.
    pub fn errors(&self) -> &[Diagnostic] {
        &self.errors
    }

    /// The tree as indented text with each node's kind and range and each token's text, then
    /// the errors: the form golden tests compare.
    pub fn debug_tree(&self) -> String {
        let mut out = String::new();
        let mut depth = 0usize;
        for event in self.syntax().preorder_with_tokens() {
            match event {
                rowan::WalkEvent::Enter(element) => {
                    let range = element.text_range();
                    out.push_str(&"  ".repeat(depth));
                    match element {
                        rowan::NodeOrToken::Node(node) => {
                            out.push_str(&format!("{:?}@{:?}\n", node.kind(), range));
                        }
                        rowan::NodeOrToken::Token(token) => {
                            out.push_str(&format!(
                                "{:?}@{:?} {:?}\n",
                                token.kind(),
                                range,
                                token.text()
                            ));
                        }
                    }
                    depth += 1;
                }
                rowan::WalkEvent::Leave(_) => depth -= 1,
            }
        }
        for error in &self.errors {
            out.push_str(&format!(
                "error {}..{} {}: {}\n",
                error.range.start,
                error.range.end,
                error.code.id(),
                error.message
            ));
        }
        out
    }
}

/// Parses a source file: POUs, types, global variable lists, configurations. Never fails.
pub fn parse(text: &str) -> Parse {
    parse_with(text, grammar::source_file, false)
}

/// Parses the statements of a POU body, as stored in a `.st` file of a project.
pub fn parse_statements(text: &str) -> Parse {
    parse_with(text, grammar::statement_file, false)
}

/// Parses a declaration part stored apart from its body, as CODESYS and TwinCAT keep POUs,
/// methods and properties: `FUNCTION_BLOCK F VAR … END_VAR` without `END_FUNCTION_BLOCK`.
pub fn parse_declaration_part(text: &str) -> Parse {
    parse_with(text, grammar::source_file, true)
}

/// Parses a type written on its own, such as a variable's type in a project:
/// `ARRAY[1..3] OF FB_Axis`, `STRING(20)`, `POINTER TO INT`.
pub fn parse_type(text: &str) -> Parse {
    parse_with(text, grammar::type_file, false)
}

fn parse_with(text: &str, entry: fn(&mut Parser<'_>), declaration_part: bool) -> Parse {
    let (tokens, lex_errors) = tokenize(text);
    let mut parser = Parser::new(text, &tokens);
    parser.declaration_part = declaration_part;
    entry(&mut parser);
    let Parser { events, errors, .. } = parser;
    let green = build_tree(text, &tokens, events);
    let mut all_errors: Vec<Diagnostic> = lex_errors
        .into_iter()
        .map(|error| Diagnostic::new(error.code, error.range, error.message))
        .chain(errors)
        .collect();
    all_errors.sort_by_key(|error| (error.range.start, error.range.end));
    Parse {
        green,
        errors: all_errors,
    }
}

/// Replays the parser's events over the tokens, putting trivia and pragmas back between them.
fn build_tree(text: &str, tokens: &[Token], mut events: Vec<Event>) -> GreenNode {
    let mut builder = GreenNodeBuilder::new();
    let mut cursor = TokenCursor {
        text,
        tokens,
        index: 0,
        offset: 0,
    };
    let mut open_nodes = 0usize;
    let mut forward_kinds = Vec::new();
    for index in 0..events.len() {
        match std::mem::replace(&mut events[index], Event::Finish) {
            Event::Start {
                kind,
                forward_parent,
            } => {
                if kind == TOMBSTONE && forward_parent.is_none() {
                    // An abandoned node has no Finish; its tokens land in the parent.
                    continue;
                }
                forward_kinds.clear();
                forward_kinds.push(kind);
                let mut at = index;
                let mut next = forward_parent;
                while let Some(offset) = next {
                    at += offset as usize;
                    next = match std::mem::replace(
                        &mut events[at],
                        Event::Start {
                            kind: TOMBSTONE,
                            forward_parent: None,
                        },
                    ) {
                        Event::Start {
                            kind,
                            forward_parent,
                        } => {
                            forward_kinds.push(kind);
                            forward_parent
                        }
                        _ => None,
                    };
                }
                for &kind in forward_kinds.iter().rev() {
                    if kind == TOMBSTONE {
                        continue;
                    }
                    // Trivia before a node belongs to its parent; the root takes all.
                    if open_nodes > 0 {
                        cursor.trivia(&mut builder);
                    }
                    builder.start_node(kind.into());
                    open_nodes += 1;
                }
            }
            Event::Finish => {
                if open_nodes == 1 {
                    cursor.trivia(&mut builder);
                    // Anything the grammar left unconsumed still belongs in the tree.
                    cursor.rest(&mut builder);
                }
                builder.finish_node();
                open_nodes = open_nodes.saturating_sub(1);
            }
            Event::Token => {
                cursor.trivia(&mut builder);
                cursor.token(&mut builder);
            }
        }
    }
    builder.finish()
}

/// Walks the raw tokens while the tree is built.
struct TokenCursor<'a> {
    text: &'a str,
    tokens: &'a [Token],
    index: usize,
    offset: usize,
}

impl TokenCursor<'_> {
    fn push(&mut self, builder: &mut GreenNodeBuilder<'_>) {
        let token = self.tokens[self.index];
        let end = self.offset + token.len as usize;
        builder.token(token.kind.into(), &self.text[self.offset..end]);
        self.offset = end;
        self.index += 1;
    }

    /// Emits the trivia and pragmas before the next significant token.
    fn trivia(&mut self, builder: &mut GreenNodeBuilder<'_>) {
        while self.index < self.tokens.len()
            && (self.tokens[self.index].kind.is_trivia() || self.tokens[self.index].kind == PRAGMA)
        {
            self.push(builder);
        }
    }

    /// Emits the next significant token.
    fn token(&mut self, builder: &mut GreenNodeBuilder<'_>) {
        if self.index < self.tokens.len() {
            self.push(builder);
        }
    }

    /// Emits every remaining token.
    fn rest(&mut self, builder: &mut GreenNodeBuilder<'_>) {
        while self.index < self.tokens.len() {
            self.push(builder);
        }
    }
}

/// The first token of `node` that is not trivia, if any.
pub fn first_significant_token(node: &SyntaxNode) -> Option<SyntaxToken> {
    node.descendants_with_tokens()
        .filter_map(|element| element.into_token())
        .find(|token| !token.kind().is_trivia() && token.kind() != PRAGMA)
}
