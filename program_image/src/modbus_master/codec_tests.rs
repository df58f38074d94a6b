//! The value codec against known bit patterns of every channel type in both word orders, and
//! round trips of arbitrary bytes.

use proptest::prelude::*;

use super::*;
use crate::Elementary;

/// The registers of `values` (little-endian bytes of `value_type` values) in `order`.
#[track_caller]
fn registers(values: &[u8], value_type: Elementary, order: WordOrder) -> Vec<u16> {
    let mut registers = vec![0; values.len() / 2];
    values_to_registers(values, value_type, order, &mut registers)
        .unwrap_or_else(|error| panic!("{error}"));
    registers
}

/// The little-endian bytes of `registers` read as `value_type` values in `order`.
#[track_caller]
fn values(registers: &[u16], value_type: Elementary, order: WordOrder) -> Vec<u8> {
    let mut values = vec![0; registers.len() * 2];
    registers_to_values(registers, value_type, order, &mut values)
        .unwrap_or_else(|error| panic!("{error}"));
    values
}

/// Checks both directions of one value: its memory bytes and its registers high word first
/// (the low-first registers are the same words reversed).
#[track_caller]
fn check(value_type: Elementary, bytes: &[u8], high_first: &[u16]) {
    let low_first: Vec<u16> = high_first.iter().rev().copied().collect();
    assert_eq!(
        registers(bytes, value_type, WordOrder::HighFirst),
        high_first
    );
    assert_eq!(registers(bytes, value_type, WordOrder::LowFirst), low_first);
    assert_eq!(values(high_first, value_type, WordOrder::HighFirst), bytes);
    assert_eq!(values(&low_first, value_type, WordOrder::LowFirst), bytes);
}

#[test]
fn every_register_type_travels_in_the_documented_words() {
    check(Elementary::Int, &(-2i16).to_le_bytes(), &[0xFFFE]);
    check(Elementary::Uint, &0xBEEFu16.to_le_bytes(), &[0xBEEF]);
    check(Elementary::Dint, &(-2i32).to_le_bytes(), &[0xFFFF, 0xFFFE]);
    check(
        Elementary::Udint,
        &0x1234_5678u32.to_le_bytes(),
        &[0x1234, 0x5678],
    );
    check(
        Elementary::Lint,
        &(-0x0102_0304_0506_0708i64).to_le_bytes(),
        &[0xFEFD, 0xFCFB, 0xFAF9, 0xF8F8],
    );
    check(
        Elementary::Ulint,
        &0x0102_0304_0506_0708u64.to_le_bytes(),
        &[0x0102, 0x0304, 0x0506, 0x0708],
    );
    // 1.5 is 16#3FC00000 as a REAL and 16#3FF8000000000000 as an LREAL.
    check(Elementary::Real, &1.5f32.to_le_bytes(), &[0x3FC0, 0x0000]);
    check(
        Elementary::Lreal,
        &1.5f64.to_le_bytes(),
        &[0x3FF8, 0x0000, 0x0000, 0x0000],
    );
}

#[test]
fn an_array_keeps_its_values_in_address_order_each_in_the_word_order() {
    let bytes: Vec<u8> = [0x1111_2222u32, 0x3333_4444]
        .iter()
        .flat_map(|value| value.to_le_bytes())
        .collect();
    assert_eq!(
        registers(&bytes, Elementary::Udint, WordOrder::HighFirst),
        [0x1111, 0x2222, 0x3333, 0x4444]
    );
    assert_eq!(
        registers(&bytes, Elementary::Udint, WordOrder::LowFirst),
        [0x2222, 0x1111, 0x4444, 0x3333]
    );
    let ints: Vec<u8> = [1i16, -1, 300]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    assert_eq!(
        registers(&ints, Elementary::Int, WordOrder::LowFirst),
        [1, 0xFFFF, 300]
    );
}

