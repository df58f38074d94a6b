//! Third-party IEC 61131-3 sources from `../shared/corpora` (see its README): the parser must
//! accept what their authors' tools accept and reject the files named as syntax errors.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::path::{Path, PathBuf};

use compiler::syntax::parse;

mod common;

use common::{corpora, files};

/// Parses every file and returns those whose outcome differs from `expect_ok`, with the first
/// error of each.
fn mismatches(paths: &[PathBuf], expect_ok: impl Fn(&Path) -> bool) -> Vec<String> {
    let mut wrong = Vec::new();
    for path in paths {
        let bytes = std::fs::read(path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        let parse = parse(&text);
        assert_eq!(
            parse.syntax().to_string(),
            text,
            "{} lost text",
            path.display()
        );
        let ok = parse.errors().is_empty();
        if ok != expect_ok(path) {
            let detail = parse
                .errors()
                .first()
                .map_or("no error".to_owned(), |error| {
                    let line = text[..error.range.start].matches('\n').count() + 1;
                    format!("line {line}: {}", error.message)
                });
            wrong.push(format!("{}: {detail}", path.display()));
        }
    }
    wrong
}

#[test]
fn ironplc_files_are_accepted_or_rejected_as_their_names_say() {
    let paths = files(&corpora().join("ironplc"), "st");
    assert!(paths.len() > 50);
    // A binary file is not source text, whatever its name. var_decl_rendered.st is ironplc's
    // pretty-printer output, which writes the repeated initialiser `[3(2)]` of var_decl.st as
    // `3 2`; that is not IEC 61131-3 syntax, so we reject it (var_decl.st itself is accepted).
    let wrong = mismatches(&paths, |path| {
        let name = path.file_name().unwrap().to_string_lossy();
        !name.contains("syntax_error") && !name.contains("binary") && name != "var_decl_rendered.st"
    });
    assert!(
        wrong.is_empty(),
        "{} of {} files:\n{}",
        wrong.len(),
        paths.len(),
        wrong.join("\n")
    );
}

#[test]
fn matiec_annex_f_st_examples_and_library_files_are_accepted() {
    let mut paths: Vec<PathBuf> = files(&corpora().join("matiec/AnnexF"), "txt")
        .into_iter()
        .filter(|path| path.to_string_lossy().ends_with("_st.txt"))
        .collect();
    paths.extend(files(&corpora().join("matiec/lib"), "txt"));
    // delay_st.txt lacks the ';' after its last declaration, a typo of the standard's Annex F
    // that matiec forgives; IEC 61131-3, CODESYS and ironplc (first_steps_syntax_error.st has
    // the very same mistake) reject it, and so do we.
    let wrong = mismatches(&paths, |path| !path.ends_with("AnnexF/delay_st.txt"));
    assert!(
        wrong.is_empty(),
        "{} of {} files:\n{}",
        wrong.len(),
        paths.len(),
        wrong.join("\n")
    );
}

/// The texts inside `<tag><![CDATA[…]]></tag>` elements of a TwinCAT XML file.
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

#[test]
fn tcunit_declarations_and_bodies_parse_without_syntax_errors() {
    let root = corpora().join("TcUnit");
    let mut paths = files(&root, "TcPOU");
    paths.extend(files(&root, "TcDUT"));
    paths.extend(files(&root, "TcGVL"));
    assert!(paths.len() > 90, "{} TwinCAT files", paths.len());
    let mut wrong = Vec::new();
    let mut parts = 0;
    for path in &paths {
        let xml = std::fs::read_to_string(path).unwrap();
        let declarations = cdata_of(&xml, "Declaration");
        let bodies = cdata_of(&xml, "ST");
        for (text, parse) in declarations
            .iter()
            .map(|text| (text, compiler::syntax::parse_declaration_part(text)))
            .chain(
                bodies
                    .iter()
                    .map(|text| (text, compiler::syntax::parse_statements(text))),
            )
        {
            parts += 1;
            assert_eq!(parse.syntax().to_string(), *text);
            if let Some(error) = parse.errors().first() {
                let line = text[..error.range.start].matches('\n').count() + 1;
                wrong.push(format!(
                    "{} (part line {line}): {}",
                    path.display(),
                    error.message
                ));
            }
        }
    }
    assert!(parts > 500, "only {parts} parts found");
    assert!(
        wrong.is_empty(),
        "{} of {parts} parts:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

/// Checks the concatenation of `files` as one project and returns its errors as
/// `line: CODE message`.
fn check_together(paths: &[PathBuf]) -> Vec<String> {
    let mut text = String::new();
    for path in paths {
        text.push_str(&std::fs::read_to_string(path).unwrap());
        text.push('\n');
    }
    let source = compiler::source_project::SourceProject::new(&text);
    assert!(source.parse.errors().is_empty());
    compiler::sema::check_project(&source.project)
        .into_iter()
        .filter(|found| found.diagnostic.severity == compiler::Severity::Error)
        .map(|found| {
            let line = source
                .locate(&found)
                .map_or(0, |range| text[..range.start].matches('\n').count() + 1);
            format!(
                "{line}: {} {}",
                found.diagnostic.code.id(),
                found.diagnostic.message
            )
        })
        .collect()
}

#[test]
fn matiec_annex_f_examples_and_library_type_check_together() {
    let st_files = |dir: &str, skip: &str| -> Vec<PathBuf> {
        files(&corpora().join(dir), "txt")
            .into_iter()
            .filter(|path| {
                let name = path.file_name().unwrap().to_string_lossy();
                !name.contains("_il") && name != skip
            })
            .collect()
    };
    // delay_st.txt is left out (it does not parse, see above), so the one use of its DELAY
    // function block is the only name the examples miss. The SFC example of the annex draws
    // two charts in one body; Rivet compiles one chart per body (E0117).
    let annex_f = check_together(&st_files("matiec/AnnexF", "delay_st.txt"));
    assert_eq!(
        annex_f
            .iter()
            .map(|error| error.split_once(": ").unwrap().1)
            .collect::<Vec<_>>(),
        [
            "E0102 FIFO: unknown type 'DELAY'",
            "E0117 the chart has its initial step 'START' already; a chart has exactly one"
        ],
        "{annex_f:#?}"
    );
    // ieclib.txt only includes the others.
    let library = check_together(&st_files("matiec/lib", "ieclib.txt"));
    assert!(library.is_empty(), "{library:#?}");
}
