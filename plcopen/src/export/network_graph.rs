//! LD and FBD networks as PLCopen graphs (`docs/plcopen-xml.md` §5.2): one network after the
//! other, each network's objects contiguous, positions from a simple layout (a column per
//! element of a chain, a row per branch), the model's element ids kept as `localId`s and fresh
//! ids above the largest for the objects the model has no element for (power rails, labels,
//! assignments of box outputs, the AND and OR boxes of FBD).

use std::collections::BTreeMap;

use project_model::{
    BlockCall, CoilKind, Edge, FlowNode, Network, NetworkOutput, Operand, max_element_id,
};

use super::error::ExportError;
use super::xml_writer::XmlWriter;
use crate::rivet_data::{GATE_ENTRY, RIVET_NAMESPACE, SOURCE_ENTRY};

/// Grid units between two columns and two rows (positions are grid units × 10).
const COLUMN_WIDTH: i64 = 10;
const ROW_HEIGHT: i64 = 4;

/// What an FBD box written for the model's structure stands for.
#[derive(Clone, Copy, Debug)]
enum Gate {
    /// The AND of a chain's operand (`IN2`) with the chain before it (`IN1`).
    Series,
    /// The OR of a parallel group's branches, one input each in branch order.
    Parallel,
}

/// Where power or a value comes from: an object and, for a box, its output pin.
#[derive(Clone, Debug)]
struct Link {
    /// The object's `localId`.
    id: u64,
    /// The box output's formal parameter.
    pin: Option<String>,
}

/// The first object of a network in document order, with the network, for the body's
/// `…/networks` entry.
pub(super) struct NetworkStart<'n> {
    /// The `localId` of the network's first object.
    pub first: u64,
    /// The network.
    pub network: &'n Network,
}

/// The writer of one LD or FBD body's networks.
pub(super) struct NetworkGraph<'x> {
    xml: &'x mut XmlWriter,
    /// True for LD (contacts, coils, power rails), false for FBD.
    ladder: bool,
    /// The next fresh `localId`.
    next_id: u64,
    /// The next free row.
    next_row: i64,
    /// The left power rail of the network being written (LD).
    left_rail: u64,
    /// The first object written for the network being written.
    first_written: Option<u64>,
    /// Other tools' `addData` entries of elements, by element id: each entry's XML as it was.
    element_data: BTreeMap<u64, Vec<String>>,
    /// The elements whose entries were written, in the order written.
    data_written: Vec<u64>,
}

impl<'x> NetworkGraph<'x> {
    /// A writer of `networks` into `xml`.
    pub fn new(xml: &'x mut XmlWriter, ladder: bool, networks: &[Network]) -> Self {
        Self {
            xml,
            ladder,
            next_id: u64::from(max_element_id(networks).0) + 1,
            next_row: 0,
            left_rail: 0,
            first_written: None,
            element_data: BTreeMap::new(),
            data_written: Vec::new(),
        }
    }

    /// The writer with other tools' entries of elements (by element id) to write in the
    /// `addData` of the object each element becomes (§5.5).
    pub fn with_element_data(mut self, element_data: BTreeMap<u64, Vec<String>>) -> Self {
        self.element_data = element_data;
        self
    }

    /// The elements whose entries were written: the others have no object in the document.
    pub fn data_written(&self) -> &[u64] {
        &self.data_written
    }

