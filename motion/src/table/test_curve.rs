//! Small curves with known values for the tests of this module.

use crate::curve::{CamCurve, CamSample};

/// The 3-4-5 polynomial rest-to-rest cam of the CODESYS manual's ST example: master 0 to 360,
/// slave 0 to 180, y = 180·(10u³ − 15u⁴ + 6u⁵) with u = x/360.
pub(crate) struct Poly345;

impl CamCurve for Poly345 {
    fn master_range(&self) -> (f64, f64) {
        (0.0, 360.0)
    }

    fn sample(&self, master: f64) -> CamSample {
        let u = master.clamp(0.0, 360.0) / 360.0;
        let stroke = 180.0;
        let width = 360.0;
        CamSample {
            position: stroke * (10.0 * u.powi(3) - 15.0 * u.powi(4) + 6.0 * u.powi(5)),
            // The divisions come last so the test values at quarter points are exact.
            velocity: stroke * 30.0 * u * u * (1.0 - u) * (1.0 - u) / width,
            acceleration: stroke * 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) / (width * width),
            jerk: stroke * 60.0 * (1.0 - 6.0 * u + 6.0 * u * u) / (width * width * width),
        }
    }
}

/// A straight line `slope·(x − start)` over `start..end`.
pub(crate) struct Line {
    pub(crate) start: f64,
    pub(crate) end: f64,
    pub(crate) slope: f64,
}

impl CamCurve for Line {
    fn master_range(&self) -> (f64, f64) {
        (self.start, self.end)
    }

    fn sample(&self, master: f64) -> CamSample {
        let x = master.clamp(self.start, self.end.max(self.start));
        CamSample {
            position: self.slope * (x - self.start),
            velocity: self.slope,
            acceleration: 0.0,
            jerk: 0.0,
        }
    }
}
