//! The trace as CSV text, for spreadsheets and other tools.

use std::fmt::Write as _;

use super::data::{TraceData, relative_ns};

impl TraceData {
    /// The trace as CSV: a header `time_ms,cycle,<path>...`, then one row per sample.
    ///
    /// Times are relative to the trigger sample when the trigger fired, else to the first sample,
    /// and are printed exactly from the nanosecond clock; values are printed in the shortest form
    /// that reads back as the same `f64`. Lines end in `\n`.
    pub fn to_csv(&self) -> String {
        let mut text = String::from("time_ms,cycle");
        for series in &self.variables {
            text.push(',');
            text.push_str(&csv_field(&series.path));
        }
        text.push('\n');
        let origin = self.origin_ns().unwrap_or(0);
        for sample in &self.samples {
            text.push_str(&exact_ms(relative_ns(sample.time_ns, origin)));
            // Writing into a String cannot fail, so the results carry nothing to handle.
            let _ = write!(text, ",{}", sample.cycle);
            for index in 0..self.variables.len() {
                match sample.values.get(index) {
                    Some(value) => {
                        let _ = write!(text, ",{value}");
                    }
                    // A sample shorter than the variable list leaves the cell empty rather than
                    // shifting the columns.
                    None => text.push(','),
                }
            }
            text.push('\n');
        }
        text
    }
}

/// A nanosecond count as milliseconds in decimal, without the rounding of a float.
fn exact_ms(ns: i128) -> String {
    let sign = if ns < 0 { "-" } else { "" };
    let magnitude = ns.unsigned_abs();
    let whole = magnitude / 1_000_000;
    let fraction = magnitude % 1_000_000;
    if fraction == 0 {
        format!("{sign}{whole}")
    } else {
        let digits = format!("{fraction:06}");
        format!("{sign}{whole}.{}", digits.trim_end_matches('0'))
    }
}

/// A field quoted as RFC 4180 asks when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::super::data::{TraceSample, TraceSeries};
    use super::*;

    fn data(trigger_sample: Option<usize>) -> TraceData {
        TraceData {
            variables: vec![
                TraceSeries {
                    path: "PLC_PRG.speed".into(),
                    color: None,
                    is_bool: false,
                },
                TraceSeries {
                    path: "GVL.\"odd,name\"".into(),
                    color: None,
                    is_bool: true,
                },
            ],
            samples: vec![
                TraceSample {
                    cycle: 41,
                    time_ns: 10_000_000,
                    values: vec![0.1, 0.0],
                },
                TraceSample {
                    cycle: 42,
                    time_ns: 11_500_250,
                    values: vec![-2.0, 1.0],
                },
                TraceSample {
                    cycle: 43,
                    time_ns: 13_000_000,
                    values: vec![1e-7, 1.0],
                },
            ],
            trigger_sample,
            cycle_time_ns: None,
        }
    }

    #[test]
    fn csv_without_trigger_is_relative_to_the_first_sample() {
        assert_eq!(
            data(None).to_csv(),
            "time_ms,cycle,PLC_PRG.speed,\"GVL.\"\"odd,name\"\"\"\n\
             0,41,0.1,0\n\
             1.50025,42,-2,1\n\
             3,43,0.0000001,1\n"
        );
    }

    #[test]
    fn csv_with_trigger_is_relative_to_the_trigger_sample() {
        assert_eq!(
            data(Some(1)).to_csv(),
            "time_ms,cycle,PLC_PRG.speed,\"GVL.\"\"odd,name\"\"\"\n\
             -1.50025,41,0.1,0\n\
             0,42,-2,1\n\
             1.49975,43,0.0000001,1\n"
        );
    }

    #[test]
    fn csv_values_read_back_as_the_same_numbers() {
        let value = 0.1 + 0.2;
        let mut trace = data(None);
        trace.samples[0].values[0] = value;
        let csv = trace.to_csv();
        let cell = csv.lines().nth(1).and_then(|line| line.split(',').nth(2));
        assert_eq!(cell.map(str::parse::<f64>), Some(Ok(value)));
    }

    #[test]
    fn an_empty_trace_is_only_the_header() {
        assert_eq!(TraceData::default().to_csv(), "time_ms,cycle\n");
    }
}
