//! The debugging commands of the command line (`docs/debugging.md` §7): `rivet break`,
//! `step`, `continue`, `halt`, `stack` and `flow`, over the debugging services of
//! `docs/protocol.md` §6. Each command is one connection; the debug session lingers between
//! them (`--linger`), so the next command takes it over.

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use anyhow::Context as _;
use online::{
    ALL_TASKS, BreakpointSpec, Client, DebugOptions, FlowCycle, FlowEntry, FrameRange, HitMode,
    Identity, Place, StepKind, TaskDebugState, TaskHalt,
};
use program_image::{FrameVariableKind, ProgramImage, StructKind, TypeDef};

use crate::debug_args::hit_rule;
pub use crate::debug_args::{
    BreakArgs, ContinueArgs, DebugCommand, DebugTarget, FlowArgs, HaltArgs, StackArgs, StepArgs,
};
use crate::debug_bodies::GraphicalBodies;
use crate::debug_places::{Statement, instance_owner, statement_at};
use crate::debug_text::{
    describe_breakpoint, describe_frame, describe_halt, describe_hit_rule, describe_place,
    describe_stack_header, describe_task_filter, task_name,
};

/// How often a command that waits for a halt asks for the halt state.
const POLL_INTERVAL: Duration = Duration::from_millis(20);

/// The most bytes of one value a `READ` answer carries: its 250 bytes of payload less the
/// cycle and one byte of forced bitmap (`docs/protocol.md` §3).
const READ_VALUE_MOST_BYTES: u64 = 250 - 9;

/// The pointer region of the data region (`docs/program-image.md` §5.2), in bits 56–63.
const DATA_POINTER: u64 = 1 << 56;

/// The build the commands work with, and the target running it.
struct Session {
    client: Client,
    image: ProgramImage,
    /// The project's graphical bodies, for places in them.
    bodies: GraphicalBodies,
    project: PathBuf,
    linger_s: u16,
}

/// Runs a debugging command to its end.
pub fn run(command: DebugCommand) -> anyhow::Result<()> {
    let debug = command.target().clone();
    let image = crate::build_cli::compile_path(&debug.project)?;
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .context("cannot start the async runtime")?;
    runtime.block_on(async move {
        let (client, identity) = crate::online_cli::connect(&debug.target).await?;
        same_build(&image, &identity, &debug.project)?;
        let bodies = graphical_bodies(&debug.project)?;
        let mut session = Session {
            client,
            image,
            bodies,
            project: debug.project.clone(),
            linger_s: debug.linger,
        };
        match command {
            DebugCommand::Break(args) => session.breakpoints(&args).await,
            DebugCommand::Step(args) => session.step(&args).await,
            DebugCommand::Continue(args) => session.resume(&args).await,
            DebugCommand::Halt(args) => session.halt(&args).await,
            DebugCommand::Stack(args) => session.stack(&args).await,
            DebugCommand::Flow(args) => session.flow(&args).await,
        }
    })
}

/// The graphical bodies of the project folder `project`; none for a `.st` file.
fn graphical_bodies(project: &Path) -> anyhow::Result<GraphicalBodies> {
    if project.is_file() {
        return Ok(GraphicalBodies::default());
    }
    let loaded = project_model::load_project(project).map_err(crate::cli::describe_load_error)?;
    Ok(GraphicalBodies::of_project(&loaded.project))
}

/// Refuses a target that runs another build than `image`, naming both identities.
fn same_build(image: &ProgramImage, identity: &Identity, project: &Path) -> anyhow::Result<()> {
    let ours = image.identity();
    let short = |hash: &[u8; 32]| crate::value_text::hex(&hash[..8]);
    match identity.image_hash {
        Some(theirs) if theirs == ours => Ok(()),
        Some(theirs) => anyhow::bail!(
            "the target runs another build (identity {}) than {} gives (identity {}); download it first: rivet download {}",
            short(&theirs),
            project.display(),
            short(&ours),
            project.display()
        ),
        None => anyhow::bail!(
            "the target has no program; download it first: rivet download {}",
            project.display()
        ),
    }
}

