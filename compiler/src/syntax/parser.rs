//! The parser's machinery: a cursor over the non-trivia tokens, markers that open and close
//! nodes, and error reporting. The grammar in `grammar/` drives it; `parse.rs` turns its events
//! into a tree.

use std::ops::Range;

use super::SyntaxKind::{self, *};
use super::lexer::Token;
use super::token_set::TokenSet;
use crate::diagnostic::{Code, Diagnostic};

/// How deep statements, and separately expressions, may nest before the parser stops descending. Real
/// programs stay far below; the limit keeps pathological input from exhausting the stack.
pub(crate) const MAX_DEPTH: u32 = 100;

/// What the parser produced, replayed by the tree builder.
#[derive(Debug)]
pub(crate) enum Event {
    /// Opens a node. `forward_parent` points (as an offset) to a node opened later that must
    /// enclose this one, which is how a finished node gets a new parent (`a` in `a + b`).
    Start {
        kind: SyntaxKind,
        forward_parent: Option<u32>,
    },
    /// Closes the last open node.
    Finish,
    /// Consumes the next non-trivia token.
    Token,
}

/// The parser state.
pub(crate) struct Parser<'t> {
    text: &'t str,
    /// Kinds of the non-trivia tokens, then `EOF`.
    kinds: Vec<SyntaxKind>,
    /// Byte range of each non-trivia token.
    ranges: Vec<Range<usize>>,
    pos: usize,
    pub(crate) events: Vec<Event>,
    pub(crate) errors: Vec<Diagnostic>,
    /// Current nesting of statements.
    pub(crate) depth: u32,
    /// Current nesting of expressions, counted apart so either limit alone bounds the stack.
    pub(crate) expression_depth: u32,
    /// The token position of the last error, so a mistake is reported once and not again by
    /// every rule that trips over the same token.
    last_error_at: Option<usize>,
    /// Parsing a declaration part alone (as CODESYS and TwinCAT store it): POUs, methods and
    /// properties may end at the end of the text without their `END_…`.
    pub(crate) declaration_part: bool,
    /// Nodes opened since the last token was consumed. Rules nest only a few levels deep at
    /// one token, so a large count means a loop that makes no progress: debug builds (and
    /// the fuzzer) stop there at once instead of spinning until memory runs out.
    opens_since_bump: u32,
}

/// More nodes than any grammar rule nests at a single token.
const MAX_OPENS_WITHOUT_PROGRESS: u32 = 10_000;

impl<'t> Parser<'t> {
    /// A parser over the tokens of `text`.
    pub(crate) fn new(text: &'t str, tokens: &[Token]) -> Self {
        let mut kinds = Vec::with_capacity(tokens.len() / 2);
        let mut ranges = Vec::with_capacity(tokens.len() / 2);
        let mut at = 0usize;
        for token in tokens {
            let end = at + token.len as usize;
            if !is_skipped(token.kind) {
                kinds.push(token.kind);
                ranges.push(at..end);
            }
            at = end;
        }
        kinds.push(EOF);
        ranges.push(at..at);
        Self {
            text,
            kinds,
            ranges,
            pos: 0,
            events: Vec::new(),
            errors: Vec::new(),
            depth: 0,
            expression_depth: 0,
            declaration_part: false,
            last_error_at: None,
            opens_since_bump: 0,
        }
    }

    /// The kind of the current token.
    pub(crate) fn current(&self) -> SyntaxKind {
        self.nth(0)
    }

    /// The kind of the token `n` ahead.
    pub(crate) fn nth(&self, n: usize) -> SyntaxKind {
        self.kinds.get(self.pos + n).copied().unwrap_or(EOF)
    }

    /// Whether the current token is `kind`.
    pub(crate) fn at(&self, kind: SyntaxKind) -> bool {
        self.current() == kind
    }

    /// Whether the current token is in `set`.
    pub(crate) fn at_set(&self, set: TokenSet) -> bool {
        set.contains(self.current())
    }

    /// Whether the token `n` ahead is an identifier spelled `word` (any case), such as the
    /// `S` of `x S= y`.
    pub(crate) fn nth_is_word(&self, n: usize, word: &str) -> bool {
        self.nth(n) == IDENT
            && self
                .ranges
                .get(self.pos + n)
                .is_some_and(|range| self.text[range.clone()].eq_ignore_ascii_case(word))
    }

    /// Whether the token `n` ahead directly follows the one before it, with no space.
    pub(crate) fn nth_is_joined(&self, n: usize) -> bool {
        let index = self.pos + n;
        index > 0
            && index < self.ranges.len()
            && self.ranges[index - 1].end == self.ranges[index].start
    }

    /// The index of the current token, to tell whether a rule made progress.
    pub(crate) fn position(&self) -> usize {
        self.pos
    }

    /// Wraps the current token in an `ERROR` node unless the parser moved since `before`: a
    /// loop that calls a rule which consumed nothing must still move on, or it would never end.
    pub(crate) fn ensure_progress(&mut self, before: usize) {
        if self.pos == before && !self.at_end() {
            if self.last_error_at != Some(self.pos) {
                let message = format!("unexpected {}", self.found());
                self.error(message);
            }
            let m = self.open();
            self.bump();
            m.complete(self, ERROR);
        }
    }

    /// Whether the input is used up.
    pub(crate) fn at_end(&self) -> bool {
        self.at(EOF)
    }

    /// Opens a node at the current position.
    pub(crate) fn open(&mut self) -> Marker {
        self.opens_since_bump += 1;
        debug_assert!(
            self.opens_since_bump < MAX_OPENS_WITHOUT_PROGRESS,
            "the parser loops without consuming a token at token {}",
            self.pos
        );
        let position = self.events.len() as u32;
        self.events.push(Event::Start {
            kind: TOMBSTONE,
            forward_parent: None,
        });
        Marker { position }
    }

