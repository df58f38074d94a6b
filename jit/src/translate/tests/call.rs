//! Inline calls (`docs/native-engine.md` §4.4): frames, transfers, the depth, the stack and
//! native stack limits, the safe point at a call; `CallVirtual` dispatch and `OpenElement`.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use program_image::{InitRun, Transfer};

use super::*;

const F: fn(u32) -> Operand = Operand::Frame;

/// A data offset the methods' instances lie at (below the program's instance).
const OBJECT_AT: u64 = 100;

/// An image of the program `main` (POU 0, on the fixture's instance) and `callees`.
fn fixture(main: Vec<Instr>, callees: Vec<Pou>, stack_size: u32) -> Fixture {
    let mut image = image(main, vec![0; 16]);
    image.layout.stack_size = stack_size;
    image.pous.extend(callees);
    Fixture::of_image(image)
}

fn site(pou: u32, instruction: u32) -> Site {
    Site { pou, instruction }
}

fn transfer(caller: Operand, callee_offset: u32, size: u32) -> Transfer {
    Transfer {
        caller,
        callee_offset,
        size,
    }
}

fn add(dst: Operand, a: Operand, b: Operand) -> Instr {
    Instr::Binary {
        op: BinaryOp::Add,
        ty: Dint,
        dst,
        a,
        b,
    }
}

/// Runs POU 0 with `native_stack_limit` and `due` as given.
fn run_entry(fixture: &Fixture, host: &mut TestHost, native_stack_limit: u64, due: bool) -> Status {
    let due = AtomicBool::new(due);
    let mut counters = Counters {
        depth: 0,
        budget: 4096,
    };
    let entry = Entry {
        instance: INSTANCE_AT,
        frame: fixture.frame_at(),
        stack_end: fixture.layout.stacks + fixture.layout.stack_size,
        native_stack_limit,
        due: &due,
        now_ns: 0,
    };
    let status = fixture.code.run(0, host, entry, &mut counters);
    // Every call counted in is counted out, faulted or not (the interpreter's `pop_depth`).
    assert_eq!(counters.depth, 0);
    status
}

/// `F(a) := a + seven`, where `seven` is the frame's initial value 7 and `untouched` a
/// variable the body does not write, which the new frame must have zeroed.
fn adder(frame_size: u32) -> Pou {
    let mut adder = pou(
        "Add7",
        PouKind::Function,
        frame_size,
        0,
        vec![add(F(4), F(0), F(8))],
    );
    adder.frame_init = vec![InitRun {
        offset: 8,
        bytes: vec![7, 0, 0, 0],
    }];
    adder
}

fn call_adder() -> Instr {
    Instr::CallFunction {
        pou: 1,
        instance: None,
        inputs: vec![transfer(I(0), 0, 4)],
        outputs: vec![transfer(I(8), 4, 4), transfer(I(12), 12, 4)],
    }
}

#[test]
fn a_function_gets_a_prepared_frame_and_its_transfers() {
    // A frame of 16 bytes is prepared by inline stores, one of 100 by the host.
    for frame_size in [16, 100] {
        let fixture = fixture(vec![call_adder()], vec![adder(frame_size)], 512);
        let mut host = fixture.host();
        host.put(0, 35, 4);
        // The callee's frame holds old bytes, which a new frame does not show.
        let callee_frame = fixture.frame_at() + u64::from(FRAME_SIZE);
        host.memory[callee_frame as usize..][..frame_size as usize].fill(0xAA);
        assert_eq!(fixture.run(&mut host), Status::Ok);
        assert_eq!(host.get(8, 4), 42, "frame of {frame_size} bytes");
        assert_eq!(host.get(12, 4), 0, "frame of {frame_size} bytes");
        assert!(host.ops.is_empty(), "the call is made inline");
        if frame_size > 64 {
            assert_eq!(host.frames, vec![(1, callee_frame)]);
        } else {
            assert!(host.frames.is_empty());
        }
    }
}

