//! The online commands of the command line: `rivet status`, `download`, `start`, `stop`,
//! `reset`, `read`, `write`, `force`, `unforce`, `forces`, `faults`, `devices`, each against
//! `--target HOST:PORT` over Rivet's online protocol (`docs/protocol.md`).

#![allow(clippy::print_stdout, clippy::print_stderr)] // Printing is what a CLI is for.

use std::net::SocketAddr;
use std::path::Path;

use anyhow::Context as _;
use online::{Client, Enumeration, OnlineError, Place, Reset, Resolved, TYPE_ENUM};

use crate::value_text::{describe_place, hex, show_typed};

/// Where and how to connect.
#[derive(Clone, Debug, clap::Args)]
pub struct Target {
    /// The runtime's address.
    #[arg(long, default_value = "127.0.0.1:5020")]
    pub target: String,
    /// A file whose first line is the runtime's password, when it has one; the password may
    /// also be given in the environment variable RIVET_PASSWORD.
    #[arg(long)]
    pub password_file: Option<std::path::PathBuf>,
    /// No longer accepted (visible in the process list): refused with a message saying where
    /// the password goes now.
    #[arg(long, hide = true)]
    pub password: Option<String>,
}

impl Target {
    /// The password from `--password-file` or RIVET_PASSWORD, if either gives one.
    fn password(&self) -> anyhow::Result<Option<String>> {
        use runtime::online::{PASSWORD_VARIABLE, read_password};
        Ok(read_password(
            self.password.as_deref(),
            self.password_file.as_deref(),
            std::env::var_os(PASSWORD_VARIABLE),
        )?)
    }

    fn address(&self) -> anyhow::Result<SocketAddr> {
        use std::net::ToSocketAddrs as _;
        self.target
            .to_socket_addrs()
            .with_context(|| {
                format!(
                    "--target {}: not an address such as 127.0.0.1:5020",
                    self.target
                )
            })?
            .next()
            .with_context(|| format!("--target {}: the name resolves to no address", self.target))
    }
}

/// Connects to the target, logging in when a password is given.
pub(crate) async fn connect(target: &Target) -> anyhow::Result<(Client, online::Identity)> {
    let address = target.address()?;
    let password = target.password()?;
    Ok(Client::connect(address, password.as_deref()).await?)
}

/// One online command.
#[derive(Debug)]
pub enum OnlineCommand {
    /// Identity, tasks and forces.
    Status,
    /// Compile and download a project or `.st` file.
    Download {
        /// The project folder or source file.
        project: std::path::PathBuf,
        /// Start the program once loaded.
        start: bool,
    },
    /// Compile a project or `.st` file and change the running program to it online.
    OnlineChange {
        /// The project folder or source file.
        project: std::path::PathBuf,
        /// Check and list only.
        dry_run: bool,
    },
    /// Start the program.
    Start,
    /// Stop the program.
    Stop,
    /// Reset the program's memory.
    Reset(Reset),
    /// Read variables.
    Read(Vec<String>),
    /// Write values once.
    Write(Vec<String>),
    /// Force values.
    Force(Vec<String>),
    /// Release forces (all when empty).
    Unforce(Vec<String>),
    /// List forces.
    Forces,
    /// List faults.
    Faults,
    /// List the Modbus devices the runtime masters, with their states and counters.
    Devices,
    /// Record a trace on the target and save it as CSV.
    Trace(TraceRequest),
}

/// What `rivet trace` records.
#[derive(Clone, Debug)]
pub struct TraceRequest {
    /// The variables.
    pub variables: Vec<String>,
    /// The task by name.
    pub task: String,
    /// How many samples.
    pub samples: u32,
    /// Every n-th cycle.
    pub every: u16,
    /// The trigger variable and its kind (`rising`, `falling`, `level`).
    pub trigger: Option<(String, String)>,
    /// Percent of samples before the trigger.
    pub pretrigger: u8,
    /// Where to write the CSV.
    pub csv: std::path::PathBuf,
}

