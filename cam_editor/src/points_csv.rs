//! CSV import and export of a cam's points (the Rivet CSV of `docs/cam-formats.md` §2); the
//! app reads and writes the files, this module only turns text into cams and back.

use motion::table::{
    CsvColumns, CsvError, TableError, read_points_csv, sample_equidistant, write_points_csv,
};
use project_model::{CamCompileFormat, CamProfile, CamTable, CamTablePoint, PointInterpolation};
use thiserror::Error;

use crate::convert::{ConvertError, Curve, curve_of};

/// How many points the export samples from a cam of segments whose compile format does not say
/// (Segments, XYVA): one per degree of the default 0 to 360 cam, with both ends.
pub const DEFAULT_EXPORT_POINTS: usize = 361;

/// Why points could not be imported or exported.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum PointsCsvError {
    /// The CSV text is not a valid point file; the message names the line and column.
    #[error(transparent)]
    Csv(#[from] CsvError),
    /// The cam to export has no curve; the message names the segment or row.
    #[error(transparent)]
    Cam(#[from] ConvertError),
    /// Sampling the cam failed.
    #[error(transparent)]
    Table(#[from] TableError),
}

/// `cam` with its profile replaced by the points of `csv_text` (master and slave columns; a
/// velocity or acceleration column is read and not kept, because a point table is interpolated
/// from positions). A point table keeps its interpolation; a cam of segments becomes a linear
/// table. The master range becomes that of the points.
pub fn import_points(cam: &CamTable, csv_text: &str) -> Result<CamTable, PointsCsvError> {
    let points = read_points_csv(csv_text)?;
    let interpolation = match &cam.profile {
        CamProfile::Points { interpolation, .. } => *interpolation,
        CamProfile::Segments { .. } => PointInterpolation::Linear,
    };
    let mut imported = cam.clone();
    imported.profile = CamProfile::Points {
        interpolation,
        points: points
            .iter()
            .map(|point| CamTablePoint {
                master: point.master,
                slave: point.slave,
            })
            .collect(),
    };
    crate::cam_edit::fit_master_range(&mut imported);
    curve_of(&imported)?;
    Ok(imported)
}

/// The Rivet CSV of `cam` with velocity and acceleration: a point table's own rows, or
/// equidistant samples of a cam of segments (as many as a table compile format names, else
/// [`DEFAULT_EXPORT_POINTS`]).
pub fn export_points(cam: &CamTable) -> Result<String, PointsCsvError> {
    let curve = curve_of(cam)?;
    let points = match &curve {
        Curve::Points(table) => table
            .points()
            .iter()
            .map(|point| {
                let sample = motion::curve::CamCurve::sample(&curve, point.master);
                motion::curve::CamPoint {
                    velocity: sample.velocity,
                    acceleration: sample.acceleration,
                    ..*point
                }
            })
            .collect(),
        Curve::Segmented(_) => {
            let count = match cam.compile_format {
                CamCompileFormat::Table1d { elements } | CamCompileFormat::Table2d { elements } => {
                    elements as usize
                }
                CamCompileFormat::Segments | CamCompileFormat::Xyva => DEFAULT_EXPORT_POINTS,
            };
            sample_equidistant(&curve, count)?
        }
    };
    Ok(write_points_csv(
        &points,
        CsvColumns::PositionsAndDerivatives,
    ))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    #[test]
    fn an_exported_point_table_imports_back_to_the_same_points() {
        let mut cam = CamTable::codesys_default("Cam");
        let csv = "master,slave\n0,0\n90,10\n360,20\n";
        cam = import_points(&cam, csv).unwrap();
        let text = export_points(&cam).unwrap();
        let again = import_points(&cam, &text).unwrap();
        assert_eq!(again, cam);
        assert_eq!((cam.master.start, cam.master.end), (0.0, 360.0));
    }

    #[test]
    fn a_bad_value_is_refused_naming_line_and_column() {
        let cam = CamTable::codesys_default("Cam");
        let error = import_points(&cam, "# comment\nmaster,slave\n0,0\n10,1x\n")
            .unwrap_err()
            .to_string();
        assert_eq!(
            error,
            "line 4, column \"slave\": \"1x\" is not a number (use . as the decimal point)"
        );
    }

    #[test]
    fn a_cam_of_segments_exports_361_samples() {
        let cam = CamTable::codesys_default("Cam");
        let text = export_points(&cam).unwrap();
        // The version comment, the header and the samples.
        assert_eq!(text.lines().count(), 2 + DEFAULT_EXPORT_POINTS);
        let last = text.lines().last().unwrap();
        let values: Vec<f64> = last.split(',').map(|v| v.parse().unwrap()).collect();
        assert_eq!(values[0], 360.0);
        assert!((values[1] - 360.0).abs() < 1e-9, "{last}");
    }
}
