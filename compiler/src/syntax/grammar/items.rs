//! Top-level items: POUs, methods, properties, actions, interfaces, types, global variable
//! lists and configurations.

use super::declarations::{VAR_BLOCK_START, type_ref, var_blocks};
use super::statements::{statement_list, statement_or_recover};
use super::{name, name_ref};
use crate::syntax::SyntaxKind::{self, *};
use crate::syntax::parser::Parser;
use crate::syntax::token_set::TokenSet;

/// Keywords that begin a top-level item, where recovery resumes.
const ITEM_START: TokenSet = TokenSet::new(&[
    PROGRAM,
    FUNCTION,
    FUNCTION_BLOCK,
    INTERFACE,
    TYPE,
    CONFIGURATION,
    ACTION,
    METHOD,
    PROPERTY,
    VAR_GLOBAL,
    VAR_CONFIG,
]);

/// Access and inheritance modifiers of POUs, methods and properties.
const MODIFIERS: TokenSet = TokenSet::new(&[ABSTRACT, FINAL, PUBLIC, PRIVATE, PROTECTED, INTERNAL]);

/// Members that can follow the declarations or the body of a function block.
const MEMBER_START: TokenSet = TokenSet::new(&[METHOD, PROPERTY, ACTION]);

/// A whole source file.
pub(crate) fn source_file(p: &mut Parser<'_>) {
    let root = p.open();
    while !p.at_end() {
        let before = p.position();
        match p.current() {
            PROGRAM | FUNCTION | FUNCTION_BLOCK => pou(p),
            INTERFACE => interface(p),
            TYPE => type_decl(p),
            CONFIGURATION => configuration(p),
            ACTION => action(p),
            METHOD => method(p),
            PROPERTY => property(p),
            VAR_GLOBAL | VAR_CONFIG => {
                let m = p.open();
                var_blocks(p);
                m.complete(p, GLOBAL_VAR_LIST);
            }
            // A property accessor's declaration part is just its variable sections.
            kind if p.declaration_part && VAR_BLOCK_START.contains(kind) => var_blocks(p),
            _ => p.error_recover(
                format!(
                    "expected PROGRAM, FUNCTION_BLOCK, FUNCTION, TYPE, VAR_GLOBAL or \
                     CONFIGURATION, found {}",
                    p.found()
                ),
                ITEM_START,
            ),
        }
        p.ensure_progress(before);
    }
    root.complete(p, SOURCE_FILE);
}

fn end_keyword(start: SyntaxKind) -> SyntaxKind {
    match start {
        PROGRAM => END_PROGRAM,
        FUNCTION => END_FUNCTION,
        FUNCTION_BLOCK => END_FUNCTION_BLOCK,
        METHOD => END_METHOD,
        PROPERTY => END_PROPERTY,
        INTERFACE => END_INTERFACE,
        ACTION => END_ACTION,
        _ => EOF,
    }
}

/// `PROGRAM`, `FUNCTION_BLOCK` or `FUNCTION` … `END_…`.
fn pou(p: &mut Parser<'_>) {
    let m = p.open();
    let start = p.current();
    p.bump();
    while p.at_set(MODIFIERS) {
        p.bump();
    }
    name(p);
    if p.at(COLON) {
        return_type(p);
    }
    inheritance(p);
    // CODESYS tolerates a ';' after the header.
    p.eat(SEMICOLON);
    body_with_members(p, end_keyword(start));
    m.complete(p, POU);
}

/// Declarations, then members and statements in any order CODESYS exports use, then the end.
fn body_with_members(p: &mut Parser<'_>, end: SyntaxKind) {
    var_blocks(p);
    members(p);
    // Statements, SFC elements and actions may interleave in a body, as in textual SFC.
    let stops = MEMBER_START.union(TokenSet::new(&[end]));
    loop {
        statement_list(p, stops);
        if !p.at_set(MEMBER_START) {
            break;
        }
        members(p);
    }
    p.expect_end(end, "to close the declaration");
}

fn members(p: &mut Parser<'_>) {
    loop {
        match p.current() {
            METHOD => method(p),
            PROPERTY => property(p),
            ACTION => action(p),
            _ => break,
        }
    }
}

fn return_type(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    type_ref(p);
    m.complete(p, RETURN_TYPE);
}

