//! The elementary types of IEC 61131-3 and the implicit conversions between them.

/// An elementary type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[allow(missing_docs)] // Each variant is the IEC type of the same name.
pub enum Elementary {
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
    String,
    Wstring,
}

use Elementary::*;

impl Elementary {
    /// Every elementary type.
    pub const ALL: [Self; 27] = [
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
        String,
        Wstring,
    ];

    /// The type named `name` (any case, long and short spellings such as `TOD`).
    pub fn from_name(name: &str) -> Option<Self> {
        let upper = name.to_ascii_uppercase();
        Some(match upper.as_str() {
            "BOOL" => Bool,
            "BYTE" => Byte,
            "WORD" => Word,
            "DWORD" => Dword,
            "LWORD" => Lword,
            "SINT" => Sint,
            "INT" => Int,
            "DINT" => Dint,
            "LINT" => Lint,
            "USINT" => Usint,
            "UINT" => Uint,
            "UDINT" => Udint,
            "ULINT" => Ulint,
            "REAL" => Real,
            "LREAL" => Lreal,
            "TIME" => Time,
            "LTIME" => Ltime,
            "DATE" => Date,
            "LDATE" => Ldate,
            "TIME_OF_DAY" | "TOD" => TimeOfDay,
            "LTIME_OF_DAY" | "LTOD" => LtimeOfDay,
            "DATE_AND_TIME" | "DT" => DateAndTime,
            "LDATE_AND_TIME" | "LDT" => LdateAndTime,
            "CHAR" => Char,
            "WCHAR" => Wchar,
            "STRING" => String,
            "WSTRING" => Wstring,
            _ => return None,
        })
    }

    /// The IEC name, such as `TIME_OF_DAY`.
    pub fn name(self) -> &'static str {
        match self.image() {
            Some(image) => image.name(),
            None if self == String => "STRING",
            None => "WSTRING",
        }
    }

    /// The type as the program image stores it; `None` for the strings, which are types of
    /// their own there. The two enumerations list the elementary types in the same order.
    pub fn image(self) -> Option<program_image::Elementary> {
        program_image::Elementary::from_tag(self as u8)
    }

    /// The type of an image's elementary type.
    pub fn of_image(image: program_image::Elementary) -> Self {
        Self::ALL[usize::from(image.tag())]
    }

    /// The size in bits of a value (strings: of one character), as the LC1200 manual lists.
    pub fn size_bits(self) -> u32 {
        match self {
            Bool | Byte | Sint | Usint | Char | String => 8,
            Word | Int | Uint | Wchar | Wstring => 16,
            Dword | Dint | Udint | Real | Time | Date | TimeOfDay | DateAndTime => 32,
            Lword | Lint | Ulint | Lreal | Ltime | Ldate | LtimeOfDay | LdateAndTime => 64,
        }
    }

    /// Signed integers.
    pub fn is_signed_integer(self) -> bool {
        matches!(self, Sint | Int | Dint | Lint)
    }

    /// Unsigned integers.
    pub fn is_unsigned_integer(self) -> bool {
        matches!(self, Usint | Uint | Udint | Ulint)
    }

    /// Any integer.
    pub fn is_integer(self) -> bool {
        self.is_signed_integer() || self.is_unsigned_integer()
    }

    /// `REAL` or `LREAL`.
    pub fn is_real(self) -> bool {
        matches!(self, Real | Lreal)
    }

    /// Bit strings, `BOOL` included.
    pub fn is_bit_string(self) -> bool {
        matches!(self, Bool | Byte | Word | Dword | Lword)
    }

    /// The range of values of an integer type, or `None` for other types.
    pub fn integer_range(self) -> Option<(i128, i128)> {
        let bits = self.size_bits();
        if self.is_signed_integer() {
            Some((-(1i128 << (bits - 1)), (1i128 << (bits - 1)) - 1))
        } else if self.is_unsigned_integer() || (self.is_bit_string() && self != Bool) {
            Some((0, (1i128 << bits) - 1))
        } else {
            None
        }
    }

    /// Whether a value of type `self` converts to `target` without an explicit conversion:
    /// IEC 61131-3 widening only (the LC1200 manual: implicit narrowing is not allowed).
    pub fn widens_to(self, target: Self) -> bool {
        if self == target {
            return true;
        }
        match (self, target) {
            // Integers widen within their family, and unsigned into a larger signed type.
            (Sint, Int | Dint | Lint) | (Int, Dint | Lint) | (Dint, Lint) => true,
            (Usint, Uint | Udint | Ulint | Int | Dint | Lint) => true,
            (Uint, Udint | Ulint | Dint | Lint) | (Udint, Ulint | Lint) => true,
            // Integers of up to 16 bits fit exactly into REAL, of up to 32 bits into LREAL.
            (Sint | Int | Usint | Uint, Real | Lreal) | (Dint | Udint, Lreal) => true,
            (Real, Lreal) => true,
            // Bit strings widen to longer bit strings.
            (Bool, Byte | Word | Dword | Lword) | (Byte, Word | Dword | Lword) => true,
            (Word, Dword | Lword) | (Dword, Lword) => true,
            // Times and dates widen to their long forms.
            (Time, Ltime)
            | (Date, Ldate)
            | (TimeOfDay, LtimeOfDay)
            | (DateAndTime, LdateAndTime) => true,
            (Char, String) | (Wchar, Wstring) => true,
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_image_lists_the_same_types_in_the_same_order() {
        for ty in Elementary::ALL {
            match ty.image() {
                Some(image) => assert_eq!(Elementary::of_image(image), ty),
                None => assert!(matches!(ty, String | Wstring)),
            }
        }
    }

    #[test]
    fn names_round_trip_and_short_forms_resolve() {
        for ty in Elementary::ALL {
            assert_eq!(Elementary::from_name(ty.name()), Some(ty));
        }
        assert_eq!(Elementary::from_name("tod"), Some(TimeOfDay));
        assert_eq!(Elementary::from_name("DT"), Some(DateAndTime));
        assert_eq!(Elementary::from_name("FB_Conveyor"), None);
    }

    #[test]
    fn ranges_follow_the_lc1200_table() {
        assert_eq!(Int.integer_range(), Some((-32_768, 32_767)));
        assert_eq!(Udint.integer_range(), Some((0, 4_294_967_295)));
        assert_eq!(
            Lint.integer_range(),
            Some((i128::from(i64::MIN), i128::from(i64::MAX)))
        );
        assert_eq!(Word.integer_range(), Some((0, 65_535)));
        assert_eq!(Real.integer_range(), None);
    }

    #[test]
    fn only_widening_is_implicit() {
        assert!(Int.widens_to(Dint));
        assert!(Usint.widens_to(Int));
        assert!(Int.widens_to(Real));
        assert!(Byte.widens_to(Word));
        assert!(Time.widens_to(Ltime));
        // Narrowing and changes of family need an explicit conversion.
        assert!(!Int.widens_to(Byte));
        assert!(!Dint.widens_to(Word));
        assert!(!Dint.widens_to(Real));
        assert!(!Uint.widens_to(Int));
        assert!(!Int.widens_to(Uint));
        assert!(!Real.widens_to(Dint));
        assert!(!Word.widens_to(Int));
        // Widening is transitive: every path through a wider type stays allowed.
        for a in Elementary::ALL {
            for b in Elementary::ALL {
                for c in Elementary::ALL {
                    if a.widens_to(b) && b.widens_to(c) {
                        assert!(a.widens_to(c), "{a:?} -> {b:?} -> {c:?}");
                    }
                }
            }
        }
    }
}