impl Session {
    /// The statement a place names, in a graphical body or by its line.
    fn statement_at(&self, place: &str) -> Result<Statement, crate::debug_places::PlaceError> {
        match self.bodies.statement_at(&self.image, place) {
            Some(found) => found,
            None => statement_at(&self.image, place),
        }
    }

    /// A statement as the commands print it: `pous/FB_Counter.st:12 (FB_Counter)`, or its
    /// network and element in a graphical body.
    fn shown(&self, statement: &Statement) -> String {
        match self.bodies.place_of(statement) {
            Some(place) => format!("{place} ({})", statement.pou_name),
            None => statement.to_string(),
        }
    }

    /// Attaches the debug session to this connection (taking a lingering one over).
    async fn attach(&mut self) -> anyhow::Result<()> {
        self.client
            .debug_attach(self.linger_s, DebugOptions::default())
            .await?;
        Ok(())
    }

    /// The index of the task named `name`.
    fn task_named(&self, name: &str) -> anyhow::Result<u8> {
        task_index(&self.image, name)
    }

    /// The task `--task` names, or else the only halted task.
    async fn halted_task(&mut self, name: Option<&str>) -> anyhow::Result<u8> {
        if let Some(name) = name {
            return self.task_named(name);
        }
        let state = self.client.halt_state().await?;
        let halted: Vec<&TaskHalt> = state
            .tasks
            .iter()
            .filter(|task| task.state == TaskDebugState::Halted)
            .collect();
        match halted.as_slice() {
            [one] => Ok(one.task),
            [] => anyhow::bail!(
                "no task is halted; rivet break sets a breakpoint, rivet halt halts a task"
            ),
            several => {
                let names: Vec<String> = several
                    .iter()
                    .map(|task| format!("'{}'", task_name(&self.image, task.task)))
                    .collect();
                anyhow::bail!(
                    "tasks {} are halted: name one with --task",
                    names.join(", ")
                )
            }
        }
    }

    /// The task `--task` names, or else the program's only task.
    fn task_or_only(&self, name: Option<&str>) -> anyhow::Result<u8> {
        match (name, self.image.tasks.len()) {
            (Some(name), _) => self.task_named(name),
            (None, 1) => Ok(0),
            (None, _) => anyhow::bail!(
                "the program has several tasks ({}): name one with --task",
                task_names(&self.image)
            ),
        }
    }

    /// The pointer value of the instance at `path`, resolved by the target and checked to be
    /// an instance the code of POU `pou` runs on.
    async fn instance(&mut self, path: &str, pou: u32) -> anyhow::Result<u64> {
        let resolved = self.client.resolve(path).await?;
        let owner = instance_owner(&self.image, pou).with_context(|| {
            format!(
                "--instance {path}: '{}' is a function, which runs on no instance",
                self.image.pous[pou as usize].name
            )
        })?;
        let pointer = DATA_POINTER | u64::from(resolved.place.offset);
        if resolved.place.region != 0 || self.image.instance_path(pointer, Some(owner)).is_none() {
            anyhow::bail!("--instance {path}: not an instance of {owner}");
        }
        Ok(pointer)
    }

