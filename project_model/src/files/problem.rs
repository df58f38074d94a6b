//! Problems found while loading a project, each naming its file and line.

use std::fmt;
use std::path::PathBuf;

use thiserror::Error;

/// How serious a load problem is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Severity {
    /// The project loaded, but something in the folder is not part of it.
    Warning,
    /// The project cannot be loaded.
    Error,
}

/// One problem found while loading, with the file and, where known, the line it is on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadProblem {
    /// Error or warning.
    pub severity: Severity,
    /// The file, as a path joined to the project folder.
    pub file: PathBuf,
    /// The 1-based line, when the problem is at a place in the file.
    pub line: Option<usize>,
    /// What was found and what was expected.
    pub message: String,
}

impl LoadProblem {
    /// An error in `file` at `line`.
    pub fn error(
        file: impl Into<PathBuf>,
        line: Option<usize>,
        message: impl Into<String>,
    ) -> Self {
        Self {
            severity: Severity::Error,
            file: file.into(),
            line,
            message: message.into(),
        }
    }

    /// A warning about `file`.
    pub fn warning(file: impl Into<PathBuf>, message: impl Into<String>) -> Self {
        Self {
            severity: Severity::Warning,
            file: file.into(),
            line: None,
            message: message.into(),
        }
    }
}

impl fmt::Display for LoadProblem {
    /// Formats as `file:line: message`, the form editors and terminals link to.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let severity = match self.severity {
            Severity::Warning => "warning",
            Severity::Error => "error",
        };
        match self.line {
            Some(line) => write!(
                f,
                "{}:{line}: {severity}: {}",
                self.file.display(),
                self.message
            ),
            None => write!(f, "{}: {severity}: {}", self.file.display(), self.message),
        }
    }
}

/// A project that could not be loaded, with every problem found.
#[derive(Clone, Debug, PartialEq, Error)]
pub struct LoadError {
    /// The problems, errors and warnings, in the order they were found.
    pub problems: Vec<LoadProblem>,
    /// The rest of the project when only application objects failed to load: they are held
    /// back (`LoadedProject::held_back`) and everything else is loaded. `None` when the
    /// manifest itself is broken.
    pub partial: Option<Box<super::LoadedProject>>,
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (index, problem) in self.problems.iter().enumerate() {
            if index > 0 {
                writeln!(f)?;
            }
            write!(f, "{problem}")?;
        }
        Ok(())
    }
}

/// The 1-based line of a byte offset in `text`.
pub(crate) fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Turns a TOML error into a problem located at its line.
pub(crate) fn toml_problem(file: PathBuf, text: &str, error: &toml::de::Error) -> LoadProblem {
    let line = error.span().map(|span| line_of(text, span.start));
    LoadProblem::error(file, line, error.message().trim_end().to_owned())
}
