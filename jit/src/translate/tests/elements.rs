//! The fused element accesses `LoadElement` and `StoreElement` translated inline
//! (`docs/native-engine.md` §5.1 rows 29 and 30, §10): every elementary type, the index checks
//! and faults of the interpreter (down to the lowest low bound), a member of a structure
//! element, arrays in the instance, the data region, the frame and the constant pool, and
//! loops that promote their variables while they read and write an array: their guard, which
//! must cover the array's whole extent, and their write-back at a fault.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;
use crate::translate::promote::{GUARD_OUTCOMES_IN_TESTS, promotable_loops};

const C: fn(u32) -> Operand = Operand::Const;
const F: fn(u32) -> Operand = Operand::Frame;

/// The array's first element in the instance.
const ARRAY: u32 = 64;

/// `dst (I 16) := array[index (I 8)]` over `ARRAY[-2..2]` at I(64), `stride` bytes an element.
fn load_element(ty: Elementary, index_ty: Elementary, stride: u32, offset: u32) -> Instr {
    Instr::LoadElement {
        ty,
        dst: I(16),
        array: I(ARRAY),
        index: I(8),
        index_ty,
        low: -2,
        count: 5,
        stride,
        offset,
    }
}

/// `array[index (I 8)] := src (I 24)` over the same array.
fn store_element(ty: Elementary, index_ty: Elementary, stride: u32, offset: u32) -> Instr {
    Instr::StoreElement {
        ty,
        array: I(ARRAY),
        index: I(8),
        index_ty,
        low: -2,
        count: 5,
        stride,
        offset,
        src: I(24),
    }
}

/// The fault of an index outside −2 ..= 2 at instruction `instruction`, as the interpreter's
/// `checked_index` reports it.
fn outside(instruction: u32, index: i64) -> Vec<(Site, NativeFault)> {
    let site = Site {
        pou: 0,
        instruction,
    };
    let fault = NativeFault::IndexOutOfBounds {
        index,
        low: -2,
        high: 2,
    };
    vec![(site, fault)]
}

/// A value of `size` bytes that differs per element and has every byte set.
fn pattern(element: u64, size: u32) -> u64 {
    let raw = 0x8877_6655_4433_2211u64.wrapping_add(element * 0x0101_0101_0101_0101);
    raw & (u64::MAX >> (64 - 8 * size))
}

#[test]
fn every_elementary_type_is_read_and_written_at_its_element_without_the_host() {
    for ty in Elementary::ALL {
        let size = ty.size_bytes();
        let fixture = Fixture::new(vec![
            load_element(ty, Dint, size, 0),
            store_element(ty, Dint, size, 0),
        ]);
        for index in -2i64..=2 {
            let mut host = fixture.host();
            for element in 0..5u32 {
                host.put(
                    ARRAY + element * size,
                    pattern(u64::from(element), size),
                    size,
                );
            }
            host.put(8, index as u64, 4);
            host.put(
                24,
                0x0102_0304_0506_0708 & (u64::MAX >> (64 - 8 * size)),
                size,
            );
            assert_eq!(fixture.run(&mut host), Status::Ok, "{ty:?} {index}");
            let chosen = (index + 2) as u32;
            assert_eq!(
                host.get(16, size),
                pattern(u64::from(chosen), size),
                "{ty:?} {index}"
            );
            for element in 0..5u32 {
                let expected = if element == chosen {
                    0x0102_0304_0506_0708 & (u64::MAX >> (64 - 8 * size))
                } else {
                    pattern(u64::from(element), size)
                };
                assert_eq!(
                    host.get(ARRAY + element * size, size),
                    expected,
                    "{ty:?} {index} {element}"
                );
            }
            // Nothing was handed to the interpreter.
            assert!(host.ops.is_empty(), "{ty:?}");
            assert!(host.faults.is_empty(), "{ty:?}");
        }
    }
}

