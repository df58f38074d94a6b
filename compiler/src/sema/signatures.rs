//! The signatures of the standard functions and function blocks: what the checker knows of a
//! call to `LIMIT`, `CONCAT` or `TON` without any source for them.

use crate::elementary::Elementary::{self, *};

use super::ty::{Generic, Type};

/// The type of one parameter or result of a standard function.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Sig {
    /// A fixed elementary type.
    E(Elementary),
    /// `STRING` or `WSTRING`, the same for every `Str` parameter and the result of one call.
    Str,
    /// Any type of the class; each such parameter is independent.
    Class(Generic),
    /// The call's type variable: every `T` argument converges to one type of the class, and a
    /// `T` result is that type.
    T(Generic),
    /// A real result: the `T` type when it is real, `LREAL` otherwise.
    RealOfT,
    /// `EXPT`'s result: `ty::power_type` of the `T` input (the base) and the other (the
    /// exponent), as `**` is typed.
    Power,
    /// An integer literal result that fits any integer place (`SIZEOF`).
    AnyInt,
    /// A pointer to anything (`ADR`).
    Pointer,
    /// No result.
    Void,
}

/// A standard function.
#[derive(Clone, Debug)]
pub(crate) struct FunctionSig {
    /// The inputs in order, with their formal names.
    pub(crate) inputs: Vec<(std::string::String, Sig)>,
    /// The last input may repeat, numbered on from its name (`IN1`, `IN2`, `IN3`…).
    pub(crate) extensible: bool,
    /// The result.
    pub(crate) result: Sig,
}

fn sig(inputs: &[(&str, Sig)], result: Sig) -> FunctionSig {
    FunctionSig {
        inputs: inputs
            .iter()
            .map(|(name, sig)| ((*name).to_owned(), *sig))
            .collect(),
        extensible: false,
        result,
    }
}

fn extensible(inputs: &[(&str, Sig)], result: Sig) -> FunctionSig {
    FunctionSig {
        extensible: true,
        ..sig(inputs, result)
    }
}

/// The input name Rivet's signature of the string function `function` (upper case) gives the
/// IEC 61131-3 input name `formal` (upper case), where the two differ: IEC names the inputs
/// `IN`, `IN1`, `IN2`, `L` and `P` (Beremiz and matiec follow it), CODESYS `STR`, `STR1`,
/// `STR2`, `SIZE`, `LEN` and `POS` (Rivet's names). Both spellings are accepted.
pub(crate) fn iec_input_alias(function: &str, formal: &str) -> Option<&'static str> {
    Some(match (function, formal) {
        ("LEN" | "LEFT" | "RIGHT" | "MID" | "DELETE", "IN") => "STR",
        ("LEFT" | "RIGHT", "L") => "SIZE",
        ("MID" | "DELETE", "L") => "LEN",
        ("MID" | "DELETE" | "INSERT", "P") => "POS",
        ("INSERT" | "REPLACE" | "FIND", "IN1") => "STR1",
        ("INSERT" | "REPLACE" | "FIND", "IN2") => "STR2",
        _ => return None,
    })
}

