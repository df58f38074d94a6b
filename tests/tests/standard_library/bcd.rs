//! The BCD conversions where no assignment gives the result its type: inside an operator, as
//! another function's argument, in a comparison. There a `*_TO_BCD` result is the bit string of
//! its argument's width (IEC 61131-3 ed. 3 table 22: `USINT_TO_BCD_BYTE`, `UINT_TO_BCD_WORD`,
//! `UDINT_TO_BCD_DWORD`, `ULINT_TO_BCD_LWORD`); the checker accepts these calls, so both engines
//! must run them.

use super::{Is, case, leak, run_case};

#[test]
fn a_bcd_result_inside_an_expression_has_its_arguments_width() {
    let case = case(
        "INT_TO_BCD",
        "i : INT := 42; j : INT := 1234; u : USINT := 99; d : DINT := 87654321; \
         l : LINT := 123456789012; w : WORD; x : WORD; b : BYTE; dw : DWORD; lw : LWORD; \
         ok : BOOL; s1 : UDINT; s2 : UDINT; s4 : UDINT; s8 : UDINT;",
        "w := INT_TO_BCD(i) OR 16#F000;
         x := SHL(INT_TO_BCD(j), 4);
         IF INT_TO_BCD(i) = 16#0042 THEN ok := TRUE; END_IF;
         b := USINT_TO_BCD(u) AND 16#0F;
         dw := DINT_TO_BCD(d) XOR 16#F000_0000;
         lw := LINT_TO_BCD(l) OR 16#F000_0000_0000_0000;
         s1 := SIZEOF(USINT_TO_BCD(u)); s2 := SIZEOF(INT_TO_BCD(i));
         s4 := SIZEOF(DINT_TO_BCD(d)); s8 := SIZEOF(LINT_TO_BCD(l));",
        vec![
            ("w", Is(leak(0xF042u16))),
            ("x", Is(leak(0x2340u16))),
            ("ok", Is("TRUE")),
            ("b", Is(leak(0x09u8))),
            ("dw", Is(leak(0x7765_4321u32))),
            ("lw", Is(leak(0xF000_1234_5678_9012u64))),
            ("s1", Is("1")),
            ("s2", Is("2")),
            ("s4", Is("4")),
            ("s8", Is("8")),
        ],
    );
    if let Err(error) = run_case(&case) {
        panic!("{error}");
    }
}

/// Where an assignment or an input gives a bit string type, the value is converted to that type
/// first (as `*_TO_<type>` does: a narrower type keeps the low bits) and coded there: the BCD of
/// a value the target holds is the same number widened, 12345 into a DWORD keeps its five digits
/// (in a WORD it would lose the 1), and 123456789012 into a WORD codes its low 16 bits, 6676. An
/// integer target is coded in alike (`d := INT_TO_BCD(k)` with `d` a DINT keeps the five digits).
#[test]
fn a_bcd_result_assigned_takes_the_targets_width() {
    let case = case(
        "INT_TO_BCD",
        "j : INT := 1234; k : INT := 12345; i : INT := 42; l : LINT := 123456789012; \
         dw : DWORD; dk : DWORD; b : BYTE; w : WORD; n : UINT; d : DINT; o : INT;",
        "dw := INT_TO_BCD(j); dk := (INT_TO_BCD(k)); b := INT_TO_BCD(i); \
         w := LINT_TO_BCD(l); n := WORD_TO_UINT(INT_TO_BCD(i)); d := INT_TO_BCD(k); \
         o := INT_TO_BCD(i);",
        vec![
            ("dw", Is(leak(0x1234u32))),
            ("dk", Is(leak(0x1_2345u32))),
            ("b", Is(leak(0x42u8))),
            ("w", Is(leak(0x6676u16))),
            ("n", Is(leak(0x42u16))),
            ("d", Is(leak(0x1_2345u32))),
            ("o", Is(leak(0x42u16))),
        ],
    );
    if let Err(error) = run_case(&case) {
        panic!("{error}");
    }
}

#[test]
fn a_bcd_argument_converts_back_inside_an_expression() {
    let case = case(
        "BCD_TO_INT",
        "w : WORD := 16#0042; lw : LWORD := 16#0000_1234_5678_9012; b : BYTE := 16#99; \
         n : INT; m : LINT; k : USINT; ok : BOOL;",
        "n := BCD_TO_INT(w) + 1;
         m := BCD_TO_LINT(lw) * 2;
         k := BCD_TO_USINT(b) - 9;
         IF BCD_TO_INT(w OR 16#0100) = 142 THEN ok := TRUE; END_IF;",
        vec![
            ("n", Is("43")),
            ("m", Is(leak(123_456_789_012i64 * 2))),
            ("k", Is("90")),
            ("ok", Is("TRUE")),
        ],
    );
    if let Err(error) = run_case(&case) {
        panic!("{error}");
    }
}
