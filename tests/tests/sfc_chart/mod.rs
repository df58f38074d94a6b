//! SFC charts drawn in the graphical model, lowered into textual SFC, compiled and run cycle
//! after cycle: branches, jumps and transition objects behave as the same chart written as
//! text does (`docs/graphical-semantics.md`, "SFC charts").

use project_model::{
    ActionAssociation, ActionQualifier, Body, ElementId, Object, PouAction, SfcBranches, SfcChart,
    SfcNode, Step, Transition,
};
use runtime::simulation::Simulation;

fn step(id: u32, name: &str, actions: &[&str]) -> SfcNode {
    SfcNode::Step(Step {
        id: ElementId(id),
        name: name.into(),
        actions: actions
            .iter()
            .map(|action| ActionAssociation {
                action: (*action).into(),
                qualifier: ActionQualifier::N,
                duration: None,
                indicator: None,
            })
            .collect(),
        ..Step::default()
    })
}

fn transition(id: u32, condition: &str) -> SfcNode {
    SfcNode::transition(ElementId(id), condition)
}

fn branches(id: u32, branches: Vec<Vec<SfcNode>>) -> SfcBranches {
    SfcBranches::new(ElementId(id), branches)
}

fn jump(id: u32, target: &str) -> SfcNode {
    SfcNode::jump(ElementId(id), target)
}

/// Compiles the program `Main` of `source` with the chart `sequence` as its body and the
/// transition objects `transitions`, and runs it for `cycles` cycles.
fn simulate_chart(
    source: &str,
    sequence: Vec<SfcNode>,
    transitions: Vec<PouAction>,
    cycles: u64,
) -> Simulation {
    let built = compiler::SourceProject::new(source);
    assert!(
        built.parse.errors().is_empty(),
        "{:?}",
        built.parse.errors()
    );
    let mut project = built.project;
    let Some(Object::Pou(main)) = project.application.object_mut("Main") else {
        panic!("no Main");
    };
    main.transitions = transitions;
    main.body = Body::Sfc {
        chart: SfcChart { sequence },
    };
    let image = match compiler::compile_project(&project) {
        Ok(image) => image,
        Err(compiler::CompileError::Diagnostics(found)) => {
            let errors: Vec<String> = found
                .iter()
                .filter(|d| d.diagnostic.severity == compiler::Severity::Error)
                .map(|d| format!("{:?}: {}", d.element, d.diagnostic.message))
                .collect();
            panic!("the chart does not check: {errors:#?}")
        }
        Err(error) => panic!("the chart does not compile: {error}"),
    };
    let simulation = crate::simulate(image, cycles);
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    simulation
}

/// `Main` counts its cycles in `Init` (`n`) and in `Left` (`m`): from `Init` an alternative
/// goes on once `n >= 3` (or back to `Init` on `stop`) into a parallel branch `Left` and
/// `Right`, which the transition object `Ready` (`m >= 2`) closes, jumping back to `Init`.
/// The boolean actions `lamp`, `inLeft` and `inRight` show which steps acted in a cycle.
fn simulate(cycles: u64) -> Simulation {
    let source = "PROGRAM Main
VAR n, m : INT; stop, lamp, inLeft, inRight : BOOL; END_VAR
ACTION Count: n := n + 1; END_ACTION
ACTION Tick: m := m + 1; END_ACTION
END_PROGRAM
";
    let ready = PouAction {
        name: "Ready".into(),
        body: Body::st("m >= 2"),
    };
    let sequence = vec![
        step(1, "Init", &["Count", "lamp"]),
        SfcNode::Alternative(branches(
            2,
            vec![
                vec![transition(3, "n >= 3 AND NOT stop")],
                vec![transition(4, "stop"), jump(5, "Init")],
            ],
        )),
        SfcNode::Parallel(branches(
            6,
            vec![
                vec![step(7, "Left", &["Tick", "inLeft"])],
                vec![step(8, "Right", &["inRight"])],
            ],
        )),
        transition(9, "Ready"),
        jump(10, "Init"),
    ];
    simulate_chart(source, sequence, vec![ready], cycles)
}

#[track_caller]
fn check(simulation: &Simulation, expected: &[(&str, &str)]) {
    for (path, want) in expected {
        let value = runtime::value::read(simulation.engine(), path)
            .unwrap_or_else(|e| panic!("{path}: {e}"))
            .to_string();
        assert_eq!(value, *want, "{path}");
    }
}

/// The steps that acted in the last of `cycles` cycles, by their boolean actions (which hold
/// the same values whether a step's `x` shows the last cycle or the next one).
#[track_caller]
fn acting(cycles: u64, lamp: &str, left: &str, right: &str) {
    check(
        &simulate(cycles),
        &[
            ("Main.lamp", lamp),
            ("Main.inLeft", left),
            ("Main.inRight", right),
        ],
    );
}

