//! Why the code generator cannot compile something the checker accepted, and where.

use std::fmt;

use crate::origin::Origin;

/// Why the code generator cannot compile something the checker accepted.
#[derive(Debug, PartialEq, Eq, thiserror::Error)]
pub enum CodegenError {
    /// A construct the generator does not compile (yet), or a limit, where it was met.
    #[error("{location}{message}")]
    Unsupported {
        /// What cannot be compiled, in words.
        message: String,
        /// Where it is, as far as the generator knows.
        location: Location,
    },
    /// The image the generator assembled does not pass the load-time checks: a bug of the
    /// generator, never of the project.
    #[error("internal error, the image does not verify: {0}")]
    InvalidImage(#[source] program_image::ImageError),
}

/// Where a code generation error is: the places it is within, outermost first, as the
/// generator learned them on the way out (a statement, then its POU, then its file).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Location {
    /// The file, POU, statement and declarations the error is within, outermost first.
    pub within: Vec<Within>,
}

impl Location {
    /// The innermost statement the error is in, when it is in a body.
    pub fn statement(&self) -> Option<&StatementPlace> {
        self.within.iter().find_map(|place| match place {
            Within::Statement(statement) => Some(statement),
            _ => None,
        })
    }
}

/// One place a code generation error is within.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Within {
    /// The file a body is in, as the image's line table names it.
    File(String),
    /// A POU, method, action or property accessor (`FB_Conveyor.Reset`).
    Pou(String),
    /// A declared variable or member, by its path (`GVL.xStart`, `ST_Point.x`).
    Declaration(String),
    /// A statement of a body.
    Statement(StatementPlace),
}

/// The statement of a body a code generation error is in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StatementPlace {
    /// The 1-based line of the statement in its file.
    pub line: u32,
    /// The statement's origin in the body.
    pub origin: Origin,
}

impl CodegenError {
    /// The same error, within `place` (outside the places it already names).
    pub(crate) fn within(mut self, place: Within) -> Self {
        if let Self::Unsupported { location, .. } = &mut self {
            location.within.insert(0, place);
        }
        self
    }

    /// The same error, in the statement at `line` from `origin`, unless an inner statement is
    /// named already.
    pub(crate) fn in_statement(mut self, line: u32, origin: Origin) -> Self {
        if let Self::Unsupported { location, .. } = &mut self
            && location.statement().is_none()
        {
            let statement = StatementPlace { line, origin };
            location.within.insert(0, Within::Statement(statement));
        }
        self
    }
}

impl From<String> for CodegenError {
    fn from(message: String) -> Self {
        Self::Unsupported {
            message,
            location: Location::default(),
        }
    }
}

impl From<&str> for CodegenError {
    fn from(message: &str) -> Self {
        Self::from(message.to_owned())
    }
}

impl fmt::Display for Location {
    /// `file: POU: declaration: line N: `, the prefix the message follows (`network:element: `
    /// instead of the line in a lowered LD or FBD body).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for place in &self.within {
            match place {
                Within::File(name) | Within::Pou(name) | Within::Declaration(name) => {
                    write!(f, "{name}: ")?;
                }
                Within::Statement(statement) => match &statement.origin {
                    // A statement of a lowered LD or FBD body is shown by its network and
                    // element, as `POU:network:element` continues.
                    Origin::Element {
                        network,
                        element,
                        pin,
                    } => {
                        write!(f, "{}:", network + 1)?;
                        match element {
                            Some(element) => write!(f, "{}", element.0)?,
                            None => write!(f, "-")?,
                        }
                        if let Some(pin) = pin {
                            write!(f, ".{pin}")?;
                        }
                        write!(f, ": ")?;
                    }
                    Origin::Text { .. } => write!(f, "line {}: ", statement.line)?,
                },
            }
        }
        Ok(())
    }
}

/// A code generation error with `format!`'s arguments as its message.
macro_rules! fail {
    ($($argument:tt)*) => {
        $crate::codegen::error::CodegenError::from(format!($($argument)*))
    };
}
pub(crate) use fail;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_in_a_statement_names_the_file_the_pou_and_the_line() {
        let error = CodegenError::from("EXIT outside a loop")
            .in_statement(7, Origin::Text { range: 40..45 })
            .in_statement(3, Origin::Text { range: 0..60 })
            .within(Within::Pou("Main".to_owned()))
            .within(Within::File("main.st".to_owned()));
        assert_eq!(
            error.to_string(),
            "main.st: Main: line 7: EXIT outside a loop"
        );
        let CodegenError::Unsupported { location, .. } = error else {
            panic!("not an unsupported construct");
        };
        assert_eq!(
            location.statement().map(|s| s.origin.clone()),
            Some(Origin::Text { range: 40..45 })
        );
    }

    #[test]
    fn a_declaration_named_inside_a_statement_follows_its_line() {
        let error = CodegenError::from("values of type X cannot be stored")
            .within(Within::Declaration("ST_A.x".to_owned()))
            .in_statement(4, Origin::Text { range: 10..20 })
            .within(Within::Pou("Main".to_owned()));
        assert_eq!(
            error.to_string(),
            "Main: line 4: ST_A.x: values of type X cannot be stored"
        );
    }

    #[test]
    fn an_error_in_a_declaration_names_it_after_its_pou() {
        let error = CodegenError::from("the array bounds 3..1 are empty")
            .within(Within::Declaration("FB_A.aValues".to_owned()))
            .within(Within::Pou("Main".to_owned()));
        assert_eq!(
            error.to_string(),
            "Main: FB_A.aValues: the array bounds 3..1 are empty"
        );
    }
}
