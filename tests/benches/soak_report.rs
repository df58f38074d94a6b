//! The soak benchmark of issue 16: the real runtime (scheduler, Modbus server, online services
//! with a password) runs a 1 ms task while 16 clients work on it at once for a set time
//! (10 minutes unless `--seconds N` says otherwise): Modbus pollers with the standard function
//! codes, online monitors, writers that also force, and one client tracing every cycle of the
//! 1 ms task. At the end it prints the trace samples lost, the cycles the scheduler dropped, the
//! requests served and failed with their response times per kind of client, and the process's
//! resident memory at start, after warm-up and at the end.
//!
//! `cargo bench -p tests --bench soak_report -- --seconds 600 [--realtime-priority 50]`; the
//! priority runs the scheduler as `rivet-runtime --realtime-priority` does (it needs root or
//! CAP_SYS_NICE; the header says what it got). Not run in CI: it takes the whole duration and
//! its figures depend on the machine.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::future::Future;
use std::net::SocketAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use online::{Client, Place, TraceConfig, TraceState, Trigger};
use runtime::scheduler::SchedulerOptions;

mod bench_runtime;
use tokio_modbus::client::Reader as _;

/// The password the runtime is given, so that every changing request carries a token.
const PASSWORD: &str = "soak-benchmark-password";
/// Clients polling the Modbus map with the standard function codes.
const MODBUS_POLLERS: usize = 6;
/// Clients monitoring variables through the online services.
const MONITORS: usize = 6;
/// Clients writing and forcing variables.
const WRITERS: usize = 3;
/// How often a Modbus poller reads (each of its reads is one request).
const MODBUS_POLL_INTERVAL: Duration = Duration::from_millis(10);
/// How often a monitor reads its variables, as a studio's watch list does.
const MONITOR_INTERVAL: Duration = Duration::from_millis(20);
/// How often a writer writes (every tenth time it forces and releases instead).
const WRITE_INTERVAL: Duration = Duration::from_millis(20);
/// How often the tracer fetches the samples recorded since its last fetch.
const TRACE_FETCH_INTERVAL: Duration = Duration::from_millis(100);
/// The samples of one trace recording (one minute of the 1 ms task); the tracer arms again
/// when it is complete, so the ring's memory does not grow with the duration.
const TRACE_SEGMENT_SAMPLES: u32 = 60_000;
/// The variables of the program besides its cycle counter; monitors read them.
const VARIABLES: usize = 48;

fn main() {
    let seconds = argument("--seconds").unwrap_or(600);
    let realtime_priority = argument("--realtime-priority")
        .map(|priority| u8::try_from(priority).expect("--realtime-priority takes 1 to 98"));
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap();
    runtime.block_on(soak(Duration::from_secs(seconds), realtime_priority));
}

/// The value of `NAME N` among the arguments (`--seconds 600`, `--realtime-priority 50`); other
/// arguments (cargo's `--bench`) are ignored.
fn argument(name: &str) -> Option<u64> {
    let arguments: Vec<String> = std::env::args().collect();
    arguments
        .windows(2)
        .find(|pair| pair[0] == name)
        .map(|pair| pair[1].parse().expect("takes a whole number"))
}

/// A program whose 1 ms task counts its cycles in `n` and changes every variable each cycle;
/// `w0`..`w15` are written and forced by the writers.
fn program() -> Vec<u8> {
    let types = ["BOOL", "INT", "DINT", "REAL"];
    let mut declarations = String::from("n : DINT;\n");
    let mut body = String::from("n := n + 1;\n");
    for i in 0..VARIABLES {
        let ty = types[i % 4];
        declarations.push_str(&format!("v{i} : {ty};\n"));
        body.push_str(&match ty {
            "BOOL" => format!("v{i} := (n MOD 2) = 0;\n"),
            "INT" => format!("v{i} := DINT_TO_INT(n MOD 1000);\n"),
            "DINT" => format!("v{i} := n + {i};\n"),
            _ => format!("v{i} := DINT_TO_REAL(n) * 0.5;\n"),
        });
    }
    for i in 0..16 {
        declarations.push_str(&format!("w{i} : INT;\n"));
        body.push_str(&format!("v1 := v1 + w{i} MOD 2;\n"));
    }
    let text = format!("PROGRAM Main\nVAR\n{declarations}END_VAR\n{body}END_PROGRAM\n");
    let source = compiler::SourceProject::new(&text);
    let mut project = source.project.clone();
    project.tasks = vec![project_model::Task {
        name: "Fast".to_owned(),
        kind: project_model::TaskKind::Cyclic { interval_us: 1000 },
        priority: 0,
        watchdog: None,
        programs: vec!["Main".to_owned()],
    }];
    compiler::compile_project(&project).unwrap().encode()
}

