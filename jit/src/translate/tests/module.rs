//! Operation codes, layouts, pure functions, library calls, forward jumps, the machine code's
//! traps and constant folding.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use program_image::Transfer;

use super::real::real_code;
use super::*;

#[test]
fn operation_codes_are_the_encoded_variant_indices() {
    for code in 0..16 {
        let unary = crate::unary_op_from_code(code).unwrap();
        assert_eq!(crate::unary_op_code(unary), code);
        let binary = crate::binary_op_from_code(code).unwrap();
        assert_eq!(crate::binary_op_code(binary), code);
    }
    assert_eq!(crate::unary_op_code(UnaryOp::FromBcd), 15);
    assert_eq!(crate::binary_op_code(BinaryOp::Atan2), 15);
    assert!(crate::unary_op_from_code(16).is_none());
}

#[test]
fn a_layout_that_is_not_the_images_is_refused() {
    let image = image(vec![Instr::Return], vec![0; 16]);
    let mut layout = Layout::of(&image, 1);
    layout.constants += 8;
    assert!(matches!(
        Translation::new(&image, &layout, &PURE),
        Err(crate::NativeUnsupported::LayoutMismatch { .. })
    ));
}

#[test]
fn pure_functions_carry_expt_bcd_and_the_real_library() {
    let code = vec![
        Instr::Binary {
            op: BinaryOp::Expt,
            ty: Int,
            dst: I(16),
            a: I(0),
            b: I(2),
        },
        Instr::Unary {
            op: UnaryOp::ToBcd,
            ty: Word,
            dst: I(18),
            src: I(4),
        },
        Instr::Unary {
            op: UnaryOp::FromBcd,
            ty: Word,
            dst: I(20),
            src: I(6),
        },
        Instr::Unary {
            op: UnaryOp::Ln,
            ty: Lreal,
            dst: I(24),
            src: I(8),
        },
        Instr::Binary {
            op: BinaryOp::Expt,
            ty: Real,
            dst: I(32),
            a: I(36),
            b: I(40),
        },
    ];
    let fixture = Fixture::new(code);
    let mut host = fixture.host();
    host.put(0, 3, 2);
    host.put(2, 5, 2);
    host.put(4, 1234, 2);
    host.put(6, 0x0987, 2);
    host.put(8, 10f64.to_bits(), 8);
    host.put(36, u64::from(2f32.to_bits()), 4);
    host.put(40, u64::from(0.5f32.to_bits()), 4);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(16, 2), 243);
    assert_eq!(host.get(18, 2), 0x1234);
    assert_eq!(host.get(20, 2), 987);
    assert_eq!(host.get(24, 8), 10f64.ln().to_bits());
    assert_eq!(host.get(32, 4), u64::from(2f32.powf(0.5).to_bits()));
}

#[test]
fn library_calls_other_than_the_float_roundings_are_foreign() {
    use cranelift_codegen::ir::LibCall;
    for call in [
        LibCall::FloorF32,
        LibCall::CeilF64,
        LibCall::TruncF64,
        LibCall::NearestF32,
    ] {
        let name = crate::translate::host_calls::libcall_name(call);
        assert!(OUR_SYMBOLS.contains(&name.as_str()), "{name}");
    }
    for call in [
        LibCall::Memcpy,
        LibCall::Memset,
        LibCall::FmaF64,
        LibCall::Probestack,
    ] {
        let name = crate::translate::host_calls::libcall_name(call);
        assert!(!OUR_SYMBOLS.contains(&name.as_str()), "{name}");
    }
}

#[test]
fn forward_jumps_skip_and_fall_through() {
    // IF c THEN x := 1 END_IF; a jump to the next instruction; y := 2 after a Return is never run.
    let code = vec![
        Instr::JumpIfNot {
            cond: I(0),
            target: 2,
        },
        Instr::Move {
            ty: Sint,
            dst: I(1),
            src: I(8),
        },
        Instr::JumpIf {
            cond: I(0),
            target: 3,
        },
        Instr::Jump { target: 5 },
        Instr::Move {
            ty: Sint,
            dst: I(2),
            src: I(8),
        },
        Instr::Return,
        Instr::Move {
            ty: Sint,
            dst: I(3),
            src: I(8),
        },
    ];
    let fixture = Fixture::new(code);
    for condition in [0u64, 1, 2] {
        let mut host = fixture.host();
        host.put(0, condition, 1);
        host.put(8, 7, 1);
        assert_eq!(fixture.run(&mut host), Status::Ok);
        assert_eq!(host.get(1, 1), if condition != 0 { 7 } else { 0 });
        assert_eq!(host.get(2, 1), 0);
        assert_eq!(host.get(3, 1), 0);
    }
}

