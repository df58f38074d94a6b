//! [`super::run_against`] on a hand-made image, with two interpreters and with a second
//! interpreter corrupted on purpose; one test compares the interpreter with the native engine
//! ([`super::run_both`]).

#![allow(clippy::unwrap_used)] // A panic is a failed test.

use program_image::{
    BinaryOp, Elementary, InitRun, InitialValues, Instr, Layout, LineEntry, Member, Operand, Pou,
    PouKind, ProgramCall, ProgramImage, Region, StructKind, Symbol, SymbolFlags, Task, TaskKind,
    TypeDef,
};

use super::*;
use crate::value::{self, Value};

/// The data offset of `Main.s[2].b`: `s` starts at 16, elements are 8 bytes, `b` is at 4.
const S2_B: usize = 28;
/// A byte of padding in `Main`, between `q` (8..12) and `s` (16..40).
const PADDING: usize = 13;

/// `Main` (data 0..40): `n`, `d` (initially 5) and `q` DINTs, padding, then
/// `s : ARRAY[1..3] OF Pair` with `Pair` = (`a` INT at 0, `b` DINT at 4). Each cycle it does
/// `n := n + 1; s[2].b := s[2].b + n; q := 100 / d;` (lines 3, 4, 5 of `main.st`). `%I` holds
/// `In_word` (`%IW0`) and `In_bit` (`%IX0.3`) and two bytes no symbol covers.
fn image() -> ProgramImage {
    let member = |name: &str, ty: u32, offset: u32| Member {
        name: name.to_owned(),
        ty,
        offset,
        located: None,
        flags: 0,
    };
    let symbol = |path: &str, ty: u32, region: Region, offset: u32, bit: Option<u8>| Symbol {
        path: path.to_owned(),
        ty,
        region,
        offset,
        bit,
        flags: SymbolFlags(0),
    };
    let dint = |offset: u32| Operand::Global(offset);
    ProgramImage {
        types: vec![
            TypeDef::Elementary(Elementary::Dint),
            TypeDef::Elementary(Elementary::Int),
            TypeDef::Struct {
                name: "Pair".to_owned(),
                kind: StructKind::Struct,
                size: 8,
                members: vec![member("a", 1, 0), member("b", 0, 4)],
            },
            TypeDef::Array {
                element: 2,
                dims: vec![(1, 3)],
            },
            TypeDef::Struct {
                name: "Main".to_owned(),
                kind: StructKind::Program,
                size: 40,
                members: vec![
                    member("n", 0, 0),
                    member("d", 0, 4),
                    member("q", 0, 8),
                    member("s", 3, 16),
                ],
            },
            TypeDef::Elementary(Elementary::Bool),
            TypeDef::Elementary(Elementary::Word),
        ],
        layout: Layout {
            data_size: 40,
            input_size: 4,
            output_size: 0,
            memory_size: 0,
            stack_size: 64,
        },
        initial: InitialValues {
            data: vec![InitRun {
                offset: 4,
                bytes: 5_i32.to_le_bytes().to_vec(),
            }],
            ..InitialValues::default()
        },
        // `Main.s` has no symbol of its own: its path is found through `Main`'s members.
        symbols: vec![
            symbol("Main", 4, Region::Data, 0, None),
            symbol("Main.n", 0, Region::Data, 0, None),
            symbol("Main.d", 0, Region::Data, 4, None),
            symbol("Main.q", 0, Region::Data, 8, None),
            symbol("In_word", 6, Region::Input, 0, None),
            symbol("In_bit", 5, Region::Input, 0, Some(3)),
        ],
        pous: vec![Pou {
            name: "Main".to_owned(),
            kind: PouKind::Program,
            frame_size: 0,
            frame_init: Vec::new(),
            instance_size: 40,
            code: vec![
                Instr::Binary {
                    op: BinaryOp::Add,
                    ty: Elementary::Dint,
                    dst: dint(0),
                    a: dint(0),
                    b: Operand::Const(0),
                },
                Instr::Binary {
                    op: BinaryOp::Add,
                    ty: Elementary::Dint,
                    dst: dint(S2_B as u32),
                    a: dint(S2_B as u32),
                    b: dint(0),
                },
                Instr::Binary {
                    op: BinaryOp::Div,
                    ty: Elementary::Dint,
                    dst: dint(8),
                    a: Operand::Const(4),
                    b: dint(4),
                },
                Instr::Return,
            ],
            lines: (0..3)
                .map(|index| LineEntry {
                    index,
                    file: 0,
                    line: index + 3,
                })
                .collect(),
        }],
        constants: [1_i32, 100]
            .into_iter()
            .flat_map(i32::to_le_bytes)
            .collect(),
        tasks: vec![Task {
            name: "Fast".to_owned(),
            kind: TaskKind::Cyclic,
            interval_ns: 1_000_000,
            trigger: None,
            priority: 1,
            watchdog_ns: 0,
            watchdog_sensitivity: 1,
            programs: vec![ProgramCall {
                pou: 0,
                instance_offset: 0,
            }],
        }],
        sources: vec!["main.st".to_owned()],
        ..ProgramImage::default()
    }
}

