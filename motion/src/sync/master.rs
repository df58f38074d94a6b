//! What a coupling reads from its master and its slave each cycle, and what it writes back.

/// The master's set values after its own `advance` in this cycle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct MasterView {
    /// The set position, wrapped into the period on a modulo axis.
    pub(crate) position: f64,
    /// The set velocity in master units per second.
    pub(crate) velocity: f64,
    /// The set acceleration in master units per second².
    pub(crate) acceleration: f64,
    /// The modulo period, `None` on a linear master.
    pub(crate) period: Option<f64>,
}

impl MasterView {
    /// The displacement from `previous` to the current position; on a modulo master the wrap is
    /// undone, assuming the master moved less than half a period in one cycle.
    pub(crate) fn displacement_from(&self, previous: f64) -> f64 {
        let difference = self.position - previous;
        match self.period {
            Some(period) => wrap_signed(difference, period),
            None => difference,
        }
    }
}

/// The master as the slave sees it in one cycle: the master's motion minus the phase shift.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SeenMaster {
    /// The displacement in this cycle.
    pub(crate) displacement: f64,
    /// The velocity in master units per second.
    pub(crate) velocity: f64,
    /// The acceleration in master units per second².
    pub(crate) acceleration: f64,
}

/// The slave's set values before the coupling steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SlaveView {
    /// The set position (wrapped on a modulo slave).
    pub(crate) position: f64,
    /// The set velocity.
    pub(crate) velocity: f64,
    /// The modulo period of the slave, `None` on a linear slave.
    pub(crate) period: Option<f64>,
}

/// The slave's new set values; the position is not wrapped yet.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct SlaveSet {
    /// The set position.
    pub(crate) position: f64,
    /// The set velocity.
    pub(crate) velocity: f64,
    /// The set acceleration.
    pub(crate) acceleration: f64,
}

/// `value` brought into `[-period/2, period/2)`, the shortest signed way round a period.
pub(crate) fn wrap_signed(value: f64, period: f64) -> f64 {
    let wrapped = (value + period / 2.0).rem_euclid(period) - period / 2.0;
    if wrapped.is_finite() { wrapped } else { value }
}
