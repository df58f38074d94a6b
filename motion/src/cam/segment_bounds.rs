//! The derived read-only values of a segment, as in the CODESYS cam table.

use crate::curve::CamSample;

/// Number of sub-intervals scanned for sign changes of a derivative. A polynomial of degree ≤ 7
/// has at most six extrema and the laws at most three per quantity, so a pair of extrema can
/// hide from the scan only when both fall inside one 1/256 of the segment, where the quantity
/// hardly differs from its value at the sub-interval's ends.
const SCAN_INTERVALS: usize = 256;

/// Bisection steps that locate a sign change of a derivative to well below f64 resolution
/// of u.
const BISECTION_STEPS: usize = 60;

/// The derived values of one segment or interval: the CODESYS cam table's read-only columns
/// min(Position), max(Position), max(Velocity) and max(Acceleration), with velocity and
/// acceleration with respect to the master.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentBounds {
    /// The lowest slave position in the segment.
    pub min_position: f64,
    /// The highest slave position in the segment.
    pub max_position: f64,
    /// The largest |dY/dX| in the segment.
    pub max_abs_velocity: f64,
    /// The largest |d²Y/dX²| in the segment.
    pub max_abs_acceleration: f64,
}

impl SegmentBounds {
    /// The bounds of the curve `evaluate` on u ∈ [0, 1].
    ///
    /// The extrema of each quantity are taken at both ends and wherever the next derivative
    /// changes sign, found by scanning and bisection, so they are exact to rounding rather than
    /// the coarse maxima of a sampled plot.
    pub(crate) fn scan(evaluate: impl Fn(f64) -> CamSample) -> Self {
        let first = evaluate(0.0);
        let last = evaluate(1.0);
        let mut bounds = Self {
            min_position: first.position.min(last.position),
            max_position: first.position.max(last.position),
            max_abs_velocity: first.velocity.abs().max(last.velocity.abs()),
            max_abs_acceleration: first.acceleration.abs().max(last.acceleration.abs()),
        };
        let mut previous_u = 0.0;
        let mut previous = first;
        for step in 1..=SCAN_INTERVALS {
            let u = step as f64 / SCAN_INTERVALS as f64;
            let current = evaluate(u);
            if changes_sign(previous.velocity, current.velocity) {
                let at = bisect(&evaluate, previous_u, u, |s| s.velocity);
                bounds.min_position = bounds.min_position.min(at.position);
                bounds.max_position = bounds.max_position.max(at.position);
            }
            if changes_sign(previous.acceleration, current.acceleration) {
                let at = bisect(&evaluate, previous_u, u, |s| s.acceleration);
                bounds.max_abs_velocity = bounds.max_abs_velocity.max(at.velocity.abs());
            }
            if changes_sign(previous.jerk, current.jerk) {
                let at = bisect(&evaluate, previous_u, u, |s| s.jerk);
                bounds.max_abs_acceleration =
                    bounds.max_abs_acceleration.max(at.acceleration.abs());
            }
            previous_u = u;
            previous = current;
        }
        bounds
    }
}

fn changes_sign(a: f64, b: f64) -> bool {
    (a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0)
}

/// The sample at the sign change of `quantity` between `low` and `high`; when the quantity
/// jumps there rather than crossing zero, the sample at the jump, which is where the
/// integrated quantity peaks all the same.
fn bisect(
    evaluate: &impl Fn(f64) -> CamSample,
    mut low: f64,
    mut high: f64,
    quantity: impl Fn(&CamSample) -> f64,
) -> CamSample {
    let low_sign = quantity(&evaluate(low)) > 0.0;
    for _ in 0..BISECTION_STEPS {
        let middle = 0.5 * (low + high);
        if (quantity(&evaluate(middle)) > 0.0) == low_sign {
            low = middle;
        } else {
            high = middle;
        }
    }
    evaluate(0.5 * (low + high))
}
