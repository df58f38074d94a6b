//! `rivet import`: every corpus file into a new project that checks, refusals that write
//! nothing, and merges into an existing project.

use std::fs;
use std::path::{Path, PathBuf};

use super::{path_str, rivet, text_of};

fn corpus(relative: &str) -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpora")).join(relative)
}

const FIRST_STEPS: &str = "plcopen/beremiz/exemples/first_steps/plc.xml";

/// The POUs of the corpus files that do not check, each for a reason outside the import (the
/// same as `tests/tests/plcopen_import/`): CODESYS's SysMem library (`x05`, `x06`), Beremiz's
/// own runtime library and extensions (`main_test`'s LOGGER, `main_program`'s SVGHMI types and
/// python_eval), and matiec's MUX of an INT and a BOOL and its STRING initialised with a real
/// literal.
const POUS_NOT_CHECKING: [&str; 6] = [
    "x05_SysMemLib",
    "x06_Combine2xByteToUint",
    "main_test",
    "main_program",
    "TEST_FROM_STRINGS",
    "MAIN_TEST",
];

/// Imports `relative` into `dir` and gives the standard output.
fn import_into_new(relative: &str, dir: &Path) -> String {
    let file = corpus(relative);
    let output = rivet(&["import", path_str(&file), "-o", path_str(dir)]);
    assert!(
        output.status.success(),
        "{relative}: {}",
        text_of(&output.stderr)
    );
    text_of(&output.stdout)
}

/// The names of the objects whose files `rivet check` reports errors in.
fn objects_with_errors(check_stderr: &str) -> Vec<String> {
    let mut names: Vec<String> = check_stderr
        .lines()
        .filter(|line| line.contains(": error["))
        .filter_map(|line| {
            let file = line.split("/application/").nth(1)?;
            Some(file.split(['.', ':']).next()?.to_owned())
        })
        .collect();
    names.sort();
    names.dedup();
    names
}

#[test]
fn every_corpus_file_imports_into_a_project_that_loads_and_checks() {
    let temp = tempfile::tempdir().unwrap();
    for relative in [
        FIRST_STEPS,
        "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
        "plcopen/beremiz/tests/projects/svghmi_basic/plc.xml",
        "plcopen/codesys/codesys_code_execution_speedTests.xml",
        "matiec/tests/LD_TEST.xml",
        "matiec/tests/SFC_TEST.xml",
        "matiec/tests/STD_TEST.xml",
    ] {
        let dir = temp.path().join(relative.replace('/', "_"));
        let stdout = import_into_new(relative, &dir);
        // The report ends with the counts, and every entry names the file and line.
        assert!(stdout.contains(" converted, "), "{stdout}");
        assert!(stdout.contains(&format!("{}:", corpus(relative).display())));
        let check = rivet(&["check", path_str(&dir)]);
        let stderr = text_of(&check.stderr);
        let failing = objects_with_errors(&stderr);
        let unexplained: Vec<&String> = failing
            .iter()
            .filter(|name| !POUS_NOT_CHECKING.contains(&name.as_str()))
            .collect();
        assert!(
            unexplained.is_empty(),
            "{relative}: {unexplained:?}\n{stderr}"
        );
        if [
            FIRST_STEPS,
            "matiec/tests/LD_TEST.xml",
            "matiec/tests/SFC_TEST.xml",
        ]
        .contains(&relative)
        {
            assert!(check.status.success(), "{relative}: {stderr}");
        }
    }
}

#[test]
fn the_report_lists_each_entry_with_outcome_file_and_line() {
    let temp = tempfile::tempdir().unwrap();
    let stdout = import_into_new(FIRST_STEPS, &temp.path().join("steps"));
    let file = corpus(FIRST_STEPS).display().to_string();
    assert!(
        stdout.contains(&format!("converted: POU 'CounterST' ({file}:451)")),
        "{stdout}"
    );
    assert!(stdout.contains(&format!(
        "{file}: PLCopen TC6 v2.01 file written by Beremiz"
    )));
    // Between the summary and the counts, one line per entry: `OUTCOME: WHAT (FILE:LINE)[: NOTE]`,
    // and the counts add the entries up.
    let lines: Vec<&str> = stdout.lines().collect();
    let entries = &lines[1..lines.len() - 2];
    let mut counts = [0usize; 3];
    for line in entries {
        let (index, rest) = ["converted: ", "kept: ", "not converted: "]
            .iter()
            .enumerate()
            .find_map(|(index, word)| Some((index, line.strip_prefix(word)?)))
            .unwrap_or_else(|| panic!("no outcome: {line}"));
        counts[index] += 1;
        let place = rest
            .split(&format!(" ({file}:"))
            .nth(1)
            .unwrap_or_else(|| panic!("no place: {line}"));
        let number = place.split(')').next().unwrap();
        assert!(number.parse::<u32>().is_ok(), "{line}");
    }
    let [converted, kept, not_converted] = counts;
    let summary = format!(
        "{file}: {converted} converted, {kept} kept for the export, {not_converted} not converted"
    );
    assert_eq!(lines[lines.len() - 2], summary);
}

