//! Online change between compiled programs (`docs/protocol.md` §7): the plan the runtime
//! makes for two builds of a project, and the engine that takes over with the values.

use program_image::{ProgramImage, Region};
use project_model::{Object, TaskKind, Variable};
use runtime::engine::{ChangeRefusal, DetailKind, Engine, OnlineChangePlan};
use runtime::value::Value;

fn compile(text: &str) -> ProgramImage {
    match compiler::compile_source(&compiler::SourceProject::new(text), "change.st") {
        Ok(image) => image,
        Err(error) => panic!("the program does not compile: {error:?}"),
    }
}

fn dint(engine: &Engine, path: &str) -> i128 {
    match runtime::value::read(engine, path) {
        Ok(Value::Int(value, _)) => value,
        other => panic!("{path}: {other:?}"),
    }
}

fn run(engine: &mut Engine, cycles: std::ops::Range<u64>) {
    for cycle in cycles {
        for task in 0..engine.image().tasks.len() {
            let now_ns = (cycle * 10_000_000) as i64;
            if let Err(fault) = engine.run_cycle(task, now_ns, cycle) {
                panic!("cycle {cycle}: {fault:?}");
            }
        }
    }
}

fn listed(plan: &OnlineChangePlan, kind: DetailKind) -> Vec<String> {
    plan.details()
        .iter()
        .filter(|detail| detail.kind == kind)
        .map(|detail| detail.name.to_ascii_lowercase())
        .collect()
}

const OLD: &str = "
FUNCTION_BLOCK counter
VAR_INPUT step : DINT; END_VAR
VAR_OUTPUT total : DINT; END_VAR
total := total + step;
END_FUNCTION_BLOCK

PROGRAM main
VAR
    c1 : counter;
    c2 : counter;
    p : POINTER TO DINT;
    first : BOOL := TRUE;
    seen : DINT;
    target : DINT;
    old_only : INT;
    kind : INT;
END_VAR
c1(step := 1);
c2(step := 2);
target := c2.total;
IF first THEN
    p := ADR(target);
    first := FALSE;
END_IF
seen := p^;
END_PROGRAM
";

/// The block gains a member before `total`, so every instance's `total` moves; the program
/// counts by ten, gains a variable, loses one and changes another's type.
const NEW: &str = "
FUNCTION_BLOCK counter
VAR_INPUT step : DINT; END_VAR
VAR_OUTPUT extra : DINT; total : DINT; END_VAR
total := total + step * 10;
extra := extra + 1;
END_FUNCTION_BLOCK

PROGRAM main
VAR
    c1 : counter;
    c2 : counter;
    p : POINTER TO DINT;
    first : BOOL := TRUE;
    seen : DINT;
    added : DINT := 7;
    target : DINT;
    kind : DINT := 5;
END_VAR
c1(step := 1);
c2(step := 2);
target := c2.total;
IF first THEN
    p := ADR(target);
    first := FALSE;
END_IF
seen := p^;
END_PROGRAM
";

/// Three POUs that use two globals; [`MOVED`] adds a global before them and edits the
/// function only.
const GLOBALS: &str = "
VAR_GLOBAL gCount : DINT; gLimit : DINT := 3; END_VAR
FUNCTION scale : DINT
VAR_INPUT x : DINT; END_VAR
scale := x * 2;
END_FUNCTION
FUNCTION_BLOCK adder
VAR_OUTPUT total : DINT; END_VAR
total := total + gLimit;
END_FUNCTION_BLOCK
PROGRAM main
VAR a : adder; n : DINT; END_VAR
a();
n := scale(gCount);
gCount := gCount + 1;
END_PROGRAM
";

const MOVED: &str = "
VAR_GLOBAL gFirst : LREAL; gCount : DINT; gLimit : DINT := 3; END_VAR
FUNCTION scale : DINT
VAR_INPUT x : DINT; END_VAR
scale := x * 3;
END_FUNCTION
FUNCTION_BLOCK adder
VAR_OUTPUT total : DINT; END_VAR
total := total + gLimit;
END_FUNCTION_BLOCK
PROGRAM main
VAR a : adder; n : DINT; END_VAR
a();
n := scale(gCount);
gCount := gCount + 1;
END_PROGRAM
";

#[test]
fn a_global_added_and_one_pou_edited_lists_only_that_pou_as_changed() {
    let (old, new) = (compile(GLOBALS), compile(MOVED));
    let code = |image: &ProgramImage, name: &str| {
        let pou = image
            .pous
            .iter()
            .find(|pou| pou.name.eq_ignore_ascii_case(name));
        pou.map(|pou| pou.code.clone()).unwrap_or_default()
    };
    // The globals moved, so the program's and the block's code were generated anew.
    for name in ["main", "adder"] {
        assert_ne!(code(&old, name), code(&new, name), "{name}");
    }
    let running = Engine::new(old.clone()).unwrap();
    let plan = OnlineChangePlan::new(&old, running.region(Region::Data), &new);
    assert_eq!(plan.refusal(), None);
    assert_eq!(listed(&plan, DetailKind::PouChanged), ["scale"]);
    assert_eq!(plan.summary().pous_changed, 1);
    let added = listed(&plan, DetailKind::VariableAdded);
    assert!(
        added.iter().any(|path| path.ends_with("gfirst")),
        "{added:?}"
    );

    // Without the debug sections the code decides: the POUs whose code only moved are listed,
    // and the function is not, because its new factor lives in the constant pool and its
    // instructions are the same.
    let (mut bare_old, mut bare_new) = (old, new);
    bare_old.debug = None;
    bare_new.debug = None;
    let plan = OnlineChangePlan::new(&bare_old, running.region(Region::Data), &bare_new);
    assert_eq!(listed(&plan, DetailKind::PouChanged), ["adder", "main"]);
}

