//! Statements.

use super::expressions::expression;
use crate::diagnostic::Code;
use crate::syntax::SyntaxKind::{self, *};
use crate::syntax::parser::{MAX_DEPTH, Parser};
use crate::syntax::token_set::TokenSet;

/// Tokens that end a statement list whatever the caller: the ends of blocks and of POUs.
const LIST_END: TokenSet = TokenSet::new(&[
    END_IF,
    ELSIF,
    ELSE,
    END_CASE,
    END_FOR,
    END_WHILE,
    UNTIL,
    END_REPEAT,
    END_PROGRAM,
    END_FUNCTION,
    END_FUNCTION_BLOCK,
    END_METHOD,
    END_PROPERTY,
    END_ACTION,
    END_INTERFACE,
    END_TYPE,
    END_VAR,
    END_STRUCT,
    END_CONFIGURATION,
    END_RESOURCE,
    // The start of the next POU ends a body whose END_… is missing.
    PROGRAM,
    FUNCTION,
    FUNCTION_BLOCK,
    TYPE,
    INTERFACE,
    CONFIGURATION,
    VAR_GLOBAL,
]);

/// Keywords that start a statement, where recovery resumes.
const STATEMENT_START: TokenSet = TokenSet::new(&[
    IF, CASE, FOR, WHILE, REPEAT, EXIT, CONTINUE, RETURN, JMP, SEMICOLON,
]);

/// Statements until a token in `stops` or a block end.
pub(crate) fn statement_list(p: &mut Parser<'_>, stops: TokenSet) {
    let m = p.open();
    let stops = stops.union(LIST_END);
    while !p.at_set(stops) && !p.at_end() {
        statement_or_recover(p, stops, false);
    }
    m.complete(p, STATEMENT_LIST);
}

/// Statements of a CASE branch: until a block end or the next case label.
fn case_branch_statements(p: &mut Parser<'_>) {
    let m = p.open();
    while !p.at_set(LIST_END) && !p.at_end() && !at_case_label(p) {
        statement_or_recover(p, LIST_END, true);
    }
    m.complete(p, STATEMENT_LIST);
}

/// One statement; unknown input is wrapped in an error node up to the next statement.
pub(crate) fn statement_or_recover(p: &mut Parser<'_>, stops: TokenSet, in_case: bool) {
    if p.depth >= MAX_DEPTH {
        depth_exceeded(p, stops);
        return;
    }
    p.depth += 1;
    let before = p.position();
    statement(p, stops, in_case);
    p.ensure_progress(before);
    p.depth -= 1;
}

/// Past the nesting limit: report once and skip the rest of this block.
fn depth_exceeded(p: &mut Parser<'_>, stops: TokenSet) {
    p.error_with_code(
        Code::NestingTooDeep,
        format!("statements are nested more than {MAX_DEPTH} levels deep; the rest of this block is not checked"),
    );
    let m = p.open();
    let mut blocks = 0usize;
    while !p.at_end() {
        let kind = p.current();
        if matches!(kind, IF | CASE | FOR | WHILE | REPEAT) {
            blocks += 1;
        } else if matches!(kind, END_IF | END_CASE | END_FOR | END_WHILE | END_REPEAT) {
            if blocks == 0 {
                break;
            }
            blocks -= 1;
        } else if blocks == 0 && stops.contains(kind) {
            break;
        }
        p.bump();
    }
    m.complete(p, ERROR);
}

fn statement(p: &mut Parser<'_>, stops: TokenSet, in_case: bool) {
    if at_step(p) {
        return sfc_step(p);
    }
    if at_transition(p) {
        return sfc_transition(p);
    }
    match p.current() {
        IF => if_statement(p),
        CASE => case_statement(p),
        FOR => for_statement(p),
        WHILE => while_statement(p),
        REPEAT => repeat_statement(p),
        EXIT => keyword_statement(p, EXIT_STMT),
        CONTINUE => keyword_statement(p, CONTINUE_STMT),
        RETURN => keyword_statement(p, RETURN_STMT),
        JMP => {
            let m = p.open();
            p.bump();
            super::name_ref(p);
            end_of_statement(p);
            m.complete(p, JMP_STMT);
        }
        SEMICOLON => {
            let m = p.open();
            p.bump();
            m.complete(p, EMPTY_STMT);
        }
        IDENT if p.nth(1) == COLON && !in_case => {
            let m = p.open();
            super::name(p);
            p.bump();
            m.complete(p, LABEL_STMT);
        }
        _ if super::expressions::at_expression_start(p) => expression_statement(p),
        _ => {
            // The caller stops at its own stop tokens, so the token here is not one of them and
            // consuming it guarantees progress.
            p.error(format!("expected a statement, found {}", p.found()));
            let recovery = stops.union(STATEMENT_START).union(LIST_END);
            let m = p.open();
            p.bump();
            while !p.at_set(recovery) && !p.at_end() && !super::expressions::at_expression_start(p)
            {
                p.bump();
            }
            p.eat(SEMICOLON);
            m.complete(p, ERROR);
        }
    }
}

