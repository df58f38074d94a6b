//! Small program images built by hand for the unit tests (`runtime` may not use the compiler).
//!
//! The data region starts with a sequence counter (`DINT` at 0); task `i` has its own slot at
//! `8 * i + 4`, where its program writes the sequence number of its last cycle, and a cycle
//! count at `8 * i + 8`. A task may instead run the "slow" program, which counts a `DINT` at
//! the end of the data region up to the value of `%MD0`, so a test sets its duration through
//! the located areas. A counting task also copies the sequence number to `%MD(2 + i)` and its
//! cycle count to `%QD(i)`, where tests see them through the shared areas. A "watching" task
//! loops a fixed number of times, with its own counter, and notes the sequence counter before
//! and after its loop: a task that interrupted it shows as a difference. A "lasting" task does
//! the same, looping for a time rather than a number of iterations.

use program_image::{
    BinaryOp, CompareOp, Elementary, Instr, Layout, Operand, Pou, PouKind, ProgramCall,
    ProgramImage, RetainLayout, Symbol, SymbolFlags, Task, TaskKind, TypeDef,
};

/// The sequence counter's offset.
pub(crate) const SEQUENCE: u32 = 0;

/// The offset of the sequence number of task `task`'s last cycle.
pub(crate) fn slot(task: usize) -> u32 {
    8 * task as u32 + 4
}

/// The offset of task `task`'s cycle count.
pub(crate) const fn count(task: usize) -> u32 {
    8 * task as u32 + 8
}

/// Where in `%M` task `task` copies the sequence number of its last cycle (`%MD(2 + task)`).
pub(crate) fn sequence_in_memory(task: usize) -> u32 {
    8 + 4 * task as u32
}

/// Where in `%Q` task `task` copies its cycle count (`%QD(task)`).
pub(crate) fn count_in_output(task: usize) -> u32 {
    4 * task as u32
}

/// What a task of a test image runs.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Body {
    /// Counts the sequence and its own cycles.
    Count,
    /// Loops `%MD0` times.
    Slow,
    /// Notes the sequence counter at [`seen_at_start`], loops `iterations` times (counting in
    /// [`watch_counter`]), notes the sequence counter again at [`seen_at_end`], and counts its
    /// own cycles; it leaves the sequence counter alone. With `sets_trigger`, it sets the
    /// event trigger `%MX4.0` (by writing 1 to `%MD1`) instead of the first note.
    Watch { iterations: i32, sets_trigger: bool },
    /// Notes task `task`'s cycle count (at [`count`]) at [`seen_at_start`], loops until it
    /// has moved on by `cycles` (the difference in [`watch_counter`]), notes it again at
    /// [`seen_at_end`], and counts its own cycles: a cycle that ends only after `cycles` cycles
    /// of task `task` ran after it started, which they can only do nested in it, so a test of
    /// preemption needs no loop sized to this machine's speed. With `sets_trigger`, it first
    /// sets the event trigger `%MX4.0` (by writing 1 to `%MD1`), so that an event task
    /// triggered by it can only run after this cycle started.
    WaitFor {
        task: usize,
        cycles: i32,
        sets_trigger: bool,
    },
    /// Notes the sequence counter at [`seen_at_start`], loops until `TIME()` has moved on by
    /// `ms` milliseconds since the loop started (the milliseconds passed at its last look in
    /// [`watch_counter`]), notes the sequence counter again at [`seen_at_end`], and counts its
    /// own cycles: a cycle that lasts as long under either engine, however fast each runs the
    /// loop (on the scheduler's real clock; on a simulated clock, which stands still during a
    /// cycle, it never ends).
    Lasting { ms: i32 },
}

/// Where watching task `task` notes the sequence counter before its loop.
pub(crate) const fn seen_at_start(task: usize) -> u32 {
    WATCH_SLOTS + WATCH_SLOT_BYTES * task as u32
}

/// Where watching task `task` notes the sequence counter after its loop.
pub(crate) const fn seen_at_end(task: usize) -> u32 {
    seen_at_start(task) + 4
}

/// The loop counter of watching task `task` (for a lasting task, the milliseconds passed).
pub(crate) const fn watch_counter(task: usize) -> u32 {
    seen_at_start(task) + 8
}

/// Where the loop of watching task `task` writes whether it is done.
const fn watch_done(task: usize) -> u32 {
    seen_at_start(task) + 12
}

/// Where lasting task `task` keeps `TIME()` at the start of its loop.
const fn lasting_since(task: usize) -> u32 {
    seen_at_start(task) + 16
}

/// Where the watching tasks' slots start in the data region, past everything else.
const WATCH_SLOTS: u32 = 1024;