#[test]
fn generated_code_has_no_trap_but_the_backends_own_unreachable_division_checks() {
    let mut images = vec![real_code(Real), real_code(Lreal)];
    for ty in INTEGERS {
        images.push(vec![
            Instr::Binary {
                op: BinaryOp::Div,
                ty,
                dst: I(16),
                a: I(0),
                b: I(8),
            },
            Instr::Binary {
                op: BinaryOp::Mod,
                ty,
                dst: I(24),
                a: I(0),
                b: I(8),
            },
            Instr::Convert {
                from: Lreal,
                to: ty,
                dst: I(32),
                src: I(40),
            },
            Instr::Trunc {
                from: Real,
                to: ty,
                dst: I(48),
                src: I(40),
            },
            Instr::Load {
                size: 8,
                dst: I(56),
                ptr: I(64),
            },
            Instr::Element {
                dst: I(72),
                base: I(80),
                index: I(88),
                index_ty: ty,
                low: 0,
                count: 10,
                stride: 4,
            },
            Instr::Jump { target: 0 },
        ]);
    }
    for code in images {
        let divisions = code
            .iter()
            .filter(|instr| {
                matches!(
                    instr,
                    Instr::Binary {
                        op: BinaryOp::Div | BinaryOp::Mod,
                        ..
                    }
                )
            })
            .count();
        let fixture = Fixture::new(code);
        let listing = &fixture.code.listings[0];
        assert!(listing.contains("ret"), "{listing}");
        let blocks = Listing::new(listing);
        let checked = blocks.after_a_fault_check();
        let mut trapping_blocks = Vec::new();
        for (block, lines) in blocks.blocks.iter().enumerate() {
            for line in lines.iter().filter(|line| line.contains("trap")) {
                let instruction = line.trim_start();
                // sdiv, srem, udiv and urem keep the backend's own zero test and the division
                // instruction's own fault site; ours make both unreachable, because the only
                // way into their block is past our own zero check.
                let division = ["idiv", "div", "sdiv", "udiv"]
                    .iter()
                    .any(|name| instruction.starts_with(name));
                // aarch64 tests a signed division for MIN / −1 itself (x86-64's lowering does
                // not, so there an overflow trap would be a trapping conversion).
                let overflow = cfg!(target_arch = "aarch64") && line.contains("int_ovf");
                assert!(
                    line.contains("int_divz") || overflow || division,
                    "a trap in generated code: {line}\n{listing}"
                );
                assert!(
                    checked.contains(&block),
                    "a division trap not behind our zero check: {line}\n{listing}"
                );
                if !trapping_blocks.contains(&block) {
                    trapping_blocks.push(block);
                }
            }
        }
        assert!(
            trapping_blocks.len() <= divisions,
            "{} blocks with traps for {divisions} divisions\n{listing}",
            trapping_blocks.len()
        );
    }
}

/// The blocks of a machine code listing (`blockN:` lines start them, `labelN` names them).
struct Listing<'a> {
    blocks: Vec<Vec<&'a str>>,
}

impl<'a> Listing<'a> {
    /// The blocks by their numbers (the listing puts cold blocks last, out of order).
    fn new(listing: &'a str) -> Self {
        let mut blocks: Vec<Vec<&str>> = Vec::new();
        let mut current = None;
        for line in listing.lines() {
            let number = line
                .strip_prefix("block")
                .and_then(|rest| rest.strip_suffix(':'))
                .and_then(|number| number.parse::<usize>().ok());
            if let Some(number) = number {
                if blocks.len() <= number {
                    blocks.resize(number + 1, Vec::new());
                }
                current = Some(number);
            } else if let Some(block) = current {
                blocks[block].push(line);
            }
        }
        Self { blocks }
    }

