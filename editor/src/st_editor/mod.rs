//! The editable Structured Text editor.
//!
//! The text lives in a line-indexed buffer; only the visible lines are laid out and painted,
//! each line's galley is cached by its text and highlighting, and input is handled here rather
//! than by an egui `TextEdit`, so a 20,000-line body stays fluid. The editor keeps no undo
//! history: every change is reported to the app, which owns undo across all documents.

mod buffer;
mod completion;
mod debug_marks;
mod editing;
mod find;
mod folding;
mod galleys;
mod highlight;
mod il_highlight;
mod input;
mod layout;
mod overlays;
mod paint;
mod syntax;
mod texts;
mod types;
mod view;

use std::ops::Range;

pub use buffer::TextBuffer;
pub use debug_marks::{BreakpointLook, BreakpointMark, StDebugMarks};
pub(crate) use debug_marks::{paint_breakpoint, paint_halt_arrow};
pub use highlight::Highlight;
pub use texts::EditorTexts;
pub use types::{
    CompletionItem, CompletionKind, EditorDiagnostic, Gesture, InlineValue, KeywordCompletions,
    LanguageServices, Severity, StEditorOutput, TextChange,
};

use completion::Completion;
use find::FindBar;
use folding::Folding;
use galleys::GalleyCache;
use syntax::Syntax;

/// Texts up to this size are parsed again in the frame that changed them.
const IMMEDIATE_REPARSE_BYTES: usize = 64 * 1024;

/// How long typing must pause before a longer text is parsed again, in seconds.
const REPARSE_DELAY_S: f64 = 0.12;

/// An editor for one Structured Text (a declaration part or a body).
///
/// The app keeps one per open text and, every frame:
/// - calls [`StEditor::set_text`] with the model's text (nothing happens when it is the same;
///   after undo, redo, the variable table or a reload the editor takes the new text);
/// - calls [`StEditor::show`] with a label and its [`LanguageServices`];
/// - applies [`StEditorOutput::changes`] to its model after the frame, as one undo step per
///   [`Gesture`] (consecutive `Typing` outputs with the same run merge into one step);
/// - answers `goto_definition`, `find_references` and `prepared` from the output.
///
/// Diagnostics and inline values come from the app with [`StEditor::set_diagnostics`] and
/// [`StEditor::set_inline_values`]; until the app sends new ones they move with the edits.
pub struct StEditor {
    /// The text, the ground truth of what is shown; lives as long as the editor.
    buffer: TextBuffer,
    /// The tree-sitter tree and queries over `buffer`.
    syntax: Syntax,
    /// Whether the tree must be parsed again before it is used.
    syntax_stale: bool,
    /// The egui time of the last change, in seconds; a long text is parsed again only when
    /// typing pauses.
    last_edit_s: f64,
    /// The egui time of the last scroll over the editor, in seconds; hover waits for it to rest.
    last_scroll_s: f64,
    /// Counts changes of the text, to know when cached results are stale.
    revision: u64,
    /// The end of the selection that does not move with Shift+movement.
    anchor: usize,
    /// The caret, the moving end of the selection.
    caret: usize,
    /// The column (in chars) that vertical movement tries to keep.
    preferred_column: Option<usize>,
    /// Whether changes are refused.
    read_only: bool,
    /// The app's latest diagnostics, moved along with edits until replaced.
    diagnostics: Vec<EditorDiagnostic>,
    /// The app's latest monitored values, sorted by where their boxes go.
    inline_values: Vec<InlineValue>,
    /// The folded blocks.
    folding: Folding,
    /// The find bar's state.
    find: FindBar,
    /// The open completion popup.
    completion: Option<Completion>,
    /// Galleys of the lines shown recently.
    galleys: GalleyCache,
    /// The words of the find bar and value box.
    texts: EditorTexts,
    /// Set when the caret moved and the next frame must scroll it into view.
    scroll_to_caret: bool,
    /// Set by [`StEditor::request_focus`], honoured by the next `show`.
    focus_requested: bool,
    /// The number of the current typing run (see [`Gesture::Typing`]).
    typing_run: u64,
    /// Where the caret is after the last typed character, while a typing run goes on.
    typing_end: Option<usize>,
    /// The inline value whose prepared value is being typed, and the text typed so far.
    value_editor: Option<(Range<usize>, String)>,
    /// The last hover asked of the services: the revision, the offset of the word and the
    /// answer.
    hover: Option<(u64, usize, Option<String>)>,
    /// The number of text rows the viewport showed last frame, for Page Up and Page Down.
    page_rows: usize,
    /// The longest line in bytes and the revision it was measured at.
    widest: Option<(u64, usize)>,
    /// The first and last buffer lines shown in the last frame.
    visible: Range<usize>,
    /// The text an input method is composing, shown at the caret, not yet in the buffer.
    preedit: String,
    /// The debugger's breakpoints, halt line and flow marks, from the app.
    debug_marks: StDebugMarks,
}

