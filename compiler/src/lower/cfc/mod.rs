//! CFC charts lowered into Structured Text (`docs/graphical-semantics.md` §8).
//!
//! The elements that run are written in their execution order, one after the other. An
//! input's expression is written where it is used. Every box output is a variable (a function
//! block's `instance.pin`, a function's or operator's result in a hidden variable of the
//! checker's type), as are a composer's structure and a selector's copy of its input; a pin
//! wired from an element reads that variable, so a wire from an element later in the order
//! reads what it stored in the previous cycle, which is how a feedback loop works. Connection
//! marks are resolved to the pin that drives their source before anything is written.

mod boxes;
mod marks;
#[cfg(test)]
mod tests;
mod typing;

use std::collections::{HashMap, HashSet};

use project_model::{
    CfcChart, CfcElement, CfcElementKind, CfcPin, CoilKind, Edge, ElementId, PinRef, Variable, Wire,
};

use super::ProbeKind;
use super::fragment::{Fragment, frag};
use super::network::{BodyLowering, is_path};
use super::value::Value;
use crate::diagnostic::Code;

/// The declared types of ST expressions over a body's names and the hidden variables given.
pub(crate) type ExpressionTypes<'c> = dyn Fn(&[Variable], &[String]) -> Vec<Option<String>> + 'c;

/// What the chart lowering asks the checker about types.
pub(crate) struct ChartTypes<'c> {
    /// The declared types of ST expressions over the body's names and the hidden variables
    /// given, one for each expression (`None` where it has no type a variable can have).
    pub of_expressions: &'c ExpressionTypes<'c>,
    /// The declared type of output `pin` of the function `function` (a `VAR_OUTPUT` of a
    /// project function), if it has one.
    pub of_function_output: &'c dyn Fn(&str, &str) -> Option<String>,
}

/// What an output pin gives when a wire reads it.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Stored {
    /// A variable holding the pin's value, on the element's side of the pin's negation.
    Path {
        /// The variable's path.
        path: String,
        /// Whether it is a BOOL.
        boolean: bool,
    },
    /// A constant: the ENO of a box whose EN is not wired.
    Constant(&'static str),
    /// Nothing: a result whose type cannot be told, reported at the box.
    Missing,
}

/// A chart indexed for the lowering.
struct Chart<'a> {
    /// The elements by id.
    elements: HashMap<ElementId, &'a CfcElement>,
    /// The wire into each input pin, by element and pin name in lower case.
    into: HashMap<(ElementId, String), &'a Wire>,
    /// The wires out of each output pin, by element and pin name in lower case.
    out_of: HashMap<(ElementId, String), Vec<&'a Wire>>,
    /// What each output pin of a box, composer and selector gives.
    stored: HashMap<(ElementId, String), Stored>,
    /// The hidden variable holding the EN of each box whose EN is wired.
    enables: HashMap<ElementId, String>,
    /// The hidden structure variable of each composer and selector.
    structures: HashMap<ElementId, String>,
    /// The hidden variable an input's expression (other than a variable or a literal) is
    /// stored in where it is read, so its wires have a value online.
    expressions: HashMap<ElementId, (String, bool)>,
    /// Each connection sink with the output pin that drives its source; sinks that cannot be
    /// resolved (reported) are missing.
    sinks: HashMap<ElementId, PinRef>,
    /// The labels' names, lower case, each with the first element that has it, the one a
    /// jump goes to.
    labels: HashMap<String, ElementId>,
}

impl Chart<'_> {
    /// Whether the wire into `pin` of `element` comes from something that gives no value (a
    /// connection mark that cannot be resolved, a result whose type cannot be told, an empty
    /// input), which was
    /// reported where it is; the element is then not written, so no finding follows from it.
    fn source_is_broken(&self, element: ElementId, pin: &str) -> bool {
        let Some(wire) = self.into.get(&key(element, pin)) else {
            return false;
        };
        let mut from = &wire.from;
        if let Some(CfcElementKind::ConnectionSink { .. }) =
            self.elements.get(&from.element).map(|e| &e.kind)
        {
            match self.sinks.get(&from.element) {
                Some(driver) => from = driver,
                None => return true,
            }
        }
        match self.elements.get(&from.element).map(|e| &e.kind) {
            Some(CfcElementKind::Input { expression }) => expression.trim().is_empty(),
            Some(_) => matches!(
                self.stored.get(&key(from.element, &from.pin)),
                Some(Stored::Missing) | None
            ),
            None => true,
        }
    }
}

