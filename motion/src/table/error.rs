//! What can go wrong when points are generated or an export is written.

use thiserror::Error;

/// Why a table could not be generated or written; each message names the point, row or field.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum TableError {
    /// The curve's master range is not finite or does not increase.
    #[error(
        "the cam's master range {start} to {end} cannot be sampled: both ends must be finite numbers and the start below the end"
    )]
    InvalidMasterRange {
        /// The first master position the curve reported.
        start: f64,
        /// The last master position the curve reported.
        end: f64,
    },
    /// Fewer than two points were asked for or given.
    #[error("a cam table needs at least 2 points, but {count} were given")]
    TooFewPoints {
        /// The number of points asked for or given.
        count: usize,
    },
    /// More points than the target system holds.
    #[error("{system} holds at most {max} points in one cam table, but {count} were given")]
    TooManyPoints {
        /// The target system, such as "a Delta DVP-15MC".
        system: &'static str,
        /// The most points the system holds.
        max: usize,
        /// The number of points asked for or given.
        count: usize,
    },
    /// A value of a point is infinite or not a number.
    #[error("point {index}: the {field} is not a finite number")]
    NotFinite {
        /// The 0-based index of the point, as in the exported array.
        index: usize,
        /// The field that is wrong: "master", "slave", "velocity" or "acceleration".
        field: &'static str,
    },
    /// The master positions of the points do not strictly increase.
    #[error("point {index}: master {master} is not greater than {previous} at point {previous_index}", previous_index = index - 1)]
    MasterNotIncreasing {
        /// The 0-based index of the offending point; the point before it is `index - 1`.
        index: usize,
        /// Its master position.
        master: f64,
        /// The master position of the point before it.
        previous: f64,
    },
    /// The name for the exported variable or type is not an IEC identifier.
    #[error(
        "\"{name}\" cannot be a variable name in Structured Text: use letters, digits and _, start with a letter or _, and do not use __ or end with _"
    )]
    InvalidIdentifier {
        /// The name as given.
        name: String,
    },
    /// The table slave range of a CODESYS table is empty, so table values cannot be scaled.
    #[error(
        "fTableSlaveMin and fTableSlaveMax are both {value}: the slave scale would divide by zero"
    )]
    EmptyTableSlaveRange {
        /// The value both fields hold.
        value: f64,
    },
}
