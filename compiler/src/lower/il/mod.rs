//! Instruction List bodies lowered into Structured Text line for line
//! (`docs/instruction-list.md`): `parse` reads the instructions, `emit` turns them into
//! statements on the same lines with the current result in typed hidden variables, and
//! [`LoweredIl`] moves the checker's findings from the generated text back to the IL file.

mod emit;
#[cfg(test)]
mod emit_tests;
mod parse;
#[cfg(test)]
mod parse_tests;

use std::ops::Range;
use std::path::{Path, PathBuf};

use project_model::TextTarget;

use crate::diagnostic::Diagnostic;
use crate::sema::ProjectDiagnostic;

pub(crate) use emit::{IlLowering, TypeOf};

/// One Instruction List body as Structured Text with the same lines.
#[derive(Clone, Debug)]
pub struct LoweredIl {
    /// The POU's name.
    pub pou: String,
    /// Which body of the POU it is.
    pub target: TextTarget,
    /// The `.il` file, relative to the project folder: where findings are shown.
    pub file: PathBuf,
    /// The `.st` file the lowered text has for the checker and the code generator; it does
    /// not exist on disk.
    pub text_file: PathBuf,
    /// The generated statements, line N holding those of IL line N.
    pub text: String,
    /// The byte range of each IL line's instruction (without comments and blanks), by line.
    lines: Vec<Range<usize>>,
    /// Each hidden name of the body with the words a message uses for it.
    descriptions: Vec<(String, String)>,
    /// What the lowering found that cannot be compiled.
    findings: Vec<ProjectDiagnostic>,
    /// Each operand copied into `text`: its range there and its start in the IL text.
    operands: Vec<(Range<usize>, usize)>,
}

impl LoweredIl {
    /// Lowers `il` (the text of the body `target` of POU `pou`, stored in `file`), whose
    /// hidden variables are named with `prefix`; returns the body and its hidden variables.
    /// A transition's body (`transition` its name) assigns its final current result to it.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        pou: &str,
        target: TextTarget,
        file: PathBuf,
        text_file: PathBuf,
        il: &str,
        prefix: String,
        type_of: TypeOf<'_>,
        transition: Option<&str>,
    ) -> (Self, Vec<project_model::Variable>) {
        let mut lowering = IlLowering::new(prefix, type_of);
        let text = lowering.lower(il, transition);
        let findings = lowering
            .findings
            .iter()
            .map(|error| ProjectDiagnostic {
                file: file.clone(),
                declaration: None,
                element: None,
                diagnostic: Diagnostic::new(error.code, error.range.clone(), error.message.clone()),
            })
            .collect();
        let mut start = 0;
        let lines = il
            .split_inclusive('\n')
            .map(|line| {
                let content = line.trim();
                let offset = start + (line.len() - line.trim_start().len());
                start += line.len();
                offset..offset + content.len()
            })
            .collect();
        let lowered = Self {
            pou: pou.to_owned(),
            target,
            file,
            text_file,
            text,
            lines,
            descriptions: lowering.descriptions,
            findings,
            operands: lowering.operands,
        };
        (lowered, lowering.hidden)
    }

    /// What the lowering found that cannot be compiled, in the IL file.
    pub(crate) fn findings(&self) -> &[ProjectDiagnostic] {
        &self.findings
    }

    /// A finding of the checker in the lowered text moved to the IL file, at the line it is
    /// on (the whole instruction of that line), with hidden names in words.
    pub(crate) fn locate(&self, mut finding: ProjectDiagnostic) -> ProjectDiagnostic {
        let offset = finding.diagnostic.range.start.min(self.text.len());
        let line = self.text[..offset].matches('\n').count();
        finding.diagnostic.range = self.lines.get(line).cloned().unwrap_or(0..0);
        finding.diagnostic.message =
            super::locate::describe_hidden(&finding.diagnostic.message, &self.descriptions);
        finding.file = self.file.clone();
        finding
    }

    /// The range in the IL text of the bytes `range` of the lowered text, when they lie in an
    /// operand the IL wrote (not in generated text such as the current result's variable).
    pub fn il_range(&self, range: Range<usize>) -> Option<Range<usize>> {
        self.operands
            .iter()
            .find(|(lowered, _)| lowered.start <= range.start && range.end <= lowered.end)
            .map(|(lowered, il)| {
                let start = il + (range.start - lowered.start);
                start..start + range.len()
            })
    }

    /// Whether `name` is a hidden variable of this body.
    pub(crate) fn is_hidden(&self, name: &str) -> bool {
        self.descriptions
            .iter()
            .any(|(hidden, _)| hidden.eq_ignore_ascii_case(name))
    }

    /// Whether the checker names this body's lowered text by `file`.
    pub(crate) fn has_text_file(&self, file: &Path) -> bool {
        self.text_file == file
    }
}
