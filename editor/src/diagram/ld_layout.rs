//! The LD view of a network: series left to right, parallel branches stacked between two rails,
//! boxes with their pins, the outputs right-aligned before the right power rail.
//!
//! A two-pass series-parallel layout, as Beremiz's `CalcBranchSize` does: every chain is first
//! measured (a series is as wide as the sum of its elements and as high as the highest, a
//! parallel group as wide as its widest branch and as high as all branches together), then
//! placed from the top-left corner. Nothing in the model holds a position.

use egui::{Pos2, Rect, Vec2, pos2, vec2};
use project_model::{
    Anchor, BlockCall, BlockInput, ElementId, FlowNode, Network, NetworkOutput, ParallelSide, Side,
};

use super::measure::{box_cells, operand_cells};
use super::placed::{InsertTarget, NetworkLayout, PinMark, PlacedElement, Power, Shape};

/// The narrowest network, in cells, so an empty rung still has a line to click and drop on.
const MIN_WIDTH_CELLS: f32 = 4.0;
/// The narrowest box, in cells (126 points, the width of a CODESYS LD timer box); a box grows
/// beyond it with its title and pin names.
const MIN_BOX_CELLS: f32 = 1.5;

/// Lays out `network`, the body's network number `network_index` (counted from 0), as a rung.
pub fn ld_layout(network: &Network, network_index: usize) -> NetworkLayout {
    let rung = measure_chain(&network.rung);
    let outputs_width = measure_outputs(&network.outputs);
    let width = (rung.x + 1.0 + outputs_width).max(MIN_WIDTH_CELLS);
    let height = rung.y.max(outputs_height(&network.outputs)).max(1.0);
    let mut builder = Builder::default();
    let power = builder.chain(&network.rung, Pos2::ZERO, Power::Rail);
    if network.rung.is_empty() {
        builder.layout.insert(
            pos2(0.5, 0.5),
            InsertTarget::Series {
                anchor: Anchor::Network(network_index),
                side: Side::After,
            },
        );
    }
    builder.outputs(
        &network.outputs,
        rung.x,
        0.0,
        width,
        power,
        Anchor::Network(network_index),
    );
    builder
        .layout
        .wire(vec![pos2(0.0, 0.0), pos2(0.0, height)], Power::Rail);
    builder
        .layout
        .wire(vec![pos2(width, 0.0), pos2(width, height)], Power::None);
    NetworkLayout {
        size: vec2(width, height),
        ..builder.layout
    }
}

/// The size of a chain in cells; an empty chain is a line with no width.
pub(super) fn measure_chain(chain: &[FlowNode]) -> Vec2 {
    chain.iter().fold(Vec2::ZERO, |size, node| {
        let node = measure_node(node);
        vec2(size.x + node.x, size.y.max(node.y))
    })
}

fn measure_node(node: &FlowNode) -> Vec2 {
    match node {
        FlowNode::Operand(operand) => vec2(operand_cells(&operand.text, 1.0), 1.0),
        FlowNode::Parallel(parallel) => {
            parallel
                .branches
                .iter()
                .fold(vec2(1.0, 0.0), |size, branch| {
                    let branch = measure_chain(&branch.rung);
                    vec2(size.x.max(branch.x), size.y + branch.y.max(1.0))
                })
        }
        FlowNode::Block(block) => measure_block(block),
    }
}

/// A box is as wide as its inputs' sources, the box and its assignments.
fn measure_block(block: &BlockCall) -> Vec2 {
    let sources = block
        .inputs
        .iter()
        .skip(1)
        .map(source_size)
        .fold(0.0_f32, |width, size| width.max(size.x));
    vec2(
        sources + box_width(block) + assignment_column(block),
        block_rows(block),
    )
}

/// The width of a box itself, from its title and pin names.
fn box_width(block: &BlockCall) -> f32 {
    box_cells(
        &block.type_name,
        &block.instance,
        block.inputs.iter().map(|input| input.pin.as_str()),
        block.outputs.iter().map(|output| output.pin.as_str()),
        MIN_BOX_CELLS,
    )
}

/// The size of what drives a box's input: a cell as wide as a single operand's text, else its
/// chain.
fn source_size(input: &BlockInput) -> Vec2 {
    match input.source.as_slice() {
        [FlowNode::Operand(operand)] => vec2(operand_cells(&operand.text, 1.0), 1.0),
        source => measure_chain(source),
    }
}

/// The rows of each input of a box: the power's input takes one, the others as many as their
/// sources need.
fn input_rows(block: &BlockCall) -> impl Iterator<Item = f32> + '_ {
    block.inputs.iter().enumerate().map(|(index, input)| {
        if index == 0 {
            1.0
        } else {
            source_size(input).y.max(1.0)
        }
    })
}

fn block_rows(block: &BlockCall) -> f32 {
    input_rows(block)
        .sum::<f32>()
        .max(block.outputs.len() as f32)
        .max(1.0)
}

