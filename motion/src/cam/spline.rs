//! The natural cubic spline through a point table's slave positions.

use crate::curve::CamPoint;

/// The slope dY/dX of the natural cubic spline through `points` at each point.
///
/// The spline's second derivatives Mᵢ solve the tridiagonal system
/// hᵢ₋₁·Mᵢ₋₁ + 2(hᵢ₋₁ + hᵢ)·Mᵢ + hᵢ·Mᵢ₊₁ = 6·(sᵢ − sᵢ₋₁) with M at both ends zero, where hᵢ
/// is the master spacing and sᵢ the chord slope; the slopes follow from them. Each interval of
/// the spline is then the cubic with these end positions and slopes. The caller guarantees at
/// least two points with strictly increasing masters, which keeps the system diagonally
/// dominant.
pub(crate) fn natural_slopes(points: &[CamPoint]) -> Vec<f64> {
    let count = points.len();
    let spacing: Vec<f64> = points
        .windows(2)
        .map(|w| w[1].master - w[0].master)
        .collect();
    let chord: Vec<f64> = points
        .windows(2)
        .zip(&spacing)
        .map(|(w, h)| (w[1].slave - w[0].slave) / h)
        .collect();
    // Thomas algorithm over the inner points 1..count-1; `upper` and `rhs` hold the
    // eliminated system.
    let mut second = vec![0.0; count];
    let inner = count.saturating_sub(2);
    let mut upper = vec![0.0; inner];
    let mut rhs = vec![0.0; inner];
    for k in 0..inner {
        let i = k + 1;
        let lower = spacing[i - 1];
        let mut diagonal = 2.0 * (spacing[i - 1] + spacing[i]);
        let mut value = 6.0 * (chord[i] - chord[i - 1]);
        if k > 0 {
            diagonal -= lower * upper[k - 1];
            value -= lower * rhs[k - 1];
        }
        upper[k] = spacing[i] / diagonal;
        rhs[k] = value / diagonal;
    }
    for k in (0..inner).rev() {
        let next = second[k + 2];
        second[k + 1] = rhs[k] - upper[k] * next;
    }
    let mut slopes = Vec::with_capacity(count);
    for i in 0..count {
        let slope = if i + 1 < count {
            chord[i] - spacing[i] * (2.0 * second[i] + second[i + 1]) / 6.0
        } else {
            chord[i - 1] + spacing[i - 1] * (second[i - 1] + 2.0 * second[i]) / 6.0
        };
        slopes.push(slope);
    }
    slopes
}
