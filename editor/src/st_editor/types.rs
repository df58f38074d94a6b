//! The plain data the editor exchanges with the app: changes, diagnostics, inline values,
//! completion candidates and the language services the app provides.

use std::ops::Range;

/// One replacement in the text: `range` (bytes of the text as it is just before this change)
/// becomes `text`. An insertion has an empty range, a deletion an empty text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TextChange {
    /// The replaced bytes, in the text before this change.
    pub range: Range<usize>,
    /// The new text.
    pub text: String,
}

impl TextChange {
    /// Applies a list of changes, one after the other, to `text`; ranges are clamped to char
    /// boundaries, so a stale change cannot panic.
    pub fn apply_all(text: &mut String, changes: &[TextChange]) {
        for change in changes {
            let mut start = change.range.start.min(text.len());
            while !text.is_char_boundary(start) {
                start -= 1;
            }
            let mut end = change.range.end.clamp(start, text.len());
            while !text.is_char_boundary(end) {
                end -= 1;
            }
            text.replace_range(start..end, &change.text);
        }
    }
}

/// What kind of user action produced the changes of a frame, so the app can make one undo
/// step of one gesture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Gesture {
    /// Characters typed one after another at the caret on one line. Outputs with the same
    /// `run` belong to one undo step; a new run starts when the caret moves elsewhere, the
    /// line changes or another gesture happens.
    Typing {
        /// The number of the typing run.
        run: u64,
    },
    /// Anything else (Enter, deletion, paste, cut, indent, replace, completion): one undo
    /// step of its own.
    Other,
}

/// How serious a diagnostic is; decides the underline colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    /// The text does not compile.
    Error,
    /// The text compiles but is suspicious.
    Warning,
    /// A note.
    Info,
}

/// A compiler diagnostic placed in the editor's text; the app converts the compiler's
/// diagnostics into these.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EditorDiagnostic {
    /// The bytes the diagnostic is about.
    pub range: Range<usize>,
    /// Error, warning or note.
    pub severity: Severity,
    /// The stable diagnostic code, such as `E0104`.
    pub code: String,
    /// The message shown on hover.
    pub message: String,
}

/// A monitored value shown after a variable's name while online.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InlineValue {
    /// The variable's name in the text; the box is drawn after it.
    pub range: Range<usize>,
    /// The value as text.
    pub text: String,
    /// Whether the value changed recently, shown with a distinct background.
    pub changed: bool,
    /// Whether the variable is forced, shown with a red `F` badge.
    pub forced: bool,
}

/// What a completion candidate is, for its icon letter in the list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompletionKind {
    /// A variable in scope.
    Variable,
    /// A member of a structure or block instance.
    Member,
    /// A function.
    Function,
    /// A function block type.
    FunctionBlock,
    /// A reserved word.
    Keyword,
    /// A type.
    Type,
    /// Anything else.
    Other,
}

/// A completion candidate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompletionItem {
    /// The text inserted when the candidate is accepted.
    pub label: String,
    /// What the candidate is.
    pub kind: CompletionKind,
    /// A short description shown beside the label (a type, a signature).
    pub detail: String,
}

/// The project-level services the editor asks for; the app implements them on its model and
/// compiler, tests with a fake.
pub trait LanguageServices {
    /// Candidates at byte offset `offset` of `text`, the text the editor currently holds.
    fn completions(&self, text: &str, offset: usize) -> Vec<CompletionItem>;
    /// Hover text for the identifier at byte offset `offset` of `text`.
    fn hover(&self, text: &str, offset: usize) -> Option<String>;
}

/// Services that know only the reserved words of Structured Text: keyword completion without
/// a project, and no hover.
#[derive(Clone, Copy, Debug, Default)]
pub struct KeywordCompletions;

/// The reserved words offered by [`KeywordCompletions`].
const KEYWORDS: &[&str] = &[
    "AND",
    "ARRAY",
    "BOOL",
    "BY",
    "BYTE",
    "CASE",
    "CONSTANT",
    "DINT",
    "DO",
    "DWORD",
    "ELSE",
    "ELSIF",
    "END_CASE",
    "END_FOR",
    "END_FUNCTION",
    "END_FUNCTION_BLOCK",
    "END_IF",
    "END_PROGRAM",
    "END_REPEAT",
    "END_STRUCT",
    "END_TYPE",
    "END_VAR",
    "END_WHILE",
    "EXIT",
    "FALSE",
    "FOR",
    "FUNCTION",
    "FUNCTION_BLOCK",
    "IF",
    "INT",
    "LINT",
    "LREAL",
    "MOD",
    "NOT",
    "OF",
    "OR",
    "POINTER",
    "PROGRAM",
    "REAL",
    "REF_TO",
    "REPEAT",
    "RETAIN",
    "RETURN",
    "SINT",
    "STRING",
    "STRUCT",
    "THEN",
    "TIME",
    "TO",
    "TRUE",
    "TYPE",
    "UDINT",
    "UINT",
    "ULINT",
    "UNTIL",
    "USINT",
    "VAR",
    "VAR_GLOBAL",
    "VAR_INPUT",
    "VAR_IN_OUT",
    "VAR_OUTPUT",
    "VAR_TEMP",
    "WHILE",
    "WORD",
    "WSTRING",
    "XOR",
];

impl KeywordCompletions {
    /// Every reserved word as a candidate.
    pub fn keywords() -> Vec<CompletionItem> {
        KEYWORDS
            .iter()
            .map(|word| CompletionItem {
                label: (*word).to_owned(),
                kind: CompletionKind::Keyword,
                detail: String::new(),
            })
            .collect()
    }
}

impl LanguageServices for KeywordCompletions {
    fn completions(&self, _text: &str, _offset: usize) -> Vec<CompletionItem> {
        Self::keywords()
    }

    fn hover(&self, _text: &str, _offset: usize) -> Option<String> {
        None
    }
}

/// What one frame of the editor produced.
#[derive(Debug)]
pub struct StEditorOutput {
    /// The response of the text area (focus, hover, the accessible label).
    pub response: egui::Response,
    /// The changes made this frame, to apply one after the other in this order (each range
    /// is in the text as the previous change left it); the editor already applied them to its
    /// own text. A gesture that changes several places at once (replace all, indent) lists
    /// them from the end of the text to its start.
    pub changes: Vec<TextChange>,
    /// The gesture of `changes`, `None` when there are none.
    pub gesture: Option<Gesture>,
    /// Set when the user asked for the definition of the name at this byte offset (F12).
    pub goto_definition: Option<usize>,
    /// Set when the user asked for the references of the name at this byte offset
    /// (Shift+F12).
    pub find_references: Option<usize>,
    /// A value the user prepared in an inline value box: the variable's range and the text.
    pub prepared: Option<(Range<usize>, String)>,
    /// The caret's byte offset after the frame.
    pub caret: usize,
    /// Set when the user asked to toggle a breakpoint on this line, counted from 0 (F9, or a
    /// click in the gutter's breakpoint column); the app decides whether the line can hold one.
    pub toggle_breakpoint: Option<usize>,
}