/// The signature of the standard function `name` (any case), conversions included.
pub(crate) fn function(name: &str) -> Option<FunctionSig> {
    use Generic as G;
    use Sig::*;
    let upper = name.to_ascii_uppercase();
    let one = |class: Generic, result: Sig| sig(&[("IN", T(class))], result);
    Some(match upper.as_str() {
        "ABS" => one(G::Num, T(G::Num)),
        "SQRT" | "LN" | "LOG" | "EXP" | "SIN" | "COS" | "TAN" | "ASIN" | "ACOS" | "ATAN" => {
            one(G::Num, RealOfT)
        }
        "EXPT" => sig(&[("IN1", T(G::Num)), ("IN2", Class(G::Num))], Power),
        "ATAN2" => sig(&[("Y", T(G::Num)), ("X", T(G::Num))], RealOfT),
        "ADD" | "MUL" => extensible(
            &[("IN1", T(G::Magnitude)), ("IN2", T(G::Magnitude))],
            T(G::Magnitude),
        ),
        "SUB" | "DIV" => sig(
            &[("IN1", T(G::Magnitude)), ("IN2", T(G::Magnitude))],
            T(G::Magnitude),
        ),
        "MOD" => sig(&[("IN1", T(G::Int)), ("IN2", T(G::Int))], T(G::Int)),
        "MOVE" => one(G::Any, T(G::Any)),
        "SHL" | "SHR" | "ROL" | "ROR" => sig(&[("IN", T(G::Bit)), ("N", Class(G::Int))], T(G::Bit)),
        "AND" | "OR" | "XOR" => extensible(&[("IN1", T(G::Bit)), ("IN2", T(G::Bit))], T(G::Bit)),
        "NOT" => one(G::Bit, T(G::Bit)),
        "SEL" => sig(
            &[("G", E(Bool)), ("IN0", T(G::Any)), ("IN1", T(G::Any))],
            T(G::Any),
        ),
        "MAX" | "MIN" => extensible(
            &[("IN1", T(G::Elementary)), ("IN2", T(G::Elementary))],
            T(G::Elementary),
        ),
        "LIMIT" => sig(
            &[
                ("MN", T(G::Elementary)),
                ("IN", T(G::Elementary)),
                ("MX", T(G::Elementary)),
            ],
            T(G::Elementary),
        ),
        "MUX" => extensible(
            &[("K", Class(G::Int)), ("IN0", T(G::Any)), ("IN1", T(G::Any))],
            T(G::Any),
        ),
        "GT" | "GE" | "EQ" | "LE" | "LT" => extensible(
            &[("IN1", T(G::Elementary)), ("IN2", T(G::Elementary))],
            E(Bool),
        ),
        "NE" => sig(
            &[("IN1", T(G::Elementary)), ("IN2", T(G::Elementary))],
            E(Bool),
        ),
        "LEN" => sig(&[("STR", Str)], E(Int)),
        "LEFT" | "RIGHT" => sig(&[("STR", Str), ("SIZE", Class(G::Int))], Str),
        "MID" => sig(
            &[("STR", Str), ("LEN", Class(G::Int)), ("POS", Class(G::Int))],
            Str,
        ),
        "CONCAT" => extensible(&[("STR1", Str), ("STR2", Str)], Str),
        "INSERT" => sig(&[("STR1", Str), ("STR2", Str), ("POS", Class(G::Int))], Str),
        "DELETE" => sig(
            &[("STR", Str), ("LEN", Class(G::Int)), ("POS", Class(G::Int))],
            Str,
        ),
        "REPLACE" => sig(
            &[
                ("STR1", Str),
                ("STR2", Str),
                ("L", Class(G::Int)),
                ("P", Class(G::Int)),
            ],
            Str,
        ),
        "FIND" => sig(&[("STR1", Str), ("STR2", Str)], E(Int)),
        "ADD_TIME" | "SUB_TIME" => sig(&[("IN1", E(Time)), ("IN2", E(Time))], E(Time)),
        "MUL_TIME" | "DIV_TIME" => sig(&[("IN1", E(Time)), ("IN2", Class(G::Num))], E(Time)),
        "ADD_TOD_TIME" | "SUB_TOD_TIME" => {
            sig(&[("IN1", E(TimeOfDay)), ("IN2", E(Time))], E(TimeOfDay))
        }
        "ADD_DT_TIME" | "SUB_DT_TIME" => {
            sig(&[("IN1", E(DateAndTime)), ("IN2", E(Time))], E(DateAndTime))
        }
        "SUB_DATE_DATE" => sig(&[("IN1", E(Date)), ("IN2", E(Date))], E(Time)),
        "SUB_TOD_TOD" => sig(&[("IN1", E(TimeOfDay)), ("IN2", E(TimeOfDay))], E(Time)),
        "SUB_DT_DT" => sig(&[("IN1", E(DateAndTime)), ("IN2", E(DateAndTime))], E(Time)),
        "CONCAT_DATE_TOD" => sig(&[("IN1", E(Date)), ("IN2", E(TimeOfDay))], E(DateAndTime)),
        // CODESYS's clock operators: the time since the runtime started.
        "TIME" => sig(&[], E(Time)),
        "LTIME" => sig(&[], E(Ltime)),
        "TRUNC" => sig(&[("IN", Class(G::Real))], E(Dint)),
        "TRUNC_INT" => sig(&[("IN", Class(G::Real))], E(Int)),
        "ROUND" => one(G::Real, T(G::Real)),
        "BCD_TO_INT" => sig(&[("IN", Class(G::Bit))], E(Int)),
        // The argument is converted to INT, so the result is a WORD; an assignment or input of
        // another bit string type gives it that type (`bcd_target.rs`).
        "INT_TO_BCD" => sig(&[("IN", Class(G::Int))], E(bcd_code(Int))),
        "ADR" | "ADRINST" | "__NEW" => sig(&[("IN", Class(G::Any))], Pointer),
        "BITADR" => sig(&[("IN", Class(G::Any))], E(Dword)),
        "SIZEOF" | "XSIZEOF" => sig(&[("IN", Class(G::Any))], AnyInt),
        "INDEXOF" => sig(&[("IN", Class(G::Any))], AnyInt),
        "LOWER_BOUND" | "UPPER_BOUND" => {
            sig(&[("ARR", Class(G::Any)), ("DIM", Class(G::Int))], E(Dint))
        }
        "ISVALIDREF" | "__ISVALIDREF" => sig(&[("IN", Class(G::Any))], E(Bool)),
        "__DELETE" => sig(&[("IN", Class(G::Any))], Void),
        "__QUERYINTERFACE" | "__QUERYPOINTER" => {
            sig(&[("ITF", Class(G::Any)), ("OUT", Class(G::Any))], E(Bool))
        }
        _ => return conversion(&upper),
    })
}

