//! The located areas `%I`, `%Q` and `%M` as bytes in the CODESYS layout.
//!
//! `%MWn` is bytes `2n..=2n+1` little-endian, `%MDn` bytes `4n..=4n+3`, `%MLn` bytes
//! `8n..=8n+7`, and `%MXb.i` bit `i` of byte `b`; `%I` and `%Q` are laid out the same way.
//! They are shared behind an `Arc<std::sync::Mutex<LocatedAreas>>`. The scheduler locks them
//! only to exchange them with the program's memory at the start and the end of an outermost
//! cycle, and never waits for the lock (a busy lock defers the exchange to the next cycle, see
//! [`LocatedAreas::exchange`]); the Modbus server holds it for one request, so every request
//! sees the areas as they are between two cycles.

mod exchange;

/// One of the three located areas.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Area {
    /// `%I`, the inputs.
    Input,
    /// `%Q`, the outputs.
    Output,
    /// `%M`, the memory (flags).
    Memory,
}

/// The bytes of `%I`, `%Q` and `%M`.
///
/// They live as long as the runtime runs one program image; they are not saved (retain data is
/// kept elsewhere). Besides the bytes, they remember which bits of `%Q` and `%M` clients wrote
/// through [`LocatedAreas::set_bit`] and [`LocatedAreas::set_word_at_byte`] since the program
/// last took them in, so that a write is never lost when an exchange is deferred (equality
/// compares those marks too).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LocatedAreas {
    /// `%I`: the inputs, written by the I/O layer before each cycle.
    pub input: Vec<u8>,
    /// `%Q`: the outputs, written by the program and read by the I/O layer after each cycle.
    pub output: Vec<u8>,
    /// `%M`: the memory, free for the program and for Modbus clients.
    pub memory: Vec<u8>,
    /// The bits of `%Q` written by clients since the last exchange; empty when none.
    written_output: Vec<u8>,
    /// The bits of `%M` written by clients since the last exchange; empty when none.
    written_memory: Vec<u8>,
}

impl Area {
    /// The IEC letter of the area: `I`, `Q` or `M`.
    pub fn letter(self) -> char {
        match self {
            Area::Input => 'I',
            Area::Output => 'Q',
            Area::Memory => 'M',
        }
    }
}

impl std::fmt::Display for Area {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "%{}", self.letter())
    }
}

impl LocatedAreas {
    /// Areas of the given sizes in bytes, all zero.
    pub fn new(input_bytes: usize, output_bytes: usize, memory_bytes: usize) -> Self {
        Self {
            input: vec![0; input_bytes],
            output: vec![0; output_bytes],
            memory: vec![0; memory_bytes],
            written_output: Vec::new(),
            written_memory: Vec::new(),
        }
    }

    /// The bytes of one area.
    pub fn bytes(&self, area: Area) -> &[u8] {
        match area {
            Area::Input => &self.input,
            Area::Output => &self.output,
            Area::Memory => &self.memory,
        }
    }

    /// The bytes of one area, for writing. A write through it is not marked as a client's: a
    /// running program's next exchange may undo it in `%Q` and `%M` (use
    /// [`LocatedAreas::write_bytes`] there).
    pub fn bytes_mut(&mut self, area: Area) -> &mut [u8] {
        match area {
            Area::Input => &mut self.input,
            Area::Output => &mut self.output,
            Area::Memory => &mut self.memory,
        }
    }

    /// Writes `bytes` from byte `byte` of `area` as a client does, so the running program takes
    /// them in at its next exchange; `None` (and no change) when they do not fit in the area.
    pub fn write_bytes(&mut self, area: Area, byte: usize, bytes: &[u8]) -> Option<()> {
        let end = byte.checked_add(bytes.len())?;
        self.bytes_mut(area)
            .get_mut(byte..end)?
            .copy_from_slice(bytes);
        self.mark_written(area, byte, std::iter::repeat_n(0xFF, bytes.len()));
        Some(())
    }

    /// Bit `bit` of byte `byte` (`%IXbyte.bit`, `%QX…`, `%MX…`), or `None` when the byte is
    /// outside the area or `bit` is above 7.
    pub fn bit(&self, area: Area, byte: usize, bit: u8) -> Option<bool> {
        if bit > 7 {
            return None;
        }
        self.bytes(area)
            .get(byte)
            .map(|value| value >> bit & 1 == 1)
    }