    /// `rivet break`.
    async fn breakpoints(&mut self, args: &BreakArgs) -> anyhow::Result<()> {
        if args.list {
            let list = self.client.break_list().await?;
            if list.is_empty() {
                println!("no breakpoints");
            }
            for breakpoint in &list {
                println!(
                    "{}",
                    describe_breakpoint(&self.image, &self.bodies, breakpoint)
                );
            }
            return Ok(());
        }
        if args.clear_all {
            self.attach().await?;
            let count = self.client.break_list().await?.len();
            self.client.break_clear(None).await?;
            println!("cleared {count} breakpoint(s)");
            return Ok(());
        }
        if !args.clear.is_empty() {
            self.attach().await?;
            for id in &args.clear {
                self.client.break_clear(Some(*id)).await?;
            }
            println!("cleared {} breakpoint(s)", args.clear.len());
            return Ok(());
        }
        let place = args.place.as_deref().context("name the place: FILE:LINE")?;
        let statement = self.statement_at(place)?;
        let instance = match &args.instance {
            Some(path) => self.instance(path, statement.pou).await?,
            None => 0,
        };
        let task = match &args.task {
            Some(name) => self.task_named(name)?,
            None => ALL_TASKS,
        };
        let condition = match &args.condition {
            Some(expression) => self.condition(&statement, expression)?,
            None => Vec::new(),
        };
        let hit = hit_rule(args);
        // Only a place, instance and condition that are right change the target.
        self.attach().await?;
        let spec = BreakpointSpec {
            pou: statement.pou,
            instruction: statement.instruction,
            instance,
            task,
            hit,
            condition,
        };
        let before = self.client.halt_state().await?.generation;
        let (id, replaced) = self.client.break_set(&spec).await?;
        let mut line = format!("breakpoint {id} at {}, ", self.shown(&statement));
        match &args.instance {
            Some(path) => line.push_str(&format!("instance {path}")),
            None => line.push_str("every instance"),
        }
        line.push_str(&format!(", {}", describe_task_filter(&self.image, task)));
        if let Some(expression) = &args.condition {
            line.push_str(&format!(", if {expression}"));
        }
        if hit.mode != HitMode::Always {
            line.push_str(&format!(", {}", describe_hit_rule(hit)));
        }
        if replaced {
            line.push_str(" (replaces the one set there before)");
        }
        println!("{line}");
        if let Some(wait_s) = args.wait {
            let halt = self
                .wait_for_halt(None, before, wait_s, |halt| halt.breakpoint == Some(id))
                .await?;
            println!("{}", self.describe(&halt, None).await?);
        }
        Ok(())
    }

    /// The compiled condition's bytes for the POU of `statement`.
    fn condition(&self, statement: &Statement, expression: &str) -> anyhow::Result<Vec<u8>> {
        let compiled = if self.project.is_file() {
            let text = std::fs::read_to_string(&self.project)
                .with_context(|| format!("{}: cannot read it", self.project.display()))?;
            let source = compiler::SourceProject::new(&text);
            let name = self.project.display().to_string();
            compiler::compile_source_condition(&source, &name, &statement.pou_name, expression)
        } else {
            let loaded = project_model::load_project(&self.project)
                .map_err(crate::cli::describe_load_error)?;
            compiler::compile_condition(&loaded.project, &statement.pou_name, expression)
        }
        .with_context(|| format!("--if {expression}"))?;
        if compiled.image != self.image.identity() || compiled.pou != statement.pou {
            anyhow::bail!(
                "--if {expression}: {} changed while the condition was compiled; try again",
                self.project.display()
            );
        }
        Ok(compiled.condition.encode())
    }

    /// `rivet step`.
    async fn step(&mut self, args: &StepArgs) -> anyhow::Result<()> {
        let kind = match args.kind.as_str() {
            "into" => StepKind::Into,
            "out" => StepKind::Out,
            _ => StepKind::Over,
        };
        self.attach().await?;
        let task = self.halted_task(args.task.as_deref()).await?;
        let before = self.client.halt_state().await?.generation;
        self.client.step(task, kind).await?;
        let halt = self
            .wait_for_halt(Some(task), before, args.wait, |_| true)
            .await?;
        println!("{}", self.describe(&halt, Some(kind)).await?);
        Ok(())
    }

