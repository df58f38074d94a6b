//! The arguments of the debugging commands (`docs/debugging.md` §7) as clap parses them:
//! what every command takes (`DebugTarget`) and each command's own options.

use std::path::PathBuf;

use online::{HitMode, HitRule};

use crate::online_cli::Target;

/// What every debugging command takes: the target, the project it runs, the linger.
#[derive(Clone, Debug, clap::Args)]
pub struct DebugTarget {
    /// The runtime to talk to.
    #[command(flatten)]
    pub target: Target,
    /// The project the target runs (a folder or a `.st` file), to turn places into
    /// statements; the current folder by default.
    #[arg(long, default_value = ".")]
    pub project: PathBuf,
    /// How long the debug session stays, breakpoints and halts included, after this
    /// command's connection closes, for the next command to take it over (at most 300).
    #[arg(long, default_value_t = 60, value_parser = clap::value_parser!(u16).range(0..=300))]
    pub linger: u16,
}

/// `rivet break`: set, list or clear breakpoints.
#[derive(Clone, Debug, clap::Args)]
pub struct BreakArgs {
    /// Where: `FILE:LINE` (a unique end of the path: `FB_Counter.st:12`) or `POU:LINE`.
    #[arg(required_unless_present_any = ["list", "clear", "clear_all"])]
    pub place: Option<String>,
    /// Halt only on this instance (`Main.fbA`).
    #[arg(long)]
    pub instance: Option<String>,
    /// Halt only this task.
    #[arg(long)]
    pub task: Option<String>,
    /// Halt only when this BOOL expression is TRUE (`iCount > 100`).
    #[arg(long = "if", value_name = "EXPR")]
    pub condition: Option<String>,
    /// Halt at the N-th hit only.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..), conflicts_with_all = ["hits_multiple", "hits_from"])]
    pub hits: Option<u32>,
    /// Halt at every hit whose count is a multiple of N.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..), conflicts_with = "hits_from")]
    pub hits_multiple: Option<u32>,
    /// Halt at every hit from the N-th on.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub hits_from: Option<u32>,
    /// Wait this many seconds for a halt at the breakpoint, and show it.
    #[arg(long, value_name = "SECONDS")]
    pub wait: Option<u64>,
    /// List the breakpoints.
    #[arg(long, conflicts_with_all = ["place", "clear", "clear_all"])]
    pub list: bool,
    /// Clear the breakpoints with these ids.
    #[arg(long, value_name = "ID", num_args = 1.., conflicts_with_all = ["place", "clear_all"])]
    pub clear: Vec<u16>,
    /// Clear every breakpoint.
    #[arg(long, conflicts_with = "place")]
    pub clear_all: bool,
    /// Where the target is and what it runs.
    #[command(flatten)]
    pub debug: DebugTarget,
}

/// `rivet step into|over|out`.
#[derive(Clone, Debug, clap::Args)]
pub struct StepArgs {
    /// into, over or out.
    #[arg(value_parser = ["into", "over", "out"])]
    pub kind: String,
    /// The halted task (by default the only halted one).
    #[arg(long)]
    pub task: Option<String>,
    /// How many seconds to wait for the step to end.
    #[arg(long, value_name = "SECONDS", default_value_t = 10)]
    pub wait: u64,
    /// Where the target is and what it runs.
    #[command(flatten)]
    pub debug: DebugTarget,
}

/// `rivet continue`.
#[derive(Clone, Debug, clap::Args)]
pub struct ContinueArgs {
    /// The halted task (by default the only halted one).
    #[arg(long, conflicts_with = "all")]
    pub task: Option<String>,
    /// Every task, ending "halt all".
    #[arg(long)]
    pub all: bool,
    /// Run to this place (`FILE:LINE`) rather than to the next breakpoint.
    #[arg(long, value_name = "PLACE", conflicts_with_all = ["all", "end"])]
    pub to: Option<String>,
    /// Wait this many seconds for the next halt, and show it.
    #[arg(long, value_name = "SECONDS")]
    pub wait: Option<u64>,
    /// End the debug session: clear every breakpoint and let every task run on.
    #[arg(long, conflicts_with_all = ["task", "all", "wait"])]
    pub end: bool,
    /// Where the target is and what it runs.
    #[command(flatten)]
    pub debug: DebugTarget,
}

/// `rivet halt`.
#[derive(Clone, Debug, clap::Args)]
pub struct HaltArgs {
    /// The task to halt (by default the program's only task).
    #[arg(long, conflicts_with = "all")]
    pub task: Option<String>,
    /// Halt every task ("halt all").
    #[arg(long)]
    pub all: bool,
    /// How many seconds to wait for the halt.
    #[arg(long, value_name = "SECONDS", default_value_t = 10)]
    pub wait: u64,
    /// Where the target is and what it runs.
    #[command(flatten)]
    pub debug: DebugTarget,
}

/// `rivet stack`.
#[derive(Clone, Debug, clap::Args)]
pub struct StackArgs {
    /// The halted task (by default the only halted one).
    #[arg(long)]
    pub task: Option<String>,
    /// Show each frame's variables with their values.
    #[arg(long)]
    pub values: bool,
    /// Show only this frame (0 the innermost).
    #[arg(long, value_name = "N")]
    pub frame: Option<usize>,
    /// Where the target is and what it runs.
    #[command(flatten)]
    pub debug: DebugTarget,
}

/// `rivet flow POU`.
#[derive(Clone, Debug, clap::Args)]
pub struct FlowArgs {
    /// The POU whose statements are recorded (`FB_Counter`, `FB_Counter.Reset`).
    pub pou: String,
    /// Only on this instance (`Main.fbA`); every instance by default.
    #[arg(long)]
    pub instance: Option<String>,
    /// The task whose cycle is recorded (by default the program's only task).
    #[arg(long)]
    pub task: Option<String>,
    /// How many seconds to wait for a recorded cycle.
    #[arg(long, value_name = "SECONDS", default_value_t = 10)]
    pub wait: u64,
    /// Where the target is and what it runs.
    #[command(flatten)]
    pub debug: DebugTarget,
}

/// One debugging command.
#[derive(Clone, Debug)]
pub enum DebugCommand {
    /// `rivet break`.
    Break(BreakArgs),
    /// `rivet step`.
    Step(StepArgs),
    /// `rivet continue`.
    Continue(ContinueArgs),
    /// `rivet halt`.
    Halt(HaltArgs),
    /// `rivet stack`.
    Stack(StackArgs),
    /// `rivet flow`.
    Flow(FlowArgs),
}

impl DebugCommand {
    /// Where the target is and what it runs, which every command takes.
    pub fn target(&self) -> &DebugTarget {
        match self {
            DebugCommand::Break(args) => &args.debug,
            DebugCommand::Step(args) => &args.debug,
            DebugCommand::Continue(args) => &args.debug,
            DebugCommand::Halt(args) => &args.debug,
            DebugCommand::Stack(args) => &args.debug,
            DebugCommand::Flow(args) => &args.debug,
        }
    }
}

/// The hit rule `--hits`, `--hits-multiple` and `--hits-from` give.
pub(crate) fn hit_rule(args: &BreakArgs) -> HitRule {
    match (args.hits, args.hits_multiple, args.hits_from) {
        (Some(target), _, _) => HitRule {
            mode: HitMode::Equal,
            target,
        },
        (_, Some(target), _) => HitRule {
            mode: HitMode::Multiple,
            target,
        },
        (_, _, Some(target)) => HitRule {
            mode: HitMode::AtLeast,
            target,
        },
        _ => HitRule::ALWAYS,
    }
}
