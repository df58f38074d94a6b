//! One network's objects → one Rivet [`Network`]: the rung's graph of points, its series and
//! parallel chains, and the tree of outputs after it (`docs/plcopen-xml.md` §3.3 to §3.6).

use std::collections::{HashMap, HashSet};

use project_model::{
    BlockCall, BlockInput, BlockOutput, Coil, CoilKind, Edge, FlowNode, Network, NetworkOutput,
    Operand,
};

use super::network_dominators::deepest_common_dominator;
use super::network_elements::{coil_kind, edge, operand};
use super::network_error::NetworkError;
use super::network_gates::Gate;
use super::network_graph::{BodyGraph, ObjectFault, Producer, chain_output};
use super::network_import::{from_object, provisional_id};
use super::network_series_parallel::{ChainEdge, compare_keys, reduce};
use crate::body_object::ObjectKind;
use crate::ld::{Edge as XmlEdge, Storage};

/// How far below an inner OR's last branch the next branch of the OR it drives is ordered: less
/// than the whole unit positions come in, many times over.
const NESTED_OR_STEP: f64 = 1e-3;

/// Why a group of objects did not become a network.
#[derive(Debug)]
pub(super) enum BuildFailure {
    /// The objects are wrong: an import error at one of them.
    Fault(ObjectFault),
    /// The objects are a valid graph that a structured network cannot hold (a feedback loop,
    /// a value read by two inputs); a CFC chart can.
    NotANetwork(String),
}

impl From<ObjectFault> for BuildFailure {
    fn from(fault: ObjectFault) -> Self {
        BuildFailure::Fault(fault)
    }
}

/// A point of the rung's graph.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum PointKey {
    /// The left power rail (in FBD, where a chain starts).
    Rail,
    /// Output `pin` of an object.
    Output(usize, usize),
    /// The meeting of several wires at input `input` of an object (a wired OR).
    Junction(usize, usize),
    /// The meeting of several wires from these outputs (object, pin), in connection order: the
    /// inputs wired to the same outputs share one wired OR.
    Wired(Vec<(usize, usize)>),
    /// The value read by a [`Producer::Read`], by its number.
    Read(usize),
}

/// What an edge of the rung's graph is.
#[derive(Clone, Debug)]
enum EdgeLabel {
    /// An object that passes power or a value on: contact, block, inVariable.
    Object(usize),
    /// A plain wire (into a wired OR, or an empty CODESYS contact).
    Wire,
    /// A variable read where a wire was.
    Read {
        /// The variable's path.
        text: String,
        /// The read is negated.
        negated: bool,
    },
}

/// An edge of the rung's graph.
#[derive(Clone, Debug)]
struct GraphEdge {
    /// The point the power or value enters.
    from: usize,
    /// The point it leaves.
    to: usize,
    /// What lies between.
    label: EdgeLabel,
    /// Its order among parallel edges and outputs: top, then document order.
    key: (f64, usize),
}

/// What the power at a point drives.
#[derive(Clone, Copy, Debug)]
struct Sink {
    /// The point whose power it takes.
    point: usize,
    /// The coil, outVariable, inOutVariable, jump or return; `None` for a chain's end.
    object: Option<usize>,
    /// Its order among the outputs: top, then document order.
    key: (f64, usize),
}

/// The conversion of one network's objects.
pub(super) struct NetworkBuilder<'g, 'b> {
    /// The body's wires.
    graph: &'g BodyGraph<'b>,
    /// The network's objects.
    members: HashSet<usize>,
    /// The points by what they are; aliases (a junction of one wire) share a number.
    points: HashMap<PointKey, usize>,
    /// The edges between points.
    edges: Vec<GraphEdge>,
    /// The coils, variables, jumps, returns and chain ends at points.
    sinks: Vec<Sink>,
    /// How many box inputs read each point as a value; its length is the number of points.
    value_uses: Vec<usize>,
    /// The edges leaving each point, by index into `edges`.
    leaving: Vec<Vec<usize>>,
    /// The edges entering each point, by index into `edges`.
    entering: Vec<Vec<usize>>,
    /// The number of variable reads so far, which numbers their points.
    reads: usize,
    /// How deep the conversion is in box inputs and output branches.
    depth: usize,
    /// For each of Rivet's ORs added so far, the top its last branch is ordered by: an OR
    /// driving another's input gives its branches to that group, ordered among them.
    or_bottoms: HashMap<usize, f64>,
    /// Whether the body is Rivet's export (it carries the `…/networks` entry): a variable read
    /// only by power inputs is one point for all its readers (the power fans out after it)
    /// rather than read again for each, and a wired OR's branches are in connection order.
    power_wires: bool,
}

