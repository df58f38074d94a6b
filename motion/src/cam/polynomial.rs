//! Polynomials in the normalised master coordinate u ∈ [0, 1], solved from boundary values.

use crate::curve::CamSample;

/// A polynomial y(u) = Σ cₖ·uᵏ in the normalised coordinate u = (x − x₀)/Δx of one segment or
/// table interval. Working in u rather than in x keeps the coefficients of long segments
/// (hundreds of master units, seventh powers) in a range where f64 loses nothing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Polynomial<const N: usize> {
    /// The coefficients, constant term first.
    pub(crate) coefficients: [f64; N],
}

/// The position and its first three derivatives at one end of an interval, with respect to the
/// master position x (the units of the key points and table rows).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Boundary {
    /// Position Y.
    pub(crate) position: f64,
    /// dY/dX.
    pub(crate) velocity: f64,
    /// d²Y/dX².
    pub(crate) acceleration: f64,
    /// d³Y/dX³.
    pub(crate) jerk: f64,
}

impl<const N: usize> Polynomial<N> {
    /// The straight line from `start` to `end` in u.
    pub(crate) fn line(start: f64, end: f64) -> Self {
        let mut coefficients = [0.0; N];
        coefficients[0] = start;
        if N > 1 {
            coefficients[1] = end - start;
        }
        Self { coefficients }
    }

    /// The Hermite polynomial of odd degree `2·order − 1` that matches the position and the
    /// first `order − 1` derivatives at both ends of an interval of length `dx` (order 2: cubic,
    /// 3: quintic, 4: seventh degree). `N` must be at least `2·order`.
    ///
    /// The lower half of the coefficients is the Taylor expansion at u = 0; the upper half
    /// solves the conditions at u = 1, a small fixed system that Gaussian elimination handles.
    pub(crate) fn hermite(order: usize, start: Boundary, end: Boundary, dx: f64) -> Self {
        let order = order.clamp(1, 4).min(N / 2);
        let at_start = scaled(start, dx);
        let at_end = scaled(end, dx);
        let mut coefficients = [0.0; N];
        let mut factorial = 1.0;
        for (k, value) in at_start.iter().enumerate().take(order) {
            if k > 0 {
                factorial *= k as f64;
            }
            coefficients[k] = value / factorial;
        }
        // Row d: Σₖ k!/(k−d)!·cₖ at u = 1 equals the d-th derivative at the end, with the known
        // lower coefficients moved to the right-hand side.
        let mut matrix = [[0.0; 4]; 4];
        let mut rhs = [0.0; 4];
        for d in 0..order {
            let mut known = 0.0;
            for (k, coefficient) in coefficients.iter().enumerate().take(order) {
                known += falling_factorial(k, d) * coefficient;
            }
            rhs[d] = at_end[d] - known;
            for (column, entry) in matrix[d].iter_mut().enumerate().take(order) {
                *entry = falling_factorial(order + column, d);
            }
        }
        let solution = solve(matrix, rhs, order);
        for (column, value) in solution.iter().enumerate().take(order) {
            coefficients[order + column] = *value;
        }
        Self { coefficients }
    }

    /// The position and its derivatives with respect to x at `u`, for an interval whose
    /// reciprocal length is `inv_dx`.
    #[inline]
    pub(crate) fn evaluate(&self, u: f64, inv_dx: f64) -> CamSample {
        // Horner's scheme carried along for the first three derivatives at once.
        let mut position = 0.0;
        let mut velocity = 0.0;
        let mut acceleration = 0.0;
        let mut jerk = 0.0;
        for &coefficient in self.coefficients.iter().rev() {
            jerk = jerk * u + acceleration;
            acceleration = acceleration * u + velocity;
            velocity = velocity * u + position;
            position = position * u + coefficient;
        }
        let inv_dx2 = inv_dx * inv_dx;
        CamSample {
            position,
            velocity: velocity * inv_dx,
            acceleration: 2.0 * acceleration * inv_dx2,
            jerk: 6.0 * jerk * inv_dx2 * inv_dx,
        }
    }
}

/// The boundary derivatives with respect to u: the d-th derivative scales with Δxᵈ.
fn scaled(boundary: Boundary, dx: f64) -> [f64; 4] {
    [
        boundary.position,
        boundary.velocity * dx,
        boundary.acceleration * dx * dx,
        boundary.jerk * dx * dx * dx,
    ]
}

/// k·(k−1)·…·(k−d+1), the factor the d-th derivative of uᵏ has at u = 1.
fn falling_factorial(k: usize, d: usize) -> f64 {
    if d > k {
        return 0.0;
    }
    ((k - d + 1)..=k).map(|factor| factor as f64).product()
}

/// Solves the leading `size`×`size` block of `matrix`·x = `rhs` by Gaussian elimination with
/// partial pivoting. The matrices here are the fixed Hermite systems, which are regular.
fn solve(mut matrix: [[f64; 4]; 4], mut rhs: [f64; 4], size: usize) -> [f64; 4] {
    for pivot in 0..size {
        let mut best = pivot;
        for row in pivot + 1..size {
            if matrix[row][pivot].abs() > matrix[best][pivot].abs() {
                best = row;
            }
        }
        matrix.swap(pivot, best);
        rhs.swap(pivot, best);
        let pivot_row = matrix[pivot];
        for row in pivot + 1..size {
            let factor = matrix[row][pivot] / pivot_row[pivot];
            let entries = matrix[row][pivot..size].iter_mut();
            for (entry, above) in entries.zip(&pivot_row[pivot..size]) {
                *entry -= factor * above;
            }
            rhs[row] -= factor * rhs[pivot];
        }
    }
    let mut solution = [0.0; 4];
    for row in (0..size).rev() {
        let mut value = rhs[row];
        for column in row + 1..size {
            value -= matrix[row][column] * solution[column];
        }
        solution[row] = value / matrix[row][row];
    }
    solution
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boundary(position: f64, velocity: f64, acceleration: f64, jerk: f64) -> Boundary {
        Boundary {
            position,
            velocity,
            acceleration,
            jerk,
        }
    }

    #[track_caller]
    fn assert_close(actual: f64, expected: f64) {
        assert!(
            (actual - expected).abs() <= 1e-9 * expected.abs().max(1.0),
            "{actual} is not {expected}"
        );
    }

    #[test]
    fn hermite_polynomials_meet_general_boundary_values_at_both_ends() {
        let start = boundary(-3.5, 2.25, -0.75, 0.125);
        let end = boundary(17.0, -1.5, 0.5, -0.0625);
        let dx = 7.25;
        for order in 2..=4 {
            let polynomial = Polynomial::<8>::hermite(order, start, end, dx);
            for (u, expected) in [(0.0, start), (1.0, end)] {
                let sample = polynomial.evaluate(u, 1.0 / dx);
                assert_close(sample.position, expected.position);
                assert_close(sample.velocity, expected.velocity);
                if order >= 3 {
                    assert_close(sample.acceleration, expected.acceleration);
                }
                if order >= 4 {
                    assert_close(sample.jerk, expected.jerk);
                }
            }
        }
    }

    #[test]
    fn the_rest_in_rest_quintic_is_the_3_4_5_polynomial() {
        let polynomial =
            Polynomial::<6>::hermite(3, Boundary::default(), boundary(1.0, 0.0, 0.0, 0.0), 1.0);
        let expected = [0.0, 0.0, 0.0, 10.0, -15.0, 6.0];
        for (actual, expected) in polynomial.coefficients.iter().zip(expected) {
            assert_close(*actual, expected);
        }
    }
}