/// `A_TO_B`, `TO_B` and the BCD conversions.
fn conversion(upper: &str) -> Option<FunctionSig> {
    use Sig::*;
    // The result's width is the target's (`STRING_TO_WSTRING` gives a WSTRING), not the input's.
    let target = |name: &str| -> Option<Sig> { Some(E(Elementary::from_name(name)?)) };
    if let Some(to) = upper.strip_prefix("TO_") {
        return Some(sig(&[("IN", Class(Generic::Elementary))], target(to)?));
    }
    for (at, _) in upper.match_indices("_TO_") {
        let (from, to) = (&upper[..at], &upper[at + 4..]);
        let from_sig = match from {
            "BCD" => Some(Class(Generic::Bit)),
            _ => Elementary::from_name(from).map(|e| match e {
                String | Wstring => Class(Generic::String),
                other => E(other),
            }),
        };
        let (from_sig, to_sig) = match to {
            "BCD" => bcd_conversion(from),
            _ => (from_sig, target(to)),
        };
        if let (Some(from), Some(to)) = (from_sig, to_sig) {
            return Some(sig(&[("IN", from)], to));
        }
    }
    None
}

/// The input and result of `from_TO_BCD`: the bit string of the integer's width, as IEC
/// 61131-3 ed. 3 names them (table 22: `USINT_TO_BCD_BYTE`, `UINT_TO_BCD_WORD`,
/// `UDINT_TO_BCD_DWORD`, `ULINT_TO_BCD_LWORD`), and CODESYS's `BYTE_TO_BCD`, `WORD_TO_BCD`,
/// `DWORD_TO_BCD` code a bit string's unsigned value. Decimal digits code integers only: a
/// name from any other type (`REAL_TO_BCD`) is no function.
fn bcd_conversion(from: &str) -> (Option<Sig>, Option<Sig>) {
    let Some(from) = Elementary::from_name(from) else {
        return (None, None);
    };
    // Decimal digits code integers (and, as CODESYS has it, a bit string's unsigned value);
    // `REAL_TO_BCD`, `TIME_TO_BCD` or `STRING_TO_BCD` is no function at all, so the checker
    // refuses the name rather than the code generator a call it cannot make.
    if !(from.is_integer() || (from.is_bit_string() && from != Bool)) {
        return (None, None);
    }
    (Some(Sig::E(from)), Some(Sig::E(bcd_code(from))))
}

