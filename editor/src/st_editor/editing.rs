//! Changing the text and moving the caret: the operations the input handler combines.

use std::ops::Range;

use super::{StEditor, TextChange};

/// The indentation added by Tab and after a block opener.
pub const INDENT: &str = "    ";

/// Words that open a block when they end a line, so Enter indents the next line further.
const OPENERS: &[&str] = &[
    "THEN",
    "DO",
    "ELSE",
    "OF",
    "REPEAT",
    "VAR",
    "VAR_INPUT",
    "VAR_OUTPUT",
    "VAR_IN_OUT",
    "VAR_TEMP",
    "VAR_GLOBAL",
    "VAR_STAT",
    "VAR_INST",
    "VAR_EXTERNAL",
    "STRUCT",
];

/// Words that close or continue a block; typed alone on an indented line, they move back one
/// level to stand under their opener.
const CLOSERS: &[&str] = &[
    "END_IF",
    "END_FOR",
    "END_WHILE",
    "END_REPEAT",
    "END_CASE",
    "END_VAR",
    "END_STRUCT",
    "END_TYPE",
    "END_PROGRAM",
    "END_FUNCTION",
    "END_FUNCTION_BLOCK",
    "END_METHOD",
    "END_ACTION",
    "END_PROPERTY",
    "ELSE",
    "ELSIF",
    "UNTIL",
];