    /// Writes every network; gives where each starts.
    pub fn write<'n>(
        &mut self,
        networks: &'n [Network],
    ) -> Result<Vec<NetworkStart<'n>>, ExportError> {
        let mut starts = Vec::new();
        for network in networks {
            self.first_written = None;
            let row = self.row();
            if !network.label.is_empty() {
                let id = self.fresh();
                self.start_object("label", id, &[("label", &network.label)], 0, row)?;
                self.xml.end("label")?;
            }
            let power = if self.ladder {
                self.left_rail = self.fresh();
                self.start_object("leftPowerRail", self.left_rail, &[], 0, row)?;
                self.xml
                    .empty("connectionPointOut", &[("formalParameter", "")])?;
                self.xml.end("leftPowerRail")?;
                vec![Link {
                    id: self.left_rail,
                    pin: None,
                }]
            } else {
                Vec::new()
            };
            let (end, column) = self.chain(&network.rung, power, 1, row)?;
            let mut coils = Vec::new();
            self.outputs(&network.outputs, &end, column, row, &mut coils)?;
            if self.ladder {
                let id = self.fresh();
                self.start_object("rightPowerRail", id, &[], column + 2, row)?;
                for coil in coils {
                    self.xml.start("connectionPointIn", &[])?;
                    self.connections(&[Link {
                        id: coil,
                        pin: None,
                    }])?;
                    self.xml.end("connectionPointIn")?;
                }
                self.xml.end("rightPowerRail")?;
            }
            if self.first_written.is_none() {
                // An empty FBD network: a comment holds its place, so its header is kept.
                let id = self.fresh();
                let id_text = id.to_string();
                self.first_written = Some(id);
                self.xml.start(
                    "comment",
                    &[("localId", &id_text), ("height", "20"), ("width", "100")],
                )?;
                self.position(0, row)?;
                self.xml.start("content", &[])?;
                self.xml.start("xhtml:p", &[])?;
                self.xml.cdata(&network.comment)?;
                self.xml.end("xhtml:p")?;
                self.xml.end("content")?;
                self.xml.end("comment")?;
            }
            starts.push(NetworkStart {
                first: self.first_written.unwrap_or_default(),
                network,
            });
        }
        Ok(starts)
    }

    /// Writes a chain fed by `input` from column `column` on row `row`; gives what leaves its
    /// end and the column after it.
    fn chain(
        &mut self,
        nodes: &[FlowNode],
        mut input: Vec<Link>,
        mut column: i64,
        row: i64,
    ) -> Result<(Vec<Link>, i64), ExportError> {
        for node in nodes {
            (input, column) = self.node(node, input, column, row)?;
        }
        Ok((input, column))
    }

    fn node(
        &mut self,
        node: &FlowNode,
        input: Vec<Link>,
        column: i64,
        row: i64,
    ) -> Result<(Vec<Link>, i64), ExportError> {
        match node {
            FlowNode::Operand(operand) if self.ladder => {
                let id = u64::from(operand.id.0);
                let attributes = modifiers(operand.negated, operand.edge);
                self.start_object("contact", id, &attributes, column, row)?;
                self.xml.start("connectionPointIn", &[])?;
                self.connections(&input)?;
                self.xml.end("connectionPointIn")?;
                self.xml.empty("connectionPointOut", &[])?;
                self.xml.text_element("variable", &[], &operand.text)?;
                self.end_object("contact", id)?;
                Ok((vec![Link { id, pin: None }], column + 1))
            }
            FlowNode::Operand(operand) => {
                let value = self.in_variable(operand, column, row)?;
                if input.is_empty() {
                    return Ok((vec![value], column + 1));
                }
                // In FBD a chain ANDs its operands into what comes before them.
                let and = self.gate(Gate::Series, &[input, vec![value]], column + 1, row)?;
                Ok((vec![and], column + 2))
            }
            FlowNode::Parallel(parallel) => {
                let mut ends = Vec::new();
                let mut widest = column;
                for (index, branch) in parallel.branches.iter().enumerate() {
                    let branch_row = if index == 0 { row } else { self.row() };
                    let (end, after) =
                        self.chain(&branch.rung, input.clone(), column, branch_row)?;
                    widest = widest.max(after);
                    ends.push(end);
                }
                if self.ladder {
                    // LD: the branches meet in a wired OR, listed in branch order.
                    Ok((ends.into_iter().flatten().collect(), widest))
                } else {
                    let or = self.gate(Gate::Parallel, &ends, widest, row)?;
                    Ok((vec![or], widest + 1))
                }
            }
            FlowNode::Block(block) => self.block(block, input, column, row),
        }
    }

    /// Writes a box: the sources of its inputs first, then the box, then the assignments of its
    /// outputs; the power (or value) goes on from its ENO or first output.
    fn block(
        &mut self,
        block: &BlockCall,
        input: Vec<Link>,
        column: i64,
        row: i64,
    ) -> Result<(Vec<Link>, i64), ExportError> {
        let mut sources = Vec::new();
        let mut source_column = column;
        for (index, pin) in block.inputs.iter().enumerate() {
            let links = if pin.source.is_empty() {
                if index == 0 {
                    input.clone()
                } else {
                    Vec::new()
                }
            } else {
                let pin_row = if index == 0 { row } else { self.row() };
                let (links, after) = match pin.source.as_slice() {
                    // One operand is a value: a variable, literal or expression.
                    [FlowNode::Operand(operand)] => (
                        vec![self.in_variable(operand, column, pin_row)?],
                        column + 1,
                    ),
                    nodes => {
                        let power = if self.ladder {
                            vec![Link {
                                id: self.left_rail,
                                pin: None,
                            }]
                        } else {
                            Vec::new()
                        };
                        self.chain(nodes, power, column, pin_row)?
                    }
                };
                source_column = source_column.max(after);
                links
            };
            sources.push(links);
        }
        let id = u64::from(block.id.0);
        let mut attributes = vec![("typeName", block.type_name.as_str())];
        if !block.instance.is_empty() {
            attributes.push(("instanceName", &block.instance));
        }
        self.start_object("block", id, &attributes, source_column, row)?;
        self.xml.start("inputVariables", &[])?;
        for (pin, links) in block.inputs.iter().zip(&sources) {
            let mut attributes = vec![("formalParameter", pin.pin.as_str())];
            attributes.extend(modifiers(pin.negated, pin.edge));
            self.xml.start("variable", &attributes)?;
            self.xml.start("connectionPointIn", &[])?;
            self.connections(links)?;
            self.xml.end("connectionPointIn")?;
            self.xml.end("variable")?;
        }
        self.xml.end("inputVariables")?;
        self.xml.empty("inOutVariables", &[])?;
        self.xml.start("outputVariables", &[])?;
        for pin in &block.outputs {
            let mut attributes = vec![("formalParameter", pin.pin.as_str())];
            if pin.negated {
                attributes.push(("negated", "true"));
            }
            self.xml.start("variable", &attributes)?;
            self.xml.empty("connectionPointOut", &[])?;
            self.xml.end("variable")?;
        }
        self.xml.end("outputVariables")?;
        // A box whose first input has its own source is marked, so that the import gives the
        // source back to the pin instead of putting it before the box (§5.2).
        let source_pin = block
            .inputs
            .first()
            .filter(|first| !first.source.is_empty())
            .map(|first| first.pin.as_str());
        self.end_object_marked("block", id, source_pin)?;
        let after = source_column + 1;
        for pin in block.outputs.iter().filter(|pin| !pin.assign.is_empty()) {
            let out = self.fresh();
            let pin_row = self.row();
            self.start_object("outVariable", out, &[], after, pin_row)?;
            self.xml.start("connectionPointIn", &[])?;
            self.connections(&[Link {
                id,
                pin: Some(pin.pin.clone()),
            }])?;
            self.xml.end("connectionPointIn")?;
            self.xml.text_element("expression", &[], &pin.assign)?;
            self.xml.end("outVariable")?;
        }
        let passed = block
            .chain_output()
            .and_then(|index| block.outputs.get(index));
        let links = passed
            .map(|pin| {
                vec![Link {
                    id,
                    pin: Some(pin.pin.clone()),
                }]
            })
            .unwrap_or_default();
        Ok((links, after))
    }

    /// Writes what the power at the end of a chain drives; the ids of LD coils are collected
    /// for the right power rail.
    fn outputs(
        &mut self,
        outputs: &[NetworkOutput],
        end: &[Link],
        column: i64,
        row: i64,
        coils: &mut Vec<u64>,
    ) -> Result<(), ExportError> {
        for (index, output) in outputs.iter().enumerate() {
            let output_row = if index == 0 { row } else { self.row() };
            match output {
                NetworkOutput::Coil(coil) => {
                    let id = u64::from(coil.id.0);
                    let mut attributes = Vec::new();
                    match coil.kind {
                        CoilKind::Normal => {}
                        CoilKind::Negated => attributes.push(("negated", "true")),
                        CoilKind::Set => attributes.push(("storage", "set")),
                        CoilKind::Reset => attributes.push(("storage", "reset")),
                        CoilKind::Rising => attributes.push(("edge", "rising")),
                        CoilKind::Falling => attributes.push(("edge", "falling")),
                    }
                    let element = if self.ladder { "coil" } else { "outVariable" };
                    self.start_object(element, id, &attributes, column + 1, output_row)?;
                    self.xml.start("connectionPointIn", &[])?;
                    self.connections(end)?;
                    self.xml.end("connectionPointIn")?;
                    if self.ladder {
                        self.xml.empty("connectionPointOut", &[])?;
                        self.xml.text_element("variable", &[], &coil.variable)?;
                        coils.push(id);
                    } else {
                        self.xml.text_element("expression", &[], &coil.variable)?;
                    }
                    self.end_object(element, id)?;
                }
                NetworkOutput::Jump { id, label } => {
                    let id = u64::from(id.0);
                    self.start_object("jump", id, &[("label", label)], column + 1, output_row)?;
                    self.xml.start("connectionPointIn", &[])?;
                    self.connections(end)?;
                    self.xml.end("connectionPointIn")?;
                    self.end_object("jump", id)?;
                }
                NetworkOutput::Return { id } => {
                    let id = u64::from(id.0);
                    self.start_object("return", id, &[], column + 1, output_row)?;
                    self.xml.start("connectionPointIn", &[])?;
                    self.connections(end)?;
                    self.xml.end("connectionPointIn")?;
                    self.end_object("return", id)?;
                }
                NetworkOutput::Branch { rung, outputs, .. } => {
                    let (branch_end, after) =
                        self.chain(rung, end.to_vec(), column + 1, output_row)?;
                    self.outputs(outputs, &branch_end, after, output_row, coils)?;
                }
            }
        }
        Ok(())
    }

    /// Writes an operand as an `inVariable`.
    fn in_variable(
        &mut self,
        operand: &Operand,
        column: i64,
        row: i64,
    ) -> Result<Link, ExportError> {
        let id = u64::from(operand.id.0);
        let attributes = modifiers(operand.negated, operand.edge);
        self.start_object("inVariable", id, &attributes, column, row)?;
        self.xml.empty("connectionPointOut", &[])?;
        self.xml.text_element("expression", &[], &operand.text)?;
        self.end_object("inVariable", id)?;
        Ok(Link { id, pin: None })
    }

    /// Writes the FBD box of `gate` over `inputs`, one pin each, marked with Rivet's `…/gate`
    /// entry so the import gives the chain or the group back.
    fn gate(
        &mut self,
        gate: Gate,
        inputs: &[Vec<Link>],
        column: i64,
        row: i64,
    ) -> Result<Link, ExportError> {
        let (name, of) = match gate {
            Gate::Series => ("AND", "series"),
            Gate::Parallel => ("OR", "parallel"),
        };
        let id = self.fresh();
        self.start_object("block", id, &[("typeName", name)], column, row)?;
        self.xml.start("inputVariables", &[])?;
        for (index, links) in inputs.iter().enumerate() {
            let pin = format!("IN{}", index + 1);
            self.xml.start("variable", &[("formalParameter", &pin)])?;
            self.xml.start("connectionPointIn", &[])?;
            self.connections(links)?;
            self.xml.end("connectionPointIn")?;
            self.xml.end("variable")?;
        }
        self.xml.end("inputVariables")?;
        self.xml.empty("inOutVariables", &[])?;
        self.xml.start("outputVariables", &[])?;
        self.xml.start("variable", &[("formalParameter", "OUT")])?;
        self.xml.empty("connectionPointOut", &[])?;
        self.xml.end("variable")?;
        self.xml.end("outputVariables")?;
        self.xml.start("addData", &[])?;
        self.xml.start(
            "data",
            &[("name", GATE_ENTRY), ("handleUnknown", "discard")],
        )?;
        self.xml
            .empty("gate", &[("xmlns", RIVET_NAMESPACE), ("of", of)])?;
        self.xml.end("data")?;
        self.xml.end("addData")?;
        self.xml.end("block")?;
        Ok(Link {
            id,
            pin: Some("OUT".into()),
        })
    }

    /// Closes the object of element `id`, after the `addData` with its entries when it has
    /// some (the schema puts `addData` last but for `documentation`, which these objects lack).
    fn end_object(&mut self, element: &str, id: u64) -> Result<(), ExportError> {
        self.end_object_marked(element, id, None)
    }

    /// [`Self::end_object`] for a box, with Rivet's source mark naming `source_pin` when its
    /// first input has its own source: one `addData` holds the kept entries and the mark.
    fn end_object_marked(
        &mut self,
        element: &str,
        id: u64,
        source_pin: Option<&str>,
    ) -> Result<(), ExportError> {
        let entries = self.element_data.remove(&id);
        if entries.is_some() || source_pin.is_some() {
            self.xml.start("addData", &[])?;
            if let Some(entries) = &entries {
                for entry in entries {
                    self.xml.raw(entry)?;
                }
                self.data_written.push(id);
            }
            if let Some(pin) = source_pin {
                self.xml.start(
                    "data",
                    &[("name", SOURCE_ENTRY), ("handleUnknown", "discard")],
                )?;
                self.xml
                    .empty("source", &[("xmlns", RIVET_NAMESPACE), ("pin", pin)])?;
                self.xml.end("data")?;
            }
            self.xml.end("addData")?;
        }
        self.xml.end(element)
    }

    /// Opens an object with its `localId` and attributes and writes its position.
    fn start_object(
        &mut self,
        element: &str,
        id: u64,
        attributes: &[(&str, &str)],
        column: i64,
        row: i64,
    ) -> Result<(), ExportError> {
        self.first_written.get_or_insert(id);
        let id_text = id.to_string();
        let mut all = vec![("localId", id_text.as_str())];
        all.extend_from_slice(attributes);
        self.xml.start(element, &all)?;
        self.position(column, row)
    }

    fn position(&mut self, column: i64, row: i64) -> Result<(), ExportError> {
        let x = (column * COLUMN_WIDTH * 10).to_string();
        let y = (row * ROW_HEIGHT * 10).to_string();
        self.xml.empty("position", &[("x", &x), ("y", &y)])
    }

    /// Writes one `connection` per link, in order.
    fn connections(&mut self, links: &[Link]) -> Result<(), ExportError> {
        for link in links {
            let id = link.id.to_string();
            let mut attributes = vec![("refLocalId", id.as_str())];
            if let Some(pin) = &link.pin {
                attributes.push(("formalParameter", pin));
            }
            self.xml.empty("connection", &attributes)?;
        }
        Ok(())
    }

    fn fresh(&mut self) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        id
    }

    /// A new row below everything written so far.
    fn row(&mut self) -> i64 {
        let row = self.next_row;
        self.next_row += 1;
        row
    }
}

/// The `negated` and `edge` attributes of a contact, variable or pin.
fn modifiers(negated: bool, edge: Edge) -> Vec<(&'static str, &'static str)> {
    let mut attributes = Vec::new();
    if negated {
        attributes.push(("negated", "true"));
    }
    match edge {
        Edge::None => {}
        Edge::Rising => attributes.push(("edge", "rising")),
        Edge::Falling => attributes.push(("edge", "falling")),
    }
    attributes
}
