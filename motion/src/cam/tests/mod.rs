//! Tests of the cam module against worked examples, VDI 2143 values and bad input.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod errors;
mod laws;
mod point_tables;
mod properties;
mod worked_examples;
