//! Lexical classes of Structured Text for highlighting.
//!
//! This is a scanner, not a parser: it tells keywords, comments, strings and numbers apart so
//! read-only views are easy to read. Diagnostics come only from the compiler.

use std::ops::Range;

/// The highlighting class of a run of text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokenClass {
    /// Identifiers, operators, punctuation and spaces.
    Plain,
    /// A reserved word such as `IF` or `VAR_INPUT`, or an elementary type name.
    Keyword,
    /// `// …`, `(* … *)` or `/* … */`.
    Comment,
    /// `'…'` or `"…"`.
    String,
    /// A number, a typed or based literal, or a time literal such as `T#2s`.
    Number,
    /// A direct address such as `%IX0.0`.
    Address,
    /// A pragma `{attribute …}`.
    Pragma,
}

/// Splits `text` into byte ranges with their class; the ranges cover the whole text in order.
pub fn classify_tokens(text: &str) -> Vec<(Range<usize>, TokenClass)> {
    let bytes = text.as_bytes();
    let mut tokens: Vec<(Range<usize>, TokenClass)> = Vec::new();
    let mut push = |range: Range<usize>, class: TokenClass| {
        if let Some((last, last_class)) = tokens.last_mut()
            && *last_class == class
            && last.end == range.start
        {
            last.end = range.end;
            return;
        }
        tokens.push((range, class));
    };
    let mut at = 0;
    while at < bytes.len() {
        let start = at;
        let byte = bytes[at];
        let next = bytes.get(at + 1).copied();
        let class = if byte == b'/' && next == Some(b'/') {
            at = find_from(text, at, "\n").unwrap_or(bytes.len());
            TokenClass::Comment
        } else if byte == b'(' && next == Some(b'*') {
            at = block_comment_end(bytes, at);
            TokenClass::Comment
        } else if byte == b'/' && next == Some(b'*') {
            at = find_from(text, at + 2, "*/").map_or(bytes.len(), |end| end + 2);
            TokenClass::Comment
        } else if byte == b'{' {
            at = find_from(text, at, "}").map_or(bytes.len(), |end| end + 1);
            TokenClass::Pragma
        } else if byte == b'\'' || byte == b'"' {
            at = string_end(bytes, at);
            TokenClass::String
        } else if byte == b'%' {
            at += 1;
            while at < bytes.len()
                && (bytes[at].is_ascii_alphanumeric() || bytes[at] == b'.' || bytes[at] == b'*')
            {
                at += 1;
            }
            TokenClass::Address
        } else if byte.is_ascii_digit() {
            at = literal_end(bytes, at);
            TokenClass::Number
        } else if byte.is_ascii_alphabetic() || byte == b'_' || byte >= 0x80 {
            at = word_end(text, at);
            let word = &text[start..at];
            if bytes.get(at) == Some(&b'#') {
                // A typed literal (`INT#5`, `T#2s`) or an enum value (`E_State#Idle`).
                at = literal_end(bytes, at + 1);
                TokenClass::Number
            } else if is_keyword(word) {
                TokenClass::Keyword
            } else {
                TokenClass::Plain
            }
        } else {
            at += text[at..].chars().next().map_or(1, char::len_utf8);
            TokenClass::Plain
        };
        push(start..at, class);
    }
    tokens
}

fn find_from(text: &str, from: usize, needle: &str) -> Option<usize> {
    text[from..].find(needle).map(|offset| from + offset)
}

/// The end of a `(* *)` comment, which nests as in CODESYS.
fn block_comment_end(bytes: &[u8], start: usize) -> usize {
    let mut depth = 0usize;
    let mut at = start;
    while at + 1 < bytes.len() {
        match (bytes[at], bytes[at + 1]) {
            (b'(', b'*') => {
                depth += 1;
                at += 2;
            }
            (b'*', b')') => {
                depth -= 1;
                at += 2;
                if depth == 0 {
                    return at;
                }
            }
            _ => at += 1,
        }
    }
    bytes.len()
}

/// The end of a string literal; `$'` and `$"` escape the quote.
fn string_end(bytes: &[u8], start: usize) -> usize {
    let quote = bytes[start];
    let mut at = start + 1;
    while at < bytes.len() {
        match bytes[at] {
            b'$' => at += 2,
            b'\n' => return at,
            byte if byte == quote => return at + 1,
            _ => at += 1,
        }
    }
    bytes.len()
}

fn literal_end(bytes: &[u8], start: usize) -> usize {
    let mut at = start;
    while at < bytes.len()
        && (bytes[at].is_ascii_alphanumeric() || matches!(bytes[at], b'_' | b'.' | b'#'))
    {
        // A `..` range operator ends a literal.
        if bytes[at] == b'.' && bytes.get(at + 1) == Some(&b'.') {
            break;
        }
        at += 1;
    }
    at.max(start + 1).min(bytes.len())
}