#[test]
fn outputs_are_not_copied_back_from_a_faulted_call() {
    let divider = pou(
        "Divide",
        PouKind::Function,
        16,
        0,
        vec![
            Instr::Move {
                ty: Dint,
                dst: F(4),
                src: F(0),
            },
            Instr::Binary {
                op: BinaryOp::Div,
                ty: Dint,
                dst: F(8),
                a: F(0),
                b: F(12),
            },
        ],
    );
    let call = Instr::CallFunction {
        pou: 1,
        instance: None,
        inputs: vec![transfer(I(0), 0, 4)],
        outputs: vec![transfer(I(8), 4, 4)],
    };
    let fixture = fixture(vec![call], vec![divider], 512);
    let mut host = fixture.host();
    host.put(0, 5, 4);
    host.put(8, 99, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.get(8, 4), 99);
    // The innermost site, alone: the caller only returns `Faulted`.
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::DivisionByZero)]);
}

#[test]
fn recursion_faults_at_depth_2000() {
    // The method `Recurse` counts itself in its instance, then calls itself on the instance
    // its pointer parameter (frame 0) reaches.
    let call = |pointer: Operand| Instr::CallFunction {
        pou: 1,
        instance: Some(pointer),
        inputs: vec![transfer(pointer, 0, 8)],
        outputs: Vec::new(),
    };
    let recurse = pou(
        "Recurse",
        PouKind::Method,
        8,
        8,
        vec![add(I(0), I(0), I(4)), call(F(0))],
    );
    let fixture = fixture(vec![call(I(40))], vec![recurse], 16_384);
    let mut host = fixture.host();
    host.put(40, 1 << 56 | OBJECT_AT, 8);
    host.memory[OBJECT_AT as usize + 4] = 1;
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Faulted);
    let count = &host.memory[OBJECT_AT as usize..][..4];
    assert_eq!(u32::from_le_bytes(count.try_into().unwrap()), 2000);
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::StackOverflow)]);
}

#[test]
fn a_frame_past_the_stack_and_a_low_native_stack_overflow() {
    // The program's frame is 128 bytes of a 256-byte stack; the callee's 200 do not fit.
    let fixture = fixture(vec![call_adder()], vec![adder(200)], 256);
    let mut host = fixture.host();
    host.put(8, 99, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, vec![(site(0, 0), NativeFault::StackOverflow)]);
    assert_eq!(host.get(8, 4), 99);
    assert!(host.frames.is_empty());
    // A frame that fits, but a machine stack below its limit.
    let fixture = self::fixture(vec![call_adder()], vec![adder(16)], 256);
    let mut host = fixture.host();
    assert_eq!(
        run_entry(&fixture, &mut host, u64::MAX, false),
        Status::Faulted
    );
    assert_eq!(host.faults, vec![(site(0, 0), NativeFault::StackOverflow)]);
    // And with a limit far below the stack pointer, the call is made.
    let mut host = fixture.host();
    host.put(0, 1, 4);
    assert_eq!(run_entry(&fixture, &mut host, 4096, false), Status::Ok);
    assert_eq!(host.get(8, 4), 8);
}

#[test]
fn a_call_is_a_safe_point() {
    // The call is instruction 1: the safe point's site is the call's.
    let fixture = fixture(
        vec![
            Instr::Move {
                ty: Dint,
                dst: I(20),
                src: I(0),
            },
            call_adder(),
        ],
        vec![adder(16)],
        512,
    );
    let mut host = fixture.host();
    assert_eq!(run_entry(&fixture, &mut host, 0, true), Status::Ok);
    let sites: Vec<Site> = host.ticks.iter().map(|(site, _)| *site).collect();
    assert_eq!(sites, vec![site(0, 1)]);
    assert_eq!(host.ticks[0].1.depth, 0);
    let mut host = fixture.host();
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Ok);
    assert!(host.ticks.is_empty());
}

/// `FB.body`: `Instance(0) += Instance(4)`.
fn block() -> Pou {
    pou(
        "Counter",
        PouKind::FunctionBlock,
        8,
        8,
        vec![add(I(0), I(0), I(4))],
    )
}

