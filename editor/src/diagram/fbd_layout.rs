//! The FBD view of a network: the same structure as the LD rung, drawn as boxes and lines.
//!
//! A chain of several operands is an AND box, a parallel group an OR box with one input per
//! branch, a box in a chain takes the chain before it on its first input; each box's input
//! subtrees stand to its left, and the outputs (assignments, jumps, returns) to the right of the
//! root. Negated and edge operands feeding a box are drawn as circles and `P`/`N` marks on its
//! pins.
//!
//! As in CODESYS's FBD, the drawing is compact: every box is as wide as its title and pin names
//! ([`box_cells`]), an input operand stands right at its pin and is as wide as its text, and a
//! line between two boxes is only long enough for a bend.

use egui::{Pos2, Rect, Vec2, pos2, vec2};
use project_model::{
    Anchor, BlockCall, Edge, ElementId, FlowNode, Network, NetworkOutput, Operand, ParallelSide,
    Side,
};

use super::measure::{box_cells, operand_cells, operand_width_px};
use super::paint::CELL_SIZE_PX;
use super::placed::{InsertTarget, NetworkLayout, PinMark, PlacedElement, Power, Shape};

/// The narrowest box, in cells, so a box of few letters still reads as a box.
const MIN_BOX_CELLS: f32 = 0.7;
/// The narrowest output or operand, in cells, so an empty one is still a target to click.
const MIN_VARIABLE_CELLS: f32 = 0.6;
/// The line between a box's output and the next box's pin, in cells: room for a bend.
const LEAD_CELLS: f32 = 0.35;
/// The line between a box's output pin and the variable it is assigned to, in cells.
const ASSIGNMENT_LEAD_CELLS: f32 = 0.1;
/// The room for an assignment's set, reset or edge letter before its variable, in cells.
const ASSIGNMENT_LETTER_CELLS: f32 = 0.2;
/// The length of a jump's arrow before its label, in points.
const JUMP_ARROW_PX: f32 = 24.0;

/// Lays out `network`, the body's network number `network_index` (counted from 0), as FBD.
pub fn fbd_layout(network: &Network, network_index: usize) -> NetworkLayout {
    let root = chain_expr(&network.rung, None);
    let mut builder = Builder::default();
    let (root_size, root_out) = match &root {
        Some(expr) => {
            let size = expr.size();
            (size, builder.expr(expr, Pos2::ZERO, false))
        }
        None => {
            builder.layout.insert(
                pos2(0.5, 0.5),
                InsertTarget::Series {
                    anchor: Anchor::Network(network_index),
                    side: Side::After,
                },
            );
            (vec2(0.0, 1.0), (pos2(0.0, 0.5), Power::Rail))
        }
    };
    let fan_x = root_size.x + LEAD_CELLS;
    let (outputs_size, _) = builder.outputs(
        &network.outputs,
        root_out,
        fan_x,
        0.0,
        Anchor::Network(network_index),
    );
    NetworkLayout {
        size: vec2(
            fan_x + outputs_size.x,
            root_size.y.max(outputs_size.y).max(1.0),
        ),
        ..builder.layout
    }
}

/// A network's logic as an expression tree.
enum Expr<'a> {
    /// An operand read in.
    Leaf(&'a Operand),
    /// A box: a call, or the AND of a chain, or the OR of a parallel group.
    Gate(Gate<'a>),
    /// The power an output branch starts from: its fan-out line.
    Incoming,
}

struct Gate<'a> {
    id: Option<ElementId>,
    type_name: String,
    instance: String,
    inputs: Vec<GateInput<'a>>,
    outputs: Vec<PinMark>,
    assignments: Vec<(usize, String)>,
    chain_output: usize,
    power: Power,
}

struct GateInput<'a> {
    pin: String,
    negated: bool,
    edge: Edge,
    source: Option<Expr<'a>>,
}

impl Expr<'_> {
    fn size(&self) -> Vec2 {
        match self {
            Self::Leaf(operand) => vec2(operand_cells(&operand.text, MIN_VARIABLE_CELLS), 1.0),
            Self::Incoming => vec2(0.0, 1.0),
            Self::Gate(gate) => {
                let (sources, rows) = gate.inputs.iter().fold((0.0_f32, 0.0), |(w, h), input| {
                    let size = input.source.as_ref().map_or(vec2(0.0, 1.0), Expr::size);
                    let lead = input.source.as_ref().map_or(0.0, Expr::lead);
                    (w.max(size.x + lead), h + size.y.max(1.0))
                });
                vec2(
                    sources + gate.box_width() + gate.assignments_width(),
                    rows.max(gate.outputs.len() as f32).max(1.0),
                )
            }
        }
    }

    /// The line between this source and the pin it feeds: none for an operand, which stands
    /// on its pin's row, room for a bend after a box.
    fn lead(&self) -> f32 {
        match self {
            Self::Leaf(_) => 0.0,
            Self::Gate(_) | Self::Incoming => LEAD_CELLS,
        }
    }

    fn power(&self) -> Power {
        match self {
            Self::Leaf(operand) => Power::After(operand.id),
            Self::Gate(gate) => gate.power,
            Self::Incoming => Power::None,
        }
    }
}