#[test]
fn a_truncated_file_gives_line_and_column_and_writes_nothing() {
    let temp = tempfile::tempdir().unwrap();
    let text = fs::read_to_string(corpus(FIRST_STEPS)).unwrap();
    let file = temp.path().join("truncated.xml");
    let cut = text.char_indices().nth(3000).unwrap().0;
    fs::write(&file, &text[..cut]).unwrap();
    let target = temp.path().join("project");
    let output = rivet(&["import", path_str(&file), "-o", path_str(&target)]);
    assert_eq!(output.status.code(), Some(1));
    let stderr = text_of(&output.stderr);
    let location = format!("{}:", file.display());
    let rest = stderr
        .strip_prefix(&location)
        .unwrap_or_else(|| panic!("{stderr}"));
    let mut numbers = rest.split(':').take(2);
    assert!(
        numbers.all(|number| number.parse::<u32>().is_ok()),
        "{stderr}"
    );
    assert!(!target.exists());
    let left: Vec<_> = fs::read_dir(temp.path()).unwrap().collect();
    assert_eq!(left.len(), 1, "only the XML file is there");
}

#[test]
fn a_50_mb_file_is_refused_from_its_size_and_writes_nothing() {
    let temp = tempfile::tempdir().unwrap();
    let file = temp.path().join("huge.xml");
    // Sparse: 50 MB long without writing them; the import must refuse it from its size.
    fs::File::create(&file)
        .unwrap()
        .set_len(50_000_000)
        .unwrap();
    let target = temp.path().join("project");
    let output = rivet(&["import", path_str(&file), "-o", path_str(&target)]);
    assert_eq!(output.status.code(), Some(1));
    assert_eq!(
        text_of(&output.stderr).trim_end(),
        format!(
            "{}:1:1: the file has 50000000 bytes (47.7 MiB), more than the 32 MiB a \
             PLCopen XML file may have",
            file.display()
        )
    );
    assert!(!target.exists());
    assert_eq!(fs::read_dir(temp.path()).unwrap().count(), 1);
}

#[test]
fn a_folder_that_is_not_empty_is_refused_and_left_untouched() {
    let temp = tempfile::tempdir().unwrap();
    let target = temp.path().join("busy");
    fs::create_dir(&target).unwrap();
    fs::write(target.join("notes.txt"), "mine").unwrap();
    let file = corpus(FIRST_STEPS);
    let output = rivet(&["import", path_str(&file), "-o", path_str(&target)]);
    assert_eq!(output.status.code(), Some(1));
    assert!(text_of(&output.stderr).contains("the folder is not empty; nothing was written"));
    let entries: Vec<_> = fs::read_dir(&target).unwrap().collect();
    assert_eq!(entries.len(), 1);
    assert_eq!(
        fs::read_to_string(target.join("notes.txt")).unwrap(),
        "mine"
    );
    assert_eq!(fs::read_dir(temp.path()).unwrap().count(), 1);
    // An empty folder is fine.
    let empty = temp.path().join("empty");
    fs::create_dir(&empty).unwrap();
    import_into_new(FIRST_STEPS, &empty);
    assert!(empty.join("rivet.toml").is_file());
}