fn word_end(text: &str, start: usize) -> usize {
    text[start..]
        .char_indices()
        .find(|(_, c)| !(c.is_alphanumeric() || *c == '_'))
        .map_or(text.len(), |(offset, _)| start + offset)
}

fn is_keyword(word: &str) -> bool {
    const KEYWORDS: &[&str] = &[
        "ABSTRACT",
        "ACTION",
        "AND",
        "AND_THEN",
        "ARRAY",
        "AT",
        "BY",
        "CASE",
        "CONSTANT",
        "CONTINUE",
        "DO",
        "ELSE",
        "ELSIF",
        "END_ACTION",
        "END_CASE",
        "END_FOR",
        "END_FUNCTION",
        "END_FUNCTION_BLOCK",
        "END_IF",
        "END_INTERFACE",
        "END_METHOD",
        "END_PROGRAM",
        "END_PROPERTY",
        "END_REPEAT",
        "END_STRUCT",
        "END_TYPE",
        "END_UNION",
        "END_VAR",
        "END_WHILE",
        "EXIT",
        "EXTENDS",
        "FALSE",
        "FINAL",
        "FOR",
        "FUNCTION",
        "FUNCTION_BLOCK",
        "IF",
        "IMPLEMENTS",
        "INTERFACE",
        "INTERNAL",
        "JMP",
        "METHOD",
        "MOD",
        "NOT",
        "OF",
        "OR",
        "OR_ELSE",
        "PERSISTENT",
        "POINTER",
        "PRIVATE",
        "PROGRAM",
        "PROPERTY",
        "PROTECTED",
        "PUBLIC",
        "REF_TO",
        "REFERENCE",
        "REPEAT",
        "RETAIN",
        "RETURN",
        "STRUCT",
        "SUPER",
        "THEN",
        "THIS",
        "TO",
        "TRUE",
        "TYPE",
        "UNION",
        "UNTIL",
        "VAR",
        "VAR_CONFIG",
        "VAR_EXTERNAL",
        "VAR_GLOBAL",
        "VAR_IN_OUT",
        "VAR_INPUT",
        "VAR_INST",
        "VAR_OUTPUT",
        "VAR_STAT",
        "VAR_TEMP",
        "WHILE",
        "XOR",
        "BOOL",
        "BYTE",
        "WORD",
        "DWORD",
        "LWORD",
        "SINT",
        "INT",
        "DINT",
        "LINT",
        "USINT",
        "UINT",
        "UDINT",
        "ULINT",
        "REAL",
        "LREAL",
        "TIME",
        "LTIME",
        "DATE",
        "LDATE",
        "TIME_OF_DAY",
        "TOD",
        "LTOD",
        "DATE_AND_TIME",
        "DT",
        "LDT",
        "STRING",
        "WSTRING",
        "CHAR",
        "WCHAR",
    ];
    KEYWORDS
        .iter()
        .any(|keyword| keyword.eq_ignore_ascii_case(word))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn classes(text: &str) -> Vec<(&str, TokenClass)> {
        classify_tokens(text)
            .into_iter()
            .filter(|(range, _)| !text[range.clone()].trim().is_empty())
            .map(|(range, class)| (&text[range], class))
            .collect()
    }

    #[test]
    fn statements_split_into_keywords_literals_comments_and_addresses() {
        let text = "IF xStart THEN tDelay := T#2s; END_IF // go\nx AT %IX0.1 : INT := 16#FF; (* a (* nested *) one *)";
        let found = classes(text);
        assert!(found.contains(&("IF", TokenClass::Keyword)));
        assert!(found.contains(&("T#2s", TokenClass::Number)));
        assert!(found.contains(&("// go", TokenClass::Comment)));
        assert!(found.contains(&("%IX0.1", TokenClass::Address)));
        assert!(found.contains(&("16#FF", TokenClass::Number)));
        assert!(found.contains(&("(* a (* nested *) one *)", TokenClass::Comment)));
    }

    #[test]
    fn the_ranges_cover_every_byte_even_of_unfinished_or_chinese_text() {
        for text in [
            "'open string",
            "(* open",
            "输送带 := 1;",
            "a..b",
            "{attribute 'x'",
        ] {
            let tokens = classify_tokens(text);
            let mut at = 0;
            for (range, _) in &tokens {
                assert_eq!(range.start, at, "gap in {text:?}");
                at = range.end;
            }
            assert_eq!(at, text.len(), "{text:?} not covered");
        }
    }
}
