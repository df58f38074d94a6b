//! A graph of FBD objects → a [`CfcChart`] (docs/plcopen-xml.md §4.5): CODESYS's CFC
//! (`Body::cfc`), an FBD body Rivet's export marked as CFC, any FBD graph (the LD/FBD import
//! falls back to it for feedback loops and fan-out) and the FBD graph of a wired SFC condition.

use std::collections::{HashMap, HashSet};

use project_model::{
    CfcBox, CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, ElementId, GridPoint, PinRef,
    Wire,
};

use super::body_fault::{BodyFault, object_place};
use super::cfc_order::{OrderedElement, execution_order};
use super::converter::Place;
use super::error::ImportErrorKind;
use crate::body_object::{BodyObject, ObjectKind};
use crate::connection::{Connection, ConnectionPointIn};
use crate::fbd::{Block, BlockPin, InOutVariable};
use crate::header::Point;
use crate::ld::{Edge, Storage};

/// Who wrote a graph, which says how its positions and execution order ids read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum CfcDialect {
    /// CODESYS's CFC: positions in grid units; `executionOrderId`s rank the elements that data
    /// flow leaves free (CODESYS's default "auto data flow" mode computes the order from the
    /// wires, and files carry numbers that run against them).
    Codesys,
    /// Rivet's own export: positions are grid units × 10; `executionOrderId` is the order + 1,
    /// kept exactly (a feedback loop depends on it).
    Rivet,
    /// Beremiz and other free-placement editors: pixels, read at 10 per grid unit;
    /// `executionOrderId`s above 0 kept exactly, else Beremiz's generator's order.
    Beremiz,
}

impl CfcDialect {
    /// Positions per grid unit.
    fn pitch(self) -> f64 {
        match self {
            CfcDialect::Codesys => 1.0,
            CfcDialect::Rivet | CfcDialect::Beremiz => f64::from(PIXELS_PER_GRID_UNIT),
        }
    }
}

/// The least distance, in grid units, from the output of an in-out's pair to its input.
const IN_OUT_MIN_WIDTH: u32 = 4;

/// The pitch at which Rivet's exported positions and Beremiz's pixels become grid units.
pub(crate) const PIXELS_PER_GRID_UNIT: u32 = 10;

/// Converts the FBD graph `objects` (document order) of the body at `body_path` (line
/// `body_line`) into a chart; `structures` are the lower-case names of the document's
/// structure types, which a block with one unnamed output composes (input selects).
pub(crate) fn fbd_graph_to_cfc(
    objects: &[BodyObject],
    dialect: CfcDialect,
    body_path: &str,
    body_line: u32,
    structures: &HashSet<String>,
) -> Result<CfcChart, BodyFault> {
    let mut builder = CfcChartBuilder::new(
        objects.iter().collect(),
        dialect,
        body_path,
        body_line,
        structures,
    );
    builder.build()?;
    builder.finish()
}

/// A chart in the making from a graph of objects.
pub(super) struct CfcChartBuilder<'o> {
    /// The lower-case names of the document's structure types.
    structures: &'o HashSet<String>,
    /// The objects converted, in document order.
    objects: Vec<&'o BodyObject>,
    /// The same objects by `localId`.
    by_local_id: HashMap<u64, &'o BodyObject>,
    /// Who wrote the graph.
    dialect: CfcDialect,
    /// The element path of the body, for errors.
    body_path: String,
    /// Line of the body, for errors about the chart as a whole.
    body_line: u32,
    /// The element made of each object that has one (unnamed connectors have none); for an
    /// `inOutVariable`, the input its readers are wired from.
    element_of: HashMap<u64, ElementId>,
    /// The output that writes the variable of each `inOutVariable`, by `localId`.
    in_out_writes: HashMap<u64, ElementId>,
    /// The elements so far, in document order.
    elements: Vec<OrderedElement>,
    /// The wires so far.
    wires: Vec<Wire>,
    /// Grid places already holding an element's top-left corner.
    taken_places: HashSet<(i32, i32)>,
    /// The last element id given out.
    last_id: u32,
}

