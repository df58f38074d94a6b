//! Compiles the generated parser and the external scanner, both committed in `src/`, so a
//! build needs no tree-sitter CLI.

fn main() {
    let src = std::path::Path::new("src");
    cc::Build::new()
        .std("c11")
        .include(src)
        .file(src.join("parser.c"))
        .file(src.join("scanner.c"))
        // The generated parser has unused parameters and the like; its warnings are not ours.
        .warnings(false)
        .compile("tree-sitter-rivet-st");
    for file in ["parser.c", "scanner.c", "tree_sitter/parser.h"] {
        println!("cargo:rerun-if-changed=src/{file}");
    }
}
