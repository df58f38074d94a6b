use super::*;
use crate::areas::Area;
use crate::modbus::map::{MapRange, WordOrder};

/// Areas as large as the default map reaches: 1024 bytes of `%I` and `%Q`, 8192 of `%M`.
fn full_areas() -> LocatedAreas {
    LocatedAreas::new(1024, 2048, 8192)
}

#[track_caller]
fn check(areas: &mut LocatedAreas, request: &[u8], expected: &[u8]) {
    let response = handle_pdu(areas, &ModbusMap::default(), request);
    assert_eq!(response, expected, "response to {request:02x?}");
}

/// Checks that `request` is answered with `exception` and leaves the areas unchanged.
#[track_caller]
fn check_exception(areas: &mut LocatedAreas, request: &[u8], exception: u8) {
    let before = areas.clone();
    let function = request.first().copied().unwrap_or(0);
    check(areas, request, &[function | 0x80, exception]);
    assert!(*areas == before, "{request:02x?} changed the areas");
}

#[test]
fn coils_read_packed_from_the_output_bits() {
    let mut areas = full_areas();
    areas.output[0] = 0b1010_0000;
    areas.output[1] = 0b0000_0111;
    // Coils 5..=14: 1, 0, 1, then 1, 1, 1, 0, 0, 0, 0.
    check(&mut areas, &[1, 0, 5, 0, 10], &[1, 2, 0b0011_1101, 0b00]);
    check(&mut areas, &[1, 0x1f, 0xff, 0, 1], &[1, 1, 0]);
}

#[test]
fn discrete_inputs_read_the_input_bits() {
    let mut areas = full_areas();
    areas.input[2] = 0b10;
    check(&mut areas, &[2, 0, 16, 0, 2], &[2, 1, 0b10]);
    check(&mut areas, &[2, 0, 0, 0x07, 0xd0], &{
        let mut expected = vec![2, 250];
        expected.extend([0; 250]);
        expected[1 + 1 + 2] = 0b10;
        expected
    });
}

#[test]
fn registers_are_big_endian_words_of_little_endian_areas() {
    let mut areas = full_areas();
    areas.set_word(Area::Input, 3, 0xbeef).unwrap();
    areas.set_word(Area::Output, 1023, 0x1234).unwrap();
    areas.set_word(Area::Memory, 0, 0x5678).unwrap();
    check(&mut areas, &[4, 0, 3, 0, 1], &[4, 2, 0xbe, 0xef]);
    // Holding registers 1023 and 1024 are %QW1023 and %MW0.
    check(
        &mut areas,
        &[3, 0x03, 0xff, 0, 2],
        &[3, 4, 0x12, 0x34, 0x56, 0x78],
    );
}

#[test]
fn a_double_word_reads_high_word_first_as_in_openplc() {
    let mut areas = full_areas();
    areas.memory[20..24].copy_from_slice(&0x1234_5678_u32.to_le_bytes());
    // %MD5 is holding registers 2058 and 2059.
    check(
        &mut areas,
        &[3, 0x08, 0x0a, 0, 2],
        &[3, 4, 0x12, 0x34, 0x56, 0x78],
    );
    check(
        &mut areas,
        &[16, 0x08, 0x0a, 0, 2, 4, 0xca, 0xfe, 0xba, 0xbe],
        &[16, 0x08, 0x0a, 0, 2],
    );
    assert_eq!(areas.memory[20..24], 0xcafe_babe_u32.to_le_bytes());
}

#[test]
fn a_long_word_reads_most_significant_word_first() {
    let mut areas = full_areas();
    areas.memory[8..16].copy_from_slice(&0x0102_0304_0506_0708_u64.to_le_bytes());
    // %ML1 is holding registers 4100..=4103.
    check(
        &mut areas,
        &[3, 0x10, 0x04, 0, 4],
        &[3, 8, 1, 2, 3, 4, 5, 6, 7, 8],
    );
}

#[test]
fn single_writes_echo_the_request() {
    let mut areas = full_areas();
    check(&mut areas, &[5, 0, 9, 0xff, 0], &[5, 0, 9, 0xff, 0]);
    assert_eq!(areas.output[1], 0b10);
    check(&mut areas, &[5, 0, 9, 0, 0], &[5, 0, 9, 0, 0]);
    assert_eq!(areas.output[1], 0);
    check(
        &mut areas,
        &[6, 0x04, 0x01, 0xab, 0xcd],
        &[6, 0x04, 0x01, 0xab, 0xcd],
    );
    assert_eq!(areas.word(Area::Memory, 1), Some(0xabcd));
}

