//! The `rivet-runtime` binary as a process: it runs an image, serves it over Modbus TCP to
//! tokio-modbus, mbpoll and pymodbus, keeps a RETAIN variable across a restart, refuses a
//! damaged image while it goes on serving, and with `--password-file` lets only a logged-in client
//! change the target over the online services. Module `rtu` runs it as a Modbus RTU slave to
//! mbpoll over socat's virtual serial cables.
//!
//! The image is built by hand from `program_image` types (the runtime may not use the compiler;
//! the `tests` crate runs compiled Structured Text in process). It is this program, with a
//! 1 ms cyclic task:
//!
//! ```text
//! out AT %QX0.0 := in AT %MX0.0;
//! counter AT %QW1 := counter + 1;
//! IF count AT %MX0.1 THEN total := total + 1; END_IF   (total : DINT RETAIN)
//! shown AT %MD1 := total;
//! quotient := 1 / (divisor AT %MW4 + 1);   (a division by zero when %MW4 is -1)
//! ```

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::{BufRead, BufReader};
use std::net::SocketAddr;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use program_image::{
    BinaryOp, Elementary, Instr, Layout, Operand, Pou, PouKind, ProgramCall, ProgramImage,
    RetainLayout, Task, TaskKind,
};
use tokio_modbus::client::{Context, Reader, Writer};

mod peers;
mod rtu;

use peers::{python_with_pymodbus, required_program, run};

/// How long any one step may take before the test gives up on the runtime.
const PATIENCE: Duration = Duration::from_secs(10);

/// Holding register of `%QW1`.
const COUNTER: u16 = 1;
/// Holding register of `%MW0` (`%MX0.0` is its bit 0, `%MX0.1` its bit 1).
const FLAGS: u16 = 1024;
/// Holding registers of `%MD1`, high word first.
const TOTAL: u16 = 2048 + 2;
/// Holding register of `%MW4`.
const DIVISOR: u16 = 1024 + 4;

fn image() -> ProgramImage {
    let code = vec![
        Instr::GetBit {
            ty: Elementary::Byte,
            dst: Operand::Global(0),
            src: Operand::Memory(0),
            bit: 0,
        },
        Instr::SetBit {
            ty: Elementary::Byte,
            dst: Operand::Output(0),
            bit: 0,
            src: Operand::Global(0),
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Elementary::Int,
            dst: Operand::Output(2),
            a: Operand::Output(2),
            b: Operand::Const(0),
        },
        Instr::GetBit {
            ty: Elementary::Byte,
            dst: Operand::Global(1),
            src: Operand::Memory(0),
            bit: 1,
        },
        Instr::JumpIfNot {
            cond: Operand::Global(1),
            target: 6,
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Elementary::Dint,
            dst: Operand::Global(4),
            a: Operand::Global(4),
            b: Operand::Const(4),
        },
        Instr::Move {
            ty: Elementary::Dint,
            dst: Operand::Memory(4),
            src: Operand::Global(4),
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Elementary::Int,
            dst: Operand::Global(2),
            a: Operand::Memory(8),
            b: Operand::Const(0),
        },
        Instr::Binary {
            op: BinaryOp::Div,
            ty: Elementary::Int,
            dst: Operand::Global(2),
            a: Operand::Const(0),
            b: Operand::Global(2),
        },
        Instr::Return,
    ];
    ProgramImage {
        layout: Layout {
            data_size: 8,
            input_size: 2,
            output_size: 4,
            memory_size: 10,
            stack_size: 64,
        },
        pous: vec![Pou {
            name: "Main".to_owned(),
            kind: PouKind::Program,
            frame_size: 0,
            frame_init: Vec::new(),
            instance_size: 0,
            code,
            lines: Vec::new(),
        }],
        constants: [1_i32.to_le_bytes(), 1_i32.to_le_bytes()].concat(),
        tasks: vec![Task {
            name: "MainTask".to_owned(),
            kind: TaskKind::Cyclic,
            interval_ns: 1_000_000,
            trigger: None,
            priority: 1,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: vec![ProgramCall {
                pou: 0,
                instance_offset: 0,
            }],
        }],
        retain: RetainLayout {
            retain: vec![(4, 4)],
            persistent: Vec::new(),
        },
        ..ProgramImage::default()
    }
}

