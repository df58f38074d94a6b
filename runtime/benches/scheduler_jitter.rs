//! Scheduler timing: `cargo bench -p runtime --bench scheduler_jitter`.
//!
//! Runs hand-built images on the real scheduler for a few seconds each and prints, per task,
//! the cycles run, the average and largest cycle time and the average and largest start jitter
//! (how much later than planned a cycle started). First one 1 ms cyclic task alone, then the
//! same with a 10 ms task of lower priority and a freewheeling task of the lowest priority.
//! Each runs once sleeping until a start and once spinning the last 200 µs before it.
//! The figures depend on the machine and its load; nothing is asserted.
//! The scheduler runs the default engine (`EngineChoice::default`: native on x86-64 and
//! aarch64).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::sync::{Arc, Mutex};
use std::time::Duration;

use program_image::{
    BinaryOp, Elementary, Instr, Layout, Operand, Pou, PouKind, ProgramCall, ProgramImage, Task,
    TaskKind,
};
use runtime::areas::LocatedAreas;
use runtime::scheduler::{Scheduler, SchedulerOptions};

/// How long each scenario runs.
const RUN: Duration = Duration::from_secs(3);

/// An image whose task `i` adds 1 to the DINT `%QD(i)` each cycle.
fn image(tasks: &[(TaskKind, u64, u8)]) -> ProgramImage {
    let pous = (0..tasks.len())
        .map(|index| Pou {
            name: format!("Program{index}"),
            kind: PouKind::Program,
            frame_size: 0,
            frame_init: Vec::new(),
            instance_size: 0,
            code: vec![
                Instr::Binary {
                    op: BinaryOp::Add,
                    ty: Elementary::Dint,
                    dst: Operand::Output(4 * index as u32),
                    a: Operand::Output(4 * index as u32),
                    b: Operand::Const(0),
                },
                Instr::Return,
            ],
            lines: Vec::new(),
        })
        .collect();
    let tasks = tasks
        .iter()
        .enumerate()
        .map(|(index, &(kind, interval_ns, priority))| Task {
            name: format!(
                "{kind:?} {} ms, priority {priority}",
                interval_ns / 1_000_000
            ),
            kind,
            interval_ns,
            trigger: None,
            priority,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: vec![ProgramCall {
                pou: index as u32,
                instance_offset: 0,
            }],
        })
        .collect::<Vec<_>>();
    ProgramImage {
        layout: Layout {
            data_size: 0,
            input_size: 0,
            output_size: 4 * tasks.len() as u32,
            memory_size: 0,
            stack_size: 64,
        },
        pous,
        constants: 1_i32.to_le_bytes().to_vec(),
        tasks,
        ..ProgramImage::default()
    }
}

fn measure(title: &str, tasks: &[(TaskKind, u64, u8)], spin: Duration) {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let options = SchedulerOptions {
        spin_before_start: spin,
        ..SchedulerOptions::default()
    };
    let scheduler = Scheduler::spawn(areas, options).unwrap();
    scheduler.load(image(tasks)).unwrap();
    scheduler.start().unwrap();
    std::thread::sleep(RUN);
    scheduler.stop().unwrap();
    println!(
        "{title}, spinning {} µs before a start, {} s:",
        spin.as_micros(),
        RUN.as_secs()
    );
    for task in scheduler.status().tasks {
        println!(
            "  {:<32} {:>7} cycles; cycle average {:>6.1} µs, max {:>7.1} µs; \
             jitter average {:>6.1} µs, max {:>7.1} µs",
            task.name,
            task.cycles,
            task.average_cycle_ns() as f64 / 1000.0,
            task.max_cycle_ns as f64 / 1000.0,
            task.average_jitter_ns() as f64 / 1000.0,
            task.max_jitter_ns as f64 / 1000.0,
        );
    }
    scheduler.shutdown().unwrap();
}

fn main() {
    const MS: u64 = 1_000_000;
    for spin in [Duration::ZERO, Duration::from_micros(200)] {
        measure("one 1 ms task", &[(TaskKind::Cyclic, MS, 0)], spin);
        measure(
            "1 ms, 10 ms and freewheeling tasks",
            &[
                (TaskKind::Cyclic, MS, 0),
                (TaskKind::Cyclic, 10 * MS, 5),
                (TaskKind::Freewheeling, 0, 31),
            ],
            spin,
        );
    }
}
