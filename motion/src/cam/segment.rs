//! One segment of a segmented cam, as the user describes it.

use crate::cam::key_point::KeyPoint;
use crate::cam::law::MotionLaw;

/// One segment of a segmented cam, from the previous key point to `end` (mirrors the project
/// model's `CamSegment`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// The motion law between the two key points.
    pub law: MotionLaw,
    /// The CODESYS inflection parameter λ of a modified sine. It is not supported: a segment
    /// with it set is refused rather than silently run as the classic law.
    pub lambda: Option<f64>,
    /// The key point the segment ends at.
    pub end: KeyPoint,
}

impl Segment {
    /// A segment following `law` to `end`, without λ.
    pub fn new(law: MotionLaw, end: KeyPoint) -> Self {
        Self {
            law,
            lambda: None,
            end,
        }
    }
}