#[test]
fn multiple_coils_are_written_from_packed_bits() {
    let mut areas = full_areas();
    areas.output[1] = 0xff;
    check(
        &mut areas,
        &[15, 0, 4, 0, 10, 2, 0b1100_0101, 0b01],
        &[15, 0, 4, 0, 10],
    );
    assert_eq!(areas.output[..3], [0b0101_0000, 0b1101_1100, 0]);
}

#[test]
fn read_write_multiple_registers_writes_before_it_reads() {
    let mut areas = full_areas();
    check(
        &mut areas,
        &[23, 0, 0, 0, 3, 0, 1, 0, 1, 2, 0x11, 0x22],
        &[23, 6, 0, 0, 0x11, 0x22, 0, 0],
    );
    assert_eq!(areas.word(Area::Output, 1), Some(0x1122));
}

#[test]
fn function_codes_other_than_the_standard_ones_are_illegal() {
    let mut areas = full_areas();
    for function in [0, 7, 8, 17, 20, 22, 24, 43, 0x41, 0x7f, 0x81, 0xff] {
        check_exception(&mut areas, &[function, 0, 0, 0, 1], 1);
    }
    check(&mut areas, &[], &[0x80, 1]);
}

#[test]
fn addresses_beyond_the_areas_present_are_illegal() {
    let mut areas = LocatedAreas::new(2, 2, 8);
    check(&mut areas, &[1, 0, 15, 0, 1], &[1, 1, 0]);
    check_exception(&mut areas, &[1, 0, 15, 0, 2], 2);
    check_exception(&mut areas, &[2, 0, 16, 0, 1], 2);
    check_exception(&mut areas, &[4, 0, 1, 0, 1], 2);
    check_exception(&mut areas, &[3, 0, 0, 0, 2], 2);
    check_exception(&mut areas, &[5, 0, 16, 0xff, 0], 2);
    check_exception(&mut areas, &[6, 0x04, 0x04, 0, 1], 2);
    // %MD1 (registers 2050, 2051) exists in 8 bytes of %M; %MD2 does not.
    check(&mut areas, &[3, 0x08, 0x02, 0, 2], &[3, 4, 0, 0, 0, 0]);
    check_exception(&mut areas, &[3, 0x08, 0x04, 0, 1], 2);
    // %ML0 (registers 4096..=4099) just fits; %ML1 does not.
    check(
        &mut areas,
        &[3, 0x10, 0x00, 0, 4],
        &[3, 8, 0, 0, 0, 0, 0, 0, 0, 0],
    );
    check_exception(&mut areas, &[3, 0x10, 0x04, 0, 1], 2);
}

#[test]
fn unmapped_addresses_are_illegal() {
    let mut areas = full_areas();
    check_exception(&mut areas, &[3, 0x20, 0x00, 0, 1], 2);
    check_exception(&mut areas, &[1, 0x20, 0x00, 0, 1], 2);
    check_exception(&mut areas, &[4, 0x04, 0x00, 0, 1], 2);
    check_exception(&mut areas, &[3, 0xff, 0xff, 0, 2], 2);
}

#[test]
fn a_write_partly_out_of_range_changes_nothing() {
    let mut areas = LocatedAreas::new(0, 4, 0);
    check_exception(&mut areas, &[16, 0, 1, 0, 2, 4, 1, 1, 2, 2], 2);
    check_exception(&mut areas, &[15, 0, 30, 0, 3, 1, 0b111], 2);
    check_exception(&mut areas, &[23, 0, 0, 0, 1, 0, 2, 0, 1, 2, 1, 1], 2);
    check_exception(&mut areas, &[23, 0, 2, 0, 1, 0, 0, 0, 1, 2, 1, 1], 2);
}

