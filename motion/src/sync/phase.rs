//! MC_Phasing: a smooth change of the master position a slave sees.

use crate::axis::Profile;
use crate::kernel::CommandId;

/// Whether `PhaseShift` replaces the shift in force or adds to it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PhasingMode {
    /// MC_PhasingAbsolute: the shift in force becomes `PhaseShift`.
    #[default]
    Absolute,
    /// MC_PhasingRelative: `PhaseShift` is added to the shift in force at the rising edge.
    Relative,
}

/// A phase change under way: a position profile of the shift itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PhaseRun {
    /// The MC_Phasing command.
    pub(crate) id: CommandId,
    /// The shift when the command started.
    pub(crate) origin: f64,
    /// The profile from `origin` to the new shift.
    pub(crate) profile: Profile,
    /// Seconds since the command started.
    pub(crate) elapsed_s: f64,
}

/// The phase shift of a coupling: the slave sees `master − shift`, so a positive shift makes
/// the slave lag (CODESYS convention). The master's own values never change.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PhaseState {
    /// The shift in force, in master units.
    pub(crate) shift: f64,
    /// The rate of change of the shift, in master units per second.
    pub(crate) velocity: f64,
    /// The second derivative of the shift.
    pub(crate) acceleration: f64,
    /// The change under way, if any.
    pub(crate) run: Option<PhaseRun>,
}

impl PhaseState {
    /// Moves the shift on by `dt_s`; returns the command that finished in this step.
    pub(crate) fn advance(&mut self, dt_s: f64) -> Option<CommandId> {
        let run = self.run.as_mut()?;
        run.elapsed_s += dt_s;
        if run.elapsed_s >= run.profile.duration_s() - dt_s * 1e-6 {
            self.shift = run.origin + run.profile.end().displacement;
            self.velocity = 0.0;
            self.acceleration = 0.0;
            let id = run.id;
            self.run = None;
            return Some(id);
        }
        let sample = run.profile.sample(run.elapsed_s);
        self.shift = run.origin + sample.displacement;
        self.velocity = sample.velocity;
        self.acceleration = sample.acceleration;
        None
    }
}
