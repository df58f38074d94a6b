//! The motion laws a cam segment can follow, as normalised rest-in-rest transfer functions.

use std::f64::consts::PI;
use std::fmt;

use crate::cam::characteristic::CharacteristicValues;
use crate::curve::CamSample;

/// The motion law of a cam segment, with the names of the project model and VDI 2143.
///
/// Each law has a normalised transfer function f(u) on u ∈ [0, 1] with f(0) = 0 and f(1) = 1
/// (VDI 2143 "rest in rest"); a segment scales it to its master range and stroke.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MotionLaw {
    /// Straight line f(u) = u: constant velocity; a segment uses only its end positions.
    Line,
    /// Cubic polynomial f(u) = 3u² − 2u³; a segment matches position and velocity at both ends.
    Poly3,
    /// Quintic "3-4-5" polynomial f(u) = 10u³ − 15u⁴ + 6u⁵; a segment matches position,
    /// velocity and acceleration at both ends.
    Poly5,
    /// Seventh-degree "4-5-6-7" polynomial f(u) = 35u⁴ − 84u⁵ + 70u⁶ − 20u⁷; a segment also
    /// matches jerk at both ends.
    Poly7,
    /// Modified sine with its inflection points at u = 1/8 and u = 7/8 (sine ramps of the
    /// acceleration over the first and last eighth, a slower sine in between).
    ModifiedSine,
    /// Modified trapezoid: constant acceleration with sine ramps over eighths of the interval.
    ModifiedTrapezoid,
    /// Cycloid f(u) = u − sin(2πu)/(2π): sine-shaped acceleration, zero at both ends.
    Cycloid,
    /// Simple harmonic f(u) = (1 − cos πu)/2: cosine-shaped acceleration that jumps from and to
    /// zero at the ends of a dwell-to-dwell segment.
    SimpleHarmonic,
    /// Inclined sine (Bestehorn's "geneigte Sinuslinie"): a sine drawn on the inclined straight
    /// line from start to end, f(u) = u − sin(2πu)/(2π). Normalised rest in rest it is the same
    /// curve as [`MotionLaw::Cycloid`]; the name is kept because CODESYS and VDI 2143 menus offer it.
    InclinedSine,
}

impl MotionLaw {
    /// Every law, in the order of the declaration.
    pub const ALL: [MotionLaw; 9] = [
        MotionLaw::Line,
        MotionLaw::Poly3,
        MotionLaw::Poly5,
        MotionLaw::Poly7,
        MotionLaw::ModifiedSine,
        MotionLaw::ModifiedTrapezoid,
        MotionLaw::Cycloid,
        MotionLaw::SimpleHarmonic,
        MotionLaw::InclinedSine,
    ];

    /// The normalised transfer function at `u`: f(u) in `position` and f′(u), f″(u), f‴(u) in
    /// the derivative fields, all with respect to u. `u` outside [0, 1] is clamped to it.
    pub fn normalised(self, u: f64) -> CamSample {
        let u = u.clamp(0.0, 1.0);
        match self {
            MotionLaw::Line => sample(u, 1.0, 0.0, 0.0),
            MotionLaw::Poly3 => sample(
                u * u * (3.0 - 2.0 * u),
                6.0 * u * (1.0 - u),
                6.0 - 12.0 * u,
                -12.0,
            ),
            MotionLaw::Poly5 => {
                let u2 = u * u;
                sample(
                    u2 * u * (10.0 + u * (-15.0 + 6.0 * u)),
                    u2 * (30.0 + u * (-60.0 + 30.0 * u)),
                    u * (60.0 + u * (-180.0 + 120.0 * u)),
                    60.0 + u * (-360.0 + 360.0 * u),
                )
            }
            MotionLaw::Poly7 => {
                let u2 = u * u;
                let u3 = u2 * u;
                sample(
                    u3 * u * (35.0 + u * (-84.0 + u * (70.0 - 20.0 * u))),
                    u3 * (140.0 + u * (-420.0 + u * (420.0 - 140.0 * u))),
                    u2 * (420.0 + u * (-1680.0 + u * (2100.0 - 840.0 * u))),
                    u * (840.0 + u * (-5040.0 + u * (8400.0 - 4200.0 * u))),
                )
            }
            MotionLaw::ModifiedSine => modified_sine(u),
            MotionLaw::ModifiedTrapezoid => modified_trapezoid(u),
            MotionLaw::Cycloid | MotionLaw::InclinedSine => {
                let (sin, cos) = (2.0 * PI * u).sin_cos();
                sample(
                    u - sin / (2.0 * PI),
                    1.0 - cos,
                    2.0 * PI * sin,
                    4.0 * PI * PI * cos,
                )
            }
            MotionLaw::SimpleHarmonic => {
                let (sin, cos) = (PI * u).sin_cos();
                sample(
                    0.5 * (1.0 - cos),
                    0.5 * PI * sin,
                    0.5 * PI * PI * cos,
                    -0.5 * PI * PI * PI * sin,
                )
            }
        }
    }

