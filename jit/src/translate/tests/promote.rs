//! Loop promotion (`docs/native-engine.md` §5.3): which loops and places the analysis
//! promotes, and that a promoted place holds the interpreter's value in memory after the
//! loop, at a tick (and is read again after it) and at a fault.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;
use crate::translate::promote::{GUARD_OUTCOMES_IN_TESTS, Guard, promotable_loops};

const C: fn(u32) -> Operand = Operand::Const;
const F: fn(u32) -> Operand = Operand::Frame;
const G: fn(u32) -> Operand = Operand::Global;

/// Constants: 1 at 0, 1000 at 4.
fn constants() -> Vec<u8> {
    let mut constants = vec![0; 16];
    constants[0] = 1;
    constants[4..8].copy_from_slice(&1000u32.to_le_bytes());
    constants
}

fn binary(op: BinaryOp, dst: Operand, a: Operand, b: Operand) -> Instr {
    Instr::Binary {
        op,
        ty: Dint,
        dst,
        a,
        b,
    }
}

/// `FOR i := 1 TO 1000 DO sum := sum + i; END_FOR` with `i` at I(0), `sum` at I(4) and the
/// loop's condition at F(0).
fn for_loop() -> Vec<Instr> {
    vec![
        Instr::Move {
            ty: Dint,
            dst: I(0),
            src: C(0),
        },
        Instr::Compare {
            op: CompareOp::Gt,
            ty: Dint,
            dst: F(0),
            a: I(0),
            b: C(4),
        },
        Instr::JumpIf {
            cond: F(0),
            target: 6,
        },
        binary(BinaryOp::Add, I(4), I(4), I(0)),
        binary(BinaryOp::Add, I(0), I(0), C(0)),
        Instr::Jump { target: 1 },
        Instr::Return,
    ]
}

/// [`for_loop`] with `extra` inserted at the start of its body.
fn for_loop_with(extra: Instr) -> Vec<Instr> {
    let mut code = for_loop();
    code.insert(3, extra);
    code[2] = Instr::JumpIf {
        cond: F(0),
        target: 7,
    };
    code[6] = Instr::Jump { target: 1 };
    code
}

/// How often, on this thread so far, a guard sent its loop to the promoted copy and to the
/// unpromoted one.
fn guard_outcomes() -> (u64, u64) {
    GUARD_OUTCOMES_IN_TESTS.with(|outcomes| {
        (
            outcomes[0].load(Ordering::Relaxed),
            outcomes[1].load(Ordering::Relaxed),
        )
    })
}

fn layout() -> Layout {
    Layout::of(&image(Vec::new(), constants()), 1)
}

#[test]
fn the_analysis_promotes_places_only_their_own_instructions_touch() {
    let loops = promotable_loops(&for_loop(), &layout(), None);
    assert_eq!(loops.len(), 1);
    assert_eq!((loops[0].start, loops[0].end), (1, 5));
    assert_eq!(loops[0].places, vec![(F(0), 1), (I(4), 4), (I(0), 4)]);
    // A store through a pointer may reach any place; a call may read any.
    for intruder in [
        Instr::Store {
            size: 4,
            ptr: I(8),
            src: I(12),
        },
        Instr::CallFunction {
            pou: 0,
            instance: None,
            inputs: Vec::new(),
            outputs: Vec::new(),
        },
    ] {
        let code = for_loop_with(intruder);
        assert!(
            promotable_loops(&code, &layout(), None).is_empty(),
            "{code:?}"
        );
    }
    // A copy over `sum`'s bytes keeps it in memory.
    let code = for_loop_with(Instr::Copy {
        size: 2,
        dst: I(6),
        src: I(40),
    });
    let loops = promotable_loops(&code, &layout(), None);
    assert_eq!(loops[0].places, vec![(F(0), 1), (I(0), 4)]);
    // Places of different bases are disjoint when the guard says so on entry: it holds the
    // ranges touched per base.
    let code = for_loop_with(binary(BinaryOp::Add, G(300), G(300), I(0)));
    let loops = promotable_loops(&code, &layout(), None);
    assert_eq!(
        loops[0].places,
        vec![(F(0), 1), (G(300), 4), (I(4), 4), (I(0), 4)]
    );
    let constants_at = layout().constants;
    let guard = Guard {
        instance: Some((0, 8)),
        frame: Some((0, 1)),
        fixed: [
            Some((300, 304)),
            None,
            None,
            None,
            Some((constants_at, constants_at + 8)),
        ],
    };
    assert_eq!(loops[0].guard, Some(guard));
    // One base, no guard.
    let code = vec![
        binary(BinaryOp::Add, I(0), I(0), I(4)),
        Instr::Jump { target: 0 },
    ];
    assert_eq!(promotable_loops(&code, &layout(), None)[0].guard, None);
}

