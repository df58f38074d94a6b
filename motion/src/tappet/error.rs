//! Why a tappet configuration cannot be evaluated.

use thiserror::Error;

/// A tappet configuration the evaluator refuses; tracks are named by ID and tappets by their
/// 1-based row in the track's tappet table.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum TappetError {
    /// The cam master range is not finite or does not increase.
    #[error(
        "the cam's master range {start} to {end} is not usable for tappets: both ends must be finite and the start below the end"
    )]
    InvalidMasterRange {
        /// The master start.
        start: f64,
        /// The master end.
        end: f64,
    },
    /// Two tracks have the same ID.
    #[error("track {id} is defined twice; each track ID switches one output")]
    DuplicateTrack {
        /// The repeated ID.
        id: u16,
    },
    /// A tappet lies outside the master range.
    #[error(
        "track {track}, tappet {row}: position {position} is outside the master range {start} to {end}"
    )]
    TappetOutsideRange {
        /// The track ID.
        track: u16,
        /// The tappet's 1-based row in the track.
        row: usize,
        /// Its position.
        position: f64,
        /// The master start.
        start: f64,
        /// The master end.
        end: f64,
    },
    /// A hysteresis is negative, not finite, or half the period or more.
    #[error(
        "track {track}: the hysteresis {hysteresis} must be 0 or more and less than half the master period ({half_period})"
    )]
    InvalidHysteresis {
        /// The track ID.
        track: u16,
        /// The hysteresis given.
        hysteresis: f64,
        /// Half the master period, the exclusive upper limit.
        half_period: f64,
    },
    /// A dead-time compensation is not finite.
    #[error(
        "track {track}: the dead-time compensation {dead_time_s} s is not a finite number of seconds"
    )]
    InvalidDeadTime {
        /// The track ID.
        track: u16,
        /// The compensation given, in seconds.
        dead_time_s: f64,
    },
    /// A timed switch has a duration that is not a positive finite time.
    #[error(
        "track {track}, tappet {row}: the timed switch lasts {duration_s} s; it must last a positive, finite number of seconds"
    )]
    InvalidDuration {
        /// The track ID.
        track: u16,
        /// The tappet's 1-based row in the track.
        row: usize,
        /// The duration given, in seconds.
        duration_s: f64,
    },
}
