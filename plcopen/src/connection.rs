//! Connection points and connections.

use crate::add_data::AddData;
use crate::header::Point;

/// `connectionPointIn`: the consumer side of a link.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConnectionPointIn {
    /// `relPosition`, relative to the object's position.
    pub rel_position: Option<Point>,
    /// The producers; several make a wired OR in LD.
    pub connections: Vec<Connection>,
    /// `expression`, the schema's alternative to connections.
    pub expression: Option<String>,
    /// Vendor data.
    pub add_data: AddData,
}

/// `connection`: a link to the producer `ref_local_id` of the same body.
#[derive(Clone, Debug, PartialEq)]
pub struct Connection {
    /// `refLocalId`.
    pub ref_local_id: u64,
    /// `formalParameter`: the producer's output pin; `None` when absent, kept apart from `""`.
    pub formal_parameter: Option<String>,
    /// `globalId`.
    pub global_id: Option<String>,
    /// The wire's `position` points, from the consumer to the producer.
    pub points: Vec<Point>,
    /// Vendor data (CODESYS `ldbranchid`).
    pub add_data: AddData,
}

/// `connectionPointOut`: the producer side.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConnectionPointOut {
    /// `relPosition`.
    pub rel_position: Option<Point>,
    /// `formalParameter` (power rails, steps and divergences: Beremiz `""`, CODESYS `none`,
    /// `sfc`, `x`).
    pub formal_parameter: Option<String>,
    /// `expression`: CODESYS's "assign this output to the variable".
    pub expression: Option<String>,
    /// Vendor data.
    pub add_data: AddData,
}