/// `INITIAL_STEP Name:` or `STEP Name:` (or `STEP Name (MIN_TIME := …):`), which are words,
/// not keywords, so variables may still be called `Step`.
fn at_step(p: &Parser<'_>) -> bool {
    (p.nth_is_word(0, "STEP") || p.nth_is_word(0, "INITIAL_STEP"))
        && p.nth(1) == IDENT
        && matches!(p.nth(2), COLON | L_PAREN)
}

/// `TRANSITION [Name] [(PRIORITY := n)] FROM`.
fn at_transition(p: &Parser<'_>) -> bool {
    p.nth_is_word(0, "TRANSITION")
        && (p.nth_is_word(1, "FROM")
            || (p.nth(1) == IDENT && p.nth_is_word(2, "FROM"))
            || p.nth(1) == L_PAREN)
}

/// A textual SFC step: `STEP Name [(properties)]: action associations END_STEP`, the
/// properties being CODESYS's `MIN_TIME`, `MAX_TIME`, `ENTRY`, `MAIN` and `EXIT`.
fn sfc_step(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    super::name(p);
    if p.at(L_PAREN) {
        step_properties(p);
    }
    p.expect_with(COLON, "after the step's name");
    while !p.nth_is_word(0, "END_STEP")
        && !p.at_set(LIST_END)
        && !p.at_end()
        && !at_step(p)
        && !at_transition(p)
    {
        statement_or_recover(p, LIST_END, false);
    }
    expect_word(p, "END_STEP", "to close the step");
    m.complete(p, STEP_DECL);
}

/// `(MIN_TIME := T#1s, EXIT := Fill_out)`: an argument list whose names may be the keyword
/// `EXIT`.
fn step_properties(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    while !p.at(R_PAREN) && !p.at(COLON) && !p.at_end() {
        let arg = p.open();
        if matches!(p.current(), IDENT | EXIT) && p.nth(1) == ASSIGN {
            p.bump();
            p.bump();
        }
        expression(p);
        arg.complete(p, ARG);
        if !p.eat(COMMA) {
            break;
        }
    }
    p.expect_with(R_PAREN, "to close the step's properties");
    m.complete(p, ARG_LIST);
}

/// A textual SFC transition: `TRANSITION FROM a TO (b, c) := condition; END_TRANSITION`.
fn sfc_transition(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    if p.at(IDENT) && !p.nth_is_word(0, "FROM") {
        super::name(p);
    }
    if p.at(L_PAREN) {
        super::expressions::arg_list(p);
    }
    expect_word(p, "FROM", "in the transition");
    step_list(p);
    p.expect_with(TO, "after the transition's source steps");
    step_list(p);
    if p.eat(ASSIGN) {
        expression(p);
        p.expect_with(SEMICOLON, "after the transition condition");
    } else if p.eat(COLON) {
        while !p.nth_is_word(0, "END_TRANSITION") && !p.at_set(LIST_END) && !p.at_end() {
            statement_or_recover(p, LIST_END, false);
        }
    } else {
        p.error(format!(
            "expected ':=' and the transition condition, found {}",
            p.found()
        ));
    }
    expect_word(p, "END_TRANSITION", "to close the transition");
    m.complete(p, TRANSITION_DECL);
}

/// `Step` or `(Step1, Step2)`.
fn step_list(p: &mut Parser<'_>) {
    let m = p.open();
    if p.eat(L_PAREN) {
        loop {
            super::name_ref(p);
            if !p.eat(COMMA) {
                break;
            }
        }
        p.expect_with(R_PAREN, "to close the step list");
    } else {
        super::name_ref(p);
    }
    m.complete(p, STEP_LIST);
}

/// Consumes the word `word` (a contextual keyword such as `END_STEP`) or reports it missing.
fn expect_word(p: &mut Parser<'_>, word: &str, context: &str) {
    if p.nth_is_word(0, word) {
        p.bump();
    } else {
        p.error_before_current(format!("expected {word} {context}, found {}", p.found()));
    }
}

/// `x := e;`, `x S= e;`, `x R= e;`, `x REF= e;`, `x ?= e;` or a call `f(a := 1);`.
fn expression_statement(p: &mut Parser<'_>) {
    let m = p.open();
    let target = expression(p);
    let kind = if p.at(ASSIGN) {
        p.bump();
        expression(p);
        ASSIGN_STMT
    } else if p.at(QUESTION_ASSIGN) {
        p.bump();
        expression(p);
        ATTEMPT_ASSIGN_STMT
    } else if let Some(kind) = set_reset_ref(p) {
        p.bump();
        p.bump();
        expression(p);
        kind
    } else if target.is_some_and(|target| target.kind(p) == CALL_EXPR) {
        CALL_STMT
    } else {
        p.error_before_current(format!(
            "expected ':=' or a call after the expression, found {}",
            p.found()
        ));
        ASSIGN_STMT
    };
    end_of_statement(p);
    m.complete(p, kind);
}