#[test]
fn quantities_outside_the_modbus_limits_are_illegal_values() {
    let mut areas = full_areas();
    check_exception(&mut areas, &[1, 0, 0, 0, 0], 3);
    check_exception(&mut areas, &[1, 0, 0, 0x07, 0xd1], 3);
    check_exception(&mut areas, &[2, 0, 0, 0, 0], 3);
    check_exception(&mut areas, &[3, 0, 0, 0, 126], 3);
    check_exception(&mut areas, &[4, 0, 0, 0, 0], 3);
    check_exception(&mut areas, &[15, 0, 0, 0, 0, 0], 3);
    let mut coils = vec![15, 0, 0, 0x07, 0xb1, 247];
    coils.extend([0; 247]);
    check_exception(&mut areas, &coils, 3);
    let mut registers = vec![16, 0, 0, 0, 124, 248];
    registers.extend([0; 248]);
    check_exception(&mut areas, &registers, 3);
    check_exception(&mut areas, &[16, 0, 0, 0, 0, 0], 3);
    check_exception(&mut areas, &[23, 0, 0, 0, 126, 0, 0, 0, 1, 2, 0, 0], 3);
    let mut read_write = vec![23, 0, 0, 0, 1, 0, 0, 0, 122, 244];
    read_write.extend([0; 244]);
    check_exception(&mut areas, &read_write, 3);
}

#[test]
fn the_largest_requests_are_served() {
    let mut areas = full_areas();
    let mut coils = vec![15, 0, 0, 0x07, 0xb0, 246];
    coils.extend([0xff; 246]);
    check(&mut areas, &coils, &[15, 0, 0, 0x07, 0xb0]);
    assert!(areas.output[..246].iter().all(|&byte| byte == 0xff));
    let mut registers = vec![16, 0, 0, 0, 123, 246];
    registers.extend([0x01; 246]);
    check(&mut areas, &registers, &[16, 0, 0, 0, 123]);
    let response = handle_pdu(&mut areas, &ModbusMap::default(), &[3, 0, 0, 0, 125]);
    assert_eq!(response.len(), 2 + 250);
}

#[test]
fn byte_counts_and_lengths_that_do_not_fit_are_illegal_values() {
    let mut areas = full_areas();
    // Truncated and overlong requests.
    check_exception(&mut areas, &[1, 0, 0, 0], 3);
    check_exception(&mut areas, &[3], 3);
    check_exception(&mut areas, &[4, 0, 0, 0, 1, 0], 3);
    check_exception(&mut areas, &[6, 0, 0, 0], 3);
    check_exception(&mut areas, &[16, 0, 0, 0, 1], 3);
    // Byte counts that disagree with the quantity or the data.
    check_exception(&mut areas, &[15, 0, 0, 0, 9, 1, 0xff], 3);
    check_exception(&mut areas, &[15, 0, 0, 0, 100, 1, 0xff], 3);
    check_exception(&mut areas, &[15, 0, 0, 0, 8, 1, 0xff, 0], 3);
    check_exception(&mut areas, &[16, 0, 0, 0, 2, 2, 0, 1], 3);
    check_exception(&mut areas, &[16, 0, 0, 0, 1, 2, 0], 3);
    check_exception(&mut areas, &[16, 0, 0, 0x80, 0, 0], 3);
    check_exception(&mut areas, &[23, 0, 0, 0, 1, 0, 0, 0x80, 0, 0], 3);
    // Coil values other than on and off.
    check_exception(&mut areas, &[5, 0, 0, 0, 1], 3);
    check_exception(&mut areas, &[5, 0, 0, 0xff, 0xff], 3);
}

#[test]
fn a_quantity_is_checked_before_the_address() {
    let mut areas = LocatedAreas::new(0, 0, 0);
    check_exception(&mut areas, &[3, 0xff, 0xff, 0, 0], 3);
    check_exception(&mut areas, &[3, 0xff, 0xff, 0, 1], 2);
}

#[test]
fn a_map_of_its_own_reaches_inputs_with_low_words_first() {
    let map = ModbusMap::new([MapRange {
        table: Table::HoldingRegisters,
        start: 100,
        count: 2,
        area: Area::Input,
        byte_offset: 4,
        words_per_value: 2,
        word_order: WordOrder::LowWordFirst,
    }])
    .unwrap();
    let mut areas = LocatedAreas::new(8, 0, 0);
    areas.input[4..8].copy_from_slice(&0x1234_5678_u32.to_le_bytes());
    let response = handle_pdu(&mut areas, &map, &[3, 0, 100, 0, 2]);
    assert_eq!(response, [3, 4, 0x56, 0x78, 0x12, 0x34]);
    assert_eq!(handle_pdu(&mut areas, &map, &[3, 0, 0, 0, 1]), [0x83, 2]);
}