impl<'o> CfcChartBuilder<'o> {
    /// A builder for `objects` (document order) of a document whose structure types are
    /// `structures` (lower-case names).
    pub fn new(
        objects: Vec<&'o BodyObject>,
        dialect: CfcDialect,
        body_path: &str,
        body_line: u32,
        structures: &'o HashSet<String>,
    ) -> Self {
        let by_local_id = objects
            .iter()
            .map(|object| (object.local_id, *object))
            .collect();
        Self {
            structures,
            objects,
            by_local_id,
            dialect,
            body_path: body_path.to_owned(),
            body_line,
            element_of: HashMap::new(),
            in_out_writes: HashMap::new(),
            elements: Vec::new(),
            wires: Vec::new(),
            taken_places: HashSet::new(),
            last_id: 0,
        }
    }

    fn place_of(&self, object: &BodyObject) -> Place {
        object_place(
            &self.body_path,
            object.kind.element_name(),
            object.local_id,
            object.line,
            object.column,
        )
    }

    /// Makes an element of every object, then a wire of every connection.
    pub fn build(&mut self) -> Result<(), BodyFault> {
        let objects = self.objects.clone();
        for object in &objects {
            self.element(object)?;
        }
        for object in &objects {
            self.wires_into(object)?;
        }
        Ok(())
    }

    fn element(&mut self, object: &BodyObject) -> Result<(), BodyFault> {
        let kind = match &object.kind {
            // A box pin has a name; Rivet's export writes a composer's structure output and a
            // selector's structure input as the one unnamed pin of a block (§5.2). Beremiz
            // names a function's result "" too, so only a block of a structure type without
            // an instance is taken for one.
            ObjectKind::Block(block)
                if self.composes_structure(block) && is_unnamed_pin(&block.outputs) =>
            {
                CfcElementKind::Composer {
                    type_name: block.type_name.clone(),
                    inputs: block.inputs.iter().map(pin).collect(),
                }
            }
            ObjectKind::Block(block)
                if self.composes_structure(block) && is_unnamed_pin(&block.inputs) =>
            {
                CfcElementKind::Selector {
                    type_name: block.type_name.clone(),
                    outputs: block.outputs.iter().map(pin).collect(),
                }
            }
            ObjectKind::Block(block) => CfcElementKind::Box(CfcBox {
                type_name: block.type_name.clone(),
                instance: block.instance_name.clone().unwrap_or_default(),
                inputs: block.inputs.iter().chain(&block.in_outs).map(pin).collect(),
                outputs: block
                    .outputs
                    .iter()
                    .chain(&block.in_outs)
                    .map(|output| CfcPin {
                        name: result_pin_name(&output.formal_parameter),
                        ..pin(output)
                    })
                    .collect(),
            }),
            ObjectKind::InVariable(variable) => {
                if matches!(variable.edge, Some(Edge::Rising | Edge::Falling)) {
                    return Err(BodyFault::NotConverted(format!(
                        "the inVariable `{}` at line {} detects an edge, which a chart's input cannot",
                        variable.expression, object.line
                    )));
                }
                let expression = variable.expression.trim();
                CfcElementKind::Input {
                    expression: if variable.negated == Some(true) {
                        format!("NOT ({expression})")
                    } else {
                        expression.to_owned()
                    },
                }
            }
            ObjectKind::OutVariable(variable) => CfcElementKind::Output {
                expression: variable.expression.trim().to_owned(),
                coil: coil_kind(variable.negated, variable.edge, variable.storage),
            },
            ObjectKind::Label(label) => CfcElementKind::Label {
                name: label.label.clone(),
            },
            ObjectKind::Jump(jump) => CfcElementKind::Jump {
                label: jump.label.clone(),
            },
            ObjectKind::Return(_) => CfcElementKind::Return,
            // CODESYS's unnamed connectors are the junctions of its wires: no element.
            ObjectKind::Connector(connector) if connector.name.trim().is_empty() => return Ok(()),
            ObjectKind::Connector(connector) => CfcElementKind::ConnectionSource {
                name: connector.name.clone(),
            },
            ObjectKind::Continuation(continuation) if continuation.name.trim().is_empty() => {
                return Err(BodyFault::Error(
                    self.place_of(object),
                    ImportErrorKind::BadCfc(
                        "an unnamed continuation reads no connector".to_owned(),
                    ),
                ));
            }
            ObjectKind::Continuation(continuation) => CfcElementKind::ConnectionSink {
                name: continuation.name.clone(),
            },
            ObjectKind::InOutVariable(variable) => return self.in_out(object, variable),
            ObjectKind::Comment(text) => CfcElementKind::Comment {
                text: text.text.trim().to_owned(),
                width: self.extent(object.size.width),
                height: self.extent(object.size.height),
            },
            ObjectKind::VendorElement(_) => {
                // CODESYS names the kind in `…/cfcelementtype` in a CFC, `…/fbdelementtype` in
                // an FBD body.
                let element_type = ["/cfcelementtype", "/fbdelementtype"]
                    .into_iter()
                    .find_map(|suffix| object.add_data.entry_ending_with(suffix))
                    .and_then(|entry| vendor_element_type(&entry.xml))
                    .unwrap_or_else(|| "vendorElement".to_owned());
                return Err(BodyFault::NotConverted(format!(
                    "its {element_type} at line {} is another tool's own element (a vendorElement): its meaning (for CODESYS's composer and selector, the structure and its members) stays in that tool's data, which this import does not read",
                    object.line
                )));
            }
            other => {
                return Err(BodyFault::NotConverted(format!(
                    "its {} at line {} has no counterpart in a CFC chart",
                    other.element_name(),
                    object.line
                )));
            }
        };
        let (x, y) = self.grid_place(object.position.as_ref());
        let id = self.push(x, y, kind, object.execution_order_id, None);
        self.element_of.insert(object.local_id, id);
        Ok(())
    }

