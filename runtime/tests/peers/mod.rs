//! Independent Modbus clients shared by the runtime's integration tests: mbpoll and pymodbus
//! are system packages that `scripts/test.sh` installs, and without them the tests that use them
//! fail and say so. `pymodbus_client.py` beside this file is the script `modbus_server.rs` runs.

use std::process::Command;

/// The path of a program that a test needs, or a failure that says how to get it.
#[track_caller]
pub fn required_program(name: &str) -> String {
    let found = Command::new("sh")
        .args(["-c", &format!("command -v {name}")])
        .output()
        .unwrap();
    assert!(
        found.status.success(),
        "{name} is not installed: run scripts/test.sh, which installs mbpoll and python3-pymodbus"
    );
    String::from_utf8(found.stdout).unwrap().trim().to_owned()
}

/// A Python interpreter that can import pymodbus: `$RIVET_PYTHON`, `python3` on the path, or
/// Debian's `/usr/bin/python3` (which a pyenv on the path may hide).
#[track_caller]
pub fn python_with_pymodbus() -> String {
    let candidates = std::env::var("RIVET_PYTHON")
        .into_iter()
        .chain(["python3".to_owned(), "/usr/bin/python3".to_owned()]);
    for python in candidates {
        let imports = Command::new(&python)
            .args(["-c", "import pymodbus"])
            .output();
        if imports.is_ok_and(|output| output.status.success()) {
            return python;
        }
    }
    panic!(
        "no python3 can import pymodbus: run scripts/test.sh, which installs mbpoll and \
         python3-pymodbus"
    );
}

/// Runs a program to its end off the async workers and returns its standard output.
pub async fn run(program: String, args: Vec<String>) -> String {
    let command_line = format!("{program} {}", args.join(" "));
    let output =
        tokio::task::spawn_blocking(move || Command::new(&program).args(&args).output().unwrap())
            .await
            .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    assert!(
        output.status.success(),
        "{command_line} failed with {}:\n{stdout}\n{}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    stdout
}
