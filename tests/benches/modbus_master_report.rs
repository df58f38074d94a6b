//! The cost of the runtime's Modbus master (`docs/modbus-master.md` §10) as a table for a note:
//! `cargo bench -p tests --bench modbus_master_report` (not in CI).
//!
//! Starts 32 of Rivet's own Modbus servers (`runtime::modbus::serve`) in this process on
//! 127.0.0.1 port 0 and runs the real `Scheduler` on a compiled program with a 10 ms task that
//! copies 32 arrays of 16 INT read from the devices into 32 arrays written to them (plus one),
//! once with a master section of 32 devices (one read channel of holding registers 0–15 and one
//! write channel of 16–31 each, a round every 10 ms, timeout 1000 ms) and once with the same
//! image without it, for `RIVET_BENCH_SECONDS` each (60 by default). It prints the task's
//! missed cycles and start jitter, the devices' rounds and overruns, the requests per second,
//! sampled response times and the task's own execution time in both runs, whose difference is
//! the master's copy in and out. The figures depend on the machine and its load (printed
//! first); nothing is asserted.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::fmt::Write as _;
use std::net::SocketAddr;
use std::sync::{Arc, Mutex, mpsc};
use std::time::{Duration, Instant};

use online_protocol::ModbusDeviceReport;
use program_image::modbus_master::{
    ChannelDef, DeviceDef, Direction, Link, MasterSection, OnError, Schedule, Trigger, WordOrder,
};
use program_image::{Elementary, ModbusTable, ProgramImage};
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::scheduler::{CycleRecord, Scheduler, SchedulerOptions};

/// How many devices (and servers) the master polls.
const DEVICES: usize = 32;
/// How many holding registers each channel reads or writes.
const REGISTERS: u16 = 16;
/// The task's interval and the devices' round interval.
const INTERVAL_MS: u32 = 10;
/// How often the snapshots are sampled for response times.
const SAMPLE_EVERY: Duration = Duration::from_millis(100);

/// The program: one array read and one written per device; the task copies each read array
/// into its written one, plus one.
fn source() -> String {
    let mut text = String::from("PROGRAM Main\nVAR\n    i : INT;\n");
    for device in 0..DEVICES {
        writeln!(text, "    aiIn{device} : ARRAY[0..15] OF INT;").unwrap();
        writeln!(text, "    aiOut{device} : ARRAY[0..15] OF INT;").unwrap();
    }
    text.push_str("END_VAR\nFOR i := 0 TO 15 DO\n");
    for device in 0..DEVICES {
        writeln!(text, "    aiOut{device}[i] := aiIn{device}[i] + 1;").unwrap();
    }
    text.push_str("END_FOR\nEND_PROGRAM\n");
    text
}

/// The image with the 10 ms task (index 0) and no master section.
fn image() -> ProgramImage {
    let source = compiler::SourceProject::new(&source());
    let mut project = source.project.clone();
    project.tasks = vec![project_model::Task {
        name: "MainTask".to_owned(),
        kind: project_model::TaskKind::Cyclic {
            interval_us: INTERVAL_MS * 1000,
        },
        priority: 1,
        watchdog: None,
        programs: vec!["Main".to_owned()],
    }];
    compiler::compile_project(&project).unwrap()
}

/// A channel of [`REGISTERS`] INT at `address` of the holding registers.
fn channel(variable: String, address: u16, direction: Direction) -> ChannelDef {
    ChannelDef {
        variable,
        table: ModbusTable::HoldingRegisters,
        address,
        value_type: Elementary::Int,
        count: REGISTERS,
        direction,
        function_code: if direction == Direction::Read { 3 } else { 16 },
        trigger: Trigger::Cyclic,
        on_error: OnError::KeepLastValue,
        error_flag: None,
    }
}

/// Device `index` at `address`: reads registers 0–15 into `Main.aiIn{index}`, writes
/// `Main.aiOut{index}` to registers 16–31.
fn device(index: usize, address: SocketAddr) -> DeviceDef {
    DeviceDef {
        name: format!("Device{index}"),
        link: Link::Tcp {
            host: address.ip().to_string(),
            port: address.port(),
        },
        unit_id: 1,
        timeout_ms: 1000,
        task: 0,
        schedule: Schedule::Interval {
            interval_ms: INTERVAL_MS,
        },
        word_order: WordOrder::HighFirst,
        max_read_gap: 0,
        status: None,
        channels: vec![
            channel(format!("Main.aiIn{index}"), 0, Direction::Read),
            channel(format!("Main.aiOut{index}"), REGISTERS, Direction::Write),
        ],
    }
}

