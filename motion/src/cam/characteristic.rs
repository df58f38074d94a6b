//! The VDI 2143 characteristic values of a motion law.

/// The VDI 2143 characteristic values (Kennwerte) of a normalised motion law: the peak
/// magnitudes of its derivatives on u ∈ [0, 1].
///
/// For a segment of stroke `h` over the master range `β` at master speed `ω`, the peaks are
/// `v_max = cv·h·ω/β`, `a_max = ca·h·ω²/β²` and `j_max = cj·h·ω³/β³`.
///
/// The values describe the law joined to dwells at both ends, as VDI 2143 does: where a
/// derivative of the law is not zero at an end, the next derivative has a jump there against the
/// dwell and is reported as `f64::INFINITY` (the straight line's acceleration, the cubic's and the
/// simple harmonic's jerk). The `*_inside` fields give the finite peak on the open interval for
/// those laws, and equal the plain values for the others.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CharacteristicValues {
    /// Velocity value Cv = max |f′(u)|.
    pub cv: f64,
    /// Acceleration value Ca = max |f″(u)|, infinite when the velocity jumps at an end.
    pub ca: f64,
    /// Jerk value Cj = max |f‴(u)|, infinite when the acceleration jumps at an end.
    pub cj: f64,
    /// Dynamic torque value Cmv = max |f′(u)·f″(u)|, infinite when the acceleration is.
    pub cmv: f64,
    /// The peak of |f″(u)| on the open interval 0 < u < 1.
    pub ca_inside: f64,
    /// The peak of |f‴(u)| on the open interval 0 < u < 1.
    pub cj_inside: f64,
}