    /// Whether `block` may be a composer or selector: no in-outs, no instance, and a type that
    /// is a structure of the document (or any type, in Rivet's own export, which writes them
    /// so for structures of libraries too).
    fn composes_structure(&self, block: &Block) -> bool {
        block.in_outs.is_empty()
            && block
                .instance_name
                .as_deref()
                .is_none_or(|name| name.trim().is_empty())
            && (self.dialect == CfcDialect::Rivet
                || self
                    .structures
                    .contains(&block.type_name.trim().to_lowercase()))
    }

    /// Whether `block` becomes a box (not a composer or selector).
    fn is_box(&self, block: &Block) -> bool {
        !(self.composes_structure(block)
            && (is_unnamed_pin(&block.outputs) || is_unnamed_pin(&block.inputs)))
    }

    /// An `inOutVariable` as an output writing its variable and, to the right of it, an input
    /// reading the variable, which its readers are wired from (docs/plcopen-xml.md §4.5). An
    /// in-out nothing is wired into writes nothing: it is the input alone.
    fn in_out(&mut self, object: &BodyObject, variable: &InOutVariable) -> Result<(), BodyFault> {
        let expression = variable.expression.trim();
        if matches!(variable.edge_out, Some(Edge::Rising | Edge::Falling)) {
            return Err(BodyFault::NotConverted(format!(
                "the inOutVariable `{expression}` at line {} detects an edge on its output, which a chart's input cannot",
                object.line
            )));
        }
        if matches!(variable.storage_out, Some(Storage::Set | Storage::Reset)) {
            return Err(BodyFault::NotConverted(format!(
                "the inOutVariable `{expression}` at line {} stores its output, which a chart's input cannot",
                object.line
            )));
        }
        let (x, y) = self.grid_place(object.position.as_ref());
        let read = CfcElementKind::Input {
            expression: if variable.negated_out == Some(true) {
                format!("NOT ({expression})")
            } else {
                expression.to_owned()
            },
        };
        let written = variable.input.as_ref().is_some_and(|point| {
            !point.connections.is_empty()
                || point
                    .expression
                    .as_deref()
                    .is_some_and(|text| !text.trim().is_empty())
        });
        if !written {
            let input = self.push(x, y, read, None, None);
            self.element_of.insert(object.local_id, input);
            return Ok(());
        }
        let write = CfcElementKind::Output {
            expression: expression.to_owned(),
            coil: coil_kind(variable.negated_in, variable.edge_in, variable.storage_in),
        };
        let output = self.push(x, y, write, object.execution_order_id, None);
        // Right of the output by the in-out's width, so the two stand where it stood.
        let width = self.extent(object.size.width).max(IN_OUT_MIN_WIDTH);
        let gap = i32::try_from(width).unwrap_or(i32::MAX);
        let input = self.push(x.saturating_add(gap), y, read, None, Some(output));
        self.in_out_writes.insert(object.local_id, output);
        self.element_of.insert(object.local_id, input);
        Ok(())
    }

