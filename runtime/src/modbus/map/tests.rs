use super::*;

fn words(table: Table, start: u16, count: u16, byte_offset: u32) -> MapRange {
    MapRange {
        table,
        start,
        count,
        area: Area::Memory,
        byte_offset,
        words_per_value: 1,
        word_order: WordOrder::HighWordFirst,
    }
}

#[track_caller]
fn check_register(map: &ModbusMap, address: u16, area: Area, byte: usize) {
    assert_eq!(
        map.locate_register(Table::HoldingRegisters, address),
        Some(RegisterLocation { area, byte }),
        "holding register {address}"
    );
}

#[test]
fn the_default_map_is_a_valid_map() {
    let default = ModbusMap::default();
    assert_eq!(
        ModbusMap::new(default.ranges().copied()),
        Ok(default.clone())
    );
    assert_eq!(default.ranges().count(), 7);
}

#[test]
fn coils_and_discrete_inputs_pack_eight_to_a_byte() {
    let map = ModbusMap::default();
    let coil = |address| map.locate_bit(Table::Coils, address);
    assert_eq!(
        coil(0),
        Some(BitLocation {
            area: Area::Output,
            byte: 0,
            bit: 0
        })
    );
    assert_eq!(
        coil(13),
        Some(BitLocation {
            area: Area::Output,
            byte: 1,
            bit: 5
        })
    );
    assert_eq!(
        coil(8191),
        Some(BitLocation {
            area: Area::Output,
            byte: 1023,
            bit: 7
        })
    );
    assert_eq!(coil(8192), None);
    assert_eq!(
        map.locate_bit(Table::DiscreteInputs, 17),
        Some(BitLocation {
            area: Area::Input,
            byte: 2,
            bit: 1
        })
    );
}

#[test]
fn input_registers_are_input_words() {
    let map = ModbusMap::default();
    assert_eq!(
        map.locate_register(Table::InputRegisters, 5),
        Some(RegisterLocation {
            area: Area::Input,
            byte: 10
        })
    );
    assert_eq!(map.locate_register(Table::InputRegisters, 1024), None);
}

#[test]
fn holding_registers_follow_openplc_with_high_words_first() {
    let map = ModbusMap::default();
    check_register(&map, 0, Area::Output, 0);
    check_register(&map, 1023, Area::Output, 2046);
    check_register(&map, 1024, Area::Memory, 0);
    check_register(&map, 1025, Area::Memory, 2);
    // %MD5 is bytes 20..=23; its high word (bytes 22, 23) comes first.
    check_register(&map, 2048 + 10, Area::Memory, 22);
    check_register(&map, 2048 + 11, Area::Memory, 20);
    // %ML1 is bytes 8..=15, most significant word first.
    check_register(&map, 4096 + 4, Area::Memory, 14);
    check_register(&map, 4096 + 5, Area::Memory, 12);
    check_register(&map, 4096 + 6, Area::Memory, 10);
    check_register(&map, 4096 + 7, Area::Memory, 8);
    check_register(&map, 8191, Area::Memory, 8 * 1023);
    assert_eq!(map.locate_register(Table::HoldingRegisters, 8192), None);
}

#[test]
fn low_word_first_keeps_the_memory_order() {
    let range = MapRange {
        words_per_value: 2,
        word_order: WordOrder::LowWordFirst,
        ..words(Table::HoldingRegisters, 100, 4, 6)
    };
    let map = ModbusMap::new([range]).unwrap();
    check_register(&map, 100, Area::Memory, 6);
    check_register(&map, 101, Area::Memory, 8);
    check_register(&map, 102, Area::Memory, 10);
    check_register(&map, 103, Area::Memory, 12);
    assert_eq!(map.locate_register(Table::HoldingRegisters, 99), None);
    assert_eq!(map.locate_register(Table::HoldingRegisters, 104), None);
}

#[test]
fn a_bit_table_has_no_registers_and_a_register_table_no_bits() {
    let map = ModbusMap::new([
        words(Table::Coils, 0, 16, 0),
        words(Table::InputRegisters, 0, 1, 0),
    ])
    .unwrap();
    assert_eq!(map.locate_register(Table::Coils, 0), None);
    assert_eq!(map.locate_bit(Table::InputRegisters, 0), None);
    assert_eq!(map.locate_bit(Table::HoldingRegisters, 0), None);
}

#[test]
fn ranges_of_one_table_may_not_overlap() {
    let error = ModbusMap::new([
        words(Table::HoldingRegisters, 150, 11, 0),
        words(Table::HoldingRegisters, 100, 100, 0),
    ])
    .unwrap_err();
    assert_eq!(
        error,
        MapError::Overlap {
            table: Table::HoldingRegisters,
            first_start: 100,
            first_last: 199,
            second_start: 150,
            second_last: 160,
        }
    );
    assert_eq!(
        error.to_string(),
        "holding registers 100..=199 overlap holding registers 150..=160"
    );
}

#[test]
fn ranges_of_different_tables_or_touching_ranges_do_not_overlap() {
    let map = ModbusMap::new([
        words(Table::HoldingRegisters, 0, 10, 0),
        words(Table::InputRegisters, 0, 10, 0),
        words(Table::HoldingRegisters, 10, 10, 100),
    ])
    .unwrap();
    check_register(&map, 9, Area::Memory, 18);
    check_register(&map, 10, Area::Memory, 100);
}

#[test]
fn bad_ranges_are_refused_with_what_was_expected() {
    let cases = [
        (
            words(Table::Coils, 7, 0, 0),
            "coils range starting at 7 is empty: a range needs a count of at least 1",
        ),
        (
            words(Table::Coils, 65530, 7, 0),
            "coils 65530+7 runs past address 65535",
        ),
        (
            MapRange {
                words_per_value: 2,
                ..words(Table::Coils, 0, 8, 0)
            },
            "coils 0..=7 has 2 registers per value; expected 1",
        ),
        (
            MapRange {
                words_per_value: 3,
                ..words(Table::HoldingRegisters, 0, 9, 0)
            },
            "holding registers 0..=8 has 3 registers per value; expected 1, 2 or 4",
        ),
        (
            MapRange {
                words_per_value: 4,
                ..words(Table::HoldingRegisters, 0, 6, 0)
            },
            "holding registers 0..=5 holds 6 registers, not a whole number of values of 4 registers",
        ),
        (
            words(Table::InputRegisters, 0, 2, u32::MAX - 2),
            "input registers 0..=1 runs past byte 4294967295 of %M",
        ),
    ];
    for (range, message) in cases {
        assert_eq!(ModbusMap::new([range]).unwrap_err().to_string(), message);
    }
}

#[test]
fn a_range_may_end_at_the_last_address_and_byte() {
    let map = ModbusMap::new([words(Table::InputRegisters, 65534, 2, u32::MAX - 3)]).unwrap();
    assert_eq!(
        map.locate_register(Table::InputRegisters, 65535),
        Some(RegisterLocation {
            area: Area::Memory,
            byte: u32::MAX as usize - 1
        })
    );
}
