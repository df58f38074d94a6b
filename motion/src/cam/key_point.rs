//! A key point of a segmented cam.

/// A key point of a segmented cam: where one segment ends and the next begins, with the slave
/// position and its derivatives with respect to the master (mirrors the project model's
/// `CamKeyPoint`).
///
/// Each law reads only what it needs: Line the positions, Poly3 also the velocities, Poly5 and
/// the rest-in-rest laws also the accelerations, Poly7 also the jerks.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct KeyPoint {
    /// Master position X.
    pub master: f64,
    /// Slave position Y.
    pub slave: f64,
    /// Slave velocity dY/dX.
    pub velocity: f64,
    /// Slave acceleration d²Y/dX².
    pub acceleration: f64,
    /// Slave jerk d³Y/dX³ (read by Poly7 segments only).
    pub jerk: f64,
}

impl KeyPoint {
    /// A key point with velocity, acceleration and jerk zero: a dwell.
    pub fn rest(master: f64, slave: f64) -> Self {
        Self {
            master,
            slave,
            ..Self::default()
        }
    }

    /// A key point with the given velocity and acceleration and jerk zero, like a row of the
    /// CODESYS cam table (X, Y, V, A).
    pub fn xyva(master: f64, slave: f64, velocity: f64, acceleration: f64) -> Self {
        Self {
            master,
            slave,
            velocity,
            acceleration,
            jerk: 0.0,
        }
    }

    /// The name of the first field that is not a finite number, if any.
    pub(crate) fn non_finite_field(&self) -> Option<&'static str> {
        [
            ("master position", self.master),
            ("slave position", self.slave),
            ("velocity", self.velocity),
            ("acceleration", self.acceleration),
            ("jerk", self.jerk),
        ]
        .into_iter()
        .find(|(_, value)| !value.is_finite())
        .map(|(name, _)| name)
    }
}