#[test]
fn blocks_run_on_their_instance_direct_or_through_a_pointer() {
    let main = vec![
        Instr::CallBlock {
            pou: 1,
            instance: I(32),
            indirect: false,
        },
        Instr::CallBlock {
            pou: 1,
            instance: I(48),
            indirect: true,
        },
    ];
    let fixture = fixture(main, vec![block()], 512);
    let mut host = fixture.host();
    host.put(32, 10, 4);
    host.put(36, 5, 4);
    // The pointer reaches the object in the data region (tag 1).
    host.put(48, 1 << 56 | OBJECT_AT, 8);
    host.memory[OBJECT_AT as usize..][..4].copy_from_slice(&100u32.to_le_bytes());
    host.memory[OBJECT_AT as usize + 4..][..4].copy_from_slice(&3u32.to_le_bytes());
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(32, 4), 15);
    assert_eq!(host.memory[OBJECT_AT as usize], 103);
    // A null instance pointer faults at the call.
    let mut host = fixture.host();
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, vec![(site(0, 1), NativeFault::NullPointer)]);
    // So does one whose instance does not fit its region.
    let mut host = fixture.host();
    let near_end = 1 << 56 | u64::from(DATA - 4);
    host.put(48, near_end, 8);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(
        host.faults,
        vec![(site(0, 1), NativeFault::BadPointer(near_end))]
    );
}

/// A method writing `tag` into its instance's first byte and its input into the second.
fn method(name: &str, tag: u64) -> Pou {
    let mut method = pou(
        name,
        PouKind::Method,
        8,
        8,
        vec![
            Instr::Move {
                ty: Usint,
                dst: I(0),
                src: Operand::Const(tag as u32),
            },
            Instr::Move {
                ty: Usint,
                dst: I(1),
                src: F(0),
            },
        ],
    );
    method.instance_size = 8;
    method
}

