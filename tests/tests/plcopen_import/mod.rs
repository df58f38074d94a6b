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
const CODESYS_POUS_NOT_CHECKING: [(&str, &str); 3] = [
    // SysMemCpy, SysMemSet and SysMemCmp come from CODESYS's SysMem library.
    ("x05_SysMemLib", "the SysMem library; ADR of a constant"),
    (
        "x06_Combine2xByteToUint.Measure",
        "SysMemCpy of the SysMem library",
    ),
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

/// Removes the objects named in `names` from `folder` and its subfolders.
fn remove_objects(folder: &mut project_model::Folder, names: &[&str]) {
    folder.children.retain(|node| match node {
        project_model::Node::Object(object) => !names.contains(&object.name()),
        project_model::Node::Folder(_) => true,
    });
    for node in &mut folder.children {
        if let project_model::Node::Folder(child) = node {
            remove_objects(child, names);
        }
    }
}

/// One of CODESYS's speed tests, imported, built and run in simulation: `x08_CheckingBools`
/// measures its loops with `LTIME()`, which on the simulated clock stands still within a cycle
/// and moves by the task interval from one cycle to the next.
#[test]
fn a_codesys_speed_test_program_builds_and_runs_in_simulation() {
    let file = corpus("plcopen/codesys/codesys_code_execution_speedTests.xml");
    let document = plcopen::read_file(&file).unwrap_or_else(|error| panic!("{error}"));
    let mut project = plcopen::import(&document)
        .unwrap_or_else(|error| panic!("{error}"))
        .project;
    // The POUs that do not check (above) and the runner that calls them; every other POU is
    // built.
    remove_objects(
        &mut project.application,
        &[
            "x02_ExecSpeedOfLanguageTypes",
            "x05_SysMemLib",
            "x06_Combine2xByteToUint",
            "speedRunner",
        ],
    );
    let Some(project_model::Object::Pou(program)) =
        project.application.object_mut("x08_CheckingBools")
    else {
        panic!("x08_CheckingBools is not imported as a POU");
    };
    // Ten repetitions instead of a million, so a debug build runs the six runs of five loops
    // in milliseconds rather than minutes.
    let repeat = program
        .variables
        .iter_mut()
        .find(|variable| variable.name == "cRepeatCalcTimes")
        .expect("x08 declares cRepeatCalcTimes");
    assert_eq!(repeat.initial.as_deref(), Some("1000000"));
    repeat.initial = Some("10".to_owned());
    // Every cycle runs the whole test, as the CODESYS event task does on each start.
    project.tasks = vec![project_model::Task {
        name: "x08".to_owned(),
        kind: project_model::TaskKind::Cyclic {
            interval_us: 200_000,
        },
        priority: 1,
        watchdog: None,
        programs: vec!["x08_CheckingBools".to_owned()],
    }];
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found
                .iter()
                .filter(|d| d.diagnostic.severity == Severity::Error)
                .map(|d| format!("{}: {}", d.file.display(), d.diagnostic.message))
                .collect();
            panic!("the project does not check: {errors:#?}")
        }
        Err(error) => panic!("the project does not compile: {error}"),
    };
    let mut simulation = runtime::simulation::Simulation::new(image).expect("the image loads");
    simulation.run(3);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    assert_eq!(simulation.cycles(), [3]);
    let value = |path: &str| {
        runtime::value::read(simulation.engine(), path)
            .unwrap_or_else(|error| panic!("{path}: {error}"))
            .to_string()
    };
    for (path, want) in [
        ("x08_CheckingBools.vDone", "TRUE"),
        // The third cycle starts at 400 ms of simulated time.
        ("x08_CheckingBools.vStartTime", "LTIME#400ms"),
        // Within a cycle the simulated clock stands still.
        ("x08_CheckingBools.vTotalTime", "LTIME#0ns"),
        ("x08_CheckingBools.vTest3.ExecTime", "LTIME#0ns"),
        ("x08_CheckingBools.vTest3.Results[5]", "LTIME#0ns"),
        ("x08_CheckingBools.vTest3.AverageExecTime", "LTIME#0ns"),
        // Two loops of 11 increments in each of 6 runs, in each of 3 cycles.
        ("x08_CheckingBools.vCounter", "396"),
        ("x08_CheckingBools.vResult", "TRUE"),
    ] {
        assert_eq!(value(path), want, "{path}");
    }
}
