//! The grammar agrees with the compiler: on every file of the third-party corpora in
//! `../shared/corpora` and every body of the example project that `compiler::syntax` accepts,
//! the tree-sitter tree holds no ERROR and no MISSING node.
//!
//! Files the compiler rejects are skipped (the compiler is the only source of diagnostics),
//! but the test counts the accepted ones, so it cannot pass by checking nothing.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::path::{Path, PathBuf};

use tree_sitter::{Node, Parser};

// The compiler's corpus tests find the corpora the same way; one file serves both crates.
#[path = "../../compiler/tests/common/mod.rs"]
mod common;

use common::{corpora, files};

/// How the compiler reads a text, which decides whether it is accepted.
#[derive(Clone, Copy, Debug)]
enum Entry {
    /// A whole source file: `compiler::syntax::parse`.
    SourceFile,
    /// A POU body as a project stores it: `compiler::syntax::parse_statements`.
    Statements,
    /// A declaration part stored apart from its body: `compiler::syntax::parse_declaration_part`.
    DeclarationPart,
}

/// One text to check, with where it came from.
struct Sample {
    origin: String,
    text: String,
    entry: Entry,
}

/// Whole files, read as the compiler's corpus test reads them (invalid UTF-8 replaced).
fn whole_files(paths: Vec<PathBuf>, entry: Entry) -> Vec<Sample> {
    paths
        .into_iter()
        .map(|path| Sample {
            origin: path.display().to_string(),
            text: String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned(),
            entry,
        })
        .collect()
}

/// The texts inside `<tag><![CDATA[…]]></tag>` elements of a TwinCAT XML file, as
/// `compiler/tests/corpus.rs` extracts them.
fn cdata_of(xml: &str, tag: &str) -> Vec<String> {
    let open = format!("<{tag}><![CDATA[");
    let mut found = Vec::new();
    let mut rest = xml;
    while let Some(start) = rest.find(&open) {
        let after = &rest[start + open.len()..];
        let Some(end) = after.find("]]>") else { break };
        found.push(after[..end].to_owned());
        rest = &after[end..];
    }
    found
}

fn tcunit_parts() -> Vec<Sample> {
    let root = corpora().join("TcUnit");
    let mut paths = files(&root, "TcPOU");
    paths.extend(files(&root, "TcDUT"));
    paths.extend(files(&root, "TcGVL"));
    assert!(paths.len() > 90, "{} TwinCAT files", paths.len());
    let mut samples = Vec::new();
    for path in paths {
        let xml = std::fs::read_to_string(&path).unwrap();
        for (index, text) in cdata_of(&xml, "Declaration").into_iter().enumerate() {
            samples.push(Sample {
                origin: format!("{} (declaration {})", path.display(), index + 1),
                text,
                entry: Entry::DeclarationPart,
            });
        }
        for (index, text) in cdata_of(&xml, "ST").into_iter().enumerate() {
            samples.push(Sample {
                origin: format!("{} (body {})", path.display(), index + 1),
                text,
                entry: Entry::Statements,
            });
        }
    }
    samples
}

fn compiler_accepts(sample: &Sample) -> bool {
    let parse = match sample.entry {
        Entry::SourceFile => compiler::syntax::parse(&sample.text),
        Entry::Statements => compiler::syntax::parse_statements(&sample.text),
        Entry::DeclarationPart => compiler::syntax::parse_declaration_part(&sample.text),
    };
    parse.errors().is_empty()
}