    /// The VDI 2143 characteristic values of the normalised law (see [`CharacteristicValues`]
    /// for how jumps at the ends are reported).
    ///
    /// Closed forms are used where they exist; the other peaks were found by scanning the
    /// derivatives on 200 001 points, and the tests scan them again independently.
    pub fn characteristic_values(self) -> CharacteristicValues {
        match self {
            // The velocity jumps from 0 to 1 at the ends of a dwell-to-dwell line.
            MotionLaw::Line => CharacteristicValues {
                cv: 1.0,
                ca: f64::INFINITY,
                cj: f64::INFINITY,
                cmv: f64::INFINITY,
                ca_inside: 0.0,
                cj_inside: 0.0,
            },
            // The acceleration jumps from 0 to ±6 at the ends, so the jerk is unbounded there.
            MotionLaw::Poly3 => CharacteristicValues {
                cv: 1.5,
                ca: 6.0,
                cj: f64::INFINITY,
                cmv: 2.0 * SQRT_3,
                ca_inside: 6.0,
                cj_inside: 12.0,
            },
            MotionLaw::Poly5 => finite(1.875, 10.0 / SQRT_3, 60.0, 6.694_268_726),
            MotionLaw::Poly7 => finite(2.1875, 7.513_188_404, 52.5, 10.750_226_164),
            MotionLaw::ModifiedSine => finite(
                4.0 * PI * MODIFIED_SINE_K,
                4.0 * PI * PI * MODIFIED_SINE_K,
                16.0 * PI * PI * PI * MODIFIED_SINE_K,
                5.457_752_763,
            ),
            MotionLaw::ModifiedTrapezoid => finite(
                MODIFIED_TRAPEZOID_A * (0.25 + 0.5 / PI),
                MODIFIED_TRAPEZOID_A,
                MODIFIED_TRAPEZOID_A * 4.0 * PI,
                8.089_980_979,
            ),
            MotionLaw::Cycloid | MotionLaw::InclinedSine => {
                finite(2.0, 2.0 * PI, 4.0 * PI * PI, 8.162_097_138)
            }
            // The acceleration jumps from 0 to ±π²/2 at the ends, so the jerk is unbounded there.
            MotionLaw::SimpleHarmonic => CharacteristicValues {
                cv: 0.5 * PI,
                ca: 0.5 * PI * PI,
                cj: f64::INFINITY,
                cmv: PI * PI * PI / 8.0,
                ca_inside: 0.5 * PI * PI,
                cj_inside: 0.5 * PI * PI * PI,
            },
        }
    }
}

impl fmt::Display for MotionLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // The names are those of the CODESYS cam table and the project files' Rust names.
        fmt::Debug::fmt(self, f)
    }
}

/// √3, for the polynomial laws' closed forms.
const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// The modified sine's scale 1/(4 + π), which makes f(1) = 1.
const MODIFIED_SINE_K: f64 = 1.0 / (4.0 + PI);

