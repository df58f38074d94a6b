//! The tree-sitter side of the editor: the syntax tree kept up to date incrementally, and the
//! highlighting, folding and matching it gives.

use std::ops::Range;

use tree_sitter::{InputEdit, Node, Parser, Point, Query, QueryCursor, StreamingIterator, Tree};

use super::buffer::TextBuffer;
use super::highlight::Highlight;
use crate::classify_tokens;

/// A run of highlighted text inside one line; the range is in bytes from the line's start.
pub type LineSpan = (Range<usize>, Highlight);

/// A result for a line range at a generation of the tree.
type Cached<T> = (u64, Range<usize>, T);

/// The syntax tree of the editor's text and the compiled queries.
pub struct Syntax {
    /// The parser; `None` if the grammar does not load (then nothing is parsed).
    parser: Option<Parser>,
    /// The latest tree, edited along with the text between parses.
    tree: Option<Tree>,
    /// The highlight query and the class of each of its captures; `None` when it does not
    /// compile against the grammar, and the lexical scanner is used instead.
    highlights: Option<(Query, Vec<Option<Highlight>>)>,
    /// The folding query; `None` when it does not compile, and nothing folds.
    folds: Option<Query>,
    /// Counts changes of the tree (edits and parses), to know when the caches are stale.
    generation: u64,
    /// The highlighting of the last line range asked for, with its generation: frames that
    /// change nothing (hover, caret moves) reuse it.
    span_cache: Option<Cached<Vec<Vec<LineSpan>>>>,
    /// The foldable blocks of the last line range asked for, with its generation.
    fold_cache: Option<Cached<Vec<(usize, usize)>>>,
    /// Whether the text is Instruction List, highlighted by `il_highlight` without a tree.
    instruction_list: bool,
}

impl Syntax {
    /// Parses `text` from scratch.
    pub fn new(text: &str) -> Self {
        let language = tree_sitter_rivet_st::language();
        let mut parser = Parser::new();
        let parser = parser.set_language(&language).is_ok().then_some(parser);
        let highlights = Query::new(&language, tree_sitter_rivet_st::HIGHLIGHTS_QUERY)
            .ok()
            .map(|query| {
                let classes = query
                    .capture_names()
                    .iter()
                    .map(|name| Highlight::from_capture(name))
                    .collect();
                (query, classes)
            });
        let folds = Query::new(&language, tree_sitter_rivet_st::FOLDS_QUERY).ok();
        let mut syntax = Self {
            parser,
            tree: None,
            highlights,
            folds,
            generation: 0,
            span_cache: None,
            fold_cache: None,
            instruction_list: false,
        };
        syntax.reparse(text, false);
        syntax
    }

    /// The syntax of an Instruction List text: no tree-sitter parser (the grammar is ST's),
    /// highlighting by the IL scanner, nothing to fold or match.
    pub fn instruction_list() -> Self {
        Self {
            parser: None,
            tree: None,
            highlights: None,
            folds: None,
            generation: 0,
            span_cache: None,
            fold_cache: None,
            instruction_list: true,
        }
    }

    /// Forgets the old tree and parses `text` again (after `set_text`).
    pub fn reset(&mut self, text: &str) {
        self.reparse(text, false);
    }

    /// Tells the tree that `range` of `buffer` (the text before the change) becomes
    /// `new_text`; call [`Syntax::reparse`] after the buffer changed.
    pub fn edit(&mut self, buffer: &TextBuffer, range: &Range<usize>, new_text: &str) {
        self.generation += 1;
        let Some(tree) = self.tree.as_mut() else {
            return;
        };
        let start_position = point(buffer, range.start);
        let old_end_position = point(buffer, range.end);
        let new_lines = new_text.matches('\n').count();
        let new_end_position = if new_lines == 0 {
            Point::new(start_position.row, start_position.column + new_text.len())
        } else {
            let last = new_text.rfind('\n').map_or(0, |at| at + 1);
            Point::new(start_position.row + new_lines, new_text.len() - last)
        };
        tree.edit(&InputEdit {
            start_byte: range.start,
            old_end_byte: range.end,
            new_end_byte: range.start + new_text.len(),
            start_position,
            old_end_position,
            new_end_position,
        });
    }