/// Starts one server per device on a shared tokio runtime, holding registers 0–15 set to
/// the register's number; returns the runtime (serving until dropped) and the addresses.
fn start_servers() -> (tokio::runtime::Runtime, Vec<SocketAddr>) {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(1)
        .enable_all()
        .build()
        .unwrap();
    let mut addresses = Vec::new();
    for _ in 0..DEVICES {
        let mut areas = LocatedAreas::new(256, 256, 256);
        for register in 0..usize::from(REGISTERS) {
            areas.output[2 * register..2 * register + 2]
                .copy_from_slice(&(register as i16).to_le_bytes());
        }
        let listener = runtime
            .block_on(tokio::net::TcpListener::bind(SocketAddr::from((
                [127, 0, 0, 1],
                0,
            ))))
            .unwrap();
        addresses.push(listener.local_addr().unwrap());
        runtime.spawn(serve(
            listener,
            Arc::new(Mutex::new(areas)),
            MapSlot::new(ModbusMap::default()),
            ServerOptions::default(),
        ));
    }
    (runtime, addresses)
}

/// The `p`-th percentile (0 to 100) of sorted values, the value at the rank `p`% of the way
/// from the first to the last (rounded to the nearest); 0 if there are none.
fn percentile(sorted: &[u64], p: f64) -> u64 {
    if sorted.is_empty() {
        return 0;
    }
    let rank = ((p / 100.0) * (sorted.len() - 1) as f64).round() as usize;
    sorted[rank.min(sorted.len() - 1)]
}

/// What one run measured.
struct Run {
    records: Vec<CycleRecord>,
    missed_cycles: u64,
    devices: Vec<ModbusDeviceReport>,
    response_us: Vec<u64>,
    seconds: f64,
    realtime: String,
}

/// Runs `image` for `duration` and returns the cycle log, the task's missed cycles, the
/// devices' last snapshots and the response times sampled every [`SAMPLE_EVERY`].
fn run(image: &ProgramImage, duration: Duration, realtime_priority: Option<u8>) -> Run {
    let (log, records) = mpsc::channel();
    let options = SchedulerOptions {
        cycle_log: Some(log),
        realtime_priority,
        ..SchedulerOptions::default()
    };
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, options).unwrap();
    scheduler.load(image.clone()).unwrap();
    let start = Instant::now();
    scheduler.start().unwrap();
    let mut response_us = Vec::new();
    while start.elapsed() < duration {
        std::thread::sleep(SAMPLE_EVERY);
        response_us.extend(
            scheduler
                .modbus_devices()
                .iter()
                .filter(|device| device.requests > 0)
                .map(|device| u64::from(device.last_response_us)),
        );
    }
    let devices = scheduler.modbus_devices();
    let status = scheduler.status();
    let missed_cycles = status.tasks[0].missed_cycles;
    let seconds = start.elapsed().as_secs_f64();
    scheduler.stop().unwrap();
    scheduler.shutdown().unwrap();
    response_us.sort_unstable();
    Run {
        records: records.try_iter().collect(),
        missed_cycles,
        devices,
        response_us,
        seconds,
        realtime: status.realtime.to_string(),
    }
}

/// Formats nanoseconds as microseconds.
fn us(ns: u64) -> String {
    format!("{:.0} µs", ns as f64 / 1e3)
}

/// Formats the difference `with - without` of two nanosecond figures as signed microseconds:
/// on a noisy machine the run with the master may be the faster, and that is reported, not
/// hidden as 0.
fn us_added(with: u64, without: u64) -> String {
    format!("{:+.0} µs", (with as f64 - without as f64) / 1e3)
}