/// The bit string as wide as `from` (a character or string: as one of its characters), which
/// holds the BCD code of an integer of that type.
fn bcd_code(from: Elementary) -> Elementary {
    match from.size_bits() {
        8 => Byte,
        16 => Word,
        32 => Dword,
        _ => Lword,
    }
}

/// A standard function block's interface.
#[derive(Debug)]
pub(crate) struct FunctionBlockSig {
    /// Inputs: formal name and type.
    pub(crate) inputs: &'static [(&'static str, Elementary)],
    /// Outputs.
    pub(crate) outputs: &'static [(&'static str, Elementary)],
    /// Other names an input may be given, as (alias, input): CODESYS names the counters'
    /// reset `RESET` where IEC writes `R`.
    pub(crate) aliases: &'static [(&'static str, &'static str)],
}

const TIMER: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("IN", Bool), ("PT", Time)],
    outputs: &[("Q", Bool), ("ET", Time)],
    aliases: &[],
};

const LONG_TIMER: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("IN", Bool), ("PT", Ltime)],
    outputs: &[("Q", Bool), ("ET", Ltime)],
    aliases: &[],
};

const CTU: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("CU", Bool), ("R", Bool), ("PV", Int)],
    outputs: &[("Q", Bool), ("CV", Int)],
    aliases: &[("RESET", "R")],
};

const CTD: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("CD", Bool), ("LD", Bool), ("PV", Int)],
    outputs: &[("Q", Bool), ("CV", Int)],
    aliases: &[("LOAD", "LD")],
};

const CTUD: FunctionBlockSig = FunctionBlockSig {
    inputs: &[
        ("CU", Bool),
        ("CD", Bool),
        ("R", Bool),
        ("LD", Bool),
        ("PV", Int),
    ],
    outputs: &[("QU", Bool), ("QD", Bool), ("CV", Int)],
    aliases: &[("RESET", "R"), ("LOAD", "LD")],
};

const TRIG: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("CLK", Bool)],
    outputs: &[("Q", Bool)],
    aliases: &[],
};

// IEC names the bistables' inputs S1/R and S/R1; CODESYS SET1/RESET and SET/RESET1.
const SR: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("S1", Bool), ("R", Bool)],
    outputs: &[("Q1", Bool)],
    aliases: &[("SET1", "S1"), ("RESET", "R")],
};

const RS: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("S", Bool), ("R1", Bool)],
    outputs: &[("Q1", Bool)],
    aliases: &[("SET", "S"), ("RESET1", "R1")],
};

const RTC: FunctionBlockSig = FunctionBlockSig {
    inputs: &[("EN", Bool), ("PDT", DateAndTime)],
    outputs: &[("Q", Bool), ("CDT", DateAndTime)],
    aliases: &[],
};

/// The interface of the standard function block `name` (any case).
pub(crate) fn function_block(name: &str) -> Option<&'static FunctionBlockSig> {
    Some(match name.to_ascii_uppercase().as_str() {
        "TON" | "TOF" | "TP" => &TIMER,
        "LTON" | "LTOF" | "LTP" => &LONG_TIMER,
        "CTU" => &CTU,
        "CTD" => &CTD,
        "CTUD" => &CTUD,
        "R_TRIG" | "F_TRIG" => &TRIG,
        "SR" => &SR,
        "RS" => &RS,
        "RTC" => &RTC,
        _ => return None,
    })
}

