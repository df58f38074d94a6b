//! Element bounds, pointers made and resolved in every region, bad pointers.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use super::*;

fn element(index_ty: Elementary) -> Instr {
    Instr::Element {
        dst: I(16),
        base: I(0),
        index: I(8),
        index_ty,
        low: -2,
        count: 5,
        stride: 4,
    }
}

#[test]
fn element_checks_its_bounds() {
    let fixture = Fixture::new(vec![element(Dint)]);
    for index in -3i64..=3 {
        let mut host = fixture.host();
        host.put(0, 1 << 56 | 100, 8);
        host.put(8, index as u64, 4);
        let status = fixture.run(&mut host);
        if (-2..=2).contains(&index) {
            assert_eq!(status, Status::Ok);
            assert_eq!(host.get(16, 8), (1 << 56 | 100) + ((index + 2) as u64) * 4);
        } else {
            assert_eq!(status, Status::Faulted);
            let site = Site {
                pou: 0,
                instruction: 0,
            };
            let fault = NativeFault::IndexOutOfBounds {
                index,
                low: -2,
                high: 2,
            };
            assert_eq!(host.faults, vec![(site, fault)]);
        }
    }
}

/// The fault of an index outside −2 ..= 2, as the interpreter reports it.
fn outside(index: i64) -> Vec<(Site, NativeFault)> {
    let site = Site {
        pou: 0,
        instruction: 0,
    };
    let fault = NativeFault::IndexOutOfBounds {
        index,
        low: -2,
        high: 2,
    };
    vec![(site, fault)]
}

#[test]
fn an_unsigned_64_bit_index_above_i64_max_is_outside_even_a_negative_low_bound() {
    // Read as i64, 2⁶⁴ − 1 would be −1, inside −2 ..= 2: it is refused and reported as
    // i64::MAX, as the interpreter does, for ULINT and LWORD alike.
    for index_ty in [Ulint, Lword] {
        let fixture = Fixture::new(vec![element(index_ty)]);
        for raw in [u64::MAX, u64::MAX - 1, 1 << 63] {
            let mut host = fixture.host();
            host.put(0, 1 << 56 | 100, 8);
            host.put(8, raw, 8);
            assert_eq!(
                fixture.run(&mut host),
                Status::Faulted,
                "{index_ty:?} {raw}"
            );
            assert_eq!(host.faults, outside(i64::MAX));
        }
        // 2 still reaches the last element.
        let mut host = fixture.host();
        host.put(0, 1 << 56 | 100, 8);
        host.put(8, 2, 8);
        assert_eq!(fixture.run(&mut host), Status::Ok);
        assert_eq!(host.get(16, 8), (1 << 56 | 100) + 16);
    }
    // A signed LINT −1 stays −1, inside.
    let fixture = Fixture::new(vec![element(Lint)]);
    let mut host = fixture.host();
    host.put(0, 1 << 56 | 100, 8);
    host.put(8, u64::MAX, 8);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(16, 8), (1 << 56 | 100) + 4);
}

#[test]
fn open_element_refuses_an_unsigned_64_bit_index_above_i64_max() {
    // ARRAY[-2..2] OF DINT through a descriptor at I(0) (pointer, low, high), the ULINT
    // index at I(24), the element pointer written at I(32).
    let fixture = Fixture::new(vec![Instr::OpenElement {
        dst: I(32),
        descriptor: I(0),
        indices: vec![(I(24), Ulint)],
        stride: 4,
    }]);
    let array = 1 << 56 | 100;
    let prepared = |raw: u64| {
        let mut host = fixture.host();
        host.put(0, array, 8);
        host.put(8, (-2i64) as u64, 8);
        host.put(16, 2, 8);
        host.put(24, raw, 8);
        host
    };
    let mut host = prepared(u64::MAX);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    assert_eq!(host.faults, outside(i64::MAX));
    let mut host = prepared(1);
    assert_eq!(fixture.run(&mut host), Status::Ok);
    assert_eq!(host.get(32, 8), array + 3 * 4);
}