impl StEditor {
    /// An editor holding `text`.
    pub fn new(text: &str) -> Self {
        Self {
            buffer: TextBuffer::new(text),
            syntax: Syntax::new(text),
            syntax_stale: false,
            last_edit_s: 0.0,
            last_scroll_s: 0.0,
            revision: 0,
            anchor: 0,
            caret: 0,
            preferred_column: None,
            read_only: false,
            diagnostics: Vec::new(),
            inline_values: Vec::new(),
            folding: Folding::default(),
            find: FindBar::default(),
            completion: None,
            galleys: GalleyCache::default(),
            texts: EditorTexts::default(),
            scroll_to_caret: false,
            focus_requested: false,
            typing_run: 0,
            typing_end: None,
            value_editor: None,
            hover: None,
            page_rows: 20,
            widest: None,
            visible: 0..0,
            preedit: String::new(),
            debug_marks: StDebugMarks::default(),
        }
    }

    /// An editor holding `text`, an Instruction List body (`docs/instruction-list.md`):
    /// highlighted by IL's own scanner (labels, operators, jump targets, functions, comments,
    /// literals); everything else is as for Structured Text.
    pub fn instruction_list(text: &str) -> Self {
        Self {
            syntax: Syntax::instruction_list(),
            ..Self::new(text)
        }
    }

    /// The text the editor holds.
    pub fn text(&self) -> &str {
        self.buffer.text()
    }

    /// Replaces the text when it differs from `text` (after undo, redo or a change made
    /// elsewhere); the selection is kept where it was, clamped to the new text.
    pub fn set_text(&mut self, text: &str) {
        if self.buffer.text() == text {
            return;
        }
        self.buffer.set_text(text);
        self.syntax.reset(text);
        self.syntax_stale = false;
        self.revision += 1;
        self.anchor = self.buffer.clamp(self.anchor);
        self.caret = self.buffer.clamp(self.caret);
        self.folding.clamp(self.buffer.line_count());
        self.completion = None;
        self.typing_end = None;
        self.value_editor = None;
    }

    /// The selected byte range, start before end; empty when nothing is selected.
    pub fn selection(&self) -> Range<usize> {
        self.anchor.min(self.caret)..self.anchor.max(self.caret)
    }

    /// The caret's byte offset.
    pub fn caret(&self) -> usize {
        self.caret
    }

    /// Selects `range` (clamped to the text), unfolds what hides it and scrolls it into view.
    pub fn reveal(&mut self, range: Range<usize>) {
        self.anchor = self.buffer.clamp(range.start);
        self.caret = self.buffer.clamp(range.end.max(range.start));
        self.folding.unfold_line(self.buffer.line_of(self.anchor));
        self.folding.unfold_line(self.buffer.line_of(self.caret));
        self.scroll_to_caret = true;
        self.typing_end = None;
    }

    /// Makes the editor take keyboard focus at the next `show`.
    pub fn request_focus(&mut self) {
        self.focus_requested = true;
    }

    /// In read-only mode the text can be navigated, selected and copied but not changed.
    pub fn set_read_only(&mut self, read_only: bool) {
        self.read_only = read_only;
        if read_only {
            self.completion = None;
        }
    }

