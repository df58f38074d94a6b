//! Highlight classes of the editor and their colours in the dark and light themes.

use egui::Color32;

use crate::{SyntaxColors, TokenClass};

/// What a run of text is, for colouring.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Highlight {
    /// Identifiers without a more specific class, operators and spaces.
    Plain,
    /// Reserved words (`IF`, `VAR_INPUT`, `AND` …).
    Keyword,
    /// Comments.
    Comment,
    /// String literals.
    String,
    /// Numbers, time and date literals.
    Number,
    /// Constants: `TRUE`, enum values, direct addresses.
    Constant,
    /// Type names.
    Type,
    /// Names of functions, methods and called blocks.
    Function,
    /// Members and properties.
    Property,
    /// Pragmas and attributes.
    Attribute,
    /// SFC steps, transitions and labels.
    Label,
}

impl Highlight {
    /// The class of a tree-sitter capture name such as `keyword.conditional`, or `None` for
    /// captures that keep the plain colour.
    pub fn from_capture(name: &str) -> Option<Self> {
        let head = name.split('.').next().unwrap_or(name);
        Some(match head {
            "keyword" => Self::Keyword,
            "comment" => Self::Comment,
            "string" => Self::String,
            "number" => Self::Number,
            "constant" | "boolean" => Self::Constant,
            "type" => Self::Type,
            "function" => Self::Function,
            "property" => Self::Property,
            "attribute" => Self::Attribute,
            "label" => Self::Label,
            _ => return None,
        })
    }

    /// The class of the lexical scanner's token class, for the fallback when the
    /// tree-sitter query cannot be used.
    pub fn from_token(class: TokenClass) -> Self {
        match class {
            TokenClass::Plain => Self::Plain,
            TokenClass::Keyword => Self::Keyword,
            TokenClass::Comment => Self::Comment,
            TokenClass::String => Self::String,
            TokenClass::Number => Self::Number,
            TokenClass::Address => Self::Constant,
            TokenClass::Pragma => Self::Attribute,
        }
    }

    /// The colour of the class in `colors`; `plain` is the theme's text colour.
    pub fn color(self, colors: &SyntaxColors, plain: Color32) -> Color32 {
        match self {
            Self::Plain => plain,
            Self::Keyword => colors.keyword,
            Self::Comment => colors.comment,
            Self::String => colors.string,
            Self::Number => colors.number,
            Self::Constant => colors.constant,
            Self::Type => colors.type_name,
            Self::Function => colors.function,
            Self::Property => colors.property,
            Self::Attribute => colors.attribute,
            Self::Label => colors.label,
        }
    }
}