/// A running `rivet-runtime`, killed when dropped.
struct Runtime {
    child: Child,
    address: SocketAddr,
    stderr: mpsc::Receiver<String>,
    /// What it said on standard error so far.
    said: Vec<String>,
}

impl Runtime {
    /// Starts the binary on port 0 of 127.0.0.1 with `extra` arguments and reads the address
    /// it bound.
    fn start(data_dir: &Path, image: Option<&Path>, extra: &[&str]) -> Self {
        let mut command = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"));
        command
            .args(["--listen", "127.0.0.1:0", "--data-dir"])
            .arg(data_dir)
            .args(extra)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        if let Some(image) = image {
            command.arg("--image").arg(image);
        }
        let mut child = command.spawn().unwrap();
        let (line_sender, lines) = mpsc::channel();
        let stdout = child.stdout.take().unwrap();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines() {
                if line_sender.send(line.unwrap_or_default()).is_err() {
                    break;
                }
            }
        });
        let (error_sender, stderr) = mpsc::channel();
        let errors = child.stderr.take().unwrap();
        std::thread::spawn(move || {
            for line in BufReader::new(errors).lines() {
                if error_sender.send(line.unwrap_or_default()).is_err() {
                    break;
                }
            }
        });
        let first = lines
            .recv_timeout(PATIENCE)
            .expect("rivet-runtime printed no address");
        let address = first
            .strip_prefix("listening on ")
            .unwrap_or_else(|| panic!("unexpected first line {first:?}"))
            .parse()
            .unwrap();
        Self {
            child,
            address,
            stderr,
            said: Vec::new(),
        }
    }

    /// Waits until a line on standard error contains `text`, and returns it.
    #[track_caller]
    fn wait_for_message(&mut self, text: &str) -> String {
        let deadline = Instant::now() + PATIENCE;
        loop {
            if let Some(line) = self.said.iter().find(|line| line.contains(text)) {
                return line.clone();
            }
            let left = deadline.saturating_duration_since(Instant::now());
            match self.stderr.recv_timeout(left) {
                Ok(line) => self.said.push(line),
                Err(_) => panic!(
                    "rivet-runtime never said {text:?}; it said {:#?}",
                    self.said
                ),
            }
        }
    }

    /// Everything it has said on standard error up to now.
    fn messages(&mut self) -> &[String] {
        while let Ok(line) = self.stderr.try_recv() {
            self.said.push(line);
        }
        &self.said
    }

    /// Sends SIGTERM, waits for a successful exit, and returns all it said on standard error.
    #[track_caller]
    fn terminate(mut self) -> Vec<String> {
        let pid = self.child.id().to_string();
        let sent = Command::new("kill").args(["-TERM", &pid]).status().unwrap();
        assert!(sent.success());
        let deadline = Instant::now() + PATIENCE;
        let status = loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                break status;
            }
            assert!(Instant::now() < deadline, "rivet-runtime ignored SIGTERM");
            std::thread::sleep(Duration::from_millis(10));
        };
        assert!(status.success(), "rivet-runtime exited with {status}");
        self.wait_for_message("terminated");
        std::mem::take(&mut self.said)
    }
}

