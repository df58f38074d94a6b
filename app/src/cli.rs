//! The headless command line: `rivet check`, `rivet fmt`.

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use project_model::{LoadError, load_project, save_project};

/// Rivet: an engineering studio for IEC 61131-3 controllers.
#[derive(Debug, Parser)]
#[command(
    name = "rivet",
    version,
    about = "Rivet: an engineering studio for IEC 61131-3 controllers",
    args_conflicts_with_subcommands = true
)]
pub struct Cli {
    /// What to do headless; without a subcommand the studio opens.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// The project folder the studio opens (default: the example machine project).
    pub project: Option<PathBuf>,
}

/// Headless subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Check a project (or one `.st` file): load it and parse every Structured Text body;
    /// print each problem as `file:line:col: severity[CODE]: message`; exit 1 on any error.
    Check {
        /// The project folder (the folder holding rivet.toml), or a `.st` source file.
        project: PathBuf,
    },
    /// Load a project and save it in canonical form; a canonical project is left untouched.
    Fmt {
        /// The project folder (the folder holding rivet.toml).
        project: PathBuf,
    },
}

/// Runs a subcommand and returns the process exit code.
pub fn run(command: Command) -> ExitCode {
    let result = match command {
        Command::Check { project } => check(&project),
        Command::Fmt { project } => fmt(&project),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            report_error(&error);
            ExitCode::FAILURE
        }
    }
}

/// Prints an error and its causes to standard error.
pub fn report_error(error: &anyhow::Error) {
    eprintln!("{error}");
    for cause in error.chain().skip(1) {
        eprintln!("  caused by: {cause}");
    }
}

fn check(path: &Path) -> anyhow::Result<()> {
    if path.is_file() {
        return check_source_file(path);
    }
    let loaded = load_project(path).map_err(describe_load_error)?;
    for warning in &loaded.warnings {
        eprintln!("{warning}");
    }
    let mut errors = 0usize;
    let mut warnings = 0usize;
    for (file, text) in project_model::st_body_files(&loaded.project) {
        let parse = compiler::syntax::parse_statements(text);
        let shown = path.join(&file).display().to_string();
        for diagnostic in parse.errors() {
            eprint!("{}", diagnostic.render(&shown, text));
            match diagnostic.severity {
                compiler::Severity::Error => errors += 1,
                compiler::Severity::Warning => warnings += 1,
            }
        }
    }
    if errors > 0 {
        anyhow::bail!(
            "{}: {errors} error(s), {warnings} warning(s)",
            path.display()
        );
    }
    println!(
        "{}: project '{}' is fine ({} objects, {} tasks, {warnings} warning(s))",
        path.display(),
        loaded.project.name,
        loaded.project.application.objects().len(),
        loaded.project.tasks.len()
    );
    Ok(())
}

/// Checks one source file holding whole POUs, types or global variable lists.
fn check_source_file(path: &Path) -> anyhow::Result<()> {
    let bytes = std::fs::read(path)
        .map_err(|error| anyhow::anyhow!("{}: cannot read: {error}", path.display()))?;
    let text = String::from_utf8(bytes).map_err(|error| {
        let valid = error.utf8_error().valid_up_to();
        let line = error.as_bytes()[..valid]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1;
        anyhow::anyhow!(
            "{}:{line}: error: not UTF-8 text; save it as UTF-8",
            path.display()
        )
    })?;
    let parse = compiler::syntax::parse(&text);
    let shown = path.display().to_string();
    for diagnostic in parse.errors() {
        eprint!("{}", diagnostic.render(&shown, &text));
    }
    let errors = parse
        .errors()
        .iter()
        .filter(|d| d.severity == compiler::Severity::Error)
        .count();
    if errors > 0 {
        anyhow::bail!("{shown}: {errors} error(s)");
    }
    println!("{shown}: no problems found");
    Ok(())
}

fn fmt(dir: &Path) -> anyhow::Result<()> {
    let loaded = load_project(dir).map_err(describe_load_error)?;
    for warning in &loaded.warnings {
        eprintln!("{warning}");
    }
    let report = save_project(&loaded.project, dir, &loaded.files)?;
    for file in &report.written {
        println!("formatted {}", dir.join(file).display());
    }
    for file in &report.removed {
        println!("removed {}", dir.join(file).display());
    }
    if report.written.is_empty() && report.removed.is_empty() {
        println!("{}: already canonical", dir.display());
    }
    Ok(())
}

/// Turns a load error into one message with a line per problem and a count.
fn describe_load_error(error: LoadError) -> anyhow::Error {
    let errors = error
        .problems
        .iter()
        .filter(|problem| problem.severity == project_model::Severity::Error)
        .count();
    anyhow::anyhow!(
        "{error}\n{errors} error(s); the project was not loaded and nothing was changed"
    )
}
