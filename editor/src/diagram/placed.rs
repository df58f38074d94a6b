//! A network laid out: elements, wires and insertion points in grid units, ready to paint and
//! to hit-test. The LD and FBD layouts produce it; the canvas scales it to pixels.

use egui::{Pos2, Rect, Vec2};
use project_model::{Anchor, CoilKind, Edge, ElementId, ParallelSide, Side};

/// One network laid out in grid units (a cell is one unit wide and one unit high); the origin is
/// the network's top-left corner below its header. Rebuilt whenever the network changes, never
/// saved.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NetworkLayout {
    /// The width and height of the network's drawing, in cells.
    pub size: Vec2,
    /// The elements, in the model's display order.
    pub elements: Vec<PlacedElement>,
    /// The connecting lines.
    pub wires: Vec<Wire>,
    /// The places a dragged element or a keyboard command can insert at.
    pub insert_points: Vec<InsertPoint>,
}

/// One element placed in the grid.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedElement {
    /// The model element drawn; `None` for a drawing-only box (the AND box of a chain in FBD).
    pub id: Option<ElementId>,
    /// Where it is drawn, in cells.
    pub rect: Rect,
    /// What is drawn.
    pub shape: Shape,
    /// What powers its input, for the online colours of its left lead.
    pub power_in: Power,
}

/// What an element looks like.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// An LD contact: `| |`, `|/|`, `|P|`, `|N|` with its operand above.
    Contact {
        /// The operand as written.
        text: String,
        /// A normally closed contact.
        negated: bool,
        /// An edge contact.
        edge: Edge,
    },
    /// An LD coil: `( )`, `(/)`, `(S)`, `(R)`, `(P)`, `(N)` with its variable above.
    Coil {
        /// The variable written.
        variable: String,
        /// How it writes.
        kind: CoilKind,
    },
    /// An FBD assignment: a line into a variable box, marked for set, reset and edges.
    Assignment {
        /// The variable written.
        variable: String,
        /// How it writes.
        kind: CoilKind,
    },
    /// A variable, literal or expression read into a pin (an FBD input, a box's LD operand).
    Variable {
        /// The text as written.
        text: String,
        /// A negation circle at its output.
        negated: bool,
        /// An edge marker at its output.
        edge: Edge,
    },
    /// A jump to a label.
    Jump {
        /// The target network's label.
        label: String,
    },
    /// A return from the POU.
    Return,
    /// A parallel group: drawn by its rails and branches, selectable as a whole around them.
    Group,
    /// A box: a call, or FBD's AND and OR of a chain and a parallel group.
    Box {
        /// The block's name, such as `TON`, `AND`.
        type_name: String,
        /// The instance of a function block; empty otherwise.
        instance: String,
        /// The input pins.
        inputs: Vec<PinMark>,
        /// The output pins.
        outputs: Vec<PinMark>,
    },
}

/// A pin of a box: its name and where its line meets the box.
#[derive(Clone, Debug, PartialEq)]
pub struct PinMark {
    /// The formal parameter's name; empty for the unnamed inputs of FBD's AND and OR.
    pub name: String,
    /// The row of the pin's line, in cells from the network's top (a line runs at `row + 0.5`).
    pub row: f32,
    /// A negation circle on the pin.
    pub negated: bool,
    /// An edge marker on the pin.
    pub edge: Edge,
}

/// A connecting line of straight segments.
#[derive(Clone, Debug, PartialEq)]
pub struct Wire {
    /// The corner points, in cells.
    pub points: Vec<Pos2>,
    /// What the line carries, for the online colours.
    pub power: Power,
}

/// Where the power on a line comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Power {
    /// The left power rail, TRUE whenever the program runs.
    Rail,
    /// The output of this element.
    After(ElementId),
    /// Nothing known (an unconnected pin).
    None,
}

/// A place the user can insert at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InsertPoint {
    /// The point's position, in cells.
    pub pos: Pos2,
    /// What inserting there means.
    pub target: InsertTarget,
}

/// What inserting at an insertion point means, as the model's operations see it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InsertTarget {
    /// In series beside an element, or at the end of a network's rung.
    Series {
        /// The element or network.
        anchor: Anchor,
        /// Before or after it.
        side: Side,
    },
    /// In a branch parallel to an element.
    Parallel {
        /// The element.
        id: ElementId,
        /// Above or below it.
        side: ParallelSide,
    },
    /// Among the outputs: below an output, or at the end of a network's outputs.
    Output {
        /// The output or network.
        anchor: Anchor,
    },
}

impl Shape {
    /// The text the user wrote for the element: its operand, variable or jump label.
    pub fn text(&self) -> Option<&str> {
        match self {
            Self::Contact { text, .. } | Self::Variable { text, .. } => Some(text),
            Self::Coil { variable, .. } | Self::Assignment { variable, .. } => Some(variable),
            Self::Jump { label } => Some(label),
            Self::Return | Self::Group | Self::Box { .. } => None,
        }
    }
}

impl NetworkLayout {
    /// Adds an insertion point at `pos` for `target`, while a layout is built.
    pub(super) fn insert(&mut self, pos: Pos2, target: InsertTarget) {
        self.insert_points.push(InsertPoint { pos, target });
    }

    /// Adds a wire through `points` carrying `power`, while a layout is built.
    pub(super) fn wire(&mut self, points: Vec<Pos2>, power: Power) {
        self.wires.push(Wire { points, power });
    }

    /// The element drawn at `pos` (in cells), the innermost when several overlap.
    pub fn element_at(&self, pos: Pos2) -> Option<&PlacedElement> {
        self.elements
            .iter()
            .rev()
            .filter(|element| element.id.is_some())
            .find(|element| element.rect.contains(pos))
    }

    /// The placed element of `id`.
    pub fn element(&self, id: ElementId) -> Option<&PlacedElement> {
        self.elements.iter().find(|element| element.id == Some(id))
    }

    /// The insertion point nearest to `pos` within `radius` cells.
    pub fn insert_point_near(&self, pos: Pos2, radius: f32) -> Option<&InsertPoint> {
        self.insert_points
            .iter()
            .map(|point| (point, point.pos.distance(pos)))
            .filter(|(_, distance)| *distance <= radius)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(point, _)| point)
    }
}
