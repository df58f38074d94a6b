//! Version 1 LD/FBD networks (placed elements joined by connections) turned into version 2's
//! structured networks.
//!
//! The graph is read backwards from what each network drives (coils, outputs, jumps, returns,
//! and elements whose flow goes nowhere): the flow into an element's input is a *point*, the
//! set of pins wired to it. A point with one driver comes after that driver's element; a point
//! with several drivers is a parallel group whose branches start at the nearest point all of
//! them come from. Chains are built between points, and what several outputs share becomes the
//! rung with output branches after it. A graph that is not series-parallel makes some element
//! appear twice, which is reported rather than guessed at; nothing is dropped silently.

use std::collections::{BTreeSet, HashMap, HashSet};

use super::graph_chart::{Chart, ChartElement, ChartElementKind};
use crate::{
    BlockCall, BlockInput, BlockOutput, Branch, Coil, CoilKind, ElementId, FlowNode,
    MAX_NETWORK_NESTING, Network, NetworkOutput, NetworkProblem, Operand, Parallel,
};

/// Converts the version 1 networks of one body; new elements (parallel groups, output
/// branches, literal inputs) take ids above every id of the body.
pub(crate) fn convert_charts(charts: &[Chart]) -> Result<Vec<Network>, Vec<NetworkProblem>> {
    let mut next_id = charts
        .iter()
        .flat_map(|chart| chart.elements.iter().map(|element| element.id.0))
        .max()
        .unwrap_or(0)
        .saturating_add(1);
    let mut networks = Vec::new();
    let mut problems = Vec::new();
    for (index, chart) in charts.iter().enumerate() {
        match Converter::new(chart, &mut next_id).and_then(Converter::network) {
            Ok(network) => networks.push(network),
            Err(failure) => problems.push(NetworkProblem {
                network: index,
                network_name: chart.label.clone(),
                element: failure.element,
                message: failure.message,
            }),
        }
    }
    if problems.is_empty() {
        Ok(networks)
    } else {
        Err(problems)
    }
}

/// Why a network cannot be converted, at an element where there is one.
struct Failure {
    element: Option<ElementId>,
    message: String,
}

fn fail<T>(element: ElementId, message: impl Into<String>) -> Result<T, Failure> {
    Err(Failure {
        element: Some(element),
        message: format!("cannot be converted to version 2: {}", message.into()),
    })
}

/// What is wired to an input.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Driver {
    /// The left power rail.
    Rail,
    /// The flow out of an element: a contact, an input, or a box's ENO (else first output).
    Out(ElementId),
    /// Another output pin of a box, lower case.
    Pin(ElementId, String),
}

/// The flow into an input: its drivers, sorted; several drivers are ORed.
type Point = Vec<Driver>;

/// Something the network drives, with the point that feeds it.
struct Sink<'a> {
    element: &'a ChartElement,
    point: Point,
    /// The points from `point` back to the rail.
    spine: Vec<Point>,
}

struct Converter<'a> {
    chart: &'a Chart,
    next_id: &'a mut u32,
    elements: HashMap<ElementId, &'a ChartElement>,
    /// The drivers of each input pin (element, lower-case pin name).
    drivers: HashMap<(ElementId, String), Vec<Driver>>,
    /// How many connections leave each output pin, not counting the right rail.
    consumers: HashMap<(ElementId, String), usize>,
    /// The variable assigned from each box output that is not its flow output.
    assigns: HashMap<(ElementId, String), String>,
    /// The points whose predecessor is being computed, to find cycles.
    in_progress: HashSet<Point>,
    predecessors: HashMap<Point, Option<Point>>,
    /// How deeply chains and parallel groups are nested where the conversion is, so that no
    /// file can exhaust the stack.
    depth: usize,
}

