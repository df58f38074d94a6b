//! `rivet-runtime`: the Rivet soft PLC as a process.
//!
//! It loads a program image, runs its tasks on the scheduler, serves the located areas over
//! Modbus TCP (and, with `--modbus-rtu`, as a Modbus RTU slave on a serial port), keeps RETAIN and PERSISTENT variables in its data directory, and saves them when
//! it is interrupted or terminated. The first line on standard output is the address it
//! listens on (`listening on 127.0.0.1:5020`), so a caller that asked for port 0 learns the
//! port; everything else it says goes to standard error.

// A command-line program talks to its operator through standard output and standard error.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use anyhow::Context;
use clap::Parser;
use program_image::ProgramImage;
use runtime::areas::LocatedAreas;
use runtime::engine::EngineChoice;
use runtime::modbus::master::MasterOptions;
use runtime::modbus::rtu_slave::{
    DamagedFrameReports, RtuPortEvent, RtuSlaveCounters, RtuSlaveOptions, serve_rtu_port,
};
use runtime::modbus::{
    DEFAULT_FRAME_TIMEOUT, DEFAULT_IDLE_TIMEOUT, MapSlot, ModbusMap, ServerOptions, WritePolicy,
    serve,
};
use runtime::online::{OnlineServices, PASSWORD_VARIABLE, read_password};
use runtime::scheduler::{Realtime, Scheduler, SchedulerOptions};
use runtime::serial::SerialSettings;
use tokio::net::TcpListener;

/// The Rivet soft PLC: runs a program image and serves Modbus TCP.
#[derive(Debug, Parser)]
#[command(name = "rivet-runtime", version)]
struct Arguments {
    /// The address to serve Modbus TCP on; port 0 picks a free port.
    #[arg(long, default_value = "127.0.0.1:5020")]
    listen: SocketAddr,
    /// The directory for RETAIN and PERSISTENT variables; created if missing.
    #[arg(long)]
    data_dir: PathBuf,
    /// The program image to run (written by `rivet build`).
    #[arg(long)]
    image: Option<PathBuf>,
    /// Load the image but do not start its tasks.
    #[arg(long)]
    stopped: bool,
    /// A file whose first line is the password the online services that change the target
    /// require (download, start, stop, reset, write, force, trace); it may also be given in
    /// the environment variable RIVET_PASSWORD. Without one, every client may change it.
    #[arg(long)]
    password_file: Option<PathBuf>,
    /// What the standard Modbus function codes (5, 6, 15, 16, 23) may write: `all`, `none`, or
    /// ranges such as `coils:0-15,holding:1024-1100`; a refused write gets exception 1. The
    /// default is `none` with a password (only a logged-in client changes the target) and
    /// `all` without one.
    #[arg(long, value_name = "POLICY")]
    modbus_writes: Option<WritePolicy>,
    /// Seconds a Modbus connection may stay silent between requests before it is closed.
    #[arg(long, default_value_t = DEFAULT_IDLE_TIMEOUT.as_secs(), value_parser = clap::value_parser!(u64).range(1..))]
    idle_timeout_seconds: u64,
    /// Seconds a Modbus frame may take from its first byte to its last before the connection
    /// is closed.
    #[arg(long, default_value_t = DEFAULT_FRAME_TIMEOUT.as_secs(), value_parser = clap::value_parser!(u64).range(1..))]
    frame_timeout_seconds: u64,
    /// Whether clients may debug the program (breakpoints, stepping, halts): `off` for a
    /// plant that must never be halted from outside; online change stays available.
    #[arg(long, value_name = "on|off", default_value = "on", value_parser = ["on", "off"])]
    debug: String,
    /// Run the scheduler at this real-time priority (1–98, Linux `SCHED_FIFO`), so that no
    /// other program on the machine delays a task's start; needs root or CAP_SYS_NICE. Without
    /// it the tasks run with normal scheduling.
    #[arg(long, value_name = "1-98", value_parser = clap::value_parser!(u8).range(1..=98))]
    realtime_priority: Option<u8>,
    /// Whether the runtime masters the image's Modbus devices (`docs/modbus-master.md`):
    /// `off` runs the program without them (on a desk, against a plant's image); their
    /// variables then keep their initial values.
    #[arg(long, value_name = "on|off", default_value = "on", value_parser = ["on", "off"])]
    modbus_master: String,
    /// The device file of the project's serial port NAME on this machine, in place of the one
    /// the image names, such as `RS485=/dev/ttyUSB1`; may be given once per port.
    #[arg(long, value_name = "NAME=PATH", value_parser = parse_serial_port)]
    serial_port: Vec<(String, String)>,
    /// Also serve the located areas as a Modbus RTU slave on this serial port (a device file
    /// such as /dev/ttyUSB0), with the same map and write policy as Modbus TCP; the port is
    /// opened again when it fails or goes away.
    #[arg(long, value_name = "PATH")]
    modbus_rtu: Option<PathBuf>,
    /// The RTU slave's line: baud rate, data bits (8), parity (N, E or O) and stop bits (1 or
    /// 2).
    #[arg(
        long,
        value_name = "BAUD-DPS",
        default_value = "19200-8E1",
        requires = "modbus_rtu"
    )]
    modbus_rtu_format: SerialSettings,
    /// The RTU slave's address on the line.
    #[arg(long, value_name = "1-247", default_value_t = 1, requires = "modbus_rtu",
          value_parser = clap::value_parser!(u8).range(1..=247))]
    modbus_rtu_unit: u8,
    /// The engine that runs the program (`docs/native-engine.md` §8.3): `native` translates it
    /// to machine code at load (a POU it cannot translate runs in the interpreter), or
    /// `interpreter`. The default is `native` on x86-64 and aarch64 and `interpreter`
    /// elsewhere; `native` on a machine without a native code generator is refused.
    #[arg(long, value_name = "native|interpreter", value_parser = ["native", "interpreter"])]
    engine: Option<String>,
    /// No longer accepted (visible in the process list): refused with a message saying where
    /// the password goes now.
    #[arg(long, hide = true)]
    password: Option<String>,
}