#[test]
fn an_index_below_or_above_the_bounds_faults_as_in_the_interpreter() {
    let load = Fixture::new(vec![load_element(Dint, Int, 4, 0)]);
    let store = Fixture::new(vec![
        Instr::Move {
            ty: Dint,
            dst: I(32),
            src: I(24),
        },
        store_element(Dint, Int, 4, 0),
    ]);
    for index in [-3i64, 3, -32768, 32767] {
        let mut host = load.host();
        host.put(8, index as u64, 2);
        host.put(16, 77, 4);
        assert_eq!(load.run(&mut host), Status::Faulted, "{index}");
        assert_eq!(host.faults, outside(0, index));
        // The destination keeps its value.
        assert_eq!(host.get(16, 4), 77);
        let mut host = store.host();
        host.put(8, index as u64, 2);
        host.put(24, 99, 4);
        assert_eq!(store.run(&mut host), Status::Faulted, "{index}");
        assert_eq!(host.faults, outside(1, index));
        assert!((0..5).all(|element| host.get(ARRAY + 4 * element, 4) == 0));
        assert!(host.ops.is_empty());
    }
    // An unsigned index is read without sign extension: 0xFFFF is 65535, above.
    let unsigned = Fixture::new(vec![load_element(Dint, Uint, 4, 0)]);
    let mut host = unsigned.host();
    host.put(8, 0xFFFF, 2);
    assert_eq!(unsigned.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, outside(0, 65535));
}

#[test]
fn an_unsigned_64_bit_index_above_i64_max_is_outside_even_a_negative_low_bound() {
    for index_ty in [Ulint, Lword] {
        let fixtures = [
            Fixture::new(vec![load_element(Dint, index_ty, 4, 0)]),
            Fixture::new(vec![store_element(Dint, index_ty, 4, 0)]),
        ];
        for fixture in &fixtures {
            for raw in [u64::MAX, u64::MAX - 1, 1 << 63] {
                let mut host = fixture.host();
                host.put(8, raw, 8);
                assert_eq!(fixture.run(&mut host), Status::Faulted, "{index_ty:?}");
                assert_eq!(host.faults, outside(0, i64::MAX));
            }
        }
        // 2 still reaches the last element.
        let mut host = fixtures[0].host();
        host.put(8, 2, 8);
        host.put(ARRAY + 16, 4242, 4);
        assert_eq!(fixtures[0].run(&mut host), Status::Ok);
        assert_eq!(host.get(16, 4), 4242);
    }
}

#[test]
fn a_member_of_a_structure_element_is_reached_at_its_offset() {
    // ARRAY[-2..2] OF STRUCT a: DINT; b: INT; c: LREAL; END_STRUCT, 16 bytes an element,
    // member `b` at 4.
    let fixture = Fixture::new(vec![
        load_element(Int, Sint, 16, 4),
        store_element(Lreal, Sint, 16, 8),
    ]);
    for index in -2i64..=2 {
        let mut host = fixture.host();
        let element = ARRAY + 16 * (index + 2) as u32;
        host.put(element + 4, 0x1234, 2);
        host.put(8, index as u64, 1);
        host.put(24, 2.5f64.to_bits(), 8);
        assert_eq!(fixture.run(&mut host), Status::Ok);
        assert_eq!(host.get(16, 2), 0x1234);
        assert_eq!(host.get(element + 8, 8), 2.5f64.to_bits());
        // The other members are untouched.
        assert_eq!(host.get(element, 4), 0);
        assert_eq!(host.get(element + 6, 2), 0);
        assert_eq!(
            (0..5 * 16u32)
                .step_by(8)
                .filter(|at| host.get(ARRAY + at, 8) != 0)
                .count(),
            2
        );
    }
}

/// Constants: 1 at 0, 10 at 4.
fn loop_constants() -> Vec<u8> {
    let mut constants = vec![0; 16];
    constants[0] = 1;
    constants[4] = 10;
    constants
}

/// `FOR i := 1 TO 10 DO a[i] := a[i] + i; sum := sum + a[i]; END_FOR` over
/// `a: ARRAY[1..10] OF DINT` at I(64), with `i` at I(0), `sum` at `sum`, the loop's
/// condition at F(0) and `a[i] + i` at F(4).
fn array_loop(sum: Operand) -> Vec<Instr> {
    array_loop_over(I(0), I(ARRAY), 10, sum)
}

