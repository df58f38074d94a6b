//! PLCopen XML files of the shared corpora imported (data types, ST, SFC and CFC POUs, global
//! variable lists, tasks) and checked by the compiler; Beremiz's SFC counter run in the engine.

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
    // Each file with the objects its ST and SFC parts give (LD_TEST is LD only: its POUs wait
    // for the LD/FBD import). svghmi_basic is apart: see below.
    for (file, objects) in [
        ("plcopen/beremiz/exemples/first_steps/plc.xml", 4),
        (
            "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
            1,
        ),
        ("matiec/tests/LD_TEST.xml", 0),
        ("matiec/tests/SFC_TEST.xml", 1),
        ("matiec/tests/STD_TEST.xml", 2),
    ] {
        let (imported, errors) = import_errors(file);
        assert_eq!(imported, objects, "{file}");
        assert!(errors.is_empty(), "{file}: {errors:#?}");
    }
}

#[test]
fn svghmi_traffic_lights_check_but_for_the_objects_the_ld_fbd_import_brings() {
    // The chart imports; its action BLINK_ORANGE_LIGHT (LD) and transition STOP (FBD) wait for
    // the LD/FBD import, so the chart names an action and a transition the POU lacks yet.
    let (imported, errors) = import_errors("plcopen/beremiz/tests/projects/svghmi_basic/plc.xml");
    assert_eq!(imported, 1);
    assert!(!errors.is_empty());
    let unexplained: Vec<&String> = errors
        .iter()
        .filter(|error| !error.contains("BLINK_ORANGE_LIGHT") && !error.contains("STOP"))
        .collect();
    assert!(unexplained.is_empty(), "{unexplained:#?}");
}

/// The CODESYS POUs that do not check, each for a reason outside the import: the file name of the
/// POU (an action's file starts with it) and why.
const CODESYS_POUS_NOT_CHECKING: [(&str, &str); 5] = [
    // `LTIME()`, CODESYS's high-resolution clock operator, is not in Rivet's standard library.
    ("x", "every x.. test program measures with LTIME()"),
    (
        "calcMIPS",
        "LTIME(), and UDINT * REAL, which CODESYS widens and Rivet refuses",
    ),
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

/// Beremiz's `first_steps` counts in every language; its SFC counter, imported, runs in a
/// program beside the ST one and counts alike: up by one each cycle, back to
/// `ResetCounterValue` (17) on `Reset`. The chart spends a cycle in each step it passes: it
/// starts one cycle late (in `Start`), and a reset goes from `Count` through `Start` to
/// `ResetCounter`, so it reaches 17 two cycles after the ST counter and leaves it one cycle
/// after `Reset` falls, as the same chart does in Beremiz.
#[test]
fn first_steps_counter_sfc_counts_like_counter_st() {
    let document = plcopen::read_file(&corpus("plcopen/beremiz/exemples/first_steps/plc.xml"))
        .unwrap_or_else(|error| panic!("{error}"));
    let imported = plcopen::import(&document).unwrap_or_else(|error| panic!("{error}"));
    let source = "PROGRAM Main
VAR
  st : CounterST;
  sfc : CounterSFC;
  cycle : INT;
  reset : BOOL;
  st_out : INT;
  sfc_out : INT;
END_VAR
cycle := cycle + 1;
reset := cycle >= 6 AND cycle <= 7;
st(Reset := reset);
sfc(Reset := reset);
st_out := st.OUT;
sfc_out := sfc.OUT;
END_PROGRAM
";
    let built = compiler::SourceProject::new(source);
    assert!(
        built.parse.errors().is_empty(),
        "{:?}",
        built.parse.errors()
    );
    let mut project = built.project;
    for object in imported.project.application.objects() {
        project
            .application
            .children
            .push(project_model::Node::Object(object.clone()));
    }
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found
                .iter()
                .filter(|d| d.diagnostic.severity == Severity::Error)
                .map(|d| format!("{}: {}", d.file.display(), d.diagnostic.message))
                .collect();
            panic!("the imported project does not check: {errors:#?}")
        }
        Err(error) => panic!("the imported project does not compile: {error}"),
    };
    let mut simulation =
        runtime::simulation::Simulation::new(image).unwrap_or_else(|error| panic!("{error}"));
    let mut seen = Vec::new();
    for _ in 0..10 {
        simulation.run(1);
        assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
        let read = |path: &str| {
            runtime::value::read(simulation.engine(), path)
                .unwrap_or_else(|error| panic!("{path}: {error}"))
                .to_string()
        };
        seen.push((read("Main.st_out"), read("Main.sfc_out")));
    }
    let expected = [
        (1, 0),
        (2, 1),
        (3, 2),
        (4, 3),
        (5, 4),
        (17, 5),
        (17, 6),
        (18, 17),
        (19, 17),
        (20, 18),
    ]
    .map(|(st, sfc): (i32, i32)| (st.to_string(), sfc.to_string()));
    assert_eq!(seen, expected);
}