impl<'a> Converter<'a> {
    fn new(chart: &'a Chart, next_id: &'a mut u32) -> Result<Self, Failure> {
        let mut converter = Self {
            chart,
            next_id,
            elements: HashMap::new(),
            drivers: HashMap::new(),
            consumers: HashMap::new(),
            assigns: HashMap::new(),
            in_progress: HashSet::new(),
            predecessors: HashMap::new(),
            depth: 0,
        };
        for element in &chart.elements {
            if converter.elements.insert(element.id, element).is_some() {
                return fail(
                    element.id,
                    format!("two elements have the id {}", element.id.0),
                );
            }
            let unsupported = match &element.kind {
                ChartElementKind::Connector { .. } | ChartElementKind::Continuation { .. } => {
                    Some("a connector")
                }
                ChartElementKind::Step { .. }
                | ChartElementKind::Transition { .. }
                | ChartElementKind::Divergence { .. }
                | ChartElementKind::Convergence { .. }
                | ChartElementKind::StepJump { .. } => Some("an SFC element"),
                _ => None,
            };
            if let Some(what) = unsupported {
                return fail(
                    element.id,
                    format!("{what} has no place in an LD or FBD network"),
                );
            }
        }
        converter.read_connections()?;
        Ok(converter)
    }

    /// Checks every connection's ends and records drivers, consumers and assignments.
    fn read_connections(&mut self) -> Result<(), Failure> {
        for connection in &self.chart.connections {
            let (from, to) = (&connection.from, &connection.to);
            for end in [from, to] {
                if !self.elements.contains_key(&end.element) {
                    let other = if end == from { to } else { from };
                    return fail(
                        other.element,
                        format!(
                            "a connection leads to element {}, which does not exist",
                            end.element.0
                        ),
                    );
                }
            }
            let source = self.elements[&from.element];
            let target = self.elements[&to.element];
            let from_pin = from.pin.to_lowercase();
            let to_pin = to.pin.to_lowercase();
            if !has_output_pin(&source.kind, &from_pin) {
                return fail(
                    source.id,
                    format!(
                        "a connection starts at '{}', which is not an output",
                        from.pin
                    ),
                );
            }
            if !has_input_pin(&target.kind, &to_pin) {
                return fail(
                    target.id,
                    format!("a connection ends at '{}', which is not an input", to.pin),
                );
            }
            if matches!(target.kind, ChartElementKind::RightRail { .. }) {
                continue;
            }
            let driver = match &source.kind {
                ChartElementKind::LeftRail { .. } => Driver::Rail,
                ChartElementKind::Block { .. }
                    if Some(&from_pin) != flow_output(&source.kind).as_ref() =>
                {
                    Driver::Pin(source.id, from_pin.clone())
                }
                _ => Driver::Out(source.id),
            };
            *self
                .consumers
                .entry((source.id, from_pin.clone()))
                .or_default() += 1;
            if let (Driver::Pin(..), ChartElementKind::Output { expression }) =
                (&driver, &target.kind)
            {
                let previous = self
                    .assigns
                    .insert((source.id, from_pin.clone()), expression.clone());
                if previous.is_some() {
                    return fail(
                        source.id,
                        format!(
                            "the output '{}' is wired to two output variables; version 2 \
                             assigns one",
                            from.pin
                        ),
                    );
                }
            }
            self.drivers
                .entry((target.id, to_pin))
                .or_default()
                .push(driver);
        }
        Ok(())
    }

    fn fresh_id(&mut self) -> ElementId {
        let id = ElementId(*self.next_id);
        *self.next_id = self.next_id.saturating_add(1);
        id
    }

    fn network(mut self) -> Result<Network, Failure> {
        let mut sinks = self.sinks()?;
        sinks.sort_by_key(|sink| (sink.element.y, sink.element.x, sink.element.id));
        let spines: Vec<&[Point]> = sinks.iter().map(|sink| &sink.spine[..]).collect();
        let base = deepest_common_point(&spines);
        let rung = self.chain(&base, &vec![Driver::Rail])?;
        let all: Vec<usize> = (0..sinks.len()).collect();
        let outputs = self.outputs(&base, &sinks, &all)?;
        let comments: Vec<&str> = self
            .chart
            .elements
            .iter()
            .filter_map(|element| match &element.kind {
                ChartElementKind::Comment { text, .. } => Some(text.as_str()),
                _ => None,
            })
            .collect();
        let mut comment = self.chart.comment.clone();
        for text in comments {
            if !comment.is_empty() {
                comment.push_str("\n\n");
            }
            comment.push_str(text);
        }
        let network = Network {
            title: String::new(),
            comment,
            label: self.chart.label.clone(),
            rung,
            outputs,
        };
        self.check_every_element_once(&network)?;
        Ok(network)
    }