    /// Whether block `index` is one of our fault exits: from it, jumps only (no two-way
    /// branch) lead through a call out (`rivet_jit_fault`, in the function's shared fault
    /// block) to a return.
    fn is_fault_exit(&self, index: usize) -> bool {
        let mut seen = Vec::new();
        let mut calls = false;
        let mut at = index;
        loop {
            if seen.contains(&at) {
                return false;
            }
            seen.push(at);
            let Some(lines) = self.blocks.get(at) else {
                return false;
            };
            calls |= lines
                .iter()
                .any(|line| line.contains("call") || line.contains("blr"));
            if lines
                .iter()
                .any(|line| line.trim_start().starts_with("ret"))
            {
                return calls;
            }
            let targets: Vec<usize> = lines
                .iter()
                .flat_map(|line| line.split_whitespace().filter_map(label))
                .collect();
            match targets.as_slice() {
                [next] => at = *next,
                _ => return false,
            }
        }
    }

    /// The blocks entered only from a two-way branch whose other way is a fault exit: the
    /// code past one of our checks.
    fn after_a_fault_check(&self) -> Vec<usize> {
        let mut entries: Vec<Vec<(usize, Vec<usize>)>> = vec![Vec::new(); self.blocks.len()];
        for (from, lines) in self.blocks.iter().enumerate() {
            for line in lines {
                let targets: Vec<usize> = line.split_whitespace().filter_map(label).collect();
                for target in &targets {
                    if let Some(entry) = entries.get_mut(*target) {
                        entry.push((from, targets.clone()));
                    }
                }
            }
        }
        (0..self.blocks.len())
            .filter(|block| {
                let ways = &entries[*block];
                !ways.is_empty()
                    && ways.iter().all(|(_, targets)| {
                        targets.len() == 2
                            && targets
                                .iter()
                                .any(|other| other != block && self.is_fault_exit(*other))
                    })
            })
            .collect()
    }
}

/// The block a word of a listing names (`label12`), if it names one.
fn label(word: &str) -> Option<usize> {
    word.trim_matches(|c: char| !c.is_ascii_alphanumeric())
        .strip_prefix("label")?
        .parse()
        .ok()
}

fn constant_reads(first: Vec<Instr>) -> Vec<Instr> {
    let c = Operand::Const;
    first
        .into_iter()
        .chain([
            Instr::Move {
                ty: Real,
                dst: I(0),
                src: c(0),
            },
            Instr::Binary {
                op: BinaryOp::Add,
                ty: Dint,
                dst: I(4),
                a: c(4),
                b: I(8),
            },
            Instr::Compare {
                op: CompareOp::Ne,
                ty: Lreal,
                dst: I(12),
                a: c(8),
                b: c(8),
            },
            Instr::Move {
                ty: Usint,
                dst: I(13),
                src: c(3),
            },
        ])
        .collect()
}