/// Reads `NAME=PATH` of `--serial-port`.
fn parse_serial_port(text: &str) -> anyhow::Result<(String, String)> {
    match text.split_once('=') {
        Some((name, path)) if !name.trim().is_empty() && !path.trim().is_empty() => {
            Ok((name.trim().to_owned(), path.trim().to_owned()))
        }
        _ => Err(anyhow::anyhow!(
            "'{text}' is not NAME=PATH (a serial port's name in the project, then its device file)"
        )),
    }
}

/// How often the runtime looks for new faults to report.
const FAULT_REPORT_INTERVAL: Duration = Duration::from_millis(100);

fn main() -> anyhow::Result<()> {
    let arguments = Arguments::parse();
    // Refused before anything loads, as a wrong argument is (exit status 2).
    let engine = match &arguments.engine {
        None => EngineChoice::default(),
        Some(value) => match EngineChoice::for_this_machine(value) {
            Ok(engine) => engine,
            Err(refusal) => {
                eprintln!("error: {refusal}");
                std::process::exit(2);
            }
        },
    };
    tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .context("cannot start the async runtime")?
        .block_on(run(arguments, engine))
}

async fn run(arguments: Arguments, engine: EngineChoice) -> anyhow::Result<()> {
    // Before anything slow (the image's load and translation), so that an early stop is one.
    let ended = end_signal();
    let password = read_password(
        arguments.password.as_deref(),
        arguments.password_file.as_deref(),
        std::env::var_os(PASSWORD_VARIABLE),
    )?;
    // With a password, standard writes would bypass it unless the operator allows them.
    let writes = match (&arguments.modbus_writes, &password) {
        (Some(writes), _) => writes.clone(),
        (None, Some(_)) => WritePolicy::None,
        (None, None) => WritePolicy::All,
    };
    std::fs::create_dir_all(&arguments.data_dir).with_context(|| {
        format!(
            "cannot create the data directory {}",
            arguments.data_dir.display()
        )
    })?;
    let listener = TcpListener::bind(arguments.listen)
        .await
        .with_context(|| format!("cannot listen on {}", arguments.listen))?;
    let address = listener
        .local_addr()
        .context("cannot read the bound address")?;
    println!("listening on {address}");

    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let options = SchedulerOptions {
        data_dir: Some(arguments.data_dir.clone()),
        realtime_priority: arguments.realtime_priority,
        modbus_master: MasterOptions {
            enabled: arguments.modbus_master == "on",
            serial_ports: arguments.serial_port.clone(),
            // One line per change of a device's state, never per request (§4.2).
            state_lines: Some(Arc::new(|line: &str| eprintln!("{line}"))),
        },
        engine,
        ..SchedulerOptions::default()
    };
    let scheduler = Arc::new(Scheduler::spawn(Arc::clone(&areas), options)?);
    match scheduler.status().realtime {
        Realtime::Normal => {}
        granted @ Realtime::Fifo(_) => eprintln!("rivet-runtime: {granted}"),
        refused @ Realtime::Refused { .. } => eprintln!("rivet-runtime: warning: {refused}"),
    }
    let loaded = match &arguments.image {
        Some(path) => load(&scheduler, path),
        None => {
            eprintln!("rivet-runtime: no program image given; serving Modbus without a program");
            None
        }
    };
    // The image's own Modbus map, or the default map without a program.
    let map = match &loaded {
        Some(map) => map.clone(),
        None => ModbusMap::default(),
    };
    let loaded = loaded.is_some();
    if loaded && !arguments.stopped {
        scheduler.start()?;
        eprintln!("rivet-runtime: running");
    }

    // A download replaces the map with the new image's.
    let map = MapSlot::new(map);
    let services = Arc::new(
        OnlineServices::new(Arc::clone(&scheduler), password)
            .with_map(Arc::clone(&map))
            .with_debugging(arguments.debug == "on"),
    );
    let server_options = ServerOptions {
        writes: writes.clone(),
        idle_timeout: Duration::from_secs(arguments.idle_timeout_seconds),
        frame_timeout: Duration::from_secs(arguments.frame_timeout_seconds),
        custom: Some(services.handler()),
        closed: Some(services.closed_handler()),
        ..ServerOptions::default()
    };
    drop(services);
    let rtu_counters = RtuSlaveCounters::default();
    let (rtu_areas, rtu_map) = (Arc::clone(&areas), Arc::clone(&map));
    let rtu_slave = serve_rtu_slave(&arguments, writes, &rtu_areas, &rtu_map, &rtu_counters);
    let mut damaged_frame_reports = DamagedFrameReports::default();
    let server = serve(listener, areas, map, server_options);
    let mut reported_faults = 0;
    let mut fault_check = tokio::time::interval(FAULT_REPORT_INTERVAL);
    let mut ended = std::pin::pin!(ended);
    let mut server = Box::pin(server);
    let mut rtu_slave = std::pin::pin!(rtu_slave);
    let outcome = loop {
        tokio::select! {
            served = &mut server => break served.context("the Modbus server stopped"),
            never = &mut rtu_slave => match never {},
            signal = &mut ended => {
                eprintln!("rivet-runtime: {signal}; stopping");
                break Ok(());
            }
            _ = fault_check.tick() => {
                let status = scheduler.status();
                let new = status.faults_total - reported_faults;
                let kept = status.faults.len();
                let unseen = usize::try_from(new).unwrap_or(usize::MAX).min(kept);
                for fault in &status.faults[kept - unseen..] {
                    eprintln!("rivet-runtime: {fault}");
                }
                reported_faults = status.faults_total;
                // Damaged frames point at a wrong line setting or a noisy cable.
                let rtu = rtu_counters.counts();
                if let Some(damaged) = damaged_frame_reports.due(&rtu, std::time::Instant::now()) {
                    eprintln!(
                        "rivet-runtime: Modbus RTU: {damaged} damaged frame(s) since the last \
                         report; {rtu}"
                    );
                }
            }
        }
    };
    // The server's connections hold the online services, and they the scheduler.
    drop(server);
    match Arc::try_unwrap(scheduler) {
        Ok(scheduler) => scheduler
            .shutdown()
            .context("cannot save the retained values")?,
        // Cannot happen once the server is gone; dropping the last handle still saves.
        Err(scheduler) => drop(scheduler),
    }
    outcome
}

