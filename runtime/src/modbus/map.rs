//! Which Modbus addresses reach which bytes of the located areas.

use crate::areas::Area;

/// One of the four Modbus tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Table {
    /// Read and written bit by bit (function codes 1, 5, 15).
    Coils,
    /// Read bit by bit (function code 2).
    DiscreteInputs,
    /// Read as 16-bit registers (function code 4).
    InputRegisters,
    /// Read and written as 16-bit registers (function codes 3, 6, 16, 23).
    HoldingRegisters,
}

/// The order of the registers of a value wider than one register.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WordOrder {
    /// The first register holds the most significant word (OpenPLC, mbpoll's `-B`).
    HighWordFirst,
    /// The first register holds the least significant word (the order of the words in memory).
    LowWordFirst,
}

/// A run of consecutive addresses of one table mapped onto consecutive bytes of one area.
///
/// In a bit table, address `start + k` is bit `k mod 8` of byte `byte_offset + k div 8`.
/// In a register table the addresses are grouped into values of `words_per_value` registers;
/// value `v` is the little-endian integer at bytes `byte_offset + 2 * words_per_value * v`
/// onwards, and its registers come in `word_order`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MapRange {
    /// The Modbus table the addresses are in.
    pub table: Table,
    /// The first Modbus address (0-based, as in the request PDU).
    pub start: u16,
    /// How many addresses (bits or registers) the range covers.
    pub count: u16,
    /// The area the addresses reach.
    pub area: Area,
    /// The byte of the area that the first address reaches.
    pub byte_offset: u32,
    /// Registers per value: 1 for `%xW`, 2 for `%xD`, 4 for `%xL`; always 1 in a bit table.
    pub words_per_value: u8,
    /// The order of the registers of one value; without effect when `words_per_value` is 1.
    pub word_order: WordOrder,
}

/// A validated Modbus map: ranges that do not overlap within a table.
///
/// It lives as long as the server that uses it; the project will save its own map later.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModbusMap {
    /// The ranges of each table, sorted by start address, indexed by `table_index`.
    ranges_by_table: [Vec<MapRange>; 4],
}

/// Where a bit address leads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BitLocation {
    /// The area of the bit.
    pub area: Area,
    /// The byte in the area.
    pub byte: usize,
    /// The bit in the byte, 0 (least significant) to 7.
    pub bit: u8,
}

/// Where a register address leads: the little-endian word at `byte` and `byte + 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RegisterLocation {
    /// The area of the word.
    pub area: Area,
    /// The first of the word's two bytes in the area.
    pub byte: usize,
}

/// Why a list of ranges is not a valid map.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MapError {
    /// A range of no addresses.
    #[error("{table} range starting at {start} is empty: a range needs a count of at least 1")]
    Empty {
        /// The table of the range.
        table: Table,
        /// Its first address.
        start: u16,
    },
    /// A range that runs past address 65535.
    #[error("{table} {start}+{count} runs past address 65535")]
    PastLastAddress {
        /// The table of the range.
        table: Table,
        /// Its first address.
        start: u16,
        /// Its count.
        count: u16,
    },
    /// A `words_per_value` other than 1, 2 or 4, or other than 1 in a bit table.
    #[error(
        "{table} {start}..={last} has {words_per_value} registers per value; expected {expected}"
    )]
    WordsPerValue {
        /// The table of the range.
        table: Table,
        /// Its first address.
        start: u16,
        /// Its last address.
        last: u16,
        /// The wrong value.
        words_per_value: u8,
        /// What the table allows, in words.
        expected: &'static str,
    },
    /// A register range that ends in the middle of a value.
    #[error(
        "{table} {start}..={last} holds {count} registers, not a whole number of values of \
         {words_per_value} registers"
    )]
    PartialValue {
        /// The table of the range.
        table: Table,
        /// Its first address.
        start: u16,
        /// Its last address.
        last: u16,
        /// Its count.
        count: u16,
        /// Its registers per value.
        words_per_value: u8,
    },
    /// A range whose bytes run past byte 2^32 - 1 of its area.
    #[error("{table} {start}..={last} runs past byte 4294967295 of {area}")]
    PastLastByte {
        /// The table of the range.
        table: Table,
        /// Its first address.
        start: u16,
        /// Its last address.
        last: u16,
        /// The area.
        area: Area,
    },
    /// Two ranges that share addresses of one table.
    #[error("{table} {first_start}..={first_last} overlap {table} {second_start}..={second_last}")]
    Overlap {
        /// The table of both ranges.
        table: Table,
        /// The first address of the range that starts first.
        first_start: u16,
        /// Its last address.
        first_last: u16,
        /// The first address of the other range.
        second_start: u16,
        /// Its last address.
        second_last: u16,
    },
}