/// CODESYS's `addTwoIntsCFC`, imported from its CFC `addData`, adds: its wires come first,
/// though the file numbers its output before its ADD box.
#[test]
fn codesys_add_two_ints_cfc_adds() {
    let document = plcopen::read_file(&corpus(
        "plcopen/codesys/codesys_code_execution_speedTests.xml",
    ))
    .unwrap_or_else(|error| panic!("{error}"));
    let imported = plcopen::import(&document).unwrap_or_else(|error| panic!("{error}"));
    let source = "PROGRAM Main
VAR
  sum : INT;
  other : INT;
END_VAR
sum := addTwoIntsCFC(int1 := 2, int2 := 3);
other := addTwoIntsCFC(int1 := -40, int2 := 2);
END_PROGRAM
";
    let built = compiler::SourceProject::new(source);
    assert!(
        built.parse.errors().is_empty(),
        "{:?}",
        built.parse.errors()
    );
    let mut project = built.project;
    for object in imported.project.application.objects() {
        if object.name() == "addTwoIntsCFC" {
            project
                .application
                .children
                .push(project_model::Node::Object(object.clone()));
        }
    }
    let image = compiler::compile_project(&project).unwrap_or_else(|error| panic!("{error:?}"));
    let mut simulation =
        runtime::simulation::Simulation::new(image).unwrap_or_else(|error| panic!("{error}"));
    simulation.run(1);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    for (path, want) in [("Main.sum", "5"), ("Main.other", "-38")] {
        let value = runtime::value::read(simulation.engine(), path)
            .unwrap_or_else(|error| panic!("{path}: {error}"));
        assert_eq!(value.to_string(), want, "{path}");
    }
}

/// matiec's `SFC_TEST` chart, imported, runs: with every input FALSE it leaves `GO` (its
/// condition is `IX1 = FALSE`) for `STEP1`, whose action `ONSTEP1` sets `QX1`, and waits there
/// for `IX2`.
#[test]
fn matiec_sfc_test_steps_into_its_first_step() {
    let document = plcopen::read_file(&corpus("matiec/tests/SFC_TEST.xml"))
        .unwrap_or_else(|error| panic!("{error}"));
    let imported = plcopen::import(&document).unwrap_or_else(|error| panic!("{error}"));
    // The file's instance runs in no task; the test puts the program in the file's task.
    let mut project = imported.project;
    let [task] = project.tasks.as_mut_slice() else {
        panic!("{:?}", project.tasks)
    };
    task.programs.push("MAIN_TEST".to_owned());
    let image = compiler::compile_project(&project).unwrap_or_else(|error| panic!("{error:?}"));
    let mut simulation =
        runtime::simulation::Simulation::new(image).unwrap_or_else(|error| panic!("{error}"));
    let read = |simulation: &runtime::simulation::Simulation, path: &str| {
        runtime::value::read(simulation.engine(), path)
            .unwrap_or_else(|error| panic!("{path}: {error}"))
            .to_string()
    };
    simulation.run(1);
    assert_eq!(read(&simulation, "MAIN_TEST.GO.x"), "TRUE");
    assert_eq!(read(&simulation, "MAIN_TEST.QX1"), "FALSE");
    simulation.run(3);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    assert_eq!(read(&simulation, "MAIN_TEST.GO.x"), "FALSE");
    assert_eq!(read(&simulation, "MAIN_TEST.STEP1.x"), "TRUE");
    assert_eq!(read(&simulation, "MAIN_TEST.QX1"), "TRUE");
}
