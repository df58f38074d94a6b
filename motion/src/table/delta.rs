//! Delta DVP-15MC key points as a `MasterPos,SlavePos,SlaveVel,SlaveAcc` CSV
//! (`docs/cam-formats.md` §5).

use super::TableError;
use super::number::plain;
use super::sampling::{check_count, check_points, sample_equidistant};
use crate::curve::{CamCurve, CamPoint};

/// The most key points one Delta DVP-15MC cam table holds.
pub const DELTA_MAX_KEY_POINTS: usize = 2048;

/// The key points of one Delta DVP-15MC cam table.
#[derive(Clone, Debug, PartialEq)]
pub struct DeltaKeyPoints {
    /// The key points in master order.
    points: Vec<CamPoint>,
}

impl DeltaKeyPoints {
    /// `count` equidistant samples of `curve` (2 to 2048), with slave velocity and
    /// acceleration with respect to the master.
    pub fn from_curve(curve: &dyn CamCurve, count: usize) -> Result<Self, TableError> {
        check_delta_count(count)?;
        Self::from_points(&sample_equidistant(curve, count)?)
    }

    /// The given points as key points: 2 to 2048, finite, strictly increasing in master.
    pub fn from_points(points: &[CamPoint]) -> Result<Self, TableError> {
        check_delta_count(points.len())?;
        check_points(points)?;
        Ok(Self {
            points: points.to_vec(),
        })
    }

    /// The key points.
    pub fn points(&self) -> &[CamPoint] {
        &self.points
    }

    /// The CSV text: the header `MasterPos,SlavePos,SlaveVel,SlaveAcc`, then one key point per
    /// line.
    pub fn csv(&self) -> String {
        let mut text = String::from("MasterPos,SlavePos,SlaveVel,SlaveAcc\n");
        for p in &self.points {
            text.push_str(&format!(
                "{},{},{},{}\n",
                plain(p.master),
                plain(p.slave),
                plain(p.velocity),
                plain(p.acceleration)
            ));
        }
        text
    }
}

/// Checks the number of key points against what one Delta cam table holds.
fn check_delta_count(count: usize) -> Result<(), TableError> {
    check_count(count, DELTA_MAX_KEY_POINTS, "a Delta DVP-15MC")
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::table::test_curve::Poly345;

    #[test]
    fn the_csv_of_five_samples_matches_the_golden_text() {
        let key_points = DeltaKeyPoints::from_curve(&Poly345, 5).unwrap();
        assert_eq!(
            key_points.csv(),
            "MasterPos,SlavePos,SlaveVel,SlaveAcc
0,0,0,0
90,18.6328125,0.52734375,0.0078125
180,90,0.9375,0
270,161.3671875,0.52734375,-0.0078125
360,180,0,0
"
        );
    }

    #[test]
    fn the_manuals_four_point_cam_is_written_as_given() {
        let point = |master: f64, slave: f64| CamPoint {
            master,
            slave,
            ..CamPoint::default()
        };
        let points = [
            point(0.0, 0.0),
            point(90.0, 100.0),
            point(180.0, 300.0),
            point(360.0, 0.0),
        ];
        let key_points = DeltaKeyPoints::from_points(&points).unwrap();
        assert_eq!(
            key_points.csv(),
            "MasterPos,SlavePos,SlaveVel,SlaveAcc\n0,0,0,0\n90,100,0,0\n180,300,0,0\n360,0,0,0\n"
        );
    }

    #[test]
    fn up_to_2048_key_points_are_taken_and_2049_refused() {
        assert_eq!(
            DeltaKeyPoints::from_curve(&Poly345, 2048)
                .unwrap()
                .points()
                .len(),
            2048
        );
        let error = DeltaKeyPoints::from_curve(&Poly345, 2049).unwrap_err();
        assert_eq!(
            error,
            TableError::TooManyPoints {
                system: "a Delta DVP-15MC",
                max: 2048,
                count: 2049
            }
        );
        assert_eq!(
            error.to_string(),
            "a Delta DVP-15MC holds at most 2048 points in one cam table, but 2049 were given"
        );
        let many: Vec<CamPoint> = (0..2049)
            .map(|i| CamPoint {
                master: f64::from(i),
                ..CamPoint::default()
            })
            .collect();
        assert!(matches!(
            DeltaKeyPoints::from_points(&many),
            Err(TableError::TooManyPoints { count: 2049, .. })
        ));
    }
}
