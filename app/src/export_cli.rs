//! `rivet export PROJECT_DIR -o FILE.xml` (`docs/plcopen-xml.md` §5): write a project as a
//! PLCopen TC6 XML v2.01 document that CODESYS, Beremiz and OpenPLC read.

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::path::Path;

use anyhow::Context;
use project_model::load_project;

use crate::cli::describe_load_error;

/// Runs `rivet export`: loads the project, exports it and writes the file through a temporary
/// sibling renamed at the end, so a failure leaves any earlier file as it was.
pub fn run(project: &Path, output: &Path) -> anyhow::Result<()> {
    let loaded = load_project(project).map_err(describe_load_error)?;
    for warning in &loaded.warnings {
        eprintln!("{warning}");
    }
    let xml = plcopen::export(&loaded.project)
        .with_context(|| format!("{}: cannot be exported", project.display()))?;
    let file_name = output
        .file_name()
        .with_context(|| format!("{}: not a file name", output.display()))?;
    let mut temporary_name = std::ffi::OsString::from(".");
    temporary_name.push(file_name);
    temporary_name.push(".partial");
    let temporary = output.with_file_name(temporary_name);
    if let Err(error) = std::fs::write(&temporary, &xml) {
        // A partly written temporary file is ours; removing it leaves the folder as it was.
        let _ = std::fs::remove_file(&temporary);
        return Err(error).with_context(|| format!("{}: cannot be written", output.display()));
    }
    if let Err(error) = std::fs::rename(&temporary, output) {
        // The temporary file is ours; removing it leaves the folder as it was.
        let _ = std::fs::remove_file(&temporary);
        return Err(error).with_context(|| format!("{}: cannot be written", output.display()));
    }
    println!(
        "{}: {} bytes of PLCopen XML written ({} objects)",
        output.display(),
        xml.len(),
        loaded.project.application.objects().len()
    );
    Ok(())
}
