//! `rivet import FILE.xml -o PROJECT_DIR` and `rivet import FILE.xml --into PROJECT_DIR
//! [--replace]` (`docs/plcopen-xml.md` §6.1): read a PLCopen XML file, print the import report,
//! and write the project only when everything succeeded.

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::path::{Path, PathBuf};

use plcopen::{Imported, Outcome};
use project_model::{ClashChoice, IgnoredPart, MergeItem, MergePlan, load_project};

use crate::plcopen_import::{import_file, outcome_counts, write_new_project};

/// Where the imported project goes.
#[derive(Debug)]
pub enum ImportTarget {
    /// A new project in a folder that does not exist or is empty.
    NewProject(PathBuf),
    /// Merged into the project in this folder; clashes are skipped, or replace what is there.
    Into {
        /// The project folder.
        project: PathBuf,
        /// Replace the clashing objects, tasks and program calls instead of skipping them.
        replace: bool,
    },
}

/// Runs `rivet import`.
pub fn run(file: &Path, target: &ImportTarget) -> anyhow::Result<()> {
    let imported = import_file(file)?;
    let summary = &imported.summary;
    println!(
        "{}: {} file written by {}: {} data types, {} POUs, {} configurations, {} tasks",
        summary.file,
        summary.dialect_name(),
        if summary.product.is_empty() {
            "an unnamed tool"
        } else {
            &summary.product
        },
        summary.data_types,
        summary.pous,
        summary.configurations,
        summary.tasks
    );
    print_report(&summary.file, &imported.imported);
    match target {
        ImportTarget::NewProject(dir) => {
            write_new_project(&imported.imported.project, dir)?;
            println!("{}: project written", dir.display());
        }
        ImportTarget::Into { project, replace } => {
            merge_into(&imported.imported, project, *replace)?;
        }
    }
    Ok(())
}

/// The word of an outcome in the report.
pub fn outcome_word(outcome: Outcome) -> &'static str {
    match outcome {
        Outcome::Converted => "converted",
        Outcome::KeptOpaque => "kept",
        Outcome::NotConverted => "not converted",
    }
}

/// Prints one line per report entry (`outcome: what (file:line): note`) and the counts.
fn print_report(file: &str, imported: &Imported) {
    // An entry stays on one line even when its text spans several (an XML comment's).
    let one_line = |text: &str| text.replace(['\n', '\r'], " ");
    for entry in &imported.report.entries {
        let note = if entry.note.is_empty() {
            String::new()
        } else {
            format!(": {}", one_line(&entry.note))
        };
        println!(
            "{}: {} ({file}:{}){note}",
            outcome_word(entry.outcome),
            one_line(&entry.what),
            entry.line
        );
    }
    let [converted, kept, not_converted] = outcome_counts(imported);
    println!(
        "{file}: {converted} converted, {kept} kept for the export, {not_converted} not converted"
    );
}

/// Merges the imported project into the project in `dir` and saves it there.
fn merge_into(imported: &Imported, dir: &Path, replace: bool) -> anyhow::Result<()> {
    let loaded = load_project(dir).map_err(crate::cli::describe_load_error)?;
    let mut plan = MergePlan::new(&loaded.project, &imported.project);
    if replace {
        plan.choose_all(ClashChoice::Replace);
    }
    for item in &plan.additions {
        println!("add {}", item_text(item));
    }
    for clash in &plan.clashes {
        let verb = match clash.choice {
            ClashChoice::Skip => "skip",
            ClashChoice::Replace => "replace",
        };
        println!(
            "{verb} {} (clashes with {})",
            item_text(&clash.imported),
            item_text(&clash.existing)
        );
    }
    for part in &plan.ignored {
        println!("keep the project's own {}", ignored_text(*part));
    }
    let merged = plan.apply(&loaded.project, &imported.project);
    project_model::save_project(&merged, dir, &loaded.files)?;
    println!(
        "{}: {} added, {} clashes {}",
        dir.display(),
        plan.additions.len(),
        plan.clashes.len(),
        if replace { "replaced" } else { "skipped" }
    );
    Ok(())
}

/// A plan item in words: `POU 'Main'`, `task 'Fast'`, `call of 'Main' by task 'Fast'`.
fn item_text(item: &MergeItem) -> String {
    match item {
        MergeItem::Object { kind, name } => format!("{} '{name}'", kind_word(*kind)),
        MergeItem::Task { name } => format!("task '{name}'"),
        MergeItem::ProgramCall { task, program } => {
            format!("call of '{program}' by task '{task}'")
        }
    }
}

fn kind_word(kind: project_model::ObjectKind) -> &'static str {
    use project_model::ObjectKind;
    match kind {
        ObjectKind::Pou => "POU",
        ObjectKind::Gvl => "global variable list",
        ObjectKind::DataType => "data type",
        ObjectKind::CamTable => "cam table",
        ObjectKind::Trace => "trace",
        ObjectKind::WatchList => "watch list",
    }
}

fn ignored_text(part: IgnoredPart) -> &'static str {
    match part {
        IgnoredPart::ProjectInfo => "name and description",
        IgnoredPart::Controller => "controller",
        IgnoredPart::Dialect => "dialect",
        IgnoredPart::IoAreas => "I/O areas",
        IgnoredPart::SerialPorts => "serial ports",
        IgnoredPart::ModbusDevices => "Modbus devices",
        IgnoredPart::Axes => "axes",
    }
}
