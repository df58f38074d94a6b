//! Expressions, by precedence climbing with the IEC 61131-3 priorities.

use crate::diagnostic::Code;
use crate::syntax::SyntaxKind::{self, *};
use crate::syntax::parser::{CompletedMarker, MAX_DEPTH, Parser};
use crate::syntax::token_set::TokenSet;

/// Tokens that can start an expression.
const EXPRESSION_START: TokenSet = TokenSet::new(&[
    IDENT,
    INT_NUMBER,
    REAL_NUMBER,
    TIME_LITERAL,
    DATE_LITERAL,
    STRING,
    WSTRING,
    TRUE,
    FALSE,
    L_PAREN,
    L_BRACK,
    NOT,
    MINUS,
    PLUS,
    THIS,
    SUPER,
    DIRECT_ADDRESS,
    DOT,
]);

const LITERALS: TokenSet = TokenSet::new(&[
    INT_NUMBER,
    REAL_NUMBER,
    TIME_LITERAL,
    DATE_LITERAL,
    STRING,
    WSTRING,
    TRUE,
    FALSE,
]);

/// Binding power of the prefix operators `NOT`, `-` and `+`: tighter than `*`, looser than `**`.
const PREFIX_POWER: u8 = 15;

/// Whether the current token can start an expression.
pub(crate) fn at_expression_start(p: &Parser<'_>) -> bool {
    // A leading dot starts an expression only as `.global`.
    p.at_set(EXPRESSION_START) && (!p.at(DOT) || p.nth(1) == IDENT)
}

/// One expression; `None` (after reporting) when there is none here.
pub(crate) fn expression(p: &mut Parser<'_>) -> Option<CompletedMarker> {
    expression_bp(p, 0)
}

/// Left and right binding power of an infix operator, weakest first:
/// `OR`, `XOR`, `AND`, `=`/`<>`, comparisons, `+`/`-`, `*`/`/`/`MOD`, `**`.
fn infix_power(kind: SyntaxKind) -> Option<(u8, u8)> {
    Some(match kind {
        OR | OR_ELSE => (1, 2),
        XOR => (3, 4),
        AND | AND_THEN | AMP => (5, 6),
        EQ | NEQ => (7, 8),
        LT | LE | GT | GE => (9, 10),
        PLUS | MINUS => (11, 12),
        STAR | SLASH | MOD => (13, 14),
        POWER => (17, 18),
        _ => return None,
    })
}

fn expression_bp(p: &mut Parser<'_>, min_power: u8) -> Option<CompletedMarker> {
    if p.expression_depth >= MAX_DEPTH {
        expression_at_depth_limit(p);
        return None;
    }
    p.expression_depth += 1;
    let result = expression_bp_inner(p, min_power);
    p.expression_depth -= 1;
    result
}

fn expression_bp_inner(p: &mut Parser<'_>, min_power: u8) -> Option<CompletedMarker> {
    let mut lhs = if matches!(p.current(), NOT | MINUS | PLUS) {
        let m = p.open();
        p.bump();
        expression_bp(p, PREFIX_POWER);
        m.complete(p, UNARY_EXPR)
    } else {
        let operand = primary(p)?;
        postfix(p, operand)
    };
    let mut chain = 0usize;
    while let Some((left, right)) = infix_power(p.current()) {
        if left < min_power {
            break;
        }
        // Each operator in a row nests the tree one level deeper; past the limit the rest is
        // skipped, so a megabyte of `a + a + …` cannot make a tree too deep to walk.
        chain += 1;
        if chain > MAX_CHAIN {
            p.error_with_code(
                Code::NestingTooDeep,
                format!("the expression has more than {MAX_CHAIN} operators in a row; the rest of it is not checked"),
            );
            let m = lhs.precede(p);
            skip_rest_of_expression(p);
            return Some(m.complete(p, ERROR));
        }
        let m = lhs.precede(p);
        p.bump();
        expression_bp(p, right);
        lhs = m.complete(p, BINARY_EXPR);
    }
    Some(lhs)
}

/// How many binary operators in a row one expression may hold.
const MAX_CHAIN: usize = 500;

/// Past the nesting limit: report it and skip to the end of the innermost open bracket.
pub(crate) fn expression_at_depth_limit(p: &mut Parser<'_>) {
    p.error_with_code(
        Code::NestingTooDeep,
        format!("the expression is nested more than {MAX_DEPTH} levels deep; the rest of it is not checked"),
    );
    let m = p.open();
    skip_rest_of_expression(p);
    m.complete(p, ERROR);
}

