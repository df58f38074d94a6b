//! The ironplc execution cases (`../shared/corpora/ironplc/extracted/e2e_cases.json`) run
//! through `rivet simulate --json` and compared with their expected values, and each case that
//! compiles also run in-process under both engines and compared after every cycle
//! (`runtime::differential::run_both`, `docs/native-engine.md` §11.1).

use std::path::PathBuf;
use std::process::Command;

use serde_json::Value;

/// How Rivet differs on a case whose expectation contradicts IEC 61131-3 or CODESYS.
#[derive(Clone, Copy, Debug)]
enum Difference {
    /// The program is refused with this diagnostic code, as CODESYS refuses it.
    Refused(&'static str),
    /// The program runs and gives another value than the corpus expects.
    Value,
}

/// Cases whose expectation contradicts IEC 61131-3 or CODESYS, with how Rivet differs and the
/// reason; every other case must match.
const DELIBERATE: &[(&str, Difference, &str)] = &[
    (
        "end_to_end_when_byte_not_zero_in_if_then_enters_body",
        Difference::Refused("E0104"),
        "an IF condition must be BOOL (IEC 61131-3 and CODESYS refuse a BYTE)",
    ),
    (
        "end_to_end_when_not_zero_then_one",
        Difference::Value,
        "NOT on a DINT is the bitwise complement, so NOT 0 = -1 as in CODESYS",
    ),
    (
        "end_to_end_when_eq_function_then_returns_bool",
        Difference::Refused("E0104"),
        "a BOOL result does not convert implicitly to DINT",
    ),
    (
        "end_to_end_when_ne_function_then_returns_bool",
        Difference::Refused("E0104"),
        "a BOOL result does not convert implicitly to DINT",
    ),
    (
        "end_to_end_when_or_function_then_returns_bool",
        Difference::Refused("E0104"),
        "a BOOL result does not convert implicitly to DINT",
    ),
];

fn corpus() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/corpora/ironplc/extracted/e2e_cases.json")
}

/// A JSON value as a number: numbers as they are, BOOL as 0/1, times and dates (printed as
/// IEC literals) in the raw units the runtime stores (TIME ms, DATE and DT s, TOD ms).
fn number(value: &Value) -> Option<f64> {
    match value {
        Value::Number(n) => n.as_f64(),
        Value::Bool(b) => Some(f64::from(u8::from(*b))),
        Value::String(text) => {
            let prefix = text.split('#').next()?.to_ascii_uppercase();
            let ns = match prefix.as_str() {
                "T" | "TIME" => compiler::literal::parse_duration(text).ok()? / 1_000_000,
                "LTIME" => compiler::literal::parse_duration(text).ok()?,
                "D" | "DATE" => i128::from(compiler::literal::parse_date(text).ok()?) * 86_400,
                "TOD" | "TIME_OF_DAY" => {
                    compiler::literal::parse_time_of_day(text).ok()? / 1_000_000
                }
                "DT" | "DATE_AND_TIME" => {
                    compiler::literal::parse_date_and_time(text).ok()? / 1_000_000_000
                }
                _ => return None,
            };
            Some(ns as f64)
        }
        _ => None,
    }
}

/// Compiles `source` in-process as `rivet simulate` does with a `.st` file and runs it for
/// `cycles` cycles under the interpreter and the native engine, compared after the load and
/// after every cycle, giving the first [`Difference`](runtime::differential::Difference) the
/// harness found. `None` when the source does not compile: there is nothing to run, and the
/// checks of the command's output judge the case.
fn compare_engines(
    source: &str,
    id: &str,
    cycles: u64,
) -> Option<Result<(), runtime::differential::Difference>> {
    let project = compiler::SourceProject::new(source);
    if !project.parse.errors().is_empty() {
        return None;
    }
    let image = compiler::compile_source(&project, &format!("{id}.st")).ok()?;
    Some(runtime::differential::run_both(image, cycles, |_, _| {}).map(|_| ()))
}

