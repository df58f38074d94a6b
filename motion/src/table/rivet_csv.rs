//! The Rivet CSV of cam points, as the cam editor exports it (`docs/cam-formats.md` §2.1).

use super::number::plain;
use crate::curve::CamPoint;

/// Which columns the Rivet CSV export writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsvColumns {
    /// `master,slave`.
    Positions,
    /// `master,slave,velocity,acceleration`, the derivatives with respect to the master.
    PositionsAndDerivatives,
}

/// The Rivet CSV text of `points`: the version comment, the header for `columns`, then one point
/// per line. The points are written as they are; [`read_points_csv`](super::read_points_csv)
/// reads the text back.
pub fn write_points_csv(points: &[CamPoint], columns: CsvColumns) -> String {
    let mut text = format!(
        "# Rivet cam points, format version {}\n",
        super::FORMAT_VERSION
    );
    match columns {
        CsvColumns::Positions => {
            text.push_str("master,slave\n");
            for p in points {
                text.push_str(&format!("{},{}\n", plain(p.master), plain(p.slave)));
            }
        }
        CsvColumns::PositionsAndDerivatives => {
            text.push_str("master,slave,velocity,acceleration\n");
            for p in points {
                text.push_str(&format!(
                    "{},{},{},{}\n",
                    plain(p.master),
                    plain(p.slave),
                    plain(p.velocity),
                    plain(p.acceleration)
                ));
            }
        }
    }
    text
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::table::sample_equidistant;
    use crate::table::test_curve::Poly345;

    #[test]
    fn positions_only_match_the_golden_text() {
        let points = sample_equidistant(&Poly345, 3).unwrap();
        assert_eq!(
            write_points_csv(&points, CsvColumns::Positions),
            "# Rivet cam points, format version 1\nmaster,slave\n0,0\n180,90\n360,180\n"
        );
    }

    #[test]
    fn positions_and_derivatives_match_the_golden_text() {
        let points = sample_equidistant(&Poly345, 5).unwrap();
        assert_eq!(
            write_points_csv(&points, CsvColumns::PositionsAndDerivatives),
            "# Rivet cam points, format version 1
master,slave,velocity,acceleration
0,0,0,0
90,18.6328125,0.52734375,0.0078125
180,90,0.9375,0
270,161.3671875,0.52734375,-0.0078125
360,180,0,0
"
        );
    }
}
