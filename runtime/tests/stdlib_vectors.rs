//! Every test vector with numbers that the LC1200 (CODESYS) and Delta DVP-15MC digests give for
//! the functions of `runtime::stdlib`, as assertions against its API.
//!
//! The digests are `shared/reference/digests/lc1200-codesys.md` (D§ numbers) and
//! `shared/reference/digests/delta-dvp15mc.md` (§ numbers); the manual sections are in brackets.
//! Where this implementation deliberately differs from a digest, the test says so and asserts
//! the decided value.

use program_image::Elementary::{self, *};
use runtime::stdlib::{
    bits, convert::convert, convert::trunc, numeric, raw_from_i64, raw_from_real, real_value,
    sign_extend, string, text, time,
};

fn real(x: f32) -> u64 {
    u64::from(x.to_bits())
}

fn lreal(x: f64) -> u64 {
    x.to_bits()
}

/// The raw value of a literal, read by the library itself.
#[track_caller]
fn lit(text: &str, ty: Elementary) -> u64 {
    let raw = text::from_text(text.as_bytes(), ty);
    assert_eq!(
        text::from_text(text::to_text(raw, ty).as_bytes(), ty),
        raw,
        "{text} does not read back"
    );
    raw
}

#[track_caller]
fn value(raw: u64, ty: Elementary) -> i64 {
    sign_extend(raw, ty)
}

// LC1200 D§2.5 (§5.3.9 BOOL_TO): TRUE converts to 1 in the target's unit.
#[test]
fn lc1200_bool_to_other_types() {
    assert_eq!(convert(1, Bool, Int), 1);
    assert_eq!(text::to_text(1, Bool), "TRUE");
    assert_eq!(convert(1, Bool, Time), lit("T#1ms", Time));
    assert_eq!(
        convert(1, Bool, TimeOfDay),
        lit("TOD#00:00:00.001", TimeOfDay)
    );
    assert_eq!(
        text::to_text(convert(1, Bool, TimeOfDay), TimeOfDay),
        "TOD#00:00:00.001"
    );
    assert_eq!(convert(0, Bool, Date), lit("D#1970-01-01", Date));
    assert_eq!(text::to_text(convert(0, Bool, Date), Date), "D#1970-01-01");
    assert_eq!(
        convert(1, Bool, DateAndTime),
        lit("DT#1970-01-01-00:00:01", DateAndTime)
    );
    assert_eq!(
        text::to_text(convert(1, Bool, DateAndTime), DateAndTime),
        "DT#1970-01-01-00:00:01"
    );
}

// LC1200 D§2.5 (§5.3.9 TO_BOOL): nonzero is TRUE, and 'TRUE' is TRUE.
#[test]
fn lc1200_to_bool() {
    assert_eq!(convert(0b1101_0101, Byte, Bool), 1);
    assert_eq!(convert(0, Int, Bool), 0);
    assert_eq!(convert(lit("T#5ms", Time), Time, Bool), 1);
    assert_eq!(text::from_text(b"TRUE", Bool), 1);
}

// LC1200 D§2.5 (§5.3.9 TO_<type>).
#[test]
fn lc1200_to_type() {
    assert_eq!(convert(real(4.22), Real, Int), 4);
    assert_eq!(convert(1, Int, Bool), 1);
    assert_eq!(text::to_text(342, Int), "342");
    assert_eq!(text::from_text(b"123", Word), 123);
}

// LC1200 D§2.5 (§5.3.9 <INT type>_TO_<INT type>): INT_TO_SINT(4223) keeps the low byte.
#[test]
fn lc1200_integer_narrowing_keeps_the_low_bits() {
    assert_eq!(convert(4223, Int, Sint), 127);
    assert_eq!(convert(0x107F, Int, Sint), 0x7F);
}

// LC1200 D§2.5 (§5.3.9 REAL_TO): round half away from zero.
#[test]
fn lc1200_real_to_int_rounds_half_away_from_zero() {
    assert_eq!(value(convert(real(1.5), Real, Int), Int), 2);
    assert_eq!(value(convert(real(1.4), Real, Int), Int), 1);
    assert_eq!(value(convert(real(-1.5), Real, Int), Int), -2);
    assert_eq!(value(convert(real(-1.4), Real, Int), Int), -1);
}

// LC1200 D§2.5 (§5.3.9 TIME_TO / TIME_OF_DAY_TO).
#[test]
fn lc1200_time_to_other_types() {
    assert_eq!(text::to_text(lit("T#12ms", Time), Time), "T#12ms");
    assert_eq!(convert(lit("T#5m", Time), Time, Dword), 300_000);
    assert_eq!(
        convert(lit("TOD#00:00:00.012", TimeOfDay), TimeOfDay, Sint),
        12
    );
}