fn inheritance(p: &mut Parser<'_>) {
    if p.at(EXTENDS) {
        let m = p.open();
        p.bump();
        name_ref(p);
        while p.eat(COMMA) {
            name_ref(p);
        }
        m.complete(p, EXTENDS_CLAUSE);
    }
    if p.at(IMPLEMENTS) {
        let m = p.open();
        p.bump();
        name_ref(p);
        while p.eat(COMMA) {
            name_ref(p);
        }
        m.complete(p, IMPLEMENTS_CLAUSE);
    }
}

/// `METHOD [modifiers] Name [: Type]` declarations, statements, `END_METHOD`.
fn method(p: &mut Parser<'_>) {
    member(p, END_METHOD, METHOD_DECL, "method");
}

/// `PROPERTY [modifiers] Name : Type` declarations, statements, `END_PROPERTY`.
fn property(p: &mut Parser<'_>) {
    member(p, END_PROPERTY, PROPERTY_DECL, "property");
}

/// A method or property: keyword, modifiers, name, type (required for a property), a tolerated
/// `;`, declarations, statements and the `END_…` keyword.
fn member(p: &mut Parser<'_>, end: SyntaxKind, kind: SyntaxKind, what: &str) {
    let m = p.open();
    p.bump();
    while p.at_set(MODIFIERS) {
        p.bump();
    }
    name(p);
    if p.at(COLON) {
        return_type(p);
    } else if kind == PROPERTY_DECL {
        p.error_before_current("expected ':' and the property's type");
    }
    p.eat(SEMICOLON);
    var_blocks(p);
    if kind == PROPERTY_DECL {
        while let Some(end_word) = at_accessor(p) {
            accessor(p, end_word);
        }
    }
    statement_list(p, TokenSet::new(&[end]).union(ITEM_START));
    p.expect_end(end, &format!("to close the {what}"));
    m.complete(p, kind);
}

