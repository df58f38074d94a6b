//! Keyboard and clipboard input: egui events turned into caret moves and text changes.

use egui::{Event, ImeEvent, Key, Modifiers};

use super::editing::{INDENT, is_word_char};
use super::{Gesture, LanguageServices, StEditor, TextChange};

/// What the events of one frame produced.
#[derive(Debug, Default)]
pub(super) struct FrameResult {
    /// The changes, in the order they were made.
    pub changes: Vec<TextChange>,
    /// Whether a change other than typing happened.
    pub other: bool,
    /// F12 at this offset.
    pub goto_definition: Option<usize>,
    /// Shift+F12 at this offset.
    pub find_references: Option<usize>,
    /// A value prepared in an inline value box.
    pub prepared: Option<(std::ops::Range<usize>, String)>,
    /// F9 or a click in the breakpoint column on this line (from 0).
    pub toggle_breakpoint: Option<usize>,
}

impl FrameResult {
    /// The gesture of the frame's changes.
    pub fn gesture(&self, typing_run: u64) -> Option<Gesture> {
        if self.changes.is_empty() {
            None
        } else if self.other {
            Some(Gesture::Other)
        } else {
            Some(Gesture::Typing { run: typing_run })
        }
    }
}

impl StEditor {
    /// Handles the events of a frame while the editor has keyboard focus.
    pub(super) fn handle_events(
        &mut self,
        ctx: &egui::Context,
        events: &[Event],
        services: &dyn LanguageServices,
        result: &mut FrameResult,
    ) {
        // Some platforms send the space of Ctrl+Space as text too; it must not be typed.
        let mut after_ctrl_space = false;
        for event in events {
            match event {
                Event::Text(text) if after_ctrl_space && text == " " => {}
                Event::Text(text) => self.type_text(text, services, result),
                // Text composed with an input method (Chinese, Japanese …) arrives committed.
                Event::Ime(ImeEvent::Commit(text)) => {
                    self.preedit.clear();
                    self.type_text(text, services, result);
                }
                // The text being composed is shown at the caret until it is committed.
                Event::Ime(ImeEvent::Preedit { text, .. }) if !self.read_only => {
                    text.clone_into(&mut self.preedit);
                }
                Event::Key {
                    key,
                    pressed: true,
                    modifiers,
                    ..
                } => {
                    after_ctrl_space = *key == Key::Space && (modifiers.ctrl || modifiers.command);
                    self.key(*key, *modifiers, services, result);
                    continue;
                }
                Event::Copy => self.copy(ctx),
                Event::Cut => {
                    self.copy(ctx);
                    if !self.selection().is_empty() {
                        self.edit_other(result, |editor, changes| {
                            editor.replace_selection("", changes);
                        });
                    }
                }
                Event::Paste(text) => {
                    let text = text.replace("\r\n", "\n");
                    self.edit_other(result, |editor, changes| {
                        editor.replace_selection(&text, changes);
                    });
                }
                _ => {}
            }
            after_ctrl_space = false;
        }
        let caret_line = self.buffer.line_of(self.caret);
        if self.folding.is_hidden(caret_line) {
            self.folding.unfold_line(caret_line);
        }
        self.update_completion();
    }

    /// Runs an edit that is its own undo step.
    fn edit_other(
        &mut self,
        result: &mut FrameResult,
        edit: impl FnOnce(&mut Self, &mut Vec<TextChange>),
    ) {
        if self.read_only {
            return;
        }
        let before = result.changes.len();
        edit(self, &mut result.changes);
        if result.changes.len() > before {
            result.other = true;
            self.typing_end = None;
        }
    }

    fn type_text(&mut self, text: &str, services: &dyn LanguageServices, result: &mut FrameResult) {
        if self.read_only || text.is_empty() || text.chars().any(char::is_control) {
            return;
        }
        let typing = self.selection().is_empty() && text.chars().count() == 1;
        if !typing {
            self.edit_other(result, |editor, changes| {
                editor.replace_selection(text, changes);
            });
            return;
        }
        if self.typing_end != Some(self.caret) {
            self.typing_run += 1;
            // Changes earlier in this frame belong to another step, so the frame's changes
            // cannot be merged into one typing run.
            if !result.changes.is_empty() {
                result.other = true;
            }
        }
        let before_dot = self.prev_char(self.caret);
        let after_name = self.buffer.text()[before_dot..self.caret]
            .chars()
            .next()
            .is_some_and(|c| is_word_char(c) || c == ')' || c == ']');
        self.replace_selection(text, &mut result.changes);
        self.typing_end = Some(self.caret);
        if self.outdent_closer(&mut result.changes) {
            result.other = true;
            self.typing_end = None;
        }
        if text == "." && after_name {
            self.open_completion(services, self.caret);
        }
    }

