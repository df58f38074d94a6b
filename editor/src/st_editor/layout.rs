//! Layout of the visible lines: the galleys with highlighting and inline value boxes, and
//! the geometry that maps columns to positions.

use std::hash::{DefaultHasher, Hash, Hasher};
use std::ops::Range;
use std::sync::Arc;

use egui::text::{CCursor, LayoutJob, TextFormat};
use egui::{Color32, FontId, Galley, Rect, Ui, pos2};

use super::StEditor;
use super::syntax::LineSpan;
use crate::SyntaxColors;

/// A laid-out visible line.
pub(super) struct LineLayout {
    /// The buffer line.
    pub(super) line: usize,
    /// The row it is shown on.
    pub(super) row: usize,
    /// The shaped text, with blank room for the inline value boxes.
    pub(super) galley: Arc<Galley>,
    /// Inline value boxes: the char column they follow, their width in chars and the index
    /// of the value.
    pub(super) boxes: Vec<(usize, usize, usize)>,
}

impl LineLayout {
    /// The galley's char index of buffer column `col`: boxes before the column shift it.
    pub(super) fn galley_index(&self, col: usize) -> usize {
        col + self
            .boxes
            .iter()
            .filter(|(at, _, _)| *at < col)
            .map(|(_, width, _)| width)
            .sum::<usize>()
    }

    /// The buffer column of galley char index `index`; inside a box means before it.
    pub(super) fn column(&self, index: usize) -> usize {
        let mut shift = 0;
        for (at, width, _) in &self.boxes {
            let start = at + shift;
            if index <= start {
                break;
            }
            if index < start + width {
                return *at;
            }
            shift += width;
        }
        index - shift
    }

    /// The x of the caret position before buffer column `col`, from the galley's left.
    pub(super) fn x_of_col(&self, col: usize) -> f32 {
        self.galley
            .pos_from_cursor(CCursor::new(self.galley_index(col)))
            .min
            .x
    }
}

/// Sizes of the monospace font and the gutter.
#[derive(Clone, Copy)]
pub(super) struct Metrics {
    /// The height of a text row, in points.
    pub(super) row_height: f32,
    /// The width of a monospace char, in points.
    pub(super) char_width: f32,
    /// The width of the gutter (markers and line numbers), in points.
    pub(super) gutter_width: f32,
    /// Where the text starts, from the content's left, in points.
    pub(super) text_left: f32,
}

impl StEditor {
    /// The sizes of this frame's font and gutter.
    pub(super) fn metrics(&self, ui: &Ui, font: &FontId) -> Metrics {
        let (row_height, char_width) =
            ui.fonts_mut(|fonts| (fonts.row_height(font), fonts.glyph_width(font, '0')));
        let digits = self.buffer.line_count().to_string().len().max(3);
        // The breakpoint column, the numbers and the fold marker.
        let gutter_width =
            (super::debug_marks::BREAKPOINT_COLUMN_CHARS + digits as f32 + 3.0) * char_width;
        Metrics {
            row_height: row_height.max(1.0),
            char_width: char_width.max(1.0),
            gutter_width,
            text_left: gutter_width + char_width,
        }
    }

    /// The longest line in bytes, cached per revision.
    pub(super) fn widest_line(&mut self) -> usize {
        if let Some((revision, widest)) = self.widest
            && revision == self.revision
        {
            return widest;
        }
        let widest = (0..self.buffer.line_count())
            .map(|line| self.buffer.line_range(line).len())
            .max()
            .unwrap_or(0);
        self.widest = Some((self.revision, widest));
        widest
    }

    /// Lays out the rows `rows`, highlighting each run of consecutive lines with one query.
    pub(super) fn layout_rows(
        &mut self,
        ui: &Ui,
        rows: Range<usize>,
        font: &FontId,
    ) -> Vec<LineLayout> {
        let line_count = self.buffer.line_count();
        let lines: Vec<(usize, usize)> = rows
            .map(|row| (row, self.folding.line_of_row(row, line_count)))
            .collect();
        let mut layouts = Vec::with_capacity(lines.len());
        let colors = crate::EditorPalette::of(ui).syntax;
        let plain = ui.visuals().text_color();
        let mut at = 0;
        while at < lines.len() {
            let mut end = at + 1;
            while end < lines.len() && lines[end].1 == lines[end - 1].1 + 1 {
                end += 1;
            }
            let first_line = lines[at].1;
            let spans = self
                .syntax
                .highlight_lines(&self.buffer, first_line..lines[end - 1].1 + 1);
            for (index, &(row, line)) in lines[at..end].iter().enumerate() {
                let line_spans = spans.get(index).map_or(&[][..], Vec::as_slice);
                let boxes = self.line_boxes(line);
                let galley = self.line_galley(ui, line, line_spans, &boxes, font, &colors, plain);
                layouts.push(LineLayout {
                    line,
                    row,
                    galley,
                    boxes,
                });
            }
            at = end;
        }
        layouts
    }

