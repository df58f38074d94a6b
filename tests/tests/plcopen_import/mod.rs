//! PLCopen XML files of the shared corpora imported (their ST part: data types, ST POUs, global
//! variable lists, tasks) and checked by the compiler.

use std::path::{Path, PathBuf};

use compiler::Severity;

fn corpus(relative: &str) -> PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/corpora")).join(relative)
}

/// The number of application objects imported from `relative`, and the errors the compiler
/// finds in the project, as `file: message`.
fn import_errors(relative: &str) -> (usize, Vec<String>) {
    let document = plcopen::read_file(&corpus(relative)).unwrap_or_else(|error| panic!("{error}"));
    let imported = plcopen::import(&document).unwrap_or_else(|error| panic!("{error}"));
    let errors = compiler::sema::check_project(&imported.project)
        .into_iter()
        .filter(|found| found.diagnostic.severity == Severity::Error)
        .map(|found| format!("{}: {}", found.file.display(), found.diagnostic.message))
        .collect();
    (imported.project.application.objects().len(), errors)
}

#[test]
fn beremiz_and_matiec_files_check_without_errors() {
    // Each file with the objects its ST part gives (svghmi_basic and LD_TEST are graphical only:
    // their POUs wait for the graphical import).
    for (file, objects) in [
        ("plcopen/beremiz/exemples/first_steps/plc.xml", 3),
        (
            "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
            1,
        ),
        ("plcopen/beremiz/tests/projects/svghmi_basic/plc.xml", 0),
        ("matiec/tests/LD_TEST.xml", 0),
        ("matiec/tests/SFC_TEST.xml", 0),
        ("matiec/tests/STD_TEST.xml", 2),
    ] {
        let (imported, errors) = import_errors(file);
        assert_eq!(imported, objects, "{file}");
        assert!(errors.is_empty(), "{file}: {errors:#?}");
    }
}

/// The CODESYS POUs that do not check, each for a reason outside the import: the file name of the
/// POU (an action's file starts with it) and why.
const CODESYS_POUS_NOT_CHECKING: [(&str, &str); 5] = [
    // `LTIME()`, CODESYS's high-resolution clock operator, is not in Rivet's standard library.
    ("x", "every x.. test program measures with LTIME()"),
    ("calcMIPS", "LTIME()"),
    ("calcFLOPS", "LTIME()"),
    // SysMemCpy, SysMemSet and SysMemCmp come from CODESYS's SysMem library.
    ("x05_SysMemLib", "the SysMem library; ADR of a constant"),
    // addTwoIntsLadder, addTwoIntsFBD and addTwoIntsCFC wait for the graphical import.
    (
        "x02_ExecSpeedOfLanguageTypes",
        "calls LD, FBD and CFC functions",
    ),
];

#[test]
fn codesys_st_pous_check_except_for_missing_library_parts() {
    let (imported, errors) = import_errors("plcopen/codesys/codesys_code_execution_speedTests.xml");
    assert!(imported >= 40, "only {imported} objects");
    let unexplained: Vec<&String> = errors
        .iter()
        .filter(|error| {
            let file = error.strip_prefix("application/").unwrap_or(error.as_str());
            !CODESYS_POUS_NOT_CHECKING
                .iter()
                .any(|(prefix, _)| file.starts_with(prefix))
        })
        .collect();
    assert!(unexplained.is_empty(), "{unexplained:#?}");
    // The runner, the functions and the data types did check: only the listed POUs fail.
    assert!(
        errors
            .iter()
            .all(|error| !error.starts_with("application/speedRunner")),
        "{errors:#?}"
    );
}