/// [`array_loop`] with `i` at `i` and `a: ARRAY[1..count] OF DINT` at `array`: the loop still
/// runs to 10, so a `count` below 10 makes it fault at `LoadElement` (instruction 3).
fn array_loop_over(i: Operand, array: Operand, count: u64, sum: Operand) -> Vec<Instr> {
    let add = |dst, a, b| Instr::Binary {
        op: BinaryOp::Add,
        ty: Dint,
        dst,
        a,
        b,
    };
    let element = (array, i, Dint, 1, count, 4, 0);
    vec![
        Instr::Move {
            ty: Dint,
            dst: i,
            src: C(0),
        },
        Instr::Compare {
            op: CompareOp::Gt,
            ty: Dint,
            dst: F(0),
            a: i,
            b: C(4),
        },
        Instr::JumpIf {
            cond: F(0),
            target: 9,
        },
        Instr::LoadElement {
            ty: Dint,
            dst: F(4),
            array: element.0,
            index: element.1,
            index_ty: element.2,
            low: element.3,
            count: element.4,
            stride: element.5,
            offset: element.6,
        },
        add(F(4), F(4), i),
        Instr::StoreElement {
            ty: Dint,
            array: element.0,
            index: element.1,
            index_ty: element.2,
            low: element.3,
            count: element.4,
            stride: element.5,
            offset: element.6,
            src: F(4),
        },
        add(sum, sum, F(4)),
        add(i, i, C(0)),
        Instr::Jump { target: 1 },
        Instr::Return,
    ]
}

/// The array and `sum` after [`array_loop`], computed here: `a[k] = 100 · k` before, and
/// `sum`, when `alias` names an element, is that element.
fn expected_after_loop(alias: Option<usize>) -> ([i32; 10], i32) {
    let mut a: [i32; 10] = std::array::from_fn(|k| 100 * (k as i32 + 1));
    let mut sum = 0;
    for k in 1..=10usize {
        let value = a[k - 1] + k as i32;
        a[k - 1] = value;
        match alias {
            Some(element) => a[element - 1] += value,
            None => sum += value,
        }
    }
    (a, alias.map_or(sum, |element| a[element - 1]))
}

fn guard_outcomes() -> (u64, u64) {
    GUARD_OUTCOMES_IN_TESTS.with(|outcomes| {
        (
            outcomes[0].load(Ordering::Relaxed),
            outcomes[1].load(Ordering::Relaxed),
        )
    })
}

/// Runs [`array_loop`] with `a[k] = 100 · k`; the array, then `i`.
fn run_array_loop(fixture: &Fixture) -> ([i32; 10], u64) {
    let mut host = fixture.host();
    for k in 1..=10u32 {
        host.put(ARRAY + 4 * (k - 1), u64::from(100 * k), 4);
    }
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert!(host.ops.is_empty());
    assert!(host.faults.is_empty());
    let array = std::array::from_fn(|k| host.get(ARRAY + 4 * k as u32, 4) as u32 as i32);
    (array, host.get(0, 4))
}

#[test]
fn a_loop_over_an_array_keeps_its_index_and_sum_in_registers() {
    let code = array_loop(I(4));
    let layout = Layout::of(&image(Vec::new(), loop_constants()), 1);
    let loops = promotable_loops(&code, &layout, None);
    assert_eq!(loops.len(), 1);
    assert_eq!((loops[0].start, loops[0].end), (1, 8));
    for place in [(I(0), 4), (I(4), 4), (F(4), 4)] {
        assert!(loops[0].places.contains(&place), "{:?}", loops[0].places);
    }
    // The guard covers the whole array, which the loop reaches past `load` and `store`.
    let guard = loops[0].guard.as_ref().expect("two bases");
    assert_eq!(guard.instance, Some((0, u64::from(ARRAY) + 40)));
    let fixture = Fixture::with_constants(code, loop_constants());
    let before = guard_outcomes();
    let (array, i) = run_array_loop(&fixture);
    let (promoted, unpromoted) = guard_outcomes();
    assert_eq!((promoted - before.0, unpromoted - before.1), (1, 0));
    let (expected_array, expected_sum) = expected_after_loop(None);
    assert_eq!(array, expected_array);
    assert_eq!(i, 11);
    let mut host = fixture.host();
    for k in 1..=10u32 {
        host.put(ARRAY + 4 * (k - 1), u64::from(100 * k), 4);
    }
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(4, 4) as u32 as i32, expected_sum);
}

