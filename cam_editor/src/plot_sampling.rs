//! Sampling a cam for plots at the plot's resolution: at most a few points per pixel column,
//! whatever the number of key points, with the key points exact where they are sparse and the
//! extremes of every column kept where they are dense.

use motion::curve::{CamCurve, CamSample};

/// The polylines of the four plots, as `[master, value]` points in master order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PlotSamples {
    /// Slave position.
    pub position: Vec<[f64; 2]>,
    /// dY/dX.
    pub velocity: Vec<[f64; 2]>,
    /// d²Y/dX².
    pub acceleration: Vec<[f64; 2]>,
    /// d³Y/dX³.
    pub jerk: Vec<[f64; 2]>,
}

/// How many candidate samples a column may hold before only its first, lowest, highest and
/// last are kept.
const KEEP_ALL_UP_TO: usize = 4;

/// Samples `curve` over `view` (clamped to its master range) for a plot `columns` pixels wide.
///
/// Each column is sampled at its start, its middle when it holds no key point, and both sides
/// of every key point in it (the key point itself exactly, its left side a billionth of the
/// range before) (`key_masters`, ascending), so jumps of the derivatives show as
/// vertical steps. A column with more than four candidates keeps its first, lowest, highest and
/// last, which draws the same pixels as all of them; so a 10,000-point cam on an 800-pixel plot
/// is at most 3,200 points per line.
pub fn sample_for_plot(
    curve: &dyn CamCurve,
    key_masters: &[f64],
    view: (f64, f64),
    columns: usize,
) -> PlotSamples {
    let (first, last) = curve.master_range();
    let low = view.0.max(first);
    let high = view.1.min(last);
    let mut samples = PlotSamples::default();
    // A NaN bound leaves nothing to draw, like an empty range.
    if high.is_nan() || low.is_nan() || high <= low {
        return samples;
    }
    let columns = columns.clamp(1, 100_000);
    let width = (high - low) / columns as f64;
    // Left of a joint the previous segment applies; this offset is far below a pixel.
    let left_offset = (last - first) * 1e-9;
    let mut key = key_masters.partition_point(|&master| master < low);
    let mut column_samples: Vec<(f64, CamSample)> = Vec::with_capacity(8);
    for column in 0..columns {
        let start = low + width * column as f64;
        let end = if column + 1 == columns {
            high
        } else {
            start + width
        };
        column_samples.clear();
        column_samples.push((start, curve.sample(start)));
        let key_start = key;
        while key < key_masters.len() && key_masters[key] < end {
            let master = key_masters[key];
            if master > start {
                column_samples.push((master - left_offset, curve.sample(master - left_offset)));
                column_samples.push((master, curve.sample(master)));
            }
            key += 1;
        }
        if key == key_start {
            let middle = 0.5 * (start + end);
            column_samples.push((middle, curve.sample(middle)));
        }
        if column + 1 == columns {
            column_samples.push((high, curve.sample(high)));
        }
        push_column(&mut samples.position, &column_samples, |s| s.position);
        push_column(&mut samples.velocity, &column_samples, |s| s.velocity);
        push_column(&mut samples.acceleration, &column_samples, |s| {
            s.acceleration
        });
        push_column(&mut samples.jerk, &column_samples, |s| s.jerk);
    }
    samples
}

/// Appends one column's samples of one quantity: all of them when few, else the first, the
/// lowest, the highest and the last in master order.
fn push_column(
    line: &mut Vec<[f64; 2]>,
    column: &[(f64, CamSample)],
    value: impl Fn(&CamSample) -> f64,
) {
    if column.len() <= KEEP_ALL_UP_TO {
        line.extend(
            column
                .iter()
                .map(|(master, sample)| [*master, value(sample)]),
        );
        return;
    }
    let mut lowest = 0;
    let mut highest = 0;
    for (index, (_, sample)) in column.iter().enumerate() {
        if value(sample) < value(&column[lowest].1) {
            lowest = index;
        }
        if value(sample) > value(&column[highest].1) {
            highest = index;
        }
    }
    let mut kept = [0, lowest, highest, column.len() - 1];
    kept.sort_unstable();
    let mut previous = None;
    for index in kept {
        if previous != Some(index) {
            let (master, sample) = &column[index];
            line.push([*master, value(sample)]);
            previous = Some(index);
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use motion::cam::{PointCam, PointInterpolation, SegmentedCam};
    use motion::curve::CamPoint;

    #[test]
    fn a_sparse_cam_keeps_its_key_points_exactly() {
        let cam = SegmentedCam::codesys_default();
        let samples = sample_for_plot(&cam, &[0.0, 120.0, 240.0, 360.0], (0.0, 360.0), 800);
        for key in [0.0, 120.0, 240.0, 360.0] {
            let found = samples.position.iter().find(|[master, _]| *master == key);
            // The sample is the curve's own value at the key point, which is the key point's
            // slave position to rounding.
            let expected = cam.sample(key).position;
            assert_eq!(
                found.map(|point| point[1]),
                Some(expected),
                "key point {key}"
            );
            assert!((expected - key).abs() < 1e-9);
        }
    }

    #[test]
    fn ten_thousand_points_are_drawn_with_a_few_points_per_column() {
        let points: Vec<CamPoint> = (0..10_000)
            .map(|i| CamPoint {
                master: f64::from(i),
                slave: if i % 2 == 0 { 0.0 } else { 1.0 },
                ..CamPoint::default()
            })
            .collect();
        let masters: Vec<f64> = points.iter().map(|p| p.master).collect();
        let cam = PointCam::new(points, PointInterpolation::Linear).unwrap();
        let samples = sample_for_plot(&cam, &masters, (0.0, 9_999.0), 800);
        assert!(
            samples.position.len() <= 4 * 800 + 1,
            "{}",
            samples.position.len()
        );
        // The zigzag's extremes survive the reduction in every column.
        let highest = samples
            .position
            .iter()
            .map(|p| p[1])
            .fold(f64::MIN, f64::max);
        let lowest = samples
            .position
            .iter()
            .map(|p| p[1])
            .fold(f64::MAX, f64::min);
        assert_eq!((lowest, highest), (0.0, 1.0));
        assert!(
            samples
                .position
                .windows(2)
                .all(|pair| pair[0][0] <= pair[1][0])
        );
    }
}