    /// Adds an element at the first free place from (`x`, `y`) downwards (upwards from the
    /// chart's last row); returns its id.
    fn push(
        &mut self,
        x: i32,
        y: i32,
        kind: CfcElementKind,
        execution_order_id: Option<u64>,
        reads_write_of: Option<ElementId>,
    ) -> ElementId {
        // Rounding pixels to the grid may bring two elements onto one place: keep them apart.
        // The column holds more rows than the chart has elements, so a free one is found.
        let below = (y..=i32::MAX).map(|row| (x, row));
        let above = (i32::MIN..y).rev().map(|row| (x, row));
        let free = below
            .chain(above)
            .find(|place| !self.taken_places.contains(place))
            .unwrap_or((x, y));
        self.taken_places.insert(free);
        let (x, y) = free;
        self.last_id += 1;
        let id = ElementId(self.last_id);
        self.elements.push(OrderedElement {
            element: CfcElement {
                id,
                x,
                y,
                order: None,
                kind,
            },
            execution_order_id,
            reads_write_of,
        });
        id
    }

    fn wires_into(&mut self, object: &BodyObject) -> Result<(), BodyFault> {
        let Some(&element) = self.element_of.get(&object.local_id) else {
            return Ok(());
        };
        let place = self.place_of(object);
        match &object.kind {
            ObjectKind::InOutVariable(variable) => {
                let output = self.in_out_writes.get(&object.local_id).copied();
                if let (Some(point), Some(output)) = (&variable.input, output) {
                    self.wire_into(point, PinRef::new(output, ""), &place)?;
                }
            }
            ObjectKind::Block(block) => {
                for input in block.inputs.iter().chain(&block.in_outs) {
                    if let Some(point) = &input.input {
                        let to = PinRef::new(element, input.formal_parameter.clone());
                        self.wire_into(point, to, &place)?;
                    }
                }
                for output in &block.outputs {
                    // CODESYS's "assign this output to a variable" becomes an output element.
                    let assigned = output
                        .output
                        .as_ref()
                        .and_then(|point| point.expression.as_deref())
                        .map(str::trim)
                        .filter(|expression| !expression.is_empty());
                    if let Some(expression) = assigned {
                        let (x, y) = self.grid_place(object.position.as_ref());
                        let kind = CfcElementKind::Output {
                            expression: expression.to_owned(),
                            coil: CoilKind::Normal,
                        };
                        let assign = self.push(x.saturating_add(8), y, kind, None, None);
                        let from = if self.is_box(block) {
                            result_pin_name(&output.formal_parameter)
                        } else {
                            output.formal_parameter.clone()
                        };
                        self.wires.push(Wire::routed(
                            PinRef::new(element, from),
                            PinRef::new(assign, ""),
                        ));
                    }
                }
            }
            ObjectKind::OutVariable(variable) => {
                if let Some(point) = &variable.input {
                    self.wire_into(point, PinRef::new(element, ""), &place)?;
                }
            }
            ObjectKind::Jump(jump) => {
                if let Some(point) = &jump.input {
                    self.wire_into(point, PinRef::new(element, ""), &place)?;
                }
            }
            ObjectKind::Return(ret) => {
                if let Some(point) = &ret.input {
                    self.wire_into(point, PinRef::new(element, ""), &place)?;
                }
            }
            ObjectKind::Connector(connector) => {
                if let Some(point) = &connector.input {
                    self.wire_into(point, PinRef::new(element, ""), &place)?;
                }
            }
            _ => {}
        }
        Ok(())
    }