/// Serves the RTU slave of `--modbus-rtu` for ever, saying on standard error when its port
/// opens, cannot be opened (once until the reason changes or the port opens: a missing
/// adapter would otherwise be reported every 5 s for as long as it is missing) or closes;
/// without `--modbus-rtu`, waits for ever.
async fn serve_rtu_slave(
    arguments: &Arguments,
    writes: WritePolicy,
    areas: &Mutex<LocatedAreas>,
    map: &MapSlot,
    counters: &RtuSlaveCounters,
) -> std::convert::Infallible {
    let Some(path) = &arguments.modbus_rtu else {
        return std::future::pending().await;
    };
    let settings = arguments.modbus_rtu_format;
    let options = RtuSlaveOptions {
        unit_id: arguments.modbus_rtu_unit,
        silence: settings.silence(),
        writes,
    };
    let shown = path.display();
    let mut last_open_failure: Option<String> = None;
    let report = |event: RtuPortEvent<'_>| match event {
        RtuPortEvent::Opened => {
            last_open_failure = None;
            eprintln!(
                "rivet-runtime: Modbus RTU slave {} on {shown} at {settings}",
                options.unit_id
            );
        }
        RtuPortEvent::OpenFailed { error, retry_in } => {
            let text = error.to_string();
            if last_open_failure.as_ref() != Some(&text) {
                eprintln!(
                    "rivet-runtime: Modbus RTU: {text}; trying again in {} ms, and every 5 s \
                     at the most (said again when the reason changes)",
                    retry_in.as_millis()
                );
                last_open_failure = Some(text);
            }
        }
        RtuPortEvent::Closed { error, retry_in } => {
            let why = match error {
                Some(error) => format!("failed: {error}"),
                None => "closed (the device went away)".to_owned(),
            };
            eprintln!(
                "rivet-runtime: Modbus RTU: {shown} {why}; opening it again in {} ms",
                retry_in.as_millis()
            );
        }
    };
    serve_rtu_port(path, &settings, areas, map, &options, counters, report).await
}

