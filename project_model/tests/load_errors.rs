//! Bad project folders: every problem names its file and, where it has one, its line; nothing
//! on disk changes.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::fs;
use std::path::{Path, PathBuf};

use project_model::{LoadError, Severity, load_project, save_project};

/// A copy of the example project in a temporary folder, to break on purpose.
fn example_copy() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    assets::copy_example_project(dir.path()).unwrap();
    dir
}

/// Every file's bytes, to check that loading changed nothing.
fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut files = Vec::new();
    let mut pending = vec![dir.to_owned()];
    while let Some(current) = pending.pop() {
        for entry in fs::read_dir(&current).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else {
                files.push((path.clone(), fs::read(&path).unwrap()));
            }
        }
    }
    files.sort();
    files
}

/// Loads `dir`, expects failure, checks that nothing changed, and returns the error.
#[track_caller]
fn load_fails(dir: &Path) -> LoadError {
    let before = snapshot(dir);
    let error = load_project(dir).expect_err("the project should not load");
    assert_eq!(snapshot(dir), before, "loading changed files");
    error
}

/// Asserts that one error names `file` (relative to `dir`), `line` and a message containing
/// `expected`.
#[track_caller]
fn assert_error(error: &LoadError, dir: &Path, file: &str, line: Option<usize>, expected: &str) {
    let found = error.problems.iter().any(|problem| {
        problem.severity == Severity::Error
            && problem.file == dir.join(file)
            && problem.line == line
            && problem.message.contains(expected)
    });
    assert!(
        found,
        "no error in {file} at {line:?} containing {expected:?}:\n{error}"
    );
}

fn replace_in(path: &Path, from: &str, to: &str) {
    let text = fs::read_to_string(path).unwrap();
    assert!(text.contains(from), "{from:?} not in {}", path.display());
    fs::write(path, text.replacen(from, to, 1)).unwrap();
}

#[test]
fn the_example_project_loads_without_warnings() {
    let loaded = load_project(&assets::example_project_dir()).unwrap();
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    assert_eq!(loaded.project.tasks.len(), 2);
    assert_eq!(loaded.project.axes.len(), 2);
}

#[test]
fn the_example_project_is_canonical() {
    let dir = example_copy();
    let loaded = load_project(dir.path()).unwrap();
    let report = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(
        report.written.is_empty(),
        "not canonical: {:?}",
        report.written
    );
}

#[test]
fn a_folder_without_manifest_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    let error = load_fails(dir.path());
    assert_error(&error, dir.path(), "rivet.toml", None, "file not found");
}

#[test]
fn malformed_toml_names_file_and_line() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    // The line of the first `priority = 0`, 1-based, wherever the example has it.
    let line = fs::read_to_string(&manifest)
        .unwrap()
        .lines()
        .position(|line| line.contains("priority = 0"))
        .unwrap()
        + 1;
    replace_in(&manifest, "priority = 0", "priority = ");
    let error = load_fails(dir.path());
    assert_error(&error, dir.path(), "rivet.toml", Some(line), "expected");
}

#[test]
fn a_newer_format_version_is_refused_with_both_versions() {
    let dir = example_copy();
    replace_in(
        &dir.path().join("rivet.toml"),
        "format_version = 3",
        "format_version = 7",
    );
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(1),
        "format_version 7 was written by a newer Rivet",
    );
}

#[test]
fn a_missing_format_version_is_reported() {
    let dir = example_copy();
    replace_in(&dir.path().join("rivet.toml"), "format_version = 3\n", "");
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(1),
        "missing 'format_version'",
    );
}

#[test]
fn unknown_fields_are_reported_not_dropped() {
    let dir = example_copy();
    let pou = dir.path().join("application/Main.pou.toml");
    replace_in(
        &pou,
        "kind = \"program\"",
        "kind = \"program\"\ncolour = \"red\"",
    );
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "application/Main.pou.toml",
        Some(2),
        "unknown field `colour`",
    );
}

#[test]
fn a_wrong_value_names_what_was_expected() {
    let dir = example_copy();
    let pou = dir.path().join("application/Sequence.pou.toml");
    replace_in(&pou, "kind = \"program\"", "kind = \"programme\"");
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "application/Sequence.pou.toml",
        Some(1),
        "expected one of",
    );
}