/// The difference `run` found; the test fails when the engines agreed.
#[track_caller]
fn differs(run: Result<Simulation, Difference>) -> Difference {
    match run {
        Ok(_) => panic!("the engines agreed"),
        Err(difference) => difference,
    }
}

fn no_writes(_cycle: u64, _engine: &mut Engine) {}

/// `image` loaded in the interpreter, whatever the default engine: the second engine of the
/// tests that compare two interpreters.
fn interpreted(image: ProgramImage) -> Result<Simulation, LoadError> {
    Simulation::with_choice(image, EngineChoice::Interpreter).map(|(simulation, _)| simulation)
}

/// A second engine that is the interpreter with `corrupt` applied to its memory after loading.
fn corrupted(
    corrupt: impl FnOnce(&mut Engine),
) -> impl FnOnce(ProgramImage) -> Result<Simulation, LoadError> {
    move |image| {
        let mut simulation = interpreted(image)?;
        corrupt(simulation.engine_mut());
        Ok(simulation)
    }
}

/// Sets `Main.d` to 0 before cycle 3, so that cycle's division faults.
fn zero_divisor_before_cycle_3(cycle: u64, engine: &mut Engine) {
    if cycle == 3 {
        engine.region_mut(Region::Data)[4..8].copy_from_slice(&0_i32.to_le_bytes());
    }
}

#[test]
fn two_equal_engines_agree_and_the_second_simulation_is_given_back() {
    let simulation = run_against(image(), 5, no_writes, interpreted).unwrap();
    assert_eq!(simulation.cycles(), [5]);
    assert_eq!(
        value::read(simulation.engine(), "Main.n"),
        Ok(Value::Int(5, Elementary::Dint))
    );
    // 1 + 2 + 3 + 4 + 5.
    assert_eq!(
        value::read(simulation.engine(), "Main.s[2].b"),
        Ok(Value::Int(15, Elementary::Dint))
    );
}

#[test]
fn one_corrupted_byte_is_found_and_named_by_its_member_and_element_path() {
    let second = corrupted(|engine| engine.region_mut(Region::Data)[S2_B] ^= 1);
    let difference = differs(run_against(image(), 5, no_writes, second));
    assert_eq!(difference.cycle, 0);
    assert_eq!(
        difference.subject,
        Subject::Memory {
            region: Region::Data,
            offset: S2_B,
            path: Some("Main.s[2].b".to_owned()),
        }
    );
    assert_eq!(difference.first, "0 (16#00000000)");
    assert_eq!(difference.second, "1 (16#00000001)");
    assert_eq!(
        difference.to_string(),
        "after cycle 0, Main.s[2].b (data byte 28) differs: the first engine has 0 (16#00000000), \
         the second 1 (16#00000001)"
    );
}

