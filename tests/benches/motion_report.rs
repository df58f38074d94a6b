//! What motion adds to a task cycle, as figures for a note:
//! `cargo bench -p tests --bench motion_report`.
//!
//! Builds the example machine with eight more modulo axes, each coupled to the virtual master
//! through `CAM_Knife` (MC_Power, MC_CamTableSelect, MC_CamIn and two SMC_GetTappetValue per
//! slave), runs its `MotionTask` on a simulated 2 ms clock, and prints the median cycle time
//! beside the same program with only the master moving. The difference is what eight camming
//! axes with tappets cost per cycle (issue 7: under 10 µs).
//! It measures the default engine (`EngineChoice::default`: native on x86-64 and aarch64); the
//! motion kernel itself is the same Rust code under both engines.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use project_model::{Axis, Body, Node, Object, Project, VarSection, Variable};
use runtime::engine::Engine;

/// How many camming slaves the loaded program has.
const SLAVES: usize = 8;
/// The task cycle, as the example's MotionTask.
const CYCLE_NS: i64 = 2_000_000;

/// The example project whose MotionControl moves the master and, with `slaves`, couples that
/// many more axes to it.
fn project(slaves: usize) -> Project {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let mut project = project_model::load_project(&dir).unwrap().project;
    let knife = project
        .axes
        .iter()
        .find(|a| a.name == "Knife")
        .unwrap()
        .clone();
    let mut variables = vec![
        var("fbPowerMaster", "MC_Power"),
        var("fbMaster", "MC_MoveVelocity"),
    ];
    let mut body = String::from(
        "fbPowerMaster(Axis := Master, Enable := TRUE);
fbMaster(Axis := Master, Execute := fbPowerMaster.Status, Velocity := 360.0,
    Acceleration := 3600.0, Deceleration := 3600.0, Direction := MC_DIRECTION.positive);
",
    );
    for index in 1..=slaves {
        project.axes.push(Axis {
            name: format!("Slave{index}"),
            ..knife.clone()
        });
        for (name, ty) in [
            ("fbPower", "MC_Power"),
            ("fbSelect", "MC_CamTableSelect"),
            ("fbCam", "MC_CamIn"),
            ("fbGlue", "SMC_GetTappetValue"),
            ("fbRelease", "SMC_GetTappetValue"),
        ] {
            variables.push(var(&format!("{name}{index}"), ty));
        }
        variables.push(var(&format!("xGlue{index}"), "BOOL"));
        body.push_str(&format!(
            "fbPower{index}(Axis := Slave{index}, Enable := TRUE);
fbSelect{index}(Master := Master, Slave := Slave{index}, CamTable := CAM_Knife,
    Execute := fbPower{index}.Status, Periodic := TRUE, MasterAbsolute := TRUE);
fbCam{index}(Master := Master, Slave := Slave{index}, Execute := fbSelect{index}.Done,
    CamTableID := fbSelect{index}.CamTableID);
fbGlue{index}(Tappets := fbCam{index}.Tappets, iID := 1);
fbRelease{index}(Tappets := fbCam{index}.Tappets, iID := 2);
xGlue{index} := fbGlue{index}.bTappet OR fbRelease{index}.bTappet;
"
        ));
    }
    for node in &mut project.application.children {
        if let Node::Object(Object::Pou(pou)) = node
            && pou.name == "MotionControl"
        {
            pou.variables = variables.clone();
            pou.body = Body::st(body.clone());
        }
    }
    project
}

fn var(name: &str, ty: &str) -> Variable {
    Variable {
        section: VarSection::Var,
        ..Variable::new(name, ty)
    }
}

/// The median time of one MotionTask cycle of `project` in nanoseconds, after a second of
/// cycles so every coupling runs.
fn cycle_ns(project: &Project) -> f64 {
    let image = compiler::compile_project(project).unwrap();
    let task = image
        .tasks
        .iter()
        .position(|task| task.name == "MotionTask")
        .unwrap();
    let mut engine = Engine::new(image).unwrap();
    let mut now_ns = 0i64;
    let mut cycle = 0u64;
    let mut step = || {
        now_ns += CYCLE_NS;
        cycle += 1;
        black_box(engine.run_cycle(task, now_ns, cycle)).unwrap();
    };
    for _ in 0..500 {
        step();
    }
    let mut batches: Vec<f64> = (0..15)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..2000 {
                step();
            }
            start.elapsed().as_nanos() as f64 / 2000.0
        })
        .collect();
    batches.sort_by(f64::total_cmp);
    batches[batches.len() / 2]
}

fn main() {
    let master_only = cycle_ns(&project(0));
    let camming = cycle_ns(&project(SLAVES));
    println!("MotionTask cycle, median of 15 batches of 2000 cycles:");
    println!(
        "  master only:                          {:8.2} µs",
        master_only / 1e3
    );
    println!(
        "  master + {SLAVES} camming slaves with tappets: {:8.2} µs",
        camming / 1e3
    );
    println!(
        "  added by {SLAVES} camming axes:              {:8.2} µs",
        (camming - master_only) / 1e3
    );
}