#[test]
fn a_loop_whose_places_overlap_across_bases_runs_on_memory() {
    // The program's instance lies at data offset 256: G(260) is `sum`, G(264) is I(8). The
    // guard sees the overlap and runs the unpromoted copy, which reads `sum` through G(260)
    // as the interpreter does.
    let code = for_loop_with(Instr::Move {
        ty: Dint,
        dst: G(INSTANCE_AT as u32 + 8),
        src: G(INSTANCE_AT as u32 + 4),
    });
    let fixture = Fixture::with_constants(code, constants());
    let mut host = fixture.host();
    let before = guard_outcomes();
    assert_eq!(fixture.run(&mut host), Status::Ok);
    // Every iteration goes back through the guard, which fails each time.
    let (promoted, unpromoted) = guard_outcomes();
    assert_eq!((promoted - before.0, unpromoted - before.1), (0, 1001));
    assert_eq!(host.get(0, 4), 1001);
    assert_eq!(host.get(4, 4), 500_500);
    // The Move runs before the addition: the sum up to 999.
    assert_eq!(host.get(8, 4), 499_500);
    // The guard, both copies of the loop and the write-backs emit no trap (§7 rule 5).
    assert!(!fixture.code.listings[0].contains("trap"));
}

#[test]
fn promoted_places_are_in_memory_after_the_loop_and_at_a_tick() {
    let fixture = Fixture::with_constants(for_loop(), constants());
    let due = AtomicBool::new(false);
    // The 100th backward jump spends the budget: a tick, after `i` became 101.
    let mut counters = Counters {
        depth: 0,
        budget: 100,
    };
    let mut host = fixture.host();
    let before = guard_outcomes();
    assert_eq!(fixture.run_with(&mut host, &due, &mut counters), Status::Ok);
    // The instance and the frame are disjoint: the loop, entered once, runs promoted (the
    // tick is on its back-edge, inside it).
    let (promoted, unpromoted) = guard_outcomes();
    assert_eq!((promoted - before.0, unpromoted - before.1), (1, 0));
    assert_eq!(host.get(0, 4), 1001);
    assert_eq!(host.get(4, 4), 500_500);
    assert_eq!(host.tick_snapshots.len(), 1);
    let at_tick = &host.tick_snapshots[0];
    assert_eq!(u32::from_le_bytes(at_tick[0..4].try_into().unwrap()), 101);
    assert_eq!(u32::from_le_bytes(at_tick[4..8].try_into().unwrap()), 5050);
    // What the tick wrote is read again after it: `sum` set to 0 then counts 101 ..= 1000.
    let mut counters = Counters {
        depth: 0,
        budget: 100,
    };
    let mut host = fixture.host();
    host.tick_poke = Some((4, 0));
    // The poke clears only the lowest byte of 5050 (0x13BA): 0x1300 remains.
    assert_eq!(fixture.run_with(&mut host, &due, &mut counters), Status::Ok);
    assert_eq!(host.get(4, 4), 0x1300 + (101..=1000).sum::<u32>() as u64);
}

