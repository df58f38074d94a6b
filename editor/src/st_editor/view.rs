//! Showing the editor: layout of the visible lines, pointer input and painting.

use std::hash::{DefaultHasher, Hash, Hasher};
use std::ops::Range;
use std::sync::Arc;

use egui::text::{CCursor, LayoutJob, TextFormat};
use egui::{
    Color32, EventFilter, FontId, Galley, Painter, Pos2, Rect, Role, Sense, Stroke, TextStyle, Ui,
    Vec2, WidgetInfo, pos2, vec2,
};

use super::input::FrameResult;
use super::syntax::LineSpan;
use super::{LanguageServices, Severity, StEditor, StEditorOutput};

/// How long the pointer must rest before hover information shows, in seconds.
const HOVER_DELAY_S: f32 = 0.4;

/// A laid-out visible line.
struct LineLayout {
    /// The buffer line.
    line: usize,
    /// The row it is shown on.
    row: usize,
    galley: Arc<Galley>,
    /// Inline value boxes: the char column they follow, their width in chars and the index
    /// of the value.
    boxes: Vec<(usize, usize, usize)>,
}

impl LineLayout {
    /// The galley's char index of buffer column `col`: boxes before the column shift it.
    fn galley_index(&self, col: usize) -> usize {
        col + self
            .boxes
            .iter()
            .filter(|(at, _, _)| *at < col)
            .map(|(_, width, _)| width)
            .sum::<usize>()
    }

    /// The buffer column of galley char index `index`; inside a box means before it.
    fn column(&self, index: usize) -> usize {
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

    fn x_of_col(&self, col: usize) -> f32 {
        self.galley
            .pos_from_cursor(CCursor::new(self.galley_index(col)))
            .min
            .x
    }
}

/// Sizes of the monospace font and the gutter.
#[derive(Clone, Copy)]
struct Metrics {
    row_height: f32,
    char_width: f32,
    gutter_width: f32,
    text_left: f32,
}

impl StEditor {
    /// Shows the editor filling the available space. `label` is its accessible name (and
    /// keeps its state apart from other editors); `services` answer completion and hover.
    pub fn show(
        &mut self,
        ui: &mut Ui,
        label: &str,
        services: &dyn LanguageServices,
    ) -> StEditorOutput {
        let id = ui.make_persistent_id(("st_editor", label));
        let mut result = FrameResult::default();
        self.galleys.begin_frame();
        if self.find_bar_ui(ui, &mut result) {
            self.focus_requested = true;
        }
        let font = TextStyle::Monospace.resolve(ui.style());
        let metrics = self.metrics(ui, &font);
        if ui.memory(|memory| memory.has_focus(id)) {
            let filter = EventFilter {
                tab: true,
                horizontal_arrows: true,
                vertical_arrows: true,
                escape: true,
            };
            ui.memory_mut(|memory| memory.set_focus_lock_filter(id, filter));
            let events = ui.input(|input| input.filtered_events(&filter));
            self.handle_events(ui.ctx(), &events, services, &mut result);
        }
        self.refresh_syntax();
        let line_count = self.buffer.line_count();
        let row_count = self.folding.row_count(line_count);
        let widest = self.widest_line();
        let content = vec2(
            metrics.text_left + (widest as f32 + 16.0) * metrics.char_width,
            (row_count as f32 + 1.0) * metrics.row_height,
        );
        let scroll = egui::ScrollArea::both()
            .id_salt(id.with("scroll"))
            .auto_shrink([false, false])
            .show_viewport(ui, |ui, viewport| {
                self.text_area_ui(
                    ui,
                    id,
                    label,
                    content,
                    viewport,
                    &metrics,
                    &font,
                    services,
                    &mut result,
                )
            });
        let response = scroll.inner;
        StEditorOutput {
            response,
            gesture: result.gesture(self.typing_run),
            changes: result.changes,
            goto_definition: result.goto_definition,
            find_references: result.find_references,
            prepared: result.prepared,
            caret: self.caret,
        }
    }

    fn metrics(&self, ui: &Ui, font: &FontId) -> Metrics {
        let (row_height, char_width) =
            ui.fonts_mut(|fonts| (fonts.row_height(font), fonts.glyph_width(font, '0')));
        let digits = self.buffer.line_count().to_string().len().max(3);
        let gutter_width = (digits as f32 + 3.0) * char_width;
        Metrics {
            row_height: row_height.max(1.0),
            char_width: char_width.max(1.0),
            gutter_width,
            text_left: gutter_width + char_width,
        }
    }

