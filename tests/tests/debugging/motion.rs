//! Axes while a task is halted (`docs/debugging.md` §2.2): the halted task's axes stand still
//! and the first advance after the halt covers one cycle, not the halt's length; the axis of
//! another task, whose cycles run from inside the halt as the scheduler runs them, keeps its
//! timing. The clock is simulated, except during the halt, which the engine measures on the
//! real clock: the test's clock jumps by the time the halt took, as the scheduler's would.

use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use program_image::{ProgramImage, Region};
use project_model::{Body, Node, Object, Project, VarSection, Variable};
use runtime::engine::{
    BreakpointSpec, Engine, EngineView, HitMode, Preempt, Preemption, TaskClock,
};

/// MotionTask's interval, as the example's.
const MOTION_NS: i64 = 2_000_000;
/// MainTask's interval, as the example's.
const MAIN_NS: i64 = 10_000_000;
/// Both axes' velocity in degrees per second.
const VELOCITY: f64 = 360.0;
/// The MotionTask cycle (counted from 1) that halts, long after both axes reached speed.
const HALTING_CYCLE: u32 = 250;
/// How long the halt lasts on the real clock, at least.
const HALT: Duration = Duration::from_millis(120);

/// The example machine with MotionControl turning `Master` at constant velocity and Main
/// turning `Spare`, an axis of MainTask, the same way.
fn project() -> Project {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples/packaging_machine");
    let mut project = project_model::load_project(&dir)
        .expect("the example loads")
        .project;
    let master = project
        .axes
        .iter()
        .find(|axis| axis.name == "Master")
        .expect("the example has a master")
        .clone();
    project.axes.push(project_model::Axis {
        name: "Spare".to_owned(),
        task: "MainTask".to_owned(),
        ..master
    });
    let turn = |axis: &str| {
        format!(
            "fbPower{axis}(Axis := {axis}, Enable := TRUE);
fbMove{axis}(Axis := {axis}, Execute := fbPower{axis}.Status, Velocity := {VELOCITY:.1},
    Acceleration := 3600.0, Deceleration := 3600.0, Direction := MC_DIRECTION.positive);
"
        )
    };
    let blocks = |axis: &str| {
        [
            (format!("fbPower{axis}"), "MC_Power"),
            (format!("fbMove{axis}"), "MC_MoveVelocity"),
        ]
        .map(|(name, ty)| Variable {
            section: VarSection::Var,
            ..Variable::new(name, ty)
        })
    };
    for node in &mut project.application.children {
        let Node::Object(Object::Pou(pou)) = node else {
            continue;
        };
        if pou.name == "MotionControl" {
            pou.variables = blocks("Master").to_vec();
            pou.body = Body::st(turn("Master"));
        } else if pou.name == "Main" {
            pou.variables.extend(blocks("Spare"));
            let body = pou.body.st_text_mut().expect("Main is in ST");
            body.push_str(&format!("\n{}", turn("Spare")));
        }
    }
    project
}

/// The data offset of `axis`'s `fActPosition`.
fn position_offset(image: &ProgramImage, axis: &str) -> usize {
    let place = runtime::value::resolve(image, &format!("{axis}.fActPosition"))
        .unwrap_or_else(|e| panic!("{axis}: {e}"));
    place.offset as usize
}

fn lreal(data: &[u8], at: usize) -> f64 {
    f64::from_le_bytes(data[at..at + 8].try_into().expect("eight bytes"))
}

/// How far a modulo-360 position moved forward from `from` to `to`.
fn moved(from: f64, to: f64) -> f64 {
    (to - from).rem_euclid(360.0)
}

/// The scheduler's part: MainTask's cycles when they are due, also from inside a halt.
struct Clock {
    main_task: usize,
    spare_at: usize,
    next_main_ns: i64,
    main_cycles: u64,
    /// `Spare`'s position after each MainTask cycle, with whether the cycle ran in the halt.
    spare: Vec<(f64, bool)>,
    /// The simulated time of the halted cycle's start, and how long its halt lasted.
    halted_at_ns: i64,
    halted_ns: i64,
    halts: usize,
}