/// `GET` or `SET` opening a property accessor written inline, with the word that closes it.
/// The words are not reserved, so `GET := 1;` or `SET(x)` stay statements.
fn at_accessor(p: &Parser<'_>) -> Option<&'static str> {
    if matches!(p.nth(1), ASSIGN | L_PAREN | DOT | L_BRACK | EQ | CARET) {
        return None;
    }
    if p.nth_is_word(0, "GET") {
        Some("END_GET")
    } else if p.nth_is_word(0, "SET") {
        Some("END_SET")
    } else {
        None
    }
}

/// `GET` declarations statements `END_GET` (or the same with `SET`), as a property's accessor
/// is written in a text export.
fn accessor(p: &mut Parser<'_>, end_word: &str) {
    let m = p.open();
    p.bump();
    p.eat(SEMICOLON);
    var_blocks(p);
    let stops = TokenSet::new(&[END_PROPERTY]).union(ITEM_START);
    let list = p.open();
    while !p.nth_is_word(0, end_word) && !p.at_set(stops) && !p.at_end() {
        statement_or_recover(p, stops, false);
    }
    list.complete(p, STATEMENT_LIST);
    if p.nth_is_word(0, end_word) {
        p.bump();
    } else {
        p.error_before_current(format!(
            "expected {end_word} to close the accessor, found {}",
            p.found()
        ));
    }
    p.eat(SEMICOLON);
    m.complete(p, ACCESSOR_DECL);
}

/// `ACTION Name:` statements `END_ACTION`.
fn action(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    name(p);
    p.eat(COLON);
    statement_list(p, TokenSet::new(&[END_ACTION]).union(ITEM_START));
    p.expect_end(END_ACTION, "to close the action");
    m.complete(p, ACTION_DECL);
}

/// `INTERFACE Name [EXTENDS …]` methods and properties `END_INTERFACE`.
fn interface(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    name(p);
    inheritance(p);
    loop {
        match p.current() {
            METHOD => method(p),
            PROPERTY => property(p),
            END_INTERFACE | EOF => break,
            _ => p.error_recover(
                format!(
                    "expected METHOD, PROPERTY or END_INTERFACE, found {}",
                    p.found()
                ),
                TokenSet::new(&[METHOD, PROPERTY, END_INTERFACE]).union(ITEM_START),
            ),
        }
        if p.at_set(ITEM_START) && !p.at(METHOD) && !p.at(PROPERTY) {
            break;
        }
    }
    p.expect_end(END_INTERFACE, "to close the interface");
    m.complete(p, INTERFACE_DECL);
}

/// `TYPE` one or more type declarations `END_TYPE`.
fn type_decl(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    loop {
        let before = p.position();
        match p.current() {
            IDENT => type_definition(p),
            END_TYPE | EOF => break,
            _ if p.at_set(ITEM_START) => break,
            _ => p.error_recover(
                format!("expected a type name or END_TYPE, found {}", p.found()),
                TokenSet::new(&[IDENT, END_TYPE, SEMICOLON]).union(ITEM_START),
            ),
        }
        p.eat(SEMICOLON);
        p.ensure_progress(before);
    }
    p.expect_with(END_TYPE, "to close the type declaration");
    m.complete(p, TYPE_DECL);
}

/// `Name [EXTENDS Base] : <structure | union | enumeration | type> [:= init];`
fn type_definition(p: &mut Parser<'_>) {
    let m = p.open();
    name(p);
    if p.at(EXTENDS) {
        inheritance(p);
    }
    p.expect_with(COLON, "after the type name");
    match p.current() {
        STRUCT => struct_type(p, STRUCT, END_STRUCT, STRUCT_TYPE),
        UNION => struct_type(p, UNION, END_UNION, UNION_TYPE),
        L_PAREN => enum_type(p),
        _ => {
            type_ref(p);
        }
    }
    if p.at(ASSIGN) {
        super::declarations::initializer(p);
    }
    m.complete(p, TYPE_DEFINITION);
}

fn struct_type(p: &mut Parser<'_>, open: SyntaxKind, close: SyntaxKind, kind: SyntaxKind) {
    let m = p.open();
    p.expect(open);
    while !p.at(close) && !p.at_end() && !p.at(END_TYPE) {
        let before = p.position();
        super::declarations::var_decl(p, TokenSet::new(&[close, END_TYPE]));
        p.ensure_progress(before);
    }
    p.expect_with(close, "to close the structure");
    m.complete(p, kind);
}

/// `(Idle := 0, Running, Stopped) [BaseType]`.
fn enum_type(p: &mut Parser<'_>) {
    let m = p.open();
    super::declarations::enum_values(p);
    if p.at(IDENT) {
        type_ref(p);
    }
    m.complete(p, ENUM_TYPE);
}

/// `CONFIGURATION Name` globals and resources `END_CONFIGURATION`.
fn configuration(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    name(p);
    configuration_content(p, END_CONFIGURATION);
    p.expect_with(END_CONFIGURATION, "to close the configuration");
    m.complete(p, CONFIGURATION_DECL);
}

fn configuration_content(p: &mut Parser<'_>, end: SyntaxKind) {
    loop {
        let before = p.position();
        match p.current() {
            kind if VAR_BLOCK_START.contains(kind) => var_blocks(p),
            RESOURCE => {
                let m = p.open();
                p.bump();
                name(p);
                if p.eat(ON) {
                    name_ref(p);
                }
                configuration_content(p, END_RESOURCE);
                p.expect_with(END_RESOURCE, "to close the resource");
                m.complete(p, RESOURCE_DECL);
            }
            TASK => {
                let m = p.open();
                p.bump();
                name(p);
                if p.at(L_PAREN) {
                    super::expressions::arg_list(p);
                }
                p.expect_with(SEMICOLON, "after the task");
                m.complete(p, TASK_DECL);
            }
            PROGRAM => {
                let m = p.open();
                p.bump();
                p.eat(RETAIN);
                name(p);
                if p.eat(WITH) {
                    name_ref(p);
                }
                p.expect_with(COLON, "before the program type");
                name_ref(p);
                if p.at(L_PAREN) {
                    super::expressions::arg_list(p);
                }
                p.expect_with(SEMICOLON, "after the program configuration");
                m.complete(p, PROGRAM_CONFIG);
            }
            kind if kind == end || kind == EOF || kind == END_CONFIGURATION => break,
            _ => p.error_recover(
                format!(
                    "expected RESOURCE, TASK, PROGRAM or {end:?}, found {}",
                    p.found()
                ),
                TokenSet::new(&[RESOURCE, TASK, PROGRAM, SEMICOLON, end, END_CONFIGURATION])
                    .union(VAR_BLOCK_START),
            ),
        }
        p.eat(SEMICOLON);
        p.ensure_progress(before);
    }
}