#[test]
fn call_virtual_picks_the_first_method_of_the_class() {
    let main = vec![Instr::CallVirtual {
        // POUs 4 and 5 are the classes.
        table: vec![(4, 1), (5, 2), (4, 3)],
        interface: I(0),
        inputs: vec![transfer(I(16), 0, 1)],
        outputs: Vec::new(),
    }];
    let mut image = image(main, vec![0, 1, 2, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    image
        .pous
        .extend([method("A.M", 1), method("B.M", 2), method("C.M", 3)]);
    let class = |name: &str| pou(name, PouKind::FunctionBlock, 0, 8, Vec::new());
    image.pous.extend([class("A"), class("B")]);
    let fixture = Fixture::of_image(image);
    let pointer = 1 << 56 | OBJECT_AT;
    for (class, expected) in [(4u64, 1u8), (5, 2)] {
        let mut host = fixture.host();
        host.put(0, pointer, 8);
        host.put(8, class, 4);
        host.put(16, 0x44, 1);
        assert_eq!(fixture.run(&mut host), Status::Ok, "class {class}");
        assert_eq!(
            host.memory[OBJECT_AT as usize..][..2],
            [expected, 0x44],
            "class {class}"
        );
    }
    for listing in &fixture.code.listings {
        assert!(!listing.contains("trap"), "{listing}");
    }
    // An unknown class is a bad pointer, a null interface a null pointer.
    let mut host = fixture.host();
    host.put(0, pointer, 8);
    host.put(8, 9, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(
        host.faults,
        vec![(site(0, 0), NativeFault::BadPointer(pointer))]
    );
    let mut host = fixture.host();
    host.put(8, 4, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, vec![(site(0, 0), NativeFault::NullPointer)]);
    // A pointer to the region's last 4 bytes reaches 0 bytes, but not the method's instance.
    let mut host = fixture.host();
    let near_end = 1 << 56 | u64::from(DATA - 4);
    host.put(0, near_end, 8);
    host.put(8, 5, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(
        host.faults,
        vec![(site(0, 0), NativeFault::BadPointer(near_end))]
    );
}

#[test]
fn open_element_checks_each_dimension() {
    // ARRAY[-1..1, 10..13] OF DINT: the descriptor at I(0), indices at I(64) (DINT) and
    // I(68) (INT), the element pointer written at I(80).
    let main = vec![Instr::OpenElement {
        dst: I(80),
        descriptor: I(0),
        indices: vec![(I(64), Dint), (I(68), Int)],
        stride: 4,
    }];
    let fixture = Fixture::new(main);
    let array = 1 << 56 | 40;
    let prepared = |i: i64, j: i64| {
        let mut host = fixture.host();
        host.put(0, array, 8);
        host.put(8, (-1i64) as u64, 8);
        host.put(16, 1, 8);
        host.put(24, 10, 8);
        host.put(32, 13, 8);
        host.put(64, i as u64, 4);
        host.put(68, j as u64, 2);
        host
    };
    for i in -2..=2 {
        for j in 9..=14 {
            let mut host = prepared(i, j);
            let status = fixture.run(&mut host);
            if !(-1..=1).contains(&i) {
                assert_eq!(status, Status::Faulted);
                let fault = NativeFault::IndexOutOfBounds {
                    index: i,
                    low: -1,
                    high: 1,
                };
                assert_eq!(host.faults, vec![(site(0, 0), fault)]);
            } else if !(10..=13).contains(&j) {
                assert_eq!(status, Status::Faulted);
                let fault = NativeFault::IndexOutOfBounds {
                    index: j,
                    low: 10,
                    high: 13,
                };
                assert_eq!(host.faults, vec![(site(0, 0), fault)]);
            } else {
                assert_eq!(status, Status::Ok);
                let linear = (i + 1) * 4 + (j - 10);
                assert_eq!(host.get(80, 8), array + linear as u64 * 4);
            }
        }
    }
}

#[test]
fn a_call_of_a_refused_pou_goes_to_the_interpreter() {
    let mut refused = adder(16);
    refused.name = crate::translate::REFUSED_IN_TESTS.into();
    // POU 2 calls nothing: only POU 0, the refused POU's caller, is translated again.
    let unrelated = adder(16);
    crate::translate::TRANSLATED_IN_TESTS.with(|translated| translated.borrow_mut().clear());
    let fixture = fixture(vec![call_adder()], vec![refused, unrelated], 512);
    let translated = crate::translate::TRANSLATED_IN_TESTS.with(|translated| translated.take());
    assert_eq!(translated, vec![0, 1, 2, 0]);
    assert!(fixture.code.has(0));
    assert!(!fixture.code.has(1));
    assert!(fixture.code.has(2));
    let mut host = fixture.host();
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(
        host.ops,
        vec![(site(0, 0), INSTANCE_AT, fixture.frame_at())]
    );
}

#[test]
fn nested_calls_count_their_depth_and_copy_large_transfers() {
    // `Outer(s)` passes its 100-byte `s` on to `Inner`, which returns it with its first
    // byte incremented; the transfers over 64 bytes are made by the host's `copy`. With
    // `due` set, each call's safe point shows the depth the interpreter counts there.
    let inner = pou(
        "Inner",
        PouKind::Function,
        104,
        0,
        vec![Instr::Binary {
            op: BinaryOp::Add,
            ty: Usint,
            dst: F(0),
            a: F(0),
            b: Operand::Const(0),
        }],
    );
    let outer = pou(
        "Outer",
        PouKind::Function,
        104,
        0,
        vec![
            Instr::Move {
                ty: Dint,
                dst: F(100),
                src: F(0),
            },
            Instr::CallFunction {
                pou: 2,
                instance: None,
                inputs: vec![transfer(F(0), 0, 100)],
                outputs: vec![transfer(F(0), 0, 100)],
            },
        ],
    );
    let main = vec![Instr::CallFunction {
        pou: 1,
        instance: None,
        inputs: vec![transfer(I(0), 0, 100)],
        outputs: vec![transfer(I(100), 0, 100)],
    }];
    let mut image = image(main, vec![1; 16]);
    image.layout.stack_size = 1024;
    image.pous.extend([outer, inner]);
    let fixture = Fixture::of_image(image);
    let mut host = fixture.host();
    for offset in 0..100 {
        host.put(offset, u64::from(offset), 1);
    }
    assert_eq!(run_entry(&fixture, &mut host, 0, true), Status::Ok);
    assert_eq!(host.get(100, 1), 1);
    for offset in 1..100 {
        assert_eq!(host.get(100 + offset, 1), u64::from(offset));
    }
    let depths = tick_depths(&host);
    assert_eq!(depths, vec![(site(0, 0), 0), (site(1, 1), 1)]);
    // Calls, frames and transfers emit no trap (§7 rule 5).
    for listing in &fixture.code.listings {
        assert!(!listing.contains("trap"), "{listing}");
    }
    // Both frames are prepared by the host, being over 64 bytes.
    let outer_frame = fixture.frame_at() + u64::from(FRAME_SIZE);
    assert_eq!(host.frames, vec![(1, outer_frame), (2, outer_frame + 104)]);
}

/// `Nest` (POU 1) calls `Leaf` (POU 2) through `Leaf`'s enter stub at its instruction 1,
/// after a move; `Leaf` adds its instance's second DINT to its first.
fn nested_block_calls(leaf_frame_size: u32) -> Vec<Pou> {
    let nest = pou(
        "Nest",
        PouKind::FunctionBlock,
        8,
        16,
        vec![
            Instr::Move {
                ty: Dint,
                dst: I(12),
                src: I(0),
            },
            Instr::CallBlock {
                pou: 2,
                instance: I(0),
                indirect: false,
            },
        ],
    );
    let leaf = pou(
        "Leaf",
        PouKind::FunctionBlock,
        leaf_frame_size,
        8,
        vec![add(I(0), I(0), I(4))],
    );
    vec![nest, leaf]
}

fn call_nest() -> Instr {
    Instr::CallBlock {
        pou: 1,
        instance: I(32),
        indirect: false,
    }
}

#[test]
fn the_enter_stub_reports_a_frame_past_the_stack_at_its_call_site() {
    // The program's frame is 128 bytes of a 256-byte stack, `Nest`'s 8 follow; `Leaf`'s 200
    // do not fit, 16 do.
    let fixture = fixture(vec![call_nest()], nested_block_calls(200), 256);
    let mut host = fixture.host();
    host.put(32, 5, 4);
    host.put(36, 3, 4);
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Faulted);
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::StackOverflow)]);
    // Nothing of `Leaf` ran, and the move before the call did.
    assert_eq!(host.get(32, 4), 5);
    assert_eq!(host.get(44, 4), 5);
    assert!(host.frames.is_empty());
    let fixture = self::fixture(vec![call_nest()], nested_block_calls(16), 256);
    let mut host = fixture.host();
    host.put(32, 5, 4);
    host.put(36, 3, 4);
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Ok);
    assert_eq!(host.get(32, 4), 8);
    // A machine stack below its limit is found by the stub at the first call site.
    let mut host = fixture.host();
    assert_eq!(
        run_entry(&fixture, &mut host, u64::MAX, false),
        Status::Faulted
    );
    assert_eq!(host.faults, vec![(site(0, 0), NativeFault::StackOverflow)]);
    // With `due` set, both stubs make their safe point at their call sites, at the depth
    // counted before them, and the calls go on with their instances and frames.
    let mut host = fixture.host();
    host.put(32, 5, 4);
    host.put(36, 3, 4);
    assert_eq!(run_entry(&fixture, &mut host, 0, true), Status::Ok);
    assert_eq!(host.get(32, 4), 8);
    assert_eq!(host.get(44, 4), 5);
    let depths = tick_depths(&host);
    assert_eq!(depths, vec![(site(0, 0), 0), (site(1, 1), 1)]);
}

