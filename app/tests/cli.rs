//! The headless command line: `rivet check` and `rivet fmt` on the example and broken copies.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::fs;
use std::path::Path;
use std::process::{Command, Output};

#[path = "cli/import.rs"]
mod import;
#[path = "cli/simulate_import.rs"]
mod simulate_import;

fn rivet(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rivet"))
        .args(args)
        .output()
        .expect("rivet runs")
}

fn text_of(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn example_copy() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    dir
}

fn path_str(path: &Path) -> &str {
    path.to_str().unwrap()
}

#[test]
fn check_accepts_the_example() {
    let output = rivet(&["check", path_str(&assets::example_project_dir())]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert!(text_of(&output.stdout).contains("project 'Packaging machine' is fine"));
}

#[test]
fn check_fails_on_a_broken_copy_with_file_and_line() {
    let dir = example_copy();
    let pou = dir.path().join("application/Main.pou.toml");
    let broken = fs::read_to_string(&pou)
        .unwrap()
        .replace("kind = \"program\"", "kind = \"prgram\"");
    fs::write(&pou, broken).unwrap();
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    let location = format!("{}:1: error:", pou.display());
    assert!(stderr.contains(&location), "{stderr}");
    assert!(stderr.contains("unknown variant `prgram`"), "{stderr}");
    assert!(stderr.contains("nothing was changed"), "{stderr}");
}

#[test]
fn check_points_a_modbus_channel_finding_at_the_channel_s_variable_line() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    // A runtime device on the loopback address, whose second channel reads a BOOL into a REAL.
    let broken = fs::read_to_string(&manifest)
        .unwrap()
        .replace(
            "host = \"192.168.1.50\"",
            "host = \"127.0.0.1\"\ntask = \"MainTask\"",
        )
        .replace(
            "variable = \"GVL_Machine.xDriveReady\"",
            "variable = \"GVL_Machine.rBeltSpeedActual\"",
        );
    fs::write(&manifest, &broken).unwrap();
    // The second of the two channels now bound to the speed.
    let second = broken
        .lines()
        .enumerate()
        .filter(|(_, text)| *text == "variable = \"GVL_Machine.rBeltSpeedActual\"")
        .map(|(index, _)| index + 1)
        .nth(1)
        .unwrap();
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    let expected = format!(
        "{}:{second}: error[E0141]: Modbus device 'BeltDrive', channel 2 (GVL_Machine.rBeltSpeedActual): the channel reads one bool value, but the variable is declared as REAL: declare it as BOOL",
        manifest.display()
    );
    assert!(stderr.contains(&expected), "{stderr}");
}

#[test]
fn fmt_leaves_a_canonical_project_untouched() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    let modified = fs::metadata(&manifest).unwrap().modified().unwrap();
    let output = rivet(&["fmt", path_str(dir.path())]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert!(text_of(&output.stdout).contains("already canonical"));
    assert_eq!(
        fs::metadata(&manifest).unwrap().modified().unwrap(),
        modified
    );
}