/// The kinds of client, in the order the report lists them.
#[derive(Clone, Copy, Debug)]
enum Kind {
    ModbusPoll,
    Monitor,
    WriteForce,
    Trace,
}

const KINDS: [Kind; 4] = [
    Kind::ModbusPoll,
    Kind::Monitor,
    Kind::WriteForce,
    Kind::Trace,
];

impl Kind {
    fn label(self) -> &'static str {
        match self {
            Kind::ModbusPoll => "Modbus poll (FC 1/3/4)",
            Kind::Monitor => "online monitor (READ)",
            Kind::WriteForce => "online write/force",
            Kind::Trace => "online trace (STATUS/UPLOAD/ARM)",
        }
    }
}

/// Response times in a fixed set of buckets (exact below 1,024 µs, then 64 per power of two),
/// so that recording millions of them allocates nothing while the memory is watched.
struct Latencies {
    buckets: Vec<u64>,
    served: u64,
    failed: u64,
    max_us: u64,
}

impl Latencies {
    const EXACT: u64 = 1024;
    const PER_OCTAVE: u64 = 64;

    fn new() -> Self {
        Self {
            buckets: vec![0; (Self::EXACT + 54 * Self::PER_OCTAVE) as usize],
            served: 0,
            failed: 0,
            max_us: 0,
        }
    }

    fn bucket(us: u64) -> usize {
        if us < Self::EXACT {
            return us as usize;
        }
        let octave = u64::from(63 - us.leading_zeros()); // 10 and up.
        let fraction = (us >> (octave - 6)) & (Self::PER_OCTAVE - 1);
        (Self::EXACT + (octave - 10) * Self::PER_OCTAVE + fraction) as usize
    }

    /// The smallest time in a bucket.
    fn lower_bound(bucket: usize) -> u64 {
        let bucket = bucket as u64;
        if bucket < Self::EXACT {
            return bucket;
        }
        let octave = (bucket - Self::EXACT) / Self::PER_OCTAVE + 10;
        let fraction = (bucket - Self::EXACT) % Self::PER_OCTAVE;
        (1 << octave) + (fraction << (octave - 6))
    }

    fn record(&mut self, took: Duration, ok: bool) {
        if !ok {
            self.failed += 1;
            return;
        }
        let us = took.as_micros() as u64;
        self.served += 1;
        self.max_us = self.max_us.max(us);
        self.buckets[Self::bucket(us)] += 1;
    }

    fn percentile_us(&self, percent: u64) -> u64 {
        self.permille_us(percent * 10)
    }

    fn permille_us(&self, permille: u64) -> u64 {
        let wanted = (self.served * permille).div_ceil(1000).max(1);
        let mut seen = 0;
        for (bucket, count) in self.buckets.iter().enumerate() {
            seen += count;
            if seen >= wanted {
                return Self::lower_bound(bucket);
            }
        }
        self.max_us
    }
}

/// The response times of each kind of client.
struct Figures {
    kinds: Vec<Mutex<Latencies>>,
}

impl Figures {
    fn new() -> Self {
        Self {
            kinds: KINDS.iter().map(|_| Mutex::new(Latencies::new())).collect(),
        }
    }

    fn record(&self, kind: Kind, took: Duration, ok: bool) {
        self.kinds[kind as usize].lock().unwrap().record(took, ok);
    }
}