#[test]
fn pointers_are_made_and_resolved_in_every_region() {
    // Address of instance, frame, global, %I, %Q, %M and constant places, then a Load of
    // four bytes through each.
    let places = [
        I(200),
        Operand::Frame(8),
        Operand::Global(4),
        Operand::Input(4),
        Operand::Output(4),
        Operand::Memory(4),
        Operand::Const(4),
    ];
    let mut code = Vec::new();
    for (index, place) in places.iter().enumerate() {
        code.push(Instr::Address {
            dst: I(8 * index as u32),
            place: *place,
        });
        code.push(Instr::Load {
            size: 4,
            dst: I(64 + 4 * index as u32),
            ptr: I(8 * index as u32),
        });
    }
    let fixture = Fixture::with_constants(code, vec![0, 0, 0, 0, 0xC1, 0xC2, 0xC3, 0xC4]);
    let layout = fixture.layout;
    let mut host = fixture.host();
    let frame = fixture.frame_at();
    let stack_start = layout.stacks;
    let absolute = [
        INSTANCE_AT + 200,
        frame + 8,
        4,
        layout.input + 4,
        layout.output + 4,
        layout.memory + 4,
        layout.constants + 4,
    ];
    for (index, at) in absolute.iter().enumerate() {
        if index != 6 {
            host.memory[*at as usize..][..4].copy_from_slice(&(index as u32 + 10).to_le_bytes());
        }
    }
    assert_eq!(fixture.run(&mut host), Status::Ok);
    let expected_pointers = [
        (1 << 56) | (INSTANCE_AT + 200),
        (2 << 56) | (frame + 8 - stack_start),
        (1 << 56) | 4,
        (3 << 56) | 4,
        (4 << 56) | 4,
        (5 << 56) | 4,
        (6 << 56) | 4,
    ];
    for (index, pointer) in expected_pointers.iter().enumerate() {
        assert_eq!(host.get(8 * index as u32, 8), *pointer, "place {index}");
        assert_eq!(
            layout.pointer_to(absolute[index], stack_start + STACK as u64),
            *pointer
        );
        let expected = if index == 6 {
            0xC4C3_C2C1
        } else {
            index as u64 + 10
        };
        assert_eq!(host.get(64 + 4 * index as u32, 4), expected, "load {index}");
    }
}

#[test]
fn the_address_past_the_constant_pool_is_the_stacks_as_in_the_interpreter() {
    // `Const(len)` is a zero-size place verification accepts; it matches no fixed span, so
    // the interpreter's `pointer_to` finds it at the start of the first task's stack.
    let constants = vec![1, 2, 3, 4, 5, 6, 7, 8];
    let code = vec![Instr::Address {
        dst: I(0),
        place: Operand::Const(constants.len() as u32),
    }];
    let fixture = Fixture::with_constants(code, constants);
    let layout = fixture.layout;
    let mut host = fixture.host();
    assert_eq!(fixture.run(&mut host), Status::Ok);
    let stack_end = layout.stacks + layout.stack_size;
    let expected = layout.pointer_to(layout.constants + 8, stack_end);
    assert_eq!(
        expected,
        2 << 56,
        "the interpreter's rule, restated by the layout"
    );
    assert_eq!(host.get(0, 8), expected);
}

#[test]
fn bad_pointers_fault() {
    let code = vec![
        Instr::Store {
            size: 4,
            ptr: I(0),
            src: I(8),
        },
        Instr::Offset {
            dst: I(16),
            base: I(24),
            offset: 4,
        },
    ];
    let fixture = Fixture::new(code);
    let first = Site {
        pou: 0,
        instruction: 0,
    };
    let cases = [
        (0u64, NativeFault::NullPointer),
        (7 << 56, NativeFault::BadPointer(7 << 56)),
        (0xFF << 56, NativeFault::BadPointer(0xFF << 56)),
        // Four bytes at offset 14 of a 16-byte %I cross its end.
        ((3 << 56) | 14, NativeFault::BadPointer((3 << 56) | 14)),
        // The stack's span is the running task's: STACK bytes.
        (
            (2 << 56) | u64::from(STACK - 3),
            NativeFault::BadPointer((2 << 56) | u64::from(STACK - 3)),
        ),
    ];
    for (pointer, fault) in cases {
        let mut host = fixture.host();
        host.put(0, pointer, 8);
        assert_eq!(fixture.run(&mut host), Status::Faulted);
        assert_eq!(host.faults, vec![(first, fault)]);
    }
    // A pointer to the last four bytes of %I stores; then a null base of Offset faults.
    let mut host = fixture.host();
    host.put(0, (3 << 56) | 12, 8);
    host.put(8, 0xDEAD_BEEF, 4);
    assert_eq!(fixture.run(&mut host), Status::Faulted);
    let input_end = (fixture.layout.input + 12) as usize;
    assert_eq!(
        host.memory[input_end..input_end + 4],
        0xDEAD_BEEFu32.to_le_bytes()
    );
    let second = Site {
        pou: 0,
        instruction: 1,
    };
    assert_eq!(host.faults, vec![(second, NativeFault::NullPointer)]);
}