    /// Parses `text` again, reusing the edited old tree when `incremental`.
    pub fn reparse(&mut self, text: &str, incremental: bool) {
        self.generation += 1;
        let Some(parser) = self.parser.as_mut() else {
            self.tree = None;
            return;
        };
        let old = if incremental {
            self.tree.as_ref()
        } else {
            None
        };
        self.tree = parser.parse(text, old);
    }

    /// The highlighted runs of each line in `lines`, one list per line.
    pub fn highlight_lines(
        &mut self,
        buffer: &TextBuffer,
        lines: Range<usize>,
    ) -> Vec<Vec<LineSpan>> {
        if let Some((generation, cached_lines, spans)) = &self.span_cache
            && *generation == self.generation
            && *cached_lines == lines
        {
            return spans.clone();
        }
        let spans = self.compute_highlights(buffer, lines.clone());
        self.span_cache = Some((self.generation, lines, spans.clone()));
        spans
    }

    fn compute_highlights(&self, buffer: &TextBuffer, lines: Range<usize>) -> Vec<Vec<LineSpan>> {
        let lines = lines.start.min(buffer.line_count())..lines.end.min(buffer.line_count());
        let mut per_byte: Vec<Vec<(usize, Highlight)>> = lines
            .clone()
            .map(|line| vec![(usize::MAX, Highlight::Plain); buffer.line_range(line).len()])
            .collect();
        match (&self.tree, &self.highlights) {
            (Some(tree), Some((query, classes))) if !lines.is_empty() => {
                let first = buffer.line_range(lines.start).start;
                let last = buffer.line_range(lines.end - 1).end;
                let mut cursor = QueryCursor::new();
                cursor.set_byte_range(first..last.max(first + 1));
                let text = buffer.text().as_bytes();
                let mut captures = cursor.captures(query, tree.root_node(), text);
                // The first pattern that captures a node wins; a smaller node inside a
                // larger capture wins over it. A byte keeps the best (size, pattern) seen.
                while let Some((found, index)) = captures.next() {
                    let capture = found.captures()[*index];
                    let Some(class) = classes.get(capture.index as usize).copied().flatten() else {
                        continue;
                    };
                    let node = capture.node;
                    let rank = node.byte_range().len().saturating_mul(1024)
                        + found.pattern_index.min(1023);
                    paint(
                        buffer,
                        &lines,
                        &mut per_byte,
                        node.byte_range(),
                        rank,
                        class,
                    );
                }
            }
            _ if self.instruction_list && !lines.is_empty() => {
                let first = buffer.line_range(lines.start).start;
                let last = buffer.line_range(lines.end - 1).end;
                for (range, class) in super::il_highlight::il_spans(buffer.text()) {
                    if range.end <= first || range.start >= last {
                        continue;
                    }
                    paint(buffer, &lines, &mut per_byte, range, 0, class);
                }
            }
            _ => {
                for (index, line) in lines.clone().enumerate() {
                    for (range, class) in classify_tokens(buffer.line(line)) {
                        for slot in &mut per_byte[index][range] {
                            slot.1 = Highlight::from_token(class);
                        }
                    }
                }
            }
        }
        per_byte.into_iter().map(|bytes| runs(&bytes)).collect()
    }

    /// Foldable blocks that start on one of `lines` and end on a later line, as
    /// (first line, last line), the largest block of each first line.
    pub fn folds_starting_in(
        &mut self,
        buffer: &TextBuffer,
        lines: Range<usize>,
    ) -> Vec<(usize, usize)> {
        if let Some((generation, cached_lines, folds)) = &self.fold_cache
            && *generation == self.generation
            && *cached_lines == lines
        {
            return folds.clone();
        }
        let folds = self.compute_folds(buffer, lines.clone());
        self.fold_cache = Some((self.generation, lines, folds.clone()));
        folds
    }