    /// `rivet continue`.
    async fn resume(&mut self, args: &ContinueArgs) -> anyhow::Result<()> {
        let target = match &args.to {
            Some(place) => Some(self.statement_at(place)?),
            None => None,
        };
        self.attach().await?;
        if args.end {
            self.client.debug_detach().await?;
            println!("the debug session ended: every breakpoint is cleared and every task runs on");
            return Ok(());
        }
        let before = self.client.halt_state().await?.generation;
        let task = if args.all {
            self.client.continue_task(ALL_TASKS).await?;
            println!("every task runs on");
            None
        } else {
            let task = self.halted_task(args.task.as_deref()).await?;
            match target {
                Some(statement) => {
                    self.client
                        .run_to(task, statement.pou, statement.instruction)
                        .await?;
                    println!(
                        "task '{}' runs to {}",
                        task_name(&self.image, task),
                        self.shown(&statement)
                    );
                }
                None => {
                    self.client.continue_task(task).await?;
                    println!("task '{}' runs on", task_name(&self.image, task));
                }
            }
            Some(task)
        };
        if let Some(wait_s) = args.wait.or(args.to.as_ref().map(|_| 10)) {
            let halt = self.wait_for_halt(task, before, wait_s, |_| true).await?;
            println!("{}", self.describe(&halt, None).await?);
        }
        Ok(())
    }

    /// `rivet halt`.
    async fn halt(&mut self, args: &HaltArgs) -> anyhow::Result<()> {
        let task = if args.all {
            None
        } else {
            Some(self.task_or_only(args.task.as_deref())?)
        };
        self.attach().await?;
        let state = self.client.halt_state().await?;
        let before = state.generation;
        self.client.halt(task.unwrap_or(ALL_TASKS)).await?;
        // A task halted already stays where it is, so there is no new halt to wait for.
        let already = state.tasks.iter().find(|halt| {
            halt.state == TaskDebugState::Halted && task.is_none_or(|task| halt.task == task)
        });
        if let Some(halt) = already {
            println!("{}", self.describe(halt, None).await?);
            return Ok(());
        }
        let halt = self
            .wait_for_halt(task, before, args.wait, |_| true)
            .await?;
        println!("{}", self.describe(&halt, None).await?);
        Ok(())
    }

    /// `rivet stack`.
    async fn stack(&mut self, args: &StackArgs) -> anyhow::Result<()> {
        let task = match &args.task {
            Some(name) => self.task_named(name)?,
            None => self.halted_task(None).await?,
        };
        let state = self.client.halt_state().await?;
        let halt = state
            .tasks
            .iter()
            .find(|halt| halt.task == task)
            .copied()
            .with_context(|| {
                format!(
                    "the target lists no task '{}'",
                    task_name(&self.image, task)
                )
            })?;
        if !matches!(halt.state, TaskDebugState::Halted | TaskDebugState::Waiting) {
            anyhow::bail!(
                "task '{}' is not halted; rivet halt --task {} halts it",
                task_name(&self.image, task),
                task_name(&self.image, task)
            );
        }
        let hits = self.hits_of(&halt).await?;
        println!("{}", describe_stack_header(&self.image, &halt, hits));
        let frames = self.client.stack(task).await?;
        for (index, frame) in frames.iter().enumerate() {
            if args.frame.is_some_and(|only| only != index) {
                continue;
            }
            println!(
                "{}",
                describe_frame(&self.image, &self.bodies, index, frame)
            );
            if args.values {
                for (name, value) in self.frame_values(task, index, frame).await? {
                    println!("    {name} = {value}");
                }
            }
        }
        if let Some(only) = args.frame.filter(|&only| only >= frames.len()) {
            anyhow::bail!("--frame {only}: the stack has {} frame(s)", frames.len());
        }
        Ok(())
    }

