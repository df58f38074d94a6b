//! `rivet build` and `rivet simulate`: compile a project or one `.st` file into a program
//! image, and run it in-process on a simulated clock.

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::path::Path;

use anyhow::Context as _;
use compiler::CompileError;
use program_image::ProgramImage;
use project_model::load_project;
use runtime::engine::EngineChoice;
use runtime::simulation::Simulation;

use crate::simulation_writes::SimulationWrite;

/// Compiles `path` (a project folder or a `.st` file). Problems the checker finds are printed
/// as `rivet check` prints them.
pub fn compile_path(path: &Path) -> anyhow::Result<ProgramImage> {
    if !path.exists() {
        anyhow::bail!("{}: no such file or project folder", path.display());
    }
    let result = if path.is_file() {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("{}: cannot read it as UTF-8 text", path.display()))?;
        let source = compiler::SourceProject::new(&text);
        if !source.parse.errors().is_empty() {
            // The checker's report names every syntax error with its line.
            return Err(crate::cli::check_for_errors(path));
        }
        compiler::compile_source(&source, &path.display().to_string())
    } else {
        let loaded = load_project(path).map_err(crate::cli::describe_load_error)?;
        compiler::compile_project(&loaded.project)
    };
    match result {
        Ok(image) => Ok(image),
        Err(CompileError::Diagnostics(_)) => Err(crate::cli::check_for_errors(path)),
        Err(CompileError::Unsupported(error)) => {
            anyhow::bail!("{}: cannot compile: {error}", path.display())
        }
    }
}

/// `rivet build PROJECT -o FILE`.
pub fn build(path: &Path, output: &Path) -> anyhow::Result<()> {
    let image = compile_path(path)?;
    let bytes = image.encode();
    let temporary = output.with_extension("tmp");
    std::fs::write(&temporary, &bytes)
        .and_then(|()| std::fs::rename(&temporary, output))
        .with_context(|| format!("{}: cannot write the image", output.display()))?;
    let hash: String = program_image::identity_of(&bytes)[..8]
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    println!(
        "{}: {} POUs, {} tasks, {} symbols, {} bytes, identity {hash}…",
        output.display(),
        image.pous.len(),
        image.tasks.len(),
        image.symbols.len(),
        bytes.len()
    );
    Ok(())
}

/// `rivet simulate PATH --cycles N --watch A,B [--set CYCLE:PATH=VALUE]… [--json]
/// [--engine native|interpreter]`.
pub fn simulate(
    path: &Path,
    cycles: u64,
    watch: &[String],
    writes: &[String],
    json: bool,
    engine: EngineChoice,
) -> anyhow::Result<()> {
    let image = compile_path(path)?;
    // Unknown variables and values that do not fit are refused before anything runs.
    for name in watch {
        runtime::value::resolve(&image, name)
            .map_err(|error| anyhow::anyhow!("--watch {name}: {error}"))?;
    }
    let writes = writes
        .iter()
        .map(|write| SimulationWrite::parse(write, &image, cycles))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let (mut simulation, report) =
        Simulation::with_choice(image, engine).context("the compiled image does not load")?;
    // Standard output stays the watched values; what runs in the interpreter although the
    // native engine was chosen is a note on standard error (docs/native-engine.md §8.2).
    for line in report.lines() {
        eprintln!("note: {line}");
    }
    // The cycles run in stretches from one write to the next; the writes of one cycle are made
    // in the order given, so a later one wins.
    let mut cycles_run = 0;
    let mut write_cycles: Vec<u64> = writes.iter().map(|write| write.cycle).collect();
    write_cycles.sort_unstable();
    write_cycles.dedup();
    for cycle in write_cycles {
        simulation.run(cycle - 1 - cycles_run);
        cycles_run = cycle - 1;
        for write in writes.iter().filter(|write| write.cycle == cycle) {
            write.apply(simulation.engine_mut());
        }
    }
    simulation.run(cycles - cycles_run);
    let mut values = Vec::new();
    for name in watch {
        let value = runtime::value::read(simulation.engine(), name)
            .map_err(|error| anyhow::anyhow!("--watch {name}: {error}"))?;
        values.push((name, value));
    }
    if json {
        let fields: Vec<String> = values
            .iter()
            .map(|(name, value)| {
                format!("{}: {}", runtime::value::json_string(name), value.to_json())
            })
            .collect();
        println!("{{{}}}", fields.join(", "));
    } else {
        for (name, value) in &values {
            println!("{name} = {value}");
        }
    }
    for fault in simulation.faults() {
        eprintln!("fault: {fault}");
    }
    if !simulation.faults().is_empty() {
        anyhow::bail!("{} task(s) stopped with a fault", simulation.faults().len());
    }
    Ok(())
}
