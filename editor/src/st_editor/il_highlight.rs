//! Highlighting of Instruction List (`docs/instruction-list.md`): the lexical classes of
//! Structured Text (comments, strings, numbers, addresses) with each line's label, operator
//! and jump target picked out. IL has no blocks, so nothing folds.

use std::ops::Range;

use super::highlight::Highlight;
use crate::{TokenClass, classify_tokens};

/// The operators of IL, upper case; any other word in the operator's place calls a function.
const OPERATORS: &[&str] = &[
    "LD", "LDN", "ST", "STN", "S", "R", "AND", "ANDN", "OR", "ORN", "XOR", "XORN", "NOT", "ADD",
    "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT", "JMP", "JMPC", "JMPCN", "CAL",
    "CALC", "CALCN", "RET", "RETC", "RETCN", "S1", "R1", "CLK", "CU", "CD", "PV", "IN", "PT", "&",
    "&N",
];

/// Where a line is: what its next word is.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Place {
    /// A label or the operator.
    Start,
    /// The operator, after a label.
    Operator,
    /// The operand of a jump: a label.
    JumpTarget,
    /// Any other operand.
    Operand,
}

/// The highlighted runs of `text`, an IL body, covering it in order.
pub(super) fn il_spans(text: &str) -> Vec<(Range<usize>, Highlight)> {
    let mut spans = Vec::new();
    let mut place = Place::Start;
    for (range, class) in classify_tokens(text) {
        match class {
            TokenClass::Plain | TokenClass::Keyword => {
                words(text, range, class, &mut place, &mut spans);
            }
            TokenClass::Comment => {
                // A comment over several lines ends on a new line, whose start comes next.
                if text[range.clone()].contains('\n') {
                    place = Place::Start;
                }
                spans.push((range, Highlight::Comment));
            }
            other => {
                if matches!(place, Place::Start | Place::Operator) {
                    place = Place::Operand;
                }
                spans.push((range, Highlight::from_token(other)));
            }
        }
    }
    spans
}

/// Classifies the words of a plain or keyword run, moving `place` along the line.
fn words(
    text: &str,
    range: Range<usize>,
    class: TokenClass,
    place: &mut Place,
    spans: &mut Vec<(Range<usize>, Highlight)>,
) {
    let run = &text[range.clone()];
    let mut at = 0;
    while at < run.len() {
        let rest = &run[at..];
        let Some(c) = rest.chars().next() else { break };
        if c == '\n' {
            *place = Place::Start;
            spans.push((range.start + at..range.start + at + 1, Highlight::Plain));
            at += 1;
            continue;
        }
        let word_len = if c == '&' {
            1 + usize::from(rest[1..].starts_with(['N', 'n']))
        } else if c.is_alphanumeric() || c == '_' {
            rest.find(|c: char| !(c.is_alphanumeric() || c == '_'))
                .unwrap_or(rest.len())
        } else {
            c.len_utf8()
        };
        let word = &rest[..word_len];
        let absolute = range.start + at..range.start + at + word_len;
        let is_word = c == '&' || c.is_alphanumeric() || c == '_';
        let highlight = if !is_word {
            Highlight::Plain
        } else {
            match *place {
                Place::Start if label_follows(&text[absolute.end..]) => {
                    *place = Place::Operator;
                    Highlight::Label
                }
                Place::Start | Place::Operator => {
                    let upper = word.to_ascii_uppercase();
                    *place = if upper.starts_with("JMP") {
                        Place::JumpTarget
                    } else {
                        Place::Operand
                    };
                    if OPERATORS.contains(&upper.as_str()) {
                        Highlight::Keyword
                    } else {
                        Highlight::Function
                    }
                }
                Place::JumpTarget => {
                    *place = Place::Operand;
                    Highlight::Label
                }
                Place::Operand if class == TokenClass::Keyword => Highlight::Keyword,
                Place::Operand => Highlight::Plain,
            }
        };
        spans.push((absolute, highlight));
        at += word_len;
    }
}

/// Whether `after` (the text after a word) makes the word a label: a colon, not `:=`.
fn label_follows(after: &str) -> bool {
    let after = after.trim_start_matches([' ', '\t']);
    after.starts_with(':') && !after.starts_with(":=")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each word of `text` that is not plain, with its class.
    fn classes(text: &str) -> Vec<(&str, Highlight)> {
        il_spans(text)
            .into_iter()
            .filter(|(range, class)| {
                *class != Highlight::Plain && !text[range.clone()].trim().is_empty()
            })
            .map(|(range, class)| (&text[range], class))
            .collect()
    }

    #[test]
    fn labels_operators_jump_targets_functions_comments_and_literals_are_told_apart() {
        let text = "Start: LD a (* load *)\n  JMPC Done\nADD 1 // one\nLIMIT 0, 10\nAND( 'x'\nDone: ST %QX0.0\n";
        assert_eq!(
            classes(text),
            vec![
                ("Start", Highlight::Label),
                ("LD", Highlight::Keyword),
                ("(* load *)", Highlight::Comment),
                ("JMPC", Highlight::Keyword),
                ("Done", Highlight::Label),
                ("ADD", Highlight::Keyword),
                ("1", Highlight::Number),
                ("// one", Highlight::Comment),
                ("LIMIT", Highlight::Function),
                ("0", Highlight::Number),
                ("10", Highlight::Number),
                ("AND", Highlight::Keyword),
                ("'x'", Highlight::String),
                ("Done", Highlight::Label),
                ("ST", Highlight::Keyword),
                ("%QX0.0", Highlight::Constant),
            ]
        );
    }

    #[test]
    fn a_comment_over_several_lines_is_one_comment_and_the_next_line_starts_afresh() {
        let text = "(* one\ntwo *) LD x\nst y\n";
        assert_eq!(
            classes(text),
            vec![
                ("(* one\ntwo *)", Highlight::Comment),
                ("LD", Highlight::Keyword),
                ("st", Highlight::Keyword),
            ]
        );
    }
}
