//! The recorded trace as plain data, and the questions the view asks of it: times relative to
//! the trigger, the value of a series at a cursor, the colour of a series.

use egui::Color32;

use crate::studio::theme::TRACE_SERIES;

/// One uploaded trace: the recorded variables and their samples, in recording order.
///
/// It lives as long as the app keeps the last upload and is not saved with the project (the
/// configuration is; the samples are exported as CSV on request).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TraceData {
    /// The recorded variables, in the order of each sample's `values`.
    pub variables: Vec<TraceSeries>,
    /// The samples in increasing time.
    pub samples: Vec<TraceSample>,
    /// The index in `samples` of the sample where the trigger fired, if it fired.
    pub trigger_sample: Option<usize>,
    /// The sampling task's cycle time, when it is cyclic; shown beside the plot.
    pub cycle_time_ns: Option<u64>,
}

/// One recorded variable.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceSeries {
    /// The variable's path as the user wrote it in the trace configuration (`PLC_PRG.speed`).
    pub path: String,
    /// The colour configured in the project (parsed with [`parse_color`]); `None` takes the next
    /// colour of the palette.
    pub color: Option<Color32>,
    /// Whether the variable is a BOOL, drawn as steps between 0 and 1.
    pub is_bool: bool,
}

/// The values of every variable in one task cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceSample {
    /// The task's cycle counter when the sample was taken.
    pub cycle: u64,
    /// The task clock when the sample was taken, in nanoseconds.
    pub time_ns: u64,
    /// One value per series of [`TraceData::variables`]; a BOOL is 0 or 1.
    pub values: Vec<f64>,
}

/// The values of every series at the two cursors, as the table under the plot shows them.
#[derive(Clone, Debug, PartialEq)]
pub struct CursorReadings {
    /// One row per series, in the order of [`TraceData::variables`].
    pub rows: Vec<CursorReading>,
    /// Cursor B's time minus cursor A's, in milliseconds, when both are placed.
    pub delta_t_ms: Option<f64>,
}

/// One series' values at the two cursors.
#[derive(Clone, Debug, PartialEq)]
pub struct CursorReading {
    /// The series' path.
    pub path: String,
    /// The value at cursor A, when it is placed on or after the first sample.
    pub at_a: Option<f64>,
    /// The value at cursor B, when it is placed on or after the first sample.
    pub at_b: Option<f64>,
    /// The value at B minus the value at A, when both exist.
    pub difference: Option<f64>,
}

/// Parses a project colour written `#rrggbb` (either case); anything else is `None`, so the
/// caller falls back to the palette rather than refusing the trace.
pub fn parse_color(text: &str) -> Option<Color32> {
    let hex = text.trim().strip_prefix('#')?;
    if hex.len() != 6 || !hex.bytes().all(|byte| byte.is_ascii_hexdigit()) {
        return None;
    }
    let channel = |index: usize| u8::from_str_radix(&hex[index..index + 2], 16).ok();
    Some(Color32::from_rgb(channel(0)?, channel(2)?, channel(4)?))
}

impl TraceData {
    /// The time every other time is relative to: the trigger sample's, else the first sample's.
    pub fn origin_ns(&self) -> Option<u64> {
        self.trigger_sample
            .and_then(|index| self.samples.get(index))
            .or_else(|| self.samples.first())
            .map(|sample| sample.time_ns)
    }

    /// Each sample's time relative to [`Self::origin_ns`], in milliseconds (the plot's x axis).
    pub fn times_ms(&self) -> Vec<f64> {
        let origin = self.origin_ns().unwrap_or(0);
        self.samples
            .iter()
            .map(|sample| relative_ns(sample.time_ns, origin) as f64 / 1e6)
            .collect()
    }

    /// The colour series `index` is drawn in: its own, else the palette's.
    pub fn series_color(&self, index: usize) -> Color32 {
        self.variables
            .get(index)
            .and_then(|series| series.color)
            .unwrap_or(TRACE_SERIES[index % TRACE_SERIES.len()])
    }

    /// The value of series `series` at `time_ms` (relative, as on the plot): the last sample at
    /// or before that time, because a PLC variable holds its value between two task cycles.
    /// Before the first sample there is no value.
    pub fn value_at(&self, times_ms: &[f64], series: usize, time_ms: f64) -> Option<f64> {
        let after = times_ms.partition_point(|&time| time <= time_ms);
        let index = after.checked_sub(1)?;
        self.samples.get(index)?.values.get(series).copied()
    }

