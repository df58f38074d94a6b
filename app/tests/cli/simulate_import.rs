//! `rivet simulate` end to end on an imported program: Beremiz's `first_steps` imported with
//! `rivet import`, then run from the command line with its `Reset` input set by `--set`; its
//! counters in ST, LD, FBD, IL and SFC count as the import tests find through the API
//! (`tests/tests/plcopen_import`).

use std::path::Path;

use super::{path_str, rivet, text_of};

/// Each counter's output, by the language of its body.
const COUNTERS: [(&str, &str); 5] = [
    ("ST", "plc_prg.CounterST0.OUT"),
    ("LD", "plc_prg.CounterLD0.Out"),
    ("FBD", "plc_prg.CounterFBD0.OUT"),
    ("IL", "plc_prg.CounterIL0.OUT"),
    ("SFC", "plc_prg.CounterSFC0.OUT"),
];

/// Runs `rivet simulate` on `project` with `arguments` and the counters watched as JSON; gives
/// each counter's value in the order of [`COUNTERS`].
fn counters(project: &Path, arguments: &[&str]) -> Vec<i64> {
    let watch = COUNTERS.map(|(_, path)| path).join(",");
    let mut all = vec!["simulate", path_str(project), "--json", "--watch", &watch];
    all.extend_from_slice(arguments);
    let output = rivet(&all);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    let values: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    COUNTERS
        .iter()
        .map(|(language, path)| {
            values[path]
                .as_i64()
                .unwrap_or_else(|| panic!("{language}: {values}"))
        })
        .collect()
}

#[test]
fn first_steps_imported_from_the_command_line_counts_in_every_language() {
    let temp = tempfile::tempdir().unwrap();
    let project = temp.path().join("first_steps");
    let file = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../shared/corpora/plcopen/beremiz/exemples/first_steps/plc.xml"
    ));
    let output = rivet(&["import", path_str(file), "-o", path_str(&project)]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));

    // Counting one per cycle from 0; the chart spends its first cycle in its initial step.
    assert_eq!(counters(&project, &["--cycles", "4"]), [4, 4, 4, 4, 3]);
    // Reset held in cycles 6 and 7 loads ResetCounterValue (17), then counting goes on; the
    // chart reaches 17 two cycles later and leaves it one cycle later, as in Beremiz.
    let set = ["--set", "6:plc_prg.Reset=TRUE"];
    let reset = ["--set", "8:plc_prg.Reset=FALSE"];
    assert_eq!(
        counters(&project, &[&["--cycles", "6"][..], &set].concat()),
        [17, 17, 17, 17, 5]
    );
    let run = |cycles: &str| {
        counters(
            &project,
            &[&["--cycles", cycles][..], &set, &reset].concat(),
        )
    };
    assert_eq!(run("8"), [18, 18, 18, 18, 17]);
    assert_eq!(run("10"), [20, 20, 20, 20, 18]);
}

#[test]
fn a_value_that_does_not_fit_or_a_cycle_that_never_runs_is_refused_before_running() {
    let example = assets::example_project_dir();
    let output = rivet(&[
        "simulate",
        path_str(&example),
        "--cycles",
        "3",
        "--set",
        "4:Main.rtrigPackage.CLK=TRUE",
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        text_of(&output.stderr).contains("cycle 4 does not run; cycles run from 1 to 3"),
        "{}",
        text_of(&output.stderr)
    );
    let output = rivet(&["simulate", path_str(&example), "--set", "1:Main.nope=1"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(
        text_of(&output.stderr).contains("--set Main.nope: "),
        "{}",
        text_of(&output.stderr)
    );
}