#[test]
fn an_unknown_dialect_is_refused_naming_the_known_ones() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    replace_in(
        &manifest,
        "application = [",
        "dialect = \"iec\"\napplication = [",
    );
    let error = load_fails(dir.path());
    assert_error(&error, dir.path(), "rivet.toml", Some(4), "`iec`");
    assert_error(&error, dir.path(), "rivet.toml", Some(4), "`codesys`");
    assert_error(&error, dir.path(), "rivet.toml", Some(4), "`iec-strict`");
}

#[test]
fn the_iec_strict_dialect_loads_and_saves_back() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    assert_eq!(
        load_project(dir.path()).unwrap().project.dialect,
        project_model::Dialect::Codesys
    );
    replace_in(
        &manifest,
        "application = [",
        "dialect = \"iec-strict\"\napplication = [",
    );
    let loaded = load_project(dir.path()).unwrap();
    assert_eq!(loaded.project.dialect, project_model::Dialect::IecStrict);
    let report = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(report.written.is_empty(), "rewrote {:?}", report.written);
}

#[test]
fn a_listed_file_that_is_missing_is_reported_at_its_manifest_line() {
    let dir = example_copy();
    fs::remove_file(dir.path().join("application/GVL_IO.gvl.toml")).unwrap();
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "application/GVL_IO.gvl.toml",
        None,
        "file not found",
    );
}

#[test]
fn a_missing_st_body_file_names_the_pou_file() {
    let dir = example_copy();
    fs::remove_file(dir.path().join("application/FB_Conveyor.Reset.st")).unwrap();
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "application/FB_Conveyor.Reset.st",
        None,
        "FB_Conveyor.pou.toml",
    );
}

#[test]
fn a_file_that_is_not_utf8_names_its_line() {
    let dir = example_copy();
    fs::write(
        dir.path().join("application/Main.st"),
        b"x := 1;\ny := \xff;\n",
    )
    .unwrap();
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "application/Main.st",
        Some(2),
        "not UTF-8",
    );
}

#[test]
fn an_unreadable_file_is_reported() {
    let dir = example_copy();
    // A directory where a file should be cannot be read as a file, even by root.
    let manifest = dir.path().join("rivet.toml");
    fs::remove_file(&manifest).unwrap();
    fs::create_dir(&manifest).unwrap();
    let error = load_fails(dir.path());
    assert_error(&error, dir.path(), "rivet.toml", None, "cannot read");
}

#[test]
fn bad_manifest_entries_name_their_line() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    replace_in(&manifest, "\"Main.pou.toml\",", "\"Main.txt\",");
    replace_in(
        &manifest,
        "\"Motion/\",",
        "\"Motion/\",\n    \"Missing/Thing.cam.toml\",",
    );
    replace_in(
        &manifest,
        "\"Sequence.pou.toml\",",
        "\"Sequence.pou.toml\",\n    \"sequence.pou.toml\",",
    );
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(5),
        "no known object suffix",
    );
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(8),
        "already used by 'Sequence'",
    );
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(19),
        "not listed before it",
    );
}

#[test]
fn unlisted_files_are_warned_about_and_left_alone() {
    let dir = example_copy();
    let stray = dir.path().join("application/Notes.pou.toml");
    fs::write(&stray, "kind = \"program\"\n").unwrap();
    let loaded = load_project(dir.path()).unwrap();
    assert_eq!(loaded.warnings.len(), 1);
    assert_eq!(loaded.warnings[0].file, stray);
    assert_eq!(loaded.warnings[0].severity, Severity::Warning);
    save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(
        stray.exists(),
        "saving removed a file the project does not own"
    );
}

#[test]
fn every_problem_is_reported_in_one_pass() {
    let dir = example_copy();
    replace_in(
        &dir.path().join("application/Main.pou.toml"),
        "kind = \"program\"",
        "kind = 3",
    );
    replace_in(
        &dir.path().join("application/GVL_IO.gvl.toml"),
        "[[variable]]",
        "[[variabel]]",
    );
    let error = load_fails(dir.path());
    assert_error(&error, dir.path(), "application/Main.pou.toml", Some(1), "");
    assert_error(
        &error,
        dir.path(),
        "application/GVL_IO.gvl.toml",
        Some(3),
        "unknown field `variabel`",
    );
}

