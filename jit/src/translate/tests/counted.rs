//! Counted loops (`docs/native-engine.md` §5.3, `translate/counted.rs`): which `FOR` loops
//! have their element checks made once in the preheader, and that they run as the
//! interpreter runs them at the array's bounds, one past them, counting down, by 0, with the
//! counter written in the body, nested, with a fault, and with a tick that changes memory;
//! and random counted loops against the same loops translated without promotion.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;
use crate::translate::promote::{
    GUARD_OUTCOMES_IN_TESTS, PROMOTION_OFF_IN_TESTS, promotable_loops,
};

const C: fn(u32) -> Operand = Operand::Const;
const F: fn(u32) -> Operand = Operand::Frame;

/// The array's first element in the instance.
const ARRAY: u32 = 64;

/// A `FOR` loop as the compiler writes it, with `ty` counter `i` at I(0) from `first` to
/// `last` by `step` (constants at C(0), C(8), C(16)), over `a: ARRAY[low .. low + count − 1]
/// OF DINT` at I(64): `a[i] := a[i] + 1` (the sum at F(8)), with `extra` inserted in the body.
struct ForLoop {
    ty: Elementary,
    first: i64,
    last: i64,
    step: i64,
    low: i64,
    count: u64,
    extra: Vec<Instr>,
}

impl ForLoop {
    fn new(first: i64, last: i64, step: i64, low: i64, count: u64) -> Self {
        Self {
            ty: Dint,
            first,
            last,
            step,
            low,
            count,
            extra: Vec::new(),
        }
    }

    fn constants(&self) -> Vec<u8> {
        let mut constants = vec![0; 32];
        let size = self.ty.size_bytes() as usize;
        for (at, value) in [(0, self.first), (8, self.last), (16, self.step), (24, 1)] {
            constants[at..at + size].copy_from_slice(&value.to_le_bytes()[..size]);
        }
        constants
    }

    fn element(&self, load: bool) -> Instr {
        if load {
            Instr::LoadElement {
                ty: Dint,
                dst: F(8),
                array: I(ARRAY),
                index: I(0),
                index_ty: self.ty,
                low: self.low,
                count: self.count,
                stride: 4,
                offset: 0,
            }
        } else {
            Instr::StoreElement {
                ty: Dint,
                array: I(ARRAY),
                index: I(0),
                index_ty: self.ty,
                low: self.low,
                count: self.count,
                stride: 4,
                offset: 0,
                src: F(8),
            }
        }
    }

    /// The loop: `Move` (0), test (1, 2), the body from 3, the increment and the jump back.
    fn code(&self) -> Vec<Instr> {
        let mut body = vec![
            self.element(true),
            Instr::Binary {
                op: BinaryOp::Add,
                ty: Dint,
                dst: F(8),
                a: F(8),
                b: C(24),
            },
            self.element(false),
        ];
        body.extend(self.extra.iter().cloned());
        let end = 3 + body.len() as u32 + 2;
        let mut code = vec![
            Instr::Move {
                ty: self.ty,
                dst: I(0),
                src: C(0),
            },
            Instr::Compare {
                op: if self.step < 0 {
                    CompareOp::Lt
                } else {
                    CompareOp::Gt
                },
                ty: self.ty,
                dst: F(0),
                a: I(0),
                b: C(8),
            },
            Instr::JumpIf {
                cond: F(0),
                target: end,
            },
        ];
        code.extend(body);
        code.push(Instr::Binary {
            op: BinaryOp::Add,
            ty: self.ty,
            dst: I(0),
            a: I(0),
            b: C(16),
        });
        code.push(Instr::Jump { target: 1 });
        code.push(Instr::Return);
        code
    }

    fn layout(&self) -> Layout {
        Layout::of(&image(Vec::new(), self.constants()), 1)
    }

    fn fixture(&self) -> Fixture {
        Fixture::with_constants(self.code(), self.constants())
    }

    /// The fixture translated without promotion, the reference the tests compare with.
    fn plain(&self) -> Fixture {
        PROMOTION_OFF_IN_TESTS.with(|off| off.set(true));
        let plain = self.fixture();
        PROMOTION_OFF_IN_TESTS.with(|off| off.set(false));
        plain
    }

