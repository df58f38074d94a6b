//! Generated sources for the benches: a project of functions and function blocks (arrays,
//! timers, CASE, loops) and long statement lists.

#![allow(dead_code)] // Each bench uses a part.

use std::fmt::Write as _;
use std::time::{Duration, Instant};

/// A function block of 50 lines using arrays, a timer, CASE and loops.
pub fn function_block(index: usize, out: &mut String) {
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
pub fn function(index: usize, out: &mut String) {
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

/// The median wall time of `runs` runs.
pub fn median(runs: usize, mut run: impl FnMut()) -> Duration {
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

/// The peak resident memory of this process, as the kernel reports it.
pub fn peak_memory_mb() -> String {
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

/// Whole POUs, a function block and a function at a time, until `lines` lines are reached;
/// with the number of pairs.
pub fn project_source(lines: usize) -> (String, usize) {
    let lines_per_pair = {
        let mut pair = String::new();
        function_block(0, &mut pair);
        function(0, &mut pair);
        pair.lines().count()
    };
    let mut source = String::new();
    let mut index = 0;
    while index * lines_per_pair < lines {
        function_block(index, &mut source);
        function(index, &mut source);
        index += 1;
    }
    (source, index)
}

/// `count` assignment statements over an array of ten REALs and a gain.
pub fn body_statements(count: usize) -> String {
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
    statements
}
