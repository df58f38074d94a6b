//! Fewer points for the plot than the trace holds, without losing a spike.
//!
//! A trace of 32 variables over 10,000 cycles has far more points than the plot has pixel
//! columns; drawing them all makes every frame slow. Keeping each column's minimum and maximum
//! draws the same picture: the line in a column goes from its lowest to its highest value either
//! way.

use std::hash::{DefaultHasher, Hash, Hasher};
use std::ops::RangeInclusive;

use super::data::TraceData;

/// The points of `xs`/`ys` to draw when `x_range` spans `columns` pixel columns.
///
/// `xs` must be sorted. Every point is kept when there are no more than two per column;
/// otherwise each column keeps its minimum and maximum, in the order they were recorded. The
/// nearest point outside the range on each side is kept too, so the line runs to the plot's
/// edges. The result has at most `2 * columns + 2` points.
pub fn decimate(
    xs: &[f64],
    ys: &[f64],
    x_range: RangeInclusive<f64>,
    columns: usize,
) -> Vec<[f64; 2]> {
    let count = xs.len().min(ys.len());
    let (xs, ys) = (&xs[..count], &ys[..count]);
    let (lo, hi) = (*x_range.start(), *x_range.end());
    // The visible points plus one neighbour each side.
    let start = xs.partition_point(|&x| x < lo).saturating_sub(1);
    let end = (xs.partition_point(|&x| x <= hi) + 1).min(count);
    if start >= end {
        return Vec::new();
    }
    let columns = columns.max(1);
    let point = |index: usize| [xs[index], ys[index]];
    if end - start <= 2 * columns + 2 || hi <= lo {
        return (start..end).map(point).collect();
    }
    let mut out = Vec::with_capacity(2 * columns + 2);
    let column_width = (hi - lo) / columns as f64;
    let column_of = |x: f64| -> usize {
        // Points just outside the range were kept as neighbours; the float cast saturates.
        (((x - lo) / column_width) as usize).min(columns - 1)
    };
    let mut index = start;
    if xs[index] < lo {
        out.push(point(index));
        index += 1;
    }
    let last_inside = if xs[end - 1] > hi { end - 1 } else { end };
    while index < last_inside {
        let column = column_of(xs[index]);
        let (mut min_index, mut max_index) = (index, index);
        index += 1;
        while index < last_inside && column_of(xs[index]) == column {
            // NaN values compare false both ways and so never become a minimum or a maximum.
            if ys[index] < ys[min_index] {
                min_index = index;
            }
            if ys[index] > ys[max_index] {
                max_index = index;
            }
            index += 1;
        }
        let (first, second) = (min_index.min(max_index), min_index.max(max_index));
        out.push(point(first));
        if second != first {
            out.push(point(second));
        }
    }
    if last_inside < end {
        out.push(point(last_inside));
    }
    out
}

/// What the decimated points were computed for: the same data, range and width give the same
/// points, so they are reused from one frame to the next.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct DecimationKey {
    /// Identifies the trace (see [`fingerprint`]).
    pub data: u64,
    /// The x range the points cover, in milliseconds.
    pub x_lo: f64,
    /// The end of that range.
    pub x_hi: f64,
    /// The pixel columns across that range.
    pub columns: usize,
}

/// The decimated points of every series for one [`DecimationKey`].
#[derive(Default)]
pub(super) struct DecimationCache {
    /// What `series` was computed for; `None` before the first computation.
    key: Option<DecimationKey>,
    /// One list of points per series, BOOL series already as steps.
    series: Vec<Vec<[f64; 2]>>,
}

impl DecimationCache {
    /// The points of every series for `key`, computed again only when the key changed; `times_ms`
    /// are the data's relative sample times ([`TraceData::times_ms`]).
    pub fn series(
        &mut self,
        data: &TraceData,
        times_ms: &[f64],
        key: DecimationKey,
    ) -> &[Vec<[f64; 2]>] {
        if self.key != Some(key) {
            let mut values = vec![0.0; data.samples.len()];
            self.series = (0..data.variables.len())
                .map(|series| {
                    for (value, sample) in values.iter_mut().zip(&data.samples) {
                        *value = sample.values.get(series).copied().unwrap_or(f64::NAN);
                    }
                    let points = decimate(times_ms, &values, key.x_lo..=key.x_hi, key.columns);
                    if data.variables[series].is_bool {
                        steps(&points)
                    } else {
                        points
                    }
                })
                .collect();
            self.key = Some(key);
        }
        &self.series
    }