impl Gate<'_> {
    /// The width of the box itself, from its title and pin names.
    fn box_width(&self) -> f32 {
        box_cells(
            &self.type_name,
            &self.instance,
            self.inputs.iter().map(|input| input.pin.as_str()),
            self.outputs.iter().map(|output| output.name.as_str()),
            MIN_BOX_CELLS,
        )
    }

    /// The width of the variables the box's other outputs are assigned to, with their leads.
    fn assignments_width(&self) -> f32 {
        self.assignments
            .iter()
            .map(|(_, variable)| {
                ASSIGNMENT_LEAD_CELLS + operand_cells(variable, MIN_VARIABLE_CELLS)
            })
            .fold(0.0, f32::max)
    }
}

/// The width of an output's drawing, in cells.
fn output_cells(output: &NetworkOutput) -> f32 {
    match output {
        NetworkOutput::Coil(coil) => {
            ASSIGNMENT_LETTER_CELLS + operand_cells(&coil.variable, MIN_VARIABLE_CELLS)
        }
        NetworkOutput::Jump { label, .. } => {
            // An empty label shows a three-letter placeholder.
            let label_px = operand_width_px(label).max(operand_width_px("???"));
            (JUMP_ARROW_PX + label_px + 8.0) / CELL_SIZE_PX.x
        }
        NetworkOutput::Return { .. } => operand_cells("RETURN", MIN_VARIABLE_CELLS),
        NetworkOutput::Branch { .. } => 0.0,
    }
}

/// The expression of `chain`, fed by `incoming`: the AND of its terms, a box taking the terms
/// before it on its first input.
fn chain_expr<'a>(chain: &'a [FlowNode], incoming: Option<Expr<'a>>) -> Option<Expr<'a>> {
    let mut terms: Vec<Expr<'a>> = incoming.into_iter().collect();
    let mut last = None;
    for node in chain {
        last = Some(node.id());
        match node {
            FlowNode::Operand(operand) => terms.push(Expr::Leaf(operand)),
            FlowNode::Parallel(parallel) => terms.push(Expr::Gate(Gate {
                id: Some(parallel.id),
                type_name: "OR".to_owned(),
                instance: String::new(),
                inputs: parallel
                    .branches
                    .iter()
                    .map(|branch| GateInput {
                        pin: String::new(),
                        negated: false,
                        edge: Edge::None,
                        source: chain_expr(&branch.rung, None),
                    })
                    .collect(),
                outputs: vec![pin_mark("", false)],
                assignments: Vec::new(),
                chain_output: 0,
                power: Power::After(parallel.id),
            })),
            FlowNode::Block(block) => {
                let before = and_of(std::mem::take(&mut terms), last_term_power(chain, node));
                terms.push(Expr::Gate(block_gate(block, before)));
            }
        }
    }
    and_of(terms, last.map_or(Power::Rail, Power::After))
}

/// The power after the element just before `node` in `chain`.
fn last_term_power(chain: &[FlowNode], node: &FlowNode) -> Power {
    let position = chain
        .iter()
        .position(|candidate| candidate.id() == node.id())
        .unwrap_or(0);
    match position.checked_sub(1) {
        Some(before) => Power::After(chain[before].id()),
        None => Power::Rail,
    }
}

fn and_of<'a>(mut terms: Vec<Expr<'a>>, power: Power) -> Option<Expr<'a>> {
    match terms.len() {
        0 => None,
        1 => terms.pop(),
        _ => Some(Expr::Gate(Gate {
            id: None,
            type_name: "AND".to_owned(),
            instance: String::new(),
            inputs: terms
                .into_iter()
                .map(|term| GateInput {
                    pin: String::new(),
                    negated: false,
                    edge: Edge::None,
                    source: Some(term),
                })
                .collect(),
            outputs: vec![pin_mark("", false)],
            assignments: Vec::new(),
            chain_output: 0,
            power,
        })),
    }
}

