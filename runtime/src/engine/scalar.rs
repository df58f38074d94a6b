//! Values of the elementary types as the engine reads and writes them: little-endian bytes in
//! memory, Rust numbers in between.

/// A value type the engine moves between memory and arithmetic.
pub(crate) trait Scalar: Copy + PartialOrd + Send + Sync + 'static {
    /// Bytes in memory.
    const SIZE: usize;
    /// Reads from exactly `SIZE` bytes.
    fn read(bytes: &[u8]) -> Self;
    /// Writes into exactly `SIZE` bytes.
    fn write(self, bytes: &mut [u8]);
    /// The value as raw bits, zero-extended (the standard library's representation).
    fn to_raw(self) -> u64;
    /// The value from raw bits (the low `SIZE` bytes).
    fn from_raw(raw: u64) -> Self;
}

/// Arithmetic of integers and reals. `None` from a division means division by zero.
pub(crate) trait Arith: Scalar {
    fn add(self, other: Self) -> Self;
    fn sub(self, other: Self) -> Self;
    fn mul(self, other: Self) -> Self;
    fn div(self, other: Self) -> Option<Self>;
    fn rem(self, other: Self) -> Option<Self>;
    fn neg(self) -> Self;
    fn abs(self) -> Self;
    fn expt(self, other: Self) -> Self;
}

/// Bit operations of bit strings and integers, sized by the type.
pub(crate) trait Bits: Scalar {
    fn and(self, other: Self) -> Self;
    fn or(self, other: Self) -> Self;
    fn xor(self, other: Self) -> Self;
    fn not(self) -> Self;
    fn shl(self, count: Self) -> Self;
    fn shr(self, count: Self) -> Self;
    fn rol(self, count: Self) -> Self;
    fn ror(self, count: Self) -> Self;
}

/// Functions of reals.
pub(crate) trait Real: Arith {
    fn apply(self, f: fn(f64) -> f64) -> Self;
    fn apply2(self, other: Self, f: fn(f64, f64) -> f64) -> Self;
}

macro_rules! scalar {
    ($($t:ty),*) => {$(
        impl Scalar for $t {
            const SIZE: usize = size_of::<$t>();
            #[inline(always)]
            fn read(bytes: &[u8]) -> Self {
                let mut array = [0u8; size_of::<$t>()];
                array.copy_from_slice(bytes);
                <$t>::from_le_bytes(array)
            }
            #[inline(always)]
            fn write(self, bytes: &mut [u8]) {
                bytes.copy_from_slice(&self.to_le_bytes());
            }
            #[inline(always)]
            fn to_raw(self) -> u64 {
                let mut array = [0u8; 8];
                array[..size_of::<$t>()].copy_from_slice(&self.to_le_bytes());
                u64::from_le_bytes(array)
            }
            #[inline(always)]
            fn from_raw(raw: u64) -> Self {
                let mut array = [0u8; size_of::<$t>()];
                array.copy_from_slice(&raw.to_le_bytes()[..size_of::<$t>()]);
                <$t>::from_le_bytes(array)
            }
        }
    )*};
}
scalar!(u8, u16, u32, u64, i8, i16, i32, i64, f32, f64);