    /// Everything the network drives: coils, jumps, returns, outputs fed by the flow, and the
    /// elements whose flow goes nowhere (a rung that ends in a contact or a box).
    fn sinks(&mut self) -> Result<Vec<Sink<'a>>, Failure> {
        let mut sinks = Vec::new();
        let elements: Vec<&'a ChartElement> = self.chart.elements.iter().collect();
        for element in elements {
            let point = match &element.kind {
                ChartElementKind::Coil { .. }
                | ChartElementKind::Jump { .. }
                | ChartElementKind::Return => self.input_point(element.id, ""),
                ChartElementKind::Output { .. } => {
                    let point = self.input_point(element.id, "");
                    if point.iter().any(|driver| matches!(driver, Driver::Pin(..))) {
                        if point.len() > 1 {
                            return fail(element.id, "the output has two drivers");
                        }
                        // Assigned by its box, as the output pin's `assign`.
                        continue;
                    }
                    point
                }
                ChartElementKind::Contact { .. }
                | ChartElementKind::Input { .. }
                | ChartElementKind::Block { .. } => {
                    let flow = flow_output(&element.kind).unwrap_or_default();
                    if self.consumers.contains_key(&(element.id, flow)) {
                        continue;
                    }
                    vec![Driver::Out(element.id)]
                }
                _ => continue,
            };
            if point.is_empty() {
                return fail(element.id, "its input is not connected");
            }
            let spine = self.spine(&point)?;
            sinks.push(Sink {
                element,
                point,
                spine,
            });
        }
        Ok(sinks)
    }

    /// The drivers of an element's input pin, with coils (which pass their flow on) replaced
    /// by what drives them.
    fn input_point(&self, element: ElementId, pin: &str) -> Point {
        let mut point = BTreeSet::new();
        let mut pending: Vec<Driver> = self
            .drivers
            .get(&(element, pin.to_owned()))
            .cloned()
            .unwrap_or_default();
        let mut expanded = HashSet::new();
        while let Some(driver) = pending.pop() {
            let coil = match &driver {
                Driver::Out(id) => {
                    matches!(self.elements[id].kind, ChartElementKind::Coil { .. }).then_some(*id)
                }
                _ => None,
            };
            match coil {
                // A coil met again adds nothing: its drivers are already in.
                Some(id) if !expanded.insert(id) => {}
                Some(id) => pending.extend(
                    self.drivers
                        .get(&(id, String::new()))
                        .cloned()
                        .unwrap_or_default(),
                ),
                None => {
                    point.insert(driver);
                }
            }
        }
        point.into_iter().collect()
    }

    /// The point that feeds an element's flow input.
    fn flow_input_point(&self, id: ElementId) -> Result<Point, Failure> {
        let element = self.elements[&id];
        match &element.kind {
            ChartElementKind::Contact { .. } => {
                let point = self.input_point(id, "");
                if point.is_empty() {
                    return fail(id, "the contact's input is not connected");
                }
                Ok(point)
            }
            ChartElementKind::Block { inputs, en_eno, .. } => {
                let Some(pin) = flow_input(&element.kind) else {
                    return Ok(vec![Driver::Rail]);
                };
                let point = self.input_point(id, &pin);
                match (point.is_empty(), en_eno) {
                    (false, _) => Ok(point),
                    // An unconnected EN is TRUE.
                    (true, true) => Ok(vec![Driver::Rail]),
                    (true, false) => fail(
                        id,
                        format!(
                            "the input '{}' is not connected; in version 2 a box's first \
                             input carries the flow of its chain",
                            inputs.first().map(String::as_str).unwrap_or_default()
                        ),
                    ),
                }
            }
            _ => Ok(vec![Driver::Rail]),
        }
    }

    /// The point a chain ending at `point` starts from: before its one element, or where the
    /// branches of its parallel group split.
    fn predecessor(&mut self, point: &Point) -> Result<Option<Point>, Failure> {
        if let Some(known) = self.predecessors.get(point) {
            return Ok(known.clone());
        }
        if !self.in_progress.insert(point.clone()) {
            return fail(first_element(point), "the elements form a cycle");
        }
        let result = match point.as_slice() {
            [Driver::Rail] | [] => None,
            [Driver::Out(id)] => Some(self.flow_input_point(*id)?),
            [Driver::Pin(id, pin)] => return pin_error(*id, pin),
            drivers => {
                self.enter(point)?;
                let mut spines = Vec::new();
                for driver in drivers {
                    spines.push(self.spine(&vec![driver.clone()])?);
                }
                self.depth -= 1;
                let spines: Vec<&[Point]> = spines.iter().map(Vec::as_slice).collect();
                Some(deepest_common_point(&spines))
            }
        };
        self.in_progress.remove(point);
        self.predecessors.insert(point.clone(), result.clone());
        Ok(result)
    }

    /// The points from `point` back to the rail.
    fn spine(&mut self, point: &Point) -> Result<Vec<Point>, Failure> {
        let mut spine = vec![point.clone()];
        let mut current = point.clone();
        while let Some(previous) = self.predecessor(&current)? {
            if spine.contains(&previous) {
                return fail(first_element(&previous), "the elements form a cycle");
            }
            spine.push(previous.clone());
            current = previous;
        }
        Ok(spine)
    }

    /// The chain from point `from` to point `to`; `from` must be on `to`'s spine.
    fn chain(&mut self, to: &Point, from: &Point) -> Result<Vec<FlowNode>, Failure> {
        self.enter(to)?;
        let mut reversed = Vec::new();
        let mut current = to.clone();
        while &current != from {
            let Some(previous) = self.predecessor(&current)? else {
                return fail(
                    first_element(to),
                    "its flow joins others in a way that is not series-parallel",
                );
            };
            match current.as_slice() {
                [Driver::Out(id)] => reversed.push(self.node(*id)?),
                [Driver::Pin(id, pin)] => return pin_error(*id, pin),
                [Driver::Rail] | [] => {}
                drivers => {
                    let mut branches = Vec::new();
                    for driver in drivers.iter().cloned() {
                        let position = self.position(&driver);
                        let rung = self.chain(&vec![driver], &previous)?;
                        branches.push((position, Branch { rung }));
                    }
                    branches.sort_by_key(|(position, _)| *position);
                    reversed.push(FlowNode::Parallel(Parallel {
                        id: self.fresh_id(),
                        branches: branches.into_iter().map(|(_, branch)| branch).collect(),
                    }));
                }
            }
            current = previous;
        }
        reversed.reverse();
        self.depth -= 1;
        Ok(reversed)
    }

    /// Goes one level deeper into nested chains, failing past the nesting version 2 allows.
    fn enter(&mut self, point: &Point) -> Result<(), Failure> {
        self.depth += 1;
        if self.depth > MAX_NETWORK_NESTING {
            return fail(
                first_element(point),
                format!("the network is nested more than {MAX_NETWORK_NESTING} levels deep"),
            );
        }
        Ok(())
    }

    /// Where a driver is drawn, to order parallel branches top to bottom.
    fn position(&self, driver: &Driver) -> (i32, i32) {
        match driver {
            Driver::Rail => (i32::MIN, i32::MIN),
            Driver::Out(id) | Driver::Pin(id, _) => {
                let element = self.elements[id];
                (element.y, element.x)
            }
        }
    }

    /// The chain node of a contact, input or box.
    fn node(&mut self, id: ElementId) -> Result<FlowNode, Failure> {
        let element = self.elements[&id];
        match &element.kind {
            ChartElementKind::Contact {
                variable,
                negated,
                edge,
            } => Ok(FlowNode::Operand(Operand {
                id,
                text: variable.clone(),
                negated: *negated,
                edge: *edge,
            })),
            ChartElementKind::Input { expression } => Ok(FlowNode::Operand(Operand {
                id,
                text: expression.clone(),
                ..Operand::default()
            })),
            ChartElementKind::Block {
                type_name,
                instance,
                inputs,
                outputs,
                en_eno,
            } => {
                let flow_in = flow_input(&element.kind);
                let mut block_inputs = Vec::new();
                let en = en_eno.then(|| crate::EN_PIN.to_owned());
                for pin in en.iter().chain(inputs) {
                    let key = pin.to_lowercase();
                    let source = if Some(&key) == flow_in.as_ref() {
                        Vec::new()
                    } else {
                        self.source(id, pin)?
                    };
                    block_inputs.push(BlockInput {
                        pin: pin.clone(),
                        source,
                        ..BlockInput::default()
                    });
                }
                let eno = en_eno.then(|| crate::ENO_PIN.to_owned());
                let block_outputs = eno
                    .iter()
                    .chain(outputs)
                    .map(|pin| BlockOutput {
                        pin: pin.clone(),
                        assign: self
                            .assigns
                            .get(&(id, pin.to_lowercase()))
                            .cloned()
                            .unwrap_or_default(),
                        ..BlockOutput::default()
                    })
                    .collect();
                Ok(FlowNode::Block(BlockCall {
                    id,
                    type_name: type_name.clone(),
                    instance: instance.clone(),
                    inputs: block_inputs,
                    outputs: block_outputs,
                }))
            }
            _ => fail(id, "the element cannot stand in a chain"),
        }
    }

    /// The source chain of a box input other than the one its flow enters by.
    fn source(&mut self, id: ElementId, pin: &str) -> Result<Vec<FlowNode>, Failure> {
        let point = self.input_point(id, &pin.to_lowercase());
        match point.as_slice() {
            [] => Ok(Vec::new()),
            [Driver::Rail] => Ok(vec![FlowNode::Operand(Operand {
                id: self.fresh_id(),
                text: "TRUE".into(),
                ..Operand::default()
            })]),
            [_] => self.chain(&point, &vec![Driver::Rail]),
            _ => fail(id, format!("the input '{pin}' has {} drivers", point.len())),
        }
    }

    /// The outputs fed from point `base` for the sinks `members`, in drawing order: the sinks
    /// at `base` itself, and an output branch for each group of sinks further on.
    fn outputs(
        &mut self,
        base: &Point,
        sinks: &[Sink<'a>],
        members: &[usize],
    ) -> Result<Vec<NetworkOutput>, Failure> {
        enum Item {
            Direct(usize),
            Group(usize),
        }
        let mut items = Vec::new();
        let mut groups: Vec<(Point, Vec<usize>)> = Vec::new();
        for &index in members {
            let sink = &sinks[index];
            if &sink.point == base {
                items.push(Item::Direct(index));
                continue;
            }
            let Some(position) = sink.spine.iter().position(|point| point == base) else {
                return fail(
                    sink.element.id,
                    "its flow joins others in a way that is not series-parallel",
                );
            };
            let child = sink.spine[position - 1].clone();
            match groups.iter_mut().position(|(point, _)| *point == child) {
                Some(group) => groups[group].1.push(index),
                None => {
                    items.push(Item::Group(groups.len()));
                    groups.push((child, vec![index]));
                }
            }
        }
        let mut outputs = Vec::new();
        for item in items {
            match item {
                Item::Direct(index) => outputs.extend(sink_output(sinks[index].element)),
                Item::Group(group) => {
                    let members = groups[group].1.clone();
                    let spines: Vec<&[Point]> = members
                        .iter()
                        .map(|&index| &sinks[index].spine[..])
                        .collect();
                    let group_base = deepest_common_point(&spines);
                    let rung = self.chain(&group_base, base)?;
                    let id = self.fresh_id();
                    let outputs_of_branch = self.outputs(&group_base, sinks, &members)?;
                    outputs.push(NetworkOutput::Branch {
                        id,
                        rung,
                        outputs: outputs_of_branch,
                    });
                }
            }
        }
        Ok(outputs)
    }

    /// Fails when an element of the graph appears twice in the network (its flow feeds
    /// branches that do not join again in series and parallel) or not at all.
    fn check_every_element_once(&self, network: &Network) -> Result<(), Failure> {
        let mut seen = HashSet::new();
        let mut twice = None;
        network.for_each_element(&mut |element| {
            if !seen.insert(element.id()) && twice.is_none() {
                twice = Some(element.id());
            }
        });
        if let Some(id) = twice {
            return fail(
                id,
                "its flow feeds branches that do not join again in series and parallel",
            );
        }
        for element in &self.chart.elements {
            let converted = match &element.kind {
                ChartElementKind::LeftRail { .. }
                | ChartElementKind::RightRail { .. }
                | ChartElementKind::Comment { .. } => true,
                ChartElementKind::Output { .. } => {
                    seen.contains(&element.id) || self.assigns_from(element.id)
                }
                _ => seen.contains(&element.id),
            };
            if !converted {
                return fail(element.id, "it is not connected to the rest of the network");
            }
        }
        Ok(())
    }

    /// Whether an output element is assigned from a box output pin.
    fn assigns_from(&self, output: ElementId) -> bool {
        self.drivers
            .get(&(output, String::new()))
            .is_some_and(|drivers| {
                drivers.iter().all(|driver| {
                    matches!(driver, Driver::Pin(box_id, _) if self.elements.contains_key(box_id))
                })
            })
    }
}