#[test]
fn fmt_rewrites_a_hand_edited_file_into_canonical_form() {
    let dir = example_copy();
    let task_file = dir.path().join("rivet.toml");
    let original = fs::read_to_string(&task_file).unwrap();
    // Same content, written the long way.
    let long_form = original.replacen(
        "controller = { name = \"PLC\", host = \"127.0.0.1\", port = 5020 }\n",
        "\n[controller]\nport = 5020\nname = \"PLC\"\nhost = \"127.0.0.1\"\n",
        1,
    );
    assert_ne!(long_form, original);
    // Tables must follow the plain keys in TOML, so move the controller table to the end.
    let (head, tail) = long_form.split_once("\n[controller]").unwrap();
    let (controller, rest) = tail.split_once("\n\n").unwrap();
    fs::write(
        &task_file,
        format!("{head}\n{rest}\n[controller]{controller}\n"),
    )
    .unwrap();

    let output = rivet(&["fmt", path_str(dir.path())]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert!(text_of(&output.stdout).contains("formatted"));
    assert_eq!(fs::read_to_string(&task_file).unwrap(), original);
}

#[test]
fn fmt_refuses_a_broken_project_and_writes_nothing() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    fs::write(&manifest, "format_version = 99\n").unwrap();
    let output = rivet(&["fmt", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text_of(&output.stderr).contains("newer Rivet"));
    assert_eq!(
        fs::read_to_string(&manifest).unwrap(),
        "format_version = 99\n"
    );
}

#[test]
fn check_of_a_missing_folder_says_what_is_missing() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nope");
    let output = rivet(&["check", path_str(&missing)]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    assert!(
        stderr.contains("rivet.toml: error: file not found"),
        "{stderr}"
    );
}

#[test]
fn check_reports_syntax_errors_in_st_bodies_with_line_column_and_code() {
    let dir = example_copy();
    let body = dir.path().join("application/Sequence.st");
    let text = fs::read_to_string(&body).unwrap().replacen(
        "eState := E_MachineState.Starting;",
        "eState := E_MachineState.Starting",
        1,
    );
    fs::write(&body, text).unwrap();
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    let location = format!(
        "{}:4:46: error[E0001]: expected ';' after the statement, found END_IF",
        body.display()
    );
    assert!(stderr.contains(&location), "{stderr}");
    assert!(
        stderr.contains("4 |             eState := E_MachineState.Starting\n"),
        "{stderr}"
    );
}

#[test]
fn check_of_a_single_st_file_parses_whole_pous() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.st");
    fs::write(
        &good,
        "FUNCTION F : INT VAR_INPUT a : INT; END_VAR F := a * 2; END_FUNCTION\n",
    )
    .unwrap();
    let output = rivet(&["check", path_str(&good)]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));

    let bad = dir.path().join("bad.st");
    fs::write(&bad, "PROGRAM P\nx := (1 + ;\nEND_PROGRAM\n").unwrap();
    let output = rivet(&["check", path_str(&bad)]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    assert!(
        stderr.contains(&format!(
            "{}:2:11: error[E0001]: expected an expression, found ';'",
            bad.display()
        )),
        "{stderr}"
    );
}

#[test]
fn check_reports_unknown_names_and_types() {
    let dir = example_copy();
    let body = dir.path().join("application/Main.st");
    let text =
        fs::read_to_string(&body)
            .unwrap()
            .replacen("GVL_IO.xStopButton", "GVL_IO.xStopButon", 1);
    fs::write(&body, text).unwrap();
    let pou = dir.path().join("application/FB_Conveyor.pou.toml");
    let text = fs::read_to_string(&pou)
        .unwrap()
        .replacen("type = \"TON\"", "type = \"TONN\"", 1);
    fs::write(&pou, text).unwrap();
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    assert!(
        stderr.contains(&format!("{}:4:21: error[E0101]: 'GVL_IO' has no member 'xStopButon'; did you mean 'xStopButton'?", body.display())),
        "{stderr}"
    );
    assert!(
        stderr.contains(&format!(
            "{}:41: error[E0102]: tonStart: unknown type 'TONN'; did you mean 'TON'?",
            pou.display()
        )),
        "{stderr}"
    );
}

#[test]
fn check_type_checks_a_single_st_file_and_reports_warnings() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("types.st");
    fs::write(
        &file,
        "PROGRAM P\nVAR\n    iCount : INT;\n    tTotal : TIME := T#5S;\n    iSpare : INT;\nEND_VAR\niCount := tTotal;\nEND_PROGRAM\n",
    )
    .unwrap();
    let output = rivet(&["check", path_str(&file)]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    assert!(
        stderr.contains(&format!(
            "{}:7:11: error[E0104]: the assignment expects INT, found TIME; IEC converts only to wider types, so write TIME_TO_INT(…)",
            file.display()
        )),
        "{stderr}"
    );
    assert!(stderr.contains("7 | iCount := tTotal;\n"), "{stderr}");
    assert!(
        stderr.contains(&format!(
            "{}:5:5: warning[W0001]: 'iSpare' is declared but never used",
            file.display()
        )),
        "{stderr}"
    );
    assert!(stderr.contains("1 error(s), 1 warning(s)"), "{stderr}");
}