#[test]
fn promoted_places_are_in_memory_at_a_fault() {
    // LOOP i := i − 1; q := 1000 / i; END_LOOP: faults when `i` reaches 0.
    let code = vec![
        binary(BinaryOp::Sub, I(0), I(0), C(0)),
        binary(BinaryOp::Div, I(4), C(4), I(0)),
        Instr::Jump { target: 0 },
    ];
    let loops = promotable_loops(&code, &layout(), None);
    // `q` is only written: it stays in memory.
    assert_eq!(loops[0].places, vec![(I(0), 4)]);
    let fixture = Fixture::with_constants(code, constants());
    let mut host = fixture.host();
    host.put(0, 5, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(
        host.faults,
        vec![(
            Site {
                pou: 0,
                instruction: 1
            },
            NativeFault::DivisionByZero
        )]
    );
    assert_eq!(host.get(0, 4), 0);
    assert_eq!(host.get(4, 4), 1000);
}

/// A small xorshift generator, so the random programs are the same in every run.
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, bound: usize) -> usize {
        (self.next() % bound as u64) as usize
    }
}

/// A random counted loop over places that overlap in every way the analysis must see:
/// within a base (I(2) over I(0) and I(4), a byte of I(5)), across bases (G(260) is I(4) of
/// the program's instance at 256), and through copies; with divisions that may fault.
fn random_loop(random: &mut Random) -> Vec<Instr> {
    let places = [
        I(0),
        I(2),
        I(4),
        I(8),
        F(4),
        F(12),
        G(INSTANCE_AT as u32 + 4),
        G(100),
        G(104),
    ];
    let counter = F(20);
    let mut body = Vec::new();
    for _ in 0..1 + random.below(6) {
        let mut place = || places[random.below(places.len())];
        let (dst, a, b) = (place(), place(), place());
        let instr = match random.below(6) {
            0 => Instr::Move {
                ty: Dint,
                dst,
                src: a,
            },
            1 => Instr::Copy {
                size: [2, 4, 6][random.below(3)],
                dst,
                src: a,
            },
            2 => Instr::Move {
                ty: Usint,
                dst: I(5),
                src: a,
            },
            3 => binary(BinaryOp::Div, dst, a, b),
            4 => binary(BinaryOp::Add, dst, a, counter),
            _ => binary(
                [BinaryOp::Sub, BinaryOp::Xor, BinaryOp::Mul][random.below(3)],
                dst,
                a,
                b,
            ),
        };
        body.push(instr);
    }
    let end = 3 + body.len() as u32 + 2;
    let mut code = vec![
        Instr::Move {
            ty: Dint,
            dst: counter,
            src: C(0),
        },
        Instr::Compare {
            op: CompareOp::Gt,
            ty: Dint,
            dst: F(0),
            a: counter,
            b: C(8),
        },
        Instr::JumpIf {
            cond: F(0),
            target: end,
        },
    ];
    code.extend(body);
    code.push(binary(BinaryOp::Add, counter, counter, C(0)));
    code.push(Instr::Jump { target: 1 });
    code.push(Instr::Return);
    code
}

