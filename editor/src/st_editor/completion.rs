//! The completion popup: candidates from the services, filtered by the word being typed.

use egui::{Key, Pos2};

use super::editing::is_word_char;
use super::input::FrameResult;
use super::{CompletionItem, CompletionKind, LanguageServices, StEditor};

/// The most rows the popup shows at once.
const VISIBLE_ROWS: usize = 12;

/// An open completion popup.
#[derive(Clone, Debug)]
pub struct Completion {
    /// Where the completed word starts; the accepted label replaces `start..caret`.
    start: usize,
    /// Every candidate the services gave.
    items: Vec<CompletionItem>,
    /// Indexes into `items` of the candidates matching the typed prefix.
    filtered: Vec<usize>,
    /// Index into `filtered` of the highlighted candidate.
    selected: usize,
}

impl Completion {
    fn new(start: usize, items: Vec<CompletionItem>) -> Self {
        let mut completion = Self {
            start,
            items,
            filtered: Vec::new(),
            selected: 0,
        };
        completion.filter("");
        completion
    }

    /// The candidates matching the typed prefix: those starting with it first, then those
    /// containing it, case-insensitively.
    fn filter(&mut self, prefix: &str) {
        let prefix = prefix.to_lowercase();
        let mut starts = Vec::new();
        let mut contains = Vec::new();
        for (index, item) in self.items.iter().enumerate() {
            let label = item.label.to_lowercase();
            if label.starts_with(&prefix) {
                starts.push(index);
            } else if label.contains(&prefix) {
                contains.push(index);
            }
        }
        starts.extend(contains);
        self.filtered = starts;
        self.selected = self.selected.min(self.filtered.len().saturating_sub(1));
    }

    /// The candidates shown now.
    pub fn visible(&self) -> Vec<&CompletionItem> {
        self.filtered
            .iter()
            .filter_map(|&index| self.items.get(index))
            .collect()
    }

    fn selected_item(&self) -> Option<&CompletionItem> {
        self.filtered
            .get(self.selected)
            .and_then(|&index| self.items.get(index))
    }
}

impl StEditor {
    /// Asks the services for candidates and opens the popup for a word starting at `start`.
    pub(super) fn open_completion(&mut self, services: &dyn LanguageServices, start: usize) {
        let items = services.completions(self.buffer.text(), self.caret);
        self.completion = (!items.is_empty()).then(|| Completion::new(start, items));
        self.update_completion();
    }

    /// Filters by the word typed since the popup opened, or closes it when the caret left
    /// the word.
    pub(super) fn update_completion(&mut self) {
        let selection_empty = self.selection().is_empty();
        let Some(completion) = self.completion.as_mut() else {
            return;
        };
        let text = self.buffer.text();
        let valid = completion.start <= self.caret
            && self.caret <= text.len()
            && text.is_char_boundary(completion.start)
            && text.is_char_boundary(self.caret)
            && selection_empty;
        let prefix = if valid {
            &text[completion.start..self.caret]
        } else {
            "\u{0}"
        };
        if !prefix.chars().all(is_word_char) {
            self.completion = None;
            return;
        }
        completion.filter(prefix);
        if completion.filtered.is_empty() {
            self.completion = None;
        }
    }

    /// Handles a key while the popup is open; returns whether the popup used it.
    pub(super) fn completion_key(&mut self, key: Key, result: &mut FrameResult) -> bool {
        let Some(completion) = self.completion.as_mut() else {
            return false;
        };
        match key {
            Key::ArrowDown => {
                completion.selected =
                    (completion.selected + 1).min(completion.filtered.len().saturating_sub(1));
            }
            Key::ArrowUp => completion.selected = completion.selected.saturating_sub(1),
            Key::Escape => self.completion = None,
            Key::Enter | Key::Tab => {
                self.accept_completion(result);
            }
            _ => return false,
        }
        true
    }

    /// Replaces the typed prefix with the selected candidate.
    fn accept_completion(&mut self, result: &mut FrameResult) {
        let Some(completion) = self.completion.take() else {
            return;
        };
        let Some(item) = completion.selected_item() else {
            return;
        };
        let label = item.label.clone();
        self.anchor = completion.start.min(self.caret);
        let before = result.changes.len();
        self.replace_selection(&label, &mut result.changes);
        if result.changes.len() > before {
            result.other = true;
            self.typing_end = None;
        }
    }

    /// Draws the popup below the caret at `caret_bottom` (screen coordinates).
    pub(super) fn completion_ui(
        &mut self,
        ctx: &egui::Context,
        id: egui::Id,
        caret_bottom: Pos2,
        result: &mut FrameResult,
    ) {
        let Some(completion) = self.completion.as_ref() else {
            return;
        };
        let first = completion
            .selected
            .saturating_sub(VISIBLE_ROWS - 1)
            .min(completion.filtered.len().saturating_sub(VISIBLE_ROWS));
        let mut clicked = None;
        egui::Area::new(id.with("completion"))
            .order(egui::Order::Foreground)
            .fixed_pos(caret_bottom)
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.set_min_width(180.0);
                    for (row, &index) in completion
                        .filtered
                        .iter()
                        .enumerate()
                        .skip(first)
                        .take(VISIBLE_ROWS)
                    {
                        let Some(item) = completion.items.get(index) else {
                            continue;
                        };
                        let text = format!(
                            "{}  {}  {}",
                            kind_letter(item.kind),
                            item.label,
                            item.detail
                        );
                        let label = egui::RichText::new(text.trim_end()).monospace();
                        if ui
                            .selectable_label(row == completion.selected, label)
                            .clicked()
                        {
                            clicked = Some(row);
                        }
                    }
                });
            });
        if let Some(row) = clicked {
            if let Some(completion) = self.completion.as_mut() {
                completion.selected = row;
            }
            self.accept_completion(result);
        }
    }
}

/// A one-letter mark of the candidate's kind.
fn kind_letter(kind: CompletionKind) -> char {
    match kind {
        CompletionKind::Variable => 'v',
        CompletionKind::Member => 'm',
        CompletionKind::Function => 'f',
        CompletionKind::FunctionBlock => 'b',
        CompletionKind::Keyword => 'k',
        CompletionKind::Type => 't',
        CompletionKind::Other => '·',
    }
}