#[test]
fn build_writes_an_image_the_runtime_format_reads() {
    let dir = tempfile::tempdir().unwrap();
    let image = dir.path().join("app.img");
    let output = rivet(&[
        "build",
        path_str(&assets::example_project_dir()),
        "-o",
        path_str(&image),
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert!(
        text_of(&output.stdout).contains("2 tasks"),
        "{}",
        text_of(&output.stdout)
    );
    let bytes = fs::read(&image).unwrap();
    let decoded = program_image::ProgramImage::decode(&bytes).unwrap();
    assert!(
        decoded
            .symbols
            .iter()
            .any(|s| s.path == "GVL_IO.xConveyorMotor")
    );
}

#[test]
fn simulate_prints_watched_values_as_text_and_json() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("count.st");
    fs::write(&file, "PROGRAM main VAR n : INT; t : TIME; big : BOOL; END_VAR n := n + 1; t := t + T#10ms; big := n > 2; END_PROGRAM").unwrap();
    let output = rivet(&[
        "simulate",
        path_str(&file),
        "--cycles",
        "3",
        "--watch",
        "main.n,main.t,main.big",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "main.n = 3\nmain.t = T#30ms\nmain.big = TRUE\n"
    );
    let output = rivet(&[
        "simulate",
        path_str(&file),
        "--cycles",
        "3",
        "--watch",
        "main.n,main.t",
        "--json",
    ]);
    assert_eq!(
        text_of(&output.stdout).trim(),
        r#"{"main.n": 3, "main.t": "T#30ms"}"#
    );
}

#[test]
fn simulate_runs_under_either_engine_once_and_refuses_an_unknown_one() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("count.st");
    fs::write(
        &file,
        "PROGRAM main VAR n : DINT; r : REAL; END_VAR n := n + 1; r := r + 0.5; END_PROGRAM",
    )
    .unwrap();
    for engine in ["native", "interpreter"] {
        let output = rivet(&[
            "simulate",
            path_str(&file),
            "--cycles",
            "4",
            "--watch",
            "main.n,main.r",
            "--engine",
            engine,
        ]);
        assert!(output.status.success(), "{}", text_of(&output.stderr));
        assert_eq!(
            text_of(&output.stdout),
            "main.n = 4\nmain.r = 2\n",
            "{engine}"
        );
        // Every POU runs as chosen: nothing to note.
        assert_eq!(text_of(&output.stderr), "", "{engine}");
    }
    let output = rivet(&["simulate", path_str(&file), "--engine", "fast"]);
    assert!(!output.status.success());
    assert!(
        text_of(&output.stderr).contains("invalid value 'fast' for '--engine"),
        "{}",
        text_of(&output.stderr)
    );
    let output = rivet(&[
        "simulate",
        path_str(&file),
        "--engine",
        "native",
        "--engine",
        "interpreter",
    ]);
    assert!(!output.status.success());
    assert!(
        text_of(&output.stderr).contains("cannot be used multiple times"),
        "{}",
        text_of(&output.stderr)
    );
}

/// A project whose program `Counter` is a CFC chart: an ADD whose output feeds its own input
/// (run second) and a MOVE reading that output first, so it sees the previous cycle's count.
const CFC_COUNTER: &str = r#"kind = "program"

[[variable]]
name = "count"
section = "VAR"
type = "INT"

[[variable]]
name = "previous"
section = "VAR"
type = "INT"

[body]
language = "cfc"

[body.chart]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "input", expression = "1" } },
    { id = 2, x = 8, y = 0, order = 1, kind = { type = "box", type_name = "ADD", input = [{ name = "IN1" }, { name = "IN2" }], output = [{ name = "OUT" }] } },
    { id = 3, x = 16, y = 0, order = 2, kind = { type = "output", expression = "count" } },
    { id = 4, x = 8, y = 6, order = 0, kind = { type = "box", type_name = "MOVE", input = [{ name = "IN" }], output = [{ name = "OUT" }] } },
    { id = 5, x = 16, y = 6, order = 3, kind = { type = "output", expression = "previous" } },
]
wire = [
    { from = { element = 2, pin = "OUT" }, to = { element = 2, pin = "IN1" } },
    { from = { element = 1 }, to = { element = 2, pin = "IN2" } },
    { from = { element = 2, pin = "OUT" }, to = { element = 3 } },
    { from = { element = 2, pin = "OUT" }, to = { element = 4, pin = "IN" } },
    { from = { element = 4, pin = "OUT" }, to = { element = 5 } },
]
"#;

