//! Folded blocks: which lines are hidden, and the rows that remain visible.

/// The folded blocks of the editor, each as its first and last line; the first line stays
/// visible and the others are hidden.
#[derive(Clone, Debug, Default)]
pub struct Folding {
    /// Folded blocks, sorted by first line; lasts only as long as the editor.
    folded: Vec<(usize, usize)>,
    /// The visible lines in order, when something is folded; rebuilt on demand.
    rows: Option<Vec<usize>>,
    /// The line count `rows` was built for.
    rows_lines: usize,
}

impl Folding {
    /// Folds the block `first..=last`, or unfolds it when its first line is folded.
    pub fn toggle(&mut self, first: usize, last: usize) {
        if let Some(at) = self.folded.iter().position(|(start, _)| *start == first) {
            self.folded.remove(at);
        } else {
            self.folded.push((first, last));
            self.folded.sort_unstable();
        }
        self.rows = None;
    }

    /// Whether a folded block starts on `line`.
    pub fn is_folded_at(&self, line: usize) -> bool {
        self.folded.iter().any(|(start, _)| *start == line)
    }

    /// Whether `line` is hidden by a fold.
    pub fn is_hidden(&self, line: usize) -> bool {
        self.folded
            .iter()
            .any(|(start, end)| line > *start && line <= *end)
    }

    /// Unfolds every block that hides `line`.
    pub fn unfold_line(&mut self, line: usize) {
        let before = self.folded.len();
        self.folded
            .retain(|(start, end)| !(line > *start && line <= *end));
        if self.folded.len() != before {
            self.rows = None;
        }
    }

    /// Drops folds past the end of a text of `line_count` lines.
    pub fn clamp(&mut self, line_count: usize) {
        self.folded.retain(|(_, end)| *end < line_count);
        self.rows = None;
    }

    /// Follows a change that replaced lines `first..=last` with `new_last - first + 1`
    /// lines: later folds move, folds whose hidden lines were touched open.
    pub fn follow_edit(&mut self, first: usize, last: usize, new_last: usize) {
        if self.folded.is_empty() {
            return;
        }
        let delta = new_last as isize - last as isize;
        let single_line = first == last && delta == 0;
        self.folded.retain_mut(|(start, end)| {
            if *start > last {
                *start = (*start as isize + delta) as usize;
                *end = (*end as isize + delta) as usize;
                true
            } else {
                *end < first || (single_line && *start == first)
            }
        });
        self.rows = None;
    }

    /// The number of visible rows of a text of `line_count` lines.
    pub fn row_count(&mut self, line_count: usize) -> usize {
        self.rows(line_count).map_or(line_count, <[usize]>::len)
    }

    /// The line shown on row `row` (clamped).
    pub fn line_of_row(&mut self, row: usize, line_count: usize) -> usize {
        match self.rows(line_count) {
            Some(rows) => rows.get(row).or(rows.last()).copied().unwrap_or_default(),
            None => row.min(line_count.saturating_sub(1)),
        }
    }

    /// The row showing `line`, or the row of the fold that hides it.
    pub fn row_of_line(&mut self, line: usize, line_count: usize) -> usize {
        match self.rows(line_count) {
            Some(rows) => rows
                .partition_point(|&shown| shown <= line)
                .saturating_sub(1),
            None => line,
        }
    }

    fn rows(&mut self, line_count: usize) -> Option<&[usize]> {
        if self.folded.is_empty() {
            return None;
        }
        if self.rows.is_none() || self.rows_lines != line_count {
            let rows = (0..line_count)
                .filter(|&line| !self.is_hidden(line))
                .collect();
            self.rows = Some(rows);
            self.rows_lines = line_count;
        }
        self.rows.as_deref()
    }
}