/// Skips tokens up to the end of the innermost open bracket or of the statement.
fn skip_rest_of_expression(p: &mut Parser<'_>) {
    let mut open_brackets = 0usize;
    while !p.at_end() {
        match p.current() {
            L_PAREN | L_BRACK => open_brackets += 1,
            R_PAREN | R_BRACK => {
                if open_brackets == 0 {
                    break;
                }
                open_brackets -= 1;
            }
            SEMICOLON | THEN | DO | OF | END_IF | END_CASE | END_FOR | END_WHILE
                if open_brackets == 0 =>
            {
                break;
            }
            _ => {}
        }
        p.bump();
    }
}

fn primary(p: &mut Parser<'_>) -> Option<CompletedMarker> {
    let m = p.open();
    let kind = match p.current() {
        kind if LITERALS.contains(kind) => {
            p.bump();
            LITERAL
        }
        IDENT if p.nth(1) == HASH => {
            p.bump();
            p.bump();
            p.eat(MINUS);
            if p.at_set(LITERALS) || p.at(IDENT) {
                p.bump();
            } else {
                p.error(format!("expected a value after '#', found {}", p.found()));
            }
            TYPED_LITERAL
        }
        // Operators called like functions, `MOD(a, b)`, `OR(a, b, c)`, as matiec allows.
        MOD | AND | OR | XOR if p.nth(1) == L_PAREN => {
            p.bump();
            NAME_EXPR
        }
        IDENT | THIS | SUPER => {
            p.bump();
            NAME_EXPR
        }
        DOT if p.nth(1) == IDENT => {
            // `.iGlobal`: the global, even where a local hides it.
            p.bump();
            p.bump();
            NAME_EXPR
        }
        DIRECT_ADDRESS => {
            p.bump();
            ADDRESS_EXPR
        }
        L_PAREN => {
            p.bump();
            expression(p);
            p.expect_with(R_PAREN, "to close the parenthesis");
            PAREN_EXPR
        }
        L_BRACK => {
            p.bump();
            if !p.at(R_BRACK) {
                expression(p);
                while p.eat(COMMA) {
                    expression(p);
                }
            }
            p.expect_with(R_BRACK, "to close the array");
            ARRAY_INIT
        }
        _ => {
            m.abandon(p);
            p.error(format!("expected an expression, found {}", p.found()));
            return None;
        }
    };
    Some(m.complete(p, kind))
}

/// Member access, indexing, dereference and calls after an operand.
fn postfix(p: &mut Parser<'_>, mut operand: CompletedMarker) -> CompletedMarker {
    loop {
        operand = match p.current() {
            DOT if matches!(p.nth(1), IDENT | INT_NUMBER | DIRECT_ADDRESS) => {
                let m = operand.precede(p);
                p.bump();
                p.bump();
                m.complete(p, FIELD_EXPR)
            }
            L_BRACK => {
                let m = operand.precede(p);
                p.bump();
                expression(p);
                while p.eat(COMMA) {
                    expression(p);
                }
                p.expect_with(R_BRACK, "to close the index");
                m.complete(p, INDEX_EXPR)
            }
            CARET => {
                let m = operand.precede(p);
                p.bump();
                m.complete(p, DEREF_EXPR)
            }
            L_PAREN => {
                let m = operand.precede(p);
                arg_list(p);
                m.complete(p, CALL_EXPR)
            }
            _ => return operand,
        };
    }
}

/// `(a := 1, b => x, 3)`.
pub(crate) fn arg_list(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    if !p.at(R_PAREN) {
        loop {
            argument(p);
            if !p.eat(COMMA) {
                break;
            }
        }
    }
    p.expect_with(R_PAREN, "to close the argument list");
    m.complete(p, ARG_LIST);
}

fn argument(p: &mut Parser<'_>) {
    let m = p.open();
    let negated_output = p.at(NOT) && p.nth(1) == IDENT && p.nth(2) == OUTPUT_ASSIGN;
    if negated_output {
        p.bump();
    }
    if p.at(IDENT) && matches!(p.nth(1), ASSIGN | OUTPUT_ASSIGN) {
        p.bump();
        let output = p.at(OUTPUT_ASSIGN);
        p.bump();
        // `Q =>` with nothing after it leaves the output unconnected.
        if !(output && matches!(p.current(), COMMA | R_PAREN)) {
            expression(p);
        }
    } else {
        expression(p);
    }
    m.complete(p, ARG);
}