    fn counted(&self) -> bool {
        let loops = promotable_loops(&self.code(), &self.layout(), None);
        loops.len() == 1 && loops[0].counted.is_some()
    }
}

/// What a run left: its status, faults, ticks' snapshots and the whole memory.
type Outcome = (Status, Vec<(Site, NativeFault)>, Vec<Vec<u8>>, Vec<u8>);

/// Runs `fixture` with `a[k] = 100 · k` (by element) and a tick every `budget` backward
/// jumps, `host` prepared by `prepare`.
fn run(fixture: &Fixture, budget: u32, prepare: impl Fn(&mut TestHost)) -> Outcome {
    let mut host = fixture.host();
    for element in 0..32u32 {
        host.put(ARRAY + 4 * element, u64::from(100 * element), 4);
    }
    // An endless loop ends as the watchdog ends it.
    host.watchdog_after_ticks = Some(20);
    prepare(&mut host);
    let due = AtomicBool::new(false);
    let mut counters = Counters { depth: 0, budget };
    let status = fixture.run_with(&mut host, &due, &mut counters);
    (status, host.faults, host.tick_snapshots, host.memory)
}

/// How often, on this thread so far, a preheader sent its loop to the promoted copy and to
/// the unpromoted one.
fn guard_outcomes() -> (u64, u64) {
    GUARD_OUTCOMES_IN_TESTS.with(|outcomes| {
        (
            outcomes[0].load(Ordering::Relaxed),
            outcomes[1].load(Ordering::Relaxed),
        )
    })
}

/// Runs `for_loop` promoted and plain with the same memory and ticks; asserts they agree and
/// returns the outcome and the entries into the promoted and unpromoted copies.
#[track_caller]
fn run_alike(for_loop: &ForLoop, budget: u32) -> (Outcome, (u64, u64)) {
    run_alike_prepared(for_loop, budget, |_| {})
}

#[track_caller]
fn run_alike_prepared(
    for_loop: &ForLoop,
    budget: u32,
    prepare: impl Fn(&mut TestHost) + Copy,
) -> (Outcome, (u64, u64)) {
    let plain = run(&for_loop.plain(), budget, prepare);
    let before = guard_outcomes();
    let promoted = run(&for_loop.fixture(), budget, prepare);
    let after = guard_outcomes();
    assert!(
        promoted == plain,
        "promoted {:?} {:?}, plain {:?} {:?}: {:?}",
        promoted.0,
        promoted.1,
        plain.0,
        plain.1,
        for_loop.code()
    );
    (promoted, (after.0 - before.0, after.1 - before.1))
}

fn element(outcome: &Outcome, index: u32) -> u32 {
    let at = INSTANCE_AT as usize + (ARRAY + 4 * index) as usize;
    u32::from_le_bytes(outcome.3[at..at + 4].try_into().unwrap())
}

fn counter(outcome: &Outcome) -> u32 {
    let at = INSTANCE_AT as usize;
    u32::from_le_bytes(outcome.3[at..at + 4].try_into().unwrap())
}

#[test]
fn a_loop_over_the_whole_array_runs_without_index_checks() {
    // FOR i := 1 TO 10 over ARRAY[1..10]: the preheader's checks hold at both ends.
    let for_loop = ForLoop::new(1, 10, 1, 1, 10);
    let loops = promotable_loops(&for_loop.code(), &for_loop.layout(), None);
    let counted = loops[0].counted.as_ref().expect("a counted loop");
    assert_eq!(counted.accesses, vec![3, 5]);
    assert_eq!((counted.low, counted.high, counted.upward), (1, 10, true));
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!(entries, (1, 0));
    assert_eq!(outcome.0, Status::Ok);
    assert!((0..10).all(|k| element(&outcome, k) == 100 * k + 1));
    assert_eq!(element(&outcome, 10), 1000);
    assert_eq!(counter(&outcome), 11);
}