    /// Sets bit `bit` of byte `byte` to `value`; `None` (and no change) when the byte is outside
    /// the area or `bit` is above 7.
    pub fn set_bit(&mut self, area: Area, byte: usize, bit: u8, value: bool) -> Option<()> {
        if bit > 7 {
            return None;
        }
        let target = self.bytes_mut(area).get_mut(byte)?;
        if value {
            *target |= 1 << bit;
        } else {
            *target &= !(1 << bit);
        }
        self.mark_written(area, byte, [1 << bit]);
        Some(())
    }

    /// The 16-bit word `%IWn`, `%QWn` or `%MWn` (bytes `2n` and `2n+1`, little-endian), or `None`
    /// when either byte is outside the area.
    pub fn word(&self, area: Area, index: usize) -> Option<u16> {
        self.word_at_byte(area, index.checked_mul(2)?)
    }

    /// Sets the 16-bit word `%IWn`, `%QWn` or `%MWn`; `None` (and no change) when either byte is
    /// outside the area.
    pub fn set_word(&mut self, area: Area, index: usize, value: u16) -> Option<()> {
        self.set_word_at_byte(area, index.checked_mul(2)?, value)
    }

    /// The little-endian 16-bit word at bytes `byte` and `byte+1`, which need not be aligned, or
    /// `None` when either byte is outside the area.
    pub fn word_at_byte(&self, area: Area, byte: usize) -> Option<u16> {
        let bytes = self.bytes(area).get(byte..byte.checked_add(2)?)?;
        Some(u16::from_le_bytes([bytes[0], bytes[1]]))
    }

    /// Sets the little-endian 16-bit word at bytes `byte` and `byte+1`; `None` (and no change)
    /// when either byte is outside the area.
    pub fn set_word_at_byte(&mut self, area: Area, byte: usize, value: u16) -> Option<()> {
        let end = byte.checked_add(2)?;
        self.bytes_mut(area)
            .get_mut(byte..end)?
            .copy_from_slice(&value.to_le_bytes());
        self.mark_written(area, byte, [0xFF, 0xFF]);
        Some(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_memory_word_overlaps_two_bytes_little_endian() {
        let mut areas = LocatedAreas::new(0, 0, 4);
        areas.set_word(Area::Memory, 1, 0x1234).unwrap();
        assert_eq!(areas.memory, [0, 0, 0x34, 0x12]);
        assert_eq!(areas.word(Area::Memory, 1), Some(0x1234));
        assert_eq!(areas.word_at_byte(Area::Memory, 1), Some(0x3400));
    }

    #[test]
    fn bits_count_from_the_least_significant_bit_of_their_byte() {
        let mut areas = LocatedAreas::new(2, 2, 0);
        areas.set_bit(Area::Output, 1, 3, true).unwrap();
        assert_eq!(areas.output, [0, 0b1000]);
        assert_eq!(areas.bit(Area::Output, 1, 3), Some(true));
        assert_eq!(areas.bit(Area::Output, 1, 2), Some(false));
        areas.set_bit(Area::Output, 1, 3, false).unwrap();
        assert_eq!(areas.output, [0, 0]);
        assert_eq!(areas.bit(Area::Input, 0, 0), Some(false));
    }

    #[test]
    fn accesses_outside_an_area_give_none_and_change_nothing() {
        let mut areas = LocatedAreas::new(1, 3, 0);
        assert_eq!(areas.bit(Area::Input, 1, 0), None);
        assert_eq!(areas.bit(Area::Input, 0, 8), None);
        assert_eq!(areas.set_bit(Area::Output, 3, 0, true), None);
        assert_eq!(areas.set_bit(Area::Output, 0, 8, true), None);
        assert_eq!(areas.word(Area::Output, 1), None);
        assert_eq!(areas.set_word(Area::Output, 1, 0xffff), None);
        assert_eq!(areas.word(Area::Memory, 0), None);
        assert_eq!(areas.word(Area::Output, usize::MAX), None);
        assert_eq!(areas.word_at_byte(Area::Output, usize::MAX), None);
        assert_eq!(areas.set_word_at_byte(Area::Output, usize::MAX, 1), None);
        assert_eq!(areas.output, [0, 0, 0]);
        assert_eq!(areas.word(Area::Output, 0), Some(0));
    }

    #[test]
    fn an_area_displays_as_its_iec_prefix() {
        assert_eq!(Area::Input.to_string(), "%I");
        assert_eq!(Area::Output.to_string(), "%Q");
        assert_eq!(Area::Memory.to_string(), "%M");
    }
}
