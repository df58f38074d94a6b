//! The debugging commands (`docs/debugging.md` §7) against a real `rivet-runtime`: what a
//! command refuses before it changes anything on the target.

use super::{ok, rivet, start_runtime};

/// A function block called on two instances, a function it calls, and a counter; the tests
/// name places by these line numbers.
pub(super) const DEBUG_PROGRAM: &str = "FUNCTION Twice : INT
VAR_INPUT x : INT; END_VAR
Twice := x * 2;
END_FUNCTION

FUNCTION_BLOCK FB_Counter
VAR_INPUT step : INT; END_VAR
VAR count : INT; doubled : INT; END_VAR
count := count + step;
doubled := Twice(count);
count := count MOD 1000;
END_FUNCTION_BLOCK

PROGRAM Main
VAR fbA : FB_Counter; fbB : FB_Counter; n : INT; END_VAR
fbA(step := 1);
fbB(step := 2);
n := (n + 1) MOD 10000;
END_PROGRAM
";

#[test]
fn a_target_running_another_build_is_refused_with_a_hint_to_download() {
    let dir = tempfile::tempdir().unwrap();
    let source = dir.path().join("counter.st");
    std::fs::write(&source, DEBUG_PROGRAM).unwrap();
    let runtime = start_runtime(&dir.path().join("data"), None);
    let target = runtime.target.as_str();
    let project = source.to_str().unwrap();
    ok(&["download", project, "--start", "--target", target]);

    std::fs::write(&source, DEBUG_PROGRAM.replace("MOD 10000", "MOD 20000")).unwrap();
    let refused = rivet(&[
        "break",
        "counter.st:9",
        "--project",
        project,
        "--target",
        target,
    ]);
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(!refused.status.success());
    assert!(
        said.contains("another build") && said.contains("rivet download"),
        "{said}"
    );

    // A place the program does not have is refused before anything is sent.
    std::fs::write(&source, DEBUG_PROGRAM).unwrap();
    let refused = rivet(&[
        "break",
        "counter.st:40",
        "--project",
        project,
        "--target",
        target,
    ]);
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(
        said.contains("counter.st:40: no statement starts"),
        "{said}"
    );
    let refused = rivet(&[
        "break",
        "counter.st:9",
        "--if",
        "count",
        "--project",
        project,
        "--target",
        target,
    ]);
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(said.contains("not BOOL"), "{said}");
}