    /// Forgets the points, so the next frame computes them again.
    pub fn clear(&mut self) {
        self.key = None;
    }
}

/// A held signal as steps: each value lasts until the next sample's time.
fn steps(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(points.len() * 2);
    for (index, &[x, y]) in points.iter().enumerate() {
        if let Some(&[_, previous_y]) = index.checked_sub(1).and_then(|i| points.get(i)) {
            out.push([x, previous_y]);
        }
        out.push([x, y]);
    }
    out
}

/// A cheap identity of a trace: its shape, first and last times, paths, and the values of up to
/// 64 evenly spread samples. A new upload differs in at least one of them in practice, and the
/// cost does not grow with the trace.
pub(super) fn fingerprint(data: &TraceData) -> u64 {
    let mut hasher = DefaultHasher::new();
    data.samples.len().hash(&mut hasher);
    data.trigger_sample.hash(&mut hasher);
    for series in &data.variables {
        series.path.hash(&mut hasher);
        series.is_bool.hash(&mut hasher);
    }
    let step = (data.samples.len() / 64).max(1);
    let probes = data.samples.iter().step_by(step).chain(data.samples.last());
    for sample in probes {
        sample.time_ns.hash(&mut hasher);
        sample.cycle.hash(&mut hasher);
        for value in &sample.values {
            value.to_bits().hash(&mut hasher);
        }
    }
    hasher.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A noisy signal with one spike up and one down, 10,000 samples over 0–10 ms, each in the
    /// middle of its microsecond so none lies on a column boundary.
    fn spiky() -> (Vec<f64>, Vec<f64>) {
        let xs: Vec<f64> = (0..10_000).map(|i| (f64::from(i) + 0.5) / 1000.0).collect();
        let ys = (0..10_000)
            .map(|i| match i {
                4321 => 100.0,
                7777 => -100.0,
                _ => f64::from(i % 7),
            })
            .collect();
        (xs, ys)
    }

    #[test]
    fn every_column_keeps_its_minimum_and_maximum() {
        let (xs, ys) = spiky();
        let columns = 100;
        let points = decimate(&xs, &ys, 0.0..=10.0, columns);
        assert!(points.len() <= 2 * columns + 2, "{} points", points.len());
        assert!(points.contains(&[xs[4321], 100.0]));
        assert!(points.contains(&[xs[7777], -100.0]));
        // Each column of 100 samples holds the values 0 to 6 (and a spike in two columns).
        for column in 0..columns {
            let lo = column as f64 / 10.0;
            let in_column: Vec<f64> = points
                .iter()
                .filter(|[x, _]| *x > lo && *x < lo + 0.1)
                .map(|[_, y]| *y)
                .collect();
            let min = in_column.iter().copied().fold(f64::INFINITY, f64::min);
            let max = in_column.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let expected_min = if column == 77 { -100.0 } else { 0.0 };
            let expected_max = if column == 43 { 100.0 } else { 6.0 };
            assert_eq!((min, max), (expected_min, expected_max), "column {column}");
        }
    }

    #[test]
    fn a_zoomed_range_keeps_one_neighbour_each_side_and_stays_bounded() {
        let (xs, ys) = spiky();
        let points = decimate(&xs, &ys, 2.001..=2.011, 3);
        assert_eq!(points.first(), Some(&[xs[2000], ys[2000]]));
        assert_eq!(points.last(), Some(&[xs[2011], ys[2011]]));
        assert!(points.len() <= 8, "{} points", points.len());
    }

    #[test]
    fn few_points_are_kept_as_they_are() {
        let xs = [0.0, 1.0, 2.0, 3.0];
        let ys = [5.0, 6.0, 7.0, 8.0];
        let points = decimate(&xs, &ys, 0.0..=3.0, 800);
        assert_eq!(points, vec![[0.0, 5.0], [1.0, 6.0], [2.0, 7.0], [3.0, 8.0]]);
    }

    #[test]
    fn a_range_beside_the_data_keeps_only_the_nearest_point() {
        let xs = [0.0, 1.0];
        let ys = [5.0, 6.0];
        assert_eq!(decimate(&xs, &ys, 5.0..=6.0, 10), vec![[1.0, 6.0]]);
        assert_eq!(decimate(&[], &[], 0.0..=1.0, 10), Vec::<[f64; 2]>::new());
    }

    #[test]
    fn bool_steps_hold_the_previous_value_until_the_next_sample() {
        let points = steps(&[[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]);
        assert_eq!(
            points,
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [2.0, 0.0]]
        );
    }
}
