//! The headless command line: `rivet check`, `rivet fmt`, `rivet build`, `rivet simulate`,
//! `rivet import`, the online commands (`rivet status`, `download`, `start`, `stop`, `reset`,
//! `read`, `write`, `force`, `unforce`, `forces`, `faults`) and the debugging ones (`break`, `step`, `continue`,
//! `halt`, `stack`, `flow`).

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use project_model::{LoadError, load_project, save_project};
use runtime::engine::EngineChoice;

use crate::debug_cli::{self, DebugCommand};
use crate::online_cli::{self, OnlineCommand, Target};

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
    /// Check a project (or one `.st` file): load it, parse and type-check every Structured
    /// Text body and declaration;
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
    /// Compile a project (or one `.st` file) into a program image that `rivet-runtime` runs.
    Build {
        /// The project folder, or a `.st` source file.
        project: PathBuf,
        /// Where to write the image.
        #[arg(short, long, default_value = "image.bin")]
        output: PathBuf,
    },
    /// Compile and run N cycles on a simulated clock, then print the watched variables.
    ///
    /// Time advances by the task interval each cycle (a single `.st` file with one PROGRAM
    /// runs in an implicit 10 ms task); with several tasks, N counts cycles of the fastest.
    /// Runtime Modbus devices are not polled: variables they fill keep their values unless
    /// `--set` writes them, so that a run gives the same output every time.
    Simulate {
        /// The project folder, or a `.st` source file.
        project: PathBuf,
        /// How many cycles to run.
        #[arg(long, default_value_t = 1)]
        cycles: u64,
        /// Variables to print, by path (`main.x`, `Main.fb.ET`, `Main.a[3]`), comma-separated.
        #[arg(long, value_delimiter = ',')]
        watch: Vec<String>,
        /// A value to write before a cycle, as `CYCLE:PATH=VALUE` (`5:Main.reset=TRUE`; cycles
        /// count from 1); repeat it for several. The value stays until the program changes it.
        #[arg(long = "set", value_name = "CYCLE:PATH=VALUE")]
        writes: Vec<String>,
        /// Print one JSON object mapping each watched path to its value.
        #[arg(long)]
        json: bool,
        /// The engine that runs the program: `native` (machine code made at load; a POU it
        /// cannot translate runs in the interpreter, said in a `note:` line) or `interpreter`.
        /// The default is `native` on x86-64 and aarch64 and `interpreter` elsewhere.
        #[arg(long, value_name = "native|interpreter", value_parser = ["native", "interpreter"])]
        engine: Option<String>,
    },
    /// Import a PLCopen XML file (CODESYS, Beremiz, OpenPLC) into a new project, or merge it
    /// into an existing one; print the import report. Nothing is written unless the whole
    /// import succeeds.
    Import {
        /// The PLCopen XML file.
        file: PathBuf,
        /// The new project's folder: it must not exist or be empty.
        #[arg(short, long, required_unless_present = "into", conflicts_with = "into")]
        output: Option<PathBuf>,
        /// Merge into the project in this folder instead; what clashes with it is skipped.
        #[arg(long)]
        into: Option<PathBuf>,
        /// With --into: replace what clashes instead of skipping it.
        #[arg(long, requires = "into")]
        replace: bool,
    },
    /// Export a project as a PLCopen XML (TC6 v2.01) file that CODESYS, Beremiz and OpenPLC
    /// read; Rivet's own data goes into `addData`, so importing the file gives the project back.
    Export {
        /// The project folder (the folder holding rivet.toml).
        project: PathBuf,
        /// The XML file to write.
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Work with a project's cam tables: list them, evaluate one, export its point table.
    Cam {
        /// What to do.
        #[command(subcommand)]
        action: crate::cam_cli::CamCommand,
    },
    /// Show a runtime's state, program identity, task statistics and forces.
    Status {
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Compile a project (or `.st` file) and download it to a runtime; the old program keeps
    /// running unless the whole image arrives and verifies.
    Download {
        /// The project folder, or a `.st` source file.
        project: PathBuf,
        /// Start the program once it is loaded.
        #[arg(long, conflicts_with = "online_change")]
        start: bool,
        /// Change the running program between two cycles without stopping its tasks, the
        /// variables keeping their values by path and type (docs/debugging.md §6); refused,
        /// with the reason, when the change does not allow it.
        #[arg(long)]
        online_change: bool,
        /// With --online-change: check and list what would change, and change nothing.
        #[arg(long, requires = "online_change")]
        dry_run: bool,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Start the runtime's program.
    Start {
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Stop the runtime's program.
    Stop {
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Reset the program's memory: warm keeps RETAIN and PERSISTENT, cold keeps PERSISTENT,
    /// origin keeps nothing.
    Reset {
        /// warm, cold or origin.
        #[arg(value_parser = ["warm", "cold", "origin"])]
        kind: String,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Read variables by path (`Main.fb.ET`, `GVL.x`, `Main.a[3]`), as IEC literals.
    Read {
        /// The variables.
        #[arg(required = true)]
        variables: Vec<String>,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Write values once: `VAR=VALUE` with the value as an IEC literal (`Main.speed=1500`,
    /// `Main.t=T#2s`, `Main.on=TRUE`).
    Write {
        /// The assignments.
        #[arg(required = true)]
        assignments: Vec<String>,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Force values: held before and after every cycle until released.
    Force {
        /// The assignments, `VAR=VALUE`.
        #[arg(required = true)]
        assignments: Vec<String>,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Release forces of the given variables, or every force with --all.
    Unforce {
        /// The variables.
        variables: Vec<String>,
        /// Release every force.
        #[arg(long, conflicts_with = "variables")]
        all: bool,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// List the forced places and their values.
    Forces {
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Record a trace on the target (every cycle of a task, so nothing is lost) and save it as
    /// CSV.
    Trace {
        /// The variables, comma-separated.
        #[arg(long, value_delimiter = ',', required = true)]
        vars: Vec<String>,
        /// The task whose cycles are sampled.
        #[arg(long)]
        task: String,
        /// How many samples to record.
        #[arg(long, default_value_t = 1000)]
        samples: u32,
        /// Sample every n-th cycle.
        #[arg(long, default_value_t = 1)]
        every: u16,
        /// A BOOL whose edge starts the recording.
        #[arg(long)]
        trigger: Option<String>,
        /// Start on the trigger's rising edge (the default).
        #[arg(long, conflicts_with_all = ["falling", "level"])]
        rising: bool,
        /// Start on the trigger's falling edge.
        #[arg(long, conflicts_with = "level")]
        falling: bool,
        /// Record while the trigger is TRUE.
        #[arg(long)]
        level: bool,
        /// Percent of the samples kept before the trigger.
        #[arg(long, default_value_t = 0)]
        pretrigger: u8,
        /// Where to write the samples.
        #[arg(long)]
        csv: PathBuf,
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// List the faults that stopped tasks, with POU and source line.
    Faults {
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// List the Modbus devices the runtime masters: state, last error, counters
    /// (`docs/modbus-master.md` §9.1).
    Devices {
        /// The runtime to talk to.
        #[command(flatten)]
        target: Target,
    },
    /// Set a breakpoint at FILE:LINE, or list or clear them (`docs/debugging.md` §7).
    Break(debug_cli::BreakArgs),
    /// Step the halted task into, over or out of a call, and show where it halts.
    Step(debug_cli::StepArgs),
    /// Let a halted task (or every task) run on, to the next breakpoint or to a place.
    Continue(debug_cli::ContinueArgs),
    /// Halt a task (or every task) at its next statement, and show where.
    Halt(debug_cli::HaltArgs),
    /// Show a halted task's call stack, with each frame's variables on request.
    Stack(debug_cli::StackArgs),
    /// Record one cycle of a task and print the lines of a POU that ran.
    Flow(debug_cli::FlowArgs),
}

/// Runs a subcommand and returns the process exit code.
pub fn run(command: Command) -> ExitCode {
    let result = match command {
        Command::Check { project } => check(&project),
        Command::Fmt { project } => fmt(&project),
        Command::Build { project, output } => crate::build_cli::build(&project, &output),
        Command::Simulate {
            project,
            cycles,
            watch,
            writes,
            json,
            engine,
        } => {
            // Refused before anything compiles or loads, as a wrong argument is.
            let engine = match engine.as_deref().map(EngineChoice::for_this_machine) {
                None => EngineChoice::default(),
                Some(Ok(engine)) => engine,
                Some(Err(refusal)) => {
                    eprintln!("error: {refusal}");
                    return ExitCode::from(2);
                }
            };
            crate::build_cli::simulate(&project, cycles, &watch, &writes, json, engine)
        }
        Command::Import {
            file,
            output,
            into,
            replace,
        } => {
            let target = match (output, into) {
                (_, Some(project)) => crate::import_cli::ImportTarget::Into { project, replace },
                (Some(dir), None) => crate::import_cli::ImportTarget::NewProject(dir),
                (None, None) => {
                    return fail(&anyhow::anyhow!(
                        "name the new project's folder (-o) or the project to merge into (--into)"
                    ));
                }
            };
            crate::import_cli::run(&file, &target)
        }
        Command::Export { project, output } => crate::export_cli::run(&project, &output),
        Command::Cam { action } => crate::cam_cli::run(action),
        Command::Status { target } => online_cli::run(&target, OnlineCommand::Status),
        Command::Download {
            project,
            online_change: true,
            dry_run,
            target,
            ..
        } => online_cli::run(&target, OnlineCommand::OnlineChange { project, dry_run }),
        Command::Download {
            project,
            start,
            target,
            ..
        } => online_cli::run(&target, OnlineCommand::Download { project, start }),
        Command::Start { target } => online_cli::run(&target, OnlineCommand::Start),
        Command::Stop { target } => online_cli::run(&target, OnlineCommand::Stop),
        Command::Reset { kind, target } => {
            let kind = match kind.as_str() {
                "warm" => online::Reset::Warm,
                "cold" => online::Reset::Cold,
                _ => online::Reset::Origin,
            };
            online_cli::run(&target, OnlineCommand::Reset(kind))
        }
        Command::Read { variables, target } => {
            online_cli::run(&target, OnlineCommand::Read(variables))
        }
        Command::Write {
            assignments,
            target,
        } => online_cli::run(&target, OnlineCommand::Write(assignments)),
        Command::Force {
            assignments,
            target,
        } => online_cli::run(&target, OnlineCommand::Force(assignments)),
        Command::Unforce {
            variables,
            all,
            target,
        } => {
            if variables.is_empty() && !all {
                Err(anyhow::anyhow!(
                    "name the variables to release, or give --all"
                ))
            } else {
                online_cli::run(&target, OnlineCommand::Unforce(variables))
            }
        }
        Command::Forces { target } => online_cli::run(&target, OnlineCommand::Forces),
        Command::Faults { target } => online_cli::run(&target, OnlineCommand::Faults),
        Command::Devices { target } => online_cli::run(&target, OnlineCommand::Devices),
        Command::Break(args) => debug_cli::run(DebugCommand::Break(args)),
        Command::Step(args) => debug_cli::run(DebugCommand::Step(args)),
        Command::Continue(args) => debug_cli::run(DebugCommand::Continue(args)),
        Command::Halt(args) => debug_cli::run(DebugCommand::Halt(args)),
        Command::Stack(args) => debug_cli::run(DebugCommand::Stack(args)),
        Command::Flow(args) => debug_cli::run(DebugCommand::Flow(args)),
        Command::Trace {
            vars,
            task,
            samples,
            every,
            trigger,
            rising: _,
            falling,
            level,
            pretrigger,
            csv,
            target,
        } => {
            let kind = if falling {
                "falling"
            } else if level {
                "level"
            } else {
                "rising"
            };
            let request = online_cli::TraceRequest {
                variables: vars,
                task,
                samples,
                every,
                trigger: trigger.map(|variable| (variable, kind.to_owned())),
                pretrigger,
                csv,
            };
            online_cli::run(&target, OnlineCommand::Trace(request))
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => fail(&error),
    }
}

/// Reports `error` and gives the failure exit code.
fn fail(error: &anyhow::Error) -> ExitCode {
    report_error(error);
    ExitCode::FAILURE
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
    let bodies: HashMap<PathBuf, &str> = project_model::text_body_files(&loaded.project)
        .into_iter()
        .map(|body| (body.file, body.text))
        .collect();
    let mut errors = 0usize;
    let mut warnings = 0usize;
    for found in compiler::sema::check_project(&loaded.project) {
        let shown = path.join(&found.file).display().to_string();
        match (&found.declaration, bodies.get(&found.file)) {
            // A finding in an LD or FBD body: `file:POU:network:element`.
            _ if let Some(place) = &found.element => eprintln!(
                "{shown}:{place}: {}[{}]: {}",
                severity_word(found.diagnostic.severity),
                found.diagnostic.code.id(),
                found.diagnostic.message
            ),
            (None, Some(text)) => eprint!("{}", found.diagnostic.render(&shown, text)),
            (declaration, _) => {
                // A finding in data: point at the line that declares the name, if it is found;
                // for a Modbus channel, at the line of the channel's variable.
                let line = declaration.as_deref().and_then(|name| {
                    let file = path.join(&found.file);
                    modbus_channel(name, &found.diagnostic.message)
                        .and_then(|channel| modbus_channel_line(&file, name, channel))
                        .or_else(|| declaration_line(&file, name))
                });
                let location = line.map_or(shown.clone(), |line| format!("{shown}:{line}"));
                eprintln!(
                    "{location}: {}[{}]: {}",
                    severity_word(found.diagnostic.severity),
                    found.diagnostic.code.id(),
                    found.diagnostic.message
                );
            }
        }
        match found.diagnostic.severity {
            compiler::Severity::Error => errors += 1,
            compiler::Severity::Warning => warnings += 1,
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

/// The 1-based line of `name = "NAME"` in a project file, where a declaration stored as data
/// begins.
fn declaration_line(file: &Path, name: &str) -> Option<usize> {
    let text = std::fs::read_to_string(file).ok()?;
    let needle = format!("name = \"{name}\"");
    let offset = text.find(&needle)?;
    Some(text[..offset].matches('\n').count() + 1)
}

/// The channel number (from 1) a finding about the Modbus device `device` names, as the build
/// words it: `Modbus device 'BeltDrive', channel 2 (GVL_Io.aiTemps): …` (`docs/modbus-master.md`
/// §3).
fn modbus_channel(device: &str, message: &str) -> Option<usize> {
    let rest = message.strip_prefix(&format!("Modbus device '{device}', channel "))?;
    let digits = rest.split(' ').next()?;
    digits.parse().ok()
}

/// The 1-based line of the `variable = "…"` key of channel `channel` (from 1) of the Modbus
/// device `device` in the manifest `file`, as the project files write it: the device's
/// `[[modbus_device]]` table with its `name`, then one `[[modbus_device.binding]]` table per
/// channel.
fn modbus_channel_line(file: &Path, device: &str, channel: usize) -> Option<usize> {
    let text = std::fs::read_to_string(file).ok()?;
    modbus_channel_line_in(&text, device, channel)
}

/// [`modbus_channel_line`] on the manifest's text.
fn modbus_channel_line_in(text: &str, device: &str, channel: usize) -> Option<usize> {
    let name = format!("name = \"{device}\"");
    // Whether the lines are in the device's tables, and how many channel tables began there.
    let mut in_device = false;
    let mut in_device_table = false;
    let mut channels = 0usize;
    for (index, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.starts_with('[') {
            in_device_table = line == "[[modbus_device]]";
            if in_device_table {
                in_device = false;
            } else if line == "[[modbus_device.binding]]" && in_device {
                channels += 1;
            } else if !line.starts_with("[modbus_device.") {
                in_device = false;
            }
            continue;
        }
        if in_device_table && line == name {
            in_device = true;
            channels = 0;
        } else if in_device && channels == channel && line.starts_with("variable =") {
            return Some(index + 1);
        }
    }
    None
}

fn severity_word(severity: compiler::Severity) -> &'static str {
    match severity {
        compiler::Severity::Error => "error",
        compiler::Severity::Warning => "warning",
    }
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
    // The file becomes a project of its own, so it is type-checked exactly like a folder.
    let source = compiler::source_project::SourceProject::new(&text);
    let shown = path.display().to_string();
    let mut findings: Vec<compiler::Diagnostic> = source.parse.errors().to_vec();
    findings.extend(source.diagnostics.iter().cloned());
    for found in compiler::sema::check_project(&source.project) {
        let mut diagnostic = found.diagnostic.clone();
        diagnostic.range = source.locate(&found).unwrap_or(0..0);
        findings.push(diagnostic);
    }
    findings.sort_by_key(|diagnostic| diagnostic.range.start);
    for diagnostic in &findings {
        eprint!("{}", diagnostic.render(&shown, &text));
    }
    let errors = findings
        .iter()
        .filter(|d| d.severity == compiler::Severity::Error)
        .count();
    let warnings = findings.len() - errors;
    if errors > 0 {
        anyhow::bail!("{shown}: {errors} error(s), {warnings} warning(s)");
    }
    println!("{shown}: no errors ({warnings} warning(s))");
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

/// Runs the checker on `path` to print its problems, and returns the error that ends the
/// command (also when, unexpectedly, the checker finds nothing).
pub(crate) fn check_for_errors(path: &Path) -> anyhow::Error {
    match check(path) {
        Err(error) => error,
        Ok(()) => anyhow::anyhow!("{}: the project does not compile", path.display()),
    }
}

/// Turns a load error into one message with a line per problem and a count.
pub(crate) fn describe_load_error(error: LoadError) -> anyhow::Error {
    let errors = error
        .problems
        .iter()
        .filter(|problem| problem.severity == project_model::Severity::Error)
        .count();
    anyhow::anyhow!(
        "{error}\n{errors} error(s); the project was not loaded and nothing was changed"
    )
}