/// A column after a box for the variables its outputs are assigned to, as wide as the longest
/// (at least a cell), when any output other than the one passing the power on is assigned.
fn assignment_column(block: &BlockCall) -> f32 {
    let chain = block.chain_output();
    block
        .outputs
        .iter()
        .enumerate()
        .filter(|(index, output)| Some(*index) != chain && !output.assign.is_empty())
        .map(|(_, output)| operand_cells(&output.assign, 1.0))
        .fold(0.0, f32::max)
}

/// The width of an output's cell: a coil as wide as its variable, at least a cell.
fn output_cell_width(output: &NetworkOutput) -> f32 {
    match output {
        NetworkOutput::Coil(coil) => operand_cells(&coil.variable, 1.0),
        NetworkOutput::Jump { label, .. } => operand_cells(label, 1.0),
        NetworkOutput::Return { .. } | NetworkOutput::Branch { .. } => 1.0,
    }
}

fn measure_output(output: &NetworkOutput) -> f32 {
    match output {
        NetworkOutput::Branch { rung, outputs, .. } => {
            measure_chain(rung).x + 1.0 + measure_outputs(outputs)
        }
        _ => output_cell_width(output),
    }
}

fn measure_outputs(outputs: &[NetworkOutput]) -> f32 {
    outputs.iter().map(measure_output).fold(1.0, f32::max)
}

fn output_height(output: &NetworkOutput) -> f32 {
    match output {
        NetworkOutput::Branch { rung, outputs, .. } => {
            measure_chain(rung).y.max(outputs_height(outputs))
        }
        _ => 1.0,
    }
}

fn outputs_height(outputs: &[NetworkOutput]) -> f32 {
    outputs.iter().map(output_height).sum::<f32>().max(1.0)
}

/// Collects what is placed.
#[derive(Default)]
struct Builder {
    layout: NetworkLayout,
}

impl Builder {
    fn place(&mut self, id: Option<ElementId>, rect: Rect, shape: Shape, power_in: Power) {
        self.layout.elements.push(PlacedElement {
            id,
            rect,
            shape,
            power_in,
        });
    }

    /// Places `chain` from `origin`, fed with `power`; returns the power at its end.
    fn chain(&mut self, chain: &[FlowNode], origin: Pos2, power: Power) -> Power {
        let mut x = origin.x;
        let mut power = power;
        for node in chain {
            let size = measure_node(node);
            let id = node.id();
            self.layout.insert(
                pos2(x, origin.y + 0.5),
                InsertTarget::Series {
                    anchor: Anchor::Element(id),
                    side: Side::Before,
                },
            );
            self.layout.insert(
                pos2(x + size.x / 2.0, origin.y + size.y),
                InsertTarget::Parallel {
                    id,
                    side: ParallelSide::Below,
                },
            );
            power = self.node(node, pos2(x, origin.y), power);
            x += size.x;
        }
        if let Some(last) = chain.last() {
            self.layout.insert(
                pos2(x, origin.y + 0.5),
                InsertTarget::Series {
                    anchor: Anchor::Element(last.id()),
                    side: Side::After,
                },
            );
        }
        power
    }

    fn node(&mut self, node: &FlowNode, at: Pos2, power: Power) -> Power {
        match node {
            FlowNode::Operand(operand) => {
                self.place(
                    Some(operand.id),
                    Rect::from_min_size(at, vec2(operand_cells(&operand.text, 1.0), 1.0)),
                    Shape::Contact {
                        text: operand.text.clone(),
                        negated: operand.negated,
                        edge: operand.edge,
                    },
                    power,
                );
                Power::After(operand.id)
            }
            FlowNode::Parallel(parallel) => {
                let size = measure_node(node);
                let out = Power::After(parallel.id);
                self.place(
                    Some(parallel.id),
                    Rect::from_min_size(at, size),
                    Shape::Group,
                    power,
                );
                let mut y = at.y;
                let mut last_row = at.y;
                for branch in &parallel.branches {
                    let branch_size = measure_chain(&branch.rung);
                    let end = self.chain(&branch.rung, pos2(at.x, y), power);
                    if branch_size.x < size.x {
                        self.layout.wire(
                            vec![
                                pos2(at.x + branch_size.x, y + 0.5),
                                pos2(at.x + size.x, y + 0.5),
                            ],
                            end,
                        );
                    }
                    last_row = y;
                    y += branch_size.y.max(1.0);
                }
                self.layout.wire(
                    vec![pos2(at.x, at.y + 0.5), pos2(at.x, last_row + 0.5)],
                    power,
                );
                self.layout.wire(
                    vec![
                        pos2(at.x + size.x, at.y + 0.5),
                        pos2(at.x + size.x, last_row + 0.5),
                    ],
                    out,
                );
                out
            }
            FlowNode::Block(block) => self.block(block, at, power),
        }
    }

