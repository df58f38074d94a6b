//! Motion control for Rivet: cam laws and cam table evaluation, tappets, virtual axes,
//! the PLCopen axis state machine, synchronised motion (camming, gearing, phasing) and the
//! motion function blocks.
//!
//! This crate is pure computation: it does no I/O and spawns no threads.
//! The runtime drives it from the task that calls the motion function blocks, and the cam editor
//! uses it to plot position, velocity, acceleration and jerk.

pub mod axis;
pub mod cam;
pub mod curve;
pub mod fb;
pub mod kernel;
pub mod sync;
pub mod table;
pub mod tappet;