/// Times one request and records it under `kind`; returns whether it succeeded.
async fn timed<T, E>(
    figures: &Figures,
    kind: Kind,
    request: impl Future<Output = Result<T, E>>,
) -> Option<T> {
    let started = Instant::now();
    let result = request.await;
    figures.record(kind, started.elapsed(), result.is_ok());
    result.ok()
}

/// The process's resident memory in kB (VmRSS of /proc/self/status).
fn resident_kb() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|line| line.strip_prefix("VmRSS:"))
        .and_then(|rest| rest.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0)
}

/// The machine's load averages over 1, 5 and 15 minutes (/proc/loadavg): on a machine busy
/// with other work the 1 ms task waits for a processor, which the report must show.
fn load_average() -> String {
    let text = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    text.split_whitespace()
        .take(3)
        .collect::<Vec<_>>()
        .join(" ")
}

/// What the tracer found.
struct TraceFindings {
    /// The time from one traced cycle's start to the next's, within a recording (1 ms when
    /// the task runs on time): its spread shows the start jitter cycle by cycle.
    intervals: Latencies,
    /// Samples uploaded.
    samples: u64,
    /// Cycles missing between two consecutive samples of one recording.
    lost: u64,
    /// Recordings completed and armed again.
    recordings: u64,
    /// Cycles between the end of one recording and the start of the next (not lost: nothing
    /// records while the tracer arms again).
    rearm_gap_cycles: u64,
}

async fn modbus_poller(address: SocketAddr, figures: Arc<Figures>, stop: Arc<AtomicBool>) {
    let mut context = tokio_modbus::client::tcp::connect(address).await.unwrap();
    let mut ticker = tokio::time::interval(MODBUS_POLL_INTERVAL);
    let mut turn = 0u64;
    while !stop.load(Ordering::Relaxed) {
        ticker.tick().await;
        turn += 1;
        let ok = match turn % 3 {
            0 => timed(&figures, Kind::ModbusPoll, async {
                // An exception answer fails as a lost connection does.
                context
                    .read_holding_registers(0, 100)
                    .await
                    .ok()
                    .and_then(Result::ok)
                    .ok_or(())
            })
            .await
            .is_some(),
            1 => timed(&figures, Kind::ModbusPoll, async {
                // An exception answer fails as a lost connection does.
                context
                    .read_input_registers(0, 64)
                    .await
                    .ok()
                    .and_then(Result::ok)
                    .ok_or(())
            })
            .await
            .is_some(),
            _ => timed(&figures, Kind::ModbusPoll, async {
                // An exception answer fails as a lost connection does.
                context
                    .read_coils(0, 256)
                    .await
                    .ok()
                    .and_then(Result::ok)
                    .ok_or(())
            })
            .await
            .is_some(),
        };
        if !ok {
            // A dropped connection is opened again; the failure is counted above.
            if let Ok(fresh) = tokio_modbus::client::tcp::connect(address).await {
                context = fresh;
            }
        }
    }
}

async fn monitor(
    address: SocketAddr,
    places: Vec<Place>,
    figures: Arc<Figures>,
    stop: Arc<AtomicBool>,
) {
    let (mut client, _) = Client::connect(address, None).await.unwrap();
    let mut ticker = tokio::time::interval(MONITOR_INTERVAL);
    while !stop.load(Ordering::Relaxed) {
        ticker.tick().await;
        if timed(&figures, Kind::Monitor, client.read(&places))
            .await
            .is_none()
            && let Ok((fresh, _)) = Client::connect(address, None).await
        {
            client = fresh;
        }
    }
}