#[test]
fn a_difference_made_by_the_code_is_found_after_the_cycle_that_made_it() {
    // The second engine subtracts where the first adds: equal after loading, different after
    // cycle 1.
    let second = |mut image: ProgramImage| {
        if let Some(Instr::Binary { op, .. }) = image.pous[0].code.first_mut() {
            *op = BinaryOp::Sub;
        }
        interpreted(image)
    };
    let difference = differs(run_against(image(), 5, no_writes, second));
    assert_eq!(difference.cycle, 1);
    assert_eq!(
        difference.subject,
        Subject::Memory {
            region: Region::Data,
            offset: 0,
            path: Some("Main.n".to_owned()),
        }
    );
    assert_eq!(
        (difference.first.as_str(), difference.second.as_str()),
        ("1 (16#00000001)", "-1 (16#FFFFFFFF)")
    );
}

#[test]
fn a_changed_constant_pool_is_found_after_loading() {
    let second = |mut image: ProgramImage| {
        image.constants[4] = 99;
        interpreted(image)
    };
    let difference = differs(run_against(image(), 5, no_writes, second));
    assert_eq!(difference.cycle, 0);
    assert_eq!(difference.subject, Subject::Constants { offset: 4 });
    assert_eq!(
        (difference.first.as_str(), difference.second.as_str()),
        ("16#64", "16#63")
    );
}

#[test]
fn writes_that_differ_between_the_engines_are_the_tests_difference() {
    // A writer that keeps state writes 7 into the first engine and 8 into the second.
    let mut written = 6;
    let writes = |_cycle: u64, engine: &mut Engine| {
        written += 1;
        engine.region_mut(Region::Data)[0..4].copy_from_slice(&i32::to_le_bytes(written));
    };
    let difference = differs(run_against(image(), 2, writes, interpreted));
    assert_eq!(difference.cycle, 1);
    assert!(
        matches!(&difference.subject, Subject::Writes { place } if matches!(**place, Subject::Memory { offset: 0, .. })),
        "{difference}"
    );
    assert!(difference.to_string().contains("Main.n"), "{difference}");
}

#[test]
fn padding_and_bytes_no_symbol_covers_are_named_as_such() {
    let second = corrupted(|engine| engine.region_mut(Region::Data)[PADDING] = 0x5A);
    let difference = differs(run_against(image(), 1, no_writes, second));
    assert_eq!(
        difference.subject.to_string(),
        "Main (padding) (data byte 13)"
    );
    assert_eq!(
        (difference.first.as_str(), difference.second.as_str()),
        ("byte 16#00", "byte 16#5A")
    );
    let second = corrupted(|engine| engine.region_mut(Region::Input)[3] = 7);
    let difference = differs(run_against(image(), 1, no_writes, second));
    assert_eq!(difference.subject.to_string(), "%I byte 3 (no variable)");
    assert_eq!(difference.second, "byte 16#07");
}

#[test]
fn a_located_bit_is_named_when_it_differs_and_its_word_otherwise() {
    let second = corrupted(|engine| engine.region_mut(Region::Input)[0] |= 1 << 3);
    let difference = differs(run_against(image(), 1, no_writes, second));
    assert_eq!(
        difference.subject,
        Subject::Memory {
            region: Region::Input,
            offset: 0,
            path: Some("In_bit".to_owned()),
        }
    );
    assert_eq!(
        (difference.first.as_str(), difference.second.as_str()),
        ("FALSE", "TRUE")
    );
    let second = corrupted(|engine| engine.region_mut(Region::Input)[0] |= 1 << 5);
    let difference = differs(run_against(image(), 1, no_writes, second));
    assert_eq!(difference.subject.to_string(), "In_word (%I byte 0)");
    assert_eq!(difference.second, "32 (16#0020)");
}

#[test]
fn writes_reach_both_engines_and_an_equal_fault_is_no_difference() {
    let simulation = run_against(image(), 5, zero_divisor_before_cycle_3, interpreted).unwrap();
    let faults = simulation.faults();
    assert_eq!(faults.len(), 1, "{faults:?}");
    assert_eq!(faults[0].kind, crate::engine::FaultKind::DivisionByZero);
    assert_eq!(faults[0].line, Some(5));
    // The faulted task runs no more in either engine.
    assert_eq!(simulation.cycles(), [3]);
}

