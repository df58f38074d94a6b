//! The wires of an LD or FBD body, resolved: every input point with the outputs that drive it,
//! connectors and continuations replaced by direct connections (`docs/plcopen-xml.md` §3.2).

use std::collections::HashMap;

use super::network_error::NetworkError;
use super::network_gates::{Gate, gate_of, has_own_first_source};
use crate::body_object::{BodyObject, ObjectKind};
use crate::connection::ConnectionPointIn;
use crate::fbd::Block;

/// The most connectors a wire may pass through one after another.
const MAX_CONNECTOR_CHAIN: usize = 256;

/// The resolved wires of one body; it lives as long as the conversion of the body.
pub(super) struct BodyGraph<'b> {
    /// The body's objects in document order; indices into this slice name objects.
    pub objects: &'b [BodyObject],
    /// Each object's input points in order (a block's inputs, then its in-outs).
    pub inputs: Vec<Vec<InputPoint<'b>>>,
    /// The consumers of each output (object, pin): object and input index, in document order;
    /// rebuilt after each change of the wires.
    consumer_index: HashMap<(usize, usize), Vec<(usize, usize)>>,
    /// For each object, the objects its outputs drive; rebuilt with `consumer_index`.
    reader_index: Vec<Vec<usize>>,
    /// For each object, the structure Rivet's export wrote it for, if it is such a box.
    gates: Vec<Option<Gate>>,
    /// For each object, whether it is a box whose first input has a source of its own.
    own_first_source: Vec<bool>,
}

/// One input point of an object and what drives it.
pub(super) struct InputPoint<'b> {
    /// The block pin's formal parameter; `None` for the single input of other objects.
    pub pin: Option<&'b str>,
    /// The connection point as written (its `expression` is CODESYS's value of an input).
    pub point: Option<&'b ConnectionPointIn>,
    /// The outputs that drive it, in connection order (several make a wired OR).
    pub producers: Vec<Producer>,
}

/// What drives an input.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(super) enum Producer {
    /// Output `pin` of `object` (the index into a block's outputs; 0 for other objects).
    Output {
        /// The producing object.
        object: usize,
        /// The output's index.
        pin: usize,
    },
    /// A variable read where the wire was: an instance's output read away from its box, or an
    /// `inOutVariable` read by what comes before its write.
    Read {
        /// The variable's path, such as `timer.Q`.
        text: String,
        /// The output pin was negated.
        negated: bool,
        /// The object whose network must run first for the read to see this cycle's value:
        /// the instance or the `inOutVariable` read; `None` for a read before the write.
        after: Option<usize>,
    },
}

/// A fault at one object of the body.
#[derive(Debug)]
pub(super) struct ObjectFault {
    /// The object's index; out of range for a fault of the body itself.
    pub object: usize,
    /// The fault.
    pub error: NetworkError,
}

/// The index of the output that passes power or value on in a chain: ENO, else the first.
pub(super) fn chain_output(block: &Block) -> usize {
    block
        .outputs
        .iter()
        .position(|pin| {
            pin.formal_parameter
                .eq_ignore_ascii_case(project_model::ENO_PIN)
        })
        .unwrap_or(0)
}

impl<'b> BodyGraph<'b> {
    /// Resolves the wires of `objects`; with `power_wires`, an instance's output that only
    /// power inputs read stays a wire to each of them (else all but one read the variable).
    pub fn new(objects: &'b [BodyObject], power_wires: bool) -> Result<Self, ObjectFault> {
        let index: HashMap<u64, usize> = objects
            .iter()
            .enumerate()
            .map(|(position, object)| (object.local_id, position))
            .collect();
        let mut graph = Self {
            objects,
            inputs: Vec::with_capacity(objects.len()),
            consumer_index: HashMap::new(),
            reader_index: Vec::new(),
            gates: Vec::new(),
            own_first_source: Vec::new(),
        };
        for (position, object) in objects.iter().enumerate() {
            let points = graph.raw_inputs(position, object, &index)?;
            graph.inputs.push(points);
        }
        graph.resolve_continuations()?;
        graph.reindex();
        graph.gates = (0..objects.len())
            .map(|object| {
                gate_of(objects, &graph.inputs, object, |producer, pin| {
                    graph
                        .consumer_index
                        .get(&(producer, pin))
                        .map_or(0, Vec::len)
                })
            })
            .collect();
        graph.own_first_source = (0..objects.len())
            .map(|object| {
                has_own_first_source(objects, &graph.inputs, object, |producer, pin| {
                    graph
                        .consumer_index
                        .get(&(producer, pin))
                        .map_or(0, Vec::len)
                })
            })
            .collect();
        graph.read_instances(power_wires);
        graph.reindex();
        graph.read_in_outs_before_their_write();
        graph.reindex();
        Ok(graph)
    }

