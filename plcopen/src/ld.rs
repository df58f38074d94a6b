//! The LD objects.

use crate::connection::{ConnectionPointIn, ConnectionPointOut};

/// `edge` of a contact, coil or pin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edge {
    /// `none`.
    None,
    /// `rising` (P).
    Rising,
    /// `falling` (N).
    Falling,
}

impl Edge {
    /// The value of an attribute, or `None` when it is not one of the three.
    pub fn parse(text: &str) -> Option<Edge> {
        match text {
            "none" => Some(Edge::None),
            "rising" => Some(Edge::Rising),
            "falling" => Some(Edge::Falling),
            _ => None,
        }
    }
}

/// `storage` of a coil or pin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// `none`.
    None,
    /// `set` (S).
    Set,
    /// `reset` (R).
    Reset,
}

impl Storage {
    /// The value of an attribute, or `None` when it is not one of the three.
    pub fn parse(text: &str) -> Option<Storage> {
        match text {
            "none" => Some(Storage::None),
            "set" => Some(Storage::Set),
            "reset" => Some(Storage::Reset),
            _ => None,
        }
    }
}

/// `leftPowerRail`.
#[derive(Clone, Debug, PartialEq)]
pub struct LeftPowerRail {
    /// `connectionPointOut` elements in order.
    pub outputs: Vec<ConnectionPointOut>,
}

/// `rightPowerRail`.
#[derive(Clone, Debug, PartialEq)]
pub struct RightPowerRail {
    /// `connectionPointIn` elements in order.
    pub inputs: Vec<ConnectionPointIn>,
}

/// `contact`.
#[derive(Clone, Debug, PartialEq)]
pub struct Contact {
    /// `variable`: the operand.
    pub variable: String,
    /// `negated` (NC).
    pub negated: Option<bool>,
    /// `edge`.
    pub edge: Option<Edge>,
    /// `storage` (unused on contacts, kept as written).
    pub storage: Option<Storage>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}

/// `coil`.
#[derive(Clone, Debug, PartialEq)]
pub struct Coil {
    /// `variable`: the written variable.
    pub variable: String,
    /// `negated`.
    pub negated: Option<bool>,
    /// `edge`.
    pub edge: Option<Edge>,
    /// `storage` (S, R).
    pub storage: Option<Storage>,
    /// `connectionPointIn`.
    pub input: Option<ConnectionPointIn>,
    /// `connectionPointOut`.
    pub output: Option<ConnectionPointOut>,
}
