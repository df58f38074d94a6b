//! Structured Text syntax: the lexer, the resilient parser and the lossless tree.
//!
//! The parser never fails: it returns a tree that holds every byte of the input (whitespace,
//! comments and pragmas included) plus the errors it found, and it recovers at statement and
//! declaration boundaries so one mistake does not hide the rest of the file.

pub mod ast;
mod grammar;
mod kind;
mod lexer;
mod parse;
mod parser;
mod token_set;

pub use kind::{StLanguage, SyntaxKind, SyntaxNode, SyntaxToken};
pub use lexer::{LexError, Token, tokenize};
pub use parse::{
    Parse, first_significant_token, parse, parse_declaration_part, parse_statements, parse_type,
};
pub use token_set::TokenSet;

#[cfg(test)]
mod tests;