    /// The structure Rivet's export wrote `object` for, if it is such a box.
    pub fn gate(&self, object: usize) -> Option<Gate> {
        self.gates.get(object).copied().flatten()
    }

    /// Whether the box `object`'s first input has a source of its own, as Rivet's export
    /// marks it: a value input, the box starting its chain.
    pub fn has_own_first_source(&self, object: usize) -> bool {
        self.own_first_source.get(object).copied().unwrap_or(false)
    }

    /// Whether input `input` of `object` carries power along a chain (a contact's, coil's or
    /// variable's single input, a block's first input unless it has a source of its own, every
    /// input of a parallel group's OR) rather than a value into a box.
    pub fn is_power_input(&self, object: usize, input: usize) -> bool {
        match &self.objects[object].kind {
            ObjectKind::Block(_) => {
                input == 0 && !self.has_own_first_source(object)
                    || self.gate(object) == Some(Gate::Parallel)
            }
            ObjectKind::RightPowerRail(_) => false,
            _ => true,
        }
    }

    /// Every consumer of output `pin` of `object`: the object and its input's index.
    pub fn consumers(&self, object: usize, pin: usize) -> Vec<(usize, usize)> {
        self.consumer_index
            .get(&(object, pin))
            .cloned()
            .unwrap_or_default()
    }

    fn reindex(&mut self) {
        let mut consumers: HashMap<(usize, usize), Vec<(usize, usize)>> = HashMap::new();
        let mut readers = vec![Vec::new(); self.objects.len()];
        for (consumer, points) in self.inputs.iter().enumerate() {
            if self.is_ignored(consumer) {
                continue;
            }
            for (input, point) in points.iter().enumerate() {
                for producer in &point.producers {
                    if let Producer::Output { object, pin } = producer {
                        let list = consumers.entry((*object, *pin)).or_default();
                        if !list.contains(&(consumer, input)) {
                            list.push((consumer, input));
                        }
                        readers[*object].push(consumer);
                    }
                }
            }
        }
        self.consumer_index = consumers;
        self.reader_index = readers;
    }

    /// Objects whose inputs mean nothing to a network: right power rails (and the connectors,
    /// which continuations replace).
    pub fn is_ignored(&self, object: usize) -> bool {
        matches!(
            self.objects[object].kind,
            ObjectKind::RightPowerRail(_) | ObjectKind::Connector(_)
        )
    }