/// Runs an online command to its end.
pub fn run(target: &Target, command: OnlineCommand) -> anyhow::Result<()> {
    let address = target.address()?;
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .context("cannot start the async runtime")?;
    runtime.block_on(async move {
        let password = target.password()?;
        let (mut client, identity) = Client::connect(address, password.as_deref()).await?;
        match command {
            OnlineCommand::Status => {
                println!("{address}: rivet-runtime {}, {}", identity.runtime_version, identity.state.describe());
                match identity.image_hash {
                    Some(hash) => println!("program: '{}', identity {}", identity.project, hex(&hash[..8])),
                    None => println!("program: none"),
                }
                if identity.password_required {
                    println!("changes need a password");
                }
                for task in client.tasks().await? {
                    println!(
                        "task {}: {} cycles, last {} µs, min {} µs, max {} µs, average {} µs, jitter up to {} µs{}",
                        task.name,
                        task.cycles,
                        task.last_ns / 1000,
                        task.min_ns / 1000,
                        task.max_ns / 1000,
                        task.average_ns / 1000,
                        task.jitter_max_ns / 1000,
                        if task.faulted { ", stopped by a fault" } else { "" }
                    );
                }
                let forces = client.forces().await?;
                if !forces.is_empty() {
                    println!("{} forced place(s); `rivet forces` lists them", forces.len());
                }
            }
            OnlineCommand::Download { project, start } => download(&mut client, &identity, &project, start).await?,
            OnlineCommand::OnlineChange { project, dry_run } => {
                crate::online_change_cli::online_change(&mut client, &project, dry_run).await?;
            }
            OnlineCommand::Start => println!("{}", client.start().await?.describe()),
            OnlineCommand::Stop => println!("{}", client.stop().await?.describe()),
            OnlineCommand::Reset(kind) => println!("{}", client.reset(kind).await?.describe()),
            OnlineCommand::Read(paths) => {
                let resolved = resolve_all(&mut client, &paths).await?;
                let places: Vec<Place> = resolved.iter().map(|r| r.place).collect();
                let enumerations = enumerations_of(&mut client, &paths, &resolved).await?;
                let snapshot = client.read(&places).await?;
                let typed = resolved.iter().zip(&enumerations);
                for ((path, (resolved, enumeration)), (bytes, forced)) in paths.iter().zip(typed).zip(&snapshot.values) {
                    let marker = if *forced { " (forced)" } else { "" };
                    println!("{path} = {}{marker}", show_typed(resolved, enumeration.as_ref(), bytes));
                }
            }
            OnlineCommand::Write(assignments) | OnlineCommand::Force(assignments) if assignments.is_empty() => {
                anyhow::bail!("give at least one VAR=VALUE");
            }
            OnlineCommand::Write(assignments) => {
                let values = parse_assignments(&mut client, &assignments).await?;
                client.write(&values).await?;
                println!("wrote {} value(s)", values.len());
            }
            OnlineCommand::Force(assignments) => {
                let values = parse_assignments(&mut client, &assignments).await?;
                client.force(&values).await?;
                println!("forced {} value(s)", values.len());
            }
            OnlineCommand::Unforce(paths) => {
                let resolved = resolve_all(&mut client, &paths).await?;
                let places: Vec<Place> = resolved.iter().map(|r| r.place).collect();
                client.unforce(&places).await?;
                if paths.is_empty() {
                    println!("released every force");
                } else {
                    println!("released {} force(s)", places.len());
                }
            }
            OnlineCommand::Forces => {
                let forces = client.forces().await?;
                if forces.is_empty() {
                    println!("no forces");
                }
                for (place, bytes) in forces {
                    println!("{} = 16#{}", describe_place(&place), hex(&bytes));
                }
            }
            OnlineCommand::Trace(request) => trace(&mut client, &request).await?,
            OnlineCommand::Faults => {
                let faults = client.faults().await?;
                if faults.is_empty() {
                    println!("no faults");
                }
                for fault in faults {
                    let place = if fault.line > 0 { format!("{}:{}", fault.file, fault.line) } else { fault.file.clone() };
                    println!("task '{}' cycle {}: {} in {} ({place})", fault.task, fault.cycle, fault.kind, fault.pou);
                }
            }
            OnlineCommand::Devices => {
                let devices = client.modbus_devices().await?;
                if devices.is_empty() {
                    println!("no Modbus devices");
                }
                for device in &devices {
                    println!("{}", crate::modbus_devices_cli::device_line(device));
                }
            }
        }
        Ok::<(), anyhow::Error>(())
    })
}