/// The key of a pin in the chart's maps.
fn key(element: ElementId, pin: &str) -> (ElementId, String) {
    (element, pin.trim().to_lowercase())
}

/// A pin's name for a probe or a finding: `None` for an element's only pin.
fn pin_name(pin: &str) -> Option<&str> {
    let pin = pin.trim();
    (!pin.is_empty()).then_some(pin)
}

/// The value read where something cannot be: a finding was reported, so the text only has to
/// parse.
fn placeholder(element: ElementId) -> Value {
    Value::stable(Fragment::plain("FALSE"), true, Some(element))
}

impl BodyLowering<'_> {
    /// Lowers a CFC chart: the elements that run, in their execution order.
    pub(crate) fn chart(&mut self, chart: &CfcChart, types: &ChartTypes<'_>) {
        self.network = 0;
        let mut indexed = Chart {
            elements: chart.elements.iter().map(|e| (e.id, e)).collect(),
            into: HashMap::new(),
            out_of: HashMap::new(),
            stored: HashMap::new(),
            enables: HashMap::new(),
            structures: HashMap::new(),
            expressions: HashMap::new(),
            sinks: HashMap::new(),
            labels: HashMap::new(),
        };
        for wire in &chart.wires {
            indexed
                .into
                .insert(key(wire.to.element, &wire.to.pin), wire);
            indexed
                .out_of
                .entry(key(wire.from.element, &wire.from.pin))
                .or_default()
                .push(wire);
        }
        let mut order: Vec<&CfcElement> = chart
            .elements
            .iter()
            .filter(|element| element.kind.is_executable())
            .collect();
        order.sort_by_key(|element| (element.order, element.id));
        self.resolve_marks(&mut indexed, chart);
        for element in &order {
            if let CfcElementKind::Label { name } = &element.kind
                && *indexed
                    .labels
                    .entry(name.trim().to_lowercase())
                    .or_insert(element.id)
                    != element.id
            {
                self.find(
                    element.id,
                    None,
                    Code::InvalidCfcElement,
                    format!("the label '{}' is given to two elements", name.trim()),
                );
            }
        }
        for element in &chart.elements {
            if let CfcElementKind::Input { expression } = &element.kind
                && expression.trim().is_empty()
            {
                self.find(
                    element.id,
                    None,
                    Code::InvalidCfcElement,
                    "the input is empty; type a variable, a constant or an expression".to_owned(),
                );
            }
        }
        self.declare_stores(&mut indexed, &order, types);
        for element in order {
            self.element(&indexed, element);
        }
        // An input read twice is reported once.
        let mut reported: Vec<super::Finding> = Vec::new();
        for finding in std::mem::take(&mut self.findings) {
            if !reported.contains(&finding) {
                reported.push(finding);
            }
        }
        self.findings = reported;
        // A pin met twice keeps its last probe: an EN's stored value rather than its wire's,
        // an output's variable rather than the value written into it.
        let mut seen = HashSet::new();
        self.probes.reverse();
        self.probes.retain(|probe| {
            seen.insert((
                probe.element,
                probe.pin.as_ref().map(|pin| pin.to_lowercase()),
                probe.kind as u8,
            ))
        });
        self.probes.reverse();
    }

    /// One element that runs.
    fn element(&mut self, chart: &Chart<'_>, element: &CfcElement) {
        let id = element.id;
        if let CfcElementKind::Box(block) = &element.kind {
            self.unwired_function_inputs(chart, id, block);
        }
        let broken = project_model::cfc_input_pins(&element.kind)
            .into_iter()
            .any(|pin| chart.source_is_broken(id, pin));
        if broken {
            return;
        }
        match &element.kind {
            CfcElementKind::Output { expression, coil } => {
                self.output(chart, id, expression, *coil)
            }
            CfcElementKind::Box(block) => self.cfc_box(chart, id, block),
            CfcElementKind::Jump { label } => {
                let label = label.trim();
                if !chart.labels.contains_key(&label.to_lowercase()) {
                    let message = if label.is_empty() {
                        "the jump names no label".to_owned()
                    } else {
                        format!(
                            "the jump goes to '{label}', but no label of this chart has that name"
                        )
                    };
                    self.find(id, None, Code::InvalidCfcElement, message);
                    return;
                }
                self.conditional_statement(chart, id, "jump", format!("JMP {label};"));
            }
            CfcElementKind::Return => {
                self.conditional_statement(chart, id, "return", "RETURN;".to_owned());
            }
            CfcElementKind::Label { name } => {
                let name = name.trim();
                // A label given twice (reported) is written once, where jumps go.
                let first = chart.labels.get(&name.to_lowercase()) == Some(&id);
                if first && project_model::is_valid_identifier(name) {
                    self.emit(frag!(name, ":").mark(self.network, Some(id), None));
                }
            }
            CfcElementKind::Composer { inputs, .. } => self.composer(chart, id, inputs),
            CfcElementKind::Selector { .. } => self.selector(chart, id),
            CfcElementKind::Input { .. }
            | CfcElementKind::Comment { .. }
            | CfcElementKind::ConnectionSource { .. }
            | CfcElementKind::ConnectionSink { .. } => {}
        }
    }

    /// The value on the wire into `pin` of `element`, with the variable the studio reads it
    /// from; `None` when no wire goes there.
    fn wired(
        &mut self,
        chart: &Chart<'_>,
        element: ElementId,
        pin: &str,
    ) -> Option<(Value, Option<String>)> {
        let wire = chart.into.get(&key(element, pin))?;
        Some(self.output_value(chart, &wire.from))
    }

    /// The value an output pin gives, negated when the pin is, with its variable.
    fn output_value(&mut self, chart: &Chart<'_>, from: &PinRef) -> (Value, Option<String>) {
        let Some(source) = chart.elements.get(&from.element) else {
            return (placeholder(from.element), None);
        };
        match &source.kind {
            CfcElementKind::Input { expression } => {
                // An empty input is reported once, before the elements are written.
                if expression.trim().is_empty() {
                    return (placeholder(source.id), None);
                }
                let value = self.user_value(source.id, None, expression, "the input");
                if let Some((name, boolean)) = chart.expressions.get(&source.id) {
                    let store = frag!(name.as_str(), " := ", value.frag, ";");
                    self.emit(store.mark(self.network, Some(source.id), None));
                    self.probe(source.id, None, ProbeKind::Value, name.clone());
                    let stored = Value::stable(
                        Fragment::plain(name.as_str()).mark(self.network, Some(source.id), None),
                        *boolean,
                        Some(source.id),
                    );
                    return (stored, Some(name.clone()));
                }
                let text = expression.trim();
                (value, is_path(text).then(|| text.to_owned()))
            }
            CfcElementKind::ConnectionSink { .. } => match chart.sinks.get(&source.id) {
                // Marks are resolved to a pin that is not a sink, so this recurses once.
                Some(driver) => self.output_value(chart, &driver.clone()),
                None => (placeholder(source.id), None),
            },
            kind => {
                let negated = output_pin(kind, &from.pin).is_some_and(|pin| pin.negated);
                let (value, path) = match chart.stored.get(&key(source.id, &from.pin)) {
                    Some(Stored::Path { path, boolean }) => (
                        Value::stable(
                            Fragment::plain(path.as_str()).mark(
                                self.network,
                                Some(source.id),
                                pin_name(&from.pin),
                            ),
                            *boolean,
                            Some(source.id),
                        ),
                        Some(path.clone()),
                    ),
                    Some(Stored::Constant(constant)) => (
                        Value::stable(Fragment::plain(*constant), true, Some(source.id)),
                        None,
                    ),
                    Some(Stored::Missing) | None => (placeholder(source.id), None),
                };
                (if negated { value.not() } else { value }, path)
            }
        }
    }

    /// The value a named pin of `element` receives: its wire's value through the pin's edge
    /// detection and negation; the wire's variable is the pin's probe.
    fn pin_value(&mut self, chart: &Chart<'_>, element: ElementId, pin: &CfcPin) -> Option<Value> {
        let name = pin.name.trim();
        let (mut value, path) = self.wired(chart, element, name)?;
        if let Some(path) = path {
            self.probe(element, pin_name(name), ProbeKind::Value, path);
        }
        if pin.edge != Edge::None {
            value = self.trigger(element, pin_name(name), pin.edge, value);
        }
        if pin.negated {
            value = value.not();
        }
        value.frag = value.frag.mark(self.network, Some(element), pin_name(name));
        Some(value)
    }

    /// The value on the only input pin of `element`, reported as `what` when not wired.
    fn single_input(&mut self, chart: &Chart<'_>, element: ElementId, what: &str) -> Option<Value> {
        match self.wired(chart, element, "") {
            Some((value, path)) => {
                if let Some(path) = path {
                    self.probe(element, None, ProbeKind::Value, path);
                }
                Some(value)
            }
            None => {
                self.find(
                    element,
                    None,
                    Code::InvalidCfcElement,
                    format!("the {what}'s input is not connected"),
                );
                None
            }
        }
    }

    /// An output: its variable written from its input as the coil says.
    fn output(&mut self, chart: &Chart<'_>, id: ElementId, expression: &str, coil: CoilKind) {
        if expression.trim().is_empty() {
            self.find(
                id,
                None,
                Code::InvalidCfcElement,
                "the output names no variable".to_owned(),
            );
            return;
        }
        let Some(value) = self.single_input(chart, id, "output") else {
            return;
        };
        let target = self.user_value(id, None, expression, "the output's variable");
        let statement = match coil {
            CoilKind::Normal => frag!(target.frag, " := ", value.frag, ";"),
            CoilKind::Negated => frag!(target.frag, " := ", value.not().frag, ";"),
            CoilKind::Set | CoilKind::Reset => {
                let constant = if coil == CoilKind::Set {
                    "TRUE"
                } else {
                    "FALSE"
                };
                frag!(
                    "IF ",
                    value.frag,
                    " THEN ",
                    target.frag,
                    format!(" := {constant}; END_IF;")
                )
            }
            CoilKind::Rising | CoilKind::Falling => {
                let edge = if coil == CoilKind::Rising {
                    Edge::Rising
                } else {
                    Edge::Falling
                };
                let pulse = self.trigger(id, None, edge, value);
                frag!(target.frag, " := ", pulse.frag, ";")
            }
        };
        self.emit(statement.mark(self.network, Some(id), None));
    }

    /// A jump or return: `statement` when its input is TRUE.
    fn conditional_statement(
        &mut self,
        chart: &Chart<'_>,
        id: ElementId,
        what: &str,
        statement: String,
    ) {
        let Some(value) = self.single_input(chart, id, what) else {
            return;
        };
        let whole = frag!("IF ", value.frag, " THEN ", statement, " END_IF;");
        self.emit(whole.mark(self.network, Some(id), None));
    }

    /// A composer: each wired member written into its structure; a member not wired keeps
    /// its value.
    fn composer(&mut self, chart: &Chart<'_>, id: ElementId, inputs: &[CfcPin]) {
        let Some(path) = chart.structures.get(&id).cloned() else {
            return;
        };
        for pin in inputs {
            let member = pin.name.trim();
            if let Some(value) = self.pin_value(chart, id, pin) {
                let target = Fragment::plain(format!("{path}.{member}")).mark(
                    self.network,
                    Some(id),
                    Some(member),
                );
                let statement = frag!(target, " := ", value.frag, ";");
                self.emit(statement.mark(self.network, Some(id), Some(member)));
            }
        }
    }

    /// A selector: its input structure copied when it runs, so its members read that copy.
    fn selector(&mut self, chart: &Chart<'_>, id: ElementId) {
        let Some(value) = self.single_input(chart, id, "selector") else {
            return;
        };
        let Some(copy) = chart.structures.get(&id).cloned() else {
            return;
        };
        let statement = frag!(copy, " := ", value.frag, ";");
        self.emit(statement.mark(self.network, Some(id), None));
    }
}

/// The output pin `pin` of an element with named outputs.
fn output_pin<'k>(kind: &'k CfcElementKind, pin: &str) -> Option<&'k CfcPin> {
    let pins = match kind {
        CfcElementKind::Box(block) => &block.outputs,
        CfcElementKind::Selector { outputs, .. } => outputs,
        _ => return None,
    };
    pins.iter()
        .find(|candidate| candidate.name.trim().eq_ignore_ascii_case(pin.trim()))
}