#[test]
fn simulate_runs_a_cfc_chart_whose_feedback_reads_the_previous_cycle() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("rivet.toml"),
        "format_version = 3\nname = \"Counter\"\napplication = [\"Counter.pou.toml\"]\ncontroller = { name = \"PLC\", host = \"127.0.0.1\", port = 5020 }\n\n[[task]]\nname = \"MainTask\"\nkind = { type = \"cyclic\", interval_us = 10000 }\npriority = 1\nprograms = [\"Counter\"]\n",
    )
    .unwrap();
    fs::create_dir(dir.path().join("application")).unwrap();
    fs::write(dir.path().join("application/Counter.pou.toml"), CFC_COUNTER).unwrap();
    let output = rivet(&[
        "simulate",
        path_str(dir.path()),
        "--cycles",
        "4",
        "--watch",
        "Counter.count,Counter.previous",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "Counter.count = 4\nCounter.previous = 3\n"
    );
    // Without the constant wired into IN2 the check names the box and its pin.
    let chart = CFC_COUNTER.replace(
        "    { from = { element = 1 }, to = { element = 2, pin = \"IN2\" } },\n",
        "",
    );
    fs::write(dir.path().join("application/Counter.pou.toml"), chart).unwrap();
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let shown = format!("{}{}", text_of(&output.stdout), text_of(&output.stderr));
    assert!(
        shown.contains("Counter.pou.toml:Counter:1:2.IN2: error[E0128]: the input IN2 of 'ADD' is not connected"),
        "{shown}"
    );
}