#[test]
fn an_alternative_and_a_parallel_branch_run_as_drawn() {
    // Cycles 1 to 3 in Init: n reaches 3, so the alternative's left branch fires in cycle 3.
    acting(3, "TRUE", "FALSE", "FALSE");
    // Cycles 4 and 5 in both branches of the parallel branch; Tick counts m to 2 in cycle 5,
    // when the transition object Ready closes the branch back to Init.
    acting(4, "FALSE", "TRUE", "TRUE");
    check(&simulate(4), &[("Main.__Ready__result", "FALSE")]);
    acting(5, "FALSE", "TRUE", "TRUE");
    check(&simulate(5), &[("Main.__Ready__result", "TRUE")]);
    // Cycle 6 in Init, which leaves at once (n >= 3 still), so cycle 7 is in the branches.
    acting(6, "TRUE", "FALSE", "FALSE");
    acting(7, "FALSE", "TRUE", "TRUE");
}

#[test]
fn a_macro_step_runs_its_steps_and_a_jump_to_it_enters_its_first_step() {
    let source = "PROGRAM Main
VAR n : INT; inA, inB : BOOL; END_VAR
ACTION Count: n := n + 1; END_ACTION
END_PROGRAM
";
    let sequence = vec![
        step(1, "Init", &["Count"]),
        transition(2, "n >= 1"),
        SfcNode::Macro(project_model::MacroStep {
            id: ElementId(3),
            name: "Work".into(),
            body: vec![
                step(4, "A", &["inA"]),
                transition(5, "TRUE"),
                step(6, "B", &["inB"]),
            ],
            ..project_model::MacroStep::default()
        }),
        transition(7, "TRUE"),
        jump(8, "Work"),
    ];
    // Cycle 1 in Init, 2 in A, 3 in B, then the jump to Work enters A again in cycle 4.
    let run = |cycles| simulate_chart(source, sequence.clone(), Vec::new(), cycles);
    check(&run(2), &[("Main.inA", "TRUE"), ("Main.inB", "FALSE")]);
    check(&run(3), &[("Main.inA", "FALSE"), ("Main.inB", "TRUE")]);
    check(&run(4), &[("Main.inA", "TRUE"), ("Main.inB", "FALSE")]);
}

#[test]
fn step_properties_timed_associations_and_priorities_of_a_drawn_chart_run() {
    let source = "PROGRAM Main
VAR n, entered, leftFill : INT; lamp, hornOn : BOOL; tMax : TIME := T#1s; END_VAR
ACTION Count: n := n + 1; END_ACTION
ACTION Enter: entered := entered + 1; END_ACTION
ACTION Leave: leftFill := leftFill + 1; END_ACTION
ACTION Horn: hornOn := TRUE; END_ACTION
END_PROGRAM
";
    let fill = SfcNode::Step(Step {
        id: ElementId(3),
        name: "Fill".into(),
        min_time: Some("T#20ms".into()),
        max_time: Some("tMax".into()),
        entry_action: Some("Enter".into()),
        exit_action: Some("Leave".into()),
        actions: vec![ActionAssociation {
            action: "Horn".into(),
            qualifier: ActionQualifier::L,
            duration: Some("T#20ms".into()),
            indicator: Some("lamp".into()),
        }],
        ..Step::default()
    });
    let prioritised = |id: u32, condition: &str, priority: Option<u32>| {
        SfcNode::Transition(Transition {
            id: ElementId(id),
            condition: condition.into(),
            priority,
            ..Transition::default()
        })
    };
    let sequence = vec![
        step(1, "Init", &["Count"]),
        transition(2, "n >= 1"),
        fill,
        SfcNode::Alternative(branches(
            4,
            vec![
                vec![prioritised(5, "TRUE", None), jump(6, "Init")],
                vec![prioritised(7, "TRUE", Some(1)), jump(8, "Init")],
            ],
        )),
    ];
    let s = simulate_chart(source, sequence.clone(), Vec::new(), 3);
    check(
        &s,
        &[
            ("Main.entered", "1"),
            ("Main.lamp", "TRUE"),
            ("Main.hornOn", "TRUE"),
        ],
    );
    // Fill's time counts from the cycle its transition fired in (docs/sfc-semantics.md), so
    // its minimum of 20 ms has elapsed in its second active cycle (the third cycle), the
    // prioritised transition leaves it, and the exit action runs in the fourth; the next round
    // takes four cycles again.
    let s = simulate_chart(source, sequence.clone(), Vec::new(), 4);
    check(&s, &[("Main.leftFill", "1")]);
    let s = simulate_chart(source, sequence, Vec::new(), 8);
    check(&s, &[("Main.leftFill", "2")]);
}