/// The first ERROR or MISSING node in document order, if any.
fn first_problem(root: Node<'_>) -> Option<Node<'_>> {
    if !root.has_error() {
        return None;
    }
    let mut cursor = root.walk();
    loop {
        let node = cursor.node();
        if node.is_error() || node.is_missing() {
            return Some(node);
        }
        // Only subtrees that hold an error are worth entering.
        if node.has_error() && cursor.goto_first_child() {
            continue;
        }
        while !cursor.goto_next_sibling() {
            if !cursor.goto_parent() {
                return None;
            }
        }
    }
}

/// Parses every sample the compiler accepts; returns how many were checked and a line for
/// each that tree-sitter does not parse cleanly.
fn disagreements(samples: &[Sample]) -> (usize, Vec<String>) {
    let mut parser = Parser::new();
    parser
        .set_language(&tree_sitter_rivet_st::language())
        .unwrap();
    let mut checked = 0;
    let mut wrong = Vec::new();
    for sample in samples {
        if !compiler_accepts(sample) {
            continue;
        }
        checked += 1;
        let tree = parser.parse(&sample.text, None).unwrap();
        if let Some(node) = first_problem(tree.root_node()) {
            let start = node.start_position();
            let line = sample.text.lines().nth(start.row).unwrap_or("").trim();
            let what = if node.is_missing() {
                format!("MISSING {}", node.kind())
            } else {
                "ERROR".to_owned()
            };
            wrong.push(format!(
                "{}:{}:{}: {what} ({:?} as {:?}) in `{line}`",
                sample.origin,
                start.row + 1,
                start.column + 1,
                node.utf8_text(sample.text.as_bytes())
                    .unwrap_or("")
                    .chars()
                    .take(60)
                    .collect::<String>(),
                sample.entry,
            ));
        }
    }
    (checked, wrong)
}

#[track_caller]
fn assert_agreement(samples: &[Sample], at_least: usize) {
    let (checked, wrong) = disagreements(samples);
    assert!(
        checked >= at_least,
        "only {checked} of {} texts are accepted by the compiler; expected at least {at_least}",
        samples.len()
    );
    assert!(
        wrong.is_empty(),
        "tree-sitter rejects {} of the {checked} texts the compiler accepts:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

/// The same texts with every letter in lower case: keywords ignore case, so what the
/// compiler accepts this way tree-sitter must accept too.
fn lower_cased(samples: &[Sample]) -> Vec<Sample> {
    samples
        .iter()
        .map(|sample| Sample {
            origin: format!("{} (lower case)", sample.origin),
            text: sample.text.to_lowercase(),
            entry: sample.entry,
        })
        .collect()
}

/// A small deterministic random number generator (xorshift), so the mutations are the same
/// on every run.
struct Xorshift(u64);

impl Xorshift {
    fn below(&mut self, bound: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        usize::try_from(self.0 % u64::try_from(bound).unwrap()).unwrap()
    }
}

/// Variants of each text with a few pieces (split after whitespace and punctuation) removed,
/// repeated or swapped. Most variants are wrong and the compiler rejects them; those it
/// accepts probe corners of its grammar that no corpus file shows.
fn mutated(samples: &[Sample], per_text: usize) -> Vec<Sample> {
    let mut random = Xorshift(0x5EED_1E55);
    let mut variants = Vec::new();
    for sample in samples {
        let pieces: Vec<&str> = sample
            .text
            .split_inclusive(|c: char| c.is_whitespace() || ";:=(),[]".contains(c))
            .collect();
        if pieces.len() < 3 {
            continue;
        }
        for variant in 0..per_text {
            let mut changed = pieces.clone();
            for _ in 0..=random.below(3) {
                let at = random.below(changed.len());
                let other = random.below(changed.len());
                match random.below(3) {
                    0 => {
                        changed.remove(at);
                    }
                    1 => changed.insert(at, changed[other]),
                    _ => changed.swap(at, other),
                }
                if changed.len() < 2 {
                    break;
                }
            }
            variants.push(Sample {
                origin: format!("{} (variant {variant})", sample.origin),
                text: changed.concat(),
                entry: sample.entry,
            });
        }
    }
    variants
}

#[test]
fn mutated_corpus_texts_the_compiler_accepts_parse_without_errors() {
    let mut samples = whole_files(files(&corpora().join("ironplc"), "st"), Entry::SourceFile);
    let matiec = corpora().join("matiec");
    samples.extend(whole_files(files(&matiec, "txt"), Entry::SourceFile));
    samples.extend(tcunit_parts());
    samples.retain(compiler_accepts);
    let variants = mutated(&samples, 12);
    // About a third of the variants stay valid; the count guards against a broken mutator.
    assert_agreement(&variants, variants.len() / 5);
}

#[test]
fn the_check_finds_error_and_missing_nodes() {
    let mut parser = Parser::new();
    parser
        .set_language(&tree_sitter_rivet_st::language())
        .unwrap();
    for (text, expected) in [("x := := 1;", "ERROR"), ("x := (2;", "MISSING")] {
        let tree = parser.parse(text, None).unwrap();
        let problem = first_problem(tree.root_node()).expect("a problem is found");
        let found = if problem.is_missing() {
            "MISSING"
        } else {
            "ERROR"
        };
        assert_eq!(found, expected, "{}", tree.root_node().to_sexp());
    }
    let tree = parser.parse("x := (2);", None).unwrap();
    assert!(first_problem(tree.root_node()).is_none());
}

#[test]
fn ironplc_files_the_compiler_accepts_parse_without_errors() {
    let samples = whole_files(files(&corpora().join("ironplc"), "st"), Entry::SourceFile);
    assert_agreement(&samples, 80);
    assert_agreement(&lower_cased(&samples), 80);
}

#[test]
fn matiec_files_the_compiler_accepts_parse_without_errors() {
    let root = corpora().join("matiec");
    let mut paths = files(&root, "st");
    paths.extend(files(&root, "txt"));
    paths.extend(files(&root, "test"));
    let samples = whole_files(paths, Entry::SourceFile);
    assert_agreement(&samples, 30);
    assert_agreement(&lower_cased(&samples), 30);
}

#[test]
fn rusty_files_the_compiler_accepts_parse_without_errors() {
    let samples = whole_files(files(&corpora().join("rusty"), "st"), Entry::SourceFile);
    assert_agreement(&samples, 5);
}

#[test]
fn tcunit_declarations_and_bodies_the_compiler_accepts_parse_without_errors() {
    let samples = tcunit_parts();
    assert_agreement(&samples, 900);
    assert_agreement(&lower_cased(&samples), 900);
}

#[test]
fn the_example_project_bodies_parse_without_errors() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assets/examples");
    let samples = whole_files(files(&examples, "st"), Entry::Statements);
    assert_agreement(&samples, 5);
}