#[test]
fn every_ironplc_execution_case_matches_or_is_a_documented_difference() {
    let text = std::fs::read_to_string(corpus()).expect("the ironplc corpus is beside the project");
    let cases: Vec<Value> = serde_json::from_str(&text).expect("valid JSON");
    assert!(cases.len() > 100, "the corpus holds the cases");
    let dir = tempfile::tempdir().unwrap();
    let mut failures = Vec::new();
    let mut matched = 0;
    // Cases run in-process under both engines and compared cycle by cycle.
    let mut compared = 0;
    for case in &cases {
        let id = case["id"].as_str().unwrap();
        let source = case["source"].as_str().unwrap();
        let program = source
            .split_whitespace()
            .skip_while(|word| !word.eq_ignore_ascii_case("PROGRAM"))
            .nth(1)
            .unwrap_or("main");
        let file = dir.path().join(format!("{id}.st"));
        std::fs::write(&file, source).unwrap();
        let expect = case["expect"].as_array().unwrap();
        let paths: Vec<String> = expect
            .iter()
            .map(|e| format!("{program}.{}", e["var"].as_str().unwrap()))
            .collect();
        let simulate = |engine: &[&str]| {
            Command::new(env!("CARGO_BIN_EXE_rivet"))
                .arg("simulate")
                .arg(&file)
                .args(engine)
                .arg("--cycles")
                .arg(case["scans"].as_u64().unwrap().to_string())
                .arg("--watch")
                .arg(paths.join(","))
                .arg("--json")
                .output()
                .unwrap()
        };
        // The default engine (native where there is a backend) is checked against the
        // expected values; the interpreter must print exactly what it prints, which keeps the
        // interpreter covered without checking every value twice.
        let output = simulate(&[]);
        let interpreted = simulate(&["--engine", "interpreter"]);
        if interpreted.status.code() != output.status.code() || interpreted.stdout != output.stdout
        {
            failures.push(format!(
                "{id}: the interpreter differs from the default engine: {} {:?} against {} {:?}",
                String::from_utf8_lossy(&interpreted.stdout),
                interpreted.status.code(),
                String::from_utf8_lossy(&output.stdout),
                output.status.code()
            ));
        }
        match compare_engines(source, id, case["scans"].as_u64().unwrap()) {
            Some(Ok(())) => compared += 1,
            Some(Err(difference)) => {
                failures.push(format!("{id}: the engines differ: {difference}"));
            }
            None => {}
        }
        let deliberate = DELIBERATE
            .iter()
            .find(|(known, _, _)| *known == id)
            .map(|(_, difference, _)| *difference);
        let outcome: anyhow::Result<()> = (|| {
            if !output.status.success() {
                anyhow::bail!("{}", String::from_utf8_lossy(&output.stderr));
            }
            let values: Value = serde_json::from_slice(&output.stdout)?;
            let tolerance = case["tolerance"]
                .as_str()
                .and_then(|t| t.parse::<f64>().ok())
                .or(case["tolerance"].as_f64())
                .unwrap_or(0.0);
            let kind = case["kind"].as_str().unwrap_or_default();
            for (e, path) in expect.iter().zip(&paths) {
                let expected = e["value_num"]
                    .as_f64()
                    .ok_or_else(|| anyhow::anyhow!("{path}: no expected number"))?;
                let got = number(&values[path])
                    .ok_or_else(|| anyhow::anyhow!("{path} = {}", values[path]))?;
                // The corpus keeps integers in 32- or 64-bit signed slots.
                let got = match kind {
                    "e2e_i32" => f64::from(got as i64 as i32),
                    _ => got,
                };
                if (got - expected).abs() > tolerance {
                    anyhow::bail!("{path} = {got}, expected {expected}");
                }
            }
            Ok(())
        })();
        let stderr = String::from_utf8_lossy(&output.stderr);
        match (outcome, deliberate) {
            (Ok(()), None) => matched += 1,
            (Ok(()), Some(_)) => failures.push(format!(
                "{id}: listed as a deliberate difference but matches"
            )),
            // The exact code, so a case refused for another reason is not taken as the
            // documented difference.
            (Err(_), Some(Difference::Refused(code))) => {
                if output.status.success() || !stderr.contains(&format!("error[{code}]")) {
                    failures.push(format!(
                        "{id}: expected to be refused with {code}: {stderr}"
                    ));
                }
            }
            (Err(message), Some(Difference::Value)) => {
                if !output.status.success() {
                    failures.push(format!(
                        "{id}: expected to run with another value, but: {message}"
                    ));
                }
            }
            (Err(message), None) => failures.push(format!("{id}: {message}")),
        }
    }
    assert!(
        failures.is_empty(),
        "{} case(s) differ:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert_eq!(matched + DELIBERATE.len(), cases.len());
    // Every case that runs (all but those refused) went through the differential harness.
    let refused = DELIBERATE
        .iter()
        .filter(|(_, difference, _)| matches!(difference, Difference::Refused(_)))
        .count();
    assert_eq!(compared + refused, cases.len());
}
