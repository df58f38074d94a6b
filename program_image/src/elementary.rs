//! The elementary types as the image encodes them: a one-byte tag, a size and a byte layout.

/// An elementary type of a value in memory, numbered as the type table of
/// `docs/program-image.md` §4 numbers them (the tag is the discriminant).
///
/// The strings are not elementary here: `STRING(n)` and `WSTRING(n)` carry a length and are
/// types of their own in the image.
/// Encoded (with serde) as its variant index, which is its tag.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[repr(u8)]
#[allow(missing_docs)] // Each variant is the IEC type of the same name.
pub enum Elementary {
    Bool = 0,
    Byte = 1,
    Word = 2,
    Dword = 3,
    Lword = 4,
    Sint = 5,
    Int = 6,
    Dint = 7,
    Lint = 8,
    Usint = 9,
    Uint = 10,
    Udint = 11,
    Ulint = 12,
    Real = 13,
    Lreal = 14,
    /// Milliseconds, `i32` (CODESYS `TIME`).
    Time = 15,
    /// Nanoseconds, `i64`.
    Ltime = 16,
    /// Seconds since 1970-01-01, `u32`.
    Date = 17,
    /// Nanoseconds since 1970-01-01, `i64`.
    Ldate = 18,
    /// Milliseconds since midnight, `u32`.
    TimeOfDay = 19,
    /// Nanoseconds since midnight, `i64`.
    LtimeOfDay = 20,
    /// Seconds since 1970-01-01 00:00:00, `u32`.
    DateAndTime = 21,
    /// Nanoseconds since 1970-01-01 00:00:00, `i64`.
    LdateAndTime = 22,
    /// One byte.
    Char = 23,
    /// Two bytes (UTF-16 code unit).
    Wchar = 24,
}

use Elementary::*;

impl Elementary {
    /// Every elementary type in tag order.
    pub const ALL: [Self; 25] = [
        Bool,
        Byte,
        Word,
        Dword,
        Lword,
        Sint,
        Int,
        Dint,
        Lint,
        Usint,
        Uint,
        Udint,
        Ulint,
        Real,
        Lreal,
        Time,
        Ltime,
        Date,
        Ldate,
        TimeOfDay,
        LtimeOfDay,
        DateAndTime,
        LdateAndTime,
        Char,
        Wchar,
    ];

    /// The type with tag `tag`, if there is one.
    pub fn from_tag(tag: u8) -> Option<Self> {
        Self::ALL.get(usize::from(tag)).copied()
    }

    /// The tag the image stores.
    pub fn tag(self) -> u8 {
        self as u8
    }

    /// The bytes a value takes in memory (`BOOL` takes one byte holding 0 or 1).
    pub fn size_bytes(self) -> u32 {
        match self {
            Bool | Byte | Sint | Usint | Char => 1,
            Word | Int | Uint | Wchar => 2,
            Dword | Dint | Udint | Real | Time | Date | TimeOfDay | DateAndTime => 4,
            Lword | Lint | Ulint | Lreal | Ltime | Ldate | LtimeOfDay | LdateAndTime => 8,
        }
    }

    /// Signed integers, and the time types stored as signed integers (`TIME`, `LTIME` and the
    /// long date and time types).
    pub fn is_signed(self) -> bool {
        matches!(
            self,
            Sint | Int | Dint | Lint | Time | Ltime | Ldate | LtimeOfDay | LdateAndTime
        )
    }

    /// The integers and the bit strings wider than `BOOL` (`BYTE` … `LWORD`): the types an
    /// array index may have in the fused element instructions (`docs/program-image.md` §7.2).
    pub fn is_integer(self) -> bool {
        matches!(
            self,
            Byte | Word | Dword | Lword | Sint | Int | Dint | Lint | Usint | Uint | Udint | Ulint
        )
    }

    /// `REAL` or `LREAL`.
    pub fn is_real(self) -> bool {
        matches!(self, Real | Lreal)
    }

    /// The IEC name, such as `TIME_OF_DAY`.
    pub fn name(self) -> &'static str {
        match self {
            Bool => "BOOL",
            Byte => "BYTE",
            Word => "WORD",
            Dword => "DWORD",
            Lword => "LWORD",
            Sint => "SINT",
            Int => "INT",
            Dint => "DINT",
            Lint => "LINT",
            Usint => "USINT",
            Uint => "UINT",
            Udint => "UDINT",
            Ulint => "ULINT",
            Real => "REAL",
            Lreal => "LREAL",
            Time => "TIME",
            Ltime => "LTIME",
            Date => "DATE",
            Ldate => "LDATE",
            TimeOfDay => "TIME_OF_DAY",
            LtimeOfDay => "LTIME_OF_DAY",
            DateAndTime => "DATE_AND_TIME",
            LdateAndTime => "LDATE_AND_TIME",
            Char => "CHAR",
            Wchar => "WCHAR",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_are_the_documented_numbers() {
        for (index, ty) in Elementary::ALL.iter().enumerate() {
            assert_eq!(usize::from(ty.tag()), index);
            assert_eq!(Elementary::from_tag(ty.tag()), Some(*ty));
        }
        assert_eq!(Elementary::from_tag(25), None);
        assert_eq!(Time.tag(), 15);
        assert_eq!(Wchar.tag(), 24);
    }
}
