//! The numbers the motion library keeps in memory: the error ids its blocks report without the
//! kernel (`docs/motion.md` §5) and its enumerations as the `motion` crate's types.

use motion::axis::Direction;
use motion::kernel::BufferMode;
use motion::sync::StartMode;

/// `ErrorID` for an input that is not valid.
pub(super) const INVALID_INPUT: u16 = 4;
/// `ErrorID` for a VAR_IN_OUT that names no axis or is not connected.
pub(super) const UNKNOWN_AXIS: u16 = 9;
/// `ErrorID` for a VAR_IN_OUT that names no cam table.
pub(super) const UNKNOWN_CAM: u16 = 13;

/// The `MC_BUFFER_MODE` number as a buffer mode; an unknown number aborts, the default.
pub(super) fn buffer_mode(code: i16) -> BufferMode {
    match code {
        1 => BufferMode::Buffered,
        2 => BufferMode::BlendingLow,
        3 => BufferMode::BlendingPrevious,
        4 => BufferMode::BlendingNext,
        5 => BufferMode::BlendingHigh,
        _ => BufferMode::Aborting,
    }
}

/// The `MC_DIRECTION` number as a direction; an unknown number takes the shortest way.
pub(super) fn direction(code: i16) -> Direction {
    Direction::from_code(code).unwrap_or(Direction::Shortest)
}

/// The `MC_StartMode` number as a start mode; an unknown number starts absolute, the default.
pub(super) fn start_mode(code: i16) -> StartMode {
    match code {
        1 => StartMode::Relative,
        2 => StartMode::RampIn,
        3 => StartMode::RampInPositive,
        4 => StartMode::RampInNegative,
        _ => StartMode::Absolute,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_numbers_are_those_of_the_library_enumerations() {
        for code in 0..=5 {
            assert_eq!(buffer_mode(code).code(), code as u16);
        }
        assert_eq!(buffer_mode(9), BufferMode::Aborting);
        assert_eq!(direction(-1), Direction::Negative);
        assert_eq!(direction(7), Direction::Shortest);
        for code in 0..=4 {
            assert_eq!(start_mode(code).code(), code as u16);
        }
    }
}