/// An LD program whose second network reuses the id 1, added to the example's manifest.
const LADDER_WITH_DUPLICATE_ID: &str = r#"kind = "program"

[body]
language = "ld"

[[body.network]]
rung = [{ type = "operand", id = 1, text = "start" }]
output = [{ type = "coil", id = 2, variable = "run" }]

[[body.network]]
label = "Stop"
rung = [{ type = "operand", id = 1, text = "stop", negated = true }]
output = [{ type = "coil", id = 3, variable = "run", kind = "reset" }]
"#;

fn add_ladder(dir: &Path, text: &str) {
    fs::write(dir.join("application/Ladder.pou.toml"), text).unwrap();
    replace_in(
        &dir.join("rivet.toml"),
        "\"Main.pou.toml\",",
        "\"Main.pou.toml\",\n    \"Ladder.pou.toml\",",
    );
}

#[test]
fn a_broken_ld_body_names_pou_network_and_element_and_the_rest_still_loads() {
    let dir = example_copy();
    add_ladder(dir.path(), LADDER_WITH_DUPLICATE_ID);
    let error = load_fails(dir.path());
    let shown = error.to_string();
    let file = dir.path().join("application/Ladder.pou.toml");
    assert_eq!(
        shown,
        format!(
            "{}: error: POU 'Ladder', network 2 'Stop', element 1: two elements have the id 1; \
             the other is in network 1",
            file.display()
        )
    );
    let partial = error.partial.expect("the rest of the project loads");
    assert_eq!(partial.held_back.len(), 1);
    assert_eq!(partial.held_back[0].entry, "Ladder.pou.toml");
    assert!(partial.project.application.object("Ladder").is_none());
    assert!(partial.project.application.object("Main").is_some());
    assert!(partial.warnings.is_empty(), "{:?}", partial.warnings);
    assert!(
        !partial
            .files
            .contains(Path::new("application/Ladder.pou.toml"))
    );
}

#[test]
fn saving_a_partly_loaded_project_keeps_the_broken_file_and_its_entry() {
    let dir = example_copy();
    add_ladder(dir.path(), LADDER_WITH_DUPLICATE_ID);
    let partial = *load_fails(dir.path()).partial.unwrap();
    let mut project = partial.project.clone();
    project.description = "edited while Ladder is broken".into();
    let report = project_model::save_project_keeping(
        &project,
        dir.path(),
        &partial.files,
        &partial.held_back,
    )
    .unwrap();
    assert_eq!(report.written, [PathBuf::from("rivet.toml")]);
    assert!(report.removed.is_empty(), "{:?}", report.removed);
    let file = dir.path().join("application/Ladder.pou.toml");
    assert_eq!(fs::read_to_string(&file).unwrap(), LADDER_WITH_DUPLICATE_ID);
    let again = load_fails(dir.path());
    assert_eq!(again.problems.len(), 1, "{again}");
    let again = again.partial.unwrap();
    assert_eq!(again.project.description, "edited while Ladder is broken");
    assert_eq!(again.held_back, partial.held_back);

    let mut clash = project.clone();
    let mut main = clash.application.object("Main").unwrap().clone();
    main.set_name("Ladder".into());
    clash
        .application
        .children
        .push(project_model::Node::Object(main));
    let refused =
        project_model::save_project_keeping(&clash, dir.path(), &partial.files, &partial.held_back);
    assert!(matches!(refused, Err(project_model::SaveError::Invalid(_))));
}

#[test]
fn a_broken_manifest_gives_no_partial_project() {
    let dir = example_copy();
    replace_in(
        &dir.path().join("rivet.toml"),
        "\"Main.pou.toml\",",
        "\"Main.pou.toml\",\n    \"Main.pou.toml\",",
    );
    assert!(load_fails(dir.path()).partial.is_none());
}

/// A version 1 LD program: contact `a` in series with `b` parallel to `c`, driving coil `q`.
const LADDER_VERSION_1: &str = r#"kind = "program"

[body]
language = "ld"

