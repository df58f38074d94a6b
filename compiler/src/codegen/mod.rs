//! Code generation: a checked project into a `program_image::ProgramImage`.
//!
//! The layout of every type and instance is computed once (`layout.rs`, initial values in
//! `init.rs`); each body is then walked with the checker's type of every expression
//! (`body.rs` statements, `expr.rs` places and expressions, `call.rs` and `std_call.rs`
//! calls), and `program.rs` assembles the data region, symbols, tasks and code.
//!
//! Semantics decided here (written down in `docs/program-image.md` §14): integer arithmetic
//! wraps in two's complement in the type of the expression; the FOR variable holds the first
//! value past the end after the loop, and the end and step are evaluated once; `SHR` shifts
//! in zeros on signed types too; a non-zero value converted to BOOL is TRUE; an integer
//! literal assigned to a BYTE keeps its low bits only when the checker allowed it (it fits).

mod body;
mod call;
mod condition;
mod constant;
mod debug_info;
#[cfg(test)]
mod element_tests;
mod error;
mod expr;
mod init;
mod interface;
mod layout;
#[cfg(test)]
mod line_table_tests;
pub(crate) mod modbus_device_def;
mod modbus_master;
mod motion;
mod program;
mod property;
mod sfc;
mod sfc_action;
mod sfc_layout;
#[cfg(test)]
mod snapshot_tests;
mod std_call;

use std::path::Path;

use program_image::ProgramImage;
use project_model::Project;

use crate::sema::{ProjectDiagnostic, check_lowered};
use crate::{Severity, SourceProject};

pub use condition::{
    CompiledCondition, ConditionCompileError, compile_condition, compile_source_condition,
};
pub use error::{CodegenError, Location, StatementPlace, Within};
pub use program::BodyOrigin;

/// Why a project does not compile.
#[derive(Debug, thiserror::Error)]
pub enum CompileError {
    /// The checker found errors; nothing was generated.
    #[error("the project has {} error(s)", .0.iter().filter(|d| d.diagnostic.severity == Severity::Error).count())]
    Diagnostics(Vec<ProjectDiagnostic>),
    /// Something the checker accepts that the code generator cannot compile yet, or a limit,
    /// with where it is (file, POU, declaration, line and origin); shown as the code
    /// generation error's text.
    #[error(transparent)]
    Unsupported(CodegenError),
}

/// Checks and compiles a project.
pub fn compile_project(project: &Project) -> Result<ProgramImage, CompileError> {
    let origin = |file: &Path| (file.to_string_lossy().into_owned(), 1);
    compile_with(project, &origin, None)
}

/// Checks and compiles a project made from one source file; the line table points into that
/// file, called `file_name`.
pub fn compile_source(
    source: &SourceProject,
    file_name: &str,
) -> Result<ProgramImage, CompileError> {
    let origin = |file: &Path| {
        (
            file_name.to_owned(),
            source.body_first_line(file).unwrap_or(1),
        )
    };
    compile_with(&source.project, &origin, None)
}

/// Checks and compiles a project, and the breakpoint condition of `condition` in it.
fn compile_with(
    project: &Project,
    origin: BodyOrigin<'_>,
    condition: Option<&mut condition::ConditionJob>,
) -> Result<ProgramImage, CompileError> {
    // LD and FBD bodies are checked and compiled as their Structured Text, and what is found
    // in them is moved back onto their elements.
    let lowered = crate::lower::lower_project(project);
    // The checker's trees and types are kept, so the code generator does not parse and type
    // every body a second time.
    let mut checked = crate::sema::expression_types::CheckedBodies::default();
    let diagnostics = check_lowered(project, &lowered, Some(&mut checked));
    if diagnostics
        .iter()
        .any(|d| d.diagnostic.severity == Severity::Error)
    {
        return Err(CompileError::Diagnostics(diagnostics));
    }
    // The line table names an IL body's `.il` file: its lowered text has the same lines.
    let origin = |file: &Path| origin(lowered.il_file_of(file).unwrap_or(file));
    program::build_image(&lowered.project, &origin, checked, condition)
        .map_err(|error| CompileError::Unsupported(lowered.locate_error(error)))
}
