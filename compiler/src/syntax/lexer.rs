//! Splits Structured Text into tokens. Every byte ends up in exactly one token, so the tree
//! built from them is lossless; malformed input gives error tokens and errors, never a failure.

use std::ops::Range;

use super::SyntaxKind::{self, *};
use crate::diagnostic::Code;

/// A token: its kind and its length in bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token {
    /// The kind.
    pub kind: SyntaxKind,
    /// Length in bytes.
    pub len: u32,
}

/// A problem found while splitting the text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LexError {
    /// The diagnostic code.
    pub code: Code,
    /// The bytes concerned.
    pub range: Range<usize>,
    /// What was found and what was expected.
    pub message: String,
}

/// Splits `text` into tokens, which cover it without gaps, and the problems found.
pub fn tokenize(text: &str) -> (Vec<Token>, Vec<LexError>) {
    let mut lexer = Lexer {
        text,
        bytes: text.as_bytes(),
        at: 0,
        tokens: Vec::with_capacity(text.len() / 3),
        errors: Vec::new(),
    };
    while lexer.at < lexer.bytes.len() {
        let start = lexer.at;
        let kind = lexer.next_kind();
        debug_assert!(lexer.at > start, "the lexer must always advance");
        let len = u32::try_from(lexer.at - start).unwrap_or(u32::MAX);
        lexer.tokens.push(Token { kind, len });
    }
    (lexer.tokens, lexer.errors)
}

struct Lexer<'a> {
    text: &'a str,
    bytes: &'a [u8],
    at: usize,
    tokens: Vec<Token>,
    errors: Vec<LexError>,
}

/// Prefixes of duration literals, `T#1s`.
const TIME_PREFIXES: &[&str] = &["T", "TIME", "LT", "LTIME"];
/// Prefixes of date and time-of-day literals, `D#2024-01-31`, `TOD#12:00`.
const DATE_PREFIXES: &[&str] = &[
    "D",
    "DATE",
    "LD",
    "LDATE",
    "TOD",
    "TIME_OF_DAY",
    "LTOD",
    "LTIME_OF_DAY",
    "DT",
    "DATE_AND_TIME",
    "LDT",
    "LDATE_AND_TIME",
];