[[body.network]]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "left_rail", height = 2 } },
    { id = 2, x = 2, y = 0, kind = { type = "contact", variable = "a" } },
    { id = 3, x = 4, y = 0, kind = { type = "contact", variable = "b" } },
    { id = 4, x = 4, y = 2, kind = { type = "contact", variable = "c" } },
    { id = 5, x = 6, y = 0, kind = { type = "coil", variable = "q" } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 2 }, to = { element = 3 } },
    { from = { element = 2 }, to = { element = 4 } },
    { from = { element = 3 }, to = { element = 5 } },
    { from = { element = 4 }, to = { element = 5 } },
]
"#;

#[test]
fn a_version_1_project_loads_converted_and_saves_as_the_current_version() {
    let dir = example_copy();
    add_ladder(dir.path(), LADDER_VERSION_1);
    replace_in(
        &dir.path().join("rivet.toml"),
        "format_version = 3",
        "format_version = 1",
    );
    let before = snapshot(dir.path());
    let loaded = load_project(dir.path()).unwrap();
    assert_eq!(snapshot(dir.path()), before, "loading changed files");
    let Some(project_model::Object::Pou(pou)) = loaded.project.application.object("Ladder") else {
        panic!("no Ladder POU");
    };
    let project_model::Body::Ld { networks } = &pou.body else {
        panic!("not LD: {:?}", pou.body);
    };
    assert_eq!(networks[0].rung.len(), 2);
    assert_eq!(networks[0].outputs.len(), 1);

    let report = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(report.written.contains(&PathBuf::from("rivet.toml")));
    assert!(
        report
            .written
            .contains(&PathBuf::from("application/Ladder.pou.toml"))
    );
    let manifest = fs::read_to_string(dir.path().join("rivet.toml")).unwrap();
    assert!(manifest.starts_with("format_version = 3\n"), "{manifest}");
    let again = load_project(dir.path()).unwrap();
    assert_eq!(again.project, loaded.project);
}

#[test]
fn a_version_1_network_that_cannot_be_converted_holds_back_only_its_pou() {
    let dir = example_copy();
    add_ladder(
        dir.path(),
        &LADDER_VERSION_1.replace("to = { element = 5 } },\n]", "to = { element = 9 } },\n]"),
    );
    replace_in(
        &dir.path().join("rivet.toml"),
        "format_version = 3",
        "format_version = 1",
    );
    let error = load_fails(dir.path());
    assert_error(
        &error,
        dir.path(),
        "application/Ladder.pou.toml",
        None,
        "POU 'Ladder', network 1, element 4: cannot be converted to version 2: a connection \
         leads to element 9, which does not exist",
    );
    let partial = error.partial.unwrap();
    assert_eq!(partial.held_back[0].name, "Ladder");
    assert!(partial.project.application.object("Main").is_some());
}

/// A version 2 CFC body: a graph with an old execution order and an FBD-style EN/ENO box.
const CFC_VERSION_2: &str = r#"kind = "program"

[body]
language = "cfc"

[body.chart]
comment = "Doubles the input"
element = [
    { id = 1, x = 0, y = 0, kind = { type = "input", expression = "a" } },
    { id = 2, x = 6, y = 0, execution_order = 4, kind = { type = "block", type_name = "ADD", inputs = ["IN1", "IN2"], outputs = ["OUT"], en_eno = true } },
    { id = 3, x = 12, y = 0, kind = { type = "output", expression = "b" } },
]
connection = [
    { from = { element = 1 }, to = { element = 2, pin = "IN1" } },
    { from = { element = 1 }, to = { element = 2, pin = "IN2" } },
    { from = { element = 2, pin = "OUT" }, to = { element = 3 } },
]
"#;

