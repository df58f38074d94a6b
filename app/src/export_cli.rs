//! `rivet export PROJECT_DIR -o FILE.xml` (`docs/plcopen-xml.md` §5 and §6.4): write a project
//! as a PLCopen TC6 XML v2.01 document that CODESYS, Beremiz and OpenPLC read.

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::path::Path;

use anyhow::Context;
use project_model::load_project;

use crate::cli::describe_load_error;
use crate::plcopen_export::{ExportFailure, write_export};

/// Runs `rivet export`: loads the project, exports it and writes the file through a temporary
/// sibling renamed at the end, so a failure leaves any earlier file as it was.
pub fn run(project: &Path, output: &Path) -> anyhow::Result<()> {
    let loaded = load_project(project).map_err(describe_load_error)?;
    for warning in &loaded.warnings {
        eprintln!("{warning}");
    }
    let bytes = match write_export(&loaded.project, output) {
        Ok(bytes) => bytes,
        Err(ExportFailure::Export(error)) => {
            return Err(error)
                .with_context(|| format!("{}: cannot be exported", project.display()));
        }
        Err(error) => return Err(error.into()),
    };
    println!(
        "{}: {bytes} bytes of PLCopen XML written ({} objects)",
        output.display(),
        loaded.project.application.objects().len()
    );
    Ok(())
}
