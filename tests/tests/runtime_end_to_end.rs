//! Structured Text compiled by `compiler`, run by the `runtime` scheduler and served by its
//! Modbus TCP server, all in this process, read and written by tokio-modbus, mbpoll and pymodbus
//! over 127.0.0.1. The `rivet-runtime` binary itself is tested in `runtime/tests/`.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::net::SocketAddr;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use program_image::ProgramImage;
use runtime::areas::{Area, LocatedAreas};
use runtime::engine::{FaultKind, ResetKind};
use runtime::modbus::{MapSlot, ModbusMap, ServerOptions, serve};
use runtime::retain::RetainRestore;
use runtime::scheduler::{Scheduler, SchedulerOptions, SchedulerState, SchedulerStatus};
use tests::peers::{python_with_pymodbus, required_program, run};
use tokio_modbus::client::{Context, Reader, Writer};

/// How long any one step may take before the test gives up.
const PATIENCE: Duration = Duration::from_secs(10);

/// The program of most tests; its task is the implicit 10 ms cyclic one.
const MACHINE: &str = "\
PROGRAM Main
VAR
    counter AT %QW1 : INT;
    button AT %IX0.0 : BOOL;
    lamp AT %QX0.0 : BOOL;
    request AT %MX0.0 : BOOL;
    echo AT %QX0.1 : BOOL;
    shown AT %MD1 : DINT;
END_VAR
VAR RETAIN
    total : DINT;
END_VAR
counter := counter + 1;
lamp := button;
echo := request;
IF request THEN
    total := total + 1;
END_IF
shown := total;
END_PROGRAM
";

/// Holding register of `%QW1`.
const COUNTER: u16 = 1;
/// Holding register of `%MW0`, whose bit 0 is `%MX0.0`.
const FLAGS: u16 = 1024;
/// Holding registers of `%MD1`, high word first.
const TOTAL: u16 = 2048 + 2;

fn compile(text: &str) -> ProgramImage {
    let source = compiler::SourceProject::new(text);
    match compiler::compile_source(&source, "test.st") {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(diagnostics)) => {
            panic!("the test program does not compile: {diagnostics:#?}")
        }
        Err(error) => panic!("the test program does not compile: {error}"),
    }
}

/// A scheduler and a Modbus server on 127.0.0.1 port 0, sharing their areas.
struct Plc {
    scheduler: Scheduler,
    areas: Arc<Mutex<LocatedAreas>>,
    address: SocketAddr,
    server: tokio::task::JoinHandle<std::io::Result<()>>,
}

impl Plc {
    async fn start(options: SchedulerOptions) -> Self {
        let areas = Arc::new(Mutex::new(LocatedAreas::default()));
        let scheduler = Scheduler::spawn(Arc::clone(&areas), options).unwrap();
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
        let address = listener.local_addr().unwrap();
        let server = tokio::spawn(serve(
            listener,
            Arc::clone(&areas),
            MapSlot::new(ModbusMap::default()),
            ServerOptions::default(),
        ));
        Self {
            scheduler,
            areas,
            address,
            server,
        }
    }

    async fn connect(&self) -> Context {
        tokio::time::timeout(PATIENCE, tokio_modbus::client::tcp::connect(self.address))
            .await
            .expect("connecting took too long")
            .unwrap()
    }

    /// Stops serving and shuts the scheduler down, saving retained values.
    fn shutdown(self) {
        self.server.abort();
        self.scheduler.shutdown().unwrap();
    }
}

/// Waits, without blocking the async workers, until the scheduler's status satisfies `done`.
async fn wait_for(
    scheduler: &Scheduler,
    what: &str,
    done: impl Fn(&SchedulerStatus) -> bool,
) -> SchedulerStatus {
    let deadline = Instant::now() + PATIENCE;
    loop {
        let status = scheduler.status();
        if done(&status) {
            return status;
        }
        assert!(
            Instant::now() < deadline,
            "waited in vain for {what}: {status:#?}"
        );
        tokio::time::sleep(Duration::from_millis(2)).await;
    }
}

