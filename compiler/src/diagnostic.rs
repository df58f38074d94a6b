//! Diagnostics: what the compiler reports, each with a stable code documented in
//! `docs/diagnostics/<CODE>.md`.

use std::ops::Range;

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// Worth a look; the program still builds.
    Warning,
    /// The program cannot be built.
    Error,
}

/// Defines `Code` with each code's identifier, severity and title in one place.
macro_rules! codes {
    ($($variant:ident = $id:literal, $severity:ident, $title:literal;)*) => {
        /// The stable codes of diagnostics. A code never changes meaning once released.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Code {
            $(
                #[doc = $title]
                $variant,
            )*
        }

        impl Code {
            /// Every code, in order.
            pub const ALL: &'static [Code] = &[$(Code::$variant),*];

            /// The code as written in messages and doc page names, such as `E0001`.
            pub fn id(self) -> &'static str {
                match self { $(Code::$variant => $id,)* }
            }

            /// The default severity.
            pub fn severity(self) -> Severity {
                match self { $(Code::$variant => Severity::$severity,)* }
            }

            /// A one-line title, the heading of the code's doc page.
            pub fn title(self) -> &'static str {
                match self { $(Code::$variant => $title,)* }
            }
        }
    };
}

codes! {
    UnexpectedToken = "E0001", Error, "Unexpected token";
    UnterminatedComment = "E0002", Error, "Comment or pragma not closed";
    UnterminatedString = "E0003", Error, "String not closed";
    InvalidCharacter = "E0004", Error, "Character that is not part of Structured Text";
    NestingTooDeep = "E0005", Error, "Nesting too deep";
}

/// One finding of the compiler about the source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The stable code.
    pub code: Code,
    /// Error or warning.
    pub severity: Severity,
    /// The primary span in bytes of the source the diagnostic is about.
    pub range: Range<usize>,
    /// What was found and what was expected.
    pub message: String,
}

impl Diagnostic {
    /// A diagnostic with the code's default severity.
    pub fn new(code: Code, range: Range<usize>, message: impl Into<String>) -> Self {
        Self {
            code,
            severity: code.severity(),
            range,
            message: message.into(),
        }
    }
}
