//! PLCopen XML files of the shared corpora imported (data types, POUs in every language, global
//! variable lists, tasks) and checked by the compiler; the counters of Beremiz's `first_steps`
//! and CODESYS's functions run in the engine.

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

/// `project` compiled and loaded into a simulation; a project that does not check panics with
/// its errors as `file: message`. The tests write between their runs, so the image is first
/// run for 20 cycles without writes under both engines and compared (`crate::simulate`), and the
/// simulation given back is a fresh one with the default engine.
#[track_caller]
fn simulation_of(project: &project_model::Project) -> runtime::simulation::Simulation {
    let image = match compiler::compile_project(project) {
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
    crate::simulate(image.clone(), 20);
    runtime::simulation::Simulation::new(image).unwrap_or_else(|error| panic!("{error}"))
}

/// Adds the POUs of the ST `source` to `project`: a test's own `Main` that calls what was
/// imported.
fn add_st(project: &mut project_model::Project, source: &str) {
    let built = compiler::SourceProject::new(source).project;
    project
        .application
        .children
        .extend(built.application.children);
}

/// The value at `path` in `simulation`, as text.
#[track_caller]
fn value_of(simulation: &runtime::simulation::Simulation, path: &str) -> String {
    runtime::value::read(simulation.engine(), path)
        .unwrap_or_else(|error| panic!("{path}: {error}"))
        .to_string()
}

/// The Beremiz and matiec POUs that do not check, each for a reason outside the import: the
/// file, the POU and why.
const BEREMIZ_AND_MATIEC_POUS_NOT_CHECKING: [(&str, &str, &str); 4] = [
    (
        "iec61131_lang_test",
        "main_test",
        "LOGGER, a block of Beremiz's own runtime library",
    ),
    (
        "svghmi_basic",
        "main_program",
        "SVGHMI's HMI_BOOL types and python_eval, Beremiz extensions",
    ),
    (
        "STD_TEST",
        "TEST_FROM_STRINGS",
        "matiec's test feeds LEN's INT and EQ's BOOL into one MUX, whose inputs have one type",
    ),
    (
        "STD_TEST",
        "MAIN_TEST",
        "matiec's test gives a STRING a real literal as initial value",
    ),
];

#[test]
fn beremiz_and_matiec_files_check_but_for_parts_of_their_own_libraries() {
    // Each file with the objects it gives: every POU, in every language, is imported.
    for (file, objects) in [
        ("plcopen/beremiz/exemples/first_steps/plc.xml", 8),
        (
            "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
            3,
        ),
        ("plcopen/beremiz/tests/projects/svghmi_basic/plc.xml", 2),
        ("matiec/tests/LD_TEST.xml", 1),
        ("matiec/tests/SFC_TEST.xml", 1),
        ("matiec/tests/STD_TEST.xml", 6),
    ] {
        let (imported, errors) = import_errors(file);
        assert_eq!(imported, objects, "{file}");
        let pinned: Vec<&str> = BEREMIZ_AND_MATIEC_POUS_NOT_CHECKING
            .iter()
            .filter(|(pinned_file, _, _)| file.contains(pinned_file))
            .map(|(_, pou, _)| *pou)
            .collect();
        let failing_pou = |error: &String| {
            let file = error.strip_prefix("application/").unwrap_or(error.as_str());
            file.split('.').next().unwrap_or(file).to_owned()
        };
        let unexplained: Vec<&String> = errors
            .iter()
            .filter(|error| !pinned.contains(&failing_pou(error).as_str()))
            .collect();
        assert!(unexplained.is_empty(), "{file}: {unexplained:#?}");
        // Every POU pinned still fails, so the list does not outlive its reasons.
        for pou in pinned {
            assert!(
                errors.iter().any(|error| failing_pou(error) == pou),
                "{file}: {pou} checks now: unpin it"
            );
        }
    }
}

/// Beremiz's counters in ST, LD, FBD and IL, run side by side from an ST program that resets them
/// in cycle `reset_cycle`, after `cycles` cycles: each counter's output.
fn first_steps_counters(cycles: u64, reset_cycle: u32) -> [String; 4] {
    let document = plcopen::read_file(&corpus("plcopen/beremiz/exemples/first_steps/plc.xml"))
        .unwrap_or_else(|error| panic!("{error}"));
    let mut project = plcopen::import(&document)
        .unwrap_or_else(|error| panic!("{error}"))
        .project;
    // Main runs the counters instead of plc_prg.
    project.application.children.retain(
        |node| !matches!(node, project_model::Node::Object(object) if object.name() == "plc_prg"),
    );
    project.tasks.clear();
    add_st(
        &mut project,
        &format!(
            "PROGRAM Main
VAR st : CounterST; ld : CounterLD; fbd : CounterFBD; il : CounterIL; i : INT; END_VAR
i := i + 1;
st(Reset := i = {reset_cycle});
ld(Reset := i = {reset_cycle});
fbd(Reset := i = {reset_cycle});
il(Reset := i = {reset_cycle});
END_PROGRAM
"
        ),
    );
    let mut simulation = simulation_of(&project);
    simulation.run(cycles);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    ["Main.st.OUT", "Main.ld.Out", "Main.fbd.OUT", "Main.il.OUT"].map(|path| {
        runtime::value::read(simulation.engine(), path)
            .unwrap_or_else(|error| panic!("{path}: {error}"))
            .to_string()
    })
}

#[test]
fn first_steps_counters_in_ld_fbd_and_il_count_like_the_st_one() {
    // Counting one per cycle from 0.
    assert_eq!(first_steps_counters(4, 100), ["4", "4", "4", "4"]);
    // The reset in cycle 5 loads ResetCounterValue (17), then counting goes on.
    assert_eq!(first_steps_counters(5, 5), ["17", "17", "17", "17"]);
    assert_eq!(first_steps_counters(8, 5), ["20", "20", "20", "20"]);
}

/// The CODESYS POUs that do not check, each for a reason outside the import: the file name of the
/// POU (an action's file starts with it) and why.
const CODESYS_POUS_NOT_CHECKING: [(&str, &str); 2] = [
    // SysMemCpy, SysMemSet and SysMemCmp come from CODESYS's SysMem library.
    ("x05_SysMemLib", "the SysMem library; ADR of a constant"),
    (
        "x06_Combine2xByteToUint.Measure",
        "SysMemCpy of the SysMem library",
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
    let mut simulation = simulation_of(&project);
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

#[test]
fn codesys_functions_drawn_in_ld_and_fbd_add_like_the_st_one() {
    let document = plcopen::read_file(&corpus(
        "plcopen/codesys/codesys_code_execution_speedTests.xml",
    ))
    .unwrap_or_else(|error| panic!("{error}"));
    let mut project = plcopen::import(&document)
        .unwrap_or_else(|error| panic!("{error}"))
        .project;
    // Only the three functions, called from an ST program: the rest of the file needs CODESYS
    // libraries.
    project.application.children.retain(|node| {
        matches!(node, project_model::Node::Object(object)
            if ["addTwoIntsLadder", "addTwoIntsFBD", "addTwoIntsST"].contains(&object.name()))
    });
    assert_eq!(project.application.children.len(), 3);
    project.tasks.clear();
    add_st(
        &mut project,
        "PROGRAM Main
VAR ld, fbd, st : INT; END_VAR
ld := addTwoIntsLadder(Int1 := 30, Int2 := 12);
fbd := addTwoIntsFBD(int1 := 30, int2 := 12);
st := addTwoIntsST(int1 := 30, int2 := 12);
END_PROGRAM
",
    );
    let mut simulation = simulation_of(&project);
    simulation.run(1);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    let values = ["Main.ld", "Main.fbd", "Main.st"].map(|path| {
        runtime::value::read(simulation.engine(), path)
            .unwrap_or_else(|error| panic!("{path}: {error}"))
            .to_string()
    });
    assert_eq!(values, ["42", "42", "42"]);
}

/// A function block `Bridge` in LD: contacts a and b from the rail, c after a, d after b, and e
/// from a's output into d's input (a bridge), driving X; and Y set by a, reset by b.
const BRIDGE: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="Bridge" pouType="functionBlock">
    <interface>
      <inputVars><variable name="a"><type><BOOL/></type></variable><variable name="b"><type><BOOL/></type></variable><variable name="c"><type><BOOL/></type></variable><variable name="d"><type><BOOL/></type></variable><variable name="e"><type><BOOL/></type></variable></inputVars>
      <outputVars><variable name="X"><type><BOOL/></type></variable><variable name="Y"><type><BOOL/></type></variable></outputVars>
    </interface>
    <body><LD>
      <leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
      <contact localId="2"><position x="20" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact>
      <contact localId="3"><position x="20" y="40"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact>
      <contact localId="4"><position x="40" y="20"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>e</variable></contact>
      <contact localId="5"><position x="60" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>c</variable></contact>
      <contact localId="6"><position x="60" y="40"/><connectionPointIn><connection refLocalId="3"/><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><variable>d</variable></contact>
      <coil localId="7"><position x="100" y="0"/><connectionPointIn><connection refLocalId="5"/><connection refLocalId="6"/></connectionPointIn><connectionPointOut/><variable>X</variable></coil>
      <leftPowerRail localId="8"><position x="0" y="100"/><connectionPointOut formalParameter=""/></leftPowerRail>
      <contact localId="9"><position x="20" y="100"/><connectionPointIn><connection refLocalId="8"/></connectionPointIn><connectionPointOut/><variable>a</variable></contact>
      <coil localId="10" storage="set"><position x="100" y="100"/><connectionPointIn><connection refLocalId="9"/></connectionPointIn><connectionPointOut/><variable>Y</variable></coil>
      <contact localId="11"><position x="20" y="140"/><connectionPointIn><connection refLocalId="8"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact>
      <coil localId="12" storage="reset"><position x="100" y="140"/><connectionPointIn><connection refLocalId="11"/></connectionPointIn><connectionPointOut/><variable>Y</variable></coil>
    </LD></body>
  </pou></pous></types>
  <instances><configurations/></instances>
</project>
"#;

#[test]
fn an_imported_ld_bridge_and_set_reset_coils_run_as_their_logic_says() {
    let document = plcopen::read(BRIDGE, "bridge.xml").unwrap_or_else(|error| panic!("{error}"));
    let mut project = plcopen::import(&document)
        .unwrap_or_else(|error| panic!("{error}"))
        .project;
    // Every combination of the five inputs, one per cycle; Y follows a set and b reset, the
    // reset written after the set.
    add_st(
        &mut project,
        "PROGRAM Main
VAR fb : Bridge; i : INT; mismatches : INT; a, b, c, d, e, y : BOOL; END_VAR
IF i < 32 THEN
  a := (i MOD 2) = 1; b := ((i / 2) MOD 2) = 1; c := ((i / 4) MOD 2) = 1;
  d := ((i / 8) MOD 2) = 1; e := ((i / 16) MOD 2) = 1;
  fb(a := a, b := b, c := c, d := d, e := e);
  IF a THEN y := TRUE; END_IF;
  IF b THEN y := FALSE; END_IF;
  IF fb.X <> ((a AND c) OR (a AND e AND d) OR (b AND d)) OR fb.Y <> y THEN
    mismatches := mismatches + 1;
  END_IF;
  i := i + 1;
END_IF;
END_PROGRAM
",
    );
    let mut simulation = simulation_of(&project);
    simulation.run(40);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    let read = |path: &str| value_of(&simulation, path);
    assert_eq!(
        (read("Main.i"), read("Main.mismatches")),
        ("32".to_owned(), "0".to_owned())
    );
}

/// A Beremiz-style FBD body (no Rivet entries): the INT variable `x` read by the first input of
/// two `ADD` boxes, the upper one writing `x` back.
const TWO_ADDS_READING_ONE_VARIABLE: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="TwoAdds" pouType="functionBlock">
    <interface>
      <outputVars><variable name="x"><type><INT/></type></variable><variable name="y"><type><INT/></type></variable></outputVars>
    </interface>
    <body><FBD>
      <inVariable localId="1" height="30" width="20"><position x="20" y="20"/><connectionPointOut/><expression>x</expression></inVariable>
      <inVariable localId="2" height="30" width="20"><position x="20" y="60"/><connectionPointOut/><expression>1</expression></inVariable>
      <block localId="3" typeName="ADD" height="60" width="60"><position x="100" y="20"/>
        <inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="2"/></connectionPointIn></variable>
        </inputVariables>
        <inOutVariables/>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
      </block>
      <outVariable localId="4" height="30" width="20"><position x="200" y="20"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>x</expression></outVariable>
      <inVariable localId="5" height="30" width="20"><position x="20" y="160"/><connectionPointOut/><expression>10</expression></inVariable>
      <block localId="6" typeName="ADD" height="60" width="60"><position x="100" y="120"/>
        <inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
          <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="5"/></connectionPointIn></variable>
        </inputVariables>
        <inOutVariables/>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
      </block>
      <outVariable localId="7" height="30" width="20"><position x="200" y="120"/><connectionPointIn><connection refLocalId="6" formalParameter="OUT"/></connectionPointIn><expression>y</expression></outVariable>
    </FBD></body>
  </pou></pous></types>
  <instances><configurations/></instances>
</project>
"#;

#[test]
fn another_tools_variable_read_by_two_boxes_is_read_again_by_each_after_the_earlier_writes() {
    let document = plcopen::read(TWO_ADDS_READING_ONE_VARIABLE, "two_adds.xml")
        .unwrap_or_else(|error| panic!("{error}"));
    let mut project = plcopen::import(&document)
        .unwrap_or_else(|error| panic!("{error}"))
        .project;
    add_st(
        &mut project,
        "PROGRAM Main
VAR adds : TwoAdds; END_VAR
adds();
END_PROGRAM
",
    );
    // An INT is no power: a rung holding x with two branches after it would not check.
    let mut simulation = simulation_of(&project);
    simulation.run(3);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    let read = |path: &str| value_of(&simulation, path);
    // The lower box runs after the upper one wrote x, and reads x again: 3 + 10.
    assert_eq!(
        (read("Main.adds.x"), read("Main.adds.y")),
        ("3".to_owned(), "13".to_owned())
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
    // The imported objects but plc_prg: Main runs the counters instead.
    for object in imported.project.application.objects() {
        if object.name() != "plc_prg" {
            project
                .application
                .children
                .push(project_model::Node::Object(object.clone()));
        }
    }
    let mut simulation = simulation_of(&project);
    let mut seen = Vec::new();
    for _ in 0..10 {
        simulation.run(1);
        assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
        let read = |path: &str| value_of(&simulation, path);
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
    let mut simulation = simulation_of(&project);
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
    let mut simulation = simulation_of(&project);
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

/// A function block `Seq` in SFC as Beremiz draws it: step `A` leaves for `B` on a condition
/// wired from an LD rung (contact `go`, coil `seen`, contact `enable`; the coil passes its power
/// on and, as in Beremiz's generator, writes nothing), and `B`, whose inline LD action copies
/// `go` into `held`, goes back to `A` on `NOT go`.
const LD_IN_SFC: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="c" productName="p" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="Seq" pouType="functionBlock">
    <interface>
      <inputVars><variable name="go"><type><BOOL/></type></variable><variable name="enable"><type><BOOL/></type></variable></inputVars>
      <outputVars><variable name="seen"><type><BOOL/></type></variable><variable name="held"><type><BOOL/></type></variable></outputVars>
    </interface>
    <body><SFC>
      <step localId="1" name="A" initialStep="true"><position x="100" y="10"/><connectionPointOut/></step>
      <leftPowerRail localId="10"><position x="10" y="60"/><connectionPointOut formalParameter=""/></leftPowerRail>
      <contact localId="11"><position x="30" y="60"/><connectionPointIn><connection refLocalId="10"/></connectionPointIn><connectionPointOut/><variable>go</variable></contact>
      <coil localId="12"><position x="60" y="60"/><connectionPointIn><connection refLocalId="11"/></connectionPointIn><connectionPointOut/><variable>seen</variable></coil>
      <contact localId="13"><position x="80" y="60"/><connectionPointIn><connection refLocalId="12"/></connectionPointIn><connectionPointOut/><variable>enable</variable></contact>
      <transition localId="2"><position x="100" y="60"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><condition><connectionPointIn><connection refLocalId="13"/></connectionPointIn></condition></transition>
      <step localId="4" name="B"><position x="100" y="110"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><connectionPointOutAction/></step>
      <actionBlock localId="7"><position x="150" y="110"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn>
        <action localId="0" qualifier="N"><inline><LD>
          <leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>
          <contact localId="2"><position x="20" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>go</variable></contact>
          <coil localId="3"><position x="60" y="0"/><connectionPointIn><connection refLocalId="2"/></connectionPointIn><connectionPointOut/><variable>held</variable></coil>
        </LD></inline></action>
      </actionBlock>
      <transition localId="5"><position x="100" y="160"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><connectionPointOut/><condition><inline name=""><ST><xhtml:p><![CDATA[NOT go]]></xhtml:p></ST></inline></condition></transition>
      <jumpStep localId="6" targetName="A"><position x="100" y="210"/><connectionPointIn><connection refLocalId="5"/></connectionPointIn></jumpStep>
    </SFC></body>
  </pou></pous></types>
  <instances><configurations/></instances>
</project>
"#;

/// The chart of [`LD_IN_SFC`], imported, runs: its wired LD condition became the expression
/// of its contacts, its inline LD action an action, and both behave as Beremiz runs them.
#[test]
fn an_imported_sfc_with_an_ld_condition_and_an_inline_ld_action_runs_as_drawn() {
    let document =
        plcopen::read(LD_IN_SFC, "ld_in_sfc.xml").unwrap_or_else(|error| panic!("{error}"));
    let imported = plcopen::import(&document).unwrap_or_else(|error| panic!("{error}"));
    let not_converted: Vec<_> = imported
        .report
        .with_outcome(plcopen::Outcome::NotConverted)
        .collect();
    assert!(not_converted.is_empty(), "{not_converted:#?}");
    let mut project = imported.project;
    add_st(
        &mut project,
        "PROGRAM Main
VAR fb : Seq; cycle : INT; END_VAR
cycle := cycle + 1;
fb(go := cycle >= 3 AND cycle <= 8, enable := cycle >= 5);
END_PROGRAM
",
    );
    let mut simulation = simulation_of(&project);
    let mut seen = Vec::new();
    for _ in 0..12 {
        simulation.run(1);
        assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
        let read = |path: &str| value_of(&simulation, path);
        let step = if read("Main.fb.A.x") == "TRUE" {
            "A"
        } else {
            "B"
        };
        seen.push(format!(
            "{step} {} {}",
            read("Main.fb.seen"),
            read("Main.fb.held")
        ));
    }
    // `seen` is never written (Beremiz writes no coil of a condition); the condition holds
    // from cycle 5 (go and enable), so `B` is active from cycle 6, its action copies `go` into
    // `held` (one last run when `go` falls at cycle 9), and `NOT go` brings the chart back to
    // `A`.
    let expected = [
        "A FALSE FALSE",
        "A FALSE FALSE",
        "A FALSE FALSE",
        "A FALSE FALSE",
        "A FALSE FALSE",
        "B FALSE TRUE",
        "B FALSE TRUE",
        "B FALSE TRUE",
        "B FALSE FALSE",
        "A FALSE FALSE",
        "A FALSE FALSE",
        "A FALSE FALSE",
    ];
    assert_eq!(seen, expected);
}

/// A function block `Counter` in CODESYS's CFC counting as Beremiz draws a counter: `ADD(a, 1)` into
/// an in-out `a`, whose output `b` reads.
const IN_OUT_CFC: &str = r#"<?xml version="1.0" encoding="UTF-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0200" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="c" productName="CODESYS" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="n"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous><pou name="Counter" pouType="functionBlock">
    <interface><localVars><variable name="a"><type><INT/></type></variable><variable name="b"><type><INT/></type></variable></localVars></interface>
    <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml"/></ST><addData><data name="http://www.3s-software.com/plcopenxml/cfc" handleUnknown="implementation"><CFC>
      <inVariable localId="1"><position x="1" y="2"/><connectionPointOut/><expression>1</expression></inVariable>
      <block localId="3" typeName="ADD" executionOrderId="1"><position x="6" y="1"/>
        <inputVariables>
          <variable formalParameter="IN1"><connectionPointIn><connection refLocalId="4"/></connectionPointIn></variable>
          <variable formalParameter="IN2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable>
        </inputVariables><inOutVariables/>
        <outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables>
      </block>
      <inOutVariable localId="4" executionOrderId="2"><position x="12" y="1"/><connectionPointIn><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><connectionPointOut/><expression>a</expression></inOutVariable>
      <outVariable localId="5" executionOrderId="3"><position x="20" y="1"/><connectionPointIn><connection refLocalId="4"/></connectionPointIn><expression>b</expression></outVariable>
    </CFC></data></addData></body>
  </pou></pous></types>
  <instances><configurations/></instances>
</project>
"#;

/// The in-out of [`IN_OUT_CFC`], imported as an output and an input of `a`, counts: `ADD`
/// reads the previous cycle's `a`, and `b` the new one.
#[test]
fn an_imported_cfc_in_out_variable_counts_and_is_read_after_its_write() {
    let document =
        plcopen::read(IN_OUT_CFC, "in_out.xml").unwrap_or_else(|error| panic!("{error}"));
    let mut project = plcopen::import(&document)
        .unwrap_or_else(|error| panic!("{error}"))
        .project;
    add_st(
        &mut project,
        "PROGRAM Main
VAR counter : Counter; END_VAR
counter();
END_PROGRAM
",
    );
    let mut simulation = simulation_of(&project);
    simulation.run(5);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    let values = ["Main.counter.a", "Main.counter.b"].map(|path| value_of(&simulation, path));
    assert_eq!(values, ["5", "5"]);
}
