//! Whether a cycle runs on the real clock or a simulated one, which decides what the clock
//! operators `TIME()` and `LTIME()` read during the cycle.

/// The kind of clock a cycle's task time comes from. The scheduler of `rivet-runtime` runs
/// cycles on the real clock; [`crate::simulation::Simulation`] (`rivet simulate`, the tests)
/// on a simulated one. Timers and SFC step times read the task time at the cycle's start
/// either way; only `TIME()` and `LTIME()` differ (`docs/program-image.md` §14).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TaskClock {
    /// Time passes during the cycle: `TIME()` and `LTIME()` give the task time at the cycle's
    /// start plus the time elapsed since it started, so two calls in one cycle measure the code
    /// between them.
    Real,
    /// Time stands still during the cycle: `TIME()` and `LTIME()` give the task time, so a run
    /// gives the same values every time.
    Simulated,
}
