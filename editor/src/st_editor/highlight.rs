//! Highlight classes of the editor and their colours in the dark and light themes.

use egui::Color32;

use crate::TokenClass;

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

    /// The colour of the class; `plain` is the theme's text colour.
    pub fn color(self, dark: bool, plain: Color32) -> Color32 {
        let (dark_color, light_color) = match self {
            Self::Plain => return plain,
            Self::Keyword => ((86, 156, 214), (0, 70, 180)),
            Self::Comment => ((106, 153, 85), (0, 128, 0)),
            Self::String => ((206, 145, 120), (163, 21, 21)),
            Self::Number => ((181, 206, 168), (9, 134, 88)),
            Self::Constant => ((100, 180, 230), (0, 110, 150)),
            Self::Type => ((78, 201, 176), (38, 127, 153)),
            Self::Function => ((220, 220, 170), (121, 94, 38)),
            Self::Property => ((156, 220, 254), (0, 16, 128)),
            Self::Attribute => ((197, 134, 192), (140, 40, 140)),
            Self::Label => ((220, 180, 90), (150, 90, 0)),
        };
        let (r, g, b) = if dark { dark_color } else { light_color };
        Color32::from_rgb(r, g, b)
    }
}
