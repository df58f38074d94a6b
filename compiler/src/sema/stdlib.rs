//! Names of the IEC 61131-3 standard library and the CODESYS system functions the checker
//! knows, for suggestions and for the built-in type names. Whether a name is a library function
//! is decided by its signature in `signatures`.

use crate::elementary::Elementary;

/// Standard functions and operators that are called like functions.
const FUNCTIONS: &[&str] = &[
    // Numeric.
    "ABS",
    "SQRT",
    "LN",
    "LOG",
    "EXP",
    "EXPT",
    "SIN",
    "COS",
    "TAN",
    "ASIN",
    "ACOS",
    "ATAN",
    "ATAN2",
    // Arithmetic and assignment.
    "ADD",
    "SUB",
    "MUL",
    "DIV",
    "MOD",
    "MOVE",
    // Bit strings.
    "SHL",
    "SHR",
    "ROL",
    "ROR",
    "AND",
    "OR",
    "XOR",
    "NOT",
    // Selection and comparison.
    "SEL",
    "MAX",
    "MIN",
    "LIMIT",
    "MUX",
    "GT",
    "GE",
    "EQ",
    "LE",
    "LT",
    "NE",
    // Strings.
    "LEN",
    "LEFT",
    "RIGHT",
    "MID",
    "CONCAT",
    "INSERT",
    "DELETE",
    "REPLACE",
    "FIND",
    // Time and date.
    "ADD_TIME",
    "SUB_TIME",
    "MUL_TIME",
    "DIV_TIME",
    "ADD_TOD_TIME",
    "ADD_DT_TIME",
    "SUB_DATE_DATE",
    "SUB_TOD_TIME",
    "SUB_TOD_TOD",
    "SUB_DT_TIME",
    "SUB_DT_DT",
    "CONCAT_DATE_TOD",
    // CODESYS's clock operators.
    "TIME",
    "LTIME",
    // Conversion helpers.
    "TRUNC",
    "TRUNC_INT",
    "ROUND",
    "BCD_TO_INT",
    "INT_TO_BCD",
    // Addresses, sizes and references (CODESYS).
    "ADR",
    "ADRINST",
    "BITADR",
    "SIZEOF",
    "XSIZEOF",
    "INDEXOF",
    "LOWER_BOUND",
    "UPPER_BOUND",
    "ISVALIDREF",
    "__ISVALIDREF",
    "__NEW",
    "__DELETE",
    "__QUERYINTERFACE",
    "__QUERYPOINTER",
];

/// Standard function blocks.
const FUNCTION_BLOCKS: &[&str] = &[
    "TON", "TOF", "TP", "LTON", "LTOF", "LTP", "CTU", "CTD", "CTUD", "R_TRIG", "F_TRIG", "SR",
    "RS", "RTC",
];

/// Type names that are not elementary but always available.
const BUILT_IN_TYPES: &[&str] = &[
    "ANY",
    "ANY_DERIVED",
    "ANY_ELEMENTARY",
    "ANY_MAGNITUDE",
    "ANY_NUM",
    "ANY_REAL",
    "ANY_INT",
    "ANY_BIT",
    "ANY_STRING",
    "ANY_DATE",
    "ANY_DURATION",
    "ANY_SIGNED",
    "ANY_UNSIGNED",
    "ANY_CHAR",
    "ANY_CHARS",
    "BIT",
    "__XWORD",
    "__UXINT",
    "__XINT",
];

/// Whether `name` (any case) is a standard function, operator function or conversion: whether
/// the checker knows its signature.
pub fn is_function(name: &str) -> bool {
    super::signatures::function(name).is_some()
}

/// Whether `name` (any case) is a standard function block.
pub fn is_function_block(name: &str) -> bool {
    super::signatures::function_block(name).is_some()
}

/// Whether `name` (any case) names a type every project has: elementary, generic or a standard
/// function block.
pub fn is_built_in_type(name: &str) -> bool {
    let upper = name.to_ascii_uppercase();
    Elementary::from_name(&upper).is_some()
        || BUILT_IN_TYPES.contains(&upper.as_str())
        || is_function_block(&upper)
}

/// Every standard name, for suggestions.
pub fn all_names() -> impl Iterator<Item = &'static str> {
    FUNCTIONS.iter().chain(FUNCTION_BLOCKS).copied()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_are_recognised_by_their_parts() {
        assert!(is_function("REAL_TO_INT"));
        assert!(is_function("time_of_day_to_dint"));
        assert!(is_function("TO_WORD"));
        assert!(is_function("INT_TO_BCD"));
        assert!(!is_function("REAL_TO_FOO"));
        assert!(is_function_block("ton"));
        assert!(is_built_in_type("TON"));
        assert!(is_built_in_type("tod"));
        assert!(!is_built_in_type("FB_Conveyor"));
    }
}