#[test]
fn into_adds_what_is_new_and_skips_clashes_unless_told_to_replace() {
    let temp = tempfile::tempdir().unwrap();
    let project = temp.path().join("project");
    import_into_new(FIRST_STEPS, &project);
    let body = project.join("application/CounterST.st");
    let theirs = fs::read_to_string(&body).unwrap();
    fs::write(&body, format!("(* mine *)\n{theirs}")).unwrap();
    let mine = fs::read_to_string(&body).unwrap();

    let std_test = corpus("matiec/tests/STD_TEST.xml");
    let output = rivet(&["import", path_str(&std_test), "--into", path_str(&project)]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    let stdout = text_of(&output.stdout);
    assert!(
        stdout.contains("add global variable list 'STD_CONF'"),
        "{stdout}"
    );
    assert!(stdout.contains("add task 'STD_TASK'"), "{stdout}");
    let manifest = fs::read_to_string(project.join("rivet.toml")).unwrap();
    assert!(manifest.contains("STD_CONF.gvl.toml") && manifest.contains("STD_TASK"));
    assert!(manifest.contains("name = \"First Steps\""), "{manifest}");

    let first_steps = corpus(FIRST_STEPS);
    let output = rivet(&[
        "import",
        path_str(&first_steps),
        "--into",
        path_str(&project),
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    let stdout = text_of(&output.stdout);
    assert!(
        stdout.contains("skip POU 'CounterST' (clashes with POU 'CounterST')"),
        "{stdout}"
    );
    assert!(stdout.contains("skip task 'plc_task'"), "{stdout}");
    assert_eq!(fs::read_to_string(&body).unwrap(), mine);

    let output = rivet(&[
        "import",
        path_str(&first_steps),
        "--into",
        path_str(&project),
        "--replace",
    ]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert_eq!(fs::read_to_string(&body).unwrap(), theirs);
    // Only STD_TEST's string tests fail (matiec's names for the string functions' inputs).
    let check = rivet(&["check", path_str(&project)]);
    let failing = objects_with_errors(&text_of(&check.stderr));
    assert!(
        failing
            .iter()
            .all(|name| POUS_NOT_CHECKING.contains(&name.as_str())),
        "{}",
        text_of(&check.stderr)
    );
}

#[test]
fn into_keeps_the_vendor_data_of_the_objects_it_adds() {
    let temp = tempfile::tempdir().unwrap();
    let project = temp.path().join("project");
    import_into_new(FIRST_STEPS, &project);
    let codesys = corpus("plcopen/codesys/codesys_code_execution_speedTests.xml");
    let output = rivet(&["import", path_str(&codesys), "--into", path_str(&project)]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    // CODESYS's call type of the ADD box of the LD POU comes along, with its element.
    let kept = fs::read_to_string(project.join("plcopen.toml")).unwrap();
    assert!(
        kept.contains("place = \"pou:addTwoIntsLadder/body/element:"),
        "{kept}"
    );
    assert!(kept.contains("fbdcalltype"), "{kept}");
}

#[test]
fn export_writes_a_file_that_imports_back_into_the_same_project() {
    let temp = tempfile::tempdir().unwrap();
    let example = assets::example_project_dir();
    let xml = temp.path().join("machine.xml");
    let output = rivet(&["export", path_str(&example), "-o", path_str(&xml)]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    assert!(text_of(&output.stdout).contains("bytes of PLCopen XML written"));
    assert!(
        fs::read_to_string(&xml)
            .unwrap()
            .contains("http://www.plcopen.org/xml/tc6_0201")
    );
    // No partial file is left beside it.
    let left: Vec<_> = fs::read_dir(temp.path()).unwrap().collect();
    assert_eq!(left.len(), 1);

    let back = temp.path().join("back");
    let file = xml.to_string_lossy().into_owned();
    let output = rivet(&["import", &file, "-o", path_str(&back)]);
    assert!(output.status.success(), "{}", text_of(&output.stderr));
    let original = project_model::load_project(&example).unwrap().project;
    let imported = project_model::load_project(&back).unwrap().project;
    assert_eq!(imported.application, original.application);
    assert_eq!(imported.tasks, original.tasks);
    assert_eq!(imported.axes, original.axes);
    assert_eq!(imported.modbus_devices, original.modbus_devices);

    // A project that does not load is an error naming it, and nothing is written.
    let missing = temp.path().join("missing");
    let refused = temp.path().join("refused.xml");
    let output = rivet(&["export", path_str(&missing), "-o", path_str(&refused)]);
    assert!(!output.status.success());
    assert!(
        text_of(&output.stderr).contains(&*missing.to_string_lossy()),
        "{}",
        text_of(&output.stderr)
    );
    assert!(!refused.exists());
}