#[test]
fn members_of_every_instance_keep_their_values_and_a_pointer_follows_its_target() {
    let (old, new) = (compile(OLD), compile(NEW));
    let mut running = Engine::new(old.clone()).unwrap();
    run(&mut running, 0..5);
    assert_eq!(dint(&running, "main.c2.total"), 10);

    let plan = OnlineChangePlan::new(&old, running.region(Region::Data), &new);
    assert_eq!(plan.refusal(), None);
    let added = listed(&plan, DetailKind::VariableAdded);
    for path in ["main.c1.extra", "main.c2.extra", "main.added"] {
        assert!(added.contains(&path.to_owned()), "{added:?}");
    }
    assert_eq!(
        listed(&plan, DetailKind::VariableRemoved),
        ["main.old_only"]
    );
    assert_eq!(
        listed(&plan, DetailKind::VariableReinitialised),
        ["main.kind"]
    );
    assert!(listed(&plan, DetailKind::PouChanged).contains(&"counter".to_owned()));
    assert_eq!(plan.summary().pointers_moved, 1);

    let mut next = Engine::new(new).unwrap();
    let applied = plan.apply(&mut running, &mut next);
    assert_eq!(applied.pointers_moved, 1);
    // Before the first new cycle: the values of the old one, the new ones' initial values.
    assert_eq!(dint(&next, "main.c1.total"), 5);
    assert_eq!(dint(&next, "main.added"), 7);
    assert_eq!(dint(&next, "main.kind"), 5);
    run(&mut next, 5..6);
    assert_eq!(dint(&next, "main.c1.total"), 15);
    assert_eq!(dint(&next, "main.c2.total"), 30);
    assert_eq!(dint(&next, "main.c1.extra"), 1);
    // The pointer set in the first old cycle reads the moved `target`, not what now lies at
    // its old address.
    assert_eq!(dint(&next, "main.seen"), 30);
}

fn example() -> project_model::Project {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../assets/examples/packaging_machine");
    match project_model::load_project(&dir) {
        Ok(loaded) => loaded.project,
        Err(error) => panic!("the example does not load: {error:?}"),
    }
}

fn compile_project(project: &project_model::Project) -> ProgramImage {
    match compiler::compile_project(project) {
        Ok(image) => image,
        Err(error) => panic!("{error}"),
    }
}

#[test]
fn the_example_changes_online_with_its_axes_and_a_changed_task_interval_is_refused() {
    let project = example();
    let old = compile_project(&project);
    let mut running = Engine::new(old.clone()).unwrap();
    run(&mut running, 0..20);

    let mut changed = project.clone();
    match changed.application.object_mut("FB_Conveyor") {
        Some(Object::Pou(pou)) => pou.variables.insert(0, Variable::new("nSpare", "DINT")),
        other => panic!("FB_Conveyor: {other:?}"),
    }
    match changed.application.object_mut("MotionControl") {
        Some(Object::Pou(pou)) => pou.variables.insert(0, Variable::new("nSpare", "DINT")),
        other => panic!("MotionControl: {other:?}"),
    }
    let new = compile_project(&changed);
    let plan = OnlineChangePlan::new(&old, running.region(Region::Data), &new);
    assert_eq!(plan.refusal(), None, "{:?}", plan.details());
    assert!(
        listed(&plan, DetailKind::VariableAdded).contains(&"main.fbconveyor.nspare".to_owned()),
        "{:?}",
        plan.details()
    );
    assert!(
        listed(&plan, DetailKind::VariableReinitialised).is_empty(),
        "{:?}",
        plan.details()
    );
    // The motion blocks the kernel keeps are found at their instances' new places.
    let instances = running.motion_instances();
    assert!(!instances.is_empty());
    assert!(instances.iter().all(|&at| plan.moved_byte(at).is_some()));
    assert!(
        instances.iter().any(|&at| plan.moved_byte(at) != Some(at)),
        "the added variable moves the instances after it"
    );
    let mut next = Engine::new(new).unwrap();
    let applied = plan.apply(&mut running, &mut next);
    assert_eq!(applied.motion_blocks_dropped, 0);
    assert_eq!(next.motion_instances().len(), instances.len());
    assert!(applied.carried > 0);
    run(&mut next, 20..25);

    let mut slower = project;
    slower.tasks[1].kind = TaskKind::Cyclic { interval_us: 1000 };
    let refused = OnlineChangePlan::new(&old, &[], &compile_project(&slower));
    assert_eq!(
        refused.refusal(),
        Some((
            ChangeRefusal::Tasks,
            "task 'MotionTask': interval changed from 2 ms to 1 ms"
        ))
    );
}
