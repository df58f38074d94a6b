//! The value codec of `docs/modbus-master.md` §6.5: coils and registers as they travel, to and
//! from the little-endian bytes the program's variables hold.
//!
//! Registers are 16-bit words (tokio-modbus has already taken each from its big-endian bytes);
//! a value of 2 or 4 registers is assembled in the device's word order. Bits are booleans, one
//! per coil or discrete input, and a BOOL variable holds one byte, 0 or 1. A read of bits does
//! not give exactly those booleans: tokio-modbus 0.17's `Client::call` answers with 8 booleans
//! per byte of the response, the last byte padded, since the response does not say how many
//! were asked for. The caller first checks the byte count (`ceil(quantity / 8)`,
//! `docs/modbus-master.md` §6.6), then passes each channel the slice `[offset, offset + count)`
//! of its request. The master converts on its own thread, so the scheduler's copy into the
//! program is one `memcpy` per channel.

use crate::Elementary;

use super::WordOrder;

/// Why a conversion could not be made: the caller's buffers do not match the channel.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum CodecError {
    /// The type takes no whole number of registers (BOOL and the one-byte types).
    #[error("{} values do not travel in registers", .0.name())]
    NotARegisterType(Elementary),
    /// The two sides hold different numbers of values.
    #[error(
        "{registers_or_bits} coils or registers do not hold the {value_bytes} bytes of the values: expected {expected_bytes} bytes"
    )]
    LengthMismatch {
        /// The registers or bits given.
        registers_or_bits: usize,
        /// The bytes of values given.
        value_bytes: usize,
        /// The bytes of values that the registers or bits hold.
        expected_bytes: usize,
    },
}

/// How many registers one value of `value_type` takes: 1 for the 2-byte types, 2 for the 4-byte
/// ones, 4 for the 8-byte ones, and `None` for BOOL and the one-byte types.
pub fn words_per_value(value_type: Elementary) -> Option<u32> {
    match value_type.size_bytes() {
        2 => Some(1),
        4 => Some(2),
        8 => Some(4),
        _ => None,
    }
}

/// Converts `registers` (consecutive values of `value_type`, words in `order`) into `values`,
/// the little-endian bytes of the same values in the program's memory layout.
pub fn registers_to_values(
    registers: &[u16],
    value_type: Elementary,
    order: WordOrder,
    values: &mut [u8],
) -> Result<(), CodecError> {
    let words = checked_words(registers.len(), value_type, values.len())?;
    for (value, bytes) in registers.chunks(words).zip(values.chunks_mut(2 * words)) {
        for (index, word) in value.iter().enumerate() {
            // In memory the least significant word comes first.
            let place = match order {
                WordOrder::HighFirst => words - 1 - index,
                WordOrder::LowFirst => index,
            };
            bytes[2 * place..2 * place + 2].copy_from_slice(&word.to_le_bytes());
        }
    }
    Ok(())
}

/// Converts `values` (little-endian bytes of consecutive values of `value_type`) into
/// `registers`, words in `order`: the inverse of [`registers_to_values`].
pub fn values_to_registers(
    values: &[u8],
    value_type: Elementary,
    order: WordOrder,
    registers: &mut [u16],
) -> Result<(), CodecError> {
    let words = checked_words(registers.len(), value_type, values.len())?;
    for (value, bytes) in registers.chunks_mut(words).zip(values.chunks(2 * words)) {
        for (index, word) in value.iter_mut().enumerate() {
            let place = match order {
                WordOrder::HighFirst => words - 1 - index,
                WordOrder::LowFirst => index,
            };
            *word = u16::from_le_bytes([bytes[2 * place], bytes[2 * place + 1]]);
        }
    }
    Ok(())
}

/// Converts coils or discrete inputs into BOOL values, one byte each: 1 for a set bit, 0 else.
pub fn bits_to_values(bits: &[bool], values: &mut [u8]) -> Result<(), CodecError> {
    if bits.len() != values.len() {
        return Err(CodecError::LengthMismatch {
            registers_or_bits: bits.len(),
            value_bytes: values.len(),
            expected_bytes: bits.len(),
        });
    }
    for (value, bit) in values.iter_mut().zip(bits) {
        *value = u8::from(*bit);
    }
    Ok(())
}

/// Converts BOOL values, one byte each, into coils: any byte but 0 sets its coil, as any byte
/// but 0 is TRUE to the program.
pub fn values_to_bits(values: &[u8], bits: &mut [bool]) -> Result<(), CodecError> {
    if bits.len() != values.len() {
        return Err(CodecError::LengthMismatch {
            registers_or_bits: bits.len(),
            value_bytes: values.len(),
            expected_bytes: bits.len(),
        });
    }
    for (bit, value) in bits.iter_mut().zip(values) {
        *bit = *value != 0;
    }
    Ok(())
}

/// The registers per value of `value_type`, once `registers` registers are known to hold a
/// whole number of values whose bytes are exactly `value_bytes`.
fn checked_words(
    registers: usize,
    value_type: Elementary,
    value_bytes: usize,
) -> Result<usize, CodecError> {
    let words = words_per_value(value_type).ok_or(CodecError::NotARegisterType(value_type))?;
    let words = words as usize;
    if !registers.is_multiple_of(words) || registers * 2 != value_bytes {
        return Err(CodecError::LengthMismatch {
            registers_or_bits: registers,
            value_bytes,
            expected_bytes: registers * 2,
        });
    }
    Ok(words)
}