#[test]
fn a_fault_at_another_line_is_a_difference_of_its_cycle() {
    let second = |mut image: ProgramImage| {
        image.pous[0].lines[2].line = 6;
        interpreted(image)
    };
    let difference = differs(run_against(image(), 5, zero_divisor_before_cycle_3, second));
    assert_eq!(difference.cycle, 3);
    assert_eq!(difference.subject, Subject::Fault { index: 0 });
    assert!(difference.first.contains("main.st:5"), "{difference}");
    assert!(difference.second.contains("main.st:6"), "{difference}");
}

#[test]
fn a_load_that_fails_in_one_engine_is_a_difference_of_cycle_0() {
    let second = |mut image: ProgramImage| {
        image.tasks[0].programs[0].pou = 9;
        interpreted(image)
    };
    let difference = differs(run_against(image(), 5, no_writes, second));
    assert_eq!(difference.cycle, 0);
    assert_eq!(difference.subject, Subject::Load);
    assert_eq!(difference.first, "loads");
    assert!(
        difference.second.starts_with("does not load: "),
        "{difference}"
    );
}

/// [`image`] with a function `Recurse` (a frame of 8 bytes in the task's 64-byte stack) that
/// adds `step` to `Main.s[3].b` and calls itself; `Main` calls it first, so its first cycle
/// ends in a stack overflow after `Main.s[3].b` has grown by a few `step`s.
fn recursive_image(op: BinaryOp) -> ProgramImage {
    let mut image = image();
    let recurse = Instr::CallFunction {
        pou: 1,
        instance: None,
        inputs: Vec::new(),
        outputs: Vec::new(),
    };
    image.pous[0].code.insert(0, recurse.clone());
    image.constants.extend(1i32.to_le_bytes());
    let s3_b = Operand::Global(S2_B as u32 + 8);
    image.pous.push(Pou {
        name: "Recurse".to_owned(),
        kind: PouKind::Function,
        frame_size: 8,
        frame_init: Vec::new(),
        instance_size: 0,
        code: vec![
            Instr::Binary {
                op,
                ty: Elementary::Dint,
                dst: s3_b,
                a: s3_b,
                b: Operand::Const(8),
            },
            recurse,
            Instr::Return,
        ],
        lines: Vec::new(),
    });
    image
}

#[test]
fn after_a_stack_overflow_the_memory_is_no_longer_compared_but_the_fault_is() {
    // The second engine's recursion subtracts 1 where the first adds 1 (the same constant
    // pool, so only the memory can differ): after the overflow, which both report in the same
    // task and POU, their memory legitimately differs.
    let second = |_| interpreted(recursive_image(BinaryOp::Sub));
    let simulation = run_against(recursive_image(BinaryOp::Add), 3, no_writes, second).unwrap();
    let faults = simulation.faults();
    assert_eq!(faults.len(), 1, "{faults:?}");
    assert_eq!(faults[0].kind, crate::engine::FaultKind::StackOverflow);
    assert_eq!(faults[0].pou, "Recurse");
    let Ok(Value::Int(grown, _)) = value::read(simulation.engine(), "Main.s[3].b") else {
        panic!("Main.s[3].b reads as a DINT");
    };
    assert!(grown < 0, "{grown}");
}

#[test]
fn the_native_engine_agrees_with_the_interpreter_and_runs_the_image_natively() {
    let simulation = run_both(image(), 5, zero_divisor_before_cycle_3).unwrap();
    assert_eq!(simulation.faults().len(), 1);
    assert_eq!(
        simulation.faults()[0].kind,
        crate::engine::FaultKind::DivisionByZero
    );
    if jit::native_support().is_ok() {
        assert!(simulation.engine().native_report().runs_natively());
        assert!(simulation.engine().native_entries() > 0);
    }
}