/// The deepest point that every spine passes through; the rail when they share nothing else.
fn deepest_common_point(spines: &[&[Point]]) -> Point {
    let Some((first, others)) = spines.split_first() else {
        return vec![Driver::Rail];
    };
    first
        .iter()
        .find(|point| others.iter().all(|spine| spine.contains(point)))
        .cloned()
        .unwrap_or_else(|| vec![Driver::Rail])
}

fn first_element(point: &Point) -> ElementId {
    point
        .iter()
        .find_map(|driver| match driver {
            Driver::Out(id) | Driver::Pin(id, _) => Some(*id),
            Driver::Rail => None,
        })
        .unwrap_or_default()
}

fn pin_error<T>(id: ElementId, pin: &str) -> Result<T, Failure> {
    fail(
        id,
        format!(
            "its output '{pin}' drives more than an output variable; in version 2 a box passes \
             on only its ENO, or else its first output"
        ),
    )
}

/// The network output of a sink; `None` for an element whose flow just ends.
fn sink_output(element: &ChartElement) -> Option<NetworkOutput> {
    let id = element.id;
    match &element.kind {
        ChartElementKind::Coil { variable, coil } => Some(NetworkOutput::Coil(Coil {
            id,
            variable: variable.clone(),
            kind: *coil,
        })),
        ChartElementKind::Output { expression } => Some(NetworkOutput::Coil(Coil {
            id,
            variable: expression.clone(),
            kind: CoilKind::Normal,
        })),
        ChartElementKind::Jump { label } => Some(NetworkOutput::Jump {
            id,
            label: label.clone(),
        }),
        ChartElementKind::Return => Some(NetworkOutput::Return { id }),
        _ => None,
    }
}