    /// Consumes the current token into the open node.
    pub(crate) fn bump(&mut self) {
        if self.at_end() {
            return;
        }
        self.pos += 1;
        self.opens_since_bump = 0;
        self.events.push(Event::Token);
    }

    /// Consumes the current token if it is `kind`.
    pub(crate) fn eat(&mut self, kind: SyntaxKind) -> bool {
        if self.at(kind) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Consumes `kind` or reports that it was expected, consuming nothing.
    pub(crate) fn expect(&mut self, kind: SyntaxKind) -> bool {
        self.expect_with(kind, "")
    }

    /// Like [`Self::expect`], with `context` ("after the statement") in the message.
    pub(crate) fn expect_with(&mut self, kind: SyntaxKind, context: &str) -> bool {
        if self.eat(kind) {
            return true;
        }
        let context = if context.is_empty() {
            String::new()
        } else {
            format!(" {context}")
        };
        let message = format!(
            "expected {}{context}, found {}",
            kind.describe(),
            self.found()
        );
        self.error_before_current(message);
        false
    }

    /// Consumes the `END_…` keyword `end` that closes a declaration, which a declaration part
    /// parsed alone may leave out.
    pub(crate) fn expect_end(&mut self, end: SyntaxKind, context: &str) {
        if self.declaration_part && self.at_end() {
            return;
        }
        self.expect_with(end, context);
    }

    /// How the current token is described in messages: `'foo'` or `the end of the file`.
    pub(crate) fn found(&self) -> String {
        match self.current() {
            EOF => EOF.describe(),
            kind if kind.is_keyword() => format!("{kind:?}"),
            _ => {
                let range = self.ranges[self.pos].clone();
                let text: String = self.text[range].chars().take(40).collect();
                format!("'{text}'")
            }
        }
    }

    /// Reports an error at the current token.
    pub(crate) fn error(&mut self, message: impl Into<String>) {
        self.error_with_code(Code::UnexpectedToken, message);
    }

    /// Records an error unless one was already reported at the current token.
    fn push_error(&mut self, code: Code, range: Range<usize>, message: impl Into<String>) {
        if self.last_error_at == Some(self.pos) {
            return;
        }
        self.last_error_at = Some(self.pos);
        self.errors.push(Diagnostic::new(code, range, message));
    }

    /// Reports an error for something missing: at the end of the previous token, where the
    /// missing piece belongs (a missing `;` is reported at the end of its line, not on the next).
    pub(crate) fn error_before_current(&mut self, message: impl Into<String>) {
        let range = match self.pos.checked_sub(1) {
            Some(previous) => {
                let end = self.ranges[previous].end;
                end..end
            }
            None => self.ranges[0].clone(),
        };
        self.push_error(Code::UnexpectedToken, range, message);
    }

    /// Reports an error with a given code at the current token.
    pub(crate) fn error_with_code(&mut self, code: Code, message: impl Into<String>) {
        let range = self.ranges[self.pos.min(self.ranges.len() - 1)].clone();
        self.push_error(code, range, message);
    }

    /// Reports an error and wraps tokens into an `ERROR` node until one in `recovery` (or the
    /// end); always consumes at least one token unless at a recovery token.
    pub(crate) fn error_recover(&mut self, message: impl Into<String>, recovery: TokenSet) {
        self.error(message);
        if self.at_set(recovery) || self.at_end() {
            return;
        }
        let marker = self.open();
        while !self.at_set(recovery) && !self.at_end() {
            self.bump();
        }
        marker.complete(self, ERROR);
    }
}

/// Tokens the parser does not see: trivia, and pragmas, which may stand anywhere and are kept
/// in the tree for the checker to read.
fn is_skipped(kind: SyntaxKind) -> bool {
    kind.is_trivia() || kind == PRAGMA
}

/// The kind of a marker not yet completed (and of an abandoned one).
pub(crate) const TOMBSTONE: SyntaxKind = __LAST;

/// An open node.
#[must_use = "a marker must be completed or abandoned"]
pub(crate) struct Marker {
    position: u32,
}

impl Marker {
    /// Closes the node as `kind`.
    pub(crate) fn complete(self, parser: &mut Parser<'_>, kind: SyntaxKind) -> CompletedMarker {
        if let Some(Event::Start { kind: slot, .. }) = parser.events.get_mut(self.position as usize)
        {
            *slot = kind;
        }
        parser.events.push(Event::Finish);
        CompletedMarker {
            position: self.position,
        }
    }

    /// Drops the node; its tokens go to the parent.
    pub(crate) fn abandon(self, parser: &mut Parser<'_>) {
        let index = self.position as usize;
        if index + 1 == parser.events.len() {
            parser.events.pop();
        }
        // Otherwise the start stays a tombstone, which the builder skips.
    }
}

/// A closed node, which can still get a parent.
#[derive(Clone, Copy)]
pub(crate) struct CompletedMarker {
    position: u32,
}

impl CompletedMarker {
    /// Opens a node that will enclose this one.
    pub(crate) fn precede(self, parser: &mut Parser<'_>) -> Marker {
        let new = parser.open();
        if let Some(Event::Start { forward_parent, .. }) =
            parser.events.get_mut(self.position as usize)
        {
            *forward_parent = Some(new.position - self.position);
        }
        new
    }

    /// The kind the node was closed as.
    pub(crate) fn kind(self, parser: &Parser<'_>) -> SyntaxKind {
        match parser.events.get(self.position as usize) {
            Some(Event::Start { kind, .. }) => *kind,
            _ => TOMBSTONE,
        }
    }
}
