//! The online services' figures (issue 5): monitoring 1,000 variables, downloading a 1 MB
//! image, and tracing 32 variables every cycle of a 1 ms task for 10,000 samples while four
//! other clients poll the I/O map. `cargo bench -p tests --bench online_report` prints them.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use online::{Client, Place, TraceConfig, Trigger};
use runtime::areas::LocatedAreas;
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};
use tokio_modbus::client::Reader as _;

fn compile(text: &str) -> Vec<u8> {
    let source = compiler::SourceProject::new(text);
    compiler::compile_source(&source, "bench.st")
        .unwrap()
        .encode()
}

/// A program of 1,000 variables of mixed types, changing every cycle, in a task of `interval`.
fn mixed_program(variables: usize) -> String {
    let types = ["BOOL", "INT", "DINT", "REAL"];
    let mut declarations = String::new();
    let mut body = String::from("n := n + 1;\n");
    for i in 0..variables {
        let ty = types[i % 4];
        declarations.push_str(&format!("v{i} : {ty};\n"));
        body.push_str(&match ty {
            "BOOL" => format!("v{i} := (n MOD 2) = 0;\n"),
            "INT" => format!("v{i} := DINT_TO_INT(n MOD 1000);\n"),
            "DINT" => format!("v{i} := n + {i};\n"),
            _ => format!("v{i} := DINT_TO_REAL(n) * 0.5;\n"),
        });
    }
    format!("PROGRAM Main\nVAR\nn : DINT;\n{declarations}END_VAR\n{body}END_PROGRAM\n")
}

async fn start() -> (std::net::SocketAddr, Arc<Scheduler>) {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler =
        Arc::new(Scheduler::spawn(Arc::clone(&areas), SchedulerOptions::default()).unwrap());
    let services = Arc::new(OnlineServices::new(Arc::clone(&scheduler), None));
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let address = listener.local_addr().unwrap();
    tokio::spawn(serve(
        listener,
        areas,
        MapSlot::new(ModbusMap::default()),
        ServerOptions {
            custom: Some(services.handler()),
            closed: Some(services.closed_handler()),
            ..ServerOptions::default()
        },
    ));
    (address, scheduler)
}

#[tokio::main(flavor = "multi_thread", worker_threads = 2)]
async fn main() {
    let (address, _scheduler) = start().await;
    let (mut client, _) = Client::connect(address, None).await.unwrap();

    // 1. Monitoring 1,000 variables of mixed types.
    client
        .download(&compile(&mixed_program(1000)), true, |_, _| {})
        .await
        .unwrap();
    let mut places: Vec<Place> = Vec::new();
    for i in 0..1000 {
        places.push(client.resolve(&format!("Main.v{i}")).await.unwrap().place);
    }
    let refreshes = 200;
    let started = Instant::now();
    for _ in 0..refreshes {
        client.read(&places).await.unwrap();
    }
    let per_refresh = started.elapsed() / refreshes;
    println!(
        "| monitor 1,000 variables | {:.2} ms per refresh | {:.0} Hz (target >= 100 Hz) |",
        per_refresh.as_secs_f64() * 1e3,
        1.0 / per_refresh.as_secs_f64()
    );

    // 2. Downloading a 1 MB image.
    let mut big = mixed_program(1000);
    let mut n = 1000;
    let mut image = compile(&big);
    while image.len() < 1_000_000 {
        n += 4000;
        big = mixed_program(n);
        image = compile(&big);
    }
    let started = Instant::now();
    client.download(&image, true, |_, _| {}).await.unwrap();
    let took = started.elapsed();
    println!(
        "| download {:.2} MB | {:.0} ms | {:.1} MB/s (target < 500 ms for 1 MB) |",
        image.len() as f64 / 1e6,
        took.as_secs_f64() * 1e3,
        image.len() as f64 / 1e6 / took.as_secs_f64()
    );

    // 3. Tracing 32 variables every cycle of a 1 ms task, four clients polling meanwhile.
    let source = compiler::SourceProject::new(&mixed_program(32));
    let mut project = source.project.clone();
    project.tasks = vec![project_model::Task {
        name: "Fast".to_owned(),
        kind: project_model::TaskKind::Cyclic { interval_us: 1000 },
        priority: 0,
        watchdog: None,
        programs: vec!["Main".to_owned()],
    }];
    let image = compiler::compile_project(&project).unwrap().encode();
    client.download(&image, true, |_, _| {}).await.unwrap();
    let mut places = Vec::new();
    for i in 0..32 {
        places.push(client.resolve(&format!("Main.v{i}")).await.unwrap().place);
    }
    let samples = 10_000;
    client
        .trace_configure(&TraceConfig {
            task: 0,
            every: 1,
            samples,
            pretrigger_percent: 0,
            trigger: Trigger::None,
            places: places.clone(),
        })
        .await
        .unwrap();
    let stop = Arc::new(std::sync::atomic::AtomicBool::new(false));
    let mut pollers = Vec::new();
    for _ in 0..4 {
        let stop = Arc::clone(&stop);
        pollers.push(tokio::spawn(async move {
            let mut context = tokio_modbus::client::tcp::connect(address).await.unwrap();
            let mut polls = 0u64;
            while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                let _ = context.read_holding_registers(0, 100).await;
                polls += 1;
            }
            polls
        }));
    }
    client.trace_arm().await.unwrap();
    let started = Instant::now();
    loop {
        let status = client.trace_status().await.unwrap();
        if status.state == online::TraceState::Complete
            || started.elapsed() > Duration::from_secs(60)
        {
            break;
        }
        tokio::time::sleep(Duration::from_millis(100)).await;
    }
    let recorded_in = started.elapsed();
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    let mut polls = 0;
    for poller in pollers {
        polls += poller.await.unwrap();
    }
    let started = Instant::now();
    let uploaded = client.trace_upload(&places, |_| {}).await.unwrap();
    let upload = started.elapsed();
    let consecutive = uploaded.windows(2).all(|w| w[1].cycle == w[0].cycle + 1);
    println!(
        "| trace 32 variables, 1 ms task | {} of {samples} samples, consecutive: {consecutive} | recorded in {:.1} s, uploaded in {:.0} ms; 4 pollers made {polls} requests meanwhile |",
        uploaded.len(),
        recorded_in.as_secs_f64(),
        upload.as_secs_f64() * 1e3
    );
}