#[test]
fn a_block_calling_itself_faults_at_depth_2000_through_its_enter_stub() {
    // `Again` counts itself in its instance, then calls itself on the same instance.
    let again = pou(
        "Again",
        PouKind::FunctionBlock,
        8,
        8,
        vec![
            add(I(0), I(0), I(4)),
            Instr::CallBlock {
                pou: 1,
                instance: I(0),
                indirect: false,
            },
        ],
    );
    let main = vec![Instr::CallBlock {
        pou: 1,
        instance: I(32),
        indirect: false,
    }];
    let fixture = fixture(main, vec![again], 32_768);
    let mut host = fixture.host();
    host.put(36, 1, 4);
    let mut counters = Counters {
        depth: 0,
        budget: 4096,
    };
    let due = AtomicBool::new(false);
    assert_eq!(
        fixture.run_with(&mut host, &due, &mut counters),
        Status::Faulted
    );
    assert_eq!(host.get(32, 4), 2000);
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::StackOverflow)]);
    assert_eq!(counters.depth, 0);
    // Entered at depth 1 (an interpreted caller counted the program's call), one call less.
    let mut host = fixture.host();
    host.put(36, 1, 4);
    counters.depth = 1;
    assert_eq!(
        fixture.run_with(&mut host, &due, &mut counters),
        Status::Faulted
    );
    assert_eq!(host.get(32, 4), 1999);
    assert_eq!(counters.depth, 1);
}