#[test]
fn bits_become_bool_bytes_and_any_true_byte_sets_its_coil() {
    let mut bytes = [7; 4];
    bits_to_values(&[true, false, true, true], &mut bytes).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(bytes, [1, 0, 1, 1]);
    let mut bits = [false; 4];
    values_to_bits(&[0, 1, 2, 255], &mut bits).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(bits, [false, true, true, true]);
}

#[test]
fn buffers_that_do_not_match_are_refused_not_cut() {
    let mut values3 = [0u8; 3];
    assert!(matches!(
        registers_to_values(&[1], Elementary::Int, WordOrder::HighFirst, &mut values3),
        Err(CodecError::LengthMismatch { .. })
    ));
    // Three registers are not a whole number of DINTs.
    let mut values6 = [0u8; 6];
    assert!(matches!(
        registers_to_values(
            &[1, 2, 3],
            Elementary::Dint,
            WordOrder::HighFirst,
            &mut values6
        ),
        Err(CodecError::LengthMismatch { .. })
    ));
    let mut registers1 = [0u16; 1];
    assert_eq!(
        values_to_registers(
            &[1],
            Elementary::Bool,
            WordOrder::HighFirst,
            &mut registers1
        ),
        Err(CodecError::NotARegisterType(Elementary::Bool))
    );
    let mut bits = [false; 2];
    assert!(values_to_bits(&[1], &mut bits).is_err());
    let mut bytes = [0u8; 1];
    assert!(bits_to_values(&[true, true], &mut bytes).is_err());
    assert_eq!(
        CodecError::NotARegisterType(Elementary::Bool).to_string(),
        "BOOL values do not travel in registers"
    );
}

#[test]
fn words_per_value_follows_the_size_of_the_type() {
    for value_type in Elementary::ALL {
        let expected = match value_type.size_bytes() {
            1 => None,
            size => Some(size / 2),
        };
        assert_eq!(
            words_per_value(value_type),
            expected,
            "{}",
            value_type.name()
        );
    }
}

/// A register type and a whole number of its values as bytes.
fn typed_bytes() -> impl Strategy<Value = (Elementary, Vec<u8>)> {
    prop::sample::select(vec![
        Elementary::Int,
        Elementary::Uint,
        Elementary::Dint,
        Elementary::Udint,
        Elementary::Lint,
        Elementary::Ulint,
        Elementary::Real,
        Elementary::Lreal,
    ])
    .prop_flat_map(|value_type| {
        let size = value_type.size_bytes() as usize;
        (
            Just(value_type),
            (1usize..8)
                .prop_flat_map(move |count| prop::collection::vec(any::<u8>(), count * size)),
        )
    })
}

proptest! {
    #[test]
    fn values_survive_registers_in_either_word_order((value_type, bytes) in typed_bytes()) {
        for order in [WordOrder::HighFirst, WordOrder::LowFirst] {
            let words = registers(&bytes, value_type, order);
            prop_assert_eq!(values(&words, value_type, order), bytes.clone());
        }
        // The two orders differ exactly by reversing each value's words.
        let width = words_per_value(value_type).map_or(1, |w| w as usize);
        let high: Vec<u16> = registers(&bytes, value_type, WordOrder::HighFirst);
        let low: Vec<u16> = registers(&bytes, value_type, WordOrder::LowFirst);
        for (h, l) in high.chunks(width).zip(low.chunks(width)) {
            let reversed: Vec<u16> = l.iter().rev().copied().collect();
            prop_assert_eq!(h, reversed.as_slice());
        }
    }

    #[test]
    fn bits_survive_bool_bytes(bits in prop::collection::vec(any::<bool>(), 0..64)) {
        let mut bytes = vec![0; bits.len()];
        prop_assert!(bits_to_values(&bits, &mut bytes).is_ok());
        let mut back = vec![false; bits.len()];
        prop_assert!(values_to_bits(&bytes, &mut back).is_ok());
        prop_assert_eq!(back, bits);
    }
}