/// Whether `c` can be part of an identifier (Chinese names included).
pub fn is_word_char(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

impl StEditor {
    /// Replaces `range` with `text` in the buffer and the syntax tree and records the change;
    /// does nothing in read-only mode. Returns the range really replaced.
    pub(super) fn replace(
        &mut self,
        range: Range<usize>,
        text: &str,
        changes: &mut Vec<TextChange>,
    ) -> Range<usize> {
        let start = self.buffer.clamp(range.start.min(range.end));
        let end = self.buffer.clamp(range.end.max(start));
        if self.read_only || (start == end && text.is_empty()) {
            return start..end;
        }
        let first_line = self.buffer.line_of(start);
        let last_line = self.buffer.line_of(end);
        self.syntax.edit(&self.buffer, &(start..end), text);
        self.buffer.replace(start..end, text);
        self.syntax_stale = true;
        self.revision += 1;
        let new_last = first_line + text.matches('\n').count();
        self.folding.follow_edit(first_line, last_line, new_last);
        let delta = text.len() as isize - (end - start) as isize;
        shift_ranges(&mut self.diagnostics, |d| &mut d.range, start..end, delta);
        shift_ranges(&mut self.inline_values, |v| &mut v.range, start..end, delta);
        changes.push(TextChange {
            range: start..end,
            text: text.to_owned(),
        });
        start..end
    }

    /// Replaces the selection with `text` and puts the caret after it.
    pub(super) fn replace_selection(&mut self, text: &str, changes: &mut Vec<TextChange>) {
        let replaced = self.replace(self.selection(), text, changes);
        if !self.read_only {
            self.caret = replaced.start + text.len();
            self.anchor = self.caret;
        }
        self.preferred_column = None;
        self.scroll_to_caret = true;
    }

    /// Moves the caret to `offset`, extending the selection when `extend`.
    pub(super) fn move_to(&mut self, offset: usize, extend: bool) {
        self.caret = self.buffer.clamp(offset);
        if !extend {
            self.anchor = self.caret;
        }
        self.scroll_to_caret = true;
        self.typing_end = None;
    }

    /// The offset one char before `offset`.
    pub(super) fn prev_char(&self, offset: usize) -> usize {
        let text = self.buffer.text();
        text[..self.buffer.clamp(offset)]
            .char_indices()
            .next_back()
            .map_or(0, |(at, _)| at)
    }

    /// The offset one char after `offset`.
    pub(super) fn next_char(&self, offset: usize) -> usize {
        let offset = self.buffer.clamp(offset);
        let text = self.buffer.text();
        text[offset..]
            .chars()
            .next()
            .map_or(offset, |c| offset + c.len_utf8())
    }

    /// The start of the word before `offset` (Ctrl+Left).
    pub(super) fn word_left(&self, offset: usize) -> usize {
        let text = self.buffer.text();
        let mut at = self.buffer.clamp(offset);
        let mut chars = text[..at].char_indices().rev().peekable();
        while let Some(&(index, c)) = chars.peek() {
            if !c.is_whitespace() {
                break;
            }
            at = index;
            chars.next();
        }
        let word = chars.peek().is_some_and(|(_, c)| is_word_char(*c));
        for (index, c) in chars {
            if is_word_char(c) != word || c.is_whitespace() {
                break;
            }
            at = index;
        }
        at
    }

    /// The end of the word after `offset` (Ctrl+Right).
    pub(super) fn word_right(&self, offset: usize) -> usize {
        let text = self.buffer.text();
        let start = self.buffer.clamp(offset);
        let mut chars = text[start..].char_indices().peekable();
        let word = chars.peek().is_some_and(|(_, c)| is_word_char(*c));
        let mut at = text.len();
        let mut in_space = false;
        for (index, c) in chars {
            if c.is_whitespace() {
                in_space = true;
            } else if in_space || is_word_char(c) != word {
                at = start + index;
                break;
            }
        }
        at
    }

    /// The word (identifier) around `offset`, empty when there is none.
    pub(super) fn word_at(&self, offset: usize) -> Range<usize> {
        let text = self.buffer.text();
        let offset = self.buffer.clamp(offset);
        let start = text[..offset]
            .char_indices()
            .rev()
            .take_while(|(_, c)| is_word_char(*c))
            .last()
            .map_or(offset, |(at, _)| at);
        let end = text[offset..]
            .char_indices()
            .find(|(_, c)| !is_word_char(*c))
            .map_or(text.len(), |(at, _)| offset + at);
        start..end
    }

    /// The text Enter inserts at the caret: a line break and the indentation of the current
    /// line, one level more after a block opener.
    pub(super) fn newline_text(&self) -> String {
        let line = self.buffer.line_of(self.caret);
        let line_text = self.buffer.line(line);
        let indent: String = line_text
            .chars()
            .take_while(|c| *c == ' ' || *c == '\t')
            .collect();
        let before_caret = &self.buffer.text()[self.buffer.line_range(line).start..self.caret];
        let last_word = before_caret
            .trim_end()
            .rsplit(|c: char| !is_word_char(c))
            .next()
            .unwrap_or("")
            .to_ascii_uppercase();
        let extra = if OPENERS.contains(&last_word.as_str()) {
            INDENT
        } else {
            ""
        };
        format!("\n{indent}{extra}")
    }

    /// After a typed character completes a block closer (`END_IF`, `ELSE` …) alone on its
    /// line, moves the line back one level when it is indented as deep as the line above.
    /// Returns whether it did.
    pub(super) fn outdent_closer(&mut self, changes: &mut Vec<TextChange>) -> bool {
        let line = self.buffer.line_of(self.caret);
        let range = self.buffer.line_range(line);
        let text = self.buffer.line(line);
        let word = text.trim();
        if self.caret != range.end
            || !CLOSERS
                .iter()
                .any(|closer| closer.eq_ignore_ascii_case(word))
        {
            return false;
        }
        let indent_of = |text: &str| text.len() - text.trim_start().len();
        let indent = indent_of(text);
        let above = (0..line)
            .rev()
            .map(|previous| self.buffer.line(previous))
            .find(|previous| !previous.trim().is_empty())
            .map_or(0, indent_of);
        if indent == 0 || indent < above {
            return false;
        }
        let remove = if text.starts_with('\t') {
            1
        } else {
            indent.min(INDENT.len())
        };
        self.replace(range.start..range.start + remove, "", changes);
        self.caret -= remove;
        self.anchor = self.caret;
        true
    }

    /// Indents (or outdents) every line the selection touches; one change per line, from
    /// the last line to the first.
    pub(super) fn indent_lines(&mut self, outdent: bool, changes: &mut Vec<TextChange>) {
        let selection = self.selection();
        let first = self.buffer.line_of(selection.start);
        let mut last = self.buffer.line_of(selection.end);
        if last > first && self.buffer.line_range(last).start == selection.end {
            last -= 1;
        }
        let (anchor_pos, caret_pos) = (
            self.buffer.line_col(self.anchor),
            self.buffer.line_col(self.caret),
        );
        let mut shifts = vec![0isize; last - first + 1];
        for line in (first..=last).rev() {
            let range = self.buffer.line_range(line);
            if outdent {
                let text = self.buffer.line(line);
                let remove = if text.starts_with('\t') {
                    1
                } else {
                    text.chars()
                        .take(INDENT.len())
                        .take_while(|c| *c == ' ')
                        .count()
                };
                if remove > 0 {
                    self.replace(range.start..range.start + remove, "", changes);
                    shifts[line - first] = -(remove as isize);
                }
            } else if !(range.is_empty() && first != last) {
                self.replace(range.start..range.start, INDENT, changes);
                shifts[line - first] = INDENT.len() as isize;
            }
        }
        let place = |editor: &Self, (line, col): (usize, usize)| {
            let shift = line
                .checked_sub(first)
                .and_then(|index| shifts.get(index))
                .copied()
                .unwrap_or(0);
            let col = (col as isize + shift).max(0) as usize;
            editor.buffer.offset_of(line, col)
        };
        self.anchor = place(self, anchor_pos);
        self.caret = place(self, caret_pos);
        self.scroll_to_caret = true;
    }
}

/// Moves the ranges after a change by `delta` and drops the ones the change overlapped, so
/// diagnostics and inline values stay on their words until the app sends new ones.
fn shift_ranges<T>(
    items: &mut Vec<T>,
    range_of: impl Fn(&mut T) -> &mut Range<usize>,
    changed: Range<usize>,
    delta: isize,
) {
    items.retain_mut(|item| {
        let range = range_of(item);
        if range.end <= changed.start {
            true
        } else if range.start >= changed.end {
            range.start = (range.start as isize + delta).max(0) as usize;
            range.end = (range.end as isize + delta).max(0) as usize;
            true
        } else {
            false
        }
    });
}