macro_rules! integer {
    ($($t:ty),*) => {$(
        impl Arith for $t {
            #[inline(always)]
            fn add(self, other: Self) -> Self { self.wrapping_add(other) }
            #[inline(always)]
            fn sub(self, other: Self) -> Self { self.wrapping_sub(other) }
            #[inline(always)]
            fn mul(self, other: Self) -> Self { self.wrapping_mul(other) }
            #[inline(always)]
            fn div(self, other: Self) -> Option<Self> {
                if other == 0 { None } else { Some(self.wrapping_div(other)) }
            }
            #[inline(always)]
            fn rem(self, other: Self) -> Option<Self> {
                // The remainder takes the sign of the dividend, as in CODESYS and Rust.
                if other == 0 { None } else { Some(self.wrapping_rem(other)) }
            }
            #[inline(always)]
            fn neg(self) -> Self { (0 as $t).wrapping_sub(self) }
            #[inline(always)]
            #[allow(unused_comparisons)]
            fn abs(self) -> Self { if self < 0 as $t { self.neg() } else { self } }
            fn expt(self, other: Self) -> Self {
                // A negative exponent of an integer gives 0 unless the base is 1 or -1, as
                // the real result truncated toward zero would.
                let exponent = other.to_raw();
                #[allow(unused_comparisons)]
                if other < 0 as $t {
                    let one = 1 as $t;
                    return if self == one { one } else if self.neg() == one {
                        if exponent & 1 == 0 { one } else { self }
                    } else { 0 };
                }
                self.wrapping_pow(u32::try_from(exponent).unwrap_or(u32::MAX))
            }
        }
        impl Bits for $t {
            #[inline(always)]
            fn and(self, other: Self) -> Self { self & other }
            #[inline(always)]
            fn or(self, other: Self) -> Self { self | other }
            #[inline(always)]
            fn xor(self, other: Self) -> Self { self ^ other }
            #[inline(always)]
            fn not(self) -> Self { !self }
            fn shl(self, count: Self) -> Self {
                // A shift by the width or more clears every bit.
                u32::try_from(count.to_raw()).ok().and_then(|n| self.checked_shl(n)).unwrap_or(0)
            }
            fn shr(self, count: Self) -> Self {
                // SHR is a logical shift on the bits, whatever the type's sign (CODESYS).
                let bits = (size_of::<$t>() * 8) as u64;
                let raw = self.to_raw();
                let n = count.to_raw();
                if n >= bits { 0 } else { Self::from_raw(raw >> n) }
            }
            fn rol(self, count: Self) -> Self {
                let bits = (size_of::<$t>() * 8) as u64;
                let n = (count.to_raw() % bits) as u32;
                Self::from_raw(rotate_left(self.to_raw(), n, bits as u32))
            }
            fn ror(self, count: Self) -> Self {
                let bits = (size_of::<$t>() * 8) as u64;
                let n = (count.to_raw() % bits) as u32;
                Self::from_raw(rotate_left(self.to_raw(), (bits as u32 - n) % bits as u32, bits as u32))
            }
        }
    )*};
}
integer!(u8, u16, u32, u64, i8, i16, i32, i64);

fn rotate_left(raw: u64, n: u32, bits: u32) -> u64 {
    if n == 0 {
        return raw;
    }
    let mask = if bits == 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    };
    ((raw << n) | (raw >> (bits - n))) & mask
}

macro_rules! real {
    ($($t:ty),*) => {$(
        impl Arith for $t {
            #[inline(always)]
            fn add(self, other: Self) -> Self { self + other }
            #[inline(always)]
            fn sub(self, other: Self) -> Self { self - other }
            #[inline(always)]
            fn mul(self, other: Self) -> Self { self * other }
            #[inline(always)]
            fn div(self, other: Self) -> Option<Self> { Some(self / other) }
            #[inline(always)]
            fn rem(self, other: Self) -> Option<Self> { Some(self % other) }
            #[inline(always)]
            fn neg(self) -> Self { -self }
            #[inline(always)]
            fn abs(self) -> Self { <$t>::abs(self) }
            fn expt(self, other: Self) -> Self { self.powf(other) }
        }
        impl Real for $t {
            fn apply(self, f: fn(f64) -> f64) -> Self { f(f64::from(self)) as $t }
            fn apply2(self, other: Self, f: fn(f64, f64) -> f64) -> Self {
                f(f64::from(self), f64::from(other)) as $t
            }
        }
    )*};
}
real!(f32, f64);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_are_sized_by_the_type() {
        // LC1200: ROR(WORD#16#45, 2) = 16#4011.
        assert_eq!(0x45u16.ror(2), 0x4011);
        assert_eq!(0x4011u16.rol(2), 0x45);
        assert_eq!(0x81u8.rol(1), 0x03);
        assert_eq!(1u64.ror(1), 1 << 63);
    }

    #[test]
    fn shifts_by_the_width_or_more_clear_the_value() {
        assert_eq!(1u16.shl(16), 0);
        assert_eq!((-1i16).shr(15), 1);
        assert_eq!(0x8000u16.shr(20), 0);
    }

    #[test]
    fn integer_arithmetic_wraps_and_division_by_zero_is_reported() {
        assert_eq!(i16::MAX.add(1), i16::MIN);
        assert_eq!(7i32.div(0), None);
        assert_eq!((-7i32).rem(2), Some(-1));
        assert_eq!(i32::MIN.div(-1), Some(i32::MIN));
        assert_eq!(2i32.expt(10), 1024);
        assert_eq!(2i32.expt(-1), 0);
    }
}