#[test]
fn constants_fold_only_when_nothing_can_write_the_pool() {
    let mut pool = Vec::new();
    pool.extend_from_slice(&0x7F80_0001u32.to_le_bytes()); // a signalling NaN
    pool.extend_from_slice(&(-5i32).to_le_bytes());
    pool.extend_from_slice(&f64::NAN.to_bits().to_le_bytes());
    let harmless = vec![Instr::Move {
        ty: Dint,
        dst: I(100),
        src: I(104),
    }];
    let written = vec![Instr::Move {
        ty: Dint,
        dst: Operand::Const(4),
        src: I(104),
    }];
    // ADR(g) + SHL(LWORD#5, 56) + 4: a pointer moved from the data region into the pool's,
    // then a store through it, as ST's pointer arithmetic allows.
    let stored_through_a_pointer = vec![
        Instr::Address {
            dst: I(112),
            place: Operand::Global(0),
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Lword,
            dst: I(112),
            a: I(112),
            b: I(120),
        },
        Instr::Store {
            size: 4,
            ptr: I(112),
            src: I(104),
        },
    ];
    let read_only = |first: &[Instr]| {
        crate::translate::scalar::constant_pool_is_read_only(&image(
            constant_reads(first.to_vec()),
            pool.clone(),
        ))
    };
    assert!(read_only(&harmless));
    assert!(!read_only(&written));
    assert!(!read_only(&stored_through_a_pointer));
    // Reading the pool through a pointer leaves it read-only.
    assert!(read_only(&[Instr::Address {
        dst: I(100),
        place: Operand::Const(0),
    }]));
    // Every way to write through a pointer makes it writable.
    for writer in [
        Instr::CallBlock {
            pou: 0,
            instance: I(112),
            indirect: true,
        },
        Instr::CallStdBlock {
            block: program_image::StdBlock::RTrig,
            long: false,
            instance: I(112),
            indirect: true,
        },
        Instr::CallFunction {
            pou: 0,
            instance: Some(I(112)),
            inputs: Vec::new(),
            outputs: Vec::new(),
        },
        Instr::CallVirtual {
            table: Vec::new(),
            interface: I(112),
            inputs: Vec::new(),
            outputs: Vec::new(),
        },
        Instr::Native {
            block: "MC_Power".into(),
        },
    ] {
        assert!(!read_only(std::slice::from_ref(&writer)), "{writer:?}");
    }
    for (first, expected_sum) in [
        (harmless, -5i32 + 7),
        (written, 9 + 7),
        (stored_through_a_pointer, 9 + 7),
    ] {
        let fixture = Fixture::with_constants(constant_reads(first), pool.clone());
        let mut host = fixture.host();
        host.put(8, 7, 4);
        host.put(104, 9, 4);
        host.put(120, (5 << 56) + 4, 8);
        assert_eq!(fixture.run(&mut host), Status::Ok);
        assert!(host.faults.is_empty(), "{:?}", host.faults);
        assert_eq!(host.get(0, 4), 0x7F80_0001);
        assert_eq!(host.get(4, 4), u64::from(expected_sum as u32));
        assert_eq!(host.get(12, 1), 1, "NaN is unequal to itself");
        assert_eq!(host.get(13, 1), 0x7F);
    }
}

/// An image of 44 POUs: `Main` (POU 0) runs a `FOR` loop and calls the function blocks
/// 1 ..= 30 (every fifth of which calls the next one too), the functions 31 ..= 40, the
/// function 41 the translator refuses and the function block 42 the code generator panics
/// on; so `Main` is translated again after the first round, and the blocks get enter stubs,
/// the functions prepare stubs. The function block 43, which nothing calls, panics in the
/// translator halfway through its function, and the POUs built after it on the same thread
/// must come out as on one thread.
fn many_pous() -> ProgramImage {
    let add = |dst, a, b| Instr::Binary {
        op: BinaryOp::Add,
        ty: Dint,
        dst,
        a,
        b,
    };
    let block_call = |pou, instance| Instr::CallBlock {
        pou,
        instance,
        indirect: false,
    };
    let function_call = |pou| Instr::CallFunction {
        pou,
        instance: None,
        inputs: vec![Transfer {
            caller: I(8),
            callee_offset: 0,
            size: 4,
        }],
        outputs: vec![Transfer {
            caller: I(12),
            callee_offset: 4,
            size: 4,
        }],
    };
    // FOR I(0) := 1 TO 1000 DO I(4) := I(4) + I(0); END_FOR, the constants 1 and 1000.
    let mut main = vec![
        Instr::Move {
            ty: Dint,
            dst: I(0),
            src: Operand::Const(0),
        },
        Instr::Compare {
            op: CompareOp::Gt,
            ty: Dint,
            dst: Operand::Frame(0),
            a: I(0),
            b: Operand::Const(4),
        },
        Instr::JumpIf {
            cond: Operand::Frame(0),
            target: 6,
        },
        add(I(4), I(4), I(0)),
        add(I(0), I(0), Operand::Const(0)),
        Instr::Jump { target: 1 },
    ];
    main.extend((1..=30).map(|block| block_call(block, I(64 + 8 * (block % 20)))));
    main.extend((31..=41).map(function_call));
    main.push(block_call(42, I(56)));
    let mut constants = vec![0; 16];
    constants[0] = 1;
    constants[4..8].copy_from_slice(&1000u32.to_le_bytes());
    let mut image = image(main, constants);
    image.layout.stack_size = 1024;
    for block in 1..=30u32 {
        // Bodies of different sizes, so that the threads take pieces of different sizes.
        let mut code: Vec<Instr> = (0..=block % 6).map(|_| add(I(0), I(0), I(4))).collect();
        if block % 5 == 0 && block < 30 {
            code.push(block_call(block + 1, I(0)));
        }
        image.pous.push(pou(
            &format!("Block{block}"),
            PouKind::FunctionBlock,
            8,
            8,
            code,
        ));
    }
    for function in 31..=40 {
        image.pous.push(pou(
            &format!("Function{function}"),
            PouKind::Function,
            16,
            0,
            vec![add(Operand::Frame(4), Operand::Frame(0), Operand::Frame(0))],
        ));
    }
    image.pous.push(pou(
        crate::translate::REFUSED_IN_TESTS,
        PouKind::Function,
        16,
        0,
        vec![add(Operand::Frame(4), Operand::Frame(0), Operand::Frame(0))],
    ));
    image.pous.push(pou(
        crate::compile::COMPILE_PANICS_IN_TESTS,
        PouKind::FunctionBlock,
        8,
        8,
        vec![add(I(0), I(0), I(4))],
    ));
    image.pous.push(pou(
        crate::translate::TRANSLATE_PANICS_IN_TESTS,
        PouKind::FunctionBlock,
        8,
        8,
        vec![add(I(0), I(0), I(4))],
    ));
    image
}

