//! The variables a chart's outputs are stored in, declared before anything is written, and
//! the types of functions' and operators' results, told by the checker.
//!
//! A result's type is the type of its expression over its inputs, which may read other
//! results: those are typed first, so results are typed in rounds until no more can be. A
//! result in a feedback loop reads itself (or a result that reads it), so it cannot wait for
//! its inputs: an operator box is typed from its inputs outside the loop (`ADD(self, x)` has
//! the type of `x + x`), and any result can take the type of what it is wired to (an
//! output's variable, a function block's input, a composer's member).

use std::collections::HashSet;

use project_model::{CfcElement, CfcElementKind, CfcPin, Edge, ElementId};

use super::boxes::{has_enable, instance_of, is_enable, result_index};
use super::{Chart, ChartTypes, Stored, key, pin_name};
use crate::diagnostic::Code;
use crate::lower::fragment::Fragment;
use crate::lower::network::{BodyLowering, is_simple};
use crate::lower::value::{Value, prec};
use crate::lower::{Callee, ProbeKind};

/// A function's or operator's result whose type is still to be told.
struct Pending {
    /// The box.
    element: ElementId,
    /// The result's pin.
    pin: String,
    /// The hidden variable that will hold it.
    name: String,
}

/// What an input contributes to a result's typing expression.
enum Typing {
    /// Its value, written over the user's names and hidden variables of known type.
    Value(Value),
    /// It reads a result whose type is not known yet.
    Blocked,
    /// It is not wired (reported when the box is written).
    Unwired,
}