#[test]
fn a_loop_one_past_the_array_faults_at_the_interpreters_site_with_its_memory() {
    // FOR i := 1 TO 11 over ARRAY[1..10]: the preheader sends the loop to its checked copy,
    // which faults at i = 11 in the LoadElement (instruction 3).
    let for_loop = ForLoop::new(1, 11, 1, 1, 10);
    assert!(for_loop.counted());
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!(entries.0, 0);
    assert_eq!(outcome.0, Status::Faulted);
    let site = Site {
        pou: 0,
        instruction: 3,
    };
    let fault = NativeFault::IndexOutOfBounds {
        index: 11,
        low: 1,
        high: 10,
    };
    assert_eq!(outcome.1, vec![(site, fault)]);
    assert_eq!(counter(&outcome), 11);
    assert!((0..10).all(|k| element(&outcome, k) == 100 * k + 1));
    // One below the low bound faults on the first iteration.
    let for_loop = ForLoop::new(0, 10, 1, 1, 10);
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!(entries.0, 0);
    assert_eq!(
        outcome.1[0].1.clone(),
        NativeFault::IndexOutOfBounds {
            index: 0,
            low: 1,
            high: 10,
        }
    );
}

#[test]
fn a_loop_counting_down_is_checked_from_its_end_to_its_start() {
    // FOR i := 10 TO 1 BY -1, then to 0 (one past the low bound).
    let for_loop = ForLoop::new(10, 1, -1, 1, 10);
    let loops = promotable_loops(&for_loop.code(), &for_loop.layout(), None);
    assert!(!loops[0].counted.as_ref().expect("counted").upward);
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!((entries, outcome.0), ((1, 0), Status::Ok));
    assert_eq!(counter(&outcome) as i32, 0);
    assert!((0..10).all(|k| element(&outcome, k) == 100 * k + 1));
    let for_loop = ForLoop::new(10, 0, -2, 1, 10);
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!(entries.0, 0);
    assert_eq!(outcome.0, Status::Faulted);
    assert_eq!(counter(&outcome), 0);
    // An unsigned counter counting down adds a wrapping step: no checks are hoisted.
    let mut unsigned = ForLoop::new(10, 1, -1, 1, 10);
    unsigned.ty = Udint;
    assert!(!unsigned.counted());
    let (outcome, _) = run_alike(&unsigned, 4096);
    assert_eq!(outcome.0, Status::Ok);
}

#[test]
fn a_loop_by_zero_runs_until_a_tick_moves_its_counter_past_the_end() {
    // FOR i := 1 TO 10 BY 0 never ends by itself; the tick at the 50th backward jump writes
    // 200 into the counter's low byte, which the preheader reads again: the loop then ends.
    let for_loop = ForLoop::new(1, 10, 0, 1, 10);
    assert!(for_loop.counted());
    let (outcome, entries) = run_alike_prepared(&for_loop, 50, |host| {
        host.tick_poke = Some((0, 200));
    });
    assert_eq!(outcome.0, Status::Ok);
    // Entered once, then again after the tick, both times promoted.
    assert_eq!(entries, (2, 0));
    assert_eq!(counter(&outcome), 200);
    // a[1] counted 50 iterations.
    assert_eq!(element(&outcome, 0), 50);
    assert_eq!(outcome.2.len(), 1);
}

#[test]
fn a_tick_that_moves_the_counter_below_the_array_sends_the_loop_to_its_checks() {
    // FOR i := 1 TO 10 over ARRAY[1..10], a tick every 3 backward jumps: the first, after
    // i became 4, sets the counter's high byte, making it negative. Without the preheader's
    // second look the promoted copy would reach memory far below the array.
    let for_loop = ForLoop::new(1, 10, 1, 1, 10);
    let (outcome, entries) = run_alike_prepared(&for_loop, 3, |host| {
        host.tick_poke = Some((3, 0x80));
    });
    assert_eq!(entries, (1, 1));
    assert_eq!(outcome.0, Status::Faulted);
    let index = i64::from(0x8000_0004u32 as i32);
    assert_eq!(
        outcome.1[0].1.clone(),
        NativeFault::IndexOutOfBounds {
            index,
            low: 1,
            high: 10,
        }
    );
    assert_eq!(outcome.1[0].0.instruction, 3);
    // The three iterations before the tick were made.
    assert!((0..3).all(|k| element(&outcome, k) == 100 * k + 1));
    assert_eq!(element(&outcome, 3), 300);
}