fn main() {
    let seconds: u64 = std::env::var("RIVET_BENCH_SECONDS")
        .ok()
        .and_then(|text| text.parse().ok())
        .unwrap_or(60);
    let duration = Duration::from_secs(seconds);
    // The figures mean little on a loaded machine; say how loaded it was.
    if let Ok(load) = std::fs::read_to_string("/proc/loadavg") {
        println!("Load average before the runs: {}\n", load.trim());
    }
    println!(
        "{DEVICES} devices × {REGISTERS} holding registers read and {REGISTERS} written, a round \
         every {INTERVAL_MS} ms over loopback TCP to Rivet's own servers in this process; a \
         {INTERVAL_MS} ms task copying all of it; {seconds} s each:\n"
    );
    let (servers, addresses) = start_servers();
    let without = image();
    let mut with = without.clone();
    with.modbus_master = Some(MasterSection {
        serial_ports: Vec::new(),
        devices: addresses
            .iter()
            .enumerate()
            .map(|(index, address)| device(index, *address))
            .collect(),
    });

    println!(
        "| master | cycles | missed | jitter p50 | jitter p99 | jitter max | own p50 | own p99 | own mean | rounds/device/s | udiOverruns | requests/s |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut runs = Vec::new();
    // The spec asks for normal priority and, where permitted, a real-time one.
    for (label, image, realtime) in [
        ("32 devices", &with, None),
        ("none", &without, None),
        ("32 devices", &with, Some(50)),
    ] {
        let run = run(image, duration, realtime);
        let label = format!("{label}, {}", run.realtime);
        let interval_ns = u64::from(INTERVAL_MS) * 1_000_000;
        let task: Vec<&CycleRecord> = run.records.iter().filter(|r| r.task == 0).collect();
        let mut jitter: Vec<u64> = task.iter().map(|r| r.jitter_ns()).collect();
        jitter.sort_unstable();
        let mut own: Vec<u64> = task.iter().map(|r| r.own_ns()).collect();
        own.sort_unstable();
        // A start later than one interval after its due time counts as missed too, beside
        // the cycles the scheduler dropped.
        let late = jitter.iter().filter(|&&ns| ns > interval_ns).count();
        let own_mean = own.iter().sum::<u64>() / own.len().max(1) as u64;
        let rounds: u64 = run.devices.iter().map(|d| u64::from(d.rounds)).sum();
        let requests: u64 = run.devices.iter().map(|d| u64::from(d.requests)).sum();
        let overruns: u64 = run.devices.iter().map(|d| u64::from(d.overruns)).sum();
        let per_second = |count: u64| count as f64 / run.seconds;
        println!(
            "| {label} | {} | {} dropped, {late} late | {} | {} | {} | {} | {} | {} | {:.1} | {overruns} | {:.0} |",
            task.len(),
            run.missed_cycles,
            us(percentile(&jitter, 50.0)),
            us(percentile(&jitter, 99.0)),
            us(jitter.last().copied().unwrap_or(0)),
            us(percentile(&own, 50.0)),
            us(percentile(&own, 99.0)),
            us(own_mean),
            per_second(rounds) / run.devices.len().max(1) as f64,
            per_second(requests),
        );
        runs.push((run, own_mean, percentile(&own, 50.0)));
    }
    drop(servers);

    let (master, master_mean, master_p50) = &runs[0];
    let (_, plain_mean, plain_p50) = &runs[1];
    println!("\nThe figures below are of the first run (32 devices, normal priority).");
    let rounds: Vec<f64> = master
        .devices
        .iter()
        .map(|device| f64::from(device.rounds) / master.seconds)
        .collect();
    let requests: u64 = master.devices.iter().map(|d| u64::from(d.requests)).sum();
    let errors: u64 = master.devices.iter().map(|d| u64::from(d.errors)).sum();
    let overruns: u64 = master.devices.iter().map(|d| u64::from(d.overruns)).sum();
    println!();
    println!(
        "Rounds per device per second: mean {:.1}, min {:.1}, max {:.1} (100 asked for)",
        rounds.iter().sum::<f64>() / rounds.len().max(1) as f64,
        rounds.iter().copied().fold(f64::MAX, f64::min),
        rounds.iter().copied().fold(0.0, f64::max),
    );
    println!("udiOverruns, all devices: {overruns}; requests failed: {errors}");
    println!(
        "Requests per second, all devices: {:.0}",
        requests as f64 / master.seconds
    );
    println!(
        "Response time (last_response_us sampled every {} ms, {} samples): p50 {} µs, p99 {} µs, max {} µs",
        SAMPLE_EVERY.as_millis(),
        master.response_us.len(),
        percentile(&master.response_us, 50.0),
        percentile(&master.response_us, 99.0),
        master.response_us.last().copied().unwrap_or(0),
    );
    println!(
        "Added cost per task cycle (own time with the master minus without): mean {}, p50 {}",
        us_added(*master_mean, *plain_mean),
        us_added(*master_p50, *plain_p50),
    );
}