    /// The variables of one frame with their values: its instance's, then those in the frame
    /// (a function's or method's parameters, result and locals, a body's VAR_TEMP) as the
    /// image's debug section names them.
    async fn frame_values(
        &mut self,
        task: u8,
        index: usize,
        frame: &online::StackFrame,
    ) -> anyhow::Result<Vec<(String, String)>> {
        let mut values = Vec::new();
        if let Some(members) = instance_members(&self.image, frame.pou, frame.instance) {
            let places: Vec<Place> = members.iter().map(|(_, _, place)| *place).collect();
            let snapshot = self.client.read(&places).await?;
            for ((name, ty, _), (bytes, _)) in members.iter().zip(&snapshot.values) {
                let value = runtime::value::decode(&self.image, *ty, bytes);
                values.push((name.clone(), value.to_string()));
            }
        }
        let variables = self
            .image
            .debug
            .as_ref()
            .and_then(|debug| debug.pous.get(frame.pou as usize))
            .map(|pou| pou.frame.clone())
            .unwrap_or_default();
        let shown: Vec<_> = variables
            .iter()
            .filter(|variable| !variable.name.contains("__"))
            .collect();
        let ranges: Vec<FrameRange> = shown
            .iter()
            .map(|variable| FrameRange {
                offset: variable.offset,
                size: variable
                    .size_bytes(&self.image.types)
                    .min(u64::from(u16::MAX)) as u16,
            })
            .collect();
        if ranges.is_empty() {
            return Ok(values);
        }
        let frame_index = u16::try_from(index).unwrap_or(u16::MAX);
        let bytes = self.client.frame_read(task, frame_index, &ranges).await?;
        for (variable, bytes) in shown.iter().zip(&bytes) {
            let text = if variable.kind == FrameVariableKind::InOut {
                let mut raw = [0u8; 8];
                let n = bytes.len().min(8);
                raw[..n].copy_from_slice(&bytes[..n]);
                format!("(VAR_IN_OUT, pointer 16#{:X})", u64::from_le_bytes(raw))
            } else {
                runtime::value::decode(&self.image, variable.ty, bytes).to_string()
            };
            values.push((variable.name.clone(), text));
        }
        Ok(values)
    }

    /// `rivet flow`.
    async fn flow(&mut self, args: &FlowArgs) -> anyhow::Result<()> {
        let pou = self
            .image
            .pous
            .iter()
            .position(|pou| pou.name.eq_ignore_ascii_case(args.pou.trim()))
            .with_context(|| {
                format!(
                    "'{}' is no POU of the program (a method or action is named 'FB_Name.Member')",
                    args.pou
                )
            })? as u32;
        let task = self.task_or_only(args.task.as_deref())?;
        let instance = match &args.instance {
            Some(path) => self.instance(path, pou).await?,
            None => 0,
        };
        self.attach().await?;
        self.client
            .flow_configure(task, &[FlowEntry { pou, instance }])
            .await?;
        let deadline = Instant::now() + Duration::from_secs(args.wait);
        let flow = loop {
            let flow = self.client.flow_read(0, FlowCycle::LastComplete).await?;
            if flow.cycle != 0 {
                break flow;
            }
            if Instant::now() >= deadline {
                self.client.flow_configure(task, &[]).await?;
                anyhow::bail!(
                    "task '{}' has finished no cycle within {} s",
                    task_name(&self.image, task),
                    args.wait
                );
            }
            tokio::time::sleep(POLL_INTERVAL).await;
        };
        self.client.flow_configure(task, &[]).await?;
        let code = &self.image.pous[pou as usize];
        println!(
            "cycle {} of task '{}': the statements of {} that ran",
            flow.cycle,
            task_name(&self.image, task),
            code.name
        );
        let mut printed = std::collections::BTreeSet::new();
        for (index, entry) in code.lines.iter().enumerate() {
            if flow.ran(index) && printed.insert((entry.file, entry.line)) {
                println!(
                    "{}",
                    describe_place(&self.image, &self.bodies, pou, entry.index)
                );
            }
        }
        if printed.is_empty() {
            println!("(none)");
        }
        Ok(())
    }

    /// The hit count of the breakpoint a task halted at.
    async fn hits_of(&mut self, halt: &TaskHalt) -> anyhow::Result<Option<u32>> {
        let Some(id) = halt.breakpoint else {
            return Ok(None);
        };
        let list = self.client.break_list().await?;
        Ok(list.iter().find(|b| b.id == id).map(|b| b.hits))
    }