async fn download(
    client: &mut Client,
    identity: &online::Identity,
    project: &Path,
    start: bool,
) -> anyhow::Result<()> {
    let image = crate::build_cli::compile_path(project)?;
    let bytes = image.encode();
    let ours = program_image::identity_of(&bytes);
    match identity.image_hash {
        Some(theirs) if theirs == ours => {
            println!("the target already runs this program; downloading it again")
        }
        Some(_) => println!(
            "the target runs another program ('{}'); replacing it",
            identity.project
        ),
        None => println!("the target has no program"),
    }
    let bar = indicatif::ProgressBar::new(bytes.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {bytes}/{total_bytes} {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    let retained = client
        .download(&bytes, start, |sent, _| bar.set_position(sent as u64))
        .await;
    bar.finish_and_clear();
    let retained = retained?;
    println!(
        "downloaded {} bytes, identity {}{}{}",
        bytes.len(),
        hex(&ours[..8]),
        if retained {
            ", retained values kept"
        } else {
            ""
        },
        if start { ", running" } else { "" }
    );
    Ok(())
}

async fn trace(client: &mut Client, request: &TraceRequest) -> anyhow::Result<()> {
    let tasks = client.tasks().await?;
    let task = tasks
        .iter()
        .position(|t| t.name.eq_ignore_ascii_case(&request.task))
        .with_context(|| {
            let names: Vec<&str> = tasks.iter().map(|t| t.name.as_str()).collect();
            format!(
                "--task {}: the target's tasks are {}",
                request.task,
                names.join(", ")
            )
        })?;
    let resolved = resolve_all(client, &request.variables).await?;
    let enumerations = enumerations_of(client, &request.variables, &resolved).await?;
    let places: Vec<Place> = resolved.iter().map(|r| r.place).collect();
    let trigger = match &request.trigger {
        None => online::Trigger::None,
        Some((variable, kind)) => {
            let place = client.resolve(variable).await?.place;
            match kind.as_str() {
                "falling" => online::Trigger::Falling(place),
                "level" => online::Trigger::Level(place),
                _ => online::Trigger::Rising(place),
            }
        }
    };
    client
        .trace_configure(&online::TraceConfig {
            task: task as u8,
            every: request.every,
            samples: request.samples,
            pretrigger_percent: request.pretrigger,
            trigger,
            places: places.clone(),
        })
        .await?;
    client.trace_arm().await?;
    let bar = indicatif::ProgressBar::new(u64::from(request.samples));
    bar.set_message("recording");
    loop {
        let status = client.trace_status().await?;
        bar.set_position(u64::from(status.recorded));
        if status.state == online::TraceState::Complete {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    bar.set_message("uploading");
    let samples = client
        .trace_upload(&places, |n| bar.set_position(n as u64))
        .await?;
    bar.finish_and_clear();
    let mut csv = String::from("cycle,time_ms");
    for variable in &request.variables {
        csv.push(',');
        csv.push_str(variable);
    }
    csv.push('\n');
    for sample in &samples {
        csv.push_str(&format!(
            "{},{:.3}",
            sample.cycle,
            sample.time_ns as f64 / 1e6
        ));
        for ((resolved, enumeration), bytes) in
            resolved.iter().zip(&enumerations).zip(&sample.values)
        {
            csv.push(',');
            csv.push_str(&show_typed(resolved, enumeration.as_ref(), bytes));
        }
        csv.push('\n');
    }
    std::fs::write(&request.csv, csv)
        .with_context(|| format!("{}: cannot write the trace", request.csv.display()))?;
    println!(
        "{} samples of {} variable(s) written to {}",
        samples.len(),
        places.len(),
        request.csv.display()
    );
    Ok(())
}

async fn resolve_all(client: &mut Client, paths: &[String]) -> Result<Vec<Resolved>, OnlineError> {
    let mut out = Vec::new();
    for path in paths {
        out.push(client.resolve(path).await?);
    }
    Ok(out)
}

/// The values of each enumeration-typed variable among `paths`, so that its values print by
/// name; `None` for the others.
async fn enumerations_of(
    client: &mut Client,
    paths: &[String],
    resolved: &[Resolved],
) -> Result<Vec<Option<Enumeration>>, OnlineError> {
    let mut out = Vec::new();
    for (path, resolved) in paths.iter().zip(resolved) {
        out.push(
            if resolved.type_tag == TYPE_ENUM && resolved.place.bit.is_none() {
                Some(client.enumeration(path).await?)
            } else {
                None
            },
        );
    }
    Ok(out)
}

async fn parse_assignments(
    client: &mut Client,
    assignments: &[String],
) -> anyhow::Result<Vec<(Place, Vec<u8>)>> {
    let mut values = Vec::new();
    for assignment in assignments {
        let (path, literal) = assignment
            .split_once('=')
            .with_context(|| format!("'{assignment}': write VAR=VALUE, such as Main.speed=1500"))?;
        let resolved = client.resolve(path.trim()).await?;
        let bytes = if resolved.type_tag == TYPE_ENUM && resolved.place.bit.is_none() {
            let enumeration = client.enumeration(path.trim()).await?;
            enumeration_value(&enumeration, literal.trim())
                .with_context(|| path.trim().to_owned())?
        } else {
            crate::literal_value::parse(literal.trim(), resolved.type_tag, resolved.length)
                .map_err(|message| anyhow::anyhow!("{}: {message}", path.trim()))?
        };
        values.push((resolved.place, bytes));
    }
    Ok(values)
}

/// The bytes of the value of `enumeration` named by `text` (`GREEN` or `Light#GREEN`, in any
/// case), stored as the enumeration's base integer type.
fn enumeration_value(enumeration: &Enumeration, text: &str) -> anyhow::Result<Vec<u8>> {
    let name = text.rsplit_once('#').map_or(text, |(_, name)| name);
    let Some((_, number)) = enumeration
        .values
        .iter()
        .find(|(value, _)| value.eq_ignore_ascii_case(name))
    else {
        let names: Vec<&str> = enumeration
            .values
            .iter()
            .map(|(name, _)| name.as_str())
            .collect();
        anyhow::bail!(
            "'{text}' is not a value of the enumeration; its values are {}",
            names.join(", ")
        );
    };
    crate::literal_value::parse(&number.to_string(), enumeration.base, 0)
        .map_err(|message| anyhow::anyhow!("'{text}' ({number}): {message}"))
}
