//! What the rest of the motion crate needs from a cam curve: the slave position and its
//! derivatives at a master position. The cam laws implement it, the axis kernel couples slaves
//! through it, and the table exporters sample it.

/// The slave position and its derivatives with respect to the master position, at one master
/// position. Derivatives are taken with respect to the master position (dY/dX), not time.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CamSample {
    /// Slave position Y.
    pub position: f64,
    /// dY/dX.
    pub velocity: f64,
    /// d²Y/dX².
    pub acceleration: f64,
    /// d³Y/dX³.
    pub jerk: f64,
}

/// A point of a point table: master position, slave position and the slave's first two
/// derivatives with respect to the master (CODESYS `SMC_CAMXYVA`, Delta key points; Omron and
/// CODESYS XY tables leave the derivatives at zero).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CamPoint {
    /// Master position X.
    pub master: f64,
    /// Slave position Y.
    pub slave: f64,
    /// dY/dX at the point.
    pub velocity: f64,
    /// d²Y/dX² at the point.
    pub acceleration: f64,
}

/// A cam curve a slave can be coupled through.
pub trait CamCurve {
    /// The first and the last master position of the curve; the first is below the last.
    fn master_range(&self) -> (f64, f64);

    /// The slave at `master`; positions outside the master range are clamped to it.
    fn sample(&self, master: f64) -> CamSample;
}