#[test]
fn a_variable_inside_the_array_it_loops_over_is_not_promoted() {
    // `sum` is a[3]: its bytes lie inside the array's extent.
    let sum = I(ARRAY + 8);
    let code = array_loop(sum);
    let layout = Layout::of(&image(Vec::new(), loop_constants()), 1);
    let loops = promotable_loops(&code, &layout, None);
    assert_eq!(loops.len(), 1);
    assert!(
        !loops[0].places.contains(&(sum, 4)),
        "{:?}",
        loops[0].places
    );
    assert!(loops[0].places.contains(&(I(0), 4)));
    let fixture = Fixture::with_constants(code, loop_constants());
    let (array, i) = run_array_loop(&fixture);
    let (expected_array, expected_sum) = expected_after_loop(Some(3));
    assert_eq!(array, expected_array);
    assert_eq!(array[2], expected_sum);
    assert_eq!(i, 11);
}

/// Writes `size` bytes of `raw` at the absolute offset `at` of the memory.
fn put_at(host: &mut TestHost, at: u64, raw: u64, size: u32) {
    let at = at as usize;
    host.memory[at..at + size as usize].copy_from_slice(&raw.to_le_bytes()[..size as usize]);
}

/// The `size` bytes at the absolute offset `at` of the memory.
fn get_at(host: &TestHost, at: u64, size: u32) -> u64 {
    let at = at as usize;
    let mut bytes = [0u8; 8];
    bytes[..size as usize].copy_from_slice(&host.memory[at..at + size as usize]);
    u64::from_le_bytes(bytes)
}

/// Runs [`array_loop_over`] with its array at the absolute offset `array_at` holding
/// `a[k] = 100 · k`; the array and the memory after the run.
fn run_array_loop_at(fixture: &Fixture, array_at: u64) -> ([i32; 10], TestHost) {
    let mut host = fixture.host();
    for k in 1..=10u32 {
        put_at(
            &mut host,
            array_at + 4 * u64::from(k - 1),
            u64::from(100 * k),
            4,
        );
    }
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert!(host.ops.is_empty());
    assert!(host.faults.is_empty());
    let array = std::array::from_fn(|k| get_at(&host, array_at + 4 * k as u64, 4) as u32 as i32);
    (array, host)
}

#[test]
fn a_place_of_another_base_inside_the_array_fails_the_guard_by_the_extent_alone() {
    // The array is a global lying over the program instance's bytes 64 .. 104, `sum` is the
    // instance's 72 (a[3]) and `i` lies in the frame. The analysis takes the instance and
    // the data region as disjoint, so it promotes `sum`; only the array's extent (its first
    // element ends at 68, before `sum`) tells the guard that they share bytes.
    let layout = Layout::of(&image(Vec::new(), loop_constants()), 1);
    let array = Operand::Global((INSTANCE_AT - layout.data) as u32 + ARRAY);
    assert_eq!(layout.absolute(array), Some(INSTANCE_AT + u64::from(ARRAY)));
    let (i, sum) = (F(8), I(ARRAY + 8));
    let code = array_loop_over(i, array, 10, sum);
    let loops = promotable_loops(&code, &layout, None);
    assert_eq!(loops.len(), 1);
    assert!(loops[0].places.contains(&(sum, 4)), "{:?}", loops[0].places);
    assert!(loops[0].places.contains(&(i, 4)), "{:?}", loops[0].places);
    let guard = loops[0].guard.as_ref().expect("three bases");
    assert_eq!(
        guard.instance,
        Some((u64::from(ARRAY) + 8, u64::from(ARRAY) + 12))
    );
    let array_at = INSTANCE_AT + u64::from(ARRAY);
    assert_eq!(guard.fixed[0], Some((array_at, array_at + 40)));
    let fixture = Fixture::with_constants(code, loop_constants());
    let before = guard_outcomes();
    let (array, host) = run_array_loop_at(&fixture, array_at);
    let (promoted, unpromoted) = guard_outcomes();
    // The unpromoted copy ran, and so `sum`'s additions and the loop's stores to a[3] meet.
    // Its back-edge goes through the guard again, as in the promote tests' (0, 1001): one
    // failed guard per test of the condition, 10 passes and the exit.
    assert_eq!((promoted - before.0, unpromoted - before.1), (0, 11));
    let (expected_array, expected_sum) = expected_after_loop(Some(3));
    assert_eq!(array, expected_array);
    assert_eq!(host.get(ARRAY + 8, 4) as u32 as i32, expected_sum);
    assert_eq!(get_at(&host, fixture.frame_at() + 8, 4), 11);
}