impl Lexer<'_> {
    fn peek(&self, offset: usize) -> u8 {
        self.bytes.get(self.at + offset).copied().unwrap_or(0)
    }

    fn error(&mut self, code: Code, range: Range<usize>, message: impl Into<String>) {
        self.errors.push(LexError {
            code,
            range,
            message: message.into(),
        });
    }

    fn eat_while(&mut self, mut keep: impl FnMut(u8) -> bool) {
        while self.at < self.bytes.len() && keep(self.bytes[self.at]) {
            self.at += 1;
        }
    }

    fn next_kind(&mut self) -> SyntaxKind {
        let start = self.at;
        let byte = self.peek(0);
        let next = self.peek(1);
        match byte {
            b' ' | b'\t' | b'\r' | b'\n' | 0x0b | 0x0c => {
                self.eat_while(|b| matches!(b, b' ' | b'\t' | b'\r' | b'\n' | 0x0b | 0x0c));
                WHITESPACE
            }
            b'/' if next == b'/' => {
                self.eat_while(|b| b != b'\n');
                LINE_COMMENT
            }
            b'(' if next == b'*' => self.nested_comment(start),
            b'/' if next == b'*' => {
                match self.text[start + 2..].find("*/") {
                    Some(end) => self.at = start + 2 + end + 2,
                    None => {
                        self.at = self.bytes.len();
                        self.error(
                            Code::UnterminatedComment,
                            start..start + 2,
                            "comment '/*' is never closed; expected '*/'",
                        );
                    }
                }
                BLOCK_COMMENT
            }
            b'{' => {
                match self.text[start..].find('}') {
                    Some(end) => self.at = start + end + 1,
                    None => {
                        self.at = self.bytes.len();
                        self.error(
                            Code::UnterminatedComment,
                            start..start + 1,
                            "pragma '{' is never closed; expected '}'",
                        );
                    }
                }
                PRAGMA
            }
            b'\'' => self.string(b'\'', STRING),
            b'"' => self.string(b'"', WSTRING),
            b'%' => {
                self.at += 1;
                self.eat_while(|b| b.is_ascii_alphanumeric() || b == b'.' || b == b'*');
                DIRECT_ADDRESS
            }
            b'0'..=b'9' => self.number(),
            b'_' | b'a'..=b'z' | b'A'..=b'Z' => self.word(),
            0x80..=0xff
                if self.text[start..]
                    .chars()
                    .next()
                    .is_some_and(char::is_alphabetic) =>
            {
                self.word()
            }
            _ => self.punctuation(start),
        }
    }

    fn nested_comment(&mut self, start: usize) -> SyntaxKind {
        // OSCAT exports put free text between these two markers; it is all one comment.
        const DESCRIPTION: &str = "(*@KEY@:DESCRIPTION*)";
        const END_DESCRIPTION: &str = "(*@KEY@:END_DESCRIPTION*)";
        if self.text[start..].starts_with(DESCRIPTION)
            && let Some(end) = self.text[start..].find(END_DESCRIPTION)
        {
            self.at = start + end + END_DESCRIPTION.len();
            return BLOCK_COMMENT;
        }
        let mut depth = 0usize;
        while self.at + 1 < self.bytes.len() {
            match (self.bytes[self.at], self.bytes[self.at + 1]) {
                (b'(', b'*') => {
                    depth += 1;
                    self.at += 2;
                }
                (b'*', b')') => {
                    depth -= 1;
                    self.at += 2;
                    if depth == 0 {
                        return BLOCK_COMMENT;
                    }
                }
                _ => self.at += 1,
            }
        }
        self.at = self.bytes.len();
        self.error(
            Code::UnterminatedComment,
            start..start + 2,
            "comment '(*' is never closed; expected '*)'",
        );
        BLOCK_COMMENT
    }

    /// A string in `quote`s; `$` escapes the next character (`$'`, `$$`, `$N`, `$0A`).
    fn string(&mut self, quote: u8, kind: SyntaxKind) -> SyntaxKind {
        let start = self.at;
        self.at += 1;
        loop {
            let byte = self.peek(0);
            if self.at >= self.bytes.len() || byte == b'\n' || byte == b'\r' {
                let quote = char::from(quote);
                self.error(
                    Code::UnterminatedString,
                    start..self.at,
                    format!("string is not closed on its line; expected {quote}"),
                );
                return kind;
            }
            self.at += 1;
            if byte == quote {
                return kind;
            }
            // `$` escapes one ASCII character; a multi-byte character after it is walked
            // byte by byte like any other, which stops only at ASCII bytes.
            if byte == b'$' && self.peek(0).is_ascii() && !matches!(self.peek(0), 0 | b'\n' | b'\r')
            {
                self.at += 1;
            }
        }
    }

    fn number(&mut self) -> SyntaxKind {
        self.eat_while(|b| b.is_ascii_digit() || b == b'_');
        // A based integer: 2#1010, 8#777, 16#FF.
        if self.peek(0) == b'#' && self.peek(1).is_ascii_alphanumeric() {
            self.at += 1;
            self.eat_while(|b| b.is_ascii_alphanumeric() || b == b'_');
            return INT_NUMBER;
        }
        let mut kind = INT_NUMBER;
        // A fraction, but not the `..` of a range.
        if self.peek(0) == b'.' && self.peek(1).is_ascii_digit() {
            self.at += 1;
            self.eat_while(|b| b.is_ascii_digit() || b == b'_');
            kind = REAL_NUMBER;
        }
        let exponent_digits = match (self.peek(1), self.peek(2)) {
            (b'+' | b'-', digit) => digit.is_ascii_digit(),
            (digit, _) => digit.is_ascii_digit(),
        };
        if matches!(self.peek(0), b'e' | b'E') && exponent_digits {
            self.at += 1;
            if matches!(self.peek(0), b'+' | b'-') {
                self.at += 1;
            }
            self.eat_while(|b| b.is_ascii_digit());
            kind = REAL_NUMBER;
        }
        kind
    }

    fn word(&mut self) -> SyntaxKind {
        let start = self.at;
        // Identifiers may hold any Unicode letter or digit, so Chinese names work.
        let length: usize = self.text[start..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .map(char::len_utf8)
            .sum();
        self.at = start + length;
        let upper = self.text[start..self.at].to_ascii_uppercase();
        if self.peek(0) == b'#' {
            let literal = if TIME_PREFIXES.contains(&upper.as_str()) {
                Some(TIME_LITERAL)
            } else if DATE_PREFIXES.contains(&upper.as_str()) {
                Some(DATE_LITERAL)
            } else {
                None
            };
            if let Some(kind) = literal {
                self.at += 1;
                self.eat_while(|b| {
                    b.is_ascii_alphanumeric() || matches!(b, b'_' | b'.' | b':' | b'-' | b'+')
                });
                return kind;
            }
        }
        SyntaxKind::from_keyword(&upper).unwrap_or(IDENT)
    }

    fn punctuation(&mut self, start: usize) -> SyntaxKind {
        let two = [self.peek(0), self.peek(1)];
        let (kind, len) = match &two {
            b":=" => (ASSIGN, 2),
            b"=>" => (OUTPUT_ASSIGN, 2),
            b"?=" => (QUESTION_ASSIGN, 2),
            b"<=" => (LE, 2),
            b">=" => (GE, 2),
            b"<>" => (NEQ, 2),
            b"**" => (POWER, 2),
            b".." => (DOTDOT, 2),
            [b'=', _] => (EQ, 1),
            [b'<', _] => (LT, 1),
            [b'>', _] => (GT, 1),
            [b'+', _] => (PLUS, 1),
            [b'-', _] => (MINUS, 1),
            [b'*', _] => (STAR, 1),
            [b'/', _] => (SLASH, 1),
            [b'&', _] => (AMP, 1),
            [b'^', _] => (CARET, 1),
            [b'.', _] => (DOT, 1),
            [b',', _] => (COMMA, 1),
            [b';', _] => (SEMICOLON, 1),
            [b':', _] => (COLON, 1),
            [b'#', _] => (HASH, 1),
            [b'(', _] => (L_PAREN, 1),
            [b')', _] => (R_PAREN, 1),
            [b'[', _] => (L_BRACK, 1),
            [b']', _] => (R_BRACK, 1),
            _ => {
                let len = self.text[start..].chars().next().map_or(1, char::len_utf8);
                self.error(
                    Code::InvalidCharacter,
                    start..start + len,
                    format!(
                        "'{}' is not part of Structured Text",
                        &self.text[start..start + len]
                    ),
                );
                (ERROR_TOKEN, len)
            }
        };
        self.at += len;
        kind
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<(SyntaxKind, &str)> {
        let (tokens, _) = tokenize(text);
        let mut at = 0;
        tokens
            .into_iter()
            .filter_map(|token| {
                let piece = &text[at..at + token.len as usize];
                at += token.len as usize;
                (token.kind != WHITESPACE).then_some((token.kind, piece))
            })
            .collect()
    }

    #[test]
    fn literals_of_every_form_are_single_tokens() {
        assert_eq!(
            kinds(
                "16#FF 2#1010_1010 1.5E-3 T#1h2m3s4ms TOD#12:30:00 DT#2024-01-31-12:00 'it$'s' \"w\" %IX0.0 %I*"
            ),
            vec![
                (INT_NUMBER, "16#FF"),
                (INT_NUMBER, "2#1010_1010"),
                (REAL_NUMBER, "1.5E-3"),
                (TIME_LITERAL, "T#1h2m3s4ms"),
                (DATE_LITERAL, "TOD#12:30:00"),
                (DATE_LITERAL, "DT#2024-01-31-12:00"),
                (STRING, "'it$'s'"),
                (WSTRING, "\"w\""),
                (DIRECT_ADDRESS, "%IX0.0"),
                (DIRECT_ADDRESS, "%I*"),
            ]
        );
    }

    #[test]
    fn keywords_ignore_case_and_typed_literals_split_at_the_hash() {
        assert_eq!(
            kinds("if Then INT#5 Color#Red a..b"),
            vec![
                (IF, "if"),
                (THEN, "Then"),
                (IDENT, "INT"),
                (HASH, "#"),
                (INT_NUMBER, "5"),
                (IDENT, "Color"),
                (HASH, "#"),
                (IDENT, "Red"),
                (IDENT, "a"),
                (DOTDOT, ".."),
                (IDENT, "b"),
            ]
        );
    }

    #[test]
    fn comments_nest_and_unterminated_ones_are_reported() {
        assert_eq!(
            kinds("(* a (* b *) c *)x"),
            vec![(BLOCK_COMMENT, "(* a (* b *) c *)"), (IDENT, "x")]
        );
        let (_, errors) = tokenize("x (* open");
        assert_eq!(errors.len(), 1);
        assert_eq!(errors[0].code, Code::UnterminatedComment);
        let (_, errors) = tokenize("s := 'open\nx");
        assert_eq!(errors[0].code, Code::UnterminatedString);
    }

    #[test]
    fn tokens_cover_every_byte() {
        let text = "x := 'a' § 中文 (* c";
        let (tokens, errors) = tokenize(text);
        let total: u32 = tokens.iter().map(|t| t.len).sum();
        assert_eq!(total as usize, text.len());
        assert!(errors.iter().any(|e| e.code == Code::InvalidCharacter));
    }
}