    /// The wire (at most one) into the input pin `to`, from its connection or its expression.
    fn wire_into(
        &mut self,
        point: &ConnectionPointIn,
        to: PinRef,
        place: &Place,
    ) -> Result<(), BodyFault> {
        match point.connections.as_slice() {
            [] => {
                let expression = point.expression.as_deref().map(str::trim).unwrap_or("");
                if !expression.is_empty() {
                    let (x, y) = self
                        .elements
                        .iter()
                        .find(|placed| placed.element.id == to.element)
                        .map_or((0, 0), |placed| (placed.element.x, placed.element.y));
                    let kind = CfcElementKind::Input {
                        expression: expression.to_owned(),
                    };
                    let input = self.push(x.saturating_sub(6), y, kind, None, None);
                    self.wires.push(Wire::routed(PinRef::new(input, ""), to));
                }
                Ok(())
            }
            [connection] => {
                let from = self.source_of(connection, place)?;
                let points = self.wire_points(&connection.points);
                self.wires.push(Wire { from, to, points });
                Ok(())
            }
            several => Err(BodyFault::Error(
                place.clone(),
                ImportErrorKind::BadCfc(format!(
                    "the input {} has {} wires; an input of a chart takes one",
                    if to.pin.is_empty() {
                        "pin".to_owned()
                    } else {
                        format!("pin `{}`", to.pin)
                    },
                    several.len()
                )),
            )),
        }
    }

    /// The output pin `connection` comes from, through CODESYS's unnamed connectors.
    pub fn source_of(&self, connection: &Connection, place: &Place) -> Result<PinRef, BodyFault> {
        let mut connection = connection;
        // Each step follows one junction; more steps than objects means a ring of junctions.
        for _ in 0..=self.objects.len() {
            let missing = |id: u64| {
                BodyFault::Error(
                    place.clone(),
                    ImportErrorKind::BadCfc(format!(
                        "a connection refers to localId {id}, which is not an object of the graph"
                    )),
                )
            };
            let source = self
                .by_local_id
                .get(&connection.ref_local_id)
                .ok_or_else(|| missing(connection.ref_local_id))?;
            if let ObjectKind::Connector(connector) = &source.kind
                && connector.name.trim().is_empty()
            {
                connection = connector
                    .input
                    .as_ref()
                    .and_then(|point| point.connections.first())
                    .ok_or_else(|| {
                        BodyFault::Error(
                            self.place_of(source),
                            ImportErrorKind::BadCfc("an unnamed connector has no input".to_owned()),
                        )
                    })?;
                continue;
            }
            let element = *self
                .element_of
                .get(&source.local_id)
                .ok_or_else(|| missing(source.local_id))?;
            let pin = match &source.kind {
                ObjectKind::Block(block) => {
                    let name = match connection.formal_parameter.as_deref() {
                        Some(name) if !name.trim().is_empty() => name.to_owned(),
                        // No pin named: the block's result, its first output other than ENO.
                        _ => block
                            .outputs
                            .iter()
                            .map(|pin| pin.formal_parameter.clone())
                            .find(|name| !name.eq_ignore_ascii_case("ENO"))
                            .ok_or_else(|| {
                                BodyFault::Error(
                                    place.clone(),
                                    ImportErrorKind::BadCfc(format!(
                                        "a connection comes from the block `{}` (localId {}), which has no output",
                                        block.type_name, source.local_id
                                    )),
                                )
                            })?,
                    };
                    if self.is_box(block) {
                        result_pin_name(&name)
                    } else {
                        name
                    }
                }
                _ => String::new(),
            };
            return Ok(PinRef::new(element, pin));
        }
        Err(BodyFault::Error(
            place.clone(),
            ImportErrorKind::BadCfc(
                "the unnamed connectors it is wired through form a ring".to_owned(),
            ),
        ))
    }

    /// Adds an output writing `expression` from the pin `from`, run last (a wired SFC
    /// condition writes its transition object's name so).
    pub fn add_output(&mut self, expression: &str, from: PinRef) {
        let (x, y) = self
            .elements
            .iter()
            .find(|placed| placed.element.id == from.element)
            .map_or((0, 0), |placed| (placed.element.x, placed.element.y));
        let kind = CfcElementKind::Output {
            expression: expression.to_owned(),
            coil: CoilKind::Normal,
        };
        let output = self.push(x.saturating_add(8), y, kind, None, None);
        self.wires.push(Wire::routed(from, PinRef::new(output, "")));
    }

