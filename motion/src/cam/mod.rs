//! Cam curves: the VDI 2143 motion laws, cams made of segments between key points, cams given
//! as point tables, their continuity check and their export to the XYVA and table formats.
//!
//! The types mirror the project model's cam (`project_model::cam`) without depending on it, so
//! the studio converts one into the other and the runtime evaluates cams without the model.

mod characteristic;
mod continuity;
mod error;
mod interpolation;
mod key_point;
mod law;
mod points;
pub(crate) mod polynomial;
mod sampling;
mod segment;
mod segment_bounds;
mod segment_curve;
mod segmented;
mod spline;
#[cfg(test)]
mod tests;

pub use characteristic::CharacteristicValues;
pub use continuity::{
    CONTINUITY_TOLERANCE, ContinuityChecks, ContinuityQuantity, ContinuityWarning, Periodicity,
};
pub use error::CamError;
pub use interpolation::PointInterpolation;
pub use key_point::KeyPoint;
pub use law::MotionLaw;
pub use points::PointCam;
pub use sampling::sample_points;
pub use segment::Segment;
pub use segment_bounds::SegmentBounds;
pub use segmented::SegmentedCam;
