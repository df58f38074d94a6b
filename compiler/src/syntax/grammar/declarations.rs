//! Variable declarations, type references and initial values.

use super::expressions::expression;
use super::{name, name_ref};
use crate::syntax::SyntaxKind::*;
use crate::syntax::parser::Parser;
use crate::syntax::token_set::TokenSet;

/// Keywords that open a variable section.
pub(crate) const VAR_BLOCK_START: TokenSet = TokenSet::new(&[
    VAR,
    VAR_INPUT,
    VAR_OUTPUT,
    VAR_IN_OUT,
    VAR_GLOBAL,
    VAR_EXTERNAL,
    VAR_TEMP,
    VAR_STAT,
    VAR_INST,
    VAR_CONFIG,
    VAR_ACCESS,
]);

/// Tokens that can start a type.
const TYPE_START: TokenSet = TokenSet::new(&[IDENT, ARRAY, POINTER, REFERENCE, REF_TO, L_PAREN]);

/// Qualifiers after the section keyword.
const QUALIFIERS: TokenSet = TokenSet::new(&[CONSTANT, RETAIN, NON_RETAIN, PERSISTENT]);

/// Zero or more `VAR… END_VAR` sections.
pub(crate) fn var_blocks(p: &mut Parser<'_>) {
    while p.at_set(VAR_BLOCK_START) {
        var_block(p);
    }
}

fn var_block(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    while p.at_set(QUALIFIERS) {
        p.bump();
    }
    let stop = TokenSet::new(&[END_VAR]).union(VAR_BLOCK_START);
    while !p.at_set(stop) && !p.at_end() && (p.at(IDENT) || p.at(AT) || !is_section_end(p)) {
        let before = p.position();
        var_decl(p, stop);
        p.ensure_progress(before);
    }
    p.expect_with(END_VAR, "to close the variable section");
    m.complete(p, VAR_BLOCK);
}

/// Whether the current token ends a declaration section though `END_VAR` is missing: a body
/// statement keyword or the end of the POU.
fn is_section_end(p: &Parser<'_>) -> bool {
    matches!(
        p.current(),
        END_PROGRAM
            | END_FUNCTION
            | END_FUNCTION_BLOCK
            | END_METHOD
            | END_PROPERTY
            | END_STRUCT
            | END_UNION
            | END_TYPE
            | IF
            | CASE
            | FOR
            | WHILE
            | REPEAT
            | METHOD
            | PROPERTY
    )
}

/// `a, b AT %IX0.0 : Type := init;` (also instance paths in `VAR_CONFIG`, nameless located
/// variables `AT %IX1.0 : BOOL;`, edge inputs `x : BOOL R_EDGE;` and access paths
/// `name : path : Type READ_ONLY;`).
pub(crate) fn var_decl(p: &mut Parser<'_>, stop: TokenSet) {
    let m = p.open();
    if p.at(IDENT) {
        let names = p.open();
        declared_name(p);
        while p.eat(COMMA) {
            if !declared_name(p) {
                p.error(format!(
                    "expected a variable name after ',', found {}",
                    p.found()
                ));
            }
        }
        // matiec's library marks extensible inputs as `IN 1 .. : REAL`.
        if p.at(INT_NUMBER) && p.nth(1) == DOTDOT {
            p.bump();
            p.bump();
            p.eat(INT_NUMBER);
        }
        names.complete(p, VAR_NAME_LIST);
    } else if !p.at(AT) {
        let recovery = stop.union(TokenSet::new(&[SEMICOLON, IDENT]));
        p.error_recover(
            format!("expected a variable name, found {}", p.found()),
            recovery,
        );
        p.eat(SEMICOLON);
        m.complete(p, VAR_DECL);
        return;
    }
    if p.at(AT) {
        let address = p.open();
        p.bump();
        p.expect_with(DIRECT_ADDRESS, "after AT");
        address.complete(p, ADDRESS);
    }
    if p.expect_with(COLON, "before the type") || p.at_set(TYPE_START) {
        // A forgotten ':' is reported once and the type still parsed.
        type_ref(p);
        // An access path: `name : Program.path : Type`.
        if p.eat(COLON) {
            type_ref(p);
        }
    } else {
        let skipped = p.open();
        while !p.at_set(stop.union(TokenSet::new(&[SEMICOLON, ASSIGN]))) && !p.at_end() {
            p.bump();
        }
        skipped.complete(p, ERROR);
    }
    for word in ["R_EDGE", "F_EDGE", "READ_ONLY", "READ_WRITE"] {
        if p.nth_is_word(0, word) {
            p.bump();
        }
    }
    if p.at(ASSIGN) {
        initializer(p);
    }
    p.expect_with(SEMICOLON, "after the declaration");
    m.complete(p, VAR_DECL);
}

/// A declared name; in `VAR_CONFIG` a dotted instance path.
fn declared_name(p: &mut Parser<'_>) -> bool {
    super::dotted_name(p, NAME)
}