/// `S=`, `R=` and `REF=` are an identifier joined to `=`.
fn set_reset_ref(p: &Parser<'_>) -> Option<SyntaxKind> {
    if p.nth(1) != EQ || !p.nth_is_joined(1) {
        return None;
    }
    if p.nth_is_word(0, "S") {
        Some(SET_STMT)
    } else if p.nth_is_word(0, "R") {
        Some(RESET_STMT)
    } else if p.nth_is_word(0, "REF") {
        Some(REF_ASSIGN_STMT)
    } else {
        None
    }
}

fn end_of_statement(p: &mut Parser<'_>) {
    p.expect_with(SEMICOLON, "after the statement");
}

fn keyword_statement(p: &mut Parser<'_>, kind: SyntaxKind) {
    let m = p.open();
    p.bump();
    end_of_statement(p);
    m.complete(p, kind);
}

fn if_statement(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    expression(p);
    p.expect_with(THEN, "after the IF condition");
    statement_list(p, TokenSet::EMPTY);
    while p.at(ELSIF) {
        let branch = p.open();
        p.bump();
        expression(p);
        p.expect_with(THEN, "after the ELSIF condition");
        statement_list(p, TokenSet::EMPTY);
        branch.complete(p, ELSIF_BRANCH);
    }
    if p.at(ELSE) {
        let branch = p.open();
        p.bump();
        statement_list(p, TokenSet::EMPTY);
        branch.complete(p, ELSE_BRANCH);
    }
    p.expect_with(END_IF, "to close the IF");
    p.eat(SEMICOLON);
    m.complete(p, IF_STMT);
}

fn case_statement(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    expression(p);
    p.expect_with(OF, "after the CASE selector");
    while !p.at(END_CASE) && !p.at(ELSE) && !p.at_set(LIST_END) && !p.at_end() {
        // A label that starts with a token no expression can start (`)`, `*`) would
        // otherwise be retried forever: each branch must consume something.
        let before = p.position();
        case_branch(p);
        p.ensure_progress(before);
    }
    if p.at(ELSE) {
        let branch = p.open();
        p.bump();
        statement_list(p, TokenSet::EMPTY);
        branch.complete(p, ELSE_BRANCH);
    }
    p.expect_with(END_CASE, "to close the CASE");
    p.eat(SEMICOLON);
    m.complete(p, CASE_STMT);
}

/// One `labels: statements` branch of a CASE, or an error up to the next branch.
fn case_branch(p: &mut Parser<'_>) {
    if !at_case_label(p) {
        p.error_recover(
            format!(
                "expected a case label such as '1:' or '2..5:', found {}",
                p.found()
            ),
            TokenSet::new(&[SEMICOLON, END_CASE, ELSE]).union(LIST_END),
        );
        p.eat(SEMICOLON);
        return;
    }
    let branch = p.open();
    let labels = p.open();
    loop {
        let start = p.open();
        expression(p);
        if p.eat(DOTDOT) {
            expression(p);
            start.complete(p, CASE_RANGE);
        } else {
            start.abandon(p);
        }
        if !p.eat(COMMA) {
            break;
        }
    }
    labels.complete(p, CASE_LABELS);
    p.expect_with(COLON, "after the case labels");
    case_branch_statements(p);
    branch.complete(p, CASE_BRANCH);
}

/// Whether a case label list (`1, 3..5, E.Idle:`) starts here: a colon (not `:=`) comes
/// before any `;`, `:=` or keyword, within a bounded look-ahead.
fn at_case_label(p: &Parser<'_>) -> bool {
    for n in 0..64 {
        match p.nth(n) {
            COLON => return n > 0,
            IDENT | INT_NUMBER | REAL_NUMBER | DOT | DOTDOT | COMMA | MINUS | PLUS | HASH
            | STRING | WSTRING | TRUE | FALSE | L_PAREN | R_PAREN | STAR | SLASH => {}
            _ => return false,
        }
    }
    false
}

fn for_statement(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    expression(p);
    p.expect_with(ASSIGN, "after the FOR control variable");
    expression(p);
    p.expect_with(TO, "after the FOR start value");
    expression(p);
    if p.eat(BY) {
        expression(p);
    }
    p.expect_with(DO, "after the FOR range");
    statement_list(p, TokenSet::EMPTY);
    p.expect_with(END_FOR, "to close the FOR");
    p.eat(SEMICOLON);
    m.complete(p, FOR_STMT);
}

fn while_statement(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    expression(p);
    p.expect_with(DO, "after the WHILE condition");
    statement_list(p, TokenSet::EMPTY);
    p.expect_with(END_WHILE, "to close the WHILE");
    p.eat(SEMICOLON);
    m.complete(p, WHILE_STMT);
}

fn repeat_statement(p: &mut Parser<'_>) {
    let m = p.open();
    p.bump();
    statement_list(p, TokenSet::new(&[UNTIL]));
    p.expect_with(UNTIL, "to end the REPEAT body");
    expression(p);
    p.expect_with(END_REPEAT, "to close the REPEAT");
    p.eat(SEMICOLON);
    m.complete(p, REPEAT_STMT);
}
