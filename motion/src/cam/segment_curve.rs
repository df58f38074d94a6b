//! A segment prepared for evaluation: validated, with its coefficients solved once.

use crate::cam::error::CamError;
use crate::cam::key_point::KeyPoint;
use crate::cam::law::MotionLaw;
use crate::cam::polynomial::{Boundary, Polynomial};
use crate::cam::segment::Segment;
use crate::curve::CamSample;

/// Relative tolerance for the boundary conditions of the rest-in-rest laws: the velocity
/// difference and the accelerations, turned into slave displacement over the segment, must be
/// below this fraction of the segment's displacement scale.
const BOUNDARY_TOLERANCE: f64 = 1e-9;

/// A validated segment with everything `sample` needs precomputed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SegmentCurve {
    /// The master position the segment starts at.
    pub(crate) start_master: f64,
    /// The master position the segment ends at.
    pub(crate) end_master: f64,
    /// 1 / (end_master − start_master).
    pub(crate) inv_dx: f64,
    /// How the slave moves inside the segment.
    shape: Shape,
    /// The start key point's values, returned exactly at the start for the quantities the
    /// shape matches there.
    start: CamSample,
    /// The end key point's values, likewise at the end.
    end: CamSample,
    /// How many derivatives the shape matches at its ends: 0 for a line (position only), 1 for
    /// Poly3, 2 for Poly5, 3 for Poly7.
    matched: u8,
}

/// The two ways a segment is evaluated.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    /// Line, Poly3, Poly5 and Poly7: a polynomial in u solved from the key points.
    Polynomial(Polynomial<8>),
    /// A rest-in-rest law superposed on the straight line of the common boundary velocity:
    /// y = y₀ + v·Δx·u + (h − v·Δx)·f(u).
    Superposed {
        /// The law f.
        law: MotionLaw,
        /// Slave position at the start, y₀.
        start_slave: f64,
        /// The common boundary velocity v, dY/dX.
        velocity: f64,
        /// v·Δx, the rise of the straight line over the segment.
        line_rise: f64,
        /// h − v·Δx, the stroke the law adds to the straight line.
        law_stroke: f64,
    },
}

impl SegmentCurve {
    /// Validates segment number `segment` (1-based) from `start` and solves its shape.
    pub(crate) fn new(segment: usize, start: &KeyPoint, spec: &Segment) -> Result<Self, CamError> {
        let end = &spec.end;
        if let Some(field) = end.non_finite_field() {
            return Err(CamError::NonFiniteKeyPoint {
                key_point: segment + 1,
                field,
            });
        }
        let law = spec.law;
        let dx = end.master - start.master;
        if !(dx > 0.0 && dx.is_finite()) {
            return Err(CamError::MasterNotIncreasing {
                segment,
                law,
                start_master: start.master,
                end_master: end.master,
            });
        }
        if let Some(lambda) = spec.lambda {
            return Err(if law == MotionLaw::ModifiedSine {
                CamError::LambdaNotSupported {
                    segment,
                    start_master: start.master,
                    end_master: end.master,
                    lambda,
                }
            } else {
                CamError::LambdaNotApplicable {
                    segment,
                    law,
                    start_master: start.master,
                    end_master: end.master,
                }
            });
        }
        let hermite = |order| {
            Shape::Polynomial(Polynomial::hermite(
                order,
                boundary(start),
                boundary(end),
                dx,
            ))
        };
        let matched = match law {
            MotionLaw::Line => 0,
            MotionLaw::Poly3 => 1,
            MotionLaw::Poly5 => 2,
            MotionLaw::Poly7 => 3,
            // The superposed laws compute their end derivatives exactly (f' and f'' vanish).
            _ => 0,
        };
        let shape = match law {
            MotionLaw::Line => Shape::Polynomial(Polynomial::line(start.slave, end.slave)),
            MotionLaw::Poly3 => hermite(2),
            MotionLaw::Poly5 => hermite(3),
            MotionLaw::Poly7 => hermite(4),
            MotionLaw::ModifiedSine
            | MotionLaw::ModifiedTrapezoid
            | MotionLaw::Cycloid
            | MotionLaw::SimpleHarmonic
            | MotionLaw::InclinedSine => superposed(segment, law, start, end, dx)?,
        };
        Ok(Self {
            start_master: start.master,
            end_master: end.master,
            inv_dx: 1.0 / dx,
            shape,
            start: exact(start),
            end: exact(end),
            matched,
        })
    }

