//! The clock operators `TIME()` and `LTIME()` (instruction `Clock`) on the scheduler's real
//! clock, where time passes during a cycle, and on the simulated clock, where it stands still.

use program_image::{
    BinaryOp, CompareOp, Elementary, Instr, Layout, Operand, Pou, PouKind, ProgramCall,
    ProgramImage, Task, TaskKind,
};

use super::tests::{MS, dword, scheduler, wait_for};
use super::*;
use crate::simulation::Simulation;

/// Iterations of the busy loop between the two clock reads.
const ITERATIONS: i32 = 10_000;

/// One cyclic task of a minute's interval (so only its first cycle runs in a test) whose
/// program reads `LTIME()` into `%M` at 0, loops [`ITERATIONS`] times, reads `LTIME()` into
/// `%M` at 8 and `TIME()` into `%Q` at 0.
fn image() -> ProgramImage {
    let counter = Operand::Global(0);
    let done = Operand::Global(4);
    let code = vec![
        Instr::Clock {
            long: true,
            dst: Operand::Memory(0),
        },
        Instr::Move {
            ty: Elementary::Dint,
            dst: counter,
            src: Operand::Const(0),
        },
        Instr::Compare {
            op: CompareOp::Ge,
            ty: Elementary::Dint,
            dst: done,
            a: counter,
            b: Operand::Const(4),
        },
        Instr::JumpIf {
            cond: done,
            target: 6,
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Elementary::Dint,
            dst: counter,
            a: counter,
            b: Operand::Const(8),
        },
        Instr::Jump { target: 2 },
        Instr::Clock {
            long: true,
            dst: Operand::Memory(8),
        },
        Instr::Clock {
            long: false,
            dst: Operand::Output(0),
        },
        Instr::Return,
    ];
    ProgramImage {
        layout: Layout {
            data_size: 8,
            input_size: 0,
            output_size: 4,
            memory_size: 16,
            stack_size: 64,
        },
        pous: vec![Pou {
            name: "Measure".to_owned(),
            kind: PouKind::Program,
            frame_size: 0,
            frame_init: Vec::new(),
            instance_size: 0,
            code,
            lines: Vec::new(),
        }],
        // 0, the iterations, 1.
        constants: [0, ITERATIONS, 1]
            .into_iter()
            .flat_map(i32::to_le_bytes)
            .collect(),
        tasks: vec![Task {
            name: "Task".to_owned(),
            kind: TaskKind::Cyclic,
            interval_ns: 60_000 * MS,
            trigger: None,
            priority: 1,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: vec![ProgramCall {
                pou: 0,
                instance_offset: 0,
            }],
        }],
        ..ProgramImage::default()
    }
}

/// The LINT at `at` of `bytes`.
fn lint(bytes: &[u8], at: usize) -> i64 {
    let mut le = [0; 8];
    le.copy_from_slice(&bytes[at..at + 8]);
    i64::from_le_bytes(le)
}

#[test]
fn ltime_read_twice_in_one_cycle_on_the_real_clock_measures_the_code_between() {
    let (scheduler, areas) = scheduler(SchedulerOptions::default());
    scheduler.load(image()).unwrap();
    scheduler.start().unwrap();
    wait_for(&scheduler, "the first cycle", |status| {
        status.tasks.iter().all(|task| task.cycles == 1)
    });
    scheduler.stop().unwrap();
    let areas = areas.lock().unwrap();
    let (before_ns, after_ns) = (lint(&areas.memory, 0), lint(&areas.memory, 8));
    assert!(
        after_ns > before_ns,
        "the loop took no time: {before_ns} then {after_ns}"
    );
    // TIME() was read after the second LTIME(), in milliseconds.
    let time_ms = i64::from(dword(&areas.output, 0));
    assert!(
        time_ms >= after_ns / 1_000_000,
        "{time_ms} ms, {after_ns} ns"
    );
}

#[test]
fn the_clock_stands_still_during_a_simulated_cycle_and_moves_by_the_interval() {
    let mut simulation = Simulation::new(image()).unwrap();
    simulation.run(1);
    let memory = simulation.engine().region(program_image::Region::Memory);
    assert_eq!((lint(memory, 0), lint(memory, 8)), (0, 0));
    simulation.run(2);
    let memory = simulation.engine().region(program_image::Region::Memory);
    assert_eq!(lint(memory, 0), 120_000_000_000);
    assert_eq!(lint(memory, 8), 120_000_000_000);
    let output = simulation.engine().region(program_image::Region::Output);
    assert_eq!(dword(output, 0), 120_000);
}

#[test]
fn time_keeps_the_low_32_bits_of_the_milliseconds_as_time_wraps() {
    let mut engine = Engine::new(image()).unwrap();
    let wrap_ms: i64 = 1 << 32;
    // 49.7 days and 7 ms after the start: TIME counts on from 0, LTIME does not wrap.
    let now_ns = (wrap_ms + 7) * 1_000_000;
    engine.run_cycle(0, now_ns, 0).unwrap();
    assert_eq!(dword(engine.region(program_image::Region::Output), 0), 7);
    assert_eq!(
        lint(engine.region(program_image::Region::Memory), 0),
        now_ns
    );
    // Past 24.8 days Rivet's signed TIME reads negative, with the bits CODESYS's unsigned has.
    engine.run_cycle(0, (1 << 31) * 1_000_000, 1).unwrap();
    assert_eq!(
        dword(engine.region(program_image::Region::Output), 0),
        i32::MIN
    );
}
