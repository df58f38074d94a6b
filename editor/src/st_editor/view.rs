//! Showing the editor: the frame's order of input, layout and painting, and the pointer.

use std::ops::Range;

use egui::{
    EventFilter, FontId, Pos2, Rect, Role, Sense, Stroke, TextStyle, Ui, Vec2, WidgetInfo, pos2,
    vec2,
};

use super::input::FrameResult;
use super::layout::{LineLayout, Metrics};
use super::{LanguageServices, StEditor, StEditorOutput};

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
        let now_s = ui.input(|input| input.time);
        if !result.changes.is_empty() {
            self.last_edit_s = now_s;
        }
        self.refresh_syntax_when_idle(ui.ctx(), now_s);
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
            toggle_breakpoint: result.toggle_breakpoint,
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn text_area_ui(
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
        // Screen readers (and UI tests) read the text as the widget's value, as egui's own
        // text edits expose theirs; egui asks only while accessibility is on.
        let buffer = &self.buffer;
        response.widget_info(|| {
            let mut info = WidgetInfo::labeled(Role::MultilineTextInput, enabled, &label_text);
            info.current_text_value = Some(buffer.text().to_owned());
            info
        });
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
        self.visible = match (layouts.first(), layouts.last()) {
            (Some(first), Some(last)) => first.line..last.line + 1,
            _ => 0..0,
        };
        let text_x = origin.x + metrics.text_left;
        let row_top = |row: usize| origin.y + row as f32 * metrics.row_height;
        let clip = ui.clip_rect();

        self.pointer(ui, &response, &layouts, origin, clip, metrics, font, result);

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
        let find_color = crate::EditorPalette::of(ui).find_match;
        self.paint_halt_line(&painter, &layouts, clip, &row_top, metrics);
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
            if !self.preedit.is_empty() {
                // The composition is drawn over the text after the caret, underlined, the way
                // input methods expect; it becomes text only when committed.
                let galley = painter.layout_no_wrap(
                    self.preedit.clone(),
                    font.clone(),
                    visuals.text_color(),
                );
                let area = Rect::from_min_size(pos2(x, top), galley.size());
                painter.rect_filled(area, 0.0, visuals.extreme_bg_color);
                painter.galley(area.min, galley, visuals.text_color());
                painter.line_segment(
                    [area.left_bottom(), area.right_bottom()],
                    Stroke::new(1.0, visuals.text_color()),
                );
            }
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
            let mut target = caret_rect.expand2(margin);
            // A caret in a line's indentation (a statement revealed at its start) scrolls the
            // view fully left, so the line reads from its first column beside the gutter.
            let line = self.buffer.line(caret_line);
            let indent_bytes = line.len() - line.trim_start().len();
            if self.caret <= self.buffer.line_range(caret_line).start + indent_bytes {
                target.min.x = origin.x;
            }
            ui.scroll_to_rect(target, None);
        }
        if focused {
            // Tells the platform where the caret is, so an input method's window opens there.
            ui.output_mut(|output| {
                output.ime = Some(egui::output::IMEOutput {
                    purpose: egui::IMEPurpose::Normal,
                    rect: clip,
                    cursor_rect: caret_rect,
                    should_interrupt_composition: false,
                });
            });
            self.completion_ui(ui.ctx(), id, caret_rect.left_bottom(), result);
        }
        self.value_editor_ui(ui, id, result);
        self.hover_ui(ui, &response, &layouts, origin, metrics, services);
        response
    }

    /// Clicks, drags and double-clicks in the text and the gutter.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn pointer(
        &mut self,
        ui: &Ui,
        response: &egui::Response,
        layouts: &[LineLayout],
        origin: Pos2,
        clip: Rect,
        metrics: &Metrics,
        font: &FontId,
        result: &mut FrameResult,
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
            let in_breakpoints = pos.x
                < clip.min.x + metrics.char_width * super::debug_marks::BREAKPOINT_COLUMN_CHARS;
            if response.clicked() {
                if in_breakpoints {
                    result.toggle_breakpoint = Some(line);
                } else {
                    self.toggle_fold(line);
                }
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
        let offset = self.offset_at(ui, pos, layouts, origin, metrics, font);
        let shift = ui.input(|input| input.modifiers.shift);
        if response.double_clicked() {
            let word = self.word_at(offset);
            self.anchor = word.start;
            self.caret = word.end;
        } else if pressed {
            self.caret = offset;
            if !shift {
                // A drag is recognised only after the pointer moved: it starts where the
                // button went down.
                let origin_pos = ui.input(|input| input.pointer.press_origin());
                self.anchor = match origin_pos {
                    Some(down) if response.drag_started() => {
                        self.offset_at(ui, down, layouts, origin, metrics, font)
                    }
                    _ => offset,
                };
            }
        } else if response.dragged() {
            self.caret = offset;
            // Dragging past the edge scrolls the text along with the caret.
            self.scroll_to_caret = true;
        }
        self.typing_end = None;
        self.preferred_column = None;
        self.completion = None;
    }

    /// The text offset under screen position `pos`.
    #[allow(clippy::too_many_arguments)]
    fn offset_at(
        &mut self,
        ui: &Ui,
        pos: Pos2,
        layouts: &[LineLayout],
        origin: Pos2,
        metrics: &Metrics,
        font: &FontId,
    ) -> usize {
        let line_count = self.buffer.line_count();
        let row_count = self.folding.row_count(line_count).max(1);
        let row = (((pos.y - origin.y) / metrics.row_height).floor().max(0.0) as usize)
            .min(row_count - 1);
        let line = self.folding.line_of_row(row, line_count);
        let x = pos.x - origin.x - metrics.text_left;
        let target = vec2(x, metrics.row_height * 0.5);
        let col = match layouts.iter().find(|layout| layout.line == line) {
            Some(layout) => layout.column(layout.galley.cursor_from_pos(target).index.0),
            None => {
                // A line outside the laid-out rows (a drag past the edge): its plain galley
                // has the same geometry.
                // Only the geometry is used, so any colours do.
                let colors = crate::EditorPalette::of(ui).syntax;
                let plain = ui.visuals().text_color();
                let galley = self.line_galley(ui, line, &[], &[], font, &colors, plain);
                galley.cursor_from_pos(target).index.0
            }
        };
        self.buffer.offset_of(line, col)
    }
}