#[test]
fn a_callee_instance_past_the_memory_is_a_memory_fault_at_the_call_site() {
    // A function on the caller's instance (256 bytes at 256) whose instance is larger than
    // the caller's: checked at the call site, as the caller's own instance covers only its
    // own size.
    let wide = |instance_size: u32| {
        let mut wide = adder(16);
        wide.instance_size = instance_size;
        wide
    };
    let main = vec![
        Instr::Move {
            ty: Dint,
            dst: I(20),
            src: I(0),
        },
        call_adder(),
    ];
    let fixture = fixture(main.clone(), vec![wide(1 << 20)], 512);
    let mut host = fixture.host();
    host.put(0, 35, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, vec![(site(0, 1), NativeFault::Memory)]);
    assert_eq!(host.get(8, 4), 0);
    // A larger instance that still lies inside the memory is called.
    let fixture = self::fixture(main, vec![wide(INSTANCE_SIZE + 64)], 512);
    let mut host = fixture.host();
    host.put(0, 35, 4);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(8, 4), 42);
}

#[test]
fn a_large_frame_the_host_cannot_prepare_is_a_memory_fault_at_the_call_site() {
    // `Leaf`'s 100-byte frame is prepared by `rivet_jit_frame`; a host that fails it (here
    // one that knows no POU's frame) makes the stub record `Memory` at `Nest`'s call.
    let fixture = fixture(vec![call_nest()], nested_block_calls(100), 512);
    let mut host = fixture.host();
    host.frame_shapes.clear();
    host.put(32, 5, 4);
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Faulted);
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::Memory)]);
    assert_eq!(host.frames.len(), 1);
    // With the frame prepared, the call runs.
    let mut host = fixture.host();
    host.put(32, 5, 4);
    host.put(36, 3, 4);
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Ok);
    assert_eq!(host.get(32, 4), 8);
}

/// `Pass` (POU 1, a function on its caller's instance, of which it reads and writes the first
/// 128 bytes) notes its DINT input at I(12), then at
/// its instruction 1 calls `Sum` (POU 2) through `Sum`'s prepare stub, with the
/// `input_bytes` bytes at I(16) as `Sum`'s input and `Sum`'s result copied back into I(8).
/// `Sum` (a frame of `sum_frame_size` bytes) adds the input's last DINT to its first.
fn calls_with_inputs(input_bytes: u32, sum_frame_size: u32) -> Vec<Pou> {
    let pass = pou(
        "Pass",
        PouKind::Function,
        8,
        128,
        vec![
            Instr::Move {
                ty: Dint,
                dst: I(12),
                src: F(0),
            },
            Instr::CallFunction {
                pou: 2,
                instance: None,
                inputs: vec![transfer(I(16), 0, input_bytes)],
                outputs: vec![transfer(I(8), input_bytes, 4)],
            },
        ],
    );
    let sum = pou(
        "Sum",
        PouKind::Function,
        sum_frame_size,
        0,
        vec![add(F(input_bytes), F(0), F(input_bytes - 4))],
    );
    vec![pass, sum]
}

/// The program's call of `Pass` through `Pass`'s prepare stub, with I(0) as its input.
fn call_pass() -> Instr {
    Instr::CallFunction {
        pou: 1,
        instance: None,
        inputs: vec![transfer(I(0), 0, 4)],
        outputs: Vec::new(),
    }
}