// LC1200 D§2.5 (§5.3.9 DATE_TO / DT_TO): dates convert as their seconds since 1970.
#[test]
fn lc1200_date_to_other_types() {
    assert_eq!(convert(lit("D#1970-01-01", Date), Date, Bool), 0);
    assert_eq!(convert(lit("D#1970-01-15", Date), Date, Int), 29952);
    assert_eq!(
        convert(
            lit("DT#1970-01-15-05:05:05", DateAndTime),
            DateAndTime,
            Byte
        ),
        129
    );
    // The manual's result column repeats the literal `DT#1998-02-13-14:20`; the literal without
    // seconds is read, and the text is written with its seconds, as every DT is here.
    let dt = lit("DT#1998-02-13-14:20", DateAndTime);
    assert_eq!(dt, lit("DT#1998-02-13-14:20:00", DateAndTime));
    assert_eq!(text::to_text(dt, DateAndTime), "DT#1998-02-13-14:20:00");
}

// LC1200 D§2.5 (§5.3.9 STRING_TO): a leading constant, extra characters after it allowed.
#[test]
fn lc1200_string_to_other_types() {
    assert_eq!(text::from_text(b"TRUE", Bool), 1);
    assert_eq!(text::from_text(b"abc34", Word), 0);
    assert_eq!(text::from_text(b"34abc", Word), 34);
    assert_eq!(text::from_text(b"T#127ms", Time), 127);
    assert_eq!(text::from_text(b"1.234", Real), real(1.234));
    assert_eq!(text::from_text(b"500", Byte), 244);
}

// LC1200 D§2.5 (§5.3.9 TRUNC).
#[test]
fn lc1200_trunc() {
    assert_eq!(value(trunc(real(1.9), Real, Dint), Dint), 1);
    assert_eq!(value(trunc(real(-1.4), Real, Dint), Dint), -1);
}

// LC1200 D§2.4 (§5.3 shift operators): the width is the operand's type.
#[test]
fn lc1200_shifts_and_rotations() {
    assert_eq!(bits::shl(0x45, 2, Byte), 0x14);
    assert_eq!(bits::shr(0x45, 2, Byte), 0x11);
    assert_eq!(bits::rol(0x45, 2, Byte), 0x15);
    assert_eq!(bits::ror(0x45, 2, Byte), 0x51);
    assert_eq!(bits::shl(0x0045, 2, Word), 0x0114);
    assert_eq!(bits::shr(0x0045, 2, Word), 0x0011);
    assert_eq!(bits::rol(0x0045, 2, Word), 0x0114);
    assert_eq!(bits::ror(0x0045, 2, Word), 0x4011);
}

// LC1200 D§2.4 (§5.3 arithmetic and numeric operators).
#[test]
fn lc1200_mod_and_expt() {
    assert_eq!(numeric::modulo(9, 2, Int), 1);
    assert_eq!(numeric::expt_int(7, 2), 49);
    assert_eq!(numeric::expt_real(2.0, 7.0), 128.0);
}

// LC1200 D§2.1 (§5.1 elementary types): the limits of the time and date types as literals.
#[test]
fn lc1200_time_and_date_limits() {
    assert_eq!(lit("TOD#0:0:0.000", TimeOfDay), 0);
    assert_eq!(lit("TOD#23:59:59.999", TimeOfDay), 86_399_999);
    assert_eq!(lit("D#1970-1-1", Date), 0);
    assert_eq!(lit("D#2106-2-7", Date), 49_710 * 86_400);
    assert_eq!(lit("DT#1970-1-1-00:00:00", DateAndTime), 0);
    assert_eq!(lit("DT#2106-2-7-6:28:15", DateAndTime), u64::from(u32::MAX));
    // CODESYS counts TIME and LTIME unsigned; the image stores them signed (docs/program-image.md
    // §4), so the upper limits have the same bits but read as negative.
    assert_eq!(
        text::from_text(b"T#49d17h2m47s295ms", Time),
        u64::from(u32::MAX)
    );
    assert_eq!(text::to_text(u64::from(u32::MAX), Time), "T#-1ms");
    assert_eq!(
        text::from_text(b"LTIME#213503d23h34m33s709ms551us615ns", Ltime),
        u64::MAX
    );
    let ltime = lit("LTIME#1000d15h23m12s34ms2us44ns", Ltime);
    assert_eq!(
        ltime,
        ((((1000 * 24 + 15) * 60 + 23) * 60 + 12) * 1000 + 34) * 1_000_000 + 2044
    );
    assert_eq!(
        text::to_text(ltime, Ltime),
        "LTIME#1000d15h23m12s34ms2us44ns"
    );
}