    /// A halt in words, with the innermost frame's instance.
    async fn describe(
        &mut self,
        halt: &TaskHalt,
        step: Option<StepKind>,
    ) -> anyhow::Result<String> {
        let frames = self.client.stack(halt.task).await?;
        let instance = frames.first().map_or(0, |frame| frame.instance);
        let hits = self.hits_of(halt).await?;
        Ok(describe_halt(
            &self.image,
            &self.bodies,
            halt,
            instance,
            hits,
            step,
        ))
    }

    /// Waits until `task` (or any task) is halted in a state newer than `generation` and
    /// `accept`s the halt, for at most `wait_s` seconds.
    async fn wait_for_halt(
        &mut self,
        task: Option<u8>,
        generation: u32,
        wait_s: u64,
        accept: impl Fn(&TaskHalt) -> bool,
    ) -> anyhow::Result<TaskHalt> {
        let deadline = Instant::now() + Duration::from_secs(wait_s);
        loop {
            let state = self.client.halt_state().await?;
            if state.generation != generation {
                let halted = state.tasks.iter().find(|halt| {
                    halt.state == TaskDebugState::Halted
                        && task.is_none_or(|task| halt.task == task)
                        && accept(halt)
                });
                if let Some(halt) = halted {
                    return Ok(*halt);
                }
            }
            if Instant::now() >= deadline {
                let who = match task {
                    Some(task) => format!("task '{}' has", task_name(&self.image, task)),
                    None => "no task has".to_owned(),
                };
                anyhow::bail!(
                    "{who} not halted within {wait_s} s; rivet stack shows where it halts"
                );
            }
            tokio::time::sleep(POLL_INTERVAL).await;
        }
    }
}

/// The index of the task named `name` (in any case), or an error listing the tasks.
fn task_index(image: &ProgramImage, name: &str) -> anyhow::Result<u8> {
    let index = image
        .tasks
        .iter()
        .position(|task| task.name.eq_ignore_ascii_case(name.trim()))
        .with_context(|| {
            format!(
                "--task {name}: the program's tasks are {}",
                task_names(image)
            )
        })?;
    u8::try_from(index).context("a program with more than 255 tasks cannot be debugged")
}

/// The program's task names, quoted and comma-separated.
fn task_names(image: &ProgramImage) -> String {
    image
        .tasks
        .iter()
        .map(|task| format!("'{}'", task.name))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The members of the instance `instance` that POU `pou` runs on, each with its type and its
/// place in the data region; `None` for a function or a pointer outside the data region.
/// Located members and the compiler's hidden ones (with `__`) are left out, and so are
/// values too big for one read.
fn instance_members(
    image: &ProgramImage,
    pou: u32,
    instance: u64,
) -> Option<Vec<(String, program_image::TypeId, Place)>> {
    let owner = instance_owner(image, pou)?;
    if instance >> 56 != DATA_POINTER >> 56 {
        return None;
    }
    let base = u32::try_from(instance & (DATA_POINTER - 1)).ok()?;
    let members = image.types.iter().find_map(|ty| match ty {
        TypeDef::Struct {
            name,
            kind: StructKind::FunctionBlock | StructKind::Program,
            members,
            ..
        } if name.eq_ignore_ascii_case(owner) => Some(members),
        _ => None,
    })?;
    let most = READ_VALUE_MOST_BYTES;
    Some(
        members
            .iter()
            .filter(|member| member.located.is_none() && !member.name.contains("__"))
            .filter_map(|member| {
                let size = image
                    .types
                    .get(member.ty as usize)?
                    .size_bytes(&image.types);
                (size > 0 && size <= most).then(|| {
                    let place = Place {
                        region: 0,
                        offset: base.saturating_add(member.offset),
                        bit: None,
                        size: size as u16,
                    };
                    (member.name.clone(), member.ty, place)
                })
            })
            .collect(),
    )
}

#[cfg(test)]
#[path = "debug_cli_tests.rs"]
mod tests;