async fn writer(address: SocketAddr, place: Place, figures: Arc<Figures>, stop: Arc<AtomicBool>) {
    let (mut client, _) = Client::connect(address, Some(PASSWORD)).await.unwrap();
    let mut ticker = tokio::time::interval(WRITE_INTERVAL);
    let mut turn = 0i16;
    while !stop.load(Ordering::Relaxed) {
        ticker.tick().await;
        turn = turn.wrapping_add(1);
        let value = vec![(place, turn.to_le_bytes().to_vec())];
        let ok = if turn % 10 == 0 {
            timed(&figures, Kind::WriteForce, client.force(&value))
                .await
                .is_some()
                && timed(&figures, Kind::WriteForce, client.unforce(&[place]))
                    .await
                    .is_some()
        } else {
            timed(&figures, Kind::WriteForce, client.write(&value))
                .await
                .is_some()
        };
        if !ok && let Ok((fresh, _)) = Client::connect(address, Some(PASSWORD)).await {
            client = fresh;
        }
    }
}

/// Traces the cycle counter at every cycle of the 1 ms task, fetching the samples as they are
/// recorded and checking that their cycle numbers follow one another.
async fn tracer(
    address: SocketAddr,
    counter: Place,
    figures: Arc<Figures>,
    stop: Arc<AtomicBool>,
) -> TraceFindings {
    let (mut client, _) = Client::connect(address, Some(PASSWORD)).await.unwrap();
    let places = vec![counter];
    client
        .trace_configure(&TraceConfig {
            task: 0,
            every: 1,
            samples: TRACE_SEGMENT_SAMPLES,
            pretrigger_percent: 0,
            trigger: Trigger::None,
            places: places.clone(),
        })
        .await
        .unwrap();
    client.trace_arm().await.unwrap();
    let mut findings = TraceFindings {
        intervals: Latencies::new(),
        samples: 0,
        lost: 0,
        recordings: 0,
        rearm_gap_cycles: 0,
    };
    let mut last_start_ns: Option<u64> = None;
    let mut fetched = 0u32;
    let mut last_cycle: Option<u64> = None;
    let mut segment_end: Option<u64> = None;
    let mut ticker = tokio::time::interval(TRACE_FETCH_INTERVAL);
    while !stop.load(Ordering::Relaxed) {
        ticker.tick().await;
        let Some(status) = timed(&figures, Kind::Trace, client.trace_status()).await else {
            continue;
        };
        // The status comes first: when it says complete, the fetch below gets every sample.
        loop {
            let Some(samples) = timed(
                &figures,
                Kind::Trace,
                client.trace_upload_from(&places, fetched),
            )
            .await
            else {
                break;
            };
            if samples.is_empty() {
                break;
            }
            for sample in &samples {
                match (last_cycle, segment_end) {
                    (Some(last), _) => findings.lost += sample.cycle.saturating_sub(last + 1),
                    (None, Some(end)) => {
                        findings.rearm_gap_cycles += sample.cycle.saturating_sub(end + 1);
                    }
                    (None, None) => {}
                }
                if let (Some(_), Some(last)) = (last_cycle, last_start_ns) {
                    let interval = Duration::from_nanos(sample.time_ns.saturating_sub(last));
                    findings.intervals.record(interval, true);
                }
                last_cycle = Some(sample.cycle);
                last_start_ns = Some(sample.time_ns);
            }
            findings.samples += samples.len() as u64;
            fetched += samples.len() as u32;
        }
        if status.state == TraceState::Complete
            && timed(&figures, Kind::Trace, client.trace_arm())
                .await
                .is_some()
        {
            findings.recordings += 1;
            segment_end = last_cycle.take();
            fetched = 0;
        }
    }
    findings
}