/// Reads holding registers until `done` accepts them.
async fn read_until(
    client: &mut Context,
    address: u16,
    count: u16,
    what: &str,
    done: impl Fn(&[u16]) -> bool,
) -> Vec<u16> {
    let deadline = Instant::now() + PATIENCE;
    loop {
        let values = client
            .read_holding_registers(address, count)
            .await
            .unwrap()
            .unwrap();
        if done(&values) {
            return values;
        }
        assert!(
            Instant::now() < deadline,
            "waited in vain for {what}: {values:?}"
        );
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
}

/// Reads coils until they equal `expected`.
async fn wait_for_coils(client: &mut Context, first: u16, expected: &[bool], what: &str) {
    let deadline = Instant::now() + PATIENCE;
    loop {
        let coils = client
            .read_coils(first, expected.len() as u16)
            .await
            .unwrap()
            .unwrap();
        if coils == expected {
            return;
        }
        assert!(
            Instant::now() < deadline,
            "waited in vain for {what}: {coils:?}"
        );
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
}

fn total(words: &[u16]) -> u32 {
    (u32::from(words[0]) << 16) | u32::from(words[1])
}

/// mbpoll's arguments for the server at `address`, references counted from 1 as mbpoll does.
fn mbpoll_args(address: SocketAddr, options: &str, values: &str) -> Vec<String> {
    let port = address.port().to_string();
    ["-m", "tcp", "-a", "1", "-1", "-o", "5", "-p", &port]
        .into_iter()
        .chain(options.split_whitespace())
        .chain(["127.0.0.1"])
        .chain(values.split_whitespace())
        .map(str::to_owned)
        .collect()
}

/// Runs a blocking client program off the async workers.
async fn run_client(program: String, args: Vec<String>) -> String {
    tokio::task::spawn_blocking(move || run(&program, &args))
        .await
        .unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_compiled_program_serves_its_located_variables_to_three_clients() {
    let plc = Plc::start(SchedulerOptions::default()).await;
    plc.scheduler.load(compile(MACHINE)).unwrap();
    plc.scheduler.start().unwrap();
    let mut client = plc.connect().await;

    // tokio-modbus: the counter counts, an input reaches an output, a memory flag too.
    let first = read_until(&mut client, COUNTER, 1, "a cycle", |_| true).await[0];
    read_until(&mut client, COUNTER, 1, "the counter to count", |now| {
        now[0].wrapping_sub(first) >= 5
    })
    .await;
    // The I/O layer's place: %IX0.0 is a discrete input, which Modbus clients only read.
    plc.areas
        .lock()
        .unwrap()
        .set_bit(Area::Input, 0, 0, true)
        .unwrap();
    wait_for_coils(&mut client, 0, &[true, false], "%QX0.0 := %IX0.0").await;
    let inputs = client.read_discrete_inputs(0, 1).await.unwrap().unwrap();
    assert_eq!(inputs, [true]);
    client
        .write_single_register(FLAGS, 1)
        .await
        .unwrap()
        .unwrap();
    wait_for_coils(&mut client, 0, &[true, true], "%QX0.1 := %MX0.0").await;
    read_until(&mut client, TOTAL, 2, "the total to count", |words| {
        total(words) >= 3
    })
    .await;

    // mbpoll: reads %QW1 (its reference 2) and clears %MW0 (reference 1025).
    let mbpoll = required_program("mbpoll");
    let printed = run_client(
        mbpoll.clone(),
        mbpoll_args(plc.address, "-t 4 -r 2 -c 1", ""),
    )
    .await;
    let counter: i16 = printed
        .lines()
        .find_map(|line| line.strip_prefix("[2]:"))
        .unwrap_or_else(|| panic!("mbpoll printed no register:\n{printed}"))
        .trim()
        .parse()
        .unwrap();
    assert_ne!(counter, 0);
    run_client(mbpoll, mbpoll_args(plc.address, "-t 4 -r 1025", "0")).await;
    wait_for_coils(&mut client, 0, &[true, false], "%QX0.1 to follow %MX0.0").await;

    // pymodbus: the counter goes on, and the coils are as the program left them.
    let script = "import sys, time\n\
        from pymodbus.client import ModbusTcpClient\n\
        client = ModbusTcpClient('127.0.0.1', port=int(sys.argv[1]), timeout=5)\n\
        assert client.connect()\n\
        a = client.read_holding_registers(1, count=1).registers[0]\n\
        time.sleep(0.1)\n\
        b = client.read_holding_registers(1, count=1).registers[0]\n\
        print('counted', (b - a) % 65536, 'coils', client.read_coils(0, count=2).bits[:2])\n";
    let printed = run_client(
        python_with_pymodbus(),
        vec![
            "-c".to_owned(),
            script.to_owned(),
            plc.address.port().to_string(),
        ],
    )
    .await;
    let words: Vec<&str> = printed.split_whitespace().collect();
    assert_eq!(words[0], "counted", "{printed}");
    assert!(words[1].parse::<u32>().unwrap() > 0, "{printed}");
    assert_eq!(words[3..], ["[True,", "False]"], "{printed}");

    let status = plc.scheduler.status();
    assert_eq!(status.state, SchedulerState::Running);
    let task = &status.tasks[0];
    println!(
        "implicit 10 ms task over {} cycles: cycle last {} ns, average {} ns, max {} ns; \
         start jitter average {} ns, max {} ns",
        task.cycles,
        task.last_cycle_ns,
        task.average_cycle_ns(),
        task.max_cycle_ns,
        task.average_jitter_ns(),
        task.max_jitter_ns
    );
    plc.shutdown();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_retain_variable_survives_a_restart_and_a_cold_reset_clears_it() {
    let data = tempfile::tempdir().unwrap();
    let options = SchedulerOptions {
        data_dir: Some(data.path().to_owned()),
        ..SchedulerOptions::default()
    };
    let plc = Plc::start(options.clone()).await;
    let report = plc.scheduler.load(compile(MACHINE)).unwrap();
    assert!(matches!(
        report.retain,
        Some(RetainRestore::NothingSaved { .. })
    ));
    plc.scheduler.start().unwrap();
    let mut client = plc.connect().await;
    client
        .write_single_register(FLAGS, 1)
        .await
        .unwrap()
        .unwrap();
    read_until(&mut client, TOTAL, 2, "the total to count", |words| {
        total(words) >= 5
    })
    .await;
    plc.scheduler.stop().unwrap();
    let kept = total(
        &client
            .read_holding_registers(TOTAL, 2)
            .await
            .unwrap()
            .unwrap(),
    );
    drop(client);
    plc.shutdown();

    let plc = Plc::start(options).await;
    let report = plc.scheduler.load(compile(MACHINE)).unwrap();
    assert!(
        matches!(report.retain, Some(RetainRestore::Restored { .. })),
        "{report:?}"
    );
    plc.scheduler.start().unwrap();
    let mut client = plc.connect().await;
    // %MW0 starts at 0 again, so the total stands still at what was saved.
    let restored = read_until(&mut client, COUNTER, 1, "a cycle", |now| now[0] > 0).await;
    assert!(restored[0] > 0);
    let words = client
        .read_holding_registers(TOTAL, 2)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(total(&words), kept);

    plc.scheduler.reset(ResetKind::Cold).unwrap();
    plc.scheduler.start().unwrap();
    let cycles = plc.scheduler.status().tasks[0].cycles;
    wait_for(&plc.scheduler, "a cycle after the cold reset", |status| {
        status.tasks[0].cycles > cycles
    })
    .await;
    let words = client
        .read_holding_registers(TOTAL, 2)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(total(&words), 0);
    drop(client);
    plc.shutdown();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_division_by_zero_stops_its_task_with_the_line_and_modbus_goes_on() {
    let faulty = "\
PROGRAM Main
VAR
    divisor AT %MW2 : INT;
    result AT %QW0 : INT;
END_VAR
result := 100 / divisor;
END_PROGRAM
";
    let plc = Plc::start(SchedulerOptions::default()).await;
    plc.scheduler.load(compile(faulty)).unwrap();
    let mut client = plc.connect().await;
    client
        .write_single_register(1024 + 2, 4)
        .await
        .unwrap()
        .unwrap();
    plc.scheduler.start().unwrap();
    read_until(&mut client, 0, 1, "100 / 4", |words| words == [25]).await;
    client
        .write_single_register(1024 + 2, 0)
        .await
        .unwrap()
        .unwrap();
    let status = wait_for(&plc.scheduler, "the fault", |status| {
        !status.faults.is_empty()
    })
    .await;
    assert_eq!(status.state, SchedulerState::Faulted);
    let fault = &status.faults[0];
    assert_eq!(fault.kind, FaultKind::DivisionByZero);
    assert_eq!(fault.pou, "Main");
    assert_eq!(fault.line, Some(6), "{fault}");
    assert!(status.tasks[0].faulted);
    // The server still answers, with the outputs as the last good cycle left them.
    let words = client.read_holding_registers(0, 1).await.unwrap().unwrap();
    assert_eq!(words, [25]);
    drop(client);
    plc.shutdown();
}
