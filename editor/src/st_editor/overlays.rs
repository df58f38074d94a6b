//! The small windows over the text: the prepared value field and the hover information.

use egui::{Pos2, Ui, vec2};

use super::input::FrameResult;
use super::layout::{LineLayout, Metrics};
use super::{LanguageServices, StEditor};

/// How long the pointer must rest before hover information shows, in seconds.
const HOVER_DELAY_S: f32 = 0.4;

impl StEditor {
    /// The small field where a value is prepared for an inline value.
    pub(super) fn value_editor_ui(&mut self, ui: &Ui, id: egui::Id, result: &mut FrameResult) {
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
    pub(super) fn hover_ui(
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
        // Asking the services can cost a check of the whole body, so it waits until the
        // pointer, the view and the text have all rested: never on every frame of a scroll or
        // of typing.
        let (now_s, scrolling) = ui.input(|input| {
            let wheel = input
                .raw
                .events
                .iter()
                .any(|event| matches!(event, egui::Event::MouseWheel { .. }));
            (
                input.time,
                wheel || input.smooth_scroll_delta != egui::Vec2::ZERO,
            )
        });
        if scrolling {
            self.last_scroll_s = now_s;
        }
        let moved = ui.input(|input| input.pointer.time_since_last_movement());
        let rest = moved
            .min((now_s - self.last_scroll_s) as f32)
            .min((now_s - self.last_edit_s) as f32);
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
