//! `MC_DIRECTION` and the way round a modulo axis takes to an absolute target.

/// `MC_DIRECTION` with the CODESYS numbering.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(i8)]
pub enum Direction {
    /// Move towards rising positions.
    Positive = 1,
    /// Move towards falling positions.
    Negative = -1,
    /// Take the shorter way round (modulo axes only).
    #[default]
    Shortest = 0,
    /// Keep the current direction of motion (modulo axes only).
    Current = 2,
    /// Take the way that arrives sooner, given the current velocity (modulo axes only).
    Fastest = 3,
}

impl Direction {
    /// The direction for a CODESYS `MC_DIRECTION` number, `None` for another number.
    #[must_use]
    pub fn from_code(code: i16) -> Option<Self> {
        match code {
            1 => Some(Self::Positive),
            -1 => Some(Self::Negative),
            0 => Some(Self::Shortest),
            2 => Some(Self::Current),
            3 => Some(Self::Fastest),
            _ => None,
        }
    }

    /// The CODESYS `MC_DIRECTION` number.
    #[must_use]
    pub fn code(self) -> i16 {
        i16::from(self as i8)
    }
}

/// The two signed distances from `from` to `target` on a modulo axis of `period_units`: the
/// positive one in `[0, period)` and the negative one in `(-period, 0]`. Both positions are
/// already wrapped into `[0, period)`.
#[must_use]
pub fn modulo_distances(from: f64, target: f64, period_units: f64) -> (f64, f64) {
    let mut forward = (target - from).rem_euclid(period_units);
    if forward >= period_units {
        forward = 0.0;
    }
    if forward == 0.0 {
        (0.0, 0.0)
    } else {
        (forward, forward - period_units)
    }
}