#[test]
fn random_loops_run_alike_with_and_without_promotion() {
    let mut random = Random(0x2545_F491_4F6C_DD1D);
    let mut constants = constants();
    constants[8] = 40; // The loops count 1 ..= 40.
    let mut promoted_loops = 0;
    let mut promoted_runs = 0;
    let mut unpromoted_runs = 0;
    for program in 0..300 {
        let code = random_loop(&mut random);
        let layout = Layout::of(&image(Vec::new(), constants.clone()), 1);
        promoted_loops += usize::from(!promotable_loops(&code, &layout, None).is_empty());
        let promoted = Fixture::with_constants(code.clone(), constants.clone());
        crate::translate::promote::PROMOTION_OFF_IN_TESTS.with(|off| off.set(true));
        let plain = Fixture::with_constants(code.clone(), constants.clone());
        crate::translate::promote::PROMOTION_OFF_IN_TESTS.with(|off| off.set(false));
        let mut memory = promoted.host().memory;
        for byte in memory.iter_mut().take(layout.constants as usize) {
            *byte = random.next() as u8;
        }
        for byte in memory.iter_mut().skip(layout.stacks as usize) {
            *byte = random.next() as u8;
        }
        let mut results = Vec::new();
        let before = guard_outcomes();
        for fixture in [&promoted, &plain] {
            let mut host = fixture.host();
            host.memory.clone_from(&memory);
            let due = AtomicBool::new(false);
            // A tick every 7 backward jumps, which looks at memory.
            let mut counters = Counters {
                depth: 0,
                budget: 7,
            };
            let status = fixture.run_with(&mut host, &due, &mut counters);
            results.push((status, host.faults, host.tick_snapshots, host.memory));
        }
        assert!(results[0] == results[1], "program {program}: {code:?}");
        // Only the promoting translation has a guard; a guarded loop is entered once.
        let (entered_promoted, entered_unpromoted) = guard_outcomes();
        promoted_runs += entered_promoted - before.0;
        unpromoted_runs += entered_unpromoted - before.1;
    }
    // The programs exercise promotion, not only its refusal: the analysis accepts many of
    // the loops, and the guard lets many of those run on variables.
    assert!(promoted_loops > 100, "{promoted_loops} promoted");
    assert!(
        promoted_runs > 100,
        "{promoted_runs} runs on the promoted path"
    );
    assert!(unpromoted_runs > 0, "the guard never failed");
}

#[test]
fn a_return_inside_a_promoted_loop_writes_its_places_back() {
    // LOOP i := i + 1; IF i > limit THEN RETURN; END_IF; END_LOOP
    let code = vec![
        binary(BinaryOp::Add, I(0), I(0), C(0)),
        Instr::Compare {
            op: CompareOp::Gt,
            ty: Dint,
            dst: F(0),
            a: I(0),
            b: I(4),
        },
        Instr::JumpIfNot {
            cond: F(0),
            target: 4,
        },
        Instr::Return,
        Instr::Jump { target: 0 },
    ];
    let loops = promotable_loops(&code, &layout(), None);
    assert_eq!(loops[0].places, vec![(I(0), 4), (F(0), 1)]);
    let fixture = Fixture::with_constants(code, constants());
    let mut host = fixture.host();
    host.put(4, 10, 4);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(0, 4), 11);
    assert_eq!(host.memory[fixture.frame_at() as usize], 1);
}

#[test]
fn a_loop_over_a_global_an_instance_variable_and_constants_runs_promoted() {
    // `g := g + i` with `g` at G(100), in the data region below the program's instance at
    // 256, the constants 1 and 1000 read by the loop, and 4 bytes of the pool copied to
    // F(8) (a copy reads memory even when the pool is folded): each fixed region has its own
    // range, and the folded constants touch no memory.
    let mut code = for_loop_with(binary(BinaryOp::Add, G(100), G(100), I(0)));
    code.insert(
        3,
        Instr::Copy {
            size: 4,
            dst: F(8),
            src: C(4),
        },
    );
    code[2] = Instr::JumpIf {
        cond: F(0),
        target: 8,
    };
    code[7] = Instr::Jump { target: 1 };
    let loops = promotable_loops(&code, &layout(), Some(&constants()));
    let constants_at = layout().constants;
    let guard = Guard {
        instance: Some((0, 8)),
        frame: Some((0, 12)),
        fixed: [
            Some((100, 104)),
            None,
            None,
            None,
            Some((constants_at + 4, constants_at + 8)),
        ],
    };
    assert_eq!(loops[0].guard, Some(guard));
    let fixture = Fixture::with_constants(code.clone(), constants());
    let mut host = fixture.host();
    let before = guard_outcomes();
    assert_eq!(fixture.run(&mut host), Status::Ok);
    let (promoted, unpromoted) = guard_outcomes();
    assert_eq!((promoted - before.0, unpromoted - before.1), (1, 0));
    let global = |at: usize| u32::from_le_bytes(host.memory[at..at + 4].try_into().unwrap());
    assert_eq!(global(fixture.layout.data as usize + 100), 500_500);
    assert_eq!(host.get(4, 4), 500_500);
    let frame = fixture.frame_at() as usize + 8;
    assert_eq!(host.memory[frame..frame + 4], 1000u32.to_le_bytes());
    // Unfolded, the constants read are in the pool's range too.
    let loops = promotable_loops(&code, &layout(), None);
    assert_eq!(
        loops[0].guard.map(|guard| guard.fixed[4]),
        Some(Some((constants_at, constants_at + 8)))
    );
}