    /// The chart, numbered in execution order and checked against Rivet's rules.
    pub fn finish(self) -> Result<CfcChart, BodyFault> {
        let order = execution_order(&self.elements, &self.wires, self.dialect);
        let rank: HashMap<ElementId, u32> = order.into_iter().zip(0u32..).collect();
        let chart = CfcChart {
            elements: self
                .elements
                .into_iter()
                .map(|placed| CfcElement {
                    order: rank.get(&placed.element.id).copied(),
                    ..placed.element
                })
                .collect(),
            wires: self.wires,
        };
        let problems = project_model::cfc_problems(&chart);
        if problems.is_empty() {
            return Ok(chart);
        }
        let problems: Vec<String> = problems.iter().map(ToString::to_string).collect();
        Err(BodyFault::Error(
            Place {
                path: self.body_path,
                line: self.body_line,
                column: 1,
            },
            ImportErrorKind::BadCfc(format!(
                "the chart made of this body breaks Rivet's rules: {}",
                problems.join("; ")
            )),
        ))
    }

    /// The grid place of a position (0, 0 when there is none).
    fn grid_place(&self, position: Option<&Point>) -> (i32, i32) {
        position.map_or((0, 0), |point| (self.grid(point.x), self.grid(point.y)))
    }

    /// A coordinate in grid units, rounded.
    fn grid(&self, value: f64) -> i32 {
        let units = value / self.dialect.pitch();
        // Saturating: a coordinate beyond i32 is nonsense, and the chart still loads.
        units.round() as i32
    }

    /// A width or height in grid units, at least 1.
    fn extent(&self, value: Option<f64>) -> u32 {
        let units = self.grid(value.unwrap_or(0.0));
        u32::try_from(units).unwrap_or(0).max(1)
    }

    /// The control points of a wire drawn through `points` (consumer to producer, as PLCopen
    /// writes them): the inner points from producer to consumer, when every one is on the
    /// grid; none otherwise (the wire is routed automatically).
    fn wire_points(&self, points: &[Point]) -> Vec<GridPoint> {
        if points.len() <= 2 {
            return Vec::new();
        }
        let on_grid = |value: f64| {
            let units = value / self.dialect.pitch();
            (units.fract() == 0.0).then_some(units as i32)
        };
        points[1..points.len() - 1]
            .iter()
            .rev()
            .map(|point| {
                Some(GridPoint {
                    x: on_grid(point.x)?,
                    y: on_grid(point.y)?,
                })
            })
            .collect::<Option<Vec<_>>>()
            .unwrap_or_default()
    }
}

/// The element type of CODESYS's `…/cfcelementtype` or `…/fbdelementtype` entry
/// (`<ElementType>composer</ElementType>`).
fn vendor_element_type(xml: &str) -> Option<String> {
    let start = xml.find("<ElementType")?;
    let text = &xml[start..];
    let open_end = text.find('>')? + 1;
    let close = text.find("</ElementType>")?;
    let name = text.get(open_end..close)?.trim();
    (!name.is_empty()).then(|| format!("CODESYS {name}"))
}

/// Whether `pins` is one pin without a name: a composer's output or a selector's input.
fn is_unnamed_pin(pins: &[BlockPin]) -> bool {
    matches!(pins, [only] if only.formal_parameter.trim().is_empty())
}

/// The name of a box's output pin `name`: a function's result, which Beremiz names "", is
/// `OUT`, as Rivet names it.
fn result_pin_name(name: &str) -> String {
    if name.trim().is_empty() {
        "OUT".to_owned()
    } else {
        name.to_owned()
    }
}

/// A pin of a box: its name, negation and edge.
fn pin(pin: &BlockPin) -> CfcPin {
    CfcPin {
        name: pin.formal_parameter.clone(),
        negated: pin.negated == Some(true),
        edge: match pin.edge {
            Some(Edge::Rising) => project_model::Edge::Rising,
            Some(Edge::Falling) => project_model::Edge::Falling,
            Some(Edge::None) | None => project_model::Edge::None,
        },
    }
}

/// How an outVariable writes its variable.
fn coil_kind(negated: Option<bool>, edge: Option<Edge>, storage: Option<Storage>) -> CoilKind {
    match (storage, edge) {
        (Some(Storage::Set), _) => CoilKind::Set,
        (Some(Storage::Reset), _) => CoilKind::Reset,
        (_, Some(Edge::Rising)) => CoilKind::Rising,
        (_, Some(Edge::Falling)) => CoilKind::Falling,
        _ if negated == Some(true) => CoilKind::Negated,
        _ => CoilKind::Normal,
    }
}