impl<'g, 'b> NetworkBuilder<'g, 'b> {
    /// A builder for the objects `members` of `graph`; `power_wires` tells whether a variable
    /// read only by power inputs is one point for all its readers.
    pub fn new(graph: &'g BodyGraph<'b>, members: &[usize], power_wires: bool) -> Self {
        Self {
            graph,
            members: members.iter().copied().collect(),
            points: HashMap::from([(PointKey::Rail, 0)]),
            edges: Vec::new(),
            sinks: Vec::new(),
            value_uses: vec![0],
            leaving: vec![Vec::new()],
            entering: vec![Vec::new()],
            reads: 0,
            depth: 0,
            or_bottoms: HashMap::new(),
            power_wires,
        }
    }

    /// The network with `title`, `comment` and `label`; element ids are left 0.
    pub fn build(
        mut self,
        title: String,
        comment: String,
        label: String,
    ) -> Result<Network, BuildFailure> {
        let mut members: Vec<usize> = self.members.iter().copied().collect();
        members.sort_unstable();
        for &object in &members {
            self.add_object(object)?;
        }
        self.add_chain_ends();
        let sink_points: Vec<usize> = self.sinks.iter().map(|sink| sink.point).collect();
        let mut network = Network {
            title,
            comment,
            label,
            ..Network::default()
        };
        if sink_points.is_empty() {
            return Ok(network);
        }
        // An output no wire from the rail reaches (an object another tool left unwired in a
        // way no drawing has) would vanish from the tree: the body is no set of networks.
        let all: HashSet<usize> = (0..self.value_uses.len()).collect();
        let powered = self.descendants(0, &all);
        if let Some(sink) = self
            .sinks
            .iter()
            .find(|sink| !powered.contains(&sink.point))
        {
            let what = sink
                .object
                .or_else(|| self.object_at(sink.point))
                .map_or_else(
                    || "an output".to_owned(),
                    |object| {
                        format!(
                            "the {} with local id {}",
                            self.graph.objects[object].kind.element_name(),
                            self.graph.objects[object].local_id
                        )
                    },
                );
            return Err(BuildFailure::NotANetwork(format!(
                "{what} is reached by no wire from the power rail"
            )));
        }
        let upstream = self.ancestors(&sink_points);
        let mut in_order: Vec<usize> = upstream.iter().copied().collect();
        in_order.sort_unstable();
        for point in in_order {
            if self.value_uses[point] > 0 {
                return Err(self.fan_out(point));
            }
        }
        let root = self.deepest_dominator(0, &sink_points, &upstream)?;
        network.rung = self.chain(0, root)?;
        network.outputs = self.outputs(root)?;
        Ok(network)
    }

    /// The order key of an object: its top, then its place in the document, after every
    /// wire's connection index (so that, at one height, the connections of a wired OR decide).
    fn key(&self, object: usize) -> (f64, usize) {
        (self.top(object), self.graph.objects.len() + object)
    }

    fn top(&self, object: usize) -> f64 {
        self.graph.objects[object]
            .position
            .map_or(0.0, |position| position.y)
    }

    fn point(&mut self, key: PointKey) -> usize {
        // Aliases (a junction of one wire is its producer's point) share numbers, so the next
        // number is the count of points so far.
        let next = self.value_uses.len();
        let point = *self.points.entry(key).or_insert(next);
        if point == next {
            self.value_uses.push(0);
            self.leaving.push(Vec::new());
            self.entering.push(Vec::new());
        }
        point
    }

    fn push_edge(&mut self, edge: GraphEdge) {
        self.leaving[edge.from].push(self.edges.len());
        self.entering[edge.to].push(self.edges.len());
        self.edges.push(edge);
    }

