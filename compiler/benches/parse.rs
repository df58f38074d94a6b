//! Parse speed: `cargo bench -p compiler --bench parse`.
//!
//! Generates a 50,000-line source of functions and function blocks (arrays, timers, CASE,
//! loops), and a single POU of 50,000 statements, and prints the median parse time of each and
//! the peak resident memory of the process.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::print_stdout)] // A bench binary.

use std::fmt::Write as _;
use std::time::{Duration, Instant};

use compiler::syntax::{parse, parse_statements};

/// A function block of 50 lines using arrays, a timer, CASE and loops.
fn function_block(index: usize, out: &mut String) {
    writeln!(
        out,
        "FUNCTION_BLOCK FB_Station{index}
VAR_INPUT
    xEnable : BOOL;
    iMode : INT;
END_VAR
VAR_OUTPUT
    xDone : BOOL;
    rSum : REAL;
END_VAR
VAR
    aValues : ARRAY[1..10] OF REAL := [10(0.0)];
    tonDelay : TON;
    i : INT;
    iState : INT;
END_VAR
tonDelay(IN := xEnable, PT := T#500MS);
CASE iState OF
    0:
        IF tonDelay.Q THEN
            iState := 1;
        END_IF
    1, 2:
        rSum := 0.0;
        FOR i := 1 TO 10 DO
            rSum := rSum + aValues[i] * INT_TO_REAL(iMode);
        END_FOR
        iState := 3;
    3..5:
        WHILE i > 0 DO
            i := i - 1;
            aValues[i + 1] := aValues[i + 1] / 2.0;
        END_WHILE
        iState := 10;
ELSE
    xDone := TRUE;
    iState := 0;
END_CASE
REPEAT
    i := i + 1;
UNTIL i >= 10
END_REPEAT
END_FUNCTION_BLOCK
"
    )
    .ok();
}

/// A function of 10 lines.
fn function(index: usize, out: &mut String) {
    writeln!(
        out,
        "FUNCTION F_Scale{index} : REAL
VAR_INPUT
    iRaw : INT;
    rLow, rHigh : REAL;
END_VAR
F_Scale{index} := rLow + (rHigh - rLow) * INT_TO_REAL(iRaw) / 27648.0;
IF F_Scale{index} > rHigh THEN
    F_Scale{index} := rHigh;
END_IF
END_FUNCTION
"
    )
    .ok();
}

fn median(runs: usize, mut run: impl FnMut()) -> Duration {
    let mut samples: Vec<Duration> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            run();
            start.elapsed()
        })
        .collect();
    samples.sort();
    samples[samples.len() / 2]
}

fn peak_memory_mb() -> String {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|status| {
            status
                .lines()
                .find(|line| line.starts_with("VmHWM:"))
                .map(|line| line.trim_start_matches("VmHWM:").trim().to_owned())
        })
        .unwrap_or_else(|| "unknown".into())
}

fn main() {
    let lines_per_pair = {
        let mut pair = String::new();
        function_block(0, &mut pair);
        function(0, &mut pair);
        pair.lines().count()
    };
    let mut source = String::new();
    let mut index = 0;
    while index * lines_per_pair < 50_000 {
        function_block(index, &mut source);
        function(index, &mut source);
        index += 1;
    }
    let lines = source.lines().count();
    let check = parse(&source);
    assert!(check.errors().is_empty(), "{:?}", &check.errors()[..1]);
    drop(check);
    let project = median(7, || {
        std::hint::black_box(parse(&source));
    });

    for count in [25_000, 100_000] {
        let mut statements = String::new();
        for i in 0..count {
            writeln!(
                statements,
                "aValues[{}] := aValues[{}] + {i} * rGain;",
                i % 10,
                (i + 1) % 10
            )
            .ok();
        }
        let time = median(7, || {
            std::hint::black_box(parse_statements(&statements));
        });
        println!(
            "parse: one body of {count} statements: {:.1} ms",
            time.as_secs_f64() * 1000.0
        );
    }
    let mut statements = String::new();
    for i in 0..50_000 {
        writeln!(
            statements,
            "aValues[{}] := aValues[{}] + {i} * rGain;",
            i % 10,
            (i + 1) % 10
        )
        .ok();
    }
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
