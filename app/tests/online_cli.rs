//! The online commands against a real `rivet-runtime` on loopback: download, start, read,
//! write, force, unforce, trace, stop, faults, and the password; the debugging commands in
//! `debugging`; the runtime's Modbus master against independent slaves in `modbus`.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::io::{BufRead as _, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};

#[path = "online_cli/debugging.rs"]
mod debugging;
#[path = "online_cli/modbus.rs"]
mod modbus;

/// The workspace tests' independent Modbus peers (pymodbus, socat), shared as the runtime's
/// tests share them; each test uses a part of them.
#[allow(dead_code)]
#[path = "../../tests/src/peers.rs"]
mod peers;

/// The workspace tests' fault proxy, between the master and its slave.
#[allow(dead_code)]
#[path = "../../tests/src/fault_proxy.rs"]
mod fault_proxy;

/// The runtime binary, built beside `rivet` by `cargo test --workspace`.
fn runtime_binary() -> PathBuf {
    let rivet = Path::new(env!("CARGO_BIN_EXE_rivet"));
    let path = rivet.with_file_name(format!("rivet-runtime{}", std::env::consts::EXE_SUFFIX));
    assert!(
        path.exists(),
        "{} is missing: build it with `cargo build -p runtime` (scripts/test.sh does)",
        path.display()
    );
    path
}

/// A runtime process, killed when the test ends.
struct Runtime {
    child: Child,
    target: String,
}