    /// The point a producer's value stands at: coils and inOutVariables pass on their input.
    fn producer_point(&mut self, producer: &Producer, key: (f64, usize)) -> Option<usize> {
        match producer {
            Producer::Read { text, negated, .. } => {
                self.reads += 1;
                let point = self.point(PointKey::Read(self.reads));
                self.push_edge(GraphEdge {
                    from: 0,
                    to: point,
                    label: EdgeLabel::Read {
                        text: text.clone(),
                        negated: *negated,
                    },
                    key,
                });
                Some(point)
            }
            Producer::Output { object, pin } => match &self.graph.objects[*object].kind {
                ObjectKind::LeftPowerRail(_) => Some(0),
                // A variable read is repeated for each reader (an edge trigger is not: it has
                // a state of its own).
                ObjectKind::InVariable(variable) => {
                    let graph = self.graph;
                    let shared = variable.edge.is_some_and(|edge| edge != XmlEdge::None)
                        || self.power_wires
                            && graph
                                .consumers(*object, 0)
                                .iter()
                                .all(|&(reader, input)| graph.is_power_input(reader, input));
                    let key = if shared {
                        PointKey::Output(*object, 0)
                    } else {
                        self.reads += 1;
                        PointKey::Read(self.reads)
                    };
                    let known = self.points.contains_key(&key);
                    let point = self.point(key);
                    if !known {
                        let key = self.key(*object);
                        self.push_edge(GraphEdge {
                            from: 0,
                            to: point,
                            label: EdgeLabel::Object(*object),
                            key,
                        });
                    }
                    Some(point)
                }
                ObjectKind::Coil(_) | ObjectKind::InOutVariable(_) => self.input_point(*object, 0),
                _ => Some(self.point(PointKey::Output(*object, *pin))),
            },
        }
    }

    /// The point that drives input `input` of `object`, or `None` when nothing does.
    fn input_point(&mut self, object: usize, input: usize) -> Option<usize> {
        if let Some(&point) = self.points.get(&PointKey::Junction(object, input)) {
            return Some(point);
        }
        let key = self.key(object);
        let graph = self.graph;
        let point_in = &graph.inputs[object][input];
        match point_in.producers.as_slice() {
            [] => {
                let text = point_in.point.and_then(|point| point.expression.as_ref())?;
                let point = self.producer_point(
                    &Producer::Read {
                        text: text.trim().to_owned(),
                        negated: false,
                        after: None,
                    },
                    key,
                )?;
                self.points.insert(PointKey::Junction(object, input), point);
                Some(point)
            }
            [only] => {
                let point = self.producer_point(only, key)?;
                self.points.insert(PointKey::Junction(object, input), point);
                Some(point)
            }
            several => {
                let wired: Option<Vec<(usize, usize)>> = several
                    .iter()
                    .map(|producer| match producer {
                        Producer::Output { object, pin } => Some((*object, *pin)),
                        Producer::Read { .. } => None,
                    })
                    .collect();
                if let Some(wired) = &wired
                    && let Some(&point) = self.points.get(&PointKey::Wired(wired.clone()))
                {
                    self.points.insert(PointKey::Junction(object, input), point);
                    return Some(point);
                }
                let junction = self.point(PointKey::Junction(object, input));
                if let Some(wired) = wired {
                    self.points.insert(PointKey::Wired(wired), junction);
                }
                // A branch of a wired OR is ordered by its top, then by its connection's place
                // in the OR (CODESYS writes no positions: its connection order is the order).
                // Rivet's export lists the ends in branch order, and an empty branch's end is
                // the element before the group, higher up: there a branch's top is never above
                // the one before it nor above the element the branches meet at (§3.4).
                let mut floor = self.top(object);
                for (connection, producer) in several.iter().enumerate() {
                    let (producer_key, top) = match producer {
                        Producer::Output {
                            object: producer, ..
                        } => {
                            let top = self.top(*producer);
                            let top = if self.power_wires {
                                floor = floor.max(top);
                                floor
                            } else {
                                top
                            };
                            (self.key(*producer), top)
                        }
                        Producer::Read { .. } => (key, key.0),
                    };
                    if let Some(from) = self.producer_point(producer, producer_key) {
                        self.push_edge(GraphEdge {
                            from,
                            to: junction,
                            label: EdgeLabel::Wire,
                            key: (top, connection),
                        });
                    }
                }
                Some(junction)
            }
        }
    }

