//! Why a cam cannot be built or exported.

use thiserror::Error;

use crate::cam::law::MotionLaw;

/// Why a cam cannot be built or exported. Segments, key points and rows are numbered from 1, as
/// in the cam table; key point 1 is the start point and segment n ends at key point n + 1.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum CamError {
    /// The segmented cam has a start point but no segment.
    #[error("the cam has no segment; add at least one segment after the start point")]
    NoSegments,
    /// A key point holds a value that is not a finite number.
    #[error("key point {key_point}: the {field} is not a finite number")]
    NonFiniteKeyPoint {
        /// The key point, 1 for the start point.
        key_point: usize,
        /// The field that is wrong, such as "velocity".
        field: &'static str,
    },
    /// A segment does not advance the master.
    #[error(
        "segment {segment} ({law}, {start_master}..{end_master}): the master position must increase along the segment"
    )]
    MasterNotIncreasing {
        /// The segment.
        segment: usize,
        /// Its law.
        law: MotionLaw,
        /// The master position it starts at.
        start_master: f64,
        /// The master position it ends at.
        end_master: f64,
    },
    /// A rest-in-rest law is asked to connect two different velocities.
    #[error(
        "segment {segment} ({law}, {start_master}..{end_master}): the law cannot start at velocity {start_velocity} and end at velocity {end_velocity}; use Poly5"
    )]
    VelocitiesDiffer {
        /// The segment.
        segment: usize,
        /// Its law.
        law: MotionLaw,
        /// The master position it starts at.
        start_master: f64,
        /// The master position it ends at.
        end_master: f64,
        /// dY/dX at the start key point.
        start_velocity: f64,
        /// dY/dX at the end key point.
        end_velocity: f64,
    },
    /// A rest-in-rest law is asked to start or end with an acceleration.
    #[error(
        "segment {segment} ({law}, {start_master}..{end_master}): the law needs acceleration 0 at both ends but has {start_acceleration} at the start and {end_acceleration} at the end; use Poly5"
    )]
    AccelerationNotZero {
        /// The segment.
        segment: usize,
        /// Its law.
        law: MotionLaw,
        /// The master position it starts at.
        start_master: f64,
        /// The master position it ends at.
        end_master: f64,
        /// d²Y/dX² at the start key point.
        start_acceleration: f64,
        /// d²Y/dX² at the end key point.
        end_acceleration: f64,
    },
    /// A modified sine segment sets the inflection parameter λ, which is not supported.
    #[error(
        "segment {segment} (ModifiedSine, {start_master}..{end_master}): the inflection parameter lambda = {lambda} is not supported; clear it to use the classic modified sine with inflections at 1/8 and 7/8"
    )]
    LambdaNotSupported {
        /// The segment.
        segment: usize,
        /// The master position it starts at.
        start_master: f64,
        /// The master position it ends at.
        end_master: f64,
        /// The λ that was set.
        lambda: f64,
    },
    /// A segment whose law is not a modified sine sets λ.
    #[error(
        "segment {segment} ({law}, {start_master}..{end_master}): lambda applies to ModifiedSine segments only; clear it"
    )]
    LambdaNotApplicable {
        /// The segment.
        segment: usize,
        /// Its law.
        law: MotionLaw,
        /// The master position it starts at.
        start_master: f64,
        /// The master position it ends at.
        end_master: f64,
    },
    /// The XYVA format was asked for a cam with a segment other than Line or Poly5.
    #[error(
        "segment {segment} ({law}, {start_master}..{end_master}): the XYVA format holds only Line and Poly5 segments; compile the cam as segments or as a table"
    )]
    LawNotInXyva {
        /// The segment.
        segment: usize,
        /// Its law.
        law: MotionLaw,
        /// The master position it starts at.
        start_master: f64,
        /// The master position it ends at.
        end_master: f64,
    },
    /// A point table has fewer than two rows.
    #[error("the point table has {rows} row(s); it needs at least two")]
    TooFewRows {
        /// The number of rows it has.
        rows: usize,
    },
    /// A row of a point table holds a value that is not a finite number.
    #[error("row {row}: the {field} is not a finite number")]
    NonFiniteRow {
        /// The row.
        row: usize,
        /// The field that is wrong, such as "slave position".
        field: &'static str,
    },
    /// A row of a point table repeats the master position of the row before.
    #[error(
        "row {row}: master position {master} repeats the one of row {previous_row}; master positions must strictly increase"
    )]
    RepeatedMaster {
        /// The row.
        row: usize,
        /// The row before it.
        previous_row: usize,
        /// The repeated master position.
        master: f64,
    },
    /// A row of a point table has a master position below the row before.
    #[error(
        "row {row}: master position {master} is below {previous_master} of row {previous_row}; master positions must strictly increase"
    )]
    MasterDecreasing {
        /// The row.
        row: usize,
        /// The row before it.
        previous_row: usize,
        /// The row's master position.
        master: f64,
        /// The master position of the row before.
        previous_master: f64,
    },
    /// A table export was asked for fewer than two samples.
    #[error("a table needs at least 2 elements, including both ends, not {elements}")]
    TooFewElements {
        /// The number of elements asked for.
        elements: usize,
    },
}