/// Runs [`for_loop`] with a tick at the 10th backward jump that takes the host's memory away
/// (returning `Ok` with an empty memory, or panicking): the code must end there without
/// reading the promoted places again (§7 rules 1 and 3).
#[test]
fn a_tick_that_takes_the_memory_away_ends_a_promoted_loop_without_reading_it() {
    for panics in [false, true] {
        let fixture = Fixture::with_constants(for_loop(), constants());
        let mut host = fixture.host();
        // Above glibc's largest mmap threshold (32 MiB): the buffer is unmapped when freed,
        // so a read through its old address faults the test process.
        host.memory.resize(64 << 20, 0);
        host.tick_releases_memory = Some(panics);
        let due = AtomicBool::new(false);
        let mut counters = Counters {
            depth: 0,
            budget: 10,
        };
        let status = fixture.run_with(&mut host, &due, &mut counters);
        assert_eq!(status, Status::Faulted, "panics: {panics}");
        let fault = if panics {
            NativeFault::HostPanicked
        } else {
            NativeFault::Memory
        };
        let site = Site {
            pou: 0,
            instruction: 5,
        };
        assert_eq!(host.faults, vec![(site, fault)]);
        assert!(host.memory.is_empty());
    }
}

/// Instructions the analysis lets into a promoted loop that the host runs (integer ATAN2,
/// NOT of a real, arithmetic on BOOL): the places are in memory when the host runs them, and
/// what it writes is read again after.
#[test]
fn an_instruction_run_by_the_host_sees_and_changes_the_promoted_places() {
    for host_instruction in [
        binary(BinaryOp::Atan2, I(8), I(0), I(4)),
        Instr::Unary {
            op: UnaryOp::Not,
            ty: Real,
            dst: I(8),
            src: I(12),
        },
        Instr::Binary {
            op: BinaryOp::Add,
            ty: Bool,
            dst: I(8),
            a: I(12),
            b: I(13),
        },
    ] {
        let code = for_loop_with(host_instruction.clone());
        let loops = promotable_loops(&code, &layout(), Some(&constants()));
        assert!(
            loops[0].places.contains(&(I(4), 4)),
            "{host_instruction:?} is allowed in a promoted loop"
        );
        let fixture = Fixture::with_constants(code, constants());
        let mut host = fixture.host();
        let before = guard_outcomes();
        // Each op sets `sum`'s byte 3: from the 2nd iteration on, `sum` carries 0x0100_0000.
        host.op_poke = Some((7, 1));
        assert_eq!(fixture.run(&mut host), Status::Ok, "{host_instruction:?}");
        let (promoted, unpromoted) = guard_outcomes();
        assert_eq!((promoted - before.0, unpromoted - before.1), (1, 0));
        assert_eq!(host.op_snapshots.len(), 1000);
        // The op of iteration `i` sees `i` and the sum up to `i - 1` (with the poked byte).
        for (i, snapshot) in (1u32..).zip(&host.op_snapshots) {
            let at = |offset: usize| {
                u32::from_le_bytes(snapshot[offset..offset + 4].try_into().unwrap())
            };
            let sum = (1..i).sum::<u32>() & 0x00FF_FFFF | if i > 1 { 0x0100_0000 } else { 0 };
            assert_eq!((at(0), at(4)), (i, sum), "{host_instruction:?}");
        }
        let expected = ((1..=1000).sum::<u32>() & 0x00FF_FFFF) | 0x0100_0000;
        assert_eq!(host.get(4, 4), u64::from(expected));
        assert_eq!(host.get(0, 4), 1001);
    }
}
