//! The continuity check of a cam: jumps of position, velocity, acceleration or jerk where two
//! segments or table intervals meet, and across the period of a periodic cam.

use crate::curve::CamSample;

/// Relative tolerance of the continuity check. A quantity counts as continuous when its two
/// sides differ by at most this fraction of the quantity's scale in the cam: the largest
/// magnitude it has at any joint side, or the slave scale divided by the master span to the
/// power of the derivative's order, whichever is larger. The slave scale is the largest of the
/// joint positions' magnitudes, their spread, and the largest joint velocity times the master
/// span (the distance that velocity covers over the cam). Rounding in the solved coefficients stays near
/// 1e-12 of that scale, and a kink a user can see is far above 1e-6.
pub const CONTINUITY_TOLERANCE: f64 = 1e-6;

/// Which quantities the continuity check compares (mirrors the project model's
/// `CamContinuity`; the defaults are those of CODESYS: position, velocity and acceleration).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContinuityChecks {
    /// Compare slave positions.
    pub position: bool,
    /// Compare dY/dX.
    pub velocity: bool,
    /// Compare d²Y/dX².
    pub acceleration: bool,
    /// Compare d³Y/dX³.
    pub jerk: bool,
}

impl Default for ContinuityChecks {
    fn default() -> Self {
        Self {
            position: true,
            velocity: true,
            acceleration: true,
            jerk: false,
        }
    }
}

/// Whether the cam runs periodically, so that its end must join its start.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Periodicity {
    /// The cam runs once; its ends are not compared.
    #[default]
    NonPeriodic,
    /// The cam repeats; the end is compared with the start.
    Periodic {
        /// The end slave position may differ from the start by a whole multiple of this, as
        /// for a rotary slave that turns on by one revolution per cam period.
        slave_period: Option<f64>,
    },
}

/// A quantity the continuity check compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ContinuityQuantity {
    /// Slave position.
    Position,
    /// dY/dX.
    Velocity,
    /// d²Y/dX².
    Acceleration,
    /// d³Y/dX³.
    Jerk,
}

/// A discontinuity found by the continuity check.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContinuityWarning {
    /// The key point (segmented cam) or row (point table) where the jump is, 1-based; the
    /// period joint of a periodic cam is reported at 1, the start.
    pub joint: usize,
    /// The master position of the joint.
    pub master: f64,
    /// The quantity that jumps.
    pub quantity: ContinuityQuantity,
    /// The value on the side of lower master (for the period joint: at the cam's end).
    pub left: f64,
    /// The value on the side of higher master (for the period joint: at the cam's start).
    pub right: f64,
}

/// Both sides of one inner joint.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Joint {
    /// The 1-based key point or row.
    pub(crate) key_point: usize,
    /// Its master position.
    pub(crate) master: f64,
    /// The end of the segment before it.
    pub(crate) left: CamSample,
    /// The start of the segment after it.
    pub(crate) right: CamSample,
}

/// Compares both sides of every joint, and for a periodic cam the `last` sample with the
/// `first`, for the quantities `checks` selects.
pub(crate) fn check(
    joints: impl Iterator<Item = Joint>,
    first: CamSample,
    last: CamSample,
    (master_start, master_end): (f64, f64),
    checks: ContinuityChecks,
    periodicity: Periodicity,
) -> Vec<ContinuityWarning> {
    let joints: Vec<Joint> = joints.collect();
    let mut checker = Checker {
        selected: [
            checks.position,
            checks.velocity,
            checks.acceleration,
            checks.jerk,
        ],
        tolerances: tolerances(&joints, first, last, master_end - master_start),
        warnings: Vec::new(),
    };
    for joint in &joints {
        checker.compare(joint.key_point, joint.master, joint.left, joint.right, None);
    }
    if let Periodicity::Periodic { slave_period } = periodicity {
        let slave_period = slave_period.filter(|period| period.is_finite() && *period != 0.0);
        checker.compare(1, master_start, last, first, slave_period);
    }
    checker.warnings
}

/// The state of one continuity check: what to compare, how closely, and what was found.
struct Checker {
    /// Whether position, velocity, acceleration and jerk are compared.
    selected: [bool; 4],
    /// The absolute tolerance of each quantity.
    tolerances: [f64; 4],
    /// The discontinuities found so far.
    warnings: Vec<ContinuityWarning>,
}

impl Checker {
    /// Compares the selected quantities of both sides of one joint.
    fn compare(
        &mut self,
        joint: usize,
        master: f64,
        left: CamSample,
        right: CamSample,
        slave_period: Option<f64>,
    ) {
        let sides = quantities(left).into_iter().zip(quantities(right));
        for (index, ((quantity, left), (_, right))) in sides.enumerate() {
            if !self.selected[index] {
                continue;
            }
            let mut difference = right - left;
            if let (ContinuityQuantity::Position, Some(period)) = (quantity, slave_period) {
                difference -= period * (difference / period).round();
            }
            // A NaN difference is reported too, which is what a broken value deserves.
            if difference.is_nan() || difference.abs() > self.tolerances[index] {
                self.warnings.push(ContinuityWarning {
                    joint,
                    master,
                    quantity,
                    left,
                    right,
                });
            }
        }
    }
}

/// The four quantities of a sample with their order of derivative.
fn quantities(sample: CamSample) -> [(ContinuityQuantity, f64); 4] {
    [
        (ContinuityQuantity::Position, sample.position),
        (ContinuityQuantity::Velocity, sample.velocity),
        (ContinuityQuantity::Acceleration, sample.acceleration),
        (ContinuityQuantity::Jerk, sample.jerk),
    ]
}

/// The absolute tolerance of each quantity, as [`CONTINUITY_TOLERANCE`] describes.
fn tolerances(joints: &[Joint], first: CamSample, last: CamSample, master_span: f64) -> [f64; 4] {
    let samples = joints
        .iter()
        .flat_map(|joint| [joint.left, joint.right])
        .chain([first, last]);
    let mut largest = [0.0_f64; 4];
    let mut lowest = f64::INFINITY;
    let mut highest = f64::NEG_INFINITY;
    for sample in samples {
        for (index, (_, value)) in quantities(sample).into_iter().enumerate() {
            largest[index] = largest[index].max(value.abs());
        }
        lowest = lowest.min(sample.position);
        highest = highest.max(sample.position);
    }
    let slave_scale = largest[0]
        .max(highest - lowest)
        .max(largest[1] * master_span);
    let mut tolerances = [0.0; 4];
    let mut natural = slave_scale;
    for (index, tolerance) in tolerances.iter_mut().enumerate() {
        *tolerance = CONTINUITY_TOLERANCE * largest[index].max(natural);
        natural /= master_span;
    }
    tolerances
}