/// A host for [`calls_with_inputs`]`(input_bytes, _)`: `Pass`'s input 5, `Sum`'s first and
/// last input DINTs 3 and 4, 99 where `Sum`'s result goes, and the stack past the program's
/// frame (`Pass`'s frame, then `Sum`'s) filled with 0xAA, so that a frame prepared or an input
/// copied shows.
fn host_with_inputs(fixture: &Fixture, input_bytes: u32) -> TestHost {
    let mut host = fixture.host();
    host.put(0, 5, 4);
    host.put(16, 3, 4);
    host.put(16 + input_bytes - 4, 4, 4);
    host.put(8, 99, 4);
    let callee_frames = fixture.frame_at() + u64::from(FRAME_SIZE);
    let stack_end = fixture.layout.stacks + fixture.layout.stack_size;
    host.memory[callee_frames as usize..stack_end as usize].fill(0xAA);
    host
}

/// Whether the stack from `from` to its end still holds the filler of [`host_with_inputs`].
fn untouched_from(fixture: &Fixture, host: &TestHost, from: u64) -> bool {
    let stack_end = fixture.layout.stacks + fixture.layout.stack_size;
    host.memory[from as usize..stack_end as usize]
        .iter()
        .all(|byte| *byte == 0xAA)
}

#[test]
fn the_prepare_stub_reports_a_frame_past_the_stack_at_its_call_site() {
    // The program's frame is 128 bytes of a 256-byte stack, `Pass`'s 8 follow; `Sum`'s 200
    // do not fit, 12 do.
    let fixture = fixture(vec![call_pass()], calls_with_inputs(8, 200), 256);
    let sum_frame = fixture.frame_at() + u64::from(FRAME_SIZE) + 8;
    let mut host = host_with_inputs(&fixture, 8);
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Faulted);
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::StackOverflow)]);
    // `Pass` ran up to its call; `Sum`'s frame was neither prepared nor given its input, and
    // nothing was copied back.
    assert_eq!(host.get(12, 4), 5);
    assert!(untouched_from(&fixture, &host, sum_frame));
    assert_eq!(host.get(8, 4), 99);
    assert!(host.frames.is_empty() && host.copies.is_empty());
    let fixture = self::fixture(vec![call_pass()], calls_with_inputs(8, 12), 256);
    let mut host = host_with_inputs(&fixture, 8);
    assert_eq!(run_entry(&fixture, &mut host, 0, false), Status::Ok);
    assert_eq!(host.get(8, 4), 7);
    // A machine stack below its limit is found by the program's own call site's stub, before
    // `Pass`'s input is copied.
    let mut host = host_with_inputs(&fixture, 8);
    assert_eq!(
        run_entry(&fixture, &mut host, u64::MAX, false),
        Status::Faulted
    );
    assert_eq!(host.faults, vec![(site(0, 0), NativeFault::StackOverflow)]);
    let pass_frame = fixture.frame_at() + u64::from(FRAME_SIZE);
    assert!(untouched_from(&fixture, &host, pass_frame));
    assert_eq!(host.get(12, 4), 0);
    // With `due` set, both stubs make their safe point at their call sites, at the depth
    // counted before them, and the calls go on with their inputs.
    let mut host = host_with_inputs(&fixture, 8);
    assert_eq!(run_entry(&fixture, &mut host, 0, true), Status::Ok);
    assert_eq!((host.get(12, 4), host.get(8, 4)), (5, 7));
    let depths = tick_depths(&host);
    assert_eq!(depths, vec![(site(0, 0), 0), (site(1, 1), 1)]);
}