    /// The slave at the normalised position `u` ∈ [0, 1] of the segment.
    #[inline]
    pub(crate) fn evaluate(&self, u: f64) -> CamSample {
        let mut sample = self.evaluate_shape(u);
        // The key points are what the user typed: rounding in the polynomial's sum must not
        // move a segment's ends (360.0000000000001 for 360, or a velocity of 8.5e-15 for 0, in
        // an exported table).
        let key = if u <= 0.0 {
            &self.start
        } else if u >= 1.0 {
            &self.end
        } else {
            return sample;
        };
        sample.position = key.position;
        if self.matched >= 1 {
            sample.velocity = key.velocity;
        }
        if self.matched >= 2 {
            sample.acceleration = key.acceleration;
        }
        if self.matched >= 3 {
            sample.jerk = key.jerk;
        }
        sample
    }

    fn evaluate_shape(&self, u: f64) -> CamSample {
        match self.shape {
            Shape::Polynomial(polynomial) => polynomial.evaluate(u, self.inv_dx),
            Shape::Superposed {
                law,
                start_slave,
                velocity,
                line_rise,
                law_stroke,
            } => {
                let f = law.normalised(u);
                let inv_dx = self.inv_dx;
                let inv_dx2 = inv_dx * inv_dx;
                CamSample {
                    position: start_slave + line_rise * u + law_stroke * f.position,
                    velocity: velocity + law_stroke * f.velocity * inv_dx,
                    acceleration: law_stroke * f.acceleration * inv_dx2,
                    jerk: law_stroke * f.jerk * inv_dx2 * inv_dx,
                }
            }
        }
    }

    /// The slave at the master position `master`, which the caller keeps inside the segment.
    #[inline]
    pub(crate) fn sample(&self, master: f64) -> CamSample {
        self.evaluate(((master - self.start_master) * self.inv_dx).clamp(0.0, 1.0))
    }
}

/// A key point's values as a sample.
fn exact(point: &KeyPoint) -> CamSample {
    CamSample {
        position: point.slave,
        velocity: point.velocity,
        acceleration: point.acceleration,
        jerk: point.jerk,
    }
}

fn boundary(point: &KeyPoint) -> Boundary {
    Boundary {
        position: point.slave,
        velocity: point.velocity,
        acceleration: point.acceleration,
        jerk: point.jerk,
    }
}

/// Checks that a rest-in-rest law can join `start` to `end` (equal velocities, no acceleration)
/// and returns its superposition on the straight line of that velocity.
fn superposed(
    segment: usize,
    law: MotionLaw,
    start: &KeyPoint,
    end: &KeyPoint,
    dx: f64,
) -> Result<Shape, CamError> {
    let stroke = end.slave - start.slave;
    // Velocity and acceleration differences are judged by the slave displacement they would
    // cause over the segment, against the larger of the stroke and the straight line's rise.
    let scale = BOUNDARY_TOLERANCE
        * stroke
            .abs()
            .max(start.velocity.abs() * dx)
            .max(end.velocity.abs() * dx)
            .max(1.0);
    if (end.velocity - start.velocity).abs() * dx > scale {
        return Err(CamError::VelocitiesDiffer {
            segment,
            law,
            start_master: start.master,
            end_master: end.master,
            start_velocity: start.velocity,
            end_velocity: end.velocity,
        });
    }
    if start.acceleration.abs().max(end.acceleration.abs()) * dx * dx > scale {
        return Err(CamError::AccelerationNotZero {
            segment,
            law,
            start_master: start.master,
            end_master: end.master,
            start_acceleration: start.acceleration,
            end_acceleration: end.acceleration,
        });
    }
    let velocity = 0.5 * (start.velocity + end.velocity);
    let line_rise = velocity * dx;
    Ok(Shape::Superposed {
        law,
        start_slave: start.slave,
        velocity,
        line_rise,
        law_stroke: stroke - line_rise,
    })
}