impl Table {
    /// All four tables, in the order of their function codes' numbers.
    pub const ALL: [Table; 4] = [
        Table::Coils,
        Table::DiscreteInputs,
        Table::HoldingRegisters,
        Table::InputRegisters,
    ];

    /// Whether the table holds bits rather than registers.
    pub fn holds_bits(self) -> bool {
        matches!(self, Table::Coils | Table::DiscreteInputs)
    }

    fn index(self) -> usize {
        match self {
            Table::Coils => 0,
            Table::DiscreteInputs => 1,
            Table::InputRegisters => 2,
            Table::HoldingRegisters => 3,
        }
    }
}

impl std::fmt::Display for Table {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Table::Coils => "coils",
            Table::DiscreteInputs => "discrete inputs",
            Table::InputRegisters => "input registers",
            Table::HoldingRegisters => "holding registers",
        })
    }
}

impl MapRange {
    /// The last address of the range, saturating at 65535 for a range that runs past it.
    pub fn last(&self) -> u16 {
        self.start.saturating_add(self.count.saturating_sub(1))
    }

    fn contains(&self, address: u16) -> bool {
        address >= self.start && u32::from(address) < u32::from(self.start) + u32::from(self.count)
    }

    /// Size in bytes of the area part the range covers.
    fn size_bytes(&self) -> u64 {
        if self.table.holds_bits() {
            u64::from(self.count).div_ceil(8)
        } else {
            u64::from(self.count) * 2
        }
    }

    fn validate(&self) -> Result<(), MapError> {
        let (table, start, count, last) = (self.table, self.start, self.count, self.last());
        if count == 0 {
            return Err(MapError::Empty { table, start });
        }
        if u32::from(start) + u32::from(count) > 0x1_0000 {
            return Err(MapError::PastLastAddress {
                table,
                start,
                count,
            });
        }
        let words_per_value = self.words_per_value;
        let expected = if table.holds_bits() { "1" } else { "1, 2 or 4" };
        if !(words_per_value == 1 || !table.holds_bits() && matches!(words_per_value, 2 | 4)) {
            return Err(MapError::WordsPerValue {
                table,
                start,
                last,
                words_per_value,
                expected,
            });
        }
        if count % u16::from(words_per_value) != 0 {
            return Err(MapError::PartialValue {
                table,
                start,
                last,
                count,
                words_per_value,
            });
        }
        if u64::from(self.byte_offset) + self.size_bytes() > 1 << 32 {
            return Err(MapError::PastLastByte {
                table,
                start,
                last,
                area: self.area,
            });
        }
        Ok(())
    }
}

impl ModbusMap {
    /// A map of `ranges`, or the first reason they do not make one.
    pub fn new(ranges: impl IntoIterator<Item = MapRange>) -> Result<Self, MapError> {
        let mut ranges_by_table: [Vec<MapRange>; 4] = Default::default();
        for range in ranges {
            range.validate()?;
            ranges_by_table[range.table.index()].push(range);
        }
        for ranges in &mut ranges_by_table {
            ranges.sort_by_key(|range| range.start);
            for pair in ranges.windows(2) {
                let (first, second) = (&pair[0], &pair[1]);
                if second.start <= first.last() {
                    return Err(MapError::Overlap {
                        table: first.table,
                        first_start: first.start,
                        first_last: first.last(),
                        second_start: second.start,
                        second_last: second.last(),
                    });
                }
            }
        }
        Ok(Self { ranges_by_table })
    }

