//! Point tables of a cam and the files they are exchanged in: sampling a [`CamCurve`] into
//! points, the CODESYS, Omron and Delta exports, and the Rivet CSV the cam editor imports and
//! exports. `docs/cam-formats.md` specifies every format written and read here.
//!
//! [`CamCurve`]: crate::curve::CamCurve

mod codesys_table_1d;
mod codesys_table_2d;
mod codesys_xyva;
mod csv_error;
mod csv_reader;
#[cfg(test)]
mod csv_tests;
mod delta;
mod error;
mod number;
mod omron;
mod rivet_csv;
mod sampling;
mod scaling;
#[cfg(test)]
mod test_curve;

pub use codesys_table_1d::CodesysTable1d;
pub use codesys_table_2d::CodesysTable2d;
pub use codesys_xyva::CodesysXyva;
pub use csv_error::CsvError;
pub use csv_reader::read_points_csv;
pub use delta::{DELTA_MAX_KEY_POINTS, DeltaKeyPoints};
pub use error::TableError;
pub use omron::{OMRON_MAX_POINTS, OmronCamData};
pub use rivet_csv::{CsvColumns, write_points_csv};
pub use sampling::{MAX_SAMPLES, check_points, sample_equidistant};
pub use scaling::CodesysScaling;

/// The version of the formats in `docs/cam-formats.md` this module writes and reads.
pub const FORMAT_VERSION: u32 = 1;