    fn block(&mut self, block: &BlockCall, at: Pos2, power: Power) -> Power {
        let size = measure_block(block);
        let column = assignment_column(block);
        let width = box_width(block);
        let box_x = at.x + size.x - width - column;
        let out = Power::After(block.id);
        if box_x > at.x {
            self.layout
                .wire(vec![pos2(at.x, at.y + 0.5), pos2(box_x, at.y + 0.5)], power);
        }
        let mut inputs = Vec::new();
        let mut row = at.y;
        for (input, rows) in block
            .inputs
            .iter()
            .zip(input_rows(block).collect::<Vec<_>>())
        {
            inputs.push(PinMark {
                name: input.pin.clone(),
                row,
                negated: input.negated,
                edge: input.edge,
            });
            match input.source.as_slice() {
                [] => {}
                [FlowNode::Operand(operand)] => {
                    let cell = operand_cells(&operand.text, 1.0);
                    self.place(
                        Some(operand.id),
                        Rect::from_min_size(pos2(box_x - cell, row), vec2(cell, 1.0)),
                        Shape::Variable {
                            text: operand.text.clone(),
                            negated: operand.negated,
                            edge: operand.edge,
                        },
                        Power::None,
                    )
                }
                source => {
                    let width = measure_chain(source).x;
                    self.chain(source, pos2(box_x - width, row), Power::Rail);
                }
            }
            row += rows;
        }
        let chain = block.chain_output();
        let mut outputs = Vec::new();
        for (index, output) in block.outputs.iter().enumerate() {
            let row = at.y + index as f32;
            outputs.push(PinMark {
                name: output.pin.clone(),
                row,
                negated: output.negated,
                edge: project_model::Edge::None,
            });
            if Some(index) != chain && !output.assign.is_empty() {
                self.place(
                    None,
                    Rect::from_min_size(pos2(box_x + width, row), vec2(column, 1.0)),
                    Shape::Variable {
                        text: output.assign.clone(),
                        negated: false,
                        edge: project_model::Edge::None,
                    },
                    out,
                );
            }
        }
        let chain_row = at.y + chain.unwrap_or(0) as f32 + 0.5;
        let right = at.x + size.x;
        if column > 0.0 || chain_row > at.y + 0.5 {
            self.layout.wire(
                vec![
                    pos2(box_x + width, chain_row),
                    pos2(right, chain_row),
                    pos2(right, at.y + 0.5),
                ],
                out,
            );
        }
        self.place(
            Some(block.id),
            Rect::from_min_size(pos2(box_x, at.y), vec2(width, size.y)),
            Shape::Box {
                type_name: block.type_name.clone(),
                instance: block.instance.clone(),
                inputs,
                outputs,
            },
            power,
        );
        out
    }

    /// Places `outputs` fanning out from `fan_x` at row `top`, right-aligned to `right`;
    /// returns their height.
    fn outputs(
        &mut self,
        outputs: &[NetworkOutput],
        fan_x: f32,
        top: f32,
        right: f32,
        power: Power,
        end_anchor: Anchor,
    ) -> f32 {
        if outputs.is_empty() {
            self.layout
                .wire(vec![pos2(fan_x, top + 0.5), pos2(right, top + 0.5)], power);
            self.layout.insert(
                pos2(right - 0.5, top + 0.5),
                InsertTarget::Output { anchor: end_anchor },
            );
            return 1.0;
        }
        let mut y = top;
        let mut last_row = top;
        for output in outputs {
            let height = output_height(output);
            let cell_width = output_cell_width(output);
            let cell = Rect::from_min_size(pos2(right - cell_width, y), vec2(cell_width, 1.0));
            let shape = match output {
                NetworkOutput::Coil(coil) => Some(Shape::Coil {
                    variable: coil.variable.clone(),
                    kind: coil.kind,
                }),
                NetworkOutput::Jump { label, .. } => Some(Shape::Jump {
                    label: label.clone(),
                }),
                NetworkOutput::Return { .. } => Some(Shape::Return),
                NetworkOutput::Branch { .. } => None,
            };
            if let Some(shape) = shape {
                self.layout.wire(
                    vec![pos2(fan_x, y + 0.5), pos2(right - cell_width, y + 0.5)],
                    power,
                );
                self.place(Some(output.id()), cell, shape, power);
                self.layout.insert(
                    pos2(right - cell_width / 2.0, y + 1.0),
                    InsertTarget::Output {
                        anchor: Anchor::Element(output.id()),
                    },
                );
            } else if let NetworkOutput::Branch {
                id, rung, outputs, ..
            } = output
            {
                let end = self.chain(rung, pos2(fan_x, y), power);
                let chain_width = measure_chain(rung).x;
                self.outputs(
                    outputs,
                    fan_x + chain_width,
                    y,
                    right,
                    end,
                    Anchor::Element(*id),
                );
            }
            last_row = y;
            y += height;
        }
        if last_row > top {
            self.layout.wire(
                vec![pos2(fan_x, top + 0.5), pos2(fan_x, last_row + 0.5)],
                power,
            );
        }
        y - top
    }
}

#[cfg(test)]
mod tests;