#[test]
fn a_version_2_cfc_chart_loads_converted_with_its_execution_order() {
    let dir = example_copy();
    add_ladder(dir.path(), CFC_VERSION_2);
    replace_in(
        &dir.path().join("rivet.toml"),
        "format_version = 3",
        "format_version = 2",
    );
    let loaded = load_project(dir.path()).unwrap();
    let Some(project_model::Object::Pou(pou)) = loaded.project.application.object("Ladder") else {
        panic!("no converted POU");
    };
    let project_model::Body::Cfc { chart } = &pou.body else {
        panic!("not CFC: {:?}", pou.body);
    };
    let order = |id: u32| {
        chart
            .elements
            .iter()
            .find(|e| e.id.0 == id)
            .map(|e| e.order)
            .unwrap()
    };
    // The box had an order, the output none: the box runs first, the input has no number.
    assert_eq!((order(1), order(2), order(3)), (None, Some(0), Some(1)));
    let Some(project_model::CfcElementKind::Box(adder)) =
        chart.elements.iter().find(|e| e.id.0 == 2).map(|e| &e.kind)
    else {
        panic!("no box");
    };
    let pins: Vec<&str> = adder.inputs.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(pins, ["EN", "IN1", "IN2"]);
    assert_eq!(chart.wires.len(), 3);
    assert!(chart.elements.iter().any(|e| matches!(
        &e.kind,
        project_model::CfcElementKind::Comment { text, .. } if text == "Doubles the input"
    )));
    let report = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(
        report
            .written
            .contains(&PathBuf::from("application/Ladder.pou.toml"))
    );
    assert_eq!(load_project(dir.path()).unwrap().project, loaded.project);
}

/// A version 2 SFC body: a step, a transition and a connection back to the step.
const SFC_VERSION_2: &str = r#"kind = "program"

[body]
language = "sfc"

[body.chart]
element = [
    { id = 1, x = 0, y = 0, kind = { type = "step", name = "Init", initial = true, action = [{ action = "lamp", qualifier = "N" }] } },
    { id = 2, x = 0, y = 2, kind = { type = "transition", condition = "go" } },
    { id = 3, x = 0, y = 4, kind = { type = "step", name = "Run" } },
    { id = 4, x = 0, y = 6, kind = { type = "transition", condition = "NOT go" } },
]
connection = [
    { from = { element = 1 }, to = { element = 2 } },
    { from = { element = 2 }, to = { element = 3 } },
    { from = { element = 3 }, to = { element = 4 } },
    { from = { element = 4 }, to = { element = 1 } },
]
"#;

#[test]
fn a_version_2_sfc_graph_loads_as_a_structured_chart_or_is_held_back_naming_the_element() {
    let dir = example_copy();
    add_ladder(dir.path(), SFC_VERSION_2);
    replace_in(
        &dir.path().join("rivet.toml"),
        "format_version = 3",
        "format_version = 2",
    );
    let loaded = load_project(dir.path()).unwrap();
    let Some(project_model::Object::Pou(pou)) = loaded.project.application.object("Ladder") else {
        panic!("no converted POU");
    };
    let project_model::Body::Sfc { chart } = &pou.body else {
        panic!("not SFC: {:?}", pou.body);
    };
    // Two steps, two transitions, and the connection back to Init as a jump (id 5).
    assert_eq!(chart.sequence.len(), 5);
    assert!(matches!(
        &chart.sequence[4],
        project_model::SfcNode::Jump(jump) if jump.target == "Init" && jump.id.0 == 5
    ));
    save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert_eq!(load_project(dir.path()).unwrap().project, loaded.project);

    let broken = example_copy();
    add_ladder(
        broken.path(),
        &SFC_VERSION_2.replace("{ from = { element = 4 }, to = { element = 1 } },\n", ""),
    );
    replace_in(
        &broken.path().join("rivet.toml"),
        "format_version = 3",
        "format_version = 2",
    );
    let error = load_fails(broken.path());
    assert_error(
        &error,
        broken.path(),
        "application/Ladder.pou.toml",
        None,
        "POU 'Ladder', element 4: the transition leads nowhere; a transition leads to a step or \
         a jump",
    );
    assert_eq!(error.partial.unwrap().held_back[0].name, "Ladder");
}

/// A version 3 CFC body in its canonical form: an input into a box into an output.
const CFC_CANONICAL: &str = r#"kind = "program"

[body]
language = "cfc"