#[test]
fn global_frame_and_constant_arrays_are_read_and_written_at_their_elements() {
    // The pool holds the constant array `[-2..2] OF DINT` at 16: 700 + k at element k.
    let mut constants = vec![0; 40];
    for element in 0..5u32 {
        let at = 16 + 4 * element as usize;
        constants[at..at + 4].copy_from_slice(&(700 + element).to_le_bytes());
    }
    let layout = Layout::of(&image(Vec::new(), constants.clone()), 1);
    let frame_at = layout.stacks;
    let bases = [
        (Operand::Global(16), layout.data + 16, true),
        (F(64), frame_at + 64, true),
        (Operand::Const(16), layout.constants + 16, false),
    ];
    for (array, array_at, writable) in bases {
        let mut code = vec![Instr::LoadElement {
            ty: Dint,
            dst: I(16),
            array,
            index: I(8),
            index_ty: Dint,
            low: -2,
            count: 5,
            stride: 4,
            offset: 0,
        }];
        if writable {
            code.push(Instr::StoreElement {
                ty: Dint,
                array,
                index: I(8),
                index_ty: Dint,
                low: -2,
                count: 5,
                stride: 4,
                offset: 0,
                src: I(24),
            });
        }
        let fixture = Fixture::with_constants(code, constants.clone());
        for index in -2i64..=2 {
            let chosen = (index + 2) as u64;
            let mut host = fixture.host();
            if writable {
                for element in 0..5u64 {
                    put_at(&mut host, array_at + 4 * element, 700 + element, 4);
                }
            }
            host.put(8, index as u64, 4);
            host.put(24, 4242, 4);
            assert_eq!(fixture.run(&mut host), Status::Ok, "{array:?} {index}");
            assert_eq!(host.get(16, 4), 700 + chosen, "{array:?} {index}");
            for element in 0..5u64 {
                let expected = if writable && element == chosen {
                    4242
                } else {
                    700 + element
                };
                assert_eq!(
                    get_at(&host, array_at + 4 * element, 4),
                    expected,
                    "{array:?} {index} {element}"
                );
            }
            assert!(host.ops.is_empty() && host.faults.is_empty());
            // An index outside faults at the load, whatever the base.
            let mut host = fixture.host();
            host.put(8, 3, 4);
            assert_eq!(fixture.run(&mut host), Status::Faulted, "{array:?}");
            assert_eq!(host.faults, outside(0, 3), "{array:?}");
        }
    }
}

#[test]
fn promoted_loops_over_global_and_frame_arrays_pass_their_guard() {
    let layout = Layout::of(&image(Vec::new(), loop_constants()), 1);
    for (array, array_at) in [
        (Operand::Global(16), layout.data + 16),
        (F(64), layout.stacks + 64),
    ] {
        let code = array_loop_over(I(0), array, 10, I(4));
        let loops = promotable_loops(&code, &layout, None);
        assert_eq!(loops.len(), 1, "{array:?}");
        assert!(loops[0].guard.is_some(), "{array:?}");
        assert!(loops[0].places.contains(&(I(4), 4)), "{array:?}");
        let fixture = Fixture::with_constants(code, loop_constants());
        let before = guard_outcomes();
        let (array_after, host) = run_array_loop_at(&fixture, array_at);
        let (promoted, unpromoted) = guard_outcomes();
        assert_eq!(
            (promoted - before.0, unpromoted - before.1),
            (1, 0),
            "{array:?}"
        );
        let (expected_array, expected_sum) = expected_after_loop(None);
        assert_eq!(array_after, expected_array, "{array:?}");
        assert_eq!(host.get(4, 4) as u32 as i32, expected_sum, "{array:?}");
        assert_eq!(host.get(0, 4), 11, "{array:?}");
    }
}