#[test]
fn parallel_compilation_defines_the_same_bytes_as_one_thread() {
    use crate::compile::{THREADS_IN_TESTS, Threads};
    let image = many_pous();
    let layout = Layout::of(&image, 1);
    let translate = |threads| {
        crate::translate::TRANSLATED_IN_TESTS.with(|translated| translated.borrow_mut().clear());
        THREADS_IN_TESTS.with(|counts| counts.borrow_mut().clear());
        let table = crate::module::our_symbols(&PURE);
        let code = Translation::with_symbols(&image, &layout, table, threads).unwrap();
        let translated = crate::translate::TRANSLATED_IN_TESTS.with(|translated| translated.take());
        let counts = THREADS_IN_TESTS.with(|counts| counts.take());
        (code, translated, counts)
    };
    let (one, one_translated, one_threads) = translate(Threads::Exactly(1));
    let (four, four_translated, four_threads) = translate(Threads::Exactly(4));
    // Two rounds each: every POU, then `Main` again with its calls of the refused two handed
    // to the interpreter; the first round on four threads, the second (one function) on one.
    let expected_translated: Vec<u32> = (0..=43).chain([0]).collect();
    assert_eq!(one_translated, expected_translated);
    assert_eq!(four_translated, expected_translated);
    assert_eq!(one_threads, vec![1, 1]);
    assert_eq!(four_threads, vec![4, 1]);
    let refused: Vec<(u32, &str)> = four
        .untranslated()
        .iter()
        .map(|refusal| (refusal.pou, refusal.reason.as_str()))
        .collect();
    assert_eq!(
        refused,
        vec![
            (41, "refused by the tests"),
            (42, "the code generator failed on it (an internal error)"),
            (43, "the translator failed on it (an internal error)"),
        ]
    );
    assert_eq!(one.untranslated(), four.untranslated());
    // 41 functions, the 30 blocks' enter stubs and the 10 functions' prepare stubs.
    assert_eq!(four.defined_pieces.len(), 81);
    assert!(
        four.defined_pieces
            .iter()
            .all(|piece| !piece.bytes.is_empty())
    );
    assert_eq!(one.defined_pieces, four.defined_pieces);
    assert_eq!(one.listings, four.listings);
    for code in [&one, &four] {
        assert!((0..=40).all(|pou| code.has(pou)));
        assert!(!code.has(41) && !code.has(42) && !code.has(43));
    }
}