    /// Whether the editor is read-only.
    pub fn is_read_only(&self) -> bool {
        self.read_only
    }

    /// The compiler's diagnostics for this text, shown until replaced.
    pub fn set_diagnostics(&mut self, diagnostics: Vec<EditorDiagnostic>) {
        self.diagnostics = diagnostics;
    }

    /// The monitored values to show inline; an empty list when offline.
    pub fn set_inline_values(&mut self, mut values: Vec<InlineValue>) {
        // Sorted by where the boxes go, so the boxes of a line are found by binary search.
        values.sort_by_key(|value| (value.range.end, value.range.start));
        self.inline_values = values;
    }

    /// The user-visible words of the find bar and the value box, in the app's language.
    pub fn set_texts(&mut self, texts: EditorTexts) {
        self.texts = texts;
    }

    /// Folds or unfolds the foldable block that starts on line `line` (counted from 0);
    /// returns whether there was a block there.
    pub fn toggle_fold(&mut self, line: usize) -> bool {
        self.refresh_syntax();
        let folds = self.syntax.folds_starting_in(&self.buffer, line..line + 1);
        let Some(&(first, last)) = folds.first() else {
            return false;
        };
        self.folding.toggle(first, last);
        if self.folding.is_hidden(self.buffer.line_of(self.caret)) {
            self.caret = self.buffer.line_range(first).end;
            self.anchor = self.caret;
        }
        true
    }

    /// Whether line `line` is hidden inside a folded block.
    pub fn is_line_hidden(&self, line: usize) -> bool {
        self.folding.is_hidden(line)
    }

    /// The buffer lines the last frame showed (folded lines inside are hidden), so the app
    /// can monitor only the variables on screen.
    pub fn visible_lines(&self) -> Range<usize> {
        self.visible.clone()
    }

    /// Whether the find bar is open.
    pub fn is_find_open(&self) -> bool {
        self.find.open
    }

    /// The labels of the completion candidates the popup shows now, filtered by what was
    /// typed; empty when the popup is closed.
    pub fn completion_labels(&self) -> Vec<String> {
        self.completion
            .as_ref()
            .map(|completion| {
                completion
                    .visible()
                    .iter()
                    .map(|item| item.label.clone())
                    .collect()
            })
            .unwrap_or_default()
    }

    /// The byte ranges of the bracket or block keyword at the caret and of its partner.
    pub fn matching_pair(&mut self) -> Option<(Range<usize>, Range<usize>)> {
        self.refresh_syntax();
        self.syntax.matching_pair(self.buffer.text(), self.caret)
    }

    /// The highlighted runs of line `line`, in bytes from the line's start.
    pub fn line_highlights(&mut self, line: usize) -> Vec<(Range<usize>, Highlight)> {
        self.refresh_syntax();
        self.syntax
            .highlight_lines(&self.buffer, line..line + 1)
            .into_iter()
            .next()
            .unwrap_or_default()
    }

    /// Parses again after changes when the text is short, or when typing paused; meanwhile
    /// the edited old tree keeps highlighting (its ranges follow the edits). Parsing a
    /// 20,000-line text again takes a few milliseconds, too long for every keystroke.
    fn refresh_syntax_when_idle(&mut self, ctx: &egui::Context, now_s: f64) {
        if !self.syntax_stale {
            return;
        }
        let idle_s = now_s - self.last_edit_s;
        if self.buffer.len() <= IMMEDIATE_REPARSE_BYTES || idle_s >= REPARSE_DELAY_S {
            self.refresh_syntax();
        } else {
            ctx.request_repaint_after_secs((REPARSE_DELAY_S - idle_s) as f32);
        }
    }

    /// Parses again after changes, once, before the tree is used.
    fn refresh_syntax(&mut self) {
        if self.syntax_stale {
            self.syntax.reparse(self.buffer.text(), true);
            self.syntax_stale = false;
        }
    }
}

#[cfg(test)]
mod random_tests;
#[cfg(test)]
mod tests;