    /// The values of every series at cursors A and B and their differences.
    pub fn cursor_readings(&self, a_ms: Option<f64>, b_ms: Option<f64>) -> CursorReadings {
        let times = self.times_ms();
        let rows = self
            .variables
            .iter()
            .enumerate()
            .map(|(index, series)| {
                let at_a = a_ms.and_then(|time| self.value_at(&times, index, time));
                let at_b = b_ms.and_then(|time| self.value_at(&times, index, time));
                let difference = at_a.zip(at_b).map(|(a, b)| b - a);
                CursorReading {
                    path: series.path.clone(),
                    at_a,
                    at_b,
                    difference,
                }
            })
            .collect();
        CursorReadings {
            rows,
            delta_t_ms: a_ms.zip(b_ms).map(|(a, b)| b - a),
        }
    }
}

/// The time of the sample nearest to `time_ms`, so a cursor sits on a recorded sample and the
/// table shows recorded values rather than a point between two cycles.
pub fn nearest_sample_time(times_ms: &[f64], time_ms: f64) -> Option<f64> {
    let after = times_ms.partition_point(|&time| time < time_ms);
    let candidates = [after.checked_sub(1), Some(after)];
    candidates
        .into_iter()
        .flatten()
        .filter_map(|index| times_ms.get(index).copied())
        .min_by(|a, b| (a - time_ms).abs().total_cmp(&(b - time_ms).abs()))
}

/// `time_ns - origin_ns` as a signed count, exact for any two task clock readings.
pub(super) fn relative_ns(time_ns: u64, origin_ns: u64) -> i128 {
    i128::from(time_ns) - i128::from(origin_ns)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(cycle: u64, time_ns: u64, values: &[f64]) -> TraceSample {
        TraceSample {
            cycle,
            time_ns,
            values: values.to_vec(),
        }
    }

    fn two_series() -> TraceData {
        TraceData {
            variables: vec![
                TraceSeries {
                    path: "PLC_PRG.speed".into(),
                    color: None,
                    is_bool: false,
                },
                TraceSeries {
                    path: "PLC_PRG.run".into(),
                    color: None,
                    is_bool: true,
                },
            ],
            samples: vec![
                sample(10, 1_000_000, &[1.5, 0.0]),
                sample(11, 2_000_000, &[2.5, 1.0]),
                sample(12, 3_000_000, &[4.0, 1.0]),
                sample(13, 4_000_000, &[-1.0, 0.0]),
            ],
            trigger_sample: Some(1),
            cycle_time_ns: Some(1_000_000),
        }
    }

    #[test]
    fn colours_parse_from_hash_rrggbb_only() {
        assert_eq!(parse_color("#ff8000"), Some(Color32::from_rgb(255, 128, 0)));
        assert_eq!(
            parse_color("#A0b0C0"),
            Some(Color32::from_rgb(0xa0, 0xb0, 0xc0))
        );
        assert_eq!(parse_color("ff8000"), None);
        assert_eq!(parse_color("#ff80"), None);
        assert_eq!(parse_color("#ff800g"), None);
        assert_eq!(parse_color("#ﬀ8000"), None);
        assert_eq!(parse_color(""), None);
    }

    #[test]
    fn times_are_relative_to_the_trigger_sample() {
        assert_eq!(two_series().times_ms(), vec![-1.0, 0.0, 1.0, 2.0]);
    }

    #[test]
    fn cursor_readings_hold_the_last_sample_and_subtract_a_from_b() {
        let readings = two_series().cursor_readings(Some(0.5), Some(2.0));
        assert_eq!(readings.delta_t_ms, Some(1.5));
        assert_eq!(
            readings.rows[0],
            CursorReading {
                path: "PLC_PRG.speed".into(),
                at_a: Some(2.5),
                at_b: Some(-1.0),
                difference: Some(-3.5),
            }
        );
        assert_eq!(readings.rows[1].at_a, Some(1.0));
        assert_eq!(readings.rows[1].difference, Some(-1.0));
    }

    #[test]
    fn a_cursor_before_the_first_sample_reads_nothing() {
        let readings = two_series().cursor_readings(Some(-5.0), None);
        assert_eq!(readings.rows[0].at_a, None);
        assert_eq!(readings.rows[0].difference, None);
        assert_eq!(readings.delta_t_ms, None);
    }

    #[test]
    fn cursors_snap_to_the_nearest_sample() {
        let times = [-1.0, 0.0, 1.0, 2.0];
        assert_eq!(nearest_sample_time(&times, 0.4), Some(0.0));
        assert_eq!(nearest_sample_time(&times, 0.6), Some(1.0));
        assert_eq!(nearest_sample_time(&times, -9.0), Some(-1.0));
        assert_eq!(nearest_sample_time(&times, 9.0), Some(2.0));
        assert_eq!(nearest_sample_time(&[], 1.0), None);
    }
}