/// Loads the image at `path` and gives the Modbus map it asks for; a file that cannot be read
/// or is not a valid image is refused with the reason, and the runtime goes on without a
/// program.
fn load(scheduler: &Scheduler, path: &Path) -> Option<ModbusMap> {
    let refuse = |reason: &dyn std::fmt::Display| {
        eprintln!(
            "rivet-runtime: refusing the program image {}: {reason}; serving Modbus without a program",
            path.display()
        );
        None
    };
    let bytes = match std::fs::read(path) {
        Ok(bytes) => bytes,
        Err(error) => return refuse(&error),
    };
    let image = match ProgramImage::decode(&bytes) {
        Ok(image) => image,
        Err(error) => return refuse(&error),
    };
    let map = match ModbusMap::for_image(&image) {
        Ok(map) => map,
        Err(error) => return refuse(&error),
    };
    match scheduler.load(image) {
        Ok(report) => {
            eprintln!("rivet-runtime: loaded {}", path.display());
            eprintln!("rivet-runtime: {}", report.native.summary());
            for line in report.native.lines() {
                eprintln!("rivet-runtime: {line}");
            }
            if let Some(retain) = report.retain {
                eprintln!("rivet-runtime: {retain}");
            }
            Some(map)
        }
        Err(error) => refuse(&error),
    }
}

/// Installs the handlers of SIGINT (Ctrl+C) and, on Unix, SIGTERM at once, and returns the wait
/// for the first of them, named. Installing them before the image loads matters: a signal that
/// arrived before the handlers would get the default action, which ends the process on the spot.
fn end_signal() -> impl Future<Output = &'static str> {
    #[cfg(unix)]
    {
        use tokio::signal::unix::{Signal, SignalKind, signal};
        /// The next delivery of `signal`; never, without a handler.
        async fn next(signal: &mut Option<Signal>) {
            let delivered = match signal {
                Some(signal) => signal.recv().await.is_some(),
                None => false,
            };
            if !delivered {
                std::future::pending::<()>().await;
            }
        }
        let mut interrupt = signal(SignalKind::interrupt()).ok();
        let mut terminate = signal(SignalKind::terminate()).ok();
        async move {
            tokio::select! {
                () = next(&mut interrupt) => "interrupted",
                () = next(&mut terminate) => "terminated",
            }
        }
    }
    #[cfg(not(unix))]
    async {
        // Without a handler there is no interruption to wait for.
        if tokio::signal::ctrl_c().await.is_err() {
            std::future::pending::<()>().await;
        }
        "interrupted"
    }
}