    /// The longest line in bytes, cached per revision.
    fn widest_line(&mut self) -> usize {
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

    #[allow(clippy::too_many_arguments)]
    fn text_area_ui(
        &mut self,
        ui: &mut Ui,
        id: egui::Id,
        label: &str,
        content: Vec2,
        viewport: Rect,
        metrics: &Metrics,
        font: &FontId,
        services: &dyn LanguageServices,
        result: &mut FrameResult,
    ) -> egui::Response {
        let (_, rect) = ui.allocate_space(content);
        let response = ui.interact(rect, id, Sense::click_and_drag());
        let label_text = label.to_owned();
        let enabled = ui.is_enabled();
        response
            .widget_info(|| WidgetInfo::labeled(Role::MultilineTextInput, enabled, &label_text));
        if std::mem::take(&mut self.focus_requested)
            || response.clicked()
            || response.drag_started()
        {
            response.request_focus();
        }
        let origin = rect.min;
        let line_count = self.buffer.line_count();
        let row_count = self.folding.row_count(line_count);
        let first_row =
            ((viewport.min.y / metrics.row_height).floor().max(0.0) as usize).min(row_count);
        let last_row =
            ((viewport.max.y / metrics.row_height).ceil().max(0.0) as usize + 1).min(row_count);
        self.page_rows = ((viewport.height() / metrics.row_height) as usize)
            .saturating_sub(1)
            .max(1);
        let layouts = self.layout_rows(ui, first_row..last_row, font);
        let text_x = origin.x + metrics.text_left;
        let row_top = |row: usize| origin.y + row as f32 * metrics.row_height;
        let clip = ui.clip_rect();

        self.pointer(ui, &response, &layouts, origin, clip, metrics, font);

        let painter = ui.painter_at(clip);
        let visuals = ui.visuals().clone();
        let focused = response.has_focus();
        let selection = self.selection();
        let first_offset = layouts
            .first()
            .map_or(0, |layout| self.buffer.line_range(layout.line).start);
        let last_offset = layouts
            .last()
            .map_or(0, |layout| self.buffer.line_range(layout.line).end);
        // Backgrounds: the caret's line, find matches, the selection, the matching pair.
        let caret_line = self.buffer.line_of(self.caret);
        let mut find_ranges: Vec<Range<usize>> = Vec::new();
        if self.find.open {
            let matches = self.matches();
            let from = matches.partition_point(|range| range.end < first_offset);
            find_ranges.extend(
                matches[from..]
                    .iter()
                    .take_while(|range| range.start <= last_offset)
                    .cloned(),
            );
        }
        let pair = if focused {
            self.syntax.matching_pair(self.buffer.text(), self.caret)
        } else {
            None
        };
        let find_color = if visuals.dark_mode {
            Color32::from_rgba_unmultiplied(200, 160, 40, 70)
        } else {
            Color32::from_rgba_unmultiplied(250, 200, 60, 110)
        };
        for layout in &layouts {
            let top = row_top(layout.row);
            if layout.line == caret_line && focused {
                let line_rect = Rect::from_min_size(
                    pos2(clip.min.x, top),
                    vec2(clip.width(), metrics.row_height),
                );
                painter.rect_filled(line_rect, 0.0, visuals.faint_bg_color);
            }
            for range in &find_ranges {
                self.paint_range(&painter, layout, range, text_x, top, metrics, find_color);
            }
            if !selection.is_empty() {
                self.paint_range(
                    &painter,
                    layout,
                    &selection,
                    text_x,
                    top,
                    metrics,
                    visuals.selection.bg_fill,
                );
            }
            if let Some((here, there)) = &pair {
                for range in [here, there] {
                    if let Some(area) = self.range_rect(layout, range, text_x, top, metrics) {
                        painter.rect_stroke(
                            area,
                            2.0,
                            Stroke::new(1.0, visuals.weak_text_color()),
                            egui::StrokeKind::Inside,
                        );
                    }
                }
            }
        }
        // The text, then what is drawn over it.
        let plain = visuals.text_color();
        for layout in &layouts {
            let top = row_top(layout.row);
            painter.galley(pos2(text_x, top), layout.galley.clone(), plain);
            if self.folding.is_folded_at(layout.line) {
                let end = text_x + layout.galley.size().x + metrics.char_width;
                let marker = painter.text(
                    pos2(end, top),
                    egui::Align2::LEFT_TOP,
                    "…",
                    font.clone(),
                    visuals.weak_text_color(),
                );
                painter.rect_stroke(
                    marker.expand(1.0),
                    2.0,
                    Stroke::new(1.0, visuals.weak_text_color()),
                    egui::StrokeKind::Inside,
                );
            }
            self.paint_inline_values(&painter, layout, text_x, top, metrics, font, &visuals);
        }
        self.paint_diagnostics(
            &painter,
            &layouts,
            text_x,
            &row_top,
            metrics,
            first_offset,
            last_offset,
        );
        if focused && let Some(layout) = layouts.iter().find(|layout| layout.line == caret_line) {
            let (_, col) = self.buffer.line_col(self.caret);
            let x = text_x + layout.x_of_col(col);
            let top = row_top(layout.row);
            painter.line_segment(
                [pos2(x, top), pos2(x, top + metrics.row_height)],
                Stroke::new(2.0, visuals.text_cursor.stroke.color),
            );
        }
        self.paint_gutter(&painter, &layouts, clip, &row_top, metrics, font, &visuals);

        let caret_row = self.folding.row_of_line(caret_line, line_count);
        let caret_x = layouts
            .iter()
            .find(|layout| layout.line == caret_line)
            .map_or(0.0, |layout| {
                layout.x_of_col(self.buffer.line_col(self.caret).1)
            });
        let caret_rect = Rect::from_min_size(
            pos2(text_x + caret_x, row_top(caret_row)),
            vec2(metrics.char_width, metrics.row_height),
        );
        if std::mem::take(&mut self.scroll_to_caret) {
            let margin = vec2(metrics.char_width * 4.0, metrics.row_height * 2.0);
            ui.scroll_to_rect(caret_rect.expand2(margin), None);
        }
        if focused {
            self.completion_ui(ui.ctx(), id, caret_rect.left_bottom(), result);
        }
        self.value_editor_ui(ui, id, result);
        self.hover_ui(ui, &response, &layouts, origin, metrics, services);
        response
    }

    /// Lays out the rows `rows`, highlighting each run of consecutive lines with one query.
    fn layout_rows(&mut self, ui: &Ui, rows: Range<usize>, font: &FontId) -> Vec<LineLayout> {
        let line_count = self.buffer.line_count();
        let lines: Vec<(usize, usize)> = rows
            .map(|row| (row, self.folding.line_of_row(row, line_count)))
            .collect();
        let mut layouts = Vec::with_capacity(lines.len());
        let dark = ui.visuals().dark_mode;
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
                let galley = self.line_galley(ui, line, line_spans, &boxes, font, dark, plain);
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
    fn line_boxes(&self, line: usize) -> Vec<(usize, usize, usize)> {
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
    fn line_galley(
        &mut self,
        ui: &Ui,
        line: usize,
        spans: &[LineSpan],
        boxes: &[(usize, usize, usize)],
        font: &FontId,
        dark: bool,
        plain: Color32,
    ) -> Arc<Galley> {
        let text = self.buffer.line(line);
        let mut hasher = DefaultHasher::new();
        (text, spans, dark, plain, font.size.to_bits()).hash(&mut hasher);
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
                    class.color(dark, plain),
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
    fn range_rect(
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

    #[allow(clippy::too_many_arguments)]
    fn paint_range(
        &self,
        painter: &Painter,
        layout: &LineLayout,
        range: &Range<usize>,
        text_x: f32,
        top: f32,
        metrics: &Metrics,
        color: Color32,
    ) {
        if let Some(area) = self.range_rect(layout, range, text_x, top, metrics) {
            painter.rect_filled(area, 0.0, color);
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn paint_inline_values(
        &self,
        painter: &Painter,
        layout: &LineLayout,
        text_x: f32,
        top: f32,
        metrics: &Metrics,
        font: &FontId,
        visuals: &egui::Visuals,
    ) {
        let small = FontId::new(font.size * 0.9, font.family.clone());
        for (col, width, index) in &layout.boxes {
            let Some(value) = self.inline_values.get(*index) else {
                continue;
            };
            let x0 = text_x + layout.x_of_col(*col) + metrics.char_width * 0.5;
            let x1 = x0 + (*width as f32 - 1.0) * metrics.char_width;
            let area = Rect::from_min_max(
                pos2(x0, top + 1.0),
                pos2(x1, top + metrics.row_height - 1.0),
            );
            let fill = if value.changed {
                if visuals.dark_mode {
                    Color32::from_rgb(40, 90, 60)
                } else {
                    Color32::from_rgb(190, 240, 200)
                }
            } else {
                visuals.extreme_bg_color
            };
            painter.rect_filled(area, 2.0, fill);
            painter.rect_stroke(
                area,
                2.0,
                Stroke::new(1.0, visuals.weak_text_color()),
                egui::StrokeKind::Inside,
            );
            let mut text_left = area.min.x + metrics.char_width * 0.5;
            if value.forced {
                let badge = Rect::from_min_size(
                    pos2(area.min.x + 1.0, area.min.y + 1.0),
                    vec2(metrics.char_width * 1.4, area.height() - 2.0),
                );
                painter.rect_filled(badge, 2.0, Color32::from_rgb(200, 40, 40));
                painter.text(
                    badge.center(),
                    egui::Align2::CENTER_CENTER,
                    "F",
                    small.clone(),
                    Color32::WHITE,
                );
                text_left += metrics.char_width * 2.0;
            }
            painter.text(
                pos2(text_left, area.center().y),
                egui::Align2::LEFT_CENTER,
                &value.text,
                small.clone(),
                visuals.text_color(),
            );
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn paint_diagnostics(
        &self,
        painter: &Painter,
        layouts: &[LineLayout],
        text_x: f32,
        row_top: &dyn Fn(usize) -> f32,
        metrics: &Metrics,
        first: usize,
        last: usize,
    ) {
        for diagnostic in &self.diagnostics {
            if diagnostic.range.end < first || diagnostic.range.start > last {
                continue;
            }
            let color = severity_color(diagnostic.severity);
            let range = if diagnostic.range.is_empty() {
                diagnostic.range.start
                    ..self
                        .next_char(diagnostic.range.start)
                        .max(diagnostic.range.start + 1)
            } else {
                diagnostic.range.clone()
            };
            for layout in layouts {
                let top = row_top(layout.row);
                let area = self
                    .range_rect(layout, &range, text_x, top, metrics)
                    .or_else(|| {
                        // An empty range at a line's end still gets a short mark.
                        let line_range = self.buffer.line_range(layout.line);
                        (range.start == line_range.end).then(|| {
                            let x = text_x + layout.galley.size().x;
                            Rect::from_min_size(
                                pos2(x, top),
                                vec2(metrics.char_width, metrics.row_height),
                            )
                        })
                    });
                if let Some(area) = area {
                    wavy_line(painter, area.min.x, area.max.x, area.max.y - 2.0, color);
                }
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn paint_gutter(
        &mut self,
        painter: &Painter,
        layouts: &[LineLayout],
        clip: Rect,
        row_top: &dyn Fn(usize) -> f32,
        metrics: &Metrics,
        font: &FontId,
        visuals: &egui::Visuals,
    ) {
        let gutter = Rect::from_min_size(clip.min, vec2(metrics.gutter_width, clip.height()));
        painter.rect_filled(gutter, 0.0, visuals.panel_fill);
        let Some(first) = layouts.first() else {
            return;
        };
        let last_line = layouts.last().map_or(first.line, |layout| layout.line);
        let folds = self
            .syntax
            .folds_starting_in(&self.buffer, first.line..last_line + 1);
        let number_right = clip.min.x + metrics.gutter_width - metrics.char_width * 1.5;
        for layout in layouts {
            let top = row_top(layout.row);
            painter.text(
                pos2(number_right, top),
                egui::Align2::RIGHT_TOP,
                (layout.line + 1).to_string(),
                font.clone(),
                visuals.weak_text_color(),
            );
            let foldable = folds.iter().any(|(start, _)| *start == layout.line);
            if foldable {
                let marker = if self.folding.is_folded_at(layout.line) {
                    "+"
                } else {
                    "−"
                };
                painter.text(
                    pos2(number_right + metrics.char_width * 0.3, top),
                    egui::Align2::LEFT_TOP,
                    marker,
                    font.clone(),
                    visuals.weak_text_color(),
                );
            }
            let line_range = self.buffer.line_range(layout.line);
            let worst = self
                .diagnostics
                .iter()
                .filter(|diagnostic| {
                    diagnostic.range.start >= line_range.start
                        && diagnostic.range.start <= line_range.end
                })
                .map(|diagnostic| diagnostic.severity)
                .min_by_key(|severity| match severity {
                    Severity::Error => 0,
                    Severity::Warning => 1,
                    Severity::Info => 2,
                });
            if let Some(severity) = worst {
                let center = pos2(
                    clip.min.x + metrics.char_width * 0.6,
                    top + metrics.row_height * 0.5,
                );
                painter.circle_filled(center, metrics.char_width * 0.35, severity_color(severity));
            }
        }
    }

    /// Clicks, drags and double-clicks in the text and the gutter.
    #[allow(clippy::too_many_arguments)]
    fn pointer(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        layouts: &[LineLayout],
        origin: Pos2,
        clip: Rect,
        metrics: &Metrics,
        font: &FontId,
    ) {
        let Some(pos) = response.interact_pointer_pos() else {
            return;
        };
        let pressed = response.clicked() || response.drag_started();
        let in_gutter = pos.x < clip.min.x + metrics.gutter_width;
        let line_count = self.buffer.line_count();
        let row_count = self.folding.row_count(line_count).max(1);
        let row = (((pos.y - origin.y) / metrics.row_height).floor().max(0.0) as usize)
            .min(row_count - 1);
        let line = self.folding.line_of_row(row, line_count);
        if in_gutter {
            if response.clicked() {
                self.toggle_fold(line);
            }
            return;
        }
        let x = pos.x - origin.x - metrics.text_left;
        let layout = layouts.iter().find(|layout| layout.line == line);
        if pressed && let Some(layout) = layout {
            for (col, width, index) in &layout.boxes {
                let x0 = layout.x_of_col(*col);
                let x1 = x0 + *width as f32 * metrics.char_width;
                if (x0..x1).contains(&x)
                    && let Some(value) = self.inline_values.get(*index)
                {
                    self.value_editor = Some((value.range.clone(), String::new()));
                    return;
                }
            }
        }
        let col = match layout {
            Some(layout) => layout.column(
                layout
                    .galley
                    .cursor_from_pos(vec2(x, metrics.row_height * 0.5))
                    .index
                    .0,
            ),
            None => {
                let galley = self.line_galley(ui, line, &[], &[], font, true, Color32::WHITE);
                galley
                    .cursor_from_pos(vec2(x, metrics.row_height * 0.5))
                    .index
                    .0
            }
        };
        let offset = self.buffer.offset_of(line, col);
        let shift = ui.input(|input| input.modifiers.shift);
        if response.double_clicked() {
            let word = self.word_at(offset);
            self.anchor = word.start;
            self.caret = word.end;
        } else if pressed {
            self.caret = offset;
            if !shift {
                self.anchor = offset;
            }
        } else if response.dragged() {
            self.caret = offset;
        }
        self.typing_end = None;
        self.preferred_column = None;
        self.completion = None;
    }

    /// The small field where a value is prepared for an inline value.
    fn value_editor_ui(&mut self, ui: &Ui, id: egui::Id, result: &mut FrameResult) {
        let Some((range, mut text)) = self.value_editor.take() else {
            return;
        };
        let label = self.texts.prepared_value.clone();
        let position = ui
            .ctx()
            .pointer_latest_pos()
            .unwrap_or(ui.clip_rect().center());
        let field_id = id.with("prepared_value");
        let anchor = ui
            .memory(|memory| memory.data.get_temp::<Pos2>(field_id))
            .unwrap_or(position);
        ui.memory_mut(|memory| memory.data.insert_temp(field_id, anchor));
        let mut keep = true;
        egui::Area::new(field_id)
            .order(egui::Order::Foreground)
            .fixed_pos(anchor + vec2(0.0, 12.0))
            .show(ui.ctx(), |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.horizontal(|ui| {
                        let name = ui.label(label.as_str());
                        let field = ui
                            .add(
                                egui::TextEdit::singleline(&mut text)
                                    .id(field_id.with("field"))
                                    .desired_width(120.0),
                            )
                            .labelled_by(name.id);
                        if !field.has_focus() && !field.lost_focus() {
                            field.request_focus();
                        }
                        let (enter, escape) = ui.input(|input| {
                            (
                                input.key_pressed(egui::Key::Enter),
                                input.key_pressed(egui::Key::Escape),
                            )
                        });
                        if field.lost_focus() && enter {
                            result.prepared = Some((range.clone(), text.clone()));
                            keep = false;
                        } else if escape || (field.lost_focus() && !enter) {
                            keep = false;
                        }
                    });
                });
            });
        if keep {
            self.value_editor = Some((range, text));
        } else {
            ui.memory_mut(|memory| memory.data.remove::<Pos2>(field_id));
            self.focus_requested = true;
        }
    }

    /// Diagnostics and the services' hover text for the word under a resting pointer.
    fn hover_ui(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        layouts: &[LineLayout],
        origin: Pos2,
        metrics: &Metrics,
        services: &dyn LanguageServices,
    ) {
        let Some(pos) = response.hover_pos() else {
            return;
        };
        let rest = ui.input(|input| input.pointer.time_since_last_movement());
        if rest < HOVER_DELAY_S {
            ui.ctx().request_repaint_after_secs(HOVER_DELAY_S - rest);
            return;
        }
        let row = ((pos.y - origin.y) / metrics.row_height).floor().max(0.0) as usize;
        let Some(layout) = layouts.iter().find(|layout| layout.row == row) else {
            return;
        };
        let x = pos.x - origin.x - metrics.text_left;
        if x < 0.0 || x > layout.galley.size().x {
            return;
        }
        let col = layout.column(
            layout
                .galley
                .cursor_from_pos(vec2(x, metrics.row_height * 0.5))
                .index
                .0,
        );
        let offset = self.buffer.offset_of(layout.line, col);
        let mut text: Option<String> = self
            .diagnostics
            .iter()
            .filter(|diagnostic| {
                diagnostic.range.contains(&offset) || diagnostic.range.start == offset
            })
            .map(|diagnostic| format!("{}: {}", diagnostic.code, diagnostic.message))
            .reduce(|all, one| format!("{all}\n{one}"));
        if text.is_none() {
            let word = self.word_at(offset);
            let is_name = self.buffer.text()[word.clone()]
                .chars()
                .next()
                .is_some_and(|c| c.is_alphabetic() || c == '_');
            if is_name {
                let cached = self
                    .hover
                    .as_ref()
                    .filter(|(revision, at, _)| *revision == self.revision && *at == word.start)
                    .map(|(_, _, text)| text.clone());
                text = cached.unwrap_or_else(|| {
                    let answer = services.hover(self.buffer.text(), offset);
                    self.hover = Some((self.revision, word.start, answer.clone()));
                    answer
                });
            }
        }
        if let Some(text) = text {
            egui::Area::new(response.id.with("hover"))
                .order(egui::Order::Tooltip)
                .fixed_pos(pos + vec2(12.0, 16.0))
                .interactable(false)
                .show(ui.ctx(), |ui| {
                    egui::Frame::popup(ui.style()).show(ui, |ui| {
                        ui.set_max_width(480.0);
                        ui.label(text);
                    });
                });
        }
    }
}

fn severity_color(severity: Severity) -> Color32 {
    match severity {
        Severity::Error => Color32::from_rgb(230, 60, 60),
        Severity::Warning => Color32::from_rgb(220, 180, 40),
        Severity::Info => Color32::from_rgb(80, 150, 230),
    }
}

/// A zigzag line from `x0` to `x1` at height `y`, the usual mark of a diagnostic.
fn wavy_line(painter: &Painter, x0: f32, x1: f32, y: f32, color: Color32) {
    let step = 2.0;
    let mut points = Vec::new();
    let mut x = x0;
    let mut up = true;
    while x <= x1 {
        points.push(pos2(x, if up { y - 1.5 } else { y + 1.0 }));
        x += step;
        up = !up;
    }
    if points.len() >= 2 {
        painter.add(egui::Shape::line(points, Stroke::new(1.0, color)));
    }
}