    fn compute_folds(&self, buffer: &TextBuffer, lines: Range<usize>) -> Vec<(usize, usize)> {
        let (Some(tree), Some(query)) = (&self.tree, &self.folds) else {
            return Vec::new();
        };
        if lines.is_empty() || lines.start >= buffer.line_count() {
            return Vec::new();
        }
        let first = buffer.line_range(lines.start).start;
        let last = buffer
            .line_range(lines.end.min(buffer.line_count()) - 1)
            .end;
        let mut cursor = QueryCursor::new();
        cursor.set_byte_range(first..last.max(first + 1));
        let mut found: Vec<(usize, usize)> = Vec::new();
        let mut matches = cursor.matches(query, tree.root_node(), buffer.text().as_bytes());
        while let Some(matched) = matches.next() {
            for capture in matched.captures() {
                let node = capture.node;
                let start = node.start_position().row;
                // A block's last byte may be the line break after it; the block ends on the
                // line of its last real byte.
                let end = buffer.line_of(node.end_byte().saturating_sub(1).max(node.start_byte()));
                if lines.contains(&start) && end > start {
                    match found.iter_mut().find(|(line, _)| *line == start) {
                        Some(existing) => existing.1 = existing.1.max(end),
                        None => found.push((start, end)),
                    }
                }
            }
        }
        found.sort_unstable();
        found
    }

    /// The byte ranges of the bracket or block keyword at `offset` (or just before it) and
    /// of its partner.
    pub fn matching_pair(&self, text: &str, offset: usize) -> Option<(Range<usize>, Range<usize>)> {
        let tree = self.tree.as_ref()?;
        let root = tree.root_node();
        let candidates = [Some(offset), offset.checked_sub(1)];
        for at in candidates.into_iter().flatten() {
            let Some(leaf) = root.descendant_for_byte_range(at, at) else {
                continue;
            };
            if leaf.byte_range().is_empty() || !leaf.byte_range().contains(&at) {
                continue;
            }
            if let Some(partner) = partner_of(leaf, text) {
                return Some((leaf.byte_range(), partner.byte_range()));
            }
        }
        None
    }
}

/// The node that closes or opens the same block or bracket pair as `leaf`.
fn partner_of<'tree>(leaf: Node<'tree>, text: &str) -> Option<Node<'tree>> {
    if leaf.is_named() {
        return None;
    }
    let kind = leaf.kind();
    let parent = leaf.parent()?;
    let mut cursor = parent.walk();
    let children: Vec<Node<'tree>> = parent.children(&mut cursor).collect();
    let position = children.iter().position(|child| child.id() == leaf.id())?;
    let closer = match kind {
        "(" => Some(")"),
        "[" => Some("]"),
        _ => None,
    };
    if let Some(closer) = closer {
        return children[position + 1..]
            .iter()
            .find(|child| child.kind() == closer)
            .copied();
    }
    let opener = match kind {
        ")" => Some("("),
        "]" => Some("["),
        _ => None,
    };
    if let Some(opener) = opener {
        return children[..position]
            .iter()
            .rev()
            .find(|child| child.kind() == opener)
            .copied();
    }
    let is_word = |node: &Node| {
        !node.is_named()
            && node
                .utf8_text(text.as_bytes())
                .is_ok_and(|word| word.chars().all(|c| c.is_ascii_alphabetic() || c == '_'))
    };
    if !is_word(&leaf) {
        return None;
    }
    if kind.starts_with("END_") {
        // The block's opening keyword is its first child that is a word.
        children[..position]
            .iter()
            .find(|child| is_word(child))
            .copied()
    } else if position == children.iter().position(is_word)? {
        children[position + 1..]
            .iter()
            .rev()
            .find(|child| child.kind().starts_with("END_"))
            .copied()
    } else {
        None
    }
}