    fn raw_inputs(
        &self,
        position: usize,
        object: &'b BodyObject,
        index: &HashMap<u64, usize>,
    ) -> Result<Vec<InputPoint<'b>>, ObjectFault> {
        let single = |point: &'b Option<ConnectionPointIn>| -> Result<_, ObjectFault> {
            Ok(vec![InputPoint {
                pin: None,
                point: point.as_ref(),
                producers: self.producers(point.as_ref(), index, position)?,
            }])
        };
        match &object.kind {
            ObjectKind::Block(block) => {
                let mut points: Vec<InputPoint<'b>> = Vec::new();
                for pin in block.inputs.iter().chain(&block.in_outs) {
                    let name = pin.formal_parameter.as_str();
                    if points.iter().any(|point| {
                        point
                            .pin
                            .is_some_and(|seen| seen.eq_ignore_ascii_case(name))
                    }) {
                        return Err(ObjectFault {
                            object: position,
                            error: NetworkError::DuplicatePin {
                                pin: name.to_owned(),
                                block: block.type_name.clone(),
                            },
                        });
                    }
                    points.push(InputPoint {
                        pin: Some(name),
                        point: pin.input.as_ref(),
                        producers: self.producers(pin.input.as_ref(), index, position)?,
                    });
                }
                Ok(points)
            }
            ObjectKind::OutVariable(variable) => single(&variable.input),
            ObjectKind::InOutVariable(variable) => single(&variable.input),
            ObjectKind::Contact(contact) => single(&contact.input),
            ObjectKind::Coil(coil) => single(&coil.input),
            ObjectKind::Jump(jump) => single(&jump.input),
            ObjectKind::Return(ret) => single(&ret.input),
            ObjectKind::Connector(connector) => single(&connector.input),
            _ => Ok(Vec::new()),
        }
    }

    /// The producers of one connection point; the reader has already refused a connection to
    /// a missing local id.
    fn producers(
        &self,
        point: Option<&ConnectionPointIn>,
        index: &HashMap<u64, usize>,
        consumer: usize,
    ) -> Result<Vec<Producer>, ObjectFault> {
        let mut producers = Vec::new();
        for connection in point.map_or(&[][..], |point| &point.connections) {
            let Some(&object) = index.get(&connection.ref_local_id) else {
                continue;
            };
            let pin = match &self.objects[object].kind {
                ObjectKind::Block(block) => {
                    match connection
                        .formal_parameter
                        .as_deref()
                        .filter(|p| !p.is_empty())
                    {
                        None if block.outputs.is_empty() => {
                            return Err(ObjectFault {
                                object: consumer,
                                error: NetworkError::UnknownPin {
                                    pin: String::new(),
                                    block: block.type_name.clone(),
                                },
                            });
                        }
                        None => chain_output(block),
                        Some(name) => block
                            .outputs
                            .iter()
                            .position(|pin| pin.formal_parameter == name)
                            .or_else(|| {
                                block
                                    .outputs
                                    .iter()
                                    .position(|pin| pin.formal_parameter.eq_ignore_ascii_case(name))
                            })
                            .ok_or_else(|| ObjectFault {
                                object: consumer,
                                error: NetworkError::UnknownPin {
                                    pin: name.to_owned(),
                                    block: block.type_name.clone(),
                                },
                            })?,
                    }
                }
                _ => 0,
            };
            producers.push(Producer::Output { object, pin });
        }
        Ok(producers)
    }

    /// Replaces every continuation among the producers by what drives its connector.
    fn resolve_continuations(&mut self) -> Result<(), ObjectFault> {
        let mut connectors: HashMap<&str, usize> = HashMap::new();
        for (position, object) in self.objects.iter().enumerate() {
            if let ObjectKind::Connector(connector) = &object.kind {
                if let Some(&first) = connectors.get(connector.name.as_str()) {
                    return Err(ObjectFault {
                        object: position,
                        error: NetworkError::DuplicateConnector {
                            name: connector.name.clone(),
                            first_line: self.objects[first].line,
                            second_line: object.line,
                        },
                    });
                }
                connectors.insert(connector.name.as_str(), position);
            }
        }
        for consumer in 0..self.inputs.len() {
            for input in 0..self.inputs[consumer].len() {
                let mut resolved = Vec::new();
                for producer in &self.inputs[consumer][input].producers {
                    self.resolve(producer, &connectors, &mut resolved, 0)?;
                }
                self.inputs[consumer][input].producers = resolved;
            }
        }
        Ok(())
    }

    fn resolve(
        &self,
        producer: &Producer,
        connectors: &HashMap<&str, usize>,
        resolved: &mut Vec<Producer>,
        depth: usize,
    ) -> Result<(), ObjectFault> {
        let Producer::Output { object, .. } = producer else {
            resolved.push(producer.clone());
            return Ok(());
        };
        let ObjectKind::Continuation(continuation) = &self.objects[*object].kind else {
            resolved.push(producer.clone());
            return Ok(());
        };
        let name = continuation.name.as_str();
        let Some(&connector) = connectors.get(name) else {
            return Err(ObjectFault {
                object: *object,
                error: NetworkError::MissingConnector {
                    name: name.to_owned(),
                },
            });
        };
        // A connector reached again, or a chain of continuations longer than any drawing needs,
        // is refused before the recursion grows.
        if depth > MAX_CONNECTOR_CHAIN {
            return Err(ObjectFault {
                object: connector,
                error: NetworkError::ConnectorLoop {
                    name: name.to_owned(),
                },
            });
        }
        for next in &self.inputs[connector][0].producers {
            self.resolve(next, connectors, resolved, depth + 1)?;
        }
        Ok(())
    }

    /// An instance's output read away from its box becomes a read of `instance.pin`: what its
    /// box's chain output passes along a chain, and what a single value input nests, stay wires.
    fn read_instances(&mut self, power_wires: bool) {
        for consumer in 0..self.inputs.len() {
            for input in 0..self.inputs[consumer].len() {
                for slot in 0..self.inputs[consumer][input].producers.len() {
                    let Producer::Output { object, pin } =
                        self.inputs[consumer][input].producers[slot]
                    else {
                        continue;
                    };
                    let ObjectKind::Block(block) = &self.objects[object].kind else {
                        continue;
                    };
                    let Some(instance) = block
                        .instance_name
                        .as_deref()
                        .filter(|name| !name.is_empty())
                    else {
                        continue;
                    };
                    if self.stays_wire(object, block, pin, consumer, input) {
                        continue;
                    }
                    self.inputs[consumer][input].producers[slot] =
                        instance_read(instance, block, object, pin);
                }
            }
        }
        // An instance's output wired to several elements drives the first (top, then document
        // order) and is read as a variable by the others, so no value fans out; with
        // `power_wires` only when one of them is a box's value input. ENO is no variable of the
        // instance, so its readers stay wires (branches of the power).
        for object in 0..self.objects.len() {
            let ObjectKind::Block(block) = &self.objects[object].kind else {
                continue;
            };
            let Some(instance) = block
                .instance_name
                .as_deref()
                .filter(|name| !name.is_empty())
            else {
                continue;
            };
            let variables = (0..block.outputs.len()).filter(|&pin| {
                !block.outputs[pin]
                    .formal_parameter
                    .eq_ignore_ascii_case(project_model::ENO_PIN)
            });
            for pin in variables {
                let mut readers: Vec<(usize, usize)> = self
                    .consumers(object, pin)
                    .into_iter()
                    .filter(|(reader, _)| {
                        !matches!(
                            self.objects[*reader].kind,
                            ObjectKind::OutVariable(_) | ObjectKind::Coil(_)
                        )
                    })
                    .collect();
                // Power may fan out (parallel groups, output branches): only a value read by
                // a box input must not.
                if power_wires
                    && readers
                        .iter()
                        .all(|&(reader, input)| self.is_power_input(reader, input))
                {
                    continue;
                }
                readers.sort_by(|a, b| {
                    let top = |reader: usize| {
                        self.objects[reader]
                            .position
                            .map_or(0.0, |position| position.y)
                    };
                    top(a.0).total_cmp(&top(b.0)).then(a.0.cmp(&b.0))
                });
                for (consumer, input) in readers.into_iter().skip(1) {
                    for producer in &mut self.inputs[consumer][input].producers {
                        if *producer == (Producer::Output { object, pin }) {
                            *producer = instance_read(instance, block, object, pin);
                        }
                    }
                }
            }
        }
    }

    fn stays_wire(
        &self,
        object: usize,
        block: &Block,
        pin: usize,
        consumer: usize,
        input: usize,
    ) -> bool {
        let consumer_object = &self.objects[consumer];
        let is_out_variable = matches!(consumer_object.kind, ObjectKind::OutVariable(_));
        if pin != chain_output(block) {
            return is_out_variable;
        }
        if self.is_power_input(consumer, input) {
            return true;
        }
        // A box nested into another box's input: its only reader besides variables it assigns.
        (0..block.outputs.len())
            .flat_map(|output| self.consumers(object, output))
            .filter(|(reader, _)| !matches!(self.objects[*reader].kind, ObjectKind::OutVariable(_)))
            .count()
            == 1
    }

    /// What reads an `inOutVariable` and leads back to its input reads the variable's value
    /// before the write, as a variable, and so does a box input (after the write); the other
    /// readers follow the write like a coil's.
    fn read_in_outs_before_their_write(&mut self) {
        for in_out in 0..self.objects.len() {
            let ObjectKind::InOutVariable(variable) = &self.objects[in_out].kind else {
                continue;
            };
            for (consumer, input) in self.consumers(in_out, 0) {
                let before = self.reaches(consumer, in_out);
                if before || !self.is_power_input(consumer, input) {
                    for producer in &mut self.inputs[consumer][input].producers {
                        if *producer
                            == (Producer::Output {
                                object: in_out,
                                pin: 0,
                            })
                        {
                            *producer = Producer::Read {
                                text: variable.expression.trim().to_owned(),
                                negated: false,
                                after: (!before).then_some(in_out),
                            };
                        }
                    }
                }
            }
        }
    }

    /// An object on a wire loop (an FBD feedback, which a CFC chart can hold), if there is one.
    pub fn object_on_loop(&self) -> Option<usize> {
        // 0: not seen, 1: on the current path, 2: done.
        let mut state = vec![0u8; self.objects.len()];
        for start in 0..self.objects.len() {
            if state[start] != 0 {
                continue;
            }
            let mut stack = vec![(start, 0usize)];
            state[start] = 1;
            while let Some(&mut (object, ref mut next)) = stack.last_mut() {
                if let Some(&reader) = self.reader_index[object].get(*next) {
                    *next += 1;
                    match state[reader] {
                        1 => return Some(reader),
                        0 => {
                            state[reader] = 1;
                            stack.push((reader, 0));
                        }
                        _ => {}
                    }
                } else {
                    state[object] = 2;
                    stack.pop();
                }
            }
        }
        None
    }

    /// Whether `to` is reachable from `from` along wires.
    pub fn reaches(&self, from: usize, to: usize) -> bool {
        let mut seen = vec![false; self.objects.len()];
        let mut stack = vec![from];
        while let Some(object) = stack.pop() {
            if object == to {
                return true;
            }
            if std::mem::replace(&mut seen[object], true) {
                continue;
            }
            stack.extend(self.reader_index[object].iter().copied());
        }
        false
    }
}

/// The read of an instance's output `pin` as a variable.
fn instance_read(instance: &str, block: &Block, object: usize, pin: usize) -> Producer {
    let output = &block.outputs[pin];
    Producer::Read {
        text: format!("{instance}.{}", output.formal_parameter),
        negated: output.negated.unwrap_or(false),
        after: Some(object),
    }
}