    fn add_object(&mut self, object: usize) -> Result<(), BuildFailure> {
        let graph = self.graph;
        let key = self.key(object);
        let nothing_before = |element| ObjectFault {
            object,
            error: NetworkError::NothingBefore { element },
        };
        match &graph.objects[object].kind {
            ObjectKind::Contact(contact) => {
                let from = self
                    .input_point(object, 0)
                    .ok_or_else(|| nothing_before("contact"))?;
                let to = self.point(PointKey::Output(object, 0));
                let label = if contact.variable.trim().is_empty() {
                    EdgeLabel::Wire
                } else {
                    EdgeLabel::Object(object)
                };
                self.push_edge(GraphEdge {
                    from,
                    to,
                    label,
                    key,
                });
            }
            // A variable read by nothing stands alone as a chain of one operand.
            ObjectKind::InVariable(_) if graph.consumers(object, 0).is_empty() => {
                self.producer_point(&Producer::Output { object, pin: 0 }, key);
            }
            ObjectKind::Block(_) if graph.gate(object).is_some() => {
                self.add_gate(object);
            }
            ObjectKind::Block(block) => {
                // A box whose first input has a source of its own starts its chain.
                let own_source = graph.has_own_first_source(object);
                let from = if graph.inputs[object].is_empty() || own_source {
                    0
                } else {
                    self.input_point(object, 0).unwrap_or(0)
                };
                let to = self.point(PointKey::Output(object, chain_output(block)));
                self.push_edge(GraphEdge {
                    from,
                    to,
                    label: EdgeLabel::Object(object),
                    key,
                });
                let first_value = if own_source { 0 } else { 1 };
                for input in first_value..graph.inputs[object].len() {
                    if let Some(point) = self.input_point(object, input) {
                        self.value_uses[point] += 1;
                    }
                }
                // A function's other outputs can only be assigned to variables.
                if block.instance_name.as_deref().is_none_or(str::is_empty) {
                    for pin in (0..block.outputs.len()).filter(|&pin| pin != chain_output(block)) {
                        let readers = graph.consumers(object, pin);
                        if readers.iter().any(|(reader, _)| {
                            !matches!(graph.objects[*reader].kind, ObjectKind::OutVariable(_))
                        }) {
                            return Err(BuildFailure::NotANetwork(format!(
                                "the output {} of the function {} drives another element",
                                block.outputs[pin].formal_parameter, block.type_name
                            )));
                        }
                    }
                }
            }
            ObjectKind::OutVariable(_) if self.is_assignment(object) => {}
            ObjectKind::Coil(_)
            | ObjectKind::OutVariable(_)
            | ObjectKind::InOutVariable(_)
            | ObjectKind::Jump(_)
            | ObjectKind::Return(_) => {
                let element = graph.objects[object].kind.element_name();
                let point = self
                    .input_point(object, 0)
                    .ok_or_else(|| nothing_before(element))?;
                self.sinks.push(Sink {
                    point,
                    object: Some(object),
                    key,
                });
            }
            _ => {}
        }
        Ok(())
    }

    /// A box Rivet's export wrote for a chain's operand or a parallel group: the operand is an
    /// edge like a contact's, the group's branches meet at the box's output like a wired OR.
    fn add_gate(&mut self, object: usize) {
        let graph = self.graph;
        let output = self.point(PointKey::Output(object, 0));
        match graph.gate(object) {
            Some(Gate::Series { operand }) => {
                let from = self.input_point(object, 0).unwrap_or(0);
                let key = self.key(operand);
                self.push_edge(GraphEdge {
                    from,
                    to: output,
                    label: EdgeLabel::Object(operand),
                    key,
                });
            }
            Some(Gate::Parallel) => {
                // The branches are in pin order (§3.4), each on rows below the one before:
                // a branch's top is that of what drives it, but never above the branch before
                // it (an inner OR's last branch included, whose branches join this group's)
                // nor above the OR (the row of the first branch), since an empty branch is
                // wired from the element before the group, which may stand higher up. So the
                // group also stands among the outputs below the coils written before it.
                let mut top = self.top(object);
                for input in 0..graph.inputs[object].len() {
                    // A branch without elements at the start of an FBD rung leaves its input
                    // open: it starts where the rung does.
                    let from = self.input_point(object, input).unwrap_or(0);
                    let producer = match graph.inputs[object][input].producers.first() {
                        Some(Producer::Output {
                            object: producer, ..
                        }) => Some(*producer),
                        _ => None,
                    };
                    if let Some(producer) = producer {
                        top = top.max(self.top(producer));
                    }
                    self.push_edge(GraphEdge {
                        from,
                        to: output,
                        label: EdgeLabel::Wire,
                        key: (top, input),
                    });
                    // Just below the inner OR's last branch: positions are whole numbers, so
                    // the next branch sorts after each of its branches, however deep they nest.
                    if let Some(&bottom) = producer.and_then(|p| self.or_bottoms.get(&p)) {
                        top = top.max(bottom + NESTED_OR_STEP);
                    }
                }
                self.or_bottoms.insert(object, top);
            }
            None => {}
        }
    }