fn point(buffer: &TextBuffer, offset: usize) -> Point {
    let line = buffer.line_of(offset);
    Point::new(line, offset - buffer.line_range(line).start)
}

fn paint(
    buffer: &TextBuffer,
    lines: &Range<usize>,
    per_byte: &mut [Vec<(usize, Highlight)>],
    range: Range<usize>,
    rank: usize,
    class: Highlight,
) {
    let first = buffer.line_of(range.start).max(lines.start);
    let last = buffer.line_of(range.end).min(lines.end.saturating_sub(1));
    for line in first..=last {
        let line_range = buffer.line_range(line);
        let start = range.start.max(line_range.start) - line_range.start;
        let end = range
            .end
            .min(line_range.end)
            .saturating_sub(line_range.start);
        if let Some(bytes) = per_byte.get_mut(line - lines.start) {
            for slot in bytes.iter_mut().take(end).skip(start) {
                if rank < slot.0 {
                    *slot = (rank, class);
                }
            }
        }
    }
}

fn runs(bytes: &[(usize, Highlight)]) -> Vec<LineSpan> {
    let mut runs: Vec<LineSpan> = Vec::new();
    for (at, (_, class)) in bytes.iter().enumerate() {
        match runs.last_mut() {
            Some((range, last)) if *last == *class => range.end = at + 1,
            _ => runs.push((at..at + 1, *class)),
        }
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn class_of(text: &str, word: &str) -> Option<Highlight> {
        let buffer = TextBuffer::new(text);
        let mut syntax = Syntax::new(text);
        let at = text.find(word)?;
        let line = buffer.line_of(at);
        let column = at - buffer.line_range(line).start;
        let spans = syntax.highlight_lines(&buffer, line..line + 1);
        spans[0]
            .iter()
            .find(|(range, _)| range.contains(&column))
            .map(|(_, class)| *class)
    }

    #[test]
    fn an_instruction_list_text_is_highlighted_line_by_line_without_a_tree() {
        let text = "(* count\n   up *)\nLD x\nNext: ADD 1\nJMPC Next\n";
        let buffer = TextBuffer::new(text);
        let mut syntax = Syntax::instruction_list();
        let spans = syntax.highlight_lines(&buffer, 1..5);
        let class = |line: usize, column: usize| {
            spans[line - 1]
                .iter()
                .find(|(range, _)| range.contains(&column))
                .map(|(_, class)| *class)
        };
        assert_eq!(class(1, 4), Some(Highlight::Comment));
        assert_eq!(class(2, 0), Some(Highlight::Keyword));
        assert_eq!(class(3, 0), Some(Highlight::Label));
        assert_eq!(class(3, 6), Some(Highlight::Keyword));
        assert_eq!(class(3, 10), Some(Highlight::Number));
        assert_eq!(class(4, 6), Some(Highlight::Label));
        assert!(syntax.folds_starting_in(&buffer, 0..5).is_empty());
    }

    const SAMPLE: &str = "PROGRAM Main\nVAR\n    count : INT := 42; // 计数\n    name : STRING := 'hello';\nEND_VAR\nIF count > 10 THEN\n    count := 0;\nEND_IF;\nEND_PROGRAM\n";

    #[test]
    fn keywords_comments_strings_and_numbers_get_their_classes() {
        assert_eq!(class_of(SAMPLE, "PROGRAM"), Some(Highlight::Keyword));
        assert_eq!(class_of(SAMPLE, "END_VAR"), Some(Highlight::Keyword));
        assert_eq!(class_of(SAMPLE, "IF"), Some(Highlight::Keyword));
        assert_eq!(class_of(SAMPLE, "42"), Some(Highlight::Number));
        assert_eq!(class_of(SAMPLE, "// 计数"), Some(Highlight::Comment));
        assert_eq!(class_of(SAMPLE, "'hello'"), Some(Highlight::String));
        assert_eq!(class_of(SAMPLE, "INT"), Some(Highlight::Type));
        assert_eq!(class_of(SAMPLE, " := 0").map(|_| ()), Some(()));
    }

    #[test]
    fn an_if_block_is_foldable_and_its_keywords_match() {
        let buffer = TextBuffer::new(SAMPLE);
        let mut syntax = Syntax::new(SAMPLE);
        let folds = syntax.folds_starting_in(&buffer, 5..6);
        assert_eq!(folds, vec![(5, 7)]);
        let if_at = SAMPLE.find("IF count").unwrap_or_default();
        let end_if = SAMPLE.find("END_IF").unwrap_or_default();
        assert_eq!(
            syntax.matching_pair(SAMPLE, if_at),
            Some((if_at..if_at + 2, end_if..end_if + 6))
        );
        assert_eq!(
            syntax.matching_pair(SAMPLE, end_if + 3),
            Some((end_if..end_if + 6, if_at..if_at + 2))
        );
    }

    #[test]
    fn without_the_highlight_query_the_lexical_scanner_colours_the_text() {
        let mut syntax = Syntax::new(SAMPLE);
        syntax.highlights = None;
        let buffer = TextBuffer::new(SAMPLE);
        let spans = syntax.highlight_lines(&buffer, 2..3);
        let line = buffer.line(2);
        let class_at = |word: &str| {
            let at = line.find(word).unwrap_or_default();
            spans[0]
                .iter()
                .find(|(range, _)| range.contains(&at))
                .map(|(_, class)| *class)
        };
        assert_eq!(class_at("INT"), Some(Highlight::Keyword));
        assert_eq!(class_at("42"), Some(Highlight::Number));
        assert_eq!(class_at("//"), Some(Highlight::Comment));
    }

    #[test]
    fn every_block_keyword_finds_its_end() {
        let text = "FUNCTION_BLOCK Fb\nVAR_INPUT\n    a : INT;\nEND_VAR\nFOR i := 1 TO 3 DO\n    WHILE a > 0 DO\n        REPEAT a := a - 1; UNTIL a < 5 END_REPEAT;\n    END_WHILE;\nEND_FOR;\nCASE a OF\n1: a := 2;\nEND_CASE;\nEND_FUNCTION_BLOCK\n";
        let syntax = Syntax::new(text);
        for (open, close) in [
            ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
            ("VAR_INPUT", "END_VAR"),
            ("FOR", "END_FOR"),
            ("WHILE", "END_WHILE"),
            ("REPEAT", "END_REPEAT"),
            ("CASE", "END_CASE"),
        ] {
            let open_at = text
                .find(&format!("{open} "))
                .or_else(|| text.find(&format!("{open}\n")))
                .unwrap_or_default();
            let close_at = text.find(close).unwrap_or_default();
            assert_eq!(
                syntax.matching_pair(text, open_at + 1),
                Some((
                    open_at..open_at + open.len(),
                    close_at..close_at + close.len()
                )),
                "{open}"
            );
        }
    }

    #[test]
    fn brackets_match_after_an_incremental_edit() {
        let text = "x := (a + b) * 2;";
        let mut buffer = TextBuffer::new(text);
        let mut syntax = Syntax::new(text);
        syntax.edit(&buffer, &(0..0), "y := 1;\n");
        buffer.replace(0..0, "y := 1;\n");
        syntax.reparse(buffer.text(), true);
        let open = buffer.text().find('(').unwrap_or_default();
        let close = buffer.text().find(')').unwrap_or_default();
        assert_eq!(
            syntax.matching_pair(buffer.text(), close + 1),
            Some((close..close + 1, open..open + 1))
        );
    }
}
