//! Properties of `runtime::stdlib` over arbitrary inputs: nothing panics for any raw value and
//! type pair, and text written by `to_text` reads back to the same value.

use program_image::Elementary::{self, *};
use proptest::prelude::*;
use runtime::stdlib::{bits, convert, mask, numeric, string, text, time};

fn any_type() -> impl Strategy<Value = Elementary> {
    (0..Elementary::ALL.len()).prop_map(|index| Elementary::ALL[index])
}

proptest! {
    #[test]
    fn conversions_never_panic_and_stay_within_the_target(raw: u64, from in any_type(), to in any_type()) {
        let result = convert::convert(raw, from, to);
        prop_assert_eq!(result & !mask(to), 0);
        let truncated = convert::trunc(raw, from, to);
        prop_assert_eq!(truncated & !mask(to), 0);
    }

    #[test]
    fn text_never_panics_in_either_direction(raw: u64, ty in any_type(), bytes: Vec<u8>) {
        let written = text::to_text(raw, ty);
        let _ = text::from_text(written.as_bytes(), ty);
        let _ = text::to_text_bytes(raw, ty);
        let _ = text::to_wtext(raw, ty);
        let read = text::from_text(&bytes, ty);
        prop_assert_eq!(read & !mask(ty), 0);
        let units: Vec<u16> = bytes.iter().map(|&b| u16::from(b) << 4).collect();
        let _ = text::from_wtext(&units, ty);
    }

    #[test]
    fn literal_like_text_never_panics(
        prefix in "(T|LTIME|D|TOD|DT|LDT|LTOD|INT|WORD|REAL|BOOL|16|2|8|99)?#?",
        body in "[-+0-9_.:#a-zA-Z]{0,40}",
        ty in any_type(),
    ) {
        let _ = text::from_text(format!("{prefix}{body}").as_bytes(), ty);
    }

    #[test]
    fn shifts_never_panic_and_stay_within_the_type(raw: u64, n: u64, ty in any_type()) {
        for result in [bits::shl(raw, n, ty), bits::shr(raw, n, ty), bits::rol(raw, n, ty), bits::ror(raw, n, ty)] {
            prop_assert_eq!(result & !mask(ty), 0);
        }
        prop_assert_eq!(bits::ror(bits::rol(raw, n, ty), n, ty), raw & mask(ty));
    }

    #[test]
    fn string_functions_never_panic(a: Vec<u8>, b: Vec<u8>, l: i64, p: i64) {
        let _ = string::left(&a, l);
        let _ = string::right(&a, l);
        let _ = string::mid(&a, l, p);
        let _ = string::insert(&a, &b, p);
        let deleted = string::delete(&a, l, p);
        prop_assert!(deleted.len() <= a.len());
        let replaced = string::replace(&a, &b, l, p);
        prop_assert!(replaced.len() <= a.len() + b.len());
        let found = string::find(&a, &b);
        prop_assert!(found >= 0 && found <= string::len(&a));
        let mut memory = vec![0u8; (p.unsigned_abs() % 64) as usize];
        let written = string::store(&mut memory, &a, l.unsigned_abs() as usize);
        prop_assert_eq!(string::load(&memory, l.unsigned_abs() as usize), &a[..written]);
        let _ = string::store_wide(&mut memory, &[1, 2, 3], l.unsigned_abs() as usize);
        let _ = string::load_wide(&memory, l.unsigned_abs() as usize);
    }

    #[test]
    fn time_functions_never_panic(a: u64, b: u64, k: i64, x: f64, parts: [i64; 7], ty in any_type(), other in any_type()) {
        let _ = time::add_duration(a, ty, b, other);
        let _ = time::sub_duration(a, ty, b, other);
        let _ = time::difference(a, b, ty, other);
        let _ = time::mul_duration_int(a, ty, k);
        let _ = time::mul_duration_real(a, ty, x);
        let _ = time::div_duration_int(a, ty, k);
        let _ = time::div_duration_real(a, ty, x);
        let _ = time::split(a, ty);
        let _ = time::day_of_week(a, ty);
        let _ = time::concat_date_tod(a, ty, b, other, ty);
        let [year, month, day, hour, minute, second, millisecond] = parts;
        let _ = time::concat_dt(year, month, day, hour, minute, second, millisecond, ty);
        let _ = time::concat_tod(hour, minute, second, millisecond, ty);
        let _ = time::raw_from_ns(k, ty);
    }

    #[test]
    fn numeric_functions_never_panic(a: u64, b: u64, ty in any_type(), base: i64, exponent: i64, x: f64, y: f64) {
        let _ = numeric::div(a, b, ty);
        let _ = numeric::modulo(a, b, ty);
        let _ = numeric::expt_int(base, exponent);
        let _ = numeric::expt_real(x, y);
        let _ = numeric::floor(x);
        let _ = numeric::modreal(x, y);
        let _ = numeric::modturns(x, y);
        let _ = numeric::modabs(x, y);
    }

    #[test]
    fn integers_read_back_from_their_text(raw: u64, index in 0usize..13) {
        let ty = [Byte, Word, Dword, Lword, Sint, Int, Dint, Lint, Usint, Uint, Udint, Ulint, Bool][index];
        let raw = raw & mask(ty);
        prop_assert_eq!(text::from_text(text::to_text(raw, ty).as_bytes(), ty), raw);
    }

    #[test]
    fn durations_read_back_from_their_text(raw: u64) {
        for ty in [Time, Ltime] {
            let raw = raw & mask(ty);
            prop_assert_eq!(text::from_text(text::to_text(raw, ty).as_bytes(), ty), raw);
        }
    }

    #[test]
    fn dates_and_times_read_back_from_their_text(seconds: u32, days in 0u64..49_711, ms in 0u64..86_400_000, ns: i64) {
        let cases = [
            (days * 86_400, Date),
            (ms, TimeOfDay),
            (u64::from(seconds), DateAndTime),
            ((days * 86_400_000_000_000) & mask(Ldate), Ldate),
            (ms * 1_000_000 + (ns.unsigned_abs() % 1_000_000), LtimeOfDay),
            (ns as u64, LdateAndTime),
        ];
        for (raw, ty) in cases {
            let written = text::to_text(raw, ty);
            prop_assert_eq!(text::from_text(written.as_bytes(), ty), raw, "{}", written);
        }
    }

    #[test]
    fn finite_reals_read_back_from_their_text(x: f64, y: f32) {
        prop_assume!(x.is_finite() && y.is_finite());
        let raw = x.to_bits();
        prop_assert_eq!(text::from_text(text::to_text(raw, Lreal).as_bytes(), Lreal), raw);
        let raw = u64::from(y.to_bits());
        prop_assert_eq!(text::from_text(text::to_text(raw, Real).as_bytes(), Real), raw);
    }
}
