//! How a point table is interpolated between its points.

/// How a point table is interpolated between its points.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PointInterpolation {
    /// Straight lines between the points (CODESYS interpolation quality 1, Omron). The points'
    /// velocities and accelerations are not read.
    #[default]
    Linear,
    /// A natural cubic spline through the slave positions (CODESYS interpolation quality 3):
    /// position, velocity and acceleration are continuous at every point, and the acceleration
    /// is zero at the first and the last point. The points' velocities and accelerations are
    /// not read. Natural rather than not-a-knot because it is defined from two points on (as a
    /// straight line) and because a cam table usually starts and ends at rest or at constant
    /// velocity, where zero acceleration is the right end condition.
    Cubic,
    /// A quintic between consecutive points matching each point's position, velocity and
    /// acceleration (CODESYS XYVA, Delta key points): continuous up to the acceleration.
    Quintic,
}
