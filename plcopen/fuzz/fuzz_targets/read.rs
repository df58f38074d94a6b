//! Fuzzes the PLCopen XML reader: any bytes are read without a panic, and an error always names a
//! line and column inside the file (1-based).

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(error) = plcopen::read_bytes(data, "fuzz.xml") {
        assert!(error.line >= 1 && error.column >= 1, "{error}");
        // Display must not panic either.
        let _ = error.to_string();
    }
});