impl Drop for Runtime {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn start_runtime(data: &Path, password: Option<&str>) -> Runtime {
    start_runtime_with(data, password, &[])
}

/// A runtime on 127.0.0.1, port 0, with `arguments` after the usual ones
/// (`--serial-port RS485=PATH`).
fn start_runtime_with(data: &Path, password: Option<&str>, arguments: &[&str]) -> Runtime {
    let mut command = Command::new(runtime_binary());
    command
        .args(["--listen", "127.0.0.1:0", "--data-dir"])
        .arg(data)
        .args(arguments);
    command.env_remove("RIVET_PASSWORD");
    if let Some(password) = password {
        command.env("RIVET_PASSWORD", password);
    }
    let child = command
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Owned by its guard before anything can panic, so a runtime that says something else
    // first is killed with the test rather than left running.
    let mut runtime = Runtime {
        child,
        target: String::new(),
    };
    let mut first = String::new();
    BufReader::new(runtime.child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    runtime.target = first
        .trim()
        .strip_prefix("listening on ")
        .unwrap_or_else(|| panic!("unexpected first line {first:?}"))
        .to_owned();
    runtime
}

fn rivet(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rivet"))
        .args(args)
        .env_remove("RIVET_PASSWORD")
        .output()
        .unwrap()
}

/// `rivet` with `password` in the environment, as an operator keeps it out of the process list.
fn rivet_with_password(args: &[&str], password: &str) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rivet"))
        .args(args)
        .env("RIVET_PASSWORD", password)
        .output()
        .unwrap()
}

#[track_caller]
fn ok(args: &[&str]) -> String {
    let output = rivet(args);
    assert!(
        output.status.success(),
        "rivet {args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8_lossy(&output.stdout).into_owned()
}

const PROGRAM: &str = "PROGRAM main VAR n : DINT; k : INT; level : DINT; tick : BOOL; END_VAR
n := n + 1 + k - k; level := n * 2; tick := n MOD 4 = 0;
END_PROGRAM
";

#[test]
fn download_run_read_write_force_trace_and_stop_over_the_cli() {
    let dir = tempfile::tempdir().unwrap();
    let source = dir.path().join("counter.st");
    std::fs::write(&source, PROGRAM).unwrap();
    let runtime = start_runtime(&dir.path().join("data"), Some("secret"));
    let target = runtime.target.as_str();
    let password_file = dir.path().join("password");
    std::fs::write(&password_file, "secret\n").unwrap();
    let auth = [
        "--target",
        target,
        "--password-file",
        password_file.to_str().unwrap(),
    ];

    assert!(ok(&["status", "--target", target]).contains("program: none"));
    // Changing the target without the password is refused and changes nothing.
    let refused = rivet(&["download", source.to_str().unwrap(), "--target", target]);
    assert!(!refused.status.success());
    assert!(
        String::from_utf8_lossy(&refused.stderr).contains("password"),
        "{}",
        String::from_utf8_lossy(&refused.stderr)
    );
    let wrong = rivet_with_password(&["stop", "--target", target], "nope");
    assert!(String::from_utf8_lossy(&wrong.stderr).contains("refused the password"));
    // The password on the command line is refused before anything is sent.
    let visible = rivet(&["stop", "--target", target, "--password", "secret"]);
    assert!(!visible.status.success());
    let said = String::from_utf8_lossy(&visible.stderr);
    assert!(
        said.contains("--password-file") && said.contains("RIVET_PASSWORD"),
        "{said}"
    );
    // A wrong password locks nobody out: the right one works at once.

    let downloaded = ok(&[
        &["download", source.to_str().unwrap(), "--start"][..],
        &auth,
    ]
    .concat());
    assert!(downloaded.contains("downloaded"), "{downloaded}");
    std::thread::sleep(std::time::Duration::from_millis(100));
    let status = ok(&["status", "--target", target]);
    assert!(
        status.contains("running") && status.contains("task MainTask"),
        "{status}"
    );
    // Reading needs no password.
    let read = ok(&["read", "main.n", "main.level", "--target", target]);
    assert!(
        read.starts_with("main.n = ") && read.contains("main.level = "),
        "{read}"
    );

    let unknown = rivet(&["read", "main.nope", "--target", target]);
    assert!(
        String::from_utf8_lossy(&unknown.stderr).contains("unknown variable"),
        "{}",
        String::from_utf8_lossy(&unknown.stderr)
    );
    ok(&[&["write", "main.k=42"][..], &auth].concat());
    assert_eq!(ok(&["read", "main.k", "--target", target]), "main.k = 42\n");
    let bad = rivet(&[&["write", "main.k=hello"][..], &auth].concat());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("'hello' is not a value of INT"));

    // A force survives the program's own assignment, cycle after cycle.
    ok(&[&["force", "main.level=-7"][..], &auth].concat());
    for _ in 0..3 {
        assert_eq!(
            ok(&["read", "main.level", "--target", target]),
            "main.level = -7 (forced)\n"
        );
        std::thread::sleep(std::time::Duration::from_millis(15));
    }
    assert!(ok(&["forces", "--target", target]).contains("16#f9ffffff"));
    ok(&[&["unforce", "--all"][..], &auth].concat());
    assert!(!ok(&["read", "main.level", "--target", target]).contains("forced"));

    // A trace on a rising edge gives exactly the samples asked for, one per cycle.
    let csv = dir.path().join("trace.csv");
    let traced = ok(&[
        &[
            "trace",
            "--vars",
            "main.n,main.tick",
            "--task",
            "MainTask",
            "--samples",
            "10",
            "--trigger",
            "main.tick",
            "--rising",
            "--csv",
            csv.to_str().unwrap(),
        ][..],
        &auth,
    ]
    .concat());
    assert!(traced.contains("10 samples"), "{traced}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<&str> = text.lines().skip(1).collect();
    assert_eq!(rows.len(), 10, "{text}");
    let cycles: Vec<u64> = rows
        .iter()
        .map(|r| r.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert!(cycles.windows(2).all(|w| w[1] == w[0] + 1), "{cycles:?}");
    assert!(
        rows[0].ends_with(",TRUE"),
        "the first sample is the trigger's: {text}"
    );

    assert!(ok(&[&["stop"][..], &auth].concat()).contains("stopped"));
    assert!(ok(&["faults", "--target", target]).contains("no faults"));
}

/// A program with an enumeration of many long names, so that its values take several
/// `ENUMERATION` answers, one with explicit values, and variables of both.
const ENUM_PROGRAM: &str = "TYPE
    Station : (
        STATION_00_WAITING_FOR_PARTS,
        STATION_01_WAITING_FOR_PARTS,
        STATION_02_WAITING_FOR_PARTS,
        STATION_03_WAITING_FOR_PARTS,
        STATION_04_WAITING_FOR_PARTS,
        STATION_05_WAITING_FOR_PARTS,
        STATION_06_WAITING_FOR_PARTS,
        STATION_07_WAITING_FOR_PARTS,
        STATION_08_WAITING_FOR_PARTS,
        STATION_09_WAITING_FOR_PARTS,
        STATION_10_WAITING_FOR_PARTS,
        STATION_11_WAITING_FOR_PARTS,
        STATION_12_WAITING_FOR_PARTS,
        STATION_13_WAITING_FOR_PARTS,
        STATION_14_WAITING_FOR_PARTS,
        STATION_15_WAITING_FOR_PARTS,
        STATION_16_WAITING_FOR_PARTS,
        STATION_17_WAITING_FOR_PARTS,
        STATION_18_WAITING_FOR_PARTS,
        STATION_19_WAITING_FOR_PARTS
    );
    Light : (RED := -1, AMBER := 5, GREEN := 300);
END_TYPE
PROGRAM main
VAR
    n : DINT;
    light : Light := Light#AMBER;
    station : Station := Station#STATION_18_WAITING_FOR_PARTS;
END_VAR
n := n + 1;
IF n MOD 2 = 0 THEN light := Light#GREEN; ELSE light := Light#RED; END_IF
END_PROGRAM
";

#[test]
fn read_trace_and_write_enumerations_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let source = dir.path().join("stations.st");
    std::fs::write(&source, ENUM_PROGRAM).unwrap();
    let runtime = start_runtime(&dir.path().join("data"), None);
    let target = runtime.target.as_str();
    ok(&[
        "download",
        source.to_str().unwrap(),
        "--start",
        "--target",
        target,
    ]);
    std::thread::sleep(std::time::Duration::from_millis(100));

    // The 19th value is past the first answer's values: it shows that the pages are joined.
    assert_eq!(
        ok(&["read", "main.station", "--target", target]),
        "main.station = STATION_18_WAITING_FOR_PARTS\n"
    );
    let light = ok(&["read", "main.light", "--target", target]);
    assert!(
        light == "main.light = GREEN\n" || light == "main.light = RED\n",
        "{light}"
    );

    // A value is written by its name; a name the type does not have is refused with its names.
    ok(&[
        "write",
        "main.station=Station#STATION_03_WAITING_FOR_PARTS",
        "--target",
        target,
    ]);
    assert_eq!(
        ok(&["read", "main.station", "--target", target]),
        "main.station = STATION_03_WAITING_FOR_PARTS\n"
    );
    let refused = rivet(&["write", "main.station=PURPLE", "--target", target]);
    let message = String::from_utf8_lossy(&refused.stderr);
    assert!(
        !refused.status.success() && message.contains("'PURPLE' is not a value of the enumeration; its values are STATION_00_WAITING_FOR_PARTS,"),
        "{message}"
    );

    let csv = dir.path().join("lights.csv");
    let traced = ok(&[
        "trace",
        "--vars",
        "main.n,main.light,main.station",
        "--task",
        "MainTask",
        "--samples",
        "6",
        "--csv",
        csv.to_str().unwrap(),
        "--target",
        target,
    ]);
    assert!(traced.contains("6 samples"), "{traced}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|row| row.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 6, "{text}");
    for row in &rows {
        let n: i64 = row[2].parse().unwrap();
        let light = if n % 2 == 0 { "GREEN" } else { "RED" };
        assert_eq!(row[3..], [light, "STATION_03_WAITING_FOR_PARTS"], "{text}");
    }
}

#[test]
fn a_missing_runtime_says_what_to_check() {
    let refused = rivet(&["status", "--target", "127.0.0.1:1"]);
    assert!(String::from_utf8_lossy(&refused.stderr).contains("connection refused"));
}

/// A project folder of one program `Counter`, declaring `variables` (`name: TYPE`), running
/// `body` every `interval_us` in task MainTask.
fn write_counter_project(dir: &Path, interval_us: u32, variables: &[(&str, &str)], body: &str) {
    std::fs::create_dir_all(dir.join("application")).unwrap();
    std::fs::write(
        dir.join("rivet.toml"),
        format!(
            "format_version = 3\nname = \"Counter\"\napplication = [\"Counter.pou.toml\"]\n\
             controller = {{ name = \"PLC\", host = \"127.0.0.1\", port = 5020 }}\n\n\
             [[task]]\nname = \"MainTask\"\n\
             kind = {{ type = \"cyclic\", interval_us = {interval_us} }}\n\
             priority = 1\nprograms = [\"Counter\"]\n"
        ),
    )
    .unwrap();
    let mut pou = "kind = \"program\"\nbody = { language = \"st\" }\n".to_owned();
    for (name, ty) in variables {
        pou.push_str(&format!(
            "\n[[variable]]\nname = \"{name}\"\nsection = \"VAR\"\ntype = \"{ty}\"\n"
        ));
    }
    std::fs::write(dir.join("application/Counter.pou.toml"), pou).unwrap();
    std::fs::write(dir.join("application/Counter.st"), body).unwrap();
}

/// The integer after `name = ` in `rivet read`'s output.
fn value_of(output: &str, name: &str) -> i64 {
    output
        .lines()
        .find_map(|line| line.strip_prefix(&format!("{name} = ")))
        .unwrap_or_else(|| panic!("no {name} in {output}"))
        .trim()
        .parse()
        .unwrap()
}

#[test]
fn an_online_change_carries_the_counter_misses_no_cycle_and_a_task_change_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let project = dir.path().join("counter");
    let project_arg = project.to_str().unwrap();
    write_counter_project(
        &project,
        2000,
        &[("count", "DINT")],
        "count := count + 1;\n",
    );
    let runtime = start_runtime(&dir.path().join("data"), None);
    let target = runtime.target.as_str();
    ok(&["download", project_arg, "--start", "--target", target]);
    std::thread::sleep(std::time::Duration::from_millis(100));

    // A variable added and an expression changed: the new code counts by ten, and counts its
    // own cycles in the new variable.
    write_counter_project(
        &project,
        2000,
        &[("count", "DINT"), ("cycles", "DINT")],
        "count := count + 10;\ncycles := cycles + 1;\n",
    );
    let dry = ok(&[
        "download",
        project_arg,
        "--online-change",
        "--dry-run",
        "--target",
        target,
    ]);
    assert!(
        dry.contains("online change possible: 1 POU(s) changed, 1 variable(s) added"),
        "{dry}"
    );
    assert!(
        dry.contains("variable added (starts from its initial value): Counter.cycles"),
        "{dry}"
    );
    assert!(dry.contains("nothing changed"), "{dry}");
    let changed = ok(&[
        "download",
        project_arg,
        "--online-change",
        "--target",
        target,
    ]);
    let switched_after: i64 = changed
        .split("after cycle ")
        .nth(1)
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|cycles| cycles.parse().ok())
        .unwrap_or_else(|| panic!("no cycle in {changed}"));
    assert!(switched_after > 0, "{changed}");
    std::thread::sleep(std::time::Duration::from_millis(100));
    // One snapshot of both: the old code counted every cycle before the switch by one (the
    // value carried over), the new code every cycle since by ten; no cycle was missed.
    let read = ok(&[
        "read",
        "Counter.count",
        "Counter.cycles",
        "--target",
        target,
    ]);
    let (count, cycles) = (
        value_of(&read, "Counter.count"),
        value_of(&read, "Counter.cycles"),
    );
    assert!(cycles > 0, "{read}");
    assert_eq!(count, switched_after + 10 * cycles, "{changed}\n{read}");

    // A task configuration change is refused with its reason, and nothing changes.
    write_counter_project(
        &project,
        1000,
        &[("count", "DINT"), ("cycles", "DINT")],
        "count := count + 10;\ncycles := cycles + 1;\n",
    );
    let refused = rivet(&[
        "download",
        project_arg,
        "--online-change",
        "--target",
        target,
    ]);
    assert!(!refused.status.success());
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(
        said.contains(
            "an online change is impossible: task 'MainTask': interval changed from 2 ms to 1 ms"
        ) && said.contains("download without --online-change"),
        "{said}"
    );
    let read = ok(&[
        "read",
        "Counter.count",
        "Counter.cycles",
        "--target",
        target,
    ]);
    let (count, cycles) = (
        value_of(&read, "Counter.count"),
        value_of(&read, "Counter.cycles"),
    );
    assert_eq!(
        count,
        switched_after + 10 * cycles,
        "the changed program still runs: {read}"
    );
}