    /// Whether an outVariable is the assignment of a box's output other than its chain output.
    fn is_assignment(&self, object: usize) -> bool {
        match self.graph.inputs[object][0].producers.as_slice() {
            [
                Producer::Output {
                    object: producer,
                    pin,
                },
            ] => match &self.graph.objects[*producer].kind {
                ObjectKind::Block(block) => *pin != chain_output(block),
                _ => false,
            },
            _ => false,
        }
    }

    /// A contact, box or variable whose output drives nothing ends a chain of its own.
    fn add_chain_ends(&mut self) {
        let mut used: HashSet<usize> = self.edges.iter().map(|edge| edge.from).collect();
        used.extend(self.sinks.iter().map(|sink| sink.point));
        for edge in self.edges.clone() {
            if let EdgeLabel::Object(object) = edge.label {
                let is_end = matches!(
                    self.graph.objects[object].kind,
                    ObjectKind::Contact(_) | ObjectKind::Block(_) | ObjectKind::InVariable(_)
                );
                if is_end && !used.contains(&edge.to) && self.value_uses[edge.to] == 0 {
                    used.insert(edge.to);
                    self.sinks.push(Sink {
                        point: edge.to,
                        object: None,
                        key: edge.key,
                    });
                }
            }
        }
    }

    /// The object a point stands for: a junction of one wire is an alias of its producer's
    /// output, so the producer is preferred.
    fn object_at(&self, point: usize) -> Option<usize> {
        self.points
            .iter()
            .filter(|(_, p)| **p == point)
            .filter_map(|(key, _)| match key {
                PointKey::Output(object, _) => Some((0, *object)),
                PointKey::Junction(object, _) => Some((1, *object)),
                _ => None,
            })
            .min()
            .map(|(_, object)| object)
    }

    fn fan_out(&self, point: usize) -> BuildFailure {
        let what = self.object_at(point).map_or_else(String::new, |object| {
            format!(
                " of the {} with local id {}",
                self.graph.objects[object].kind.element_name(),
                self.graph.objects[object].local_id
            )
        });
        BuildFailure::NotANetwork(format!(
            "the value{what} drives more than one input, and one of them is a box input"
        ))
    }

    /// Every point from which one of `targets` is reached, the targets included.
    fn ancestors(&self, targets: &[usize]) -> HashSet<usize> {
        let mut seen: HashSet<usize> = HashSet::new();
        let mut stack: Vec<usize> = targets.to_vec();
        while let Some(point) = stack.pop() {
            if seen.insert(point) {
                stack.extend(
                    self.entering[point]
                        .iter()
                        .map(|&edge| self.edges[edge].from),
                );
            }
        }
        seen
    }

    /// Every point reached from `source` within `allowed`, `source` included.
    fn descendants(&self, source: usize, allowed: &HashSet<usize>) -> HashSet<usize> {
        let mut seen: HashSet<usize> = HashSet::new();
        let mut stack = vec![source];
        while let Some(point) = stack.pop() {
            if allowed.contains(&point) && seen.insert(point) {
                stack.extend(self.leaving[point].iter().map(|&edge| self.edges[edge].to));
            }
        }
        seen
    }

