//! `rivet-runtime --modbus-rtu` as an RTU slave to mbpoll on a socat pair, 8N1
//! (`docs/modbus-master.md` §10, test 4): mbpoll reads a holding register the program counts
//! up and writes one the program reads, whose effect shows on a coil over RTU and over TCP; a
//! frame with a bad CRC and a frame for another unit get no answer, and the next good frame
//! does. A port that is missing at the start or goes away is opened again by its path
//! (`docs/modbus-master.md` §7), and bad line settings are refused at the start.

use std::process::Command;
use std::time::{Duration, Instant};

use runtime::modbus::rtu_slave::rtu_frame;
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio_modbus::client::Reader;

use crate::peers::{SocatPair, required_program};
use crate::rtu::open_when_free;
use crate::{PATIENCE, Runtime, connect, image, write_image};

/// How long the test waits for an answer the slave must not send.
const NO_ANSWER: Duration = Duration::from_millis(300);

/// mbpoll as a one-shot RTU master on `port` at 19200-8N1 with a timeout of 1 s, writing
/// `values` if any, and its output when it succeeds or `Err` with everything it said.
async fn mbpoll(port: &std::path::Path, args: &[&str], values: &[&str]) -> anyhow::Result<String> {
    let mut command = Command::new(required_program("mbpoll"));
    command
        .args([
            "-m", "rtu", "-b", "19200", "-P", "none", "-s", "1", "-1", "-o", "1",
        ])
        .args(args)
        .arg(port)
        .args(values);
    let output = tokio::task::spawn_blocking(move || command.output())
        .await
        .unwrap()
        .unwrap();
    let said = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    if output.status.success() {
        Ok(said)
    } else {
        Err(anyhow::Error::msg(said))
    }
}

