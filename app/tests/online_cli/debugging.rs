//! The debugging commands (`docs/debugging.md` §7) against a real `rivet-runtime`: what a
//! command refuses before it changes anything on the target, and breakpoints, steps, the call
//! stack, continue, halt and flow control (these need the runtime side of protocol §6).

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

/// `rivet` with `args` and the project and target options after them.
#[track_caller]
fn debug_ok(args: &[&str], project: &str, target: &str) -> String {
    ok(&[args, &["--project", project, "--target", target][..]].concat())
}

#[test]
fn break_on_one_instance_step_through_a_function_read_the_stack_and_continue() {
    let dir = tempfile::tempdir().unwrap();
    let source = dir.path().join("counter.st");
    std::fs::write(&source, DEBUG_PROGRAM).unwrap();
    let runtime = start_runtime(&dir.path().join("data"), None);
    let target = runtime.target.as_str();
    let project = source.to_str().unwrap();
    ok(&["download", project, "--start", "--target", target]);
    let line = |n: u32| format!("{project}:{n}");

    // A breakpoint in the function block halts on the instance it names only.
    let set = debug_ok(
        &[
            "break",
            "counter.st:9",
            "--instance",
            "Main.fbB",
            "--wait",
            "5",
        ],
        project,
        target,
    );
    assert!(
        set.contains(&format!(
            "breakpoint 1 at {} (FB_Counter), instance Main.fbB, any task",
            line(9)
        )),
        "{set}"
    );
    assert!(
        set.contains(&format!(
            "task 'MainTask' halted at {} in Main.fbB (FB_Counter): breakpoint 1 (hit 1)",
            line(9)
        )),
        "{set}"
    );
    let stack = debug_ok(&["stack", "--values"], project, target);
    assert!(
        stack.starts_with("task 'MainTask' halted at breakpoint 1 (hit 1) in cycle "),
        "{stack}"
    );
    assert!(
        stack.contains(&format!("#0 {}  Main.fbB  (FB_Counter)", line(9))),
        "{stack}"
    );
    assert!(
        stack.contains(&format!("#1 {}  Main  (Main)", line(17))),
        "{stack}"
    );
    assert!(stack.contains("    step = 2"), "{stack}");

    // Over, into the function, and out of it again.
    let over = debug_ok(&["step", "over"], project, target);
    assert!(
        over.contains(&format!(
            "at {} in Main.fbB (FB_Counter): step over ended",
            line(10)
        )),
        "{over}"
    );
    let into = debug_ok(&["step", "into"], project, target);
    assert!(
        into.contains(&format!("at {} (Twice): step into ended", line(3))),
        "{into}"
    );
    let stack = debug_ok(&["stack", "--values"], project, target);
    assert!(
        stack.contains(&format!("#0 {}  -  (Twice)", line(3))),
        "{stack}"
    );
    assert!(
        stack.contains(&format!("#1 {}  Main.fbB  (FB_Counter)", line(10))),
        "{stack}"
    );
    assert!(
        stack.contains(&format!("#2 {}  Main  (Main)", line(17))),
        "{stack}"
    );
    assert!(stack.contains("    x = "), "{stack}");
    let out = debug_ok(&["step", "out"], project, target);
    assert!(
        out.contains(&format!(
            "at {} in Main.fbB (FB_Counter): step out ended",
            line(11)
        )),
        "{out}"
    );

    // Continue runs to the same breakpoint in the next cycle, which counts its hits.
    let next = debug_ok(&["continue", "--wait", "5"], project, target);
    assert!(next.contains("task 'MainTask' runs on"), "{next}");
    assert!(next.contains("breakpoint 1 (hit 2)"), "{next}");
    let list = debug_ok(&["break", "--list"], project, target);
    assert!(
        list.contains("instance Main.fbB  any task  no condition  always  hits 2"),
        "{list}"
    );
    assert!(
        debug_ok(&["break", "--clear", "1"], project, target).contains("cleared 1 breakpoint(s)")
    );
    assert!(debug_ok(&["continue"], project, target).contains("runs on"));

    // A condition and a hit count: the third hit with an even counter halts.
    let conditional = debug_ok(
        &[
            "break",
            "counter.st:18",
            "--if",
            "n MOD 2 = 0",
            "--hits",
            "3",
            "--wait",
            "5",
        ],
        project,
        target,
    );
    assert!(
        conditional.contains(&format!(
            "at {} in Main (Main): breakpoint 2 (hit 3)",
            line(18)
        )),
        "{conditional}"
    );
    let read = ok(&["read", "Main.n", "--target", target]);
    let n: i64 = read.trim().trim_start_matches("Main.n = ").parse().unwrap();
    assert_eq!(n % 2, 0, "{read}");

    // Ending the session clears every breakpoint and lets the task run on.
    let end = debug_ok(&["continue", "--end"], project, target);
    assert!(end.contains("the debug session ended"), "{end}");
    assert!(debug_ok(&["break", "--list"], project, target).contains("no breakpoints"));
    let later = ok(&["read", "Main.n", "--target", target]);
    std::thread::sleep(std::time::Duration::from_millis(50));
    assert_ne!(ok(&["read", "Main.n", "--target", target]), later);

    // Halting on request, and flow control over one cycle.
    let halted = debug_ok(&["halt"], project, target);
    assert!(
        halted.contains("task 'MainTask' halted at") && halted.contains("halted on request"),
        "{halted}"
    );
    debug_ok(&["continue"], project, target);
    let flow = debug_ok(
        &["flow", "FB_Counter", "--instance", "Main.fbA"],
        project,
        target,
    );
    for n in [9, 10, 11] {
        assert!(flow.contains(&line(n)), "{flow}");
    }
    debug_ok(&["continue", "--end"], project, target);
}