    /// The point nearest to `targets` that every path from `root` to them passes.
    fn deepest_dominator(
        &self,
        root: usize,
        targets: &[usize],
        allowed: &HashSet<usize>,
    ) -> Result<usize, BuildFailure> {
        let reachable = self.descendants(root, allowed);
        let order: Vec<usize> = self
            .topological_order(allowed)?
            .into_iter()
            .filter(|point| reachable.contains(point))
            .collect();
        Ok(deepest_common_dominator(root, &order, targets, |point| {
            self.entering[point]
                .iter()
                .map(|&edge| self.edges[edge].from)
                .filter(|from| reachable.contains(from))
                .collect()
        }))
    }

    fn topological_order(&self, allowed: &HashSet<usize>) -> Result<Vec<usize>, BuildFailure> {
        let mut incoming: HashMap<usize, usize> = allowed.iter().map(|&p| (p, 0)).collect();
        let inner: Vec<&GraphEdge> = self
            .edges
            .iter()
            .filter(|edge| allowed.contains(&edge.from) && allowed.contains(&edge.to))
            .collect();
        for edge in &inner {
            *incoming.entry(edge.to).or_default() += 1;
        }
        let mut ready: Vec<usize> = incoming
            .iter()
            .filter(|(_, count)| **count == 0)
            .map(|(&point, _)| point)
            .collect();
        ready.sort_unstable();
        let mut order = Vec::new();
        while let Some(point) = ready.pop() {
            order.push(point);
            for edge in self.leaving[point].iter().map(|&edge| &self.edges[edge]) {
                if !allowed.contains(&edge.to) {
                    continue;
                }
                if let Some(count) = incoming.get_mut(&edge.to) {
                    *count -= 1;
                    if *count == 0 {
                        ready.push(edge.to);
                    }
                }
            }
        }
        if order.len() < allowed.len() {
            return Err(BuildFailure::NotANetwork(
                "the rung's wires form a loop".to_owned(),
            ));
        }
        Ok(order)
    }

    /// The chain from `source` to `target` over the edges between them.
    fn chain(&mut self, source: usize, target: usize) -> Result<Vec<FlowNode>, BuildFailure> {
        let between: HashSet<usize> = {
            let upstream = self.ancestors(&[target]);
            self.descendants(source, &upstream)
        };
        let inner: Vec<GraphEdge> = self
            .edges
            .iter()
            .filter(|edge| between.contains(&edge.from) && between.contains(&edge.to))
            .cloned()
            .collect();
        let mut chain_edges = Vec::with_capacity(inner.len());
        for edge in inner {
            let (nodes, has_block) = self.label_nodes(&edge.label)?;
            chain_edges.push(ChainEdge {
                from: edge.from,
                to: edge.to,
                nodes,
                key: edge.key,
                has_block,
                branch_keys: Vec::new(),
            });
        }
        let first_object = self
            .edges
            .iter()
            .find_map(|edge| match edge.label {
                EdgeLabel::Object(object) if between.contains(&edge.to) => Some(object),
                _ => None,
            })
            .unwrap_or(0);
        reduce(source, target, chain_edges).map_err(|error| {
            BuildFailure::Fault(ObjectFault {
                object: first_object,
                error,
            })
        })
    }

    fn label_nodes(&mut self, label: &EdgeLabel) -> Result<(Vec<FlowNode>, bool), BuildFailure> {
        let graph = self.graph;
        Ok(match label {
            EdgeLabel::Wire => (Vec::new(), false),
            EdgeLabel::Read { text, negated } => (
                vec![FlowNode::Operand(Operand {
                    id: Default::default(),
                    text: text.clone(),
                    negated: *negated,
                    edge: Edge::None,
                })],
                false,
            ),
            EdgeLabel::Object(object) => match &graph.objects[*object].kind {
                ObjectKind::Contact(contact) => (
                    vec![from_object(
                        operand(&contact.variable, contact.negated, contact.edge),
                        *object,
                    )],
                    false,
                ),
                ObjectKind::InVariable(variable) => (
                    vec![from_object(
                        operand(&variable.expression, variable.negated, variable.edge),
                        *object,
                    )],
                    false,
                ),
                ObjectKind::Block(_) => (vec![FlowNode::Block(self.block(*object)?)], true),
                _ => (Vec::new(), false),
            },
        })
    }

