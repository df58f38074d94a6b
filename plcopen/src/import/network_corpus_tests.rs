//! The LD and FBD bodies of the corpora converted into networks.

use project_model::{Body, Object};

use super::{Imported, Outcome, import};
use crate::reader::corpus_tests::read_corpus;

fn import_corpus(relative: &str) -> Imported {
    let document = read_corpus(relative);
    import(&document).unwrap_or_else(|error| panic!("{error}"))
}

#[test]
fn dump() {
    for file in [
        "plcopen/beremiz/exemples/first_steps/plc.xml",
        "plcopen/beremiz/tests/projects/iec61131_lang_test/plc.xml",
        "plcopen/codesys/codesys_code_execution_speedTests.xml",
        "matiec/tests/LD_TEST.xml",
    ] {
        let imported = import_corpus(file);
        for node in &imported.project.application.children {
            if let project_model::Node::Object(Object::Pou(pou)) = node {
                if let Body::Ld { networks } | Body::Fbd { networks } = &pou.body {
                    eprintln!("== {file} {}", pou.name);
                    for n in networks {
                        eprintln!("{n:?}");
                    }
                }
            }
        }
        for entry in imported.report.with_outcome(Outcome::NotConverted) {
            eprintln!("NOT {}: {}", entry.what, entry.note);
        }
    }
}
