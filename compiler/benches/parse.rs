//! Parse speed: `cargo bench -p compiler --bench parse`.
//!
//! Generates a 50,000-line source of functions and function blocks (arrays, timers, CASE,
//! loops), and a single POU of 50,000 statements, and prints the median parse time of each and
//! the peak resident memory of the process.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use compiler::syntax::{parse, parse_statements};

mod generate;

use generate::{body_statements, median, peak_memory_mb, project_source};

fn main() {
    let (source, index) = project_source(50_000);
    let lines = source.lines().count();
    let check = parse(&source);
    assert!(check.errors().is_empty(), "{:?}", &check.errors()[..1]);
    drop(check);
    let project = median(7, || {
        std::hint::black_box(parse(&source));
    });

    for count in [25_000, 100_000] {
        let statements = body_statements(count);
        let time = median(7, || {
            std::hint::black_box(parse_statements(&statements));
        });
        println!(
            "parse: one body of {count} statements: {:.1} ms",
            time.as_secs_f64() * 1000.0
        );
    }
    let statements = body_statements(50_000);
    let single = median(7, || {
        std::hint::black_box(parse_statements(&statements));
    });

    println!(
        "parse: {lines} lines in {} POUs: {:.1} ms",
        index * 2,
        project.as_secs_f64() * 1000.0
    );
    println!(
        "parse: one body of 50,000 statements: {:.1} ms",
        single.as_secs_f64() * 1000.0
    );
    println!("parse: peak resident memory {}", peak_memory_mb());
}
