//! A cursor over a frame: every read checks the length and names its field and byte when it
//! fails, so decoding never panics.

use crate::Hash;
use crate::error::DecodeError;
use crate::framing::NO_BIT;
use crate::place::Place;

/// Reads the fields of a frame in order; positions count from the frame's first byte.
#[derive(Clone, Debug)]
pub struct Reader<'a> {
    bytes: &'a [u8],
    /// Where `bytes` starts in the frame.
    at: usize,
}

impl<'a> Reader<'a> {
    /// A reader at the start of `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes, at: 0 }
    }

    /// The position of the next byte in the frame.
    pub fn position(&self) -> usize {
        self.at
    }

    /// How many bytes are left.
    pub fn remaining(&self) -> usize {
        self.bytes.len()
    }

    /// The next `count` bytes, which are the `field`.
    pub fn take(&mut self, field: &'static str, count: usize) -> Result<&'a [u8], DecodeError> {
        if self.bytes.len() < count {
            return Err(DecodeError::TooShort {
                field,
                at: self.at,
                needed: count,
                left: self.bytes.len(),
            });
        }
        let (taken, rest) = self.bytes.split_at(count);
        self.bytes = rest;
        self.at += count;
        Ok(taken)
    }

    /// The bytes not read yet (and consumes them).
    pub fn rest(&mut self) -> &'a [u8] {
        self.at += self.bytes.len();
        std::mem::take(&mut self.bytes)
    }

    /// Fails unless every byte has been read.
    pub fn finish(&self) -> Result<(), DecodeError> {
        if self.bytes.is_empty() {
            Ok(())
        } else {
            Err(DecodeError::LeftOver {
                at: self.at,
                count: self.bytes.len(),
            })
        }
    }

    fn array<const N: usize>(&mut self, field: &'static str) -> Result<[u8; N], DecodeError> {
        let mut array = [0; N];
        array.copy_from_slice(self.take(field, N)?);
        Ok(array)
    }

    /// A u8.
    pub fn u8(&mut self, field: &'static str) -> Result<u8, DecodeError> {
        Ok(self.array::<1>(field)?[0])
    }

    /// A little-endian u16.
    pub fn u16(&mut self, field: &'static str) -> Result<u16, DecodeError> {
        Ok(u16::from_le_bytes(self.array(field)?))
    }

    /// A little-endian u32.
    pub fn u32(&mut self, field: &'static str) -> Result<u32, DecodeError> {
        Ok(u32::from_le_bytes(self.array(field)?))
    }

    /// A little-endian u128.
    pub fn u128(&mut self, field: &'static str) -> Result<u128, DecodeError> {
        Ok(u128::from_le_bytes(self.array(field)?))
    }

    /// A little-endian u64.
    pub fn u64(&mut self, field: &'static str) -> Result<u64, DecodeError> {
        Ok(u64::from_le_bytes(self.array(field)?))
    }

    /// A flag byte: 1 is true, anything else false.
    pub fn flag(&mut self, field: &'static str) -> Result<bool, DecodeError> {
        Ok(self.u8(field)? == 1)
    }

    /// A byte that numbers one of `choices`, the first being 0: an enum by its wire number.
    pub fn choice<T: Copy>(
        &mut self,
        field: &'static str,
        choices: &[T],
        expected: &'static str,
    ) -> Result<T, DecodeError> {
        let at = self.at;
        let number = self.u8(field)?;
        choices
            .get(usize::from(number))
            .copied()
            .ok_or(DecodeError::OutOfRange {
                field,
                at,
                value: u64::from(number),
                expected,
            })
    }

    /// A 32-byte hash.
    pub fn hash(&mut self, field: &'static str) -> Result<Hash, DecodeError> {
        self.array(field)
    }

    /// An `str8` that must be UTF-8.
    pub fn str8(&mut self, field: &'static str) -> Result<String, DecodeError> {
        let at = self.at;
        let length = usize::from(self.u8(field)?);
        let bytes = self.take(field, length)?;
        String::from_utf8(bytes.to_vec()).map_err(|_| DecodeError::NotUtf8 { field, at })
    }

    /// A place (8 bytes).
    pub fn place(&mut self, field: &'static str) -> Result<Place, DecodeError> {
        let region = self.u8(field)?;
        let offset = self.u32(field)?;
        let bit = self.u8(field)?;
        let size = self.u16(field)?;
        Ok(Place {
            region,
            offset,
            bit: (bit != NO_BIT).then_some(bit),
            size,
        })
    }

    /// `count:u8` and that many places.
    pub fn places(&mut self) -> Result<Vec<Place>, DecodeError> {
        let count = self.u8("count")?;
        (0..count).map(|_| self.place("place")).collect()
    }

    /// `count:u8` and that many places, each followed by a value of its `size` bytes.
    pub fn values(&mut self) -> Result<Vec<(Place, Vec<u8>)>, DecodeError> {
        let count = self.u8("count")?;
        let mut values = Vec::with_capacity(usize::from(count));
        for _ in 0..count {
            let place = self.place("place")?;
            let size = usize::from(place.size);
            if self.bytes.len() < size {
                return Err(DecodeError::ValueTooLong {
                    at: self.at,
                    size,
                    left: self.bytes.len(),
                });
            }
            values.push((place, self.take("value", size)?.to_vec()));
        }
        Ok(values)
    }
}