/// `code` with every jump target moved by `by`, for instructions inserted before it.
fn shifted(code: Vec<Instr>, by: u32) -> Vec<Instr> {
    code.into_iter()
        .map(|mut instr| {
            if let Instr::Jump { target } | Instr::JumpIf { target, .. } = &mut instr {
                *target += by;
            }
            instr
        })
        .collect()
}

/// `for_loop`'s code with its end copied to F(16) before the loop and compared there, as the
/// compiler keeps an end that is no constant.
fn with_end_in_frame(for_loop: &ForLoop) -> Vec<Instr> {
    let mut code = vec![Instr::Move {
        ty: for_loop.ty,
        dst: F(16),
        src: C(8),
    }];
    code.extend(shifted(for_loop.code(), 1));
    code[2] = Instr::Compare {
        op: CompareOp::Gt,
        ty: for_loop.ty,
        dst: F(0),
        a: I(0),
        b: F(16),
    };
    code
}

#[test]
fn a_counter_or_an_end_written_in_the_body_keeps_the_checks() {
    let write = |dst| Instr::Move {
        ty: Dint,
        dst,
        src: C(24),
    };
    // `i := 1` in the body never ends: the watchdog ends it. A DINT written over the
    // counter's upper bytes makes it 65,536 more, and ends the loop.
    for (extra, status) in [(write(I(0)), Status::Faulted), (write(I(2)), Status::Ok)] {
        let mut for_loop = ForLoop::new(1, 10, 1, 1, 10);
        for_loop.extra = vec![extra.clone()];
        assert!(!for_loop.counted(), "{extra:?}");
        let (outcome, _) = run_alike(&for_loop, 100);
        assert_eq!(outcome.0, status, "{extra:?}");
    }
    let for_loop = ForLoop::new(1, 10, 1, 1, 10);
    let code = with_end_in_frame(&for_loop);
    let loops = promotable_loops(&code, &for_loop.layout(), None);
    assert!(loops[0].counted.is_some(), "an end nothing writes");
    let fixture = Fixture::with_constants(code, for_loop.constants());
    let outcome = run(&fixture, 4096, |_| {});
    assert_eq!(outcome.0, Status::Ok);
    assert!((0..10).all(|k| element(&outcome, k) == 100 * k + 1));
    let mut for_loop = ForLoop::new(1, 10, 1, 1, 10);
    for_loop.extra = vec![write(F(16))];
    let loops = promotable_loops(&with_end_in_frame(&for_loop), &for_loop.layout(), None);
    assert!(loops[0].counted.is_none(), "an end the body writes");
}

#[test]
fn an_inner_counted_loop_runs_without_checks_inside_an_outer_loop() {
    // FOR j := 1 TO 3 DO FOR i := 1 TO 10 DO a[i] := a[i] + 1; END_FOR; END_FOR with j at
    // I(4): the inner loop is promoted and counted, entered once per outer iteration.
    let inner = ForLoop::new(1, 10, 1, 1, 10);
    let mut code = vec![Instr::Move {
        ty: Dint,
        dst: I(4),
        src: C(24),
    }];
    let outer_test = code.len() as u32;
    code.push(Instr::Compare {
        op: CompareOp::Gt,
        ty: Dint,
        dst: F(24),
        a: I(4),
        b: C(24 + 4),
    });
    let exit_jump = code.len();
    code.push(Instr::JumpIf {
        cond: F(24),
        target: 0,
    });
    let shift = code.len() as u32;
    let mut inner_code = shifted(inner.code(), shift);
    inner_code.pop();
    code.extend(inner_code);
    code.push(Instr::Binary {
        op: BinaryOp::Add,
        ty: Dint,
        dst: I(4),
        a: I(4),
        b: C(24),
    });
    code.push(Instr::Jump { target: outer_test });
    let end = code.len() as u32;
    code[exit_jump] = Instr::JumpIf {
        cond: F(24),
        target: end,
    };
    code.push(Instr::Return);
    let mut constants = inner.constants();
    constants[28] = 3;
    let layout = Layout::of(&image(Vec::new(), constants.clone()), 1);
    let loops = promotable_loops(&code, &layout, None);
    assert_eq!(loops.len(), 1);
    assert_eq!(loops[0].start, shift + 1);
    assert!(loops[0].counted.is_some());
    let fixture = Fixture::with_constants(code.clone(), constants.clone());
    PROMOTION_OFF_IN_TESTS.with(|off| off.set(true));
    let plain = Fixture::with_constants(code, constants);
    PROMOTION_OFF_IN_TESTS.with(|off| off.set(false));
    let before = guard_outcomes();
    let outcome = run(&fixture, 7, |_| {});
    let (promoted, unpromoted) = guard_outcomes();
    // Entered by each outer iteration, and again after the one tick (the 7th backward jump,
    // an inner one; the host then gives the budget 4096).
    assert_eq!((promoted - before.0, unpromoted - before.1), (3 + 1, 0));
    assert!(outcome == run(&plain, 7, |_| {}));
    assert_eq!(outcome.0, Status::Ok);
    assert!((0..10).all(|k| element(&outcome, k) == 100 * k + 3));
}