fn block_gate<'a>(block: &'a BlockCall, power_in: Option<Expr<'a>>) -> Gate<'a> {
    let mut power_in = power_in;
    let inputs = block
        .inputs
        .iter()
        .enumerate()
        .map(|(index, input)| GateInput {
            pin: input.pin.clone(),
            negated: input.negated,
            edge: input.edge,
            source: if index == 0 && input.source.is_empty() {
                power_in.take()
            } else {
                chain_expr(&input.source, None)
            },
        })
        .collect();
    let chain_output = block.chain_output().unwrap_or(0);
    Gate {
        id: Some(block.id),
        type_name: block.type_name.clone(),
        instance: block.instance.clone(),
        inputs,
        outputs: block
            .outputs
            .iter()
            .map(|output| pin_mark(&output.pin, output.negated))
            .collect(),
        assignments: block
            .outputs
            .iter()
            .enumerate()
            .filter(|(index, output)| *index != chain_output && !output.assign.is_empty())
            .map(|(index, output)| (index, output.assign.clone()))
            .collect(),
        chain_output,
        power: Power::After(block.id),
    }
}

fn pin_mark(name: &str, negated: bool) -> PinMark {
    PinMark {
        name: name.to_owned(),
        row: 0.0,
        negated,
        edge: Edge::None,
    }
}

/// Collects what is placed.
#[derive(Default)]
struct Builder {
    layout: NetworkLayout,
}

impl Builder {
    /// Places `expr` with its top-left corner at `at`; returns its output point and power.
    /// `into_pin` tells that it feeds a box's pin, which then carries its negation circle.
    fn expr(&mut self, expr: &Expr<'_>, at: Pos2, into_pin: bool) -> (Pos2, Power) {
        let size = expr.size();
        match expr {
            Expr::Incoming => (pos2(at.x, at.y + 0.5), Power::None),
            Expr::Leaf(operand) => {
                self.layout.elements.push(PlacedElement {
                    id: Some(operand.id),
                    rect: Rect::from_min_size(at, size),
                    shape: Shape::Variable {
                        text: operand.text.clone(),
                        negated: operand.negated && !into_pin,
                        edge: if into_pin { Edge::None } else { operand.edge },
                    },
                    power_in: Power::None,
                });
                self.layout.insert(
                    pos2(at.x + size.x, at.y + 0.5),
                    InsertTarget::Series {
                        anchor: Anchor::Element(operand.id),
                        side: Side::After,
                    },
                );
                self.layout.insert(
                    pos2(at.x + size.x / 2.0, at.y + 1.0),
                    InsertTarget::Parallel {
                        id: operand.id,
                        side: ParallelSide::Below,
                    },
                );
                (pos2(at.x + size.x, at.y + 0.5), expr.power())
            }
            Expr::Gate(gate) => self.gate(gate, at, size),
        }
    }

