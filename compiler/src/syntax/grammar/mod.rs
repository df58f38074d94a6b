//! The Structured Text grammar, as recursive descent over the parser's tokens.
//!
//! IEC 61131-3 3rd edition plus the CODESYS dialect: methods, properties, interfaces,
//! `EXTENDS`/`IMPLEMENTS`, `REFERENCE TO`, `S=`/`R=`/`REF=`/`?=`, nestable comments.

mod declarations;
mod expressions;
mod items;
mod statements;

use super::SyntaxKind::*;
use super::parser::Parser;
use super::token_set::TokenSet;

pub(crate) use items::source_file;

/// Entry point for the body of a POU stored on its own: statements up to the end.
pub(crate) fn statement_file(p: &mut Parser<'_>) {
    let root = p.open();
    let list = p.open();
    while !p.at_end() {
        let before = p.depth;
        statements::statement_or_recover(p, TokenSet::EMPTY, false);
        debug_assert_eq!(before, p.depth);
    }
    list.complete(p, STATEMENT_LIST);
    root.complete(p, SOURCE_FILE);
}

/// Entry point for a type written on its own, as a project stores a variable's type.
pub(crate) fn type_file(p: &mut Parser<'_>) {
    let root = p.open();
    declarations::type_ref(p);
    if !p.at_end() {
        p.error(format!("expected the end of the type, found {}", p.found()));
        let rest = p.open();
        while !p.at_end() {
            p.bump();
        }
        rest.complete(p, ERROR);
    }
    root.complete(p, SOURCE_FILE);
}

/// Parses a name being declared: one identifier as a `NAME` node.
pub(crate) fn name(p: &mut Parser<'_>) -> bool {
    // The operator functions of the standard library are declared under operator names.
    if p.at(IDENT) || (matches!(p.current(), MOD | AND | OR | XOR | NOT) && p.nth(1) == COLON) {
        let m = p.open();
        p.bump();
        m.complete(p, NAME);
        true
    } else {
        p.error(format!("expected a name, found {}", p.found()));
        false
    }
}

/// Parses a reference to a named thing, possibly qualified: `FB_Conveyor`, `MyLib.FB_X`.
pub(crate) fn name_ref(p: &mut Parser<'_>) -> bool {
    if !dotted_name(p, NAME_REF) {
        p.error(format!("expected a name, found {}", p.found()));
        return false;
    }
    true
}

/// An identifier followed by `.identifier`s, as one node of `kind`; `false` (consuming
/// nothing) when no identifier is here.
pub(crate) fn dotted_name(p: &mut Parser<'_>, kind: super::SyntaxKind) -> bool {
    if !p.at(IDENT) {
        return false;
    }
    let m = p.open();
    p.bump();
    while p.at(DOT) && p.nth(1) == IDENT {
        p.bump();
        p.bump();
    }
    m.complete(p, kind);
    true
}