    fn block(&mut self, object: usize) -> Result<BlockCall, BuildFailure> {
        let graph = self.graph;
        let ObjectKind::Block(block) = &graph.objects[object].kind else {
            return Ok(BlockCall::default());
        };
        let mut inputs = Vec::new();
        for (index, pin) in block.inputs.iter().chain(&block.in_outs).enumerate() {
            let source = if graph.is_power_input(object, index) {
                Vec::new()
            } else {
                match self.input_point(object, index) {
                    None => Vec::new(),
                    Some(point) => self.value_source(point)?,
                }
            };
            inputs.push(BlockInput {
                pin: pin.formal_parameter.clone(),
                negated: pin.negated.unwrap_or(false),
                edge: edge(pin.edge),
                source,
            });
        }
        let chain = chain_output(block);
        let mut outputs = Vec::new();
        for (index, pin) in block.outputs.iter().enumerate() {
            let mut assign = pin
                .output
                .as_ref()
                .and_then(|point| point.expression.as_deref())
                .map_or_else(String::new, |text| text.trim().to_owned());
            if index != chain {
                let variables: Vec<&str> = graph
                    .consumers(object, index)
                    .into_iter()
                    .filter_map(|(reader, _)| match &graph.objects[reader].kind {
                        ObjectKind::OutVariable(variable) => Some(variable.expression.trim()),
                        _ => None,
                    })
                    .collect();
                match (variables.as_slice(), assign.is_empty()) {
                    ([], _) => {}
                    ([only], true) => assign = (*only).to_owned(),
                    _ => {
                        return Err(BuildFailure::NotANetwork(format!(
                            "the output {} of {} is assigned to more than one variable",
                            pin.formal_parameter, block.type_name
                        )));
                    }
                }
            }
            outputs.push(BlockOutput {
                pin: pin.formal_parameter.clone(),
                negated: pin.negated.unwrap_or(false),
                assign,
            });
        }
        Ok(BlockCall {
            id: provisional_id(object),
            type_name: block.type_name.trim().to_owned(),
            instance: block
                .instance_name
                .as_deref()
                .unwrap_or_default()
                .trim()
                .to_owned(),
            inputs,
            outputs,
        })
    }

    /// The chain that drives a box input at `point`, which nothing else may read.
    fn value_source(&mut self, point: usize) -> Result<Vec<FlowNode>, BuildFailure> {
        let upstream = self.ancestors(&[point]);
        let mut in_order: Vec<usize> = upstream.iter().copied().collect();
        in_order.sort_unstable();
        for inner in in_order {
            if inner == 0 {
                continue;
            }
            let sinks = self.sinks.iter().filter(|sink| sink.point == inner).count();
            let leaving = self.leaving[inner]
                .iter()
                .filter(|&&edge| !upstream.contains(&self.edges[edge].to))
                .count();
            let uses = if inner == point { 1 } else { 0 };
            if sinks > 0 || leaving > 0 || self.value_uses[inner] != uses {
                return Err(self.fan_out(inner));
            }
        }
        // Boxes nested in inputs deeper than a body may hold would also deepen this recursion.
        self.depth += 1;
        if self.depth > project_model::MAX_NETWORK_NESTING {
            return Err(BuildFailure::Fault(ObjectFault {
                object: self.object_at(point).unwrap_or(usize::MAX),
                error: NetworkError::TooDeep {
                    limit: project_model::MAX_NETWORK_NESTING,
                },
            }));
        }
        let chain = self.chain(0, point);
        self.depth -= 1;
        chain
    }

