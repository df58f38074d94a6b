//! The words the editor shows, so the app can give them in the user's language.

/// The user-visible words of the find bar and the inline value box. The default is English;
/// the app sets its own translation with [`super::StEditor::set_texts`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EditorTexts {
    /// The label of the find field.
    pub find: String,
    /// The label of the replace field.
    pub replace: String,
    /// The match case option.
    pub match_case: String,
    /// The whole word option.
    pub whole_word: String,
    /// The button that selects the previous match.
    pub previous: String,
    /// The button that selects the next match.
    pub next: String,
    /// The button that replaces the current match.
    pub replace_one: String,
    /// The button that replaces every match.
    pub replace_all: String,
    /// The button that closes the find bar.
    pub close: String,
    /// The label of the field where a value is prepared for writing or forcing.
    pub prepared_value: String,
}

impl Default for EditorTexts {
    fn default() -> Self {
        Self {
            find: "Find".to_owned(),
            replace: "Replace with".to_owned(),
            match_case: "Match case".to_owned(),
            whole_word: "Whole word".to_owned(),
            previous: "Previous".to_owned(),
            next: "Next".to_owned(),
            replace_one: "Replace".to_owned(),
            replace_all: "Replace all".to_owned(),
            close: "Close".to_owned(),
            prepared_value: "Prepared value".to_owned(),
        }
    }
}