/// The lower-case name of the input a box's flow enters by: EN, or else its first input.
fn flow_input(kind: &ChartElementKind) -> Option<String> {
    match kind {
        ChartElementKind::Block { en_eno: true, .. } => Some("en".into()),
        ChartElementKind::Block { inputs, .. } => inputs.first().map(|pin| pin.to_lowercase()),
        _ => Some(String::new()),
    }
}

/// The lower-case name of the output a box's flow leaves by: ENO, or else its first output.
fn flow_output(kind: &ChartElementKind) -> Option<String> {
    match kind {
        ChartElementKind::Block { en_eno: true, .. } => Some("eno".into()),
        ChartElementKind::Block { outputs, .. } => outputs.first().map(|pin| pin.to_lowercase()),
        _ => Some(String::new()),
    }
}

fn has_output_pin(kind: &ChartElementKind, pin: &str) -> bool {
    match kind {
        ChartElementKind::LeftRail { .. } => true,
        ChartElementKind::Contact { .. }
        | ChartElementKind::Coil { .. }
        | ChartElementKind::Input { .. } => pin.is_empty(),
        ChartElementKind::Block {
            outputs, en_eno, ..
        } => (*en_eno && pin == "eno") || outputs.iter().any(|name| name.to_lowercase() == pin),
        _ => false,
    }
}

fn has_input_pin(kind: &ChartElementKind, pin: &str) -> bool {
    match kind {
        ChartElementKind::RightRail { .. } => true,
        ChartElementKind::Contact { .. }
        | ChartElementKind::Coil { .. }
        | ChartElementKind::Output { .. }
        | ChartElementKind::Jump { .. }
        | ChartElementKind::Return => pin.is_empty(),
        ChartElementKind::Block { inputs, en_eno, .. } => {
            (*en_eno && pin == "en") || inputs.iter().any(|name| name.to_lowercase() == pin)
        }
        _ => false,
    }
}

#[cfg(test)]
#[path = "chart_conversion_tests.rs"]
mod tests;
