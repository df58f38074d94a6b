//! Independent Modbus clients for the end-to-end tests: mbpoll and pymodbus, system packages
//! that `scripts/test.sh` installs. Without them the tests that use them fail and say so.

use std::process::Command;

/// The path of a program that a test needs, or a panic that says how to get it.
#[track_caller]
pub fn required_program(name: &str) -> String {
    let found = Command::new("sh")
        .args(["-c", &format!("command -v {name}")])
        .output()
        .unwrap_or_else(|error| panic!("cannot run sh to look for {name}: {error}"));
    assert!(
        found.status.success(),
        "{name} is not installed: run scripts/test.sh, which installs mbpoll and python3-pymodbus"
    );
    String::from_utf8_lossy(&found.stdout).trim().to_owned()
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

/// Runs `program` with `args` to its end and returns its standard output, or panics with
/// everything it said when it fails.
#[track_caller]
pub fn run(program: &str, args: &[String]) -> String {
    let output = Command::new(program)
        .args(args)
        .output()
        .unwrap_or_else(|error| panic!("cannot run {program}: {error}"));
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    assert!(
        output.status.success(),
        "{program} {} failed with {}:\n{stdout}\n{}",
        args.join(" "),
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
    stdout
}