impl BodyLowering<'_> {
    /// Declares the variable behind every output pin of the boxes, composers and selectors,
    /// and of each wired EN, and records each output pin's probe.
    pub(super) fn declare_stores(
        &mut self,
        chart: &mut Chart<'_>,
        order: &[&CfcElement],
        types: &ChartTypes<'_>,
    ) {
        let mut pending = Vec::new();
        for element in order {
            let id = element.id;
            match &element.kind {
                CfcElementKind::Box(block) => {
                    if has_enable(block) && chart.into.contains_key(&key(id, project_model::EN_PIN))
                    {
                        let name = self.declare(
                            id,
                            "_EN",
                            "BOOL",
                            format!("the EN input of element {}", id.0),
                        );
                        chart.enables.insert(id, name);
                    }
                    let callee = (self.classify)(&block.type_name);
                    for (index, pin) in block.outputs.iter().enumerate() {
                        let name = pin.name.trim();
                        let stored = if is_enable(pin) {
                            match chart.enables.get(&id) {
                                Some(enable) => Stored::Path {
                                    path: enable.clone(),
                                    boolean: true,
                                },
                                None => Stored::Constant("TRUE"),
                            }
                        } else {
                            match callee {
                                Callee::Block | Callee::Program => {
                                    match instance_of(block, callee) {
                                        Some(instance) => Stored::Path {
                                            path: format!("{instance}.{name}"),
                                            boolean: false,
                                        },
                                        None => Stored::Missing,
                                    }
                                }
                                Callee::Function { .. } if Some(index) == result_index(block) => {
                                    let hidden = self.declare(
                                        id,
                                        &format!("_{name}"),
                                        "",
                                        format!("the output {name} of element {}", id.0),
                                    );
                                    pending.push(Pending {
                                        element: id,
                                        pin: name.to_owned(),
                                        name: hidden.clone(),
                                    });
                                    Stored::Path {
                                        path: hidden,
                                        boolean: false,
                                    }
                                }
                                Callee::Function { .. } => {
                                    match (types.of_function_output)(&block.type_name, name) {
                                        Some(ty) => Stored::Path {
                                            boolean: ty.eq_ignore_ascii_case("BOOL"),
                                            path: self.declare(
                                                id,
                                                &format!("_{name}"),
                                                &ty,
                                                format!("the output {name} of element {}", id.0),
                                            ),
                                        },
                                        None => Stored::Missing,
                                    }
                                }
                                Callee::Unknown => Stored::Missing,
                            }
                        };
                        chart.stored.insert(key(id, name), stored);
                    }
                }
                CfcElementKind::Composer { type_name, .. } => {
                    let name = self.declare(
                        id,
                        "",
                        type_name.trim(),
                        format!("the structure built by element {}", id.0),
                    );
                    chart.stored.insert(
                        key(id, ""),
                        Stored::Path {
                            path: name.clone(),
                            boolean: false,
                        },
                    );
                    chart.structures.insert(id, name);
                }
                CfcElementKind::Selector { type_name, outputs } => {
                    let name = self.declare(
                        id,
                        "",
                        type_name.trim(),
                        format!("the structure element {} takes apart", id.0),
                    );
                    for pin in outputs {
                        let member = pin.name.trim();
                        chart.stored.insert(
                            key(id, member),
                            Stored::Path {
                                path: format!("{name}.{member}"),
                                boolean: false,
                            },
                        );
                    }
                    chart.structures.insert(id, name);
                }
                _ => {}
            }
        }
        self.type_results(chart, pending, types);
        self.declare_expression_stores(chart, types);
        for element in order {
            for pin in project_model::cfc_output_pins(&element.kind) {
                if let Some(Stored::Path { path, .. }) = chart.stored.get(&key(element.id, pin)) {
                    self.probe(element.id, pin_name(pin), ProbeKind::Value, path.clone());
                }
            }
            if let Some(structure) = chart.structures.get(&element.id)
                && let CfcElementKind::Composer { inputs, .. } = &element.kind
            {
                for pin in inputs {
                    let member = pin.name.trim();
                    let path = format!("{structure}.{member}");
                    self.probe(element.id, Some(member), ProbeKind::Value, path);
                }
            }
        }
    }

    /// Declares a hidden variable for each wired input whose expression is neither a
    /// variable nor a literal (`count < 3`), of the expression's type, so the value its wires
    /// carry can be shown online; an expression without a type of its own stays unstored.
    fn declare_expression_stores(&mut self, chart: &mut Chart<'_>, types: &ChartTypes<'_>) {
        let mut inputs: Vec<(ElementId, String)> = chart
            .elements
            .values()
            .filter_map(|element| match &element.kind {
                CfcElementKind::Input { expression }
                    if !is_simple(expression.trim())
                        && !expression.contains("__")
                        && chart.out_of.contains_key(&key(element.id, "")) =>
                {
                    Some((element.id, expression.trim().to_owned()))
                }
                _ => None,
            })
            .collect();
        if inputs.is_empty() {
            return;
        }
        inputs.sort_by_key(|(id, _)| *id);
        let texts: Vec<String> = inputs.iter().map(|(_, text)| text.clone()).collect();
        let found = (types.of_expressions)(&self.typed_hidden(), &texts);
        for ((id, _), ty) in inputs.into_iter().zip(found) {
            if let Some(ty) = ty {
                let name = self.declare(
                    id,
                    "",
                    &ty,
                    format!("the value of the input element {}", id.0),
                );
                chart
                    .expressions
                    .insert(id, (name, ty.eq_ignore_ascii_case("BOOL")));
            }
        }
    }

    /// Tells the type of every pending result, in rounds; a result that cannot be typed is
    /// reported at its box and stores nothing.
    fn type_results(
        &mut self,
        chart: &mut Chart<'_>,
        mut pending: Vec<Pending>,
        types: &ChartTypes<'_>,
    ) {
        while !pending.is_empty() {
            let untyped: HashSet<String> = pending
                .iter()
                .map(|result| result.name.to_lowercase())
                .collect();
            let mut ready = Vec::new();
            let mut unwired = Vec::new();
            for (index, result) in pending.iter().enumerate() {
                match self.typing_expression(chart, result, &untyped, false) {
                    Typing::Value(value) => ready.push((index, value.frag.text)),
                    Typing::Unwired => unwired.push(index),
                    Typing::Blocked => {}
                }
            }
            let mut done: Vec<(usize, Option<String>)> =
                unwired.into_iter().map(|index| (index, None)).collect();
            if !ready.is_empty() {
                let texts: Vec<String> = ready.iter().map(|(_, text)| text.clone()).collect();
                let found = (types.of_expressions)(&self.typed_hidden(), &texts);
                for ((index, _), ty) in ready.into_iter().zip(found) {
                    let ty = ty.or_else(|| self.consumer_type(chart, &pending[index], types));
                    done.push((index, ty));
                }
            } else if done.is_empty() {
                // Every result left is in a feedback loop: the first in the order is typed by
                // its inputs outside the loop or by what it feeds.
                let first = &pending[0];
                let ty = match self.typing_expression(chart, first, &untyped, true) {
                    Typing::Value(value) => {
                        (types.of_expressions)(&self.typed_hidden(), &[value.frag.text])
                            .pop()
                            .flatten()
                    }
                    Typing::Blocked | Typing::Unwired => None,
                };
                done.push((0, ty.or_else(|| self.consumer_type(chart, first, types))));
            }
            done.sort_by_key(|(index, _)| std::cmp::Reverse(*index));
            for (index, ty) in done {
                let result = pending.remove(index);
                let unwired = matches!(
                    self.typing_expression(chart, &result, &HashSet::new(), false),
                    Typing::Unwired
                );
                self.settle_result(chart, &result, ty, unwired);
            }
        }
    }

    /// Gives a result its type, or reports (unless an input is not wired, which is reported
    /// already) that it has none and drops its variable.
    fn settle_result(
        &mut self,
        chart: &mut Chart<'_>,
        result: &Pending,
        ty: Option<String>,
        unwired: bool,
    ) {
        let stored = chart.stored.get_mut(&key(result.element, &result.pin));
        match ty {
            Some(ty) => {
                if let Some(Stored::Path { boolean, .. }) = stored {
                    *boolean = ty.eq_ignore_ascii_case("BOOL");
                }
                if let Some(variable) = self.hidden.iter_mut().find(|v| v.name == result.name) {
                    variable.ty = ty;
                }
            }
            None => {
                if let Some(stored) = stored {
                    *stored = Stored::Missing;
                }
                self.hidden.retain(|variable| variable.name != result.name);
                self.descriptions.retain(|(name, _)| name != &result.name);
                if !unwired {
                    self.find(
                        result.element,
                        Some(&result.pin),
                        Code::InvalidCfcElement,
                        format!(
                            "the type of the output {} cannot be told from the box's inputs: check their types, give a constant a type (INT#1), or wire the output to a variable",
                            result.pin
                        ),
                    );
                }
            }
        }
    }

    /// The hidden variables whose type is known, for the checker's scope.
    fn typed_hidden(&self) -> Vec<project_model::Variable> {
        self.hidden
            .iter()
            .filter(|variable| !variable.ty.is_empty())
            .cloned()
            .collect()
    }

    /// The expression a result holds, over the user's names and typed hidden variables;
    /// with `substitute`, an operator's input that reads an untyped result is replaced by one
    /// that does not.
    fn typing_expression(
        &self,
        chart: &Chart<'_>,
        result: &Pending,
        untyped: &HashSet<String>,
        substitute: bool,
    ) -> Typing {
        let Some(CfcElementKind::Box(block)) = chart
            .elements
            .get(&result.element)
            .map(|element| &element.kind)
        else {
            return Typing::Unwired;
        };
        let mut inputs = Vec::new();
        for pin in block.inputs.iter().skip(usize::from(has_enable(block))) {
            inputs.push(self.typing_input(chart, result.element, pin, untyped));
        }
        if inputs.iter().any(|input| matches!(input, Typing::Unwired)) {
            return Typing::Unwired;
        }
        let operator = match (self.classify)(&block.type_name) {
            Callee::Function { operator } => operator.filter(|op| op.fits(inputs.len())),
            _ => None,
        };
        if substitute && operator.is_some() {
            let known = inputs.iter().find_map(|input| match input {
                Typing::Value(value) => Some(value.clone()),
                _ => None,
            });
            if let Some(known) = known {
                for input in &mut inputs {
                    if matches!(input, Typing::Blocked) {
                        *input = Typing::Value(known.clone());
                    }
                }
            }
        }
        let mut values = Vec::new();
        for input in inputs {
            match input {
                Typing::Value(value) => values.push(value),
                blocked => return blocked,
            }
        }
        let value = match operator {
            Some(op) => op.apply(values),
            None => {
                let pins = block.inputs.iter().skip(usize::from(has_enable(block)));
                let arguments: Vec<String> = pins
                    .zip(values)
                    .map(|(pin, value)| format!("{} := {}", pin.name.trim(), value.frag.text))
                    .collect();
                plain(format!(
                    "{}({})",
                    block.type_name.trim(),
                    arguments.join(", ")
                ))
            }
        };
        Typing::Value(value)
    }

    /// What the input `pin` of `element` contributes to a typing expression.
    fn typing_input(
        &self,
        chart: &Chart<'_>,
        element: ElementId,
        pin: &CfcPin,
        untyped: &HashSet<String>,
    ) -> Typing {
        let Some(wire) = chart.into.get(&key(element, &pin.name)) else {
            return Typing::Unwired;
        };
        let mut from = &wire.from;
        if let Some(CfcElementKind::ConnectionSink { .. }) =
            chart.elements.get(&from.element).map(|e| &e.kind)
        {
            match chart.sinks.get(&from.element) {
                Some(driver) => from = driver,
                None => return Typing::Unwired,
            }
        }
        let Some(source) = chart.elements.get(&from.element) else {
            return Typing::Unwired;
        };
        let mut value = match &source.kind {
            CfcElementKind::Input { expression } => plain(format!("({})", expression.trim())),
            kind => {
                let value = match chart.stored.get(&key(source.id, &from.pin)) {
                    Some(Stored::Path { path, .. }) if untyped.contains(&path.to_lowercase()) => {
                        return Typing::Blocked;
                    }
                    Some(Stored::Path { path, .. }) => plain(path.clone()),
                    Some(Stored::Constant(constant)) => plain((*constant).to_owned()),
                    Some(Stored::Missing) | None => return Typing::Unwired,
                };
                let negated = super::output_pin(kind, &from.pin).is_some_and(|pin| pin.negated);
                if negated { value.not() } else { value }
            }
        };
        if pin.edge != Edge::None {
            value = plain("TRUE".to_owned());
        }
        if pin.negated {
            value = value.not();
        }
        Typing::Value(value)
    }

    /// The type of what a result is wired to: an output's variable, a function block's
    /// input or a composer's member.
    fn consumer_type(
        &self,
        chart: &Chart<'_>,
        result: &Pending,
        types: &ChartTypes<'_>,
    ) -> Option<String> {
        let wires = chart.out_of.get(&key(result.element, &result.pin))?;
        let mut texts = Vec::new();
        for wire in wires {
            let Some(target) = chart.elements.get(&wire.to.element) else {
                continue;
            };
            match &target.kind {
                CfcElementKind::Output { expression, .. } => {
                    texts.push(expression.trim().to_owned())
                }
                CfcElementKind::Box(block) => {
                    let callee = (self.classify)(&block.type_name);
                    if let Some(instance) = instance_of(block, callee)
                        && matches!(callee, Callee::Block | Callee::Program)
                    {
                        texts.push(format!("{instance}.{}", wire.to.pin.trim()));
                    }
                }
                CfcElementKind::Composer { .. } => {
                    if let Some(structure) = chart.structures.get(&target.id) {
                        texts.push(format!("{structure}.{}", wire.to.pin.trim()));
                    }
                }
                _ => {}
            }
        }
        if texts.is_empty() {
            return None;
        }
        (types.of_expressions)(&self.typed_hidden(), &texts)
            .into_iter()
            .flatten()
            .next()
    }
}

/// A typing value from its text.
fn plain(text: String) -> Value {
    Value {
        frag: Fragment::plain(text),
        prec: prec::PRIMARY,
        kind: crate::lower::value::Kind::Expr,
        boolean: false,
        owner: None,
    }
}