#[test]
fn a_call_with_inputs_stops_at_its_call_site_when_the_safe_point_ends_the_cycle() {
    let fixture = fixture(vec![call_pass()], calls_with_inputs(8, 12), 256);
    let pass_frame = fixture.frame_at() + u64::from(FRAME_SIZE);
    // The cycle ends at the program's call of `Pass`, then at `Pass`'s call of `Sum`.
    for (stop, untouched_stack, noted_input) in
        [(site(0, 0), pass_frame, 0), (site(1, 1), pass_frame + 8, 5)]
    {
        let mut host = host_with_inputs(&fixture, 8);
        host.stop_at = Some(stop);
        // `run_entry` checks that the depth counted in by the outer stub is counted out.
        assert_eq!(run_entry(&fixture, &mut host, 0, true), Status::Faulted);
        let depths = tick_depths(&host);
        let expected = [(site(0, 0), 0), (site(1, 1), 1)];
        let reached = if stop == site(0, 0) { 1 } else { 2 };
        assert_eq!(depths, expected[..reached], "stopped at {stop:?}");
        // The host records the safe point's fault; the stub records none of its own.
        assert!(host.faults.is_empty(), "stopped at {stop:?}");
        // The stopped call's frame was neither prepared nor given its input, and the caller
        // went no further.
        assert!(
            untouched_from(&fixture, &host, untouched_stack),
            "stopped at {stop:?}"
        );
        assert_eq!(host.get(12, 4), noted_input, "stopped at {stop:?}");
        assert_eq!(host.get(8, 4), 99, "stopped at {stop:?}");
    }
}

#[test]
fn an_input_over_64_bytes_is_copied_by_the_host_into_the_prepared_frame() {
    // `Sum` takes 100 bytes and its frame is 104: the host prepares the frame (over 64
    // bytes), then copies the input into it (over 64 bytes), after the stub's checks.
    let fixture = fixture(vec![call_pass()], calls_with_inputs(100, 104), 256);
    let sum_frame = fixture.frame_at() + u64::from(FRAME_SIZE) + 8;
    let input = INSTANCE_AT + 16;
    let mut host = host_with_inputs(&fixture, 100);
    assert_eq!(run_entry(&fixture, &mut host, 0, true), Status::Ok);
    // Zeroed after the copy, the frame would hold no input and the sum would be 0.
    assert_eq!(host.get(8, 4), 7);
    assert_eq!(host.frames, vec![(2, sum_frame)]);
    // `Pass`'s 4-byte input is copied inline.
    assert_eq!(host.copies, vec![(sum_frame, input, 100)]);
    let depths = tick_depths(&host);
    assert_eq!(depths, vec![(site(0, 0), 0), (site(1, 1), 1)]);
    // A copy the host refuses is `Memory` at `Pass`'s call site; `Sum` does not run, and
    // its depth stays counted, as the interpreter's `?` leaves it after `push_frame` (§4.4):
    // the program's call of `Pass` counts its own out.
    let mut host = host_with_inputs(&fixture, 100);
    host.refuse_copies = true;
    let mut counters = Counters {
        depth: 0,
        budget: 4096,
    };
    let due = AtomicBool::new(false);
    assert_eq!(
        fixture.run_with(&mut host, &due, &mut counters),
        Status::Faulted
    );
    assert_eq!(host.faults, vec![(site(1, 1), NativeFault::Memory)]);
    assert_eq!(host.copies, vec![(sum_frame, input, 100)]);
    assert_eq!(host.get(8, 4), 99);
    // The prepared frame holds zeros where the sum would be.
    let result = &host.memory[sum_frame as usize + 100..][..4];
    assert_eq!(result, [0; 4]);
    assert_eq!(counters.depth, 1);
}

#[test]
fn call_sites_share_their_callee_stub() {
    // The code a call site adds stays small: the checks, the frame and the depth are the
    // stub's, made once per callee (§9.2). Measured as the bytes 100 more call sites add.
    let calls = |count: usize| -> u64 {
        let main = (0..count)
            .map(|at| Instr::CallBlock {
                pou: 1,
                instance: I(32 + 8 * (at as u32 % 8)),
                indirect: false,
            })
            .collect();
        fixture(main, vec![block()], 512).code.code_bytes()
    };
    let per_site = (calls(200) - calls(100)) / 100;
    // 49 bytes on x86-64 when written; aarch64 instructions take 4 bytes each.
    assert!(per_site <= 96, "{per_site} bytes per call site");
}

/// The site and the call depth of every tick the host saw, in order.
fn tick_depths(host: &TestHost) -> Vec<(Site, u32)> {
    host.ticks
        .iter()
        .map(|(site, counters)| (*site, counters.depth))
        .collect()
}