    fn gate(&mut self, gate: &Gate<'_>, at: Pos2, size: Vec2) -> (Pos2, Power) {
        let assignments = gate.assignments_width();
        let box_width = gate.box_width();
        let box_x = at.x + size.x - box_width - assignments;
        let mut row = at.y;
        let mut inputs = Vec::new();
        let mut power_in = Power::None;
        for input in &gate.inputs {
            let mut negated = input.negated;
            let mut edge = input.edge;
            let mut rows = 1.0;
            if let Some(source) = &input.source {
                let source_size = source.size();
                rows = source_size.y.max(1.0);
                if let Expr::Leaf(operand) = source {
                    // An operand's negation and edge are drawn at the pin it feeds, as CODESYS
                    // draws them.
                    negated ^= operand.negated;
                    if edge == Edge::None {
                        edge = operand.edge;
                    }
                }
                let lead = source.lead();
                let source_at = pos2(box_x - lead - source_size.x, row);
                let (out, power) = self.expr(source, source_at, true);
                if power_in == Power::None {
                    power_in = power;
                }
                let pin = pos2(box_x, row + 0.5);
                if (out.y - pin.y).abs() >= f32::EPSILON {
                    self.layout.wire(
                        vec![
                            out,
                            pos2(box_x - lead / 2.0, out.y),
                            pos2(box_x - lead / 2.0, pin.y),
                            pin,
                        ],
                        power,
                    );
                } else if out.x < pin.x {
                    self.layout.wire(vec![out, pin], power);
                }
            }
            inputs.push(PinMark {
                name: input.pin.clone(),
                row,
                negated,
                edge,
            });
            row += rows;
        }
        let outputs: Vec<PinMark> = gate
            .outputs
            .iter()
            .enumerate()
            .map(|(index, pin)| PinMark {
                row: at.y + index as f32,
                ..pin.clone()
            })
            .collect();
        for (index, variable) in &gate.assignments {
            let row = at.y + *index as f32;
            let from = pos2(box_x + box_width, row + 0.5);
            self.layout.wire(
                vec![from, pos2(from.x + ASSIGNMENT_LEAD_CELLS, from.y)],
                gate.power,
            );
            self.layout.elements.push(PlacedElement {
                id: None,
                rect: Rect::from_min_size(
                    pos2(from.x + ASSIGNMENT_LEAD_CELLS, row),
                    vec2(assignments - ASSIGNMENT_LEAD_CELLS, 1.0),
                ),
                shape: Shape::Variable {
                    text: variable.clone(),
                    negated: false,
                    edge: Edge::None,
                },
                power_in: gate.power,
            });
        }
        self.layout.elements.push(PlacedElement {
            id: gate.id,
            rect: Rect::from_min_size(pos2(box_x, at.y), vec2(box_width, size.y)),
            shape: Shape::Box {
                type_name: gate.type_name.clone(),
                instance: gate.instance.clone(),
                inputs,
                outputs,
            },
            power_in,
        });
        if let Some(id) = gate.id {
            self.layout.insert(
                pos2(box_x + box_width, at.y + 0.5),
                InsertTarget::Series {
                    anchor: Anchor::Element(id),
                    side: Side::After,
                },
            );
        }
        let out_y = at.y + gate.chain_output as f32 + 0.5;
        let out = pos2(box_x + box_width, out_y);
        if assignments > 0.0 {
            let end = pos2(at.x + size.x, out_y);
            self.layout.wire(vec![out, end], gate.power);
            return (end, gate.power);
        }
        (out, gate.power)
    }

    /// Places `outputs` fed from `from`, starting at column `x` and row `top`; returns the size
    /// they take from `x` and the power they carry.
    fn outputs(
        &mut self,
        outputs: &[NetworkOutput],
        from: (Pos2, Power),
        x: f32,
        top: f32,
        end_anchor: Anchor,
    ) -> (Vec2, Power) {
        let (source, power) = from;
        let bend_x = source.x + LEAD_CELLS / 2.0;
        let mut y = top;
        let mut width = MIN_VARIABLE_CELLS;
        for output in outputs {
            let output_width = output_cells(output);
            let target = pos2(x, y + 0.5);
            let shape = match output {
                NetworkOutput::Coil(coil) => Some(Shape::Assignment {
                    variable: coil.variable.clone(),
                    kind: coil.kind,
                }),
                NetworkOutput::Jump { label, .. } => Some(Shape::Jump {
                    label: label.clone(),
                }),
                NetworkOutput::Return { .. } => Some(Shape::Return),
                NetworkOutput::Branch { .. } => None,
            };
            self.layout.wire(
                vec![
                    source,
                    pos2(bend_x, source.y),
                    pos2(bend_x, target.y),
                    target,
                ],
                power,
            );
            if let Some(shape) = shape {
                self.layout.elements.push(PlacedElement {
                    id: Some(output.id()),
                    rect: Rect::from_min_size(pos2(x, y), vec2(output_width, 1.0)),
                    shape,
                    power_in: power,
                });
                width = width.max(output_width);
                self.layout.insert(
                    pos2(x + output_width / 2.0, y + 1.0),
                    InsertTarget::Output {
                        anchor: Anchor::Element(output.id()),
                    },
                );
                y += 1.0;
            } else if let NetworkOutput::Branch { id, rung, outputs } = output {
                let expr = chain_expr(rung, Some(Expr::Incoming));
                let (size, out) = match &expr {
                    Some(expr) => (expr.size(), self.expr(expr, pos2(x, y), false)),
                    None => (vec2(0.0, 1.0), (target, power)),
                };
                let (nested, _) = self.outputs(
                    outputs,
                    out,
                    x + size.x + LEAD_CELLS,
                    y,
                    Anchor::Element(*id),
                );
                width = width.max(size.x + LEAD_CELLS + nested.x);
                y += size.y.max(nested.y).max(1.0);
            }
        }
        if outputs.is_empty() {
            self.layout.insert(
                pos2(x + MIN_VARIABLE_CELLS / 2.0, top + 0.5),
                InsertTarget::Output { anchor: end_anchor },
            );
            y += 1.0;
        }
        (vec2(width, y - top), power)
    }
}

#[cfg(test)]
mod tests;