// Delta §1.4 (3.1.2.4): TOD values of a day or more display modulo a day.
#[test]
fn delta_tod_display_wraps_at_a_day() {
    assert_eq!(text::to_text(86_400_000, TimeOfDay), "TOD#00:00:00");
    assert_eq!(text::to_text(4_294_967_295, TimeOfDay), "TOD#17:02:47.295");
    assert_eq!(
        lit("TOD#17:2:47.295", TimeOfDay),
        4_294_967_295 % 86_400_000
    );
    assert_eq!(lit("DT#1970-01-01-0:0:0", DateAndTime), 0);
    assert_eq!(lit("D#2106-02-07", Date), 49_710 * 86_400);
}

// Delta §3.1 type conversion (8.13.1): BOOL to time and date types.
#[test]
fn delta_bool_to_time_and_date() {
    assert_eq!(convert(1, Bool, TimeOfDay), lit("TOD#0:0:0.001", TimeOfDay));
    assert_eq!(
        convert(1, Bool, DateAndTime),
        lit("DT#1970-01-01-00:00:01", DateAndTime)
    );
    assert_eq!(text::to_text(0, Bool), "FALSE");
    assert_eq!(convert(1, Bool, Lword), 1);
    assert_eq!(convert(1, Bool, Lreal), lreal(1.0));
}

// Delta §3.1 type conversion (8.13.4): reals round half away from zero, negatives wrap into
// unsigned types.
#[test]
fn delta_real_to_integer() {
    assert_eq!(value(convert(real(1.36), Real, Sint), Sint), 1);
    assert_eq!(convert(real(1.36), Real, Usint), 1);
    assert_eq!(value(convert(real(-2.4), Real, Sint), Sint), -2);
    assert_eq!(convert(real(-2.4), Real, Usint), 254);
    assert_eq!(value(convert(real(1.6), Real, Sint), Sint), 2);
    assert_eq!(convert(real(1.6), Real, Usint), 2);
    assert_eq!(value(convert(real(-2.6), Real, Sint), Sint), -3);
    assert_eq!(convert(real(-2.6), Real, Usint), 253);
}

// Delta §3.1 type conversion (8.13.2, 8.13.3): narrowing keeps the low bits, widening of signed
// types; the Delta tables zero-extend (SINT 16#80 → INT 128), which the digest marks as a
// documentation error: here signed types widen with their sign, as in IEC and CODESYS.
#[test]
fn delta_integer_widening_and_narrowing() {
    assert_eq!(convert(0x80, Sint, Int), raw_from_i64(-128, Int));
    assert_eq!(convert(0x80, Byte, Int), 128);
    assert_eq!(convert(0xFF, Byte, Sint), raw_from_i64(-1, Sint));
    assert_eq!(convert(0x1234_5678, Dword, Word), 0x5678);
    assert_eq!(
        convert(0x8000_0000, Dword, Dint),
        raw_from_i64(i64::from(i32::MIN), Dint)
    );
    assert_eq!(value(convert(u64::MAX, Lword, Lint), Lint), -1);
}

// Delta §3.1 type conversion (8.13.2): bit strings to reals and to time and date types.
#[test]
fn delta_bit_strings_to_reals_and_times() {
    assert_eq!(convert(0xFF, Byte, Real), real(255.0));
    assert_eq!(convert(0xFFFF, Word, Lreal), lreal(65535.0));
    assert_eq!(
        real_value(convert(0xFFFF_FFFF, Dword, Real), Real),
        4_294_967_296.0
    );
    assert_eq!(convert(0xFFFF_FFFF, Dword, Lreal), lreal(4_294_967_295.0));
    assert_eq!(
        real_value(convert(u64::MAX, Lword, Lreal), Lreal),
        1.844_674_407_370_955_2e19
    );
    assert_eq!(
        text::to_text(convert(0xFF, Byte, DateAndTime), DateAndTime),
        "DT#1970-01-01-00:04:15"
    );
    assert_eq!(
        text::to_text(convert(0xFFFF, Word, DateAndTime), DateAndTime),
        "DT#1970-01-01-18:12:15"
    );
    assert_eq!(
        text::to_text(convert(0xFFFF, Word, TimeOfDay), TimeOfDay),
        "TOD#00:01:05.535"
    );
    assert_eq!(
        text::to_text(convert(0xFF, Byte, TimeOfDay), TimeOfDay),
        "TOD#00:00:00.255"
    );
    assert_eq!(
        text::to_text(convert(0xFFFF_FFFF, Dword, TimeOfDay), TimeOfDay),
        "TOD#17:02:47.295"
    );
    assert_eq!(
        text::to_text(convert(0x0526_5BFF, Dword, TimeOfDay), TimeOfDay),
        "TOD#23:59:59.999"
    );
}

