//! Rivet's tree-sitter grammar for IEC 61131-3 Structured Text in the CODESYS dialect.
//!
//! The editor uses it for incremental highlighting, folding and bracket and block matching.
//! It is a highlighting detail: the compiler's hand-written parser (`compiler::syntax`) stays
//! the only source of diagnostics, and a corpus test (`tests/corpus.rs`) keeps this grammar
//! accepting every file that parser accepts.
//!
//! The grammar is `grammar.js`; the parser generated from it (`src/parser.c`) is committed, so
//! building this crate needs a C compiler but no tree-sitter CLI. The README says how to
//! regenerate it.
//!
//! One tree covers a whole source file (POUs, types, global variable lists, configurations),
//! a POU body as a project stores it (statements only), or a declaration part stored apart
//! from its body.
//!
//! The queries follow the tree-sitter-highlight convention: when several patterns capture the
//! same node, the first one in the file wins, so specific patterns come before general ones.

use tree_sitter_language::LanguageFn;

mod ffi {
    #![allow(unsafe_code)] // The one foreign declaration: the generated parser's entry point.

    unsafe extern "C" {
        /// Returns the static language table of the generated parser; it has no preconditions
        /// and the table lives for the whole program.
        pub(super) safe fn tree_sitter_rivet_st() -> *const ();
    }
}

/// The raw language function, for tree-sitter APIs that take a [`LanguageFn`].
// SAFETY: `tree_sitter_rivet_st` is the entry point that `tree-sitter generate` wrote into
// `src/parser.c`, compiled and linked by `build.rs`; it returns a pointer to a static
// `TSLanguage`, which is exactly what `LanguageFn` requires.
#[allow(unsafe_code)]
pub const LANGUAGE: LanguageFn = unsafe { LanguageFn::from_raw(ffi::tree_sitter_rivet_st) };

/// The Structured Text language, to give to `tree_sitter::Parser::set_language` and
/// `tree_sitter::Query::new`. Cheap to call: it wraps a static table.
pub fn language() -> tree_sitter::Language {
    tree_sitter::Language::new(LANGUAGE)
}

/// The highlighting query: captures such as `@keyword`, `@type`, `@number`, `@string`,
/// `@comment`, `@function.call`, `@variable`, `@property` and `@operator`.
pub const HIGHLIGHTS_QUERY: &str = include_str!("../queries/highlights.scm");

/// The folding query: every `@fold` capture is a foldable range (POUs, variable blocks,
/// types, IF, CASE and its branches, loops, SFC steps and transitions, long comments).
pub const FOLDS_QUERY: &str = include_str!("../queries/folds.scm");

/// The locals query: `@local.scope` (POUs, methods, actions, properties),
/// `@local.definition` (declared variables and parameters) and `@local.reference`.
pub const LOCALS_QUERY: &str = include_str!("../queries/locals.scm");

/// The node types of the grammar as tree-sitter describes them (`src/node-types.json`).
pub const NODE_TYPES: &str = include_str!("node-types.json");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_language_has_the_abi_of_the_linked_tree_sitter() {
        let language = language();
        assert!(language.abi_version() >= tree_sitter::MIN_COMPATIBLE_LANGUAGE_VERSION);
        assert!(language.abi_version() <= tree_sitter::LANGUAGE_VERSION);
        let mut parser = tree_sitter::Parser::new();
        assert!(parser.set_language(&language).is_ok());
    }
}
