//! Fuzzes the checker: any text, made into a project of its own, must check without a panic or
//! a hang, and every finding that maps back to the text must point inside it.

#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let source = compiler::source_project::SourceProject::new(text);
    for found in compiler::sema::check_project(&source.project) {
        if let Some(range) = source.locate(&found) {
            assert!(range.start <= range.end && range.end <= text.len());
            let mut diagnostic = found.diagnostic.clone();
            diagnostic.range = range;
            let _ = diagnostic.render("fuzz.st", text);
        }
    }
});