// Delta §3.1 type conversion (8.13.2, 8.13.3): to STRING. Integers are written in decimal. The
// Delta manual writes bit strings in hexadecimal of their full width (`BYTE_TO_STRING(16#FF)` =
// 'FF'); CODESYS writes them in decimal, and so does this implementation.
#[test]
fn delta_values_to_text() {
    assert_eq!(text::to_text(0xFF, Byte), "255");
    assert_eq!(text::to_text(0x80, Sint), "-128");
    assert_eq!(text::to_text(u64::MAX, Ulint), "18446744073709551615");
    assert_eq!(text::to_text(1 << 63, Lint), "-9223372036854775808");
    assert_eq!(text::to_text(0xFFFF_FFFF, Udint), "4294967295");
    assert_eq!(text::to_text(0x8000_0000, Dint), "-2147483648");
}

// Delta §3.1 type conversion (8.13.6): STRING to other types. Text that does not start with a
// literal gives 0 here; the Delta controller keeps the output's previous value.
#[test]
fn delta_text_to_values() {
    assert_eq!(text::from_text(b"TRUE", Bool), 1);
    assert_eq!(text::from_text(b"true", Bool), 1);
    assert_eq!(text::from_text(b"FALSE", Bool), 0);
    assert_eq!(text::from_text(b"123", Sint), 123);
    assert_eq!(text::from_text(b"+123", Sint), 123);
    assert_eq!(value(text::from_text(b"-123", Sint), Sint), -123);
    assert_eq!(text::from_text(b"M123", Sint), 0);
    assert_eq!(text::from_text(b"123", Real), real(123.0));
    assert_eq!(text::from_text(b"-123.123", Real), real(-123.123));
    assert_eq!(text::from_text(b"1.23e+5", Real), real(1.23e5));
    assert_eq!(text::from_text(b"M123.123", Real), 0);
    assert_eq!(text::from_text(b"T#1ns", Ltime), 1);
    assert_eq!(text::from_text(b"T#1ns", Time), 0);
    assert_eq!(text::from_text(b"D#1970-1-1", Date), 0);
    assert_eq!(text::from_text(b"TOD#0:0:0", TimeOfDay), 0);
    assert_eq!(text::from_text(b"DT#1970-1-1-0:0:0", DateAndTime), 0);
}

// Delta §3.2 golden values: overflow wraps in the output type (8.2.1), shown with the raw helpers
// the engine stores its results with.
#[test]
fn delta_overflow_wraps_in_the_output_type() {
    assert_eq!(value(raw_from_i64(32767 + 1, Int), Int), -32768);
    assert_eq!(value(raw_from_i64(32767 + 1, Dint), Dint), 32768);
    assert_eq!(value(raw_from_i64(-32768 - 1, Int), Int), 32767);
    assert_eq!(value(raw_from_i64(-32768 - 1, Dint), Dint), -32769);
    assert_eq!(value(raw_from_i64(20000 * 2, Int), Int), -25536);
    assert_eq!(value(raw_from_i64(20000 * 2, Dint), Dint), 40000);
}

// Delta §3.2 golden values: DIV and MOD (8.9).
#[test]
fn delta_div_and_mod() {
    let int = |v| raw_from_i64(v, Int);
    assert_eq!(value(numeric::div(int(-32768), int(-1), Int), Int), -32768);
    let dint = |v| convert(int(v), Int, Dint);
    assert_eq!(
        value(numeric::div(dint(-32768), dint(-1), Dint), Dint),
        32768
    );
    assert_eq!(numeric::div(10, 3, Int), 3);
    assert_eq!(numeric::div(100, 20, Int), 5);
    assert_eq!(numeric::modulo(10, 4, Int), 2);
    assert_eq!(numeric::div(10, 0, Int), 0);
    assert_eq!(numeric::modulo(10, 0, Int), 0);
}

