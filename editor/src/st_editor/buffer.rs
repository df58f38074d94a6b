//! The editor's text: one string with the byte offset of every line start, so the widget can
//! find and draw a line of a 20,000-line text without scanning it.

use std::ops::Range;

/// The text being edited with an index of its line starts.
///
/// Offsets are bytes; every offset a caller gives is clamped to the text and moved back to a
/// char boundary, so no position the user produces can panic.
#[derive(Clone, Debug, Default)]
pub struct TextBuffer {
    /// The whole text, as the app's model holds it.
    text: String,
    /// The byte offset where each line starts; the first is always 0.
    line_starts: Vec<usize>,
}

impl TextBuffer {
    /// A buffer holding `text`.
    pub fn new(text: &str) -> Self {
        let mut buffer = Self {
            text: text.to_owned(),
            line_starts: Vec::new(),
        };
        buffer.reindex();
        buffer
    }

    /// The whole text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The length of the text in bytes.
    pub fn len(&self) -> usize {
        self.text.len()
    }

    /// Whether the text is empty.
    pub fn is_empty(&self) -> bool {
        self.text.is_empty()
    }

    /// The number of lines; an empty text and a text ending in a newline count their last
    /// (empty) line.
    pub fn line_count(&self) -> usize {
        self.line_starts.len()
    }

    /// The byte range of line `line` without its line break; lines past the end give an
    /// empty range at the end of the text.
    pub fn line_range(&self, line: usize) -> Range<usize> {
        let Some(&start) = self.line_starts.get(line) else {
            return self.text.len()..self.text.len();
        };
        let mut end = self
            .line_starts
            .get(line + 1)
            .map_or(self.text.len(), |next| next - 1);
        if end > start && self.text.as_bytes().get(end - 1) == Some(&b'\r') {
            end -= 1;
        }
        start..end
    }

    /// The text of line `line` without its line break.
    pub fn line(&self, line: usize) -> &str {
        let range = self.line_range(line);
        &self.text[range]
    }

    /// The offset clamped to the text and moved back to the nearest char boundary.
    pub fn clamp(&self, offset: usize) -> usize {
        let mut offset = offset.min(self.text.len());
        while !self.text.is_char_boundary(offset) {
            offset -= 1;
        }
        offset
    }

    /// The line holding `offset` (after clamping).
    pub fn line_of(&self, offset: usize) -> usize {
        let offset = self.clamp(offset);
        self.line_starts
            .partition_point(|&start| start <= offset)
            .saturating_sub(1)
    }

    /// The line and the column in chars of `offset`; a column past the line's end is kept on
    /// the line.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = self.clamp(offset);
        let line = self.line_of(offset);
        let range = self.line_range(line);
        let end = offset.min(range.end);
        (line, self.text[range.start..end].chars().count())
    }

    /// The byte offset of a line and a column in chars, both clamped to the text.
    pub fn offset_of(&self, line: usize, col: usize) -> usize {
        let line = line.min(self.line_count().saturating_sub(1));
        let range = self.line_range(line);
        let line_text = &self.text[range.clone()];
        range.start
            + line_text
                .char_indices()
                .nth(col)
                .map_or(line_text.len(), |(at, _)| at)
    }

    /// Replaces `range` (clamped to char boundaries) with `text` and returns the range that
    /// was really replaced.
    pub fn replace(&mut self, range: Range<usize>, text: &str) -> Range<usize> {
        let start = self.clamp(range.start.min(range.end));
        let end = self.clamp(range.end.max(start));
        let first_line = self.line_of(start);
        let last_line = self.line_of(end);
        self.text.replace_range(start..end, text);
        // Only the lines the change touched are re-indexed; the later starts move by the
        // length difference, which keeps typing in a long text cheap.
        let delta = text.len() as isize - (end - start) as isize;
        let new_starts: Vec<usize> = text
            .match_indices('\n')
            .map(|(at, _)| start + at + 1)
            .collect();
        let tail: Vec<usize> = self.line_starts[last_line + 1..]
            .iter()
            .map(|&at| (at as isize + delta) as usize)
            .collect();
        self.line_starts.truncate(first_line + 1);
        self.line_starts.extend(new_starts);
        self.line_starts.extend(tail);
        start..end
    }

    /// Replaces the whole text.
    pub fn set_text(&mut self, text: &str) {
        text.clone_into(&mut self.text);
        self.reindex();
    }

    fn reindex(&mut self) {
        self.line_starts.clear();
        self.line_starts.push(0);
        self.line_starts.extend(
            self.text
                .as_bytes()
                .iter()
                .enumerate()
                .filter(|(_, byte)| **byte == b'\n')
                .map(|(at, _)| at + 1),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[track_caller]
    fn check_index(buffer: &TextBuffer) {
        assert_eq!(
            buffer.line_starts,
            TextBuffer::new(buffer.text()).line_starts
        );
    }

    #[test]
    fn inserting_and_deleting_across_lines_keeps_the_line_index() {
        let mut buffer = TextBuffer::new("a := 1;\nb := 2;\nc := 3;");
        buffer.replace(3..3, "x\ny\n");
        assert_eq!(buffer.text(), "a :x\ny\n= 1;\nb := 2;\nc := 3;");
        check_index(&buffer);
        assert_eq!(buffer.line_count(), 5);
        buffer.replace(2..16, "");
        assert_eq!(buffer.text(), "a  2;\nc := 3;");
        check_index(&buffer);
        assert_eq!(buffer.line(1), "c := 3;");
    }

    #[test]
    fn chinese_comments_map_bytes_to_lines_and_columns() {
        let buffer = TextBuffer::new("x := 1; // 计数器\r\ny := 2;");
        let counter = buffer.text().find('数').unwrap_or_default();
        assert_eq!(buffer.line_col(counter), (0, 12));
        assert_eq!(buffer.offset_of(0, 12), counter);
        // An offset inside a multibyte char is moved back to the char's start.
        assert_eq!(buffer.clamp(counter + 1), counter);
        assert_eq!(buffer.line_col(counter + 2), (0, 12));
        assert_eq!(buffer.line(0), "x := 1; // 计数器");
        assert_eq!(buffer.offset_of(1, 100), buffer.len());
        assert_eq!(buffer.offset_of(7, 0), buffer.line_range(1).start);
    }

    #[test]
    fn replacing_inside_a_multibyte_char_clamps_to_boundaries() {
        let mut buffer = TextBuffer::new("计数");
        let replaced = buffer.replace(1..4, "a");
        assert_eq!(replaced, 0..3);
        assert_eq!(buffer.text(), "a数");
        check_index(&buffer);
        assert_eq!(buffer.clamp(usize::MAX), buffer.len());
    }
}
