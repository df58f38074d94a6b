//! The live check's findings as editor diagnostics, placed in declarations and bodies.

use std::ops::Range;

use editor::EditorDiagnostic;
use project_model::{Project, TextTarget};

use super::live_check::LiveCheck;

/// The live check's findings in the POU's declarations, placed on the declared names.
pub(super) fn declaration_diagnostics(
    live: &LiveCheck,
    pou: &str,
    text: &str,
) -> Option<Vec<EditorDiagnostic>> {
    let (_, findings) = live.findings(pou)?;
    Some(
        findings
            .iter()
            .filter_map(|found| {
                let name = found.declaration.as_deref()?;
                let range = find_word(text, name)?;
                Some(EditorDiagnostic {
                    range,
                    severity: severity(found.diagnostic.severity),
                    code: found.diagnostic.code.id().to_owned(),
                    message: found.diagnostic.message.clone(),
                })
            })
            .collect(),
    )
}

pub(super) fn severity(severity: compiler::Severity) -> editor::Severity {
    match severity {
        compiler::Severity::Error => editor::Severity::Error,
        compiler::Severity::Warning => editor::Severity::Warning,
    }
}

pub(super) fn editor_diagnostic(diagnostic: &compiler::Diagnostic) -> EditorDiagnostic {
    EditorDiagnostic {
        range: diagnostic.range.clone(),
        severity: severity(diagnostic.severity),
        code: diagnostic.code.id().to_owned(),
        message: diagnostic.message.clone(),
    }
}

/// The first whole-word, case-insensitive occurrence of `word` in `text`.
pub fn find_word(text: &str, word: &str) -> Option<Range<usize>> {
    if word.is_empty() {
        return None;
    }
    let lower = text.to_ascii_lowercase();
    let wanted = word.to_ascii_lowercase();
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    let mut from = 0;
    while let Some(found) = lower[from..].find(&wanted) {
        let start = from + found;
        let end = start + wanted.len();
        let before = lower[..start].chars().next_back();
        let after = lower[end..].chars().next();
        if !before.is_some_and(is_word) && !after.is_some_and(is_word) {
            return Some(start..end);
        }
        from = end;
    }
    None
}

/// The live check's findings in one body.
pub(super) fn body_diagnostics(
    live: &LiveCheck,
    project: &Project,
    pou: &str,
    target: &TextTarget,
) -> Option<Vec<EditorDiagnostic>> {
    let (_, findings) = live.findings(pou)?;
    let file = project_model::text_body_files(project)
        .into_iter()
        .find(|body| body.target == *target)
        .map(|body| body.file)?;
    Some(
        findings
            .iter()
            .filter(|found| found.file == file && found.declaration.is_none())
            .map(|found| editor_diagnostic(&found.diagnostic))
            .collect(),
    )
}
