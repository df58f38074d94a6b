//! Find and replace: the bar above the text, the matches and the replacements.

use std::ops::Range;

use egui::{Key, Ui};

use super::editing::is_word_char;
use super::input::FrameResult;
use super::{StEditor, TextChange};

/// The state of the find bar; lives as long as the editor, not saved.
#[derive(Clone, Debug, Default)]
pub struct FindBar {
    /// Whether the bar is shown.
    pub open: bool,
    /// The searched text.
    pub query: String,
    /// The replacement text.
    pub replacement: String,
    /// Whether letter case must match.
    pub match_case: bool,
    /// Whether only whole identifiers match.
    pub whole_word: bool,
    /// Set when the find field must take focus at the next frame.
    focus_query: bool,
    /// The matches of the query, start to end.
    matches: Vec<Range<usize>>,
    /// The text revision, query and options `matches` was computed for.
    matches_key: Option<(u64, String, bool, bool)>,
}

/// Every match of `query` in `text`; case-insensitive matching folds ASCII letters only, so
/// byte offsets are the same in the folded text.
pub fn find_matches(
    text: &str,
    query: &str,
    match_case: bool,
    whole_word: bool,
) -> Vec<Range<usize>> {
    if query.is_empty() {
        return Vec::new();
    }
    let (haystack, needle) = if match_case {
        (text.to_owned(), query.to_owned())
    } else {
        (text.to_ascii_lowercase(), query.to_ascii_lowercase())
    };
    haystack
        .match_indices(&needle)
        .map(|(at, found)| at..at + found.len())
        .filter(|range| {
            !whole_word
                || (!text[..range.start]
                    .chars()
                    .next_back()
                    .is_some_and(is_word_char)
                    && !text[range.end..].chars().next().is_some_and(is_word_char))
        })
        .collect()
}

impl StEditor {
    /// Opens the find bar, with the selection as the query when it is on one line.
    pub(super) fn open_find(&mut self) {
        let selection = self.selection();
        let selected = &self.buffer.text()[selection];
        if !selected.is_empty() && !selected.contains('\n') {
            selected.clone_into(&mut self.find.query);
        }
        self.find.open = true;
        self.find.focus_query = true;
    }

    /// Sets the search options, opening the bar (for the app and tests).
    pub fn set_find(&mut self, query: &str, replacement: &str, match_case: bool, whole_word: bool) {
        self.find.open = true;
        query.clone_into(&mut self.find.query);
        replacement.clone_into(&mut self.find.replacement);
        self.find.match_case = match_case;
        self.find.whole_word = whole_word;
    }

    /// The matches of the find bar's query in the current text.
    pub(super) fn matches(&mut self) -> &[Range<usize>] {
        let key = (
            self.revision,
            self.find.query.clone(),
            self.find.match_case,
            self.find.whole_word,
        );
        if self.find.matches_key.as_ref() != Some(&key) {
            self.find.matches = find_matches(
                self.buffer.text(),
                &self.find.query,
                self.find.match_case,
                self.find.whole_word,
            );
            self.find.matches_key = Some(key);
        }
        &self.find.matches
    }

    /// Selects the next (or previous) match after (or before) the caret and reveals it.
    pub(super) fn find_next(&mut self, forward: bool) {
        let selection = self.selection();
        let matches = self.matches();
        let found = if forward {
            matches
                .iter()
                .find(|range| range.start >= selection.end && *range != &selection)
                .or(matches.first())
        } else {
            matches
                .iter()
                .rev()
                .find(|range| range.end <= selection.start)
                .or(matches.last())
        };
        if let Some(range) = found.cloned() {
            self.reveal(range);
        }
    }

    /// Replaces every match with the replacement, as one change list from the end of the
    /// text to its start.
    pub fn replace_all(&mut self) -> Vec<TextChange> {
        let mut changes = Vec::new();
        if self.read_only {
            return changes;
        }
        let matches = self.matches().to_vec();
        let replacement = self.find.replacement.clone();
        for range in matches.into_iter().rev() {
            self.replace(range, &replacement, &mut changes);
        }
        self.anchor = self.buffer.clamp(self.anchor);
        self.caret = self.buffer.clamp(self.caret);
        changes
    }

    /// Replaces the selected match and selects the next one.
    fn replace_current(&mut self, result: &mut FrameResult) {
        let selection = self.selection();
        if self.matches().contains(&selection) && !self.read_only {
            let replacement = self.find.replacement.clone();
            self.replace_selection(&replacement, &mut result.changes);
            result.other = true;
            self.typing_end = None;
        }
        self.find_next(true);
    }

    /// Draws the find bar; returns whether the editor should take focus back.
    pub(super) fn find_bar_ui(&mut self, ui: &mut Ui, result: &mut FrameResult) -> bool {
        if !self.find.open {
            return false;
        }
        let texts = self.texts.clone();
        let mut focus_editor = false;
        ui.horizontal_wrapped(|ui| {
            let find_label = ui.label(texts.find.as_str());
            let query = ui
                .add(egui::TextEdit::singleline(&mut self.find.query).desired_width(160.0))
                .labelled_by(find_label.id);
            if std::mem::take(&mut self.find.focus_query) {
                query.request_focus();
            }
            if query.changed() {
                // Find as you type: the first match from the start of the selection.
                let start = self.selection().start;
                self.anchor = start;
                self.caret = start;
                self.find_next(true);
            }
            let replace_label = ui.label(texts.replace.as_str());
            let replace = ui
                .add(egui::TextEdit::singleline(&mut self.find.replacement).desired_width(160.0))
                .labelled_by(replace_label.id);
            ui.checkbox(&mut self.find.match_case, texts.match_case.as_str());
            ui.checkbox(&mut self.find.whole_word, texts.whole_word.as_str());
            let count = self.matches().len();
            ui.label(format!("{count}"));
            if ui.button(texts.previous.as_str()).clicked() {
                self.find_next(false);
            }
            if ui.button(texts.next.as_str()).clicked() {
                self.find_next(true);
            }
            if ui.button(texts.replace_one.as_str()).clicked() {
                self.replace_current(result);
            }
            if ui.button(texts.replace_all.as_str()).clicked() {
                let changes = self.replace_all();
                if !changes.is_empty() {
                    result.changes.extend(changes);
                    result.other = true;
                    self.typing_end = None;
                }
            }
            let close = ui.button(texts.close.as_str()).clicked();
            let in_bar = query.has_focus()
                || query.lost_focus()
                || replace.has_focus()
                || replace.lost_focus();
            let (enter, shift, escape, f3) = ui.input(|input| {
                (
                    input.key_pressed(Key::Enter),
                    input.modifiers.shift,
                    input.key_pressed(Key::Escape),
                    input.key_pressed(Key::F3),
                )
            });
            if in_bar && (enter || f3) {
                self.find_next(!shift);
                query.request_focus();
            }
            if close || (in_bar && escape) {
                self.find.open = false;
                focus_editor = true;
            }
        });
        focus_editor
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_word_matching_skips_longer_names() {
        let text = "x := x1 + X; max := x;";
        assert_eq!(
            find_matches(text, "x", false, true),
            vec![0..1, 10..11, 20..21]
        );
        assert_eq!(find_matches(text, "x", true, true), vec![0..1, 20..21]);
        assert_eq!(find_matches(text, "x", true, false).len(), 4);
        assert!(find_matches("计数 x", "", false, false).is_empty());
    }
}