/// The modified trapezoid's peak acceleration 1/(1/(4π) + 1/8), which makes f(1/2) = 1/2.
const MODIFIED_TRAPEZOID_A: f64 = 1.0 / (0.25 / PI + 0.125);

/// The angular rate 4π of the modified trapezoid's sine ramps, each a quarter wave over 1/8.
const MODIFIED_TRAPEZOID_W: f64 = 4.0 * PI;

fn sample(position: f64, velocity: f64, acceleration: f64, jerk: f64) -> CamSample {
    CamSample {
        position,
        velocity,
        acceleration,
        jerk,
    }
}

fn finite(cv: f64, ca: f64, cj: f64, cmv: f64) -> CharacteristicValues {
    CharacteristicValues {
        cv,
        ca,
        cj,
        cmv,
        ca_inside: ca,
        cj_inside: cj,
    }
}

/// The classic modified sine (Rothbart): quarter waves of period 1/2 over the first and last
/// eighth, a half wave of period 3/2 in between.
fn modified_sine(u: f64) -> CamSample {
    let k = MODIFIED_SINE_K;
    if u <= 0.125 || u >= 0.875 {
        let offset = if u <= 0.125 { 0.0 } else { 4.0 };
        let (sin, cos) = (4.0 * PI * u).sin_cos();
        sample(
            k * (offset + PI * u - 0.25 * sin),
            k * PI * (1.0 - cos),
            k * 4.0 * PI * PI * sin,
            k * 16.0 * PI * PI * PI * cos,
        )
    } else {
        let (sin, cos) = (PI / 3.0 + 4.0 * PI * u / 3.0).sin_cos();
        sample(
            k * (2.0 + PI * u - 2.25 * sin),
            k * PI * (1.0 - 3.0 * cos),
            k * 4.0 * PI * PI * sin,
            k * 16.0 * PI * PI * PI / 3.0 * cos,
        )
    }
}

/// The modified trapezoid, built from its first half by the law's point symmetry about
/// (1/2, 1/2): f(u) = 1 − f(1 − u).
fn modified_trapezoid(u: f64) -> CamSample {
    if u <= 0.5 {
        modified_trapezoid_first_half(u)
    } else {
        let mirrored = modified_trapezoid_first_half(1.0 - u);
        sample(
            1.0 - mirrored.position,
            mirrored.velocity,
            -mirrored.acceleration,
            mirrored.jerk,
        )
    }
}

/// The first half of the modified trapezoid: a sine ramp up to the peak acceleration over
/// [0, 1/8], the constant peak over [1/8, 3/8], and a cosine ramp down from [3/8, 1/2].
/// Each piece starts from the position and velocity the previous one ended at.
fn modified_trapezoid_first_half(u: f64) -> CamSample {
    let a = MODIFIED_TRAPEZOID_A;
    let w = MODIFIED_TRAPEZOID_W;
    if u <= 0.125 {
        let (sin, cos) = (w * u).sin_cos();
        return sample(
            a / w * u - a / (w * w) * sin,
            a / w * (1.0 - cos),
            a * sin,
            a * w * cos,
        );
    }
    let position_1 = a / (8.0 * w) - a / (w * w);
    let velocity_1 = a / w;
    if u <= 0.375 {
        let t = u - 0.125;
        return sample(
            position_1 + velocity_1 * t + 0.5 * a * t * t,
            velocity_1 + a * t,
            a,
            0.0,
        );
    }
    let position_2 = position_1 + 0.25 * velocity_1 + a / 32.0;
    let velocity_2 = velocity_1 + 0.25 * a;
    let t = u - 0.375;
    let (sin, cos) = (w * t).sin_cos();
    sample(
        position_2 + velocity_2 * t + a / (w * w) * (1.0 - cos),
        velocity_2 + a / w * sin,
        a * cos,
        -a * w * sin,
    )
}