#[test]
fn an_end_near_the_types_limit_keeps_the_checks_where_the_counter_would_wrap() {
    // FOR i : SINT := 120 TO 127 over ARRAY[120..127]: after 127 the counter wraps to −128,
    // which is still not above 127, and the access faults with index −128.
    let mut for_loop = ForLoop::new(120, 127, 1, 120, 8);
    for_loop.ty = Sint;
    assert!(for_loop.counted());
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!(entries.0, 0);
    assert_eq!(
        outcome.1[0].1.clone(),
        NativeFault::IndexOutOfBounds {
            index: -128,
            low: 120,
            high: 127,
        }
    );
    // To 126 the increment cannot wrap: promoted.
    let mut for_loop = ForLoop::new(120, 126, 1, 120, 8);
    for_loop.ty = Sint;
    let (outcome, entries) = run_alike(&for_loop, 4096);
    assert_eq!((entries, outcome.0), ((1, 0), Status::Ok));
}

/// A small xorshift generator, so the random loops are the same in every run.
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn between(&mut self, low: i64, high: i64) -> i64 {
        low + (self.next() % (high - low + 1) as u64) as i64
    }
}

#[test]
fn random_counted_loops_run_as_their_unpromoted_translation() {
    let mut random = Random(0x9E37_79B9_7F4A_7C15);
    let types = [Sint, Int, Dint, Lint, Usint, Uint, Udint];
    let (mut promoted_entries, mut unpromoted_entries, mut counted) = (0, 0, 0);
    for _ in 0..400 {
        let ty = types[random.next() as usize % types.len()];
        let (min, max) = if ty.is_signed() {
            let bits = ty.size_bytes() * 8 - 1;
            (-(1i64 << bits.min(62)), (1i64 << bits.min(62)) - 1)
        } else {
            (0, (1i64 << (ty.size_bytes() * 8).min(62)) - 1)
        };
        // Near a bound of the type, or near zero.
        let centre = match random.next() % 3 {
            0 => min + 4,
            1 => max - 4,
            _ => 0,
        };
        let first = (centre + random.between(-6, 6)).clamp(min, max);
        let last = (centre + random.between(-6, 6)).clamp(min, max);
        // An unsigned counter's negative step is stored wrapped, as the compiler stores it.
        let step = random.between(-3, 3);
        let low = (centre + random.between(-6, 4)).clamp(min, max);
        let count = random.between(1, 12) as u64;
        let mut for_loop = ForLoop::new(first, last, step, low, count);
        for_loop.ty = ty;
        counted += usize::from(for_loop.counted());
        // Ticks now and then, which look at memory; the watchdog ends a loop that does not.
        let budget = [3, 7, 50][random.next() as usize % 3];
        let (_, entries) = run_alike(&for_loop, budget);
        promoted_entries += entries.0;
        unpromoted_entries += entries.1;
    }
    assert!(counted > 150, "{counted} counted loops");
    assert!(
        promoted_entries > 100,
        "{promoted_entries} promoted entries"
    );
    assert!(
        unpromoted_entries > 100,
        "{unpromoted_entries} unpromoted entries"
    );
}