[body.chart]
element = [
    { id = 1, x = 2, y = 4, kind = { type = "input", expression = "rSetpoint" } },
    { id = 2, x = 10, y = 4, order = 0, kind = { type = "box", type_name = "SUB", input = [{ name = "IN1" }, { name = "IN2" }], output = [{ name = "OUT" }] } },
    { id = 3, x = 18, y = 4, order = 1, kind = { type = "output", expression = "rError" } },
]
wire = [
    { from = { element = 1 }, to = { element = 2, pin = "IN1" } },
    { from = { element = 2, pin = "OUT" }, to = { element = 3 }, points = [{ x = 15, y = 6 }] },
]
"#;

#[test]
fn a_cfc_chart_loads_and_saves_unchanged_and_a_broken_one_is_refused_at_its_element() {
    let dir = example_copy();
    add_ladder(dir.path(), CFC_CANONICAL);
    let loaded = load_project(dir.path()).unwrap();
    let report = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
    assert!(report.written.is_empty(), "rewrote {:?}", report.written);
    assert_eq!(load_project(dir.path()).unwrap().project, loaded.project);

    let file = dir.path().join("application/Ladder.pou.toml");
    replace_in(
        &file,
        "{ from = { element = 1 }, to = { element = 2, pin = \"IN1\" } },",
        "{ from = { element = 1 }, to = { element = 2, pin = \"IN1\" } },\n    { from = { element = 1 }, to = { element = 2, pin = \"in1\" } },",
    );
    let error = load_fails(dir.path());
    assert_eq!(
        error.to_string(),
        format!(
            "{}: error: POU 'Ladder', element 2: the pin 'in1' has two wires; an input takes one",
            file.display()
        )
    );
}

/// The 1-based line of the first line of `path` that is `line`.
fn line_number(path: &Path, line: &str) -> usize {
    let text = fs::read_to_string(path).unwrap();
    text.lines().position(|each| each == line).unwrap() + 1
}

#[test]
fn a_modbus_device_with_both_links_or_neither_is_refused_at_its_table() {
    let cases = [
        (
            "port = 502\n",
            "port = 502\nserial_port = \"RS485\"\n",
            "has both",
        ),
        ("host = \"192.168.1.50\"\nport = 502\n", "", "has neither"),
        ("port = 502\n", "", "has 'host' but no 'port'"),
    ];
    for (from, to, expected) in cases {
        let dir = example_copy();
        let manifest = dir.path().join("rivet.toml");
        replace_in(&manifest, from, to);
        // A sound device before the broken one: the error must name the broken device's own
        // table, not the first `[[modbus_device]]` of the file.
        replace_in(
            &manifest,
            "[[modbus_device]]\n",
            "[[modbus_device]]\nname = \"Meter\"\nhost = \"192.168.1.60\"\nport = 502\n\
             unit_id = 2\ntimeout_ms = 500\n\n[[modbus_device]]\n",
        );
        let table = last_line_number(&manifest, "[[modbus_device]]");
        let error = load_fails(dir.path());
        assert_error(&error, dir.path(), "rivet.toml", Some(table), expected);
        assert_error(&error, dir.path(), "rivet.toml", Some(table), "'BeltDrive'");
        assert_eq!(error.problems.len(), 1, "{error}");
    }
}

/// The 1-based line of the last line of `path` that is `line`.
fn last_line_number(path: &Path, line: &str) -> usize {
    let text = fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    lines.iter().rposition(|each| *each == line).unwrap() + 1
}

#[test]
fn an_unknown_key_of_a_modbus_device_or_a_serial_port_is_reported() {
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    replace_in(
        &manifest,
        "timeout_ms = 500\n",
        "timeout_ms = 500\npriority = 1\n",
    );
    let error = load_fails(dir.path());
    let line = last_line_number(&manifest, "priority = 1");
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(line),
        "unknown field `priority`",
    );
    let dir = example_copy();
    let manifest = dir.path().join("rivet.toml");
    replace_in(
        &manifest,
        "[[modbus_device]]",
        "[[serial_port]]\nname = \"RS485\"\ndevice = \"/dev/ttyS1\"\nbaud_rate = 19200\n\
         parity = \"none\"\ndata_bits = 8\nstop_bits = 2\nflow_control = true\n\n[[modbus_device]]",
    );
    let error = load_fails(dir.path());
    let line = line_number(&manifest, "flow_control = true");
    assert_error(
        &error,
        dir.path(),
        "rivet.toml",
        Some(line),
        "unknown field `flow_control`",
    );
}