#[test]
fn a_fault_inside_a_promoted_array_loop_writes_its_places_back_first() {
    // `a: ARRAY[1..5]` while the loop runs to 10: i = 6 faults at the `LoadElement`.
    let code = array_loop_over(I(0), I(ARRAY), 5, I(4));
    let layout = Layout::of(&image(Vec::new(), loop_constants()), 1);
    let loops = promotable_loops(&code, &layout, None);
    assert_eq!(loops.len(), 1);
    assert!(loops[0].places.contains(&(I(0), 4)));
    assert!(loops[0].places.contains(&(I(4), 4)));
    let fixture = Fixture::with_constants(code, loop_constants());
    let mut host = fixture.host();
    for k in 1..=10u32 {
        host.put(ARRAY + 4 * (k - 1), u64::from(100 * k), 4);
    }
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    let site = Site {
        pou: 0,
        instruction: 3,
    };
    let fault = NativeFault::IndexOutOfBounds {
        index: 6,
        low: 1,
        high: 5,
    };
    assert_eq!(host.faults, vec![(site, fault)]);
    // The promoted `i` and `sum` reached memory at the fault: i is the faulting index and
    // sum the first five elements after their update.
    assert_eq!(host.get(0, 4), 6);
    let sum: i32 = (1..=5).map(|k| 100 * k + k).sum();
    assert_eq!(host.get(4, 4) as u32 as i32, sum);
    for k in 1..=10u32 {
        let expected = if k <= 5 { 101 * k } else { 100 * k };
        assert_eq!(host.get(ARRAY + 4 * (k - 1), 4), u64::from(expected), "{k}");
    }
}

#[test]
fn the_lowest_low_bound_wraps_the_offset_and_keeps_the_interpreters_high() {
    // `ARRAY[i64::MIN .. i64::MIN + 2] OF LINT`: i − low wraps for an index above 0, which
    // the bounds check must refuse before the offset is used.
    let low = i64::MIN;
    let load = Instr::LoadElement {
        ty: Lint,
        dst: I(16),
        array: I(ARRAY),
        index: I(8),
        index_ty: Lint,
        low,
        count: 3,
        stride: 8,
        offset: 0,
    };
    let store = Instr::StoreElement {
        ty: Lint,
        array: I(ARRAY),
        index: I(8),
        index_ty: Lint,
        low,
        count: 3,
        stride: 8,
        offset: 0,
        src: I(24),
    };
    let fixture = Fixture::new(vec![load, store]);
    for element in 0..3u64 {
        let index = low + element as i64;
        let mut host = fixture.host();
        for k in 0..3u32 {
            host.put(ARRAY + 8 * k, 1000 + u64::from(k), 8);
        }
        host.put(8, index as u64, 8);
        host.put(24, 55, 8);
        assert_eq!(fixture.run(&mut host), Status::Ok, "{index}");
        assert_eq!(host.get(16, 8), 1000 + element);
        for k in 0..3u32 {
            let expected = if u64::from(k) == element {
                55
            } else {
                1000 + u64::from(k)
            };
            assert_eq!(host.get(ARRAY + 8 * k, 8), expected, "{index} {k}");
        }
    }
    for index in [low + 3, -1, 0, 1, i64::MAX] {
        let mut host = fixture.host();
        host.put(8, index as u64, 8);
        assert_eq!(fixture.run(&mut host), Status::Faulted, "{index}");
        let fault = NativeFault::IndexOutOfBounds {
            index,
            low,
            high: low + 2,
        };
        let site = Site {
            pou: 0,
            instruction: 0,
        };
        assert_eq!(host.faults, vec![(site, fault)], "{index}");
        assert!((0..3).all(|k| host.get(ARRAY + 8 * k, 8) == 0));
    }
    // A high bound past i64::MAX saturates as the interpreter's: `[i64::MAX - 1 ..]` of 3.
    let saturated = Fixture::new(vec![Instr::LoadElement {
        ty: Lint,
        dst: I(16),
        array: I(ARRAY),
        index: I(8),
        index_ty: Lint,
        low: i64::MAX - 1,
        count: 3,
        stride: 8,
        offset: 0,
    }]);
    let mut host = saturated.host();
    host.put(8, 0, 8);
    assert_eq!(saturated.run(&mut host), Status::Faulted);
    let fault = NativeFault::IndexOutOfBounds {
        index: 0,
        low: i64::MAX - 1,
        high: i64::MAX,
    };
    assert_eq!(host.faults[0].1, fault);
    let mut host = saturated.host();
    host.put(ARRAY + 8, 31, 8);
    host.put(8, i64::MAX as u64, 8);
    assert_eq!(saturated.run(&mut host), Status::Ok);
    assert_eq!(host.get(16, 8), 31);
}
