//! Parse and check speed: `cargo bench -p compiler --bench check`.
//!
//! Builds a project from a generated 50,000-line source (functions and function blocks with
//! arrays, timers, CASE and loops) and checks it whole; re-checks one function block of it, as
//! the editor does after an edit; and checks one program of 50,000 statements. Prints the
//! median times and the peak resident memory of the process.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use compiler::sema::{check_pou, check_project};
use compiler::source_project::SourceProject;

mod generate;

use generate::{body_statements, median, peak_memory_mb, project_source};

fn main() {
    let (source, pairs) = project_source(50_000);
    let lines = source.lines().count();
    let built = SourceProject::new(&source);
    let errors: Vec<_> = check_project(&built.project)
        .into_iter()
        .filter(|found| found.diagnostic.severity == compiler::Severity::Error)
        .collect();
    assert!(errors.is_empty(), "{:?}", &errors[..1]);
    drop(built);
    let whole = median(5, || {
        let built = SourceProject::new(&source);
        std::hint::black_box(check_project(&built.project));
    });
    let built = SourceProject::new(&source);
    let one = median(11, || {
        std::hint::black_box(check_pou(&built.project, "FB_Station500"));
    });
    drop(built);

    // The same source as a project whose bodies are already text, as a loaded project folder
    // is: one parse per body, then the check.
    let built = SourceProject::new(&source);
    let project_check = median(5, || {
        std::hint::black_box(check_project(&built.project));
    });
    drop(built);

    let mut times = Vec::new();
    for count in [25_000, 50_000, 100_000] {
        let program = format!(
            "PROGRAM Long\nVAR\n    aValues : ARRAY[0..9] OF REAL;\n    rGain : REAL := 1.5;\nEND_VAR\n{}END_PROGRAM\n",
            body_statements(count)
        );
        let time = median(5, || {
            let built = SourceProject::new(&program);
            std::hint::black_box(check_project(&built.project));
        });
        times.push((count, time));
    }

    println!(
        "check: parse + check of {lines} lines in {} POUs: {:.1} ms",
        pairs * 2,
        whole.as_secs_f64() * 1000.0
    );
    println!(
        "check: the same as a loaded project (bodies parsed and checked): {:.1} ms",
        project_check.as_secs_f64() * 1000.0
    );
    println!(
        "check: re-check of one function block in that project: {:.2} ms",
        one.as_secs_f64() * 1000.0
    );
    for (count, time) in times {
        println!(
            "check: parse + check of one program of {count} statements: {:.1} ms",
            time.as_secs_f64() * 1000.0
        );
    }
    println!("check: peak resident memory {}", peak_memory_mb());
}
