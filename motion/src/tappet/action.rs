//! What a tappet does when the master passes it, and in which direction it was passed.

/// What a tappet does to its track's output when the master passes it in one direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TappetAction {
    /// Nothing; the pass is not a switch and leaves no hysteresis behind.
    None,
    /// Switch the output on.
    On,
    /// Switch the output off.
    Off,
    /// Invert the output.
    Invert,
    /// Switch the output on for a time, then off (a Rivet extension after PLCopen's time-based
    /// cam switch). Passing it again restarts the time; any other action ends it.
    TimedOn {
        /// How long the output stays on, in seconds of the time given to the evaluator.
        duration_s: f64,
    },
}

/// The direction the master passed a tappet in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PassDirection {
    /// The master increased over the tappet.
    Positive,
    /// The master decreased over the tappet.
    Negative,
}

impl PassDirection {
    /// +1 for positive, −1 for negative, to measure distances along the motion.
    pub(crate) fn sign(self) -> f64 {
        match self {
            Self::Positive => 1.0,
            Self::Negative => -1.0,
        }
    }
}
