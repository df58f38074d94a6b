//! What can be wrong in a CSV file of cam points.

use thiserror::Error;

/// Why a CSV file of points could not be read; lines are counted from 1 as an editor shows
/// them, comment and blank lines included, and columns are named as in the file's header.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum CsvError {
    /// The file holds nothing but blank and comment lines.
    #[error("the file is empty: it has no header line and no points")]
    Empty,
    /// The first line that is not blank or a comment is not a known header.
    #[error(
        "line {line}: the header \"{text}\" is not one of master,slave[,velocity[,acceleration]], Phase,Distance or MasterPos,SlavePos,SlaveVel,SlaveAcc"
    )]
    UnknownHeader {
        /// The line of the header.
        line: usize,
        /// The header as written, cut to 40 characters.
        text: String,
    },
    /// A point line has fewer values than the header names, or an empty value.
    #[error("line {line}: the value in column \"{column}\" is missing")]
    MissingValue {
        /// The line of the point.
        line: usize,
        /// The column's name in the header.
        column: String,
    },
    /// A point line has more values than the header names.
    #[error("line {line} has {count} values, but the header names {columns} columns")]
    TooManyValues {
        /// The line of the point.
        line: usize,
        /// The number of values on the line.
        count: usize,
        /// The number of columns the header names.
        columns: usize,
    },
    /// A value is not a finite decimal number.
    #[error(
        "line {line}, column \"{column}\": \"{text}\" is not a number (use . as the decimal point)"
    )]
    NotANumber {
        /// The line of the point.
        line: usize,
        /// The column's name in the header.
        column: String,
        /// The value as written, cut to 40 characters.
        text: String,
    },
    /// The file has fewer than two points.
    #[error("the file has {count} {noun}; a cam needs at least 2", noun = if *count == 1 { "point" } else { "points" })]
    TooFewPoints {
        /// The number of points in the file.
        count: usize,
    },
    /// A master position is not greater than the one on the point line before it.
    #[error(
        "line {line}: {column} {master} is not greater than {previous} on line {previous_line}"
    )]
    MasterNotIncreasing {
        /// The line of the offending point.
        line: usize,
        /// The name of the master column in the header (`master`, `Phase` or `MasterPos`).
        column: String,
        /// The offending master position.
        master: f64,
        /// The line of the point before it.
        previous_line: usize,
        /// The master position of the point before it.
        previous: f64,
    },
}