impl Drop for Runtime {
    fn drop(&mut self) {
        // Only a runtime that a failed test leaves behind is still running here.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn write_image(dir: &Path, bytes: &[u8]) -> PathBuf {
    let path = dir.join("program.rimg");
    std::fs::write(&path, bytes).unwrap();
    path
}

async fn connect(address: SocketAddr) -> Context {
    tokio::time::timeout(PATIENCE, tokio_modbus::client::tcp::connect(address))
        .await
        .expect("connecting took too long")
        .unwrap()
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

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_binary_runs_its_image_for_tokio_modbus_mbpoll_and_pymodbus() {
    let dir = tempfile::tempdir().unwrap();
    let image = write_image(dir.path(), &image().encode());
    let mut runtime = Runtime::start(&dir.path().join("data"), Some(&image), &[]);
    runtime.wait_for_message("running");
    let mut client = connect(runtime.address).await;

    let first = read_until(&mut client, COUNTER, 1, "the counter", |_| true).await[0];
    read_until(&mut client, COUNTER, 1, "the counter to count", |now| {
        now[0].wrapping_sub(first) >= 10
    })
    .await;
    let coil = client.read_coils(0, 1).await.unwrap().unwrap();
    assert_eq!(coil, [false]);
    client
        .write_single_register(FLAGS, 1)
        .await
        .unwrap()
        .unwrap();
    let deadline = Instant::now() + PATIENCE;
    while client.read_coils(0, 1).await.unwrap().unwrap() != [true] {
        assert!(Instant::now() < deadline, "%QX0.0 never followed %MX0.0");
        tokio::time::sleep(Duration::from_millis(5)).await;
    }

    // mbpoll counts references from 1: holding register 1 is its reference 2.
    let port = runtime.address.port().to_string();
    let mbpoll_common = ["-m", "tcp", "-a", "1", "-1", "-o", "5", "-p", &port];
    let read_counter: Vec<String> = mbpoll_common
        .iter()
        .copied()
        .chain(["-t", "4", "-r", "2", "-c", "1", "127.0.0.1"])
        .map(str::to_owned)
        .collect();
    let printed = run(required_program("mbpoll"), read_counter).await;
    let value: u16 = printed
        .lines()
        .find_map(|line| line.strip_prefix("[2]:"))
        .unwrap_or_else(|| panic!("mbpoll printed no register:\n{printed}"))
        .trim()
        .parse()
        .unwrap();
    assert_ne!(value, 0);
    let clear_flags: Vec<String> = mbpoll_common
        .iter()
        .copied()
        .chain(["-t", "4", "-r", "1025", "127.0.0.1", "0"])
        .map(str::to_owned)
        .collect();
    run(required_program("mbpoll"), clear_flags).await;

    let script = "import sys, time\n\
        from pymodbus.client import ModbusTcpClient\n\
        client = ModbusTcpClient('127.0.0.1', port=int(sys.argv[1]), timeout=5)\n\
        assert client.connect()\n\
        deadline = time.time() + 10\n\
        while client.read_coils(0, count=1).bits[0]:\n\
        \x20   assert time.time() < deadline, '%QX0.0 never followed %MX0.0'\n\
        \x20   time.sleep(0.005)\n\
        a = client.read_holding_registers(1, count=1).registers[0]\n\
        time.sleep(0.05)\n\
        b = client.read_holding_registers(1, count=1).registers[0]\n\
        print('counted', (b - a) % 65536)\n";
    let printed = run(
        python_with_pymodbus(),
        vec!["-c".to_owned(), script.to_owned(), port],
    )
    .await;
    let counted: u32 = printed
        .trim()
        .strip_prefix("counted ")
        .unwrap_or_else(|| panic!("pymodbus printed {printed:?}"))
        .parse()
        .unwrap();
    assert!(counted > 0, "the counter stood still for 50 ms");
    runtime.terminate();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_retain_variable_survives_a_restart_of_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("data");
    let image = write_image(dir.path(), &image().encode());
    let total = |words: &[u16]| (u32::from(words[0]) << 16) | u32::from(words[1]);

    let mut first = Runtime::start(&data, Some(&image), &[]);
    first.wait_for_message("no retain data saved");
    let mut client = connect(first.address).await;
    client
        .write_single_register(FLAGS, 2)
        .await
        .unwrap()
        .unwrap();
    read_until(&mut client, TOTAL, 2, "the total to count", |words| {
        total(words) >= 20
    })
    .await;
    client
        .write_single_register(FLAGS, 0)
        .await
        .unwrap()
        .unwrap();
    // Once counting has stopped, two reads a while apart agree.
    let mut kept = total(&read_until(&mut client, TOTAL, 2, "", |_| true).await);
    let deadline = Instant::now() + PATIENCE;
    loop {
        tokio::time::sleep(Duration::from_millis(20)).await;
        let now = total(&read_until(&mut client, TOTAL, 2, "", |_| true).await);
        if now == kept {
            break;
        }
        assert!(Instant::now() < deadline, "the total kept counting");
        kept = now;
    }
    drop(client);
    first.terminate();

    let mut second = Runtime::start(&data, Some(&image), &[]);
    second.wait_for_message("restored RETAIN and PERSISTENT variables");
    let mut client = connect(second.address).await;
    // %MD1 shows the total from the first cycle on.
    let restored = read_until(&mut client, COUNTER, 1, "a cycle", |now| now[0] > 0).await;
    assert!(restored[0] > 0);
    let words = client
        .read_holding_registers(TOTAL, 2)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(total(&words), kept);
    second.terminate();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_damaged_image_is_refused_with_the_reason_and_modbus_is_still_served() {
    let dir = tempfile::tempdir().unwrap();
    let bytes = image().encode();
    let mut corrupted = bytes.clone();
    let middle = corrupted.len() / 2;
    corrupted[middle] ^= 0x55;
    let mut newer = bytes.clone();
    newer[8..10].copy_from_slice(&2_u16.to_le_bytes());
    let cases = [
        (corrupted, "corrupted"),
        (bytes[..20].to_vec(), "truncated"),
        (newer, "format version 2, this runtime reads version 1"),
        (vec![b'x'; 100], "RIVETIMG"),
    ];
    for (bytes, reason) in cases {
        let image = write_image(dir.path(), &bytes);
        let mut runtime = Runtime::start(&dir.path().join("data"), Some(&image), &[]);
        let message = runtime.wait_for_message("refusing the program image");
        assert!(message.contains(reason), "{message}");
        assert!(message.contains("program.rimg"), "{message}");
        let mut client = connect(runtime.address).await;
        // Without a program the areas are empty: the server answers, with an exception.
        let answer = client.read_holding_registers(0, 1).await.unwrap();
        assert_eq!(answer, Err(tokio_modbus::ExceptionCode::IllegalDataAddress));
        drop(client);
        runtime.terminate();
    }
}

#[test]
fn a_missing_data_dir_argument_is_refused_by_the_argument_parser() {
    let output = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
        .arg("--listen")
        .arg("127.0.0.1:0")
        .output()
        .unwrap();
    assert!(!output.status.success());
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(said.contains("--data-dir"), "{said}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_runtime_started_stopped_loads_its_image_and_runs_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let image = write_image(dir.path(), &image().encode());
    let mut runtime = Runtime::start(&dir.path().join("data"), Some(&image), &["--stopped"]);
    runtime.wait_for_message("loaded");
    let mut client = connect(runtime.address).await;
    // The image's areas exist, and no cycle changes them.
    for _ in 0..10 {
        let counter = client.read_holding_registers(COUNTER, 1).await.unwrap();
        assert_eq!(counter, Ok(vec![0]));
        tokio::time::sleep(Duration::from_millis(5)).await;
    }
    drop(client);
    let said = runtime.terminate();
    assert!(
        !said.iter().any(|line| line.ends_with(": running")),
        "{said:#?}"
    );
}

#[test]
fn the_load_says_which_engine_runs_the_image_and_an_unknown_engine_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let image = write_image(dir.path(), &image().encode());
    for (engine, said) in [
        (
            "native",
            "rivet-runtime: native engine: 1 of 1 POUs run as machine code (",
        ),
        (
            "interpreter",
            "rivet-runtime: engine: the interpreter runs all 1 POUs (--engine interpreter)",
        ),
    ] {
        if engine == "native" && !runtime::engine::EngineChoice::native_available() {
            continue;
        }
        let mut runtime = Runtime::start(
            &dir.path().join("data"),
            Some(&image),
            &["--stopped", "--engine", engine],
        );
        let line = runtime.wait_for_message("engine");
        assert!(line.starts_with(said), "{line}");
        runtime.terminate();
    }
    let output = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
        .args(["--listen", "127.0.0.1:0", "--engine", "fast", "--data-dir"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(!output.status.success());
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(
        said.contains("invalid value 'fast' for '--engine"),
        "{said}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_fault_is_reported_on_standard_error_and_modbus_goes_on() {
    let dir = tempfile::tempdir().unwrap();
    let image = write_image(dir.path(), &image().encode());
    let mut runtime = Runtime::start(&dir.path().join("data"), Some(&image), &[]);
    runtime.wait_for_message("running");
    let mut client = connect(runtime.address).await;
    client
        .write_single_register(DIVISOR, 0xffff)
        .await
        .unwrap()
        .unwrap();
    let message = runtime.wait_for_message("stopped");
    assert_eq!(
        message,
        "rivet-runtime: task 'MainTask' stopped: division by zero in Main (instruction 8)"
    );
    let stood = client
        .read_holding_registers(COUNTER, 1)
        .await
        .unwrap()
        .unwrap();
    tokio::time::sleep(Duration::from_millis(20)).await;
    let now = client
        .read_holding_registers(COUNTER, 1)
        .await
        .unwrap()
        .unwrap();
    assert_eq!(now, stood, "the faulted task went on counting");
    drop(client);
    runtime.terminate();
}

/// Sends an online request (function code 0x64) and returns the status and payload.
async fn online(client: &mut Context, request: &online_protocol::Request) -> (u8, Vec<u8>) {
    use tokio_modbus::client::Client;
    let call = client.call(tokio_modbus::Request::Custom(
        online_protocol::FUNCTION_CODE,
        std::borrow::Cow::Owned(request.encode()),
    ));
    let response = tokio::time::timeout(PATIENCE, call)
        .await
        .expect("the answer took too long")
        .unwrap()
        .unwrap();
    let tokio_modbus::Response::Custom(_, body) = response else {
        panic!("not a custom response: {response:?}");
    };
    (body[1], body[2..].to_vec())
}

#[test]
fn a_password_on_the_command_line_and_bad_server_options_are_refused_saying_why() {
    let dir = tempfile::tempdir().unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
        .args([
            "--listen",
            "127.0.0.1:0",
            "--password",
            "swordfish",
            "--data-dir",
        ])
        .arg(dir.path())
        .env_remove("RIVET_PASSWORD")
        .output()
        .unwrap();
    assert!(!output.status.success());
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(
        said.contains("--password-file") && said.contains("RIVET_PASSWORD"),
        "{said}"
    );
    let output = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
        .args([
            "--listen",
            "127.0.0.1:0",
            "--modbus-writes",
            "inputs:0",
            "--data-dir",
        ])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(!output.status.success());
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(said.contains("`coils` or `holding`"), "{said}");
    let output = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
        .args([
            "--listen",
            "127.0.0.1:0",
            "--idle-timeout-seconds",
            "0",
            "--data-dir",
        ])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(!output.status.success());
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(said.contains("--idle-timeout-seconds"), "{said}");
    // The Modbus master's options (`docs/modbus-master.md` §6.11).
    for (option, value, expected) in [
        ("--serial-port", "RS485", "is not NAME=PATH"),
        ("--modbus-master", "maybe", "--modbus-master"),
    ] {
        let output = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
            .args(["--listen", "127.0.0.1:0", option, value, "--data-dir"])
            .arg(dir.path())
            .output()
            .unwrap();
        assert!(!output.status.success());
        let said = String::from_utf8_lossy(&output.stderr);
        assert!(said.contains(expected), "{said}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn with_a_password_the_binary_stops_only_for_a_logged_in_client() {
    use online_protocol::Request;

    let dir = tempfile::tempdir().unwrap();
    let image = write_image(dir.path(), &image().encode());
    let password_file = dir.path().join("password");
    std::fs::write(&password_file, "swordfish\n").unwrap();
    let mut runtime = Runtime::start(
        &dir.path().join("data"),
        Some(&image),
        &["--password-file", password_file.to_str().unwrap()],
    );
    runtime.wait_for_message("running");
    let mut client = connect(runtime.address).await;
    let (status, identity) = online(
        &mut client,
        &Request::Identify {
            protocol: online_protocol::PROTOCOL_VERSION,
        },
    )
    .await;
    assert_eq!(status, 0);
    // The password byte comes before version 3's debug byte.
    assert_eq!(identity[identity.len() - 2], 1, "a password is required");
    assert_eq!(online(&mut client, &Request::Stop { token: 0 }).await.0, 3);
    // Standard writes would bypass the password: by default they are refused, with
    // exception 1 wherever they write, while reads go on.
    for register in [1, 9000] {
        let refused = client.write_single_register(register, 7).await.unwrap();
        assert_eq!(refused, Err(tokio_modbus::ExceptionCode::IllegalFunction));
    }
    client.read_holding_registers(1, 1).await.unwrap().unwrap();
    let login = Request::Login {
        password: "swordfish".to_owned(),
    };
    let (status, token) = online(&mut client, &login).await;
    assert_eq!(status, 0);
    let token = u128::from_le_bytes(token.try_into().unwrap());
    assert_eq!(
        online(&mut client, &Request::Stop { token }).await,
        (0, vec![1])
    );
    drop(client);
    runtime.terminate();
}
