//! The inputs of MC_GearIn and MC_GearInPos as the kernel receives them.

/// The inputs of MC_GearIn sampled at its rising edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GearCoupling {
    /// `RatioNumerator`, signed.
    pub ratio_numerator: i32,
    /// `RatioDenominator`, above 0.
    pub ratio_denominator: u32,
    /// `Acceleration` while the slave speeds up to the geared velocity, above 0.
    pub acceleration: f64,
    /// `Deceleration` while the slave slows down to the geared velocity, above 0.
    pub deceleration: f64,
    /// `Jerk` of the ramp; 0 uses the slave's jerk limit (none: trapezoid).
    pub jerk: f64,
}

impl GearCoupling {
    /// The gear ratio numerator / denominator.
    #[must_use]
    pub fn ratio(&self) -> f64 {
        f64::from(self.ratio_numerator) / f64::from(self.ratio_denominator)
    }
}

/// The inputs of MC_GearInPos sampled at its rising edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GearInPosCoupling {
    /// `RatioNumerator`, signed.
    pub ratio_numerator: i32,
    /// `RatioDenominator`, above 0.
    pub ratio_denominator: u32,
    /// `MasterSyncPosition`: where the master is when the slave is in sync.
    pub master_sync_position: f64,
    /// `SlaveSyncPosition`: where the slave is at that moment.
    pub slave_sync_position: f64,
    /// `MasterStartDistance`: the master distance before `MasterSyncPosition` over which the
    /// slave synchronises; above 0 (the master moves positive), and it may exceed a period.
    pub master_start_distance: f64,
}

impl GearInPosCoupling {
    /// The gear ratio numerator / denominator.
    #[must_use]
    pub fn ratio(&self) -> f64 {
        f64::from(self.ratio_numerator) / f64::from(self.ratio_denominator)
    }
}
