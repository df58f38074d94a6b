//! Fuzzes the parser's three entry points: none may panic, hang or lose a byte, and every
//! error must point inside the text.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for parse in [
        compiler::syntax::parse(text),
        compiler::syntax::parse_statements(text),
        compiler::syntax::parse_declaration_part(text),
    ] {
        assert_eq!(parse.syntax().to_string(), text);
        for error in parse.errors() {
            assert!(error.range.start <= error.range.end && error.range.end <= text.len());
            assert!(text.is_char_boundary(error.range.start) && text.is_char_boundary(error.range.end));
            let _ = error.render("fuzz.st", text);
        }
    }
});