/// The value mbpoll printed for reference `reference` (`[2]: 17`).
#[track_caller]
fn printed_value(printed: &str, reference: u16) -> u16 {
    let prefix = format!("[{reference}]:");
    printed
        .lines()
        .find_map(|line| line.trim().strip_prefix(&prefix))
        .unwrap_or_else(|| panic!("mbpoll printed no reference {reference}:\n{printed}"))
        .trim()
        .parse()
        .unwrap()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn mbpoll_reads_and_writes_the_runtime_over_rtu_and_bad_frames_get_no_answer() {
    let dir = tempfile::tempdir().unwrap();
    let cable = SocatPair::start(dir.path());
    let image = write_image(dir.path(), &image().encode());
    let slave_path = cable.slave.to_str().unwrap();
    let mut runtime = Runtime::start(
        &dir.path().join("data"),
        Some(&image),
        &[
            "--modbus-rtu",
            slave_path,
            "--modbus-rtu-format",
            "19200-8N1",
        ],
    );
    runtime.wait_for_message("running");
    runtime.wait_for_message("Modbus RTU slave 1 on");

    // Holding register 1 (mbpoll's reference 2) is `%QW1`, the program's counter.
    let read_counter = ["-a", "1", "-t", "4", "-r", "2", "-c", "1"];
    let first = printed_value(&mbpoll(&cable.master, &read_counter, &[]).await.unwrap(), 2);
    let deadline = Instant::now() + PATIENCE;
    loop {
        let now = printed_value(&mbpoll(&cable.master, &read_counter, &[]).await.unwrap(), 2);
        if now != first {
            break;
        }
        assert!(Instant::now() < deadline, "the counter stood at {first}");
    }

    // Holding register 1024 (reference 1025) is `%MW0`; the program copies its bit 0 to
    // `%QX0.0`, coil 0.
    mbpoll(&cable.master, &["-a", "1", "-t", "4", "-r", "1025"], &["1"])
        .await
        .unwrap();
    let deadline = Instant::now() + PATIENCE;
    loop {
        let coil = mbpoll(
            &cable.master,
            &["-a", "1", "-t", "0", "-r", "1", "-c", "1"],
            &[],
        )
        .await
        .unwrap();
        if printed_value(&coil, 1) == 1 {
            break;
        }
        assert!(Instant::now() < deadline, "%QX0.0 never followed %MX0.0");
    }
    let mut tcp = connect(runtime.address).await;
    assert_eq!(tcp.read_coils(0, 1).await.unwrap().unwrap(), [true]);

    // A damaged frame gets no answer, and the next good one does.
    let mut master = open_when_free(&cable.master, "19200-8N1");
    let read_flags = rtu_frame(1, &[0x03, 0x04, 0x00, 0x00, 0x01]);
    let mut damaged = read_flags.clone();
    damaged[3] ^= 0x10;
    master.write_all(&damaged).await.unwrap();
    let mut answer = [0; 7];
    let silent = tokio::time::timeout(NO_ANSWER, master.read(&mut answer)).await;
    assert!(silent.is_err(), "a damaged frame was answered: {answer:?}");
    runtime.wait_for_message("(1 bad CRC");
    // More damage soon after is not said at once (the runtime looks every 100 ms).
    for _ in 0..2 {
        master.write_all(&damaged).await.unwrap();
        let silent = tokio::time::timeout(NO_ANSWER, master.read(&mut answer)).await;
        assert!(silent.is_err(), "a damaged frame was answered: {answer:?}");
    }
    master.write_all(&read_flags).await.unwrap();
    tokio::time::timeout(PATIENCE, master.read_exact(&mut answer))
        .await
        .unwrap()
        .unwrap();
    assert_eq!(answer.to_vec(), rtu_frame(1, &[0x03, 0x02, 0x00, 0x01]));
    drop(master);

    // Unit 2 is another slave's business: mbpoll times out (libmodbus's ETIMEDOUT), rather
    // than failing in any other way.
    let other = mbpoll(
        &cable.master,
        &["-a", "2", "-t", "4", "-r", "2", "-c", "1"],
        &[],
    )
    .await;
    assert!(
        other
            .as_ref()
            .is_err_and(|said| said.to_string().contains("failed: Connection timed out")),
        "unit 2 was answered, or mbpoll failed otherwise: {other:?}"
    );
    mbpoll(&cable.master, &read_counter, &[]).await.unwrap();
    let said = runtime.terminate();
    // The damaged frames after the first are counted, not each said on a line of its own.
    let damage_lines: Vec<&String> = said
        .iter()
        .filter(|line| line.contains("bad CRC"))
        .collect();
    assert_eq!(damage_lines.len(), 1, "{damage_lines:#?}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_slave_waits_for_its_port_and_serves_it_again_after_the_cable_comes_back() {
    let dir = tempfile::tempdir().unwrap();
    let cable_dir = dir.path().join("cable");
    std::fs::create_dir(&cable_dir).unwrap();
    let slave_path = cable_dir.join("slave");
    let image = write_image(dir.path(), &image().encode());
    let mut runtime = Runtime::start(
        &dir.path().join("data"),
        Some(&image),
        &[
            "--modbus-rtu",
            slave_path.to_str().unwrap(),
            "--modbus-rtu-format",
            "19200-8N1",
            "--modbus-rtu-unit",
            "7",
        ],
    );
    let missing = runtime.wait_for_message("trying again in 100 ms");
    assert!(
        missing.contains(&format!("cannot open {}", slave_path.display())),
        "{missing}"
    );
    // The TCP server goes on meanwhile.
    let mut tcp = connect(runtime.address).await;
    tcp.read_holding_registers(1, 1).await.unwrap().unwrap();
    // The attempts of the next second (100, 200 and 400 ms apart) fail the same way, and are
    // not said again.
    tokio::time::sleep(Duration::from_secs(1)).await;
    let failures = runtime
        .messages()
        .iter()
        .filter(|line| line.contains("cannot open"))
        .count();
    assert_eq!(failures, 1, "{:#?}", runtime.messages());

    let mut cable = SocatPair::start(&cable_dir);
    runtime.wait_for_message("Modbus RTU slave 7 on");
    let read_counter = ["-a", "7", "-t", "4", "-r", "2", "-c", "1"];
    mbpoll(&cable.master, &read_counter, &[]).await.unwrap();

    cable.kill();
    runtime.wait_for_message("closed (the device went away)");
    cable.restart();
    let deadline = Instant::now() + PATIENCE;
    while mbpoll(&cable.master, &read_counter, &[]).await.is_err() {
        assert!(
            Instant::now() < deadline,
            "the slave never served the cable again"
        );
    }
    runtime.terminate();
}

#[test]
fn a_bad_line_format_or_unit_is_refused_by_the_argument_parser_saying_why() {
    let dir = tempfile::tempdir().unwrap();
    let refusal = |arguments: &[&str]| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rivet-runtime"))
            .args(["--listen", "127.0.0.1:0", "--modbus-rtu", "/dev/ttyUSB0"])
            .args(arguments)
            .arg("--data-dir")
            .arg(dir.path())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        // A runtime that took the arguments would run for ever: it is killed instead.
        let deadline = Instant::now() + PATIENCE;
        while child.try_wait().unwrap().is_none() {
            if Instant::now() > deadline {
                let _ = child.kill();
                let _ = child.wait();
                panic!("{arguments:?} was accepted: the runtime ran");
            }
            std::thread::sleep(Duration::from_millis(10));
        }
        let output = child.wait_with_output().unwrap();
        assert!(!output.status.success(), "{arguments:?} was accepted");
        String::from_utf8_lossy(&output.stderr).into_owned()
    };
    let said = refusal(&["--modbus-rtu-format", "19200-7E1"]);
    assert!(
        said.contains("7 data bits cannot carry Modbus RTU"),
        "{said}"
    );
    let said = refusal(&["--modbus-rtu-format", "19200/8E1"]);
    assert!(said.contains("such as 19200-8E1"), "{said}");
    let said = refusal(&["--modbus-rtu-unit", "0"]);
    assert!(said.contains("--modbus-rtu-unit"), "{said}");
}