impl FunctionBlockSig {
    /// The type of the input or output called `name`, and whether it is an output.
    pub(crate) fn member(&self, name: &str) -> Option<(Type, bool)> {
        let name = self
            .aliases
            .iter()
            .find(|(alias, _)| alias.eq_ignore_ascii_case(name))
            .map_or(name, |(_, input)| input);
        let find = |list: &[(&str, Elementary)]| {
            list.iter()
                .find(|(formal, _)| formal.eq_ignore_ascii_case(name))
                .map(|(_, ty)| Type::elementary(*ty))
        };
        find(self.inputs)
            .map(|ty| (ty, false))
            .or_else(|| find(self.outputs).map(|ty| (ty, true)))
    }

    /// Every input and output name, for suggestions.
    pub(crate) fn names(&self) -> impl Iterator<Item = &'static str> {
        self.inputs
            .iter()
            .chain(self.outputs)
            .map(|(name, _)| *name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_standard_name_has_a_signature() {
        for name in super::super::stdlib::all_names() {
            assert!(
                function(name).is_some() || function_block(name).is_some(),
                "{name} has no signature"
            );
        }
    }

    #[test]
    fn conversions_know_both_ends() {
        let real_to_int = function("REAL_TO_INT").unwrap();
        assert_eq!(real_to_int.inputs[0].1, Sig::E(Real));
        assert_eq!(real_to_int.result, Sig::E(Int));
        assert_eq!(function("TO_STRING").unwrap().result, Sig::E(String));
        assert_eq!(
            function("STRING_TO_WSTRING").unwrap().result,
            Sig::E(Wstring)
        );
        assert_eq!(
            function("TIME_OF_DAY_TO_DINT").unwrap().inputs[0].1,
            Sig::E(TimeOfDay)
        );
        assert!(function("REAL_TO_FOO").is_none());
    }

    /// A BCD code is the bit string of its integer's width, so a call inside an operator has a
    /// type; only integers (and CODESYS's bit strings) have decimal digits to code.
    #[test]
    fn a_bcd_code_is_as_wide_as_its_integer() {
        for (name, input, result) in [
            ("USINT_TO_BCD", Sig::E(Usint), Byte),
            ("SINT_TO_BCD", Sig::E(Sint), Byte),
            ("INT_TO_BCD", Sig::Class(Generic::Int), Word),
            ("UINT_TO_BCD", Sig::E(Uint), Word),
            ("DINT_TO_BCD", Sig::E(Dint), Dword),
            ("udint_to_bcd", Sig::E(Udint), Dword),
            ("LINT_TO_BCD", Sig::E(Lint), Lword),
            ("ULINT_TO_BCD", Sig::E(Ulint), Lword),
            ("WORD_TO_BCD", Sig::E(Word), Word),
        ] {
            let signature = function(name).unwrap();
            assert_eq!(signature.inputs[0].1, input, "{name}");
            assert_eq!(signature.result, Sig::E(result), "{name}");
        }
        assert_eq!(
            function("BCD_TO_LINT").unwrap().inputs[0].1,
            Sig::Class(Generic::Bit)
        );
        assert!(function("FOO_TO_BCD").is_none());
        for name in ["REAL_TO_BCD", "BOOL_TO_BCD", "TIME_TO_BCD", "STRING_TO_BCD"] {
            assert!(function(name).is_none(), "{name}");
        }
    }

    #[test]
    fn counters_accept_the_codesys_reset_name() {
        let ctu = function_block("ctu").unwrap();
        assert_eq!(ctu.member("RESET"), Some((Type::BOOL, false)));
        assert_eq!(ctu.member("CV"), Some((Type::Elementary(Int), true)));
        assert!(ctu.member("ET").is_none());
    }
}
