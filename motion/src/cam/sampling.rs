//! Equidistant sampling of a cam curve, for the 1-D and 2-D table formats.

use crate::cam::error::CamError;
use crate::curve::{CamCurve, CamPoint};

/// `elements` equidistant samples of `curve` over its master range, both ends included
/// (spacing (end − start)/(elements − 1), as CODESYS tables have), with the slave's velocity
/// and acceleration at each sample.
pub fn sample_points<C: CamCurve + ?Sized>(
    curve: &C,
    elements: usize,
) -> Result<Vec<CamPoint>, CamError> {
    if elements < 2 {
        return Err(CamError::TooFewElements { elements });
    }
    let (start, end) = curve.master_range();
    let last = elements - 1;
    let step = (end - start) / last as f64;
    Ok((0..elements)
        .map(|index| {
            // The last element takes the end exactly rather than a sum with rounding in it.
            let master = if index == last {
                end
            } else {
                start + step * index as f64
            };
            let sample = curve.sample(master);
            CamPoint {
                master,
                slave: sample.position,
                velocity: sample.velocity,
                acceleration: sample.acceleration,
            }
        })
        .collect())
}