/// The bytes of each task's watching slots: the two notes, the loop counter, the loop's test
/// and a lasting task's start, rounded up.
const WATCH_SLOT_BYTES: u32 = 32;

/// A task of a test image.
#[derive(Clone, Debug)]
pub(crate) struct TestTask {
    pub kind: TaskKind,
    pub interval_ns: u64,
    pub priority: u8,
    pub watchdog_ns: u64,
    pub watchdog_sensitivity: u32,
    pub body: Body,
}

impl TestTask {
    /// A counting cyclic task.
    pub(crate) fn cyclic(interval_ns: u64, priority: u8) -> Self {
        Self {
            kind: TaskKind::Cyclic,
            interval_ns,
            priority,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            body: Body::Count,
        }
    }
}

/// An image with `tasks`; task `i` runs program `i`. Symbol 0 is the BOOL `%MX4.0`, which
/// an event task uses as its trigger. `retained` data-region ranges are RETAIN.
pub(crate) fn image(tasks: &[TestTask], retained: &[(u32, u32)]) -> ProgramImage {
    let task_count = tasks.len() as u32;
    let loop_counter = count(tasks.len());
    let flag = loop_counter + 4;
    let data_size = seen_at_start(tasks.len()).max(flag + 4);
    let one = Operand::Const(0);
    let iterations: Vec<i32> = tasks
        .iter()
        .map(|task| match task.body {
            Body::Watch { iterations, .. } => iterations,
            Body::WaitFor { cycles, .. } => cycles,
            Body::Lasting { ms } => ms,
            Body::Count | Body::Slow => 0,
        })
        .collect();
    let pous = tasks
        .iter()
        .enumerate()
        .map(|(index, task)| {
            let code = match task.body {
                Body::Count => vec![
                    add_one(Operand::Global(SEQUENCE), one),
                    Instr::Move {
                        ty: Elementary::Dint,
                        dst: Operand::Global(slot(index)),
                        src: Operand::Global(SEQUENCE),
                    },
                    add_one(Operand::Global(count(index)), one),
                    Instr::Move {
                        ty: Elementary::Dint,
                        dst: Operand::Memory(sequence_in_memory(index)),
                        src: Operand::Global(SEQUENCE),
                    },
                    Instr::Move {
                        ty: Elementary::Dint,
                        dst: Operand::Output(count_in_output(index)),
                        src: Operand::Global(count(index)),
                    },
                    Instr::Return,
                ],
                Body::Slow => vec![
                    Instr::Move {
                        ty: Elementary::Dint,
                        dst: Operand::Global(loop_counter),
                        src: Operand::Const(4),
                    },
                    Instr::Compare {
                        op: CompareOp::Ge,
                        ty: Elementary::Dint,
                        dst: Operand::Global(flag),
                        a: Operand::Global(loop_counter),
                        b: Operand::Memory(0),
                    },
                    Instr::JumpIf {
                        cond: Operand::Global(flag),
                        target: 5,
                    },
                    add_one(Operand::Global(loop_counter), one),
                    Instr::Jump { target: 1 },
                    add_one(Operand::Global(count(index)), one),
                    Instr::Return,
                ],
                Body::Watch { sets_trigger, .. } => {
                    let counter = Operand::Global(watch_counter(index));
                    let done = Operand::Global(watch_done(index));
                    let (first, value) = if sets_trigger {
                        (Operand::Memory(4), Operand::Const(0))
                    } else {
                        (
                            Operand::Global(seen_at_start(index)),
                            Operand::Global(SEQUENCE),
                        )
                    };
                    vec![
                        Instr::Move {
                            ty: Elementary::Dint,
                            dst: first,
                            src: value,
                        },
                        Instr::Move {
                            ty: Elementary::Dint,
                            dst: counter,
                            src: Operand::Const(4),
                        },
                        Instr::Compare {
                            op: CompareOp::Ge,
                            ty: Elementary::Dint,
                            dst: done,
                            a: counter,
                            b: Operand::Const(8 + 4 * index as u32),
                        },
                        Instr::JumpIf {
                            cond: done,
                            target: 6,
                        },
                        add_one(counter, one),
                        Instr::Jump { target: 2 },
                        Instr::Move {
                            ty: Elementary::Dint,
                            dst: Operand::Global(seen_at_end(index)),
                            src: Operand::Global(SEQUENCE),
                        },
                        add_one(Operand::Global(count(index)), one),
                        Instr::Return,
                    ]
                }
                Body::WaitFor {
                    task, sets_trigger, ..
                } => {
                    let counted = Operand::Global(count(task));
                    let noted = Operand::Global(seen_at_start(index));
                    let moved = Operand::Global(watch_counter(index));
                    let done = Operand::Global(watch_done(index));
                    // The trigger, when set, comes first and moves the loop on by one.
                    let first = u32::from(sets_trigger);
                    let trigger = sets_trigger.then_some(Instr::Move {
                        ty: Elementary::Dint,
                        dst: Operand::Memory(4),
                        src: Operand::Const(0),
                    });
                    trigger
                        .into_iter()
                        .chain([
                            Instr::Move {
                                ty: Elementary::Dint,
                                dst: noted,
                                src: counted,
                            },
                            Instr::Binary {
                                op: BinaryOp::Sub,
                                ty: Elementary::Dint,
                                dst: moved,
                                a: counted,
                                b: noted,
                            },
                            Instr::Compare {
                                op: CompareOp::Ge,
                                ty: Elementary::Dint,
                                dst: done,
                                a: moved,
                                b: Operand::Const(8 + 4 * index as u32),
                            },
                            Instr::JumpIfNot {
                                cond: done,
                                target: first + 1,
                            },
                            Instr::Move {
                                ty: Elementary::Dint,
                                dst: Operand::Global(seen_at_end(index)),
                                src: counted,
                            },
                            add_one(Operand::Global(count(index)), one),
                            Instr::Return,
                        ])
                        .collect()
                }
                Body::Lasting { .. } => {
                    let since = Operand::Global(lasting_since(index));
                    let passed = Operand::Global(watch_counter(index));
                    let done = Operand::Global(watch_done(index));
                    vec![
                        Instr::Move {
                            ty: Elementary::Dint,
                            dst: Operand::Global(seen_at_start(index)),
                            src: Operand::Global(SEQUENCE),
                        },
                        Instr::Clock {
                            long: false,
                            dst: since,
                        },
                        Instr::Clock {
                            long: false,
                            dst: passed,
                        },
                        Instr::Binary {
                            op: BinaryOp::Sub,
                            ty: Elementary::Dint,
                            dst: passed,
                            a: passed,
                            b: since,
                        },
                        Instr::Compare {
                            op: CompareOp::Ge,
                            ty: Elementary::Dint,
                            dst: done,
                            a: passed,
                            b: Operand::Const(8 + 4 * index as u32),
                        },
                        Instr::JumpIfNot {
                            cond: done,
                            target: 2,
                        },
                        Instr::Move {
                            ty: Elementary::Dint,
                            dst: Operand::Global(seen_at_end(index)),
                            src: Operand::Global(SEQUENCE),
                        },
                        add_one(Operand::Global(count(index)), one),
                        Instr::Return,
                    ]
                }
            };
            Pou {
                name: format!("Program{index}"),
                kind: PouKind::Program,
                frame_size: 0,
                frame_init: Vec::new(),
                instance_size: 0,
                code,
                lines: Vec::new(),
            }
        })
        .collect();
    let tasks = tasks
        .iter()
        .enumerate()
        .map(|(index, task)| Task {
            name: format!("Task{index}"),
            kind: task.kind,
            interval_ns: task.interval_ns,
            trigger: (task.kind == TaskKind::Event).then_some(0),
            priority: task.priority,
            watchdog_ns: task.watchdog_ns,
            watchdog_sensitivity: task.watchdog_sensitivity,
            programs: vec![ProgramCall {
                pou: index as u32,
                instance_offset: 0,
            }],
        })
        .collect();
    ProgramImage {
        types: vec![TypeDef::Elementary(Elementary::Bool)],
        layout: Layout {
            data_size,
            input_size: 4,
            output_size: 4 * task_count,
            memory_size: 8 + 4 * task_count,
            stack_size: 64,
        },
        symbols: vec![Symbol {
            path: "Trigger".to_owned(),
            ty: 0,
            region: program_image::Region::Memory,
            offset: 4,
            bit: Some(0),
            flags: SymbolFlags(SymbolFlags::LOCATED | SymbolFlags::GLOBAL),
        }],
        pous,
        // 1, 0, then the iterations (or cycles waited for) of each watching task.
        constants: [1_i32, 0]
            .into_iter()
            .chain(iterations)
            .flat_map(i32::to_le_bytes)
            .collect(),
        tasks,
        retain: RetainLayout {
            retain: retained.to_vec(),
            persistent: Vec::new(),
        },
        ..ProgramImage::default()
    }
}

/// `place := place + 1` on a DINT.
fn add_one(place: Operand, one: Operand) -> Instr {
    Instr::Binary {
        op: BinaryOp::Add,
        ty: Elementary::Dint,
        dst: place,
        a: place,
        b: one,
    }
}

/// The DINT at `offset` of a data region.
pub(crate) fn dint(data: &[u8], offset: u32) -> i32 {
    let at = offset as usize;
    i32::from_le_bytes([data[at], data[at + 1], data[at + 2], data[at + 3]])
}
