//! Omron NJ/NX cam data as a `Phase,Distance` CSV (`docs/cam-formats.md` §4).

use super::TableError;
use super::number::{plain, round_significant};
use super::sampling::{check_count, sample_equidistant};
use crate::curve::CamCurve;

/// The most points one Omron cam table holds.
pub const OMRON_MAX_POINTS: usize = 65_535;

/// The significant digits of an Omron `REAL` phase or distance.
const REAL_DIGITS: usize = 7;

/// Rows of Omron cam data: phase and distance relative to the start point, rounded to the 7
/// significant digits of a `REAL`.
#[derive(Clone, Debug, PartialEq)]
pub struct OmronCamData {
    /// `(Phase, Distance)` per row; the first row is `(0, 0)`.
    rows: Vec<(f64, f64)>,
}

impl OmronCamData {
    /// `count` equidistant samples of `curve` (2 to 65 535), with the phase measured from the
    /// master start and the distance from the slave position at the master start.
    ///
    /// Fails when the count is out of range. The rounded phases always increase: the phase step
    /// is at least 1/65 534 of the largest phase, far more than the 10⁻⁶ of it that 7 digits
    /// resolve.
    pub fn from_curve(curve: &dyn CamCurve, count: usize) -> Result<Self, TableError> {
        check_count(count, OMRON_MAX_POINTS, "an Omron NJ/NX")?;
        let points = sample_equidistant(curve, count)?;
        let (master_start, slave_start) = (points[0].master, points[0].slave);
        let rows: Vec<(f64, f64)> = points
            .iter()
            .map(|p| {
                (
                    round_significant(p.master - master_start, REAL_DIGITS),
                    round_significant(p.slave - slave_start, REAL_DIGITS),
                )
            })
            .collect();
        Ok(Self { rows })
    }

    /// The `(Phase, Distance)` rows.
    pub fn rows(&self) -> &[(f64, f64)] {
        &self.rows
    }

    /// The CSV text: the header `Phase,Distance`, then one row per line.
    pub fn csv(&self) -> String {
        let mut text = String::from("Phase,Distance\n");
        for (phase, distance) in &self.rows {
            text.push_str(&format!("{},{}\n", plain(*phase), plain(*distance)));
        }
        text
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::table::test_curve::{Line, Poly345};

    #[test]
    fn the_csv_of_five_samples_matches_the_golden_text() {
        let data = OmronCamData::from_curve(&Poly345, 5).unwrap();
        assert_eq!(
            data.csv(),
            "Phase,Distance\n0,0\n90,18.63281\n180,90\n270,161.3672\n360,180\n"
        );
    }

    #[test]
    fn phase_and_distance_are_relative_to_the_start_point() {
        let line = Line {
            start: 100.0,
            end: 160.0,
            slope: -0.5,
        };
        let data = OmronCamData::from_curve(&line, 3).unwrap();
        assert_eq!(data.rows(), [(0.0, 0.0), (30.0, -15.0), (60.0, -30.0)]);
    }

    #[test]
    fn more_than_65535_points_are_refused() {
        let error = OmronCamData::from_curve(&Poly345, 65_536).unwrap_err();
        assert_eq!(
            error.to_string(),
            "an Omron NJ/NX holds at most 65535 points in one cam table, but 65536 were given"
        );
    }

    #[test]
    fn the_finest_table_keeps_phases_increasing_at_real_precision() {
        let line = Line {
            start: 0.0,
            end: 9_999_999.0,
            slope: 1.0,
        };
        let data = OmronCamData::from_curve(&line, OMRON_MAX_POINTS).unwrap();
        assert!(data.rows().windows(2).all(|pair| pair[0].0 < pair[1].0));
        assert_eq!(data.rows()[OMRON_MAX_POINTS - 1].0, 9_999_999.0);
        assert_eq!(data.rows()[1].0, 152.5925);
    }
}
