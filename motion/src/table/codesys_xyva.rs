//! CODESYS XYVA points, `ARRAY[0..N-1] OF SMC_CAMXYVA` (`docs/cam-formats.md` §3.4).

use super::TableError;
use super::number::{check_identifier, st_real};
use super::sampling::{CODESYS_MAX_ELEMENTS, check_count, check_points};
use crate::curve::CamPoint;

/// Points with slave position, dY/dX and d²Y/dX² for a CODESYS XYVA cam, which joins
/// consecutive points by quintics.
#[derive(Clone, Debug, PartialEq)]
pub struct CodesysXyva {
    /// The points in master order.
    points: Vec<CamPoint>,
}

impl CodesysXyva {
    /// The given points, which must be at least two, finite and strictly increasing in master.
    pub fn from_points(points: &[CamPoint]) -> Result<Self, TableError> {
        check_count(
            points.len(),
            CODESYS_MAX_ELEMENTS,
            "CODESYS (nElements is an INT)",
        )?;
        check_points(points)?;
        Ok(Self {
            points: points.to_vec(),
        })
    }

    /// The points.
    pub fn points(&self) -> &[CamPoint] {
        &self.points
    }

    /// A global variable list declaring `variable` as the array of points.
    pub fn gvl(&self, variable: &str) -> Result<String, TableError> {
        check_identifier(variable)?;
        let rows = self
            .points
            .iter()
            .map(|p| {
                format!(
                    "        (dX := {}, dY := {}, dV := {}, dA := {})",
                    st_real(p.master),
                    st_real(p.slave),
                    st_real(p.velocity),
                    st_real(p.acceleration)
                )
            })
            .collect::<Vec<_>>()
            .join(",\n");
        Ok(format!(
            "VAR_GLOBAL\n    {variable} : ARRAY[0..{}] OF SMC_CAMXYVA := [\n{rows}\n    ];\nEND_VAR\n",
            self.points.len() - 1
        ))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::table::sample_equidistant;
    use crate::table::test_curve::Poly345;

    #[test]
    fn the_gvl_of_three_points_matches_the_golden_text() {
        let points = sample_equidistant(&Poly345, 3).unwrap();
        let xyva = CodesysXyva::from_points(&points).unwrap();
        assert_eq!(
            xyva.gvl("Cam_XYVA").unwrap(),
            "VAR_GLOBAL
    Cam_XYVA : ARRAY[0..2] OF SMC_CAMXYVA := [
        (dX := 0.0, dY := 0.0, dV := 0.0, dA := 0.0),
        (dX := 180.0, dY := 90.0, dV := 0.9375, dA := 0.0),
        (dX := 360.0, dY := 180.0, dV := 0.0, dA := 0.0)
    ];
END_VAR
"
        );
    }

    #[test]
    fn the_t5_default_cam_points_are_written_with_their_velocities() {
        let point = |x: f64, v: f64| CamPoint {
            master: x,
            slave: x,
            velocity: v,
            acceleration: 0.0,
        };
        let points = [
            point(0.0, 0.0),
            point(120.0, 1.0),
            point(240.0, 1.0),
            point(360.0, 0.0),
        ];
        let text = CodesysXyva::from_points(&points)
            .unwrap()
            .gvl("Cam0_A")
            .unwrap();
        assert!(text.contains("    Cam0_A : ARRAY[0..3] OF SMC_CAMXYVA := [\n"));
        assert!(text.contains("        (dX := 120.0, dY := 120.0, dV := 1.0, dA := 0.0),\n"));
    }

    #[test]
    fn a_single_point_is_refused() {
        assert_eq!(
            CodesysXyva::from_points(&[CamPoint::default()]),
            Err(TableError::TooFewPoints { count: 1 })
        );
    }
}
