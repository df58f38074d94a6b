//! What the evaluator is told about one task cycle.

/// Whether the cam master coordinate wrapped at the period end in this cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MasterWrap {
    /// No wrap: the master moved from `prev_master` to `master` directly.
    #[default]
    None,
    /// The master moved forward past the period end and restarted near the start.
    Forward,
    /// The master moved backward past the period start and restarted near the end.
    Backward,
}

/// One task cycle of the cam master, as the coupling saw it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TappetCycle {
    /// The cam master coordinate of the previous cycle.
    pub prev_master: f64,
    /// The cam master coordinate of this cycle.
    pub master: f64,
    /// Whether the coordinate wrapped at the period end between the two.
    pub wrap: MasterWrap,
    /// The master velocity in master units per second, for dead-time compensation.
    pub master_velocity: f64,
    /// The time of this cycle in seconds, for timed switches; it must not go backwards.
    pub now_s: f64,
}