// Delta §3.2 golden values: time arithmetic (8.9 ADD, SUB).
#[test]
fn delta_time_arithmetic() {
    let dt = lit("DT#2016-9-1-8:00:00", DateAndTime);
    let sum = time::add_duration(dt, DateAndTime, lit("TIME#1H53M34S", Time), Time);
    assert_eq!(sum, lit("DT#2016-09-01-09:53:34", DateAndTime));
    assert_eq!(text::to_text(sum, DateAndTime), "DT#2016-09-01-09:53:34");
    let a = lit("DATE#2016-10-1", Date);
    let b = lit("DATE#2016-9-1", Date);
    // TIME#30d is 2 592 000 000 ms: it fits CODESYS's unsigned TIME, and the bits are the same in
    // the image's signed TIME; as an LTIME it reads as 30 days.
    assert_eq!(time::difference(a, b, Date, Time), 2_592_000_000);
    assert_eq!(
        time::difference(a, b, Date, Time),
        text::from_text(b"TIME#30D", Time)
    );
    assert_eq!(
        text::to_text(time::difference(a, b, Date, Ltime), Ltime),
        "LTIME#30d"
    );
}

// Delta §3.2 golden values: MODREAL, MODTURNS, MODABS (8.9).
#[test]
fn delta_real_remainders() {
    assert_eq!(numeric::modreal(10.5, 2.5), 0.5);
    assert_eq!(numeric::modturns(f64::from(800.23f32), 360.0), 2);
    let close = |a: f64, b: f64| (a - b).abs() < 1e-9;
    assert!(close(
        numeric::modabs(f64::from(400.23f32), 360.0),
        40.230_010_986_328_1
    ));
    assert!(close(
        numeric::modabs(f64::from(-400.23f32), 360.0),
        319.769_989_013_672
    ));
}

// Delta §3.2 golden values: EXPT, TRUNC, FLOOR, FRACTION (8.9).
#[test]
fn delta_expt_trunc_floor_fraction() {
    assert_eq!(numeric::expt_real(-10.0, 2.0), 100.0);
    assert_eq!(numeric::expt_int(-10, 2), 100);
    assert_eq!(value(trunc(lreal(-5.6), Lreal, Lint), Lint), -5);
    assert_eq!(numeric::floor(-10.2), -11);
    assert!((numeric::fraction(-5.6) + 0.6).abs() < 1e-12);
}

// Delta §3.2 golden values: shifts of UINT 300 by 3 (8.11), and Swap, which is a rotation by
// eight bits of a 16-bit value.
#[test]
fn delta_shifts_of_uint() {
    assert_eq!(bits::shl(300, 3, Uint), 2400);
    assert_eq!(bits::shr(300, 3, Uint), 37);
    assert_eq!(bits::rol(300, 3, Uint), 2400);
    assert_eq!(bits::ror(300, 3, Uint), 32805);
    assert_eq!(bits::rol(32768, 8, Uint), 128);
    assert_eq!(bits::shl(1, 16, Uint), 0);
    assert_eq!(bits::ror(300, 3 + 16, Uint), 32805);
}

// Delta §3.1 strings (8.15): positions are 1-based.
#[test]
fn delta_string_functions() {
    let s = b"AaBbCcDd";
    assert_eq!(string::concat(b"Asasz", b"B1255"), b"AsaszB1255");
    assert_eq!(string::delete(s, 2, 3), b"AaCcDd");
    assert_eq!(string::insert(s, b"Ee", 2), b"AaEeBbCcDd");
    assert_eq!(string::insert(s, b"Ee", 0), b"EeAaBbCcDd");
    assert_eq!(string::left(s, 2), b"Aa");
    assert_eq!(string::right(s, 2), b"Dd");
    assert_eq!(string::mid(s, 2, 3), b"Bb");
    assert_eq!(string::replace(s, b"DELTA", 2, 3), b"AaDELTACcDd");
    assert_eq!(string::len(s), 8);
    assert_eq!(string::len(b"ABCDEFGH"), 8);
    assert_eq!(string::find(s, b"Cc"), 5);
    assert_eq!(string::find(b"ABCDEFGH", b"DE"), 4);
    assert_eq!(string::find(s, b"Ee"), 0);
    assert_eq!(string::find(b"CcAaCc", b"Cc"), 1);
}

// The same functions over WSTRING code units.
#[test]
fn delta_string_functions_on_wide_strings() {
    let wide = |s: &str| s.encode_utf16().collect::<Vec<u16>>();
    let s = wide("AaBbCcDd");
    assert_eq!(
        string::replace(&s, &wide("DELTA"), 2, 3),
        wide("AaDELTACcDd")
    );
    assert_eq!(string::find(&s, &wide("Cc")), 5);
    assert_eq!(string::mid(&s, 2, 3), wide("Bb"));
}

// The real accessors the engine uses for REAL results.
#[test]
fn real_results_are_stored_as_their_bits() {
    assert_eq!(raw_from_real(1.234, Real), real(1.234));
    assert_eq!(text::to_text(real(1.234), Real), "1.234");
}