    /// The inline value boxes of `line`: the column after the variable, the box width in
    /// chars and the value's index.
    pub(super) fn line_boxes(&self, line: usize) -> Vec<(usize, usize, usize)> {
        let range = self.buffer.line_range(line);
        let from = self
            .inline_values
            .partition_point(|value| value.range.end < range.start);
        self.inline_values[from..]
            .iter()
            .enumerate()
            .take_while(|(_, value)| value.range.end <= range.end)
            .filter(|(_, value)| self.buffer.text().is_char_boundary(value.range.end))
            .map(|(index, value)| {
                let col = self.buffer.text()[range.start..value.range.end]
                    .chars()
                    .count();
                let badge = if value.forced { 2 } else { 0 };
                (col, value.text.chars().count() + 3 + badge, from + index)
            })
            .collect()
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn line_galley(
        &mut self,
        ui: &Ui,
        line: usize,
        spans: &[LineSpan],
        boxes: &[(usize, usize, usize)],
        font: &FontId,
        colors: &SyntaxColors,
        plain: Color32,
    ) -> Arc<Galley> {
        let text = self.buffer.line(line);
        let mut hasher = DefaultHasher::new();
        (text, spans, colors, plain, font.size.to_bits()).hash(&mut hasher);
        for (col, width, _) in boxes {
            (col, width).hash(&mut hasher);
        }
        let key = hasher.finish();
        self.galleys.get(key, || {
            let mut job = LayoutJob::default();
            let format = |color: Color32| TextFormat::simple(font.clone(), color);
            let mut byte_boxes: Vec<(usize, usize)> = boxes
                .iter()
                .map(|(col, width, _)| {
                    let byte = text
                        .char_indices()
                        .nth(*col)
                        .map_or(text.len(), |(at, _)| at);
                    (byte, *width)
                })
                .collect();
            byte_boxes.reverse();
            let append = |job: &mut LayoutJob,
                          range: Range<usize>,
                          color: Color32,
                          boxes: &mut Vec<(usize, usize)>| {
                let mut start = range.start;
                while let Some(&(byte, width)) = boxes.last() {
                    if byte >= range.end {
                        break;
                    }
                    let byte = byte.max(start);
                    job.append(&text[start..byte], 0.0, format(color));
                    job.append(&" ".repeat(width), 0.0, format(Color32::TRANSPARENT));
                    start = byte;
                    boxes.pop();
                }
                job.append(&text[start..range.end], 0.0, format(color));
            };
            let mut covered = 0;
            for (range, class) in spans {
                if range.start < covered
                    || range.end > text.len()
                    || !text.is_char_boundary(range.start)
                    || !text.is_char_boundary(range.end)
                {
                    continue;
                }
                if range.start > covered {
                    append(&mut job, covered..range.start, plain, &mut byte_boxes);
                }
                append(
                    &mut job,
                    range.clone(),
                    class.color(colors, plain),
                    &mut byte_boxes,
                );
                covered = range.end;
            }
            if covered < text.len() {
                append(&mut job, covered..text.len(), plain, &mut byte_boxes);
            }
            for (_, width) in byte_boxes.into_iter().rev() {
                job.append(&" ".repeat(width), 0.0, format(Color32::TRANSPARENT));
            }
            if job.sections.is_empty() {
                job.append("", 0.0, format(plain));
            }
            ui.fonts_mut(|fonts| fonts.layout_job(job))
        })
    }

    /// The screen rectangle of the part of `range` on `layout`'s line.
    pub(super) fn range_rect(
        &self,
        layout: &LineLayout,
        range: &Range<usize>,
        text_x: f32,
        top: f32,
        metrics: &Metrics,
    ) -> Option<Rect> {
        let line_range = self.buffer.line_range(layout.line);
        if range.start > line_range.end || range.end < line_range.start {
            return None;
        }
        let start = range.start.clamp(line_range.start, line_range.end);
        let end = range.end.clamp(line_range.start, line_range.end);
        let text = self.buffer.text();
        if !text.is_char_boundary(start) || !text.is_char_boundary(end) {
            return None;
        }
        let start_col = text[line_range.start..start].chars().count();
        let end_col = text[line_range.start..end].chars().count();
        let x0 = text_x + layout.x_of_col(start_col);
        let mut x1 = text_x + layout.x_of_col(end_col);
        if range.end > line_range.end && range.start <= line_range.end {
            // A range that goes on past the line break shows a little of the break.
            x1 += metrics.char_width * 0.5;
        }
        (x1 > x0).then(|| Rect::from_min_max(pos2(x0, top), pos2(x1, top + metrics.row_height)))
    }
}