#[test]
fn simulate_runs_a_textual_sfc_chart_with_its_step_and_action_flags() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("chart.st");
    // 10 ms cycles: Fill is active from cycle 3 (Fill.t = 10 ms); its transition is TRUE but
    // waits for the 30 ms minimum, fires in cycle 5, and Drain is active from cycle 6. The D
    // action starts 20 ms after cycle 3, in cycle 5, and gets its final call in cycle 6.
    fs::write(
        &file,
        "PROGRAM main VAR cycle : INT; runs : INT; lamp : BOOL; SFCCurrentStep : STRING; END_VAR
         cycle := cycle + 1;
         INITIAL_STEP Idle: END_STEP
         TRANSITION FROM Idle TO Fill := cycle >= 2; END_TRANSITION
         STEP Fill (MIN_TIME := T#30ms): Pump(D, T#20ms, lamp); END_STEP
         TRANSITION FROM Fill TO Drain := TRUE; END_TRANSITION
         STEP Drain: END_STEP
         ACTION Pump: runs := runs + 1; END_ACTION
         END_PROGRAM",
    )
    .unwrap();
    let watch = "main.runs,main.lamp,main.Fill.x,main.Fill.t,main._Pump._x,main.SFCCurrentStep";
    let output = rivet(&[
        "simulate",
        path_str(&file),
        "--cycles",
        "5",
        "--watch",
        watch,
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "main.runs = 1\nmain.lamp = TRUE\nmain.Fill.x = TRUE\nmain.Fill.t = T#30ms\nmain._Pump._x = TRUE\nmain.SFCCurrentStep = 'Fill'\n"
    );
    let output = rivet(&[
        "simulate",
        path_str(&file),
        "--cycles",
        "7",
        "--watch",
        watch,
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "main.runs = 2\nmain.lamp = FALSE\nmain.Fill.x = FALSE\nmain.Fill.t = T#30ms\nmain._Pump._x = FALSE\nmain.SFCCurrentStep = 'Drain'\n"
    );
}

#[test]
fn simulate_reports_faults_unknown_variables_and_missing_files() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("div.st");
    fs::write(
        &file,
        "PROGRAM main VAR x : INT; d : INT; END_VAR\nx := 1;\nx := x / d;\nEND_PROGRAM\n",
    )
    .unwrap();
    let output = rivet(&["simulate", path_str(&file), "--watch", "main.x"]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    assert!(
        stderr.contains("division by zero in main") && stderr.contains("div.st:3"),
        "{stderr}"
    );
    let output = rivet(&["simulate", path_str(&file), "--watch", "main.nope"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text_of(&output.stderr).contains("--watch main.nope: 'main' has no member 'nope'"));
    let missing = dir.path().join("missing.st");
    let output = rivet(&["simulate", path_str(&missing)]);
    assert!(text_of(&output.stderr).contains("no such file or project folder"));
}

#[test]
fn cam_list_eval_and_export_work_on_the_example_cam() {
    let example = path_str(&assets::example_project_dir()).to_owned();
    let output = rivet(&["cam", "list", &example]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    let listed = text_of(&output.stdout);
    assert!(
        listed.starts_with("CAM_Knife: master 0..360 deg, slave 0..360 deg, 3 segments, 2 track(s) with 3 tappet(s)"),
        "{listed}"
    );

    // The knife cam: Poly5 from (0, 0) to (120, 60, v 1), a line to (240, 180), Poly5 to
    // (360, 360, v 0).
    let output = rivet(&[
        "cam",
        "eval",
        &example,
        "CAM_Knife",
        "--master",
        "0,90,180,360",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "master\tslave\tvelocity\tacceleration\n\
         0\t0\t0\t0\n\
         90\t31.640625\t0.84375\t0.009375\n\
         180\t120\t1\t0\n\
         360\t360\t0\t0\n"
    );

    let output = rivet(&[
        "cam",
        "export",
        &example,
        "CAM_Knife",
        "--format",
        "delta",
        "--elements",
        "3",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "MasterPos,SlavePos,SlaveVel,SlaveAcc\n0,0,0,0\n180,120,1,0\n360,360,0,0\n"
    );
    let output = rivet(&[
        "cam",
        "export",
        &example,
        "CAM_Knife",
        "--format",
        "omron",
        "--elements",
        "5",
    ]);
    assert_eq!(
        text_of(&output.stdout),
        "Phase,Distance\n0,0\n90,31.64062\n180,120\n270,220.7812\n360,360\n"
    );
    let output = rivet(&[
        "cam",
        "export",
        &example,
        "CAM_Knife",
        "--format",
        "codesys",
        "--elements",
        "3",
    ]);
    let gvl = text_of(&output.stdout);
    assert!(
        gvl.contains("CAM_Knife : SMC_CAMTable_LREAL_3_2 := ("),
        "{gvl}"
    );
    assert!(gvl.contains("[180.0, 120.0]"), "{gvl}");
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("knife.csv");
    let output = rivet(&[
        "cam",
        "export",
        &example,
        "CAM_Knife",
        "--format",
        "csv",
        "--elements",
        "3",
        "-o",
        path_str(&file),
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert!(fs::read_to_string(&file).unwrap().contains("180,120,1,0"));
}

#[test]
fn cam_commands_refuse_unknown_cams_and_masters_outside_the_range() {
    let example = path_str(&assets::example_project_dir()).to_owned();
    let output = rivet(&["cam", "eval", &example, "CAM_Saw", "--master", "1"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        text_of(&output.stderr)
            .contains("the project has no cam table 'CAM_Saw'; its cam tables: CAM_Knife"),
        "{}",
        text_of(&output.stderr)
    );
    let output = rivet(&["cam", "eval", &example, "CAM_Knife", "--master", "400"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        text_of(&output.stderr).contains("master 400 is outside the cam's master range 0..360")
    );
    let output = rivet(&[
        "cam",
        "export",
        &example,
        "CAM_Knife",
        "--format",
        "delta",
        "--elements",
        "3000",
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text_of(&output.stderr).contains("at most 2048 points"));
}

/// A project folder whose program `Main` (declaring `decls`) has the LD body `networks`.
fn ladder_project(decls: &str, networks: Vec<project_model::Network>) -> tempfile::TempDir {
    let source = format!("PROGRAM Main\nVAR {decls} END_VAR\nEND_PROGRAM\n");
    let mut project = compiler::SourceProject::new(&source).project;
    project.name = "Ladder".into();
    if let Some(project_model::Object::Pou(main)) = project.application.object_mut("Main") {
        main.body = project_model::Body::Ld { networks };
    }
    let dir = tempfile::tempdir().unwrap();
    project_model::save_project(&project, dir.path(), &Default::default()).unwrap();
    dir
}

/// A rung of contacts on `texts` (ids `first`, `first + 1`, …) driving coils on `coils` (ids
/// after them); ids are unique in a body, so each rung of one body starts after the last.
fn ladder_rung(
    first: u32,
    texts: &[&str],
    coils: &[(&str, project_model::CoilKind)],
) -> project_model::Network {
    use project_model::{Coil, ElementId, FlowNode, NetworkOutput, Operand};
    let rung: Vec<FlowNode> = texts
        .iter()
        .enumerate()
        .map(|(at, text)| {
            FlowNode::Operand(Operand {
                id: ElementId(first + at as u32),
                text: (*text).into(),
                ..Operand::default()
            })
        })
        .collect();
    let outputs = coils
        .iter()
        .enumerate()
        .map(|(at, (variable, kind))| {
            NetworkOutput::Coil(Coil {
                id: ElementId(first + (texts.len() + at) as u32),
                variable: (*variable).into(),
                kind: *kind,
            })
        })
        .collect();
    project_model::Network {
        rung,
        outputs,
        ..project_model::Network::default()
    }
}

#[test]
fn check_reports_a_finding_in_an_ld_body_at_its_file_pou_network_and_element() {
    use project_model::CoilKind;
    let dir = ladder_project(
        "a : BOOL; x : INT; q : BOOL;",
        vec![
            ladder_rung(1, &["a"], &[("q", CoilKind::Normal)]),
            ladder_rung(3, &["a", "x"], &[("q", CoilKind::Normal)]),
        ],
    );
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    let file = dir.path().join("application/Main.pou.toml");
    let location = format!("{}:Main:2:4: error[E0105]:", file.display());
    assert!(stderr.contains(&location), "{stderr}");
    assert!(!stderr.contains("__"), "{stderr}");
}

#[test]
fn simulate_runs_an_ld_program() {
    use project_model::CoilKind;
    // n counts cycles through an ADD box; q is set on the third cycle and latches.
    let counter = project_model::Network {
        rung: vec![project_model::FlowNode::Block(project_model::BlockCall {
            id: project_model::ElementId(1),
            type_name: "ADD".into(),
            instance: String::new(),
            inputs: ["n", "1"]
                .iter()
                .enumerate()
                .map(|(at, text)| project_model::BlockInput {
                    pin: format!("IN{}", at + 1),
                    source: vec![project_model::FlowNode::Operand(project_model::Operand {
                        id: project_model::ElementId(at as u32 + 2),
                        text: (*text).into(),
                        ..project_model::Operand::default()
                    })],
                    ..project_model::BlockInput::default()
                })
                .collect(),
            outputs: vec![project_model::BlockOutput {
                pin: "OUT".into(),
                assign: "n".into(),
                ..project_model::BlockOutput::default()
            }],
        })],
        ..project_model::Network::default()
    };
    let dir = ladder_project(
        "n : INT; q : BOOL; r : BOOL;",
        vec![
            counter,
            ladder_rung(
                4,
                &["n = 3"],
                &[("q", CoilKind::Set), ("r", CoilKind::Normal)],
            ),
        ],
    );
    let output = rivet(&[
        "simulate",
        path_str(dir.path()),
        "--cycles",
        "5",
        "--watch",
        "Main.n,Main.q,Main.r",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(
        text_of(&output.stdout),
        "Main.n = 5\nMain.q = TRUE\nMain.r = FALSE\n"
    );
}

#[test]
fn simulate_runs_an_il_program_and_check_reports_its_errors_at_the_il_line() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(
        dir.path().join("rivet.toml"),
        "format_version = 3\nname = \"Counter\"\napplication = [\"Counter.pou.toml\"]\ncontroller = { name = \"PLC\", host = \"127.0.0.1\", port = 5020 }\n\n[[task]]\nname = \"MainTask\"\nkind = { type = \"cyclic\", interval_us = 10000 }\npriority = 1\nprograms = [\"Counter\"]\n",
    )
    .unwrap();
    fs::create_dir(dir.path().join("application")).unwrap();
    fs::write(
        dir.path().join("application/Counter.pou.toml"),
        "kind = \"program\"\nbody = { language = \"il\" }\n\n[[variable]]\nname = \"count\"\ntype = \"INT\"\n",
    )
    .unwrap();
    let il = dir.path().join("application/Counter.il");
    fs::write(
        &il,
        "(* one more each cycle *)\nLD count\nADD 1\nST count\n",
    )
    .unwrap();
    let output = rivet(&[
        "simulate",
        path_str(dir.path()),
        "--cycles",
        "4",
        "--watch",
        "Counter.count",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(text_of(&output.stdout), "Counter.count = 4\n");

    fs::write(&il, "LD count\nADD 1\nST\n").unwrap();
    let output = rivet(&["check", path_str(dir.path())]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    let location = format!("{}:3:1: error[E0136]: 'ST' needs an operand", il.display());
    assert!(stderr.contains(&location), "{stderr}");
}
