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

/// Writes a project folder: `FB_Counter` with a method `Reset` and a function `Twice` it calls,
/// `Main` calling it on two instances in `MainTask` (every 2 ms) and writing `%QW0`, and
/// `Other` counting its cycles in `OtherTask` (every 1 ms). The tests name places by the lines
/// of these bodies.
fn write_method_project(dir: &std::path::Path) {
    let application = dir.join("application");
    std::fs::create_dir_all(&application).unwrap();
    std::fs::write(
        dir.join("rivet.toml"),
        "format_version = 3\nname = \"Methods\"\n\
         application = [\"Twice.pou.toml\", \"FB_Counter.pou.toml\", \"Main.pou.toml\", \
         \"Other.pou.toml\"]\n\
         controller = { name = \"PLC\", host = \"127.0.0.1\", port = 5020 }\n\n\
         [[task]]\nname = \"MainTask\"\nkind = { type = \"cyclic\", interval_us = 2000 }\n\
         priority = 1\nprograms = [\"Main\"]\n\n\
         [[task]]\nname = \"OtherTask\"\nkind = { type = \"cyclic\", interval_us = 1000 }\n\
         priority = 2\nprograms = [\"Other\"]\n",
    )
    .unwrap();
    let variable = |name: &str, section: &str, ty: &str| {
        format!("\n[[variable]]\nname = \"{name}\"\nsection = \"{section}\"\ntype = \"{ty}\"\n")
    };
    let files = [
        (
            "Twice.pou.toml",
            format!(
                "kind = \"function\"\nreturn_type = \"INT\"\nbody = {{ language = \"st\" }}\n{}",
                variable("x", "VAR_INPUT", "INT")
            ),
        ),
        ("Twice.st", "Twice := x * 2;\n".to_owned()),
        (
            "FB_Counter.pou.toml",
            format!(
                "kind = \"function_block\"\nbody = {{ language = \"st\" }}\n{}{}{}{}\n\
                 [[method]]\nname = \"Reset\"\nreturn_type = \"INT\"\n\
                 body = {{ language = \"st\" }}\n\n\
                 [[method.variable]]\nname = \"keep\"\nsection = \"VAR_INPUT\"\ntype = \"INT\"\n",
                variable("step", "VAR_INPUT", "INT"),
                variable("count", "VAR", "INT"),
                variable("doubled", "VAR", "INT"),
                variable("wraps", "VAR", "INT"),
            ),
        ),
        (
            "FB_Counter.st",
            "count := count + step;\ncount := Reset(keep := count);\ndoubled := Twice(count);\n"
                .to_owned(),
        ),
        (
            "FB_Counter.Reset.st",
            "wraps := wraps + 1;\nReset := keep MOD 1000;\n".to_owned(),
        ),
        (
            "Main.pou.toml",
            format!(
                "kind = \"program\"\nbody = {{ language = \"st\" }}\n{}{}{}{}address = \"%QW0\"\n",
                variable("fbA", "VAR", "FB_Counter"),
                variable("fbB", "VAR", "FB_Counter"),
                variable("n", "VAR", "INT"),
                variable("qOut", "VAR", "INT"),
            ),
        ),
        (
            "Main.st",
            "fbA(step := 1);\nfbB(step := 2);\nn := (n + 1) MOD 10000;\nqOut := n;\n".to_owned(),
        ),
        (
            "Other.pou.toml",
            format!(
                "kind = \"program\"\nbody = {{ language = \"st\" }}\n{}",
                variable("ticks", "VAR", "DINT")
            ),
        ),
        ("Other.st", "ticks := ticks + 1;\n".to_owned()),
    ];
    for (name, text) in files {
        std::fs::write(application.join(name), text).unwrap();
    }
}

/// The integer `rivet read` prints for `path` on `target`.
#[track_caller]
fn read_integer(path: &str, target: &str) -> i64 {
    let read = ok(&["read", path, "--target", target]);
    read.trim()
        .strip_prefix(&format!("{path} = "))
        .and_then(|value| value.parse().ok())
        .unwrap_or_else(|| panic!("no value of {path} in {read}"))
}

#[test]
fn step_into_over_and_out_of_a_method_while_the_other_task_runs_and_outputs_hold() {
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("methods");
    write_method_project(&folder);
    let runtime = start_runtime(&dir.path().join("data"), None);
    let target = runtime.target.as_str();
    let project = folder.to_str().unwrap();
    ok(&["download", project, "--start", "--target", target]);

    let set = debug_ok(
        &[
            "break",
            "FB_Counter.st:2",
            "--instance",
            "Main.fbB",
            "--wait",
            "5",
        ],
        project,
        target,
    );
    assert!(
        set.contains("FB_Counter.st:2 in Main.fbB (FB_Counter): breakpoint 1 (hit 1)"),
        "{set}"
    );

    // While MainTask is halted its output keeps its value and OtherTask goes on counting.
    let output = read_integer("Main.qOut", target);
    let ticks = read_integer("Other.ticks", target);
    std::thread::sleep(std::time::Duration::from_millis(100));
    assert_eq!(read_integer("Main.qOut", target), output);
    assert_eq!(
        read_integer("Main.n", target),
        output,
        "qOut := n has not run"
    );
    let later = read_integer("Other.ticks", target);
    assert!(later > ticks + 10, "OtherTask counted {ticks} then {later}");

    // Into the method: its first statement, on the instance it is called on.
    let into = debug_ok(&["step", "into"], project, target);
    assert!(
        into.contains("FB_Counter.Reset.st:1 in Main.fbB (FB_Counter.Reset): step into ended"),
        "{into}"
    );
    let stack = debug_ok(&["stack", "--values"], project, target);
    let frames: Vec<&str> = stack.lines().filter(|l| l.starts_with('#')).collect();
    assert_eq!(frames.len(), 3, "{stack}");
    assert!(
        frames[0].starts_with("#0 ")
            && frames[0].contains("FB_Counter.Reset.st:1  Main.fbB  (FB_Counter.Reset)"),
        "{stack}"
    );
    assert!(
        frames[1].contains("FB_Counter.st:2  Main.fbB  (FB_Counter)"),
        "{stack}"
    );
    assert!(frames[2].contains("Main.st:2  Main  (Main)"), "{stack}");
    assert!(stack.contains("    keep = "), "{stack}");

    // Over a statement of the method, then out of it to the statement after the call.
    let over = debug_ok(&["step", "over"], project, target);
    assert!(
        over.contains("FB_Counter.Reset.st:2 in Main.fbB (FB_Counter.Reset): step over ended"),
        "{over}"
    );
    let out = debug_ok(&["step", "out"], project, target);
    assert!(
        out.contains("FB_Counter.st:3 in Main.fbB (FB_Counter): step out ended"),
        "{out}"
    );
    let stack = debug_ok(&["stack"], project, target);
    let frames: Vec<&str> = stack.lines().filter(|l| l.starts_with('#')).collect();
    assert_eq!(frames.len(), 2, "{stack}");
    assert!(
        frames[0].contains("FB_Counter.st:3  Main.fbB  (FB_Counter)"),
        "{stack}"
    );
    assert!(frames[1].contains("Main.st:2  Main  (Main)"), "{stack}");

    // The halted task still holds its output; after the session ends it writes it again.
    assert_eq!(read_integer("Main.qOut", target), output);
    let end = debug_ok(&["continue", "--end"], project, target);
    assert!(end.contains("the debug session ended"), "{end}");
    std::thread::sleep(std::time::Duration::from_millis(50));
    assert_ne!(read_integer("Main.qOut", target), output);
}
