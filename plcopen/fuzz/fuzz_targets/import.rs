//! Fuzzes the whole import: any bytes are read and, when they read, converted into a project
//! without a panic, and every error (of the reader or of the conversion) names a line and column
//! inside the file (1-based).

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    match plcopen::read_bytes(data, "fuzz.xml") {
        Err(error) => {
            assert!(error.line >= 1 && error.column >= 1, "{error}");
            let _ = error.to_string();
        }
        Ok(document) => {
            if let Err(error) = plcopen::import(&document) {
                assert!(error.line >= 1 && error.column >= 1, "{error}");
                assert!(!error.path.is_empty(), "{error}");
                let _ = error.to_string();
            }
        }
    }
});