async fn soak(duration: Duration, realtime_priority: Option<u8>) {
    let rss_start = resident_kb();
    let load_start = load_average();
    let options = SchedulerOptions {
        realtime_priority,
        ..SchedulerOptions::default()
    };
    let (address, scheduler) = bench_runtime::start(options, PASSWORD).await;
    let (mut setup, _) = Client::connect(address, Some(PASSWORD)).await.unwrap();
    setup.download(&program(), true, |_, _| {}).await.unwrap();
    let counter = setup.resolve("Main.n").await.unwrap().place;
    let mut variables = Vec::new();
    for i in 0..VARIABLES {
        variables.push(setup.resolve(&format!("Main.v{i}")).await.unwrap().place);
    }
    let mut written = Vec::new();
    for i in 0..WRITERS {
        written.push(setup.resolve(&format!("Main.w{i}")).await.unwrap().place);
    }
    drop(setup);

    let figures = Arc::new(Figures::new());
    let stop = Arc::new(AtomicBool::new(false));
    let mut clients = Vec::new();
    for _ in 0..MODBUS_POLLERS {
        clients.push(tokio::spawn(modbus_poller(
            address,
            Arc::clone(&figures),
            Arc::clone(&stop),
        )));
    }
    for _ in 0..MONITORS {
        clients.push(tokio::spawn(monitor(
            address,
            variables.clone(),
            Arc::clone(&figures),
            Arc::clone(&stop),
        )));
    }
    for place in written {
        clients.push(tokio::spawn(writer(
            address,
            place,
            Arc::clone(&figures),
            Arc::clone(&stop),
        )));
    }
    let tracer = tokio::spawn(tracer(
        address,
        counter,
        Arc::clone(&figures),
        Arc::clone(&stop),
    ));
    let clients_count = clients.len() + 1;

    // Warm-up: a tenth of the run, at most a minute; memory is compared from there on.
    let warm_up = (duration / 10).min(Duration::from_secs(60));
    tokio::time::sleep(warm_up).await;
    let rss_warm = resident_kb();
    let missed_warm = scheduler.status().tasks[0].missed_cycles;
    tokio::time::sleep(duration.saturating_sub(warm_up)).await;
    let rss_end = resident_kb();
    stop.store(true, Ordering::Relaxed);
    for client in clients {
        client.await.unwrap();
    }
    let trace = tracer.await.unwrap();
    let task = scheduler.status().tasks[0].clone();

    println!(
        "soak: {clients_count} clients for {} s against a 1 ms task ({} cycles run, {}) on {} processors; load average {load_start} at the start, {} at the end",
        duration.as_secs(),
        task.cycles,
        scheduler.status().realtime,
        std::thread::available_parallelism().map_or(0, usize::from),
        load_average()
    );
    println!(
        "| trace every cycle | {} samples in {} recordings of {TRACE_SEGMENT_SAMPLES} | lost (gaps in a recording): {} | cycles between recordings (re-arming): {} |",
        trace.samples,
        trace.recordings + 1,
        trace.lost,
        trace.rearm_gap_cycles
    );
    println!(
        "| 1 ms task, start to start of consecutive traced cycles | p50 {:.3} ms | p99 {:.3} ms | p99.9 {:.3} ms | max {:.3} ms |",
        trace.intervals.percentile_us(50) as f64 / 1e3,
        trace.intervals.percentile_us(99) as f64 / 1e3,
        trace.intervals.permille_us(999) as f64 / 1e3,
        trace.intervals.max_us as f64 / 1e3
    );
    println!(
        "| 1 ms task | missed cycles: {} ({} after warm-up) | start jitter max {:.3} ms, average {:.3} ms | cycle max {:.3} ms, average {:.3} ms |",
        task.missed_cycles,
        task.missed_cycles - missed_warm,
        task.max_jitter_ns as f64 / 1e6,
        task.average_jitter_ns() as f64 / 1e6,
        task.max_cycle_ns as f64 / 1e6,
        task.average_cycle_ns() as f64 / 1e6
    );
    println!("| client kind | served | failed | p50 | p99 | max |");
    for kind in KINDS {
        let latencies = figures.kinds[kind as usize].lock().unwrap();
        println!(
            "| {} | {} | {} | {:.3} ms | {:.3} ms | {:.3} ms |",
            kind.label(),
            latencies.served,
            latencies.failed,
            latencies.percentile_us(50) as f64 / 1e3,
            latencies.percentile_us(99) as f64 / 1e3,
            latencies.max_us as f64 / 1e3
        );
    }
    println!(
        "| resident memory (VmRSS) | start {rss_start} kB | after {} s warm-up {rss_warm} kB | end {rss_end} kB | growth after warm-up {} kB |",
        warm_up.as_secs(),
        rss_end as i64 - rss_warm as i64
    );
}