/// A type: `INT`, `STRING(20)`, `ARRAY[1..3, 0..1] OF REAL`, `POINTER TO FB`, `INT(0..100)`,
/// or an inline enumeration `(a, b)`.
pub(crate) fn type_ref(p: &mut Parser<'_>) {
    let m = p.open();
    match p.current() {
        ARRAY => {
            p.bump();
            if p.expect(L_BRACK) {
                loop {
                    let range = p.open();
                    if p.at(STAR) {
                        p.bump();
                    } else {
                        expression(p);
                        p.expect_with(DOTDOT, "in the array bounds");
                        // matiec accepts an open upper bound, `ARRAY[1..] OF REAL`.
                        if !matches!(p.current(), R_BRACK | COMMA) {
                            expression(p);
                        }
                    }
                    range.complete(p, ARRAY_RANGE);
                    if !p.eat(COMMA) {
                        break;
                    }
                }
                p.expect_with(R_BRACK, "after the array bounds");
            }
            p.expect_with(OF, "after the array bounds");
            type_ref(p);
            m.complete(p, ARRAY_TYPE);
        }
        POINTER => {
            p.bump();
            p.expect_with(TO, "after POINTER");
            type_ref(p);
            m.complete(p, POINTER_TYPE);
        }
        REFERENCE => {
            p.bump();
            p.expect_with(TO, "after REFERENCE");
            type_ref(p);
            m.complete(p, REFERENCE_TYPE);
        }
        REF_TO => {
            p.bump();
            type_ref(p);
            m.complete(p, REFERENCE_TYPE);
        }
        L_PAREN => {
            // An anonymous enumeration in a declaration.
            enum_values(p);
            m.complete(p, ENUM_TYPE);
        }
        IDENT => {
            let is_string = p.nth_is_word(0, "STRING") || p.nth_is_word(0, "WSTRING");
            name_ref(p);
            if is_string && (p.at(L_PAREN) || p.at(L_BRACK)) {
                let close = if p.at(L_PAREN) { R_PAREN } else { R_BRACK };
                p.bump();
                expression(p);
                p.expect_with(close, "after the string length");
                m.complete(p, STRING_TYPE);
            } else if p.at(L_PAREN) && !subrange_follows(p) {
                // An FB instance with initialisation arguments (TwinCAT FB_init),
                // `FB_Logger(TestResults)`.
                super::expressions::arg_list(p);
                m.complete(p, NAMED_TYPE);
            } else if p.at(L_PAREN) {
                let range = p.open();
                p.bump();
                expression(p);
                p.expect_with(DOTDOT, "in the subrange");
                expression(p);
                p.expect_with(R_PAREN, "to close the subrange");
                range.complete(p, SUBRANGE);
                m.complete(p, NAMED_TYPE);
            } else {
                m.complete(p, NAMED_TYPE);
            }
        }
        _ => {
            p.error(format!("expected a type, found {}", p.found()));
            m.abandon(p);
        }
    }
}

/// `(Idle := 0, Running, Stopped)`: the values of an enumeration.
pub(crate) fn enum_values(p: &mut Parser<'_>) {
    p.expect(L_PAREN);
    loop {
        let value = p.open();
        name(p);
        if p.eat(ASSIGN) {
            expression(p);
        }
        value.complete(p, ENUM_VALUE);
        if !p.eat(COMMA) {
            break;
        }
    }
    p.expect_with(R_PAREN, "to close the enumeration");
}

/// Whether the parenthesis here holds a subrange `(lo..hi)`: a `..` before its closing `)`.
fn subrange_follows(p: &Parser<'_>) -> bool {
    let mut depth = 0usize;
    for n in 0..256 {
        match p.nth(n) {
            L_PAREN => depth += 1,
            R_PAREN => {
                depth -= 1;
                if depth == 0 {
                    return false;
                }
            }
            DOTDOT if depth == 1 => return true,
            SEMICOLON | EOF => return false,
            _ => {}
        }
    }
    false
}

/// `:= value`: an expression, an array initialiser `[1, 2, 3(0)]` or a structure initialiser
/// `(x := 1, y := 2)`.
pub(crate) fn initializer(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    let first = p.open();
    init_value(p);
    if p.at(COMMA) {
        // IEC 61131-3 2nd edition writes array initialisers without brackets: `:= 2, 7, 18`.
        while p.eat(COMMA) {
            init_value(p);
        }
        first.complete(p, ARRAY_INIT);
    } else {
        first.abandon(p);
    }
    m.complete(p, INITIALIZER);
}

fn init_value(p: &mut Parser<'_>) {
    if p.at(L_BRACK) {
        array_init(p);
    } else if p.at(L_PAREN) && p.nth(1) == IDENT && p.nth(2) == ASSIGN {
        struct_init(p);
    } else {
        expression(p);
    }
}

fn array_init(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    if !p.at(R_BRACK) {
        loop {
            // `3(0)` repeats a value; `3()` repeats the default.
            if p.at(INT_NUMBER) && p.nth(1) == L_PAREN {
                let repeat = p.open();
                p.bump();
                p.bump();
                if !p.at(R_PAREN) {
                    init_value(p);
                }
                p.expect_with(R_PAREN, "to close the repetition");
                repeat.complete(p, REPEAT_INIT);
            } else {
                init_value(p);
            }
            if !p.eat(COMMA) {
                break;
            }
        }
    }
    p.expect_with(R_BRACK, "to close the array initialiser");
    m.complete(p, ARRAY_INIT);
}

fn struct_init(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    loop {
        let field = p.open();
        name(p);
        p.expect_with(ASSIGN, "after the member name");
        init_value(p);
        field.complete(p, FIELD_INIT);
        if !p.eat(COMMA) {
            break;
        }
    }
    p.expect_with(R_PAREN, "to close the structure initialiser");
    m.complete(p, STRUCT_INIT);
}