    /// The default map, version 1 of `docs/modbus-map.md`: OpenPLC v3's map on Rivet's areas.
    pub fn openplc() -> Self {
        let range = |table, start, count, area, words_per_value| MapRange {
            table,
            start,
            count,
            area,
            byte_offset: 0,
            words_per_value,
            word_order: WordOrder::HighWordFirst,
        };
        let ranges = [
            range(Table::Coils, 0, 8192, Area::Output, 1),
            range(Table::DiscreteInputs, 0, 8192, Area::Input, 1),
            range(Table::InputRegisters, 0, 1024, Area::Input, 1),
            range(Table::HoldingRegisters, 0, 1024, Area::Output, 1),
            range(Table::HoldingRegisters, 1024, 1024, Area::Memory, 1),
            range(Table::HoldingRegisters, 2048, 2048, Area::Memory, 2),
            range(Table::HoldingRegisters, 4096, 4096, Area::Memory, 4),
        ];
        let mut ranges_by_table: [Vec<MapRange>; 4] = Default::default();
        for range in ranges {
            ranges_by_table[range.table.index()].push(range);
        }
        Self { ranges_by_table }
    }

    /// The map an image asks for: its project's own ranges, or the default map when it has
    /// none. Registers of multi-register values come most significant word first.
    pub fn for_image(image: &program_image::ProgramImage) -> Result<Self, MapError> {
        let Some(ranges) = &image.modbus_map else {
            return Ok(Self::openplc());
        };
        Self::new(ranges.iter().map(|range| MapRange {
            table: match range.table {
                program_image::ModbusTable::Coils => Table::Coils,
                program_image::ModbusTable::DiscreteInputs => Table::DiscreteInputs,
                program_image::ModbusTable::InputRegisters => Table::InputRegisters,
                program_image::ModbusTable::HoldingRegisters => Table::HoldingRegisters,
            },
            start: range.start,
            count: range.count,
            area: match range.region {
                program_image::Region::Input => Area::Input,
                program_image::Region::Output => Area::Output,
                _ => Area::Memory,
            },
            byte_offset: range.byte_offset,
            words_per_value: range.words_per_value,
            word_order: WordOrder::HighWordFirst,
        }))
    }

    /// Every range of the map, table by table, each table's ranges by start address.
    pub fn ranges(&self) -> impl Iterator<Item = &MapRange> {
        self.ranges_by_table.iter().flatten()
    }

    /// Where bit `address` of a bit table leads, or `None` when no range maps it (or `table` is
    /// a register table).
    pub fn locate_bit(&self, table: Table, address: u16) -> Option<BitLocation> {
        let range = self.range_of(table, address)?;
        if !table.holds_bits() {
            return None;
        }
        let k = usize::from(address - range.start);
        Some(BitLocation {
            area: range.area,
            byte: usize::try_from(range.byte_offset).ok()? + k / 8,
            bit: (k % 8) as u8,
        })
    }

    /// Where register `address` of a register table leads, or `None` when no range maps it (or
    /// `table` is a bit table).
    pub fn locate_register(&self, table: Table, address: u16) -> Option<RegisterLocation> {
        let range = self.range_of(table, address)?;
        if table.holds_bits() {
            return None;
        }
        let k = usize::from(address - range.start);
        let words = usize::from(range.words_per_value);
        let (value, word_in_request_order) = (k / words, k % words);
        let word_in_memory_order = match range.word_order {
            WordOrder::HighWordFirst => words - 1 - word_in_request_order,
            WordOrder::LowWordFirst => word_in_request_order,
        };
        Some(RegisterLocation {
            area: range.area,
            byte: usize::try_from(range.byte_offset).ok()?
                + 2 * (value * words + word_in_memory_order),
        })
    }

    fn range_of(&self, table: Table, address: u16) -> Option<&MapRange> {
        let ranges = &self.ranges_by_table[table.index()];
        let after = ranges.partition_point(|range| range.start <= address);
        let range = ranges.get(after.checked_sub(1)?)?;
        range.contains(address).then_some(range)
    }
}

impl Default for ModbusMap {
    /// The OpenPLC-compatible map of [`ModbusMap::openplc`].
    fn default() -> Self {
        Self::openplc()
    }
}

#[cfg(test)]
mod tests;