impl Clock {
    /// Runs the MainTask cycles due at `now_ns`.
    fn run_main(&mut self, engine: &mut EngineView<'_>, now_ns: i64, in_halt: bool) {
        while self.next_main_ns <= now_ns {
            engine
                .run_cycle(
                    self.main_task,
                    self.next_main_ns,
                    TaskClock::Simulated,
                    self.main_cycles,
                    None,
                )
                .expect("MainTask does not fault");
            self.main_cycles += 1;
            self.next_main_ns += MAIN_NS;
            let position = lreal(engine.region(Region::Data), self.spare_at);
            self.spare.push((position, in_halt));
        }
    }
}

impl Preempt for Clock {
    fn preempt(&mut self, _engine: EngineView<'_>) {}

    fn halt(&mut self, mut engine: EngineView<'_>, task: usize) {
        self.halts += 1;
        let entered = Instant::now();
        while entered.elapsed() < HALT {
            std::thread::sleep(Duration::from_millis(5));
            let now_ns = self.halted_at_ns + entered.elapsed().as_nanos() as i64;
            self.run_main(&mut engine, now_ns, true);
        }
        self.halted_ns = entered.elapsed().as_nanos() as i64;
        engine
            .debug_mut()
            .continue_task(task)
            .expect("the halted task goes on");
    }
}

#[test]
fn a_halted_tasks_axis_resumes_by_one_cycle_and_another_tasks_axis_keeps_its_timing() {
    let image = compiler::compile_project(&project()).expect("the project compiles");
    let task = |name: &str| {
        image
            .tasks
            .iter()
            .position(|task| task.name == name)
            .unwrap_or_else(|| panic!("no task {name}"))
    };
    let (motion_task, main_task) = (task("MotionTask"), task("MainTask"));
    let master_at = position_offset(&image, "Master");
    let control = image
        .pous
        .iter()
        .position(|pou| pou.name == "MotionControl")
        .expect("MotionControl is compiled");
    let mut engine = Engine::new(image.clone()).expect("the image loads");
    engine.debug_mut().begin_session();
    engine
        .view()
        .set_breakpoint(BreakpointSpec {
            pou: control as u32,
            instruction: image.pous[control].lines[0].index,
            instance: 0,
            task: None,
            hit_mode: HitMode::Equal,
            hit_target: HALTING_CYCLE,
            condition: Vec::new(),
        })
        .expect("the breakpoint is set");

    let mut clock = Clock {
        main_task,
        spare_at: position_offset(&image, "Spare"),
        next_main_ns: 0,
        main_cycles: 0,
        spare: Vec::new(),
        halted_at_ns: 0,
        halted_ns: 0,
        halts: 0,
    };
    let due = AtomicBool::new(false);
    let mut now_ns = 0i64;
    let mut master = Vec::new();
    for cycle in 0..u64::from(HALTING_CYCLE) + 20 {
        clock.run_main(&mut engine.view(), now_ns, false);
        clock.halted_at_ns = now_ns;
        let halts = clock.halts;
        engine
            .view()
            .run_cycle(
                motion_task,
                now_ns,
                TaskClock::Simulated,
                cycle,
                Some(Preemption {
                    due: &due,
                    hook: &mut clock,
                }),
            )
            .expect("MotionTask does not fault");
        master.push(lreal(engine.region(Region::Data), master_at));
        // After a halt the clock has moved on by its length; the missed cycles are dropped.
        if clock.halts > halts {
            now_ns += clock.halted_ns;
        }
        now_ns += MOTION_NS;
    }
    assert_eq!(clock.halts, 1);

    // One cycle's worth of travel at full speed, before the halt and after it.
    let per_cycle = VELOCITY * MOTION_NS as f64 / 1e9;
    let halted = HALTING_CYCLE as usize - 1;
    let before = moved(master[halted - 2], master[halted - 1]);
    assert!(
        (before - per_cycle).abs() < 1e-6,
        "{before} before the halt"
    );
    // The halted cycle advanced by one cycle before the halt; the next one by one cycle more,
    // less the microseconds between the halt's end as the test and the engine saw it.
    let in_halted = moved(master[halted - 1], master[halted]);
    assert!(
        (in_halted - per_cycle).abs() < 1e-6,
        "{in_halted} in the halted cycle"
    );
    let after = moved(master[halted], master[halted + 1]);
    let over_the_halt = VELOCITY * clock.halted_ns as f64 / 1e9;
    assert!(
        (after - per_cycle).abs() < 0.02 * per_cycle,
        "{after}° after the halt, one cycle is {per_cycle}°, the halt {over_the_halt}°"
    );
    let later = moved(master[halted + 1], master[halted + 2]);
    assert!((later - per_cycle).abs() < 1e-6, "{later} later");

    // MainTask ran its cycles during the halt, and Spare moved by its own cycle every time.
    let spare_per_cycle = VELOCITY * MAIN_NS as f64 / 1e9;
    let in_the_halt = clock.spare.iter().filter(|(_, in_halt)| *in_halt).count();
    assert!(
        in_the_halt >= 10,
        "{in_the_halt} MainTask cycles in the halt"
    );
    let first = clock
        .spare
        .iter()
        .position(|(_, in_halt)| *in_halt)
        .expect("cycles in the halt");
    for pair in clock.spare[first - 3..first + in_the_halt + 3].windows(2) {
        let step = moved(pair[0].0, pair[1].0);
        assert!(
            (step - spare_per_cycle).abs() < 1e-6,
            "Spare moved {step}° in one MainTask cycle: {:?}",
            clock.spare
        );
    }
}

#[test]
fn without_a_session_both_axes_turn_alike_under_both_engines_cycle_by_cycle() {
    // The same machine without the debugger: every cycle runs natively, and the harness
    // compares the axes and the memory of both engines after each (`docs/native-engine.md`
    // §11.1); the positions before each period are read from the native engine as the
    // harness feeds it.
    let image = compiler::compile_project(&project()).expect("the project compiles");
    let (master_at, spare_at) = (
        position_offset(&image, "Master"),
        position_offset(&image, "Spare"),
    );
    let mut positions: Vec<(f64, f64)> = Vec::new();
    let mut calls = 0u64;
    let cycles = u64::from(HALTING_CYCLE) + 20;
    let simulation = runtime::differential::run_both(image, cycles, |_, engine| {
        calls += 1;
        // Each period feeds the interpreter first, then the native engine.
        if calls.is_multiple_of(2) {
            let data = engine.region(Region::Data);
            positions.push((lreal(data, master_at), lreal(data, spare_at)));
        }
    })
    .unwrap_or_else(|difference| panic!("the engines differ: {difference}"));
    assert!(simulation.faults().is_empty(), "{:?}", simulation.faults());
    assert_eq!(positions.len() as u64, cycles);
    if runtime::engine::EngineChoice::native_available() {
        assert!(simulation.engine().native_entries() > 0);
    }
    // Both at full speed long before the end: Master one MotionTask cycle's travel per period,
    // Spare one MainTask cycle's travel every fifth period.
    let per_cycle = VELOCITY * MOTION_NS as f64 / 1e9;
    let spare_per_cycle = VELOCITY * MAIN_NS as f64 / 1e9;
    let periods_per_main = (MAIN_NS / MOTION_NS) as usize;
    let late = &positions[200..];
    for pair in late.windows(2) {
        let step = moved(pair[0].0, pair[1].0);
        assert!((step - per_cycle).abs() < 1e-6, "Master moved {step}°");
    }
    for pair in late.windows(periods_per_main + 1) {
        let step = moved(pair[0].1, pair[periods_per_main].1);
        assert!(
            (step - spare_per_cycle).abs() < 1e-6,
            "Spare moved {step}° in one MainTask period"
        );
    }
}