    /// The outputs driven by the power at `root`: its coils, jumps and returns, then a branch
    /// for each part of the graph after it, in the order of their topmost elements.
    fn outputs(&mut self, root: usize) -> Result<Vec<NetworkOutput>, BuildFailure> {
        let mut items: Vec<((f64, usize), NetworkOutput)> = Vec::new();
        for sink in self.sinks.clone() {
            if sink.point == root
                && let Some(output) = self.sink_output(sink)?
            {
                items.push((sink.key, output));
            }
        }
        let all: HashSet<usize> = (0..self.value_uses.len()).collect();
        let leaving: Vec<GraphEdge> = self.leaving[root]
            .iter()
            .map(|&edge| self.edges[edge].clone())
            .collect();
        // Edges whose downstream parts meet belong to one branch.
        let mut groups: Vec<(HashSet<usize>, (f64, usize))> = Vec::new();
        for edge in leaving {
            let reach = self.descendants(edge.to, &all);
            let key = edge.key;
            let mut merged = (reach, key);
            let mut kept = Vec::new();
            for group in groups {
                if group.0.is_disjoint(&merged.0) {
                    kept.push(group);
                } else {
                    merged.0.extend(group.0);
                    if compare_keys(group.1, merged.1).is_lt() {
                        merged.1 = group.1;
                    }
                }
            }
            kept.push(merged);
            groups = kept;
        }
        for (reach, key) in groups {
            let targets: Vec<usize> = self
                .sinks
                .iter()
                .filter(|sink| reach.contains(&sink.point))
                .map(|sink| sink.point)
                .collect();
            if targets.is_empty() {
                continue;
            }
            let mut allowed = reach.clone();
            allowed.insert(root);
            let dominator = self.deepest_dominator(root, &targets, &allowed)?;
            if dominator != root {
                let rung = self.chain(root, dominator)?;
                self.depth += 1;
                if self.depth > project_model::MAX_NETWORK_NESTING {
                    return Err(BuildFailure::Fault(ObjectFault {
                        object: self.object_at(dominator).unwrap_or(usize::MAX),
                        error: NetworkError::TooDeep {
                            limit: project_model::MAX_NETWORK_NESTING,
                        },
                    }));
                }
                let outputs = self.outputs(dominator)?;
                self.depth -= 1;
                items.push((
                    key,
                    NetworkOutput::Branch {
                        id: Default::default(),
                        rung,
                        outputs,
                    },
                ));
                continue;
            }
            // The parts meet but no point joins them all: one branch per sink, which repeats
            // the contacts they share (a box repeated is refused by the reduction).
            let mut seen = HashSet::new();
            for target in targets {
                if !seen.insert(target) {
                    continue;
                }
                let rung = self.chain(root, target)?;
                let mut outputs = Vec::new();
                for sink in self.sinks.clone() {
                    if sink.point == target
                        && let Some(output) = self.sink_output(sink)?
                    {
                        outputs.push(output);
                    }
                }
                items.push((
                    key,
                    NetworkOutput::Branch {
                        id: Default::default(),
                        rung,
                        outputs,
                    },
                ));
            }
        }
        items.sort_by(|a, b| compare_keys(a.0, b.0));
        Ok(items.into_iter().map(|(_, output)| output).collect())
    }

    fn sink_output(&self, sink: Sink) -> Result<Option<NetworkOutput>, BuildFailure> {
        let Some(object) = sink.object else {
            return Ok(None);
        };
        let id = provisional_id(object);
        Ok(Some(match &self.graph.objects[object].kind {
            ObjectKind::Coil(coil) => NetworkOutput::Coil(Coil {
                id,
                variable: coil.variable.trim().to_owned(),
                kind: coil_kind(
                    object,
                    &coil.variable,
                    coil.negated,
                    coil.edge,
                    coil.storage,
                )?,
            }),
            ObjectKind::OutVariable(variable) => NetworkOutput::Coil(Coil {
                id,
                variable: variable.expression.trim().to_owned(),
                kind: coil_kind(
                    object,
                    &variable.expression,
                    variable.negated,
                    variable.edge,
                    variable.storage,
                )?,
            }),
            ObjectKind::InOutVariable(variable) => {
                let flagged = variable.negated_in == Some(true)
                    || variable.negated_out == Some(true)
                    || variable.edge_in.is_some_and(|edge| edge != XmlEdge::None)
                    || variable.edge_out.is_some_and(|edge| edge != XmlEdge::None)
                    || variable.storage_in.is_some_and(|s| s != Storage::None)
                    || variable.storage_out.is_some_and(|s| s != Storage::None);
                if flagged {
                    return Err(BuildFailure::Fault(ObjectFault {
                        object,
                        error: NetworkError::InOutAttributes {
                            variable: variable.expression.trim().to_owned(),
                        },
                    }));
                }
                NetworkOutput::Coil(Coil {
                    id,
                    variable: variable.expression.trim().to_owned(),
                    kind: CoilKind::Normal,
                })
            }
            ObjectKind::Jump(jump) => NetworkOutput::Jump {
                id,
                label: jump.label.trim().to_owned(),
            },
            ObjectKind::Return(_) => NetworkOutput::Return { id },
            _ => return Ok(None),
        }))
    }
}
