//! Continuous Function Chart bodies: elements placed freely on a grid, joined by wires.
//!
//! As in CODESYS's CFC editor (explicit execution order mode), every element that does
//! something when the chart runs (a box, an output, a jump, a label, a return, a composer, a
//! selector) has a number in the **execution order**: the chart runs them from 0 upwards. An
//! input reads its expression when an element that uses it runs; a wire from an element later
//! in the order reads the value it left in the previous cycle, which is how a feedback loop
//! works. Positions are grid units (never pixels), so zoom and fonts do not change a file.
//! The rules, checked on load, on save and by every edit (`cfc_check.rs`): ids are unique; the
//! executable elements are numbered 0 to n-1 without gaps or repeats and the others have no
//! number; a wire joins an output pin to an input pin of existing elements; an input pin has
//! at most one wire.

use serde::{Deserialize, Serialize};

use crate::network::{CoilKind, Edge, ElementId};

/// A CFC body: placed elements and the wires between their pins.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CfcChart {
    /// The elements, in no particular order (the execution order is `CfcElement::order`).
    #[serde(default, rename = "element", skip_serializing_if = "Vec::is_empty")]
    pub elements: Vec<CfcElement>,
    /// The wires between pins.
    #[serde(default, rename = "wire", skip_serializing_if = "Vec::is_empty")]
    pub wires: Vec<Wire>,
}

/// One placed element of a chart.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CfcElement {
    /// The stable id, unique in the body.
    pub id: ElementId,
    /// Column of the element's top-left corner, in grid units.
    pub x: i32,
    /// Row of the element's top-left corner, in grid units.
    pub y: i32,
    /// The element's place in the execution order (0 runs first); `None` for the elements
    /// that do not run by themselves (inputs, comments, connection marks).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub order: Option<u32>,
    /// What the element is.
    pub kind: CfcElementKind,
}

/// The kinds of CFC elements.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum CfcElementKind {
    /// A value read into the chart: a variable, a constant or an expression, as written.
    /// Its one output pin is `""`.
    Input {
        /// The expression as written (`???` is how a new input shows before it is typed).
        expression: String,
    },
    /// A variable written by the chart. Its one input pin is `""`.
    Output {
        /// The variable as written.
        expression: String,
        /// How the value is written: directly, negated, or as set/reset (`S`, `R`).
        #[serde(default, skip_serializing_if = "crate::variable::is_default")]
        coil: CoilKind,
    },
    /// A box: an operator, function, function block instance or program call.
    Box(CfcBox),
    /// A jump to a label when its input is TRUE. Its one input pin is `""`.
    Jump {
        /// The target label.
        label: String,
    },
    /// A jump target: the place in the execution order where a jump continues.
    Label {
        /// The label's name.
        name: String,
    },
    /// A return from the POU when its input is TRUE. Its one input pin is `""`.
    Return,
    /// Builds a structure from its members: one input pin per member, the structure on the
    /// output pin `""`.
    Composer {
        /// The structure type.
        type_name: String,
        /// The member inputs, top to bottom.
        #[serde(default, rename = "input", skip_serializing_if = "Vec::is_empty")]
        inputs: Vec<CfcPin>,
    },
    /// Takes a structure apart: the structure on the input pin `""`, one output pin per
    /// member.
    Selector {
        /// The structure type.
        type_name: String,
        /// The member outputs, top to bottom.
        #[serde(default, rename = "output", skip_serializing_if = "Vec::is_empty")]
        outputs: Vec<CfcPin>,
    },
    /// A free comment.
    Comment {
        /// The comment's text.
        text: String,
        /// Width in grid units.
        width: u32,
        /// Height in grid units.
        height: u32,
    },
    /// A connection mark (source): the value wired into its input pin `""` comes out of every
    /// sink of the same name (case-insensitive), so a long wire need not cross the chart.
    ConnectionSource {
        /// The mark's name.
        name: String,
    },
    /// A connection mark (sink): gives the value of the source of the same name on its output
    /// pin `""`.
    ConnectionSink {
        /// The mark's name.
        name: String,
    },
}

/// A box of a chart.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CfcBox {
    /// The operator, function, function block or program name, such as `ADD` or `TON`.
    pub type_name: String,
    /// The function block instance (a variable of the POU); empty for operators, functions
    /// and programs.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub instance: String,
    /// The input pins, top to bottom (`EN` first when the box has EN/ENO).
    #[serde(default, rename = "input", skip_serializing_if = "Vec::is_empty")]
    pub inputs: Vec<CfcPin>,
    /// The output pins, top to bottom (`ENO` first when the box has EN/ENO).
    #[serde(default, rename = "output", skip_serializing_if = "Vec::is_empty")]
    pub outputs: Vec<CfcPin>,
}

/// A pin of a box, composer or selector.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CfcPin {
    /// The pin's name as the block declares it (`IN1`, `PT`, `Q`); a member name on a composer
    /// or selector.
    pub name: String,
    /// The value is negated (the small circle on the pin).
    #[serde(default, skip_serializing_if = "crate::variable::is_false")]
    pub negated: bool,
    /// Edge detection on a BOOL input pin (`R_TRIG`/`F_TRIG` before the box).
    #[serde(default, skip_serializing_if = "crate::variable::is_default")]
    pub edge: Edge,
}

/// A wire from an output pin to an input pin, with the control points the user pinned.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Wire {
    /// The driving output pin.
    pub from: PinRef,
    /// The driven input pin.
    pub to: PinRef,
    /// Control points the route passes through, in grid units, from `from` to `to`; empty for
    /// a wire routed automatically.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<GridPoint>,
}

/// A point of the grid.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridPoint {
    /// Column.
    pub x: i32,
    /// Row.
    pub y: i32,
}

/// A pin of an element: the element's id and the pin's name (empty for an element's only
/// pin).
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct PinRef {
    /// The element.
    pub element: ElementId,
    /// The pin's name.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub pin: String,
}

impl CfcPin {
    /// A pin named `name`, neither negated nor edge-detecting.
    pub fn named(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            ..Self::default()
        }
    }
}

impl PinRef {
    /// The pin `pin` of element `element` (`""` for its only pin).
    pub fn new(element: ElementId, pin: impl Into<String>) -> Self {
        Self {
            element,
            pin: pin.into(),
        }
    }
}

impl Wire {
    /// A wire from `from` to `to` routed automatically (no control points).
    pub fn routed(from: PinRef, to: PinRef) -> Self {
        Self {
            from,
            to,
            points: Vec::new(),
        }
    }
}

impl CfcElementKind {
    /// Whether the element runs by itself and so has a place in the execution order.
    pub fn is_executable(&self) -> bool {
        matches!(
            self,
            Self::Output { .. }
                | Self::Box(_)
                | Self::Jump { .. }
                | Self::Label { .. }
                | Self::Return
                | Self::Composer { .. }
                | Self::Selector { .. }
        )
    }
}
