//! `ide::parse_declarations` reads back what `declaration_text()` renders, for every POU, method
//! and global variable list of the example project and of the third-party corpora, so switching
//! a declaration between its table and its text never changes it.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::path::Path;

use compiler::SourceProject;
use compiler::ide::{DeclarationKind, parse_declarations};
use project_model::{Object, Project};

mod common;

use common::{corpora, files};

/// Round-trips every declaration part of `project` and returns one line per difference.
fn round_trip_failures(origin: &str, project: &Project) -> (usize, Vec<String>) {
    let mut checked = 0;
    let mut failures = Vec::new();
    let mut check = |name: &str,
                     text: String,
                     variables: &[project_model::Variable],
                     header: Option<(DeclarationKind, Option<&str>)>| {
        checked += 1;
        match parse_declarations(&text) {
            Err(errors) => failures.push(format!("{origin} {name}: {errors:?}\n{text}")),
            Ok(parsed) => {
                if parsed.variables != variables {
                    failures.push(format!(
                        "{origin} {name}: variables differ\n{:#?}\n{:#?}",
                        parsed.variables, variables
                    ));
                }
                let parsed_header = parsed
                    .header
                    .as_ref()
                    .map(|h| (h.kind, h.return_type.as_deref()));
                if parsed_header != header {
                    failures.push(format!(
                        "{origin} {name}: header {parsed_header:?} != {header:?}"
                    ));
                }
                if parsed.header.as_ref().is_some_and(|h| h.name != name) {
                    failures.push(format!("{origin} {name}: name {:?}", parsed.header));
                }
            }
        }
    };
    for object in project.application.objects() {
        match object {
            Object::Pou(pou) => {
                check(
                    &pou.name,
                    pou.declaration_text(),
                    &pou.variables,
                    Some((DeclarationKind::Pou(pou.kind), pou.return_type.as_deref())),
                );
                for method in &pou.methods {
                    check(
                        &method.name,
                        method.declaration_text(),
                        &method.variables,
                        Some((DeclarationKind::Method, method.return_type.as_deref())),
                    );
                }
            }
            Object::Gvl(gvl) => check(&gvl.name, gvl.declaration_text(), &gvl.variables, None),
            _ => {}
        }
    }
    (checked, failures)
}

#[test]
fn the_example_project_round_trips_through_its_declaration_text() {
    let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
    let (checked, failures) = round_trip_failures("example", &loaded.project);
    assert!(checked >= 6, "only {checked} declaration parts");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    // The comments hold Chinese text; they must come back as they were.
    let Some(Object::Gvl(io)) = loaded.project.application.object("GVL_IO") else {
        panic!("the example has GVL_IO");
    };
    let parsed = parse_declarations(&io.declaration_text()).unwrap();
    assert_eq!(parsed.comment, io.comment);
    assert_eq!(parsed.variables[0].comment, "启动按钮 (start button)");
}

#[test]
fn the_corpora_round_trip_through_their_declaration_text() {
    let corpora = corpora();
    let mut paths = files(&corpora.join("ironplc"), "st");
    paths.extend(files(&corpora.join("matiec/AnnexF"), "txt"));
    paths.extend(files(&corpora.join("matiec/lib"), "txt"));
    let mut checked = 0;
    let mut failures = Vec::new();
    for path in &paths {
        let text = String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned();
        let source = SourceProject::new(&text);
        // Files the parser rejects do not load into a project; those are the parser's tests.
        if !source.parse.errors().is_empty() {
            continue;
        }
        let (count, found) = round_trip_failures(&path.display().to_string(), &source.project);
        checked += count;
        failures.extend(found);
    }
    assert!(checked > 100, "only {checked} declaration parts");
    assert!(
        failures.is_empty(),
        "{} of {checked} differ:\n{}",
        failures.len(),
        failures.join("\n\n")
    );
}

/// The texts inside `<Declaration><![CDATA[…]]></Declaration>` elements of a TwinCAT XML file.
fn declarations_of(xml: &str) -> Vec<String> {
    let open = "<Declaration><![CDATA[";
    let mut found = Vec::new();
    let mut rest = xml;
    while let Some(start) = rest.find(open) {
        let after = &rest[start + open.len()..];
        let Some(end) = after.find("]]>") else { break };
        found.push(after[..end].to_owned());
        rest = &after[end..];
    }
    found
}

/// The first word of `text` that is not in a comment.
fn first_word(text: &str) -> &str {
    let mut rest = text.trim_start();
    loop {
        if let Some(after) = rest.strip_prefix("//") {
            rest = after
                .split_once('\n')
                .map_or("", |(_, next)| next)
                .trim_start();
        } else if let Some(after) = rest.strip_prefix("(*") {
            rest = after
                .split_once("*)")
                .map_or("", |(_, next)| next)
                .trim_start();
        } else {
            return rest.split_whitespace().next().unwrap_or_default();
        }
    }
}

#[test]
fn tcunit_declaration_parts_read_into_variables_that_render_and_read_back_the_same() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared/corpora/TcUnit");
    let mut paths = files(&root, "TcPOU");
    paths.extend(files(&root, "TcGVL"));
    let mut checked = 0;
    let mut with_comments = 0;
    let mut failures = Vec::new();
    for path in &paths {
        let xml = std::fs::read_to_string(path).unwrap();
        for text in declarations_of(&xml) {
            // Properties are objects of their own, refused by design.
            if first_word(&text) == "PROPERTY" {
                continue;
            }
            let parsed = match parse_declarations(&text) {
                Ok(parsed) => parsed,
                Err(errors) => {
                    failures.push(format!("{}: {errors:?}", path.display()));
                    continue;
                }
            };
            checked += 1;
            with_comments += parsed
                .variables
                .iter()
                .filter(|variable| !variable.comment.is_empty())
                .count();
            let list = project_model::GlobalVarList {
                name: "L".to_owned(),
                comment: String::new(),
                variables: parsed.variables.clone(),
            };
            match parse_declarations(&list.declaration_text()) {
                Ok(again) if again.variables == parsed.variables => {}
                other => failures.push(format!("{}: {other:?}", path.display())),
            }
        }
    }
    assert!(checked > 200, "only {checked} declaration parts");
    assert!(
        with_comments > 100,
        "only {with_comments} commented variables"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