    fn key(
        &mut self,
        key: Key,
        modifiers: Modifiers,
        services: &dyn LanguageServices,
        result: &mut FrameResult,
    ) {
        if self.completion.is_some() && self.completion_key(key, result) {
            return;
        }
        let shift = modifiers.shift;
        let command = modifiers.command;
        match key {
            Key::ArrowLeft => {
                let target = if !shift && !self.selection().is_empty() {
                    self.selection().start
                } else if command {
                    self.word_left(self.caret)
                } else {
                    self.prev_char(self.caret)
                };
                self.move_to(target, shift);
                self.preferred_column = None;
            }
            Key::ArrowRight => {
                let target = if !shift && !self.selection().is_empty() {
                    self.selection().end
                } else if command {
                    self.word_right(self.caret)
                } else {
                    self.next_char(self.caret)
                };
                self.move_to(target, shift);
                self.preferred_column = None;
            }
            Key::ArrowUp => self.move_rows(-1, shift),
            Key::ArrowDown => self.move_rows(1, shift),
            Key::PageUp => self.move_rows(-(self.page_rows as isize), shift),
            Key::PageDown => self.move_rows(self.page_rows as isize, shift),
            Key::Home if command => self.move_to(0, shift),
            Key::End if command => self.move_to(self.buffer.len(), shift),
            Key::Home => {
                let line = self.buffer.line_of(self.caret);
                let range = self.buffer.line_range(line);
                let text = self.buffer.line(line);
                let first = range.start + (text.len() - text.trim_start().len());
                let target = if self.caret == first {
                    range.start
                } else {
                    first
                };
                self.move_to(target, shift);
                self.preferred_column = None;
            }
            Key::End => {
                let line = self.buffer.line_of(self.caret);
                self.move_to(self.buffer.line_range(line).end, shift);
                self.preferred_column = None;
            }
            Key::A if command => {
                self.anchor = 0;
                self.caret = self.buffer.len();
                self.typing_end = None;
            }
            Key::F if command => self.open_find(),
            Key::Space if (modifiers.ctrl || command) && !self.read_only => {
                let start = self.word_at(self.caret).start.min(self.caret);
                self.open_completion(services, start);
            }
            Key::F12 if shift => result.find_references = Some(self.caret),
            Key::F12 => result.goto_definition = Some(self.caret),
            Key::F9 if modifiers.is_none() => {
                result.toggle_breakpoint = Some(self.buffer.line_of(self.caret));
            }
            Key::F3 => self.find_next(!shift),
            Key::Escape => self.find.open = false,
            Key::Enter if !command => {
                let text = self.newline_text();
                self.edit_other(result, |editor, changes| {
                    editor.replace_selection(&text, changes);
                });
            }
            Key::Backspace => self.edit_other(result, |editor, changes| {
                if editor.selection().is_empty() {
                    editor.anchor = if command {
                        editor.word_left(editor.caret)
                    } else {
                        editor.prev_char(editor.caret)
                    };
                }
                editor.replace_selection("", changes);
            }),
            Key::Delete => self.edit_other(result, |editor, changes| {
                if editor.selection().is_empty() {
                    editor.anchor = if command {
                        editor.word_right(editor.caret)
                    } else {
                        editor.next_char(editor.caret)
                    };
                }
                editor.replace_selection("", changes);
            }),
            Key::Tab => {
                let selection = self.selection();
                let multi_line =
                    self.buffer.line_of(selection.start) != self.buffer.line_of(selection.end);
                if shift || multi_line {
                    self.edit_other(result, |editor, changes| {
                        editor.indent_lines(shift, changes);
                    });
                } else {
                    let (_, col) = self.buffer.line_col(self.caret);
                    let width = INDENT.len() - col % INDENT.len();
                    let spaces = " ".repeat(width);
                    self.edit_other(result, |editor, changes| {
                        editor.replace_selection(&spaces, changes);
                    });
                }
            }
            // Undo and redo belong to the app's history: the editor leaves those keys alone.
            _ => {}
        }
    }

    /// Moves the caret by `rows` visible rows, keeping the column.
    fn move_rows(&mut self, rows: isize, extend: bool) {
        let line_count = self.buffer.line_count();
        let (line, col) = self.buffer.line_col(self.caret);
        let column = *self.preferred_column.get_or_insert(col);
        let row = self.folding.row_of_line(line, line_count) as isize;
        let last_row = self.folding.row_count(line_count).saturating_sub(1) as isize;
        let target_row = row + rows;
        let target = if target_row < 0 {
            0
        } else if target_row > last_row {
            self.buffer.len()
        } else {
            let target_line = self.folding.line_of_row(target_row as usize, line_count);
            self.buffer.offset_of(target_line, column)
        };
        let keep = self.preferred_column;
        self.move_to(target, extend);
        self.preferred_column = keep;
    }

    fn copy(&self, ctx: &egui::Context) {
        let selection = self.selection();
        if !selection.is_empty() {
            ctx.copy_text(self.buffer.text()[selection].to_owned());
        }
    }
}
