//! Boxes of a CFC chart: function block instances and programs called with their wired
//! inputs, functions and operators whose results are stored, all inside `IF EN` when EN is
//! wired.

use project_model::{CfcBox, CfcPin, ElementId};

use super::{Chart, Stored, key};
use crate::diagnostic::Code;
use crate::lower::fragment::{Fragment, frag};
use crate::lower::network::BodyLowering;
use crate::lower::operator::Operator;
use crate::lower::value::{Kind, Value, prec};
use crate::lower::{Callee, ProbeKind};

/// Whether `pin` is the enable input or output.
pub(super) fn is_enable(pin: &CfcPin) -> bool {
    let name = pin.name.trim();
    name.eq_ignore_ascii_case(project_model::EN_PIN)
        || name.eq_ignore_ascii_case(project_model::ENO_PIN)
}

/// The index of the output that holds a function's result: its first output other than ENO.
pub(super) fn result_index(block: &CfcBox) -> Option<usize> {
    block.outputs.iter().position(|pin| !is_enable(pin))
}

/// Whether the box's first input is EN.
pub(super) fn has_enable(block: &CfcBox) -> bool {
    block
        .inputs
        .first()
        .is_some_and(|pin| pin.name.trim().eq_ignore_ascii_case(project_model::EN_PIN))
}

/// The instance a function block or program box is called through.
pub(super) fn instance_of(block: &CfcBox, callee: Callee) -> Option<String> {
    match block.instance.trim() {
        "" if callee == Callee::Program => Some(block.type_name.trim().to_owned()),
        "" => None,
        instance => Some(instance.to_owned()),
    }
}

impl BodyLowering<'_> {
    /// A box: its inputs read, then its call or its result's assignment, inside `IF EN`
    /// when its EN is wired.
    pub(super) fn cfc_box(&mut self, chart: &Chart<'_>, id: ElementId, block: &CfcBox) {
        let callee = (self.classify)(&block.type_name);
        let skip = usize::from(has_enable(block));
        let enable = match (block.inputs.first(), chart.enables.get(&id)) {
            (Some(pin), Some(name)) if skip == 1 => self
                .pin_value(chart, id, pin)
                .map(|value| (value, name.clone())),
            _ => None,
        };
        let mut arguments: Vec<(&CfcPin, Option<Value>)> = Vec::new();
        for pin in block.inputs.iter().skip(skip) {
            let value = self.pin_value(chart, id, pin);
            arguments.push((pin, value));
        }
        let statements = match callee {
            Callee::Block | Callee::Program => self.cfc_instance_call(id, block, callee, arguments),
            Callee::Function { operator } => {
                self.cfc_function_result(chart, id, block, arguments, operator)
            }
            Callee::Unknown => {
                self.find(
                    id,
                    None,
                    Code::UnknownName,
                    format!(
                        "'{}' is not a function, operator, function block or program",
                        block.type_name
                    ),
                );
                Vec::new()
            }
        };
        match enable {
            Some((value, name)) => {
                let store = frag!(name.as_str(), " := ", value.frag, ";");
                self.emit(store.mark(self.network, Some(id), Some(project_model::EN_PIN)));
                self.probe(
                    id,
                    Some(project_model::EN_PIN),
                    ProbeKind::Value,
                    name.clone(),
                );
                if statements.is_empty() {
                    return;
                }
                self.emit(frag!("IF ", name.as_str(), " THEN").mark(self.network, Some(id), None));
                self.depth += 1;
                for statement in statements {
                    self.emit(statement);
                }
                self.depth -= 1;
                self.emit(Fragment::plain("END_IF;").mark(self.network, Some(id), None));
            }
            None => {
                for statement in statements {
                    self.emit(statement);
                }
            }
        }
    }

    /// Reports each input of a function or operator box that is not wired, before anything
    /// decides whether the box is written (a result that feeds back into the box cannot be
    /// stored when an input is missing, which would hide the reason).
    pub(super) fn unwired_function_inputs(
        &mut self,
        chart: &Chart<'_>,
        id: ElementId,
        block: &CfcBox,
    ) {
        if !matches!((self.classify)(&block.type_name), Callee::Function { .. }) {
            return;
        }
        for pin in block.inputs.iter().skip(usize::from(has_enable(block))) {
            let name = pin.name.trim();
            if !chart.into.contains_key(&key(id, name)) {
                self.find(
                    id,
                    Some(name),
                    Code::InvalidCfcElement,
                    format!(
                        "the input {name} of '{}' is not connected; a function needs every input",
                        block.type_name
                    ),
                );
            }
        }
    }

    /// `instance(IN := …);` with the wired inputs; an input not wired keeps its value.
    fn cfc_instance_call(
        &mut self,
        id: ElementId,
        block: &CfcBox,
        callee: Callee,
        arguments: Vec<(&CfcPin, Option<Value>)>,
    ) -> Vec<Fragment> {
        let Some(instance) = instance_of(block, callee) else {
            self.find(
                id,
                None,
                Code::InvalidCfcElement,
                format!(
                    "the function block box '{}' has no instance",
                    block.type_name
                ),
            );
            return Vec::new();
        };
        let mut call = frag!(
            Fragment::plain(instance.as_str()).mark_user(self.network, id, None),
            "("
        );
        let mut first = true;
        for (pin, value) in arguments {
            let Some(value) = value else { continue };
            if !first {
                call.push_str(", ");
            }
            first = false;
            let name = pin.name.trim();
            call.push(frag!(format!("{name} := "), value.frag).mark(
                self.network,
                Some(id),
                Some(name),
            ));
        }
        call.push_str(");");
        vec![call.mark(self.network, Some(id), None)]
    }

    /// A function or operator: its result stored in its hidden variable (and its other
    /// outputs in theirs); every input must be wired.
    fn cfc_function_result(
        &mut self,
        chart: &Chart<'_>,
        id: ElementId,
        block: &CfcBox,
        arguments: Vec<(&CfcPin, Option<Value>)>,
        operator: Option<Operator>,
    ) -> Vec<Fragment> {
        // An input that is not wired was reported by `unwired_function_inputs`.
        let mut values = Vec::new();
        for (pin, value) in arguments {
            if let Some(value) = value {
                values.push((value, pin.name.trim()));
            }
        }
        if values.len() + usize::from(has_enable(block)) != block.inputs.len() {
            return Vec::new();
        }
        let result = result_index(block);
        let expression = match operator.filter(|op| op.fits(values.len())) {
            Some(op) => op.apply(values.into_iter().map(|(value, _)| value).collect()),
            None => {
                let mut call = frag!(block.type_name.trim(), "(");
                let mut first = true;
                for (value, pin) in values {
                    if !first {
                        call.push_str(", ");
                    }
                    first = false;
                    call.push(frag!(format!("{pin} := "), value.frag));
                }
                for (index, pin) in block.outputs.iter().enumerate() {
                    if Some(index) == result || is_enable(pin) {
                        continue;
                    }
                    let name = pin.name.trim();
                    if let Some(Stored::Path { path, .. }) = chart.stored.get(&key(id, name)) {
                        if !first {
                            call.push_str(", ");
                        }
                        first = false;
                        call.push(frag!(format!("{name} => {path}")).mark(
                            self.network,
                            Some(id),
                            Some(name),
                        ));
                    }
                }
                call.push_str(")");
                Value {
                    frag: call,
                    prec: prec::PRIMARY,
                    kind: Kind::Expr,
                    boolean: false,
                    owner: Some(id),
                }
            }
        };
        let expression = expression.frag.mark(self.network, Some(id), None);
        let stored = result.and_then(|index| {
            let pin = block.outputs[index].name.trim();
            chart.stored.get(&key(id, pin)).map(|stored| (pin, stored))
        });
        let statement = match stored {
            Some((pin, Stored::Path { path, .. })) => frag!(
                Fragment::plain(path.as_str()).mark(self.network, Some(id), Some(pin)),
                " := ",
                expression,
                ";"
            ),
            // A result whose type cannot be told was reported; nothing reads it.
            Some(_) => return Vec::new(),
            // A call without a result pin still runs for its other outputs.
            None if operator.is_none() => frag!(expression, ";"),
            None => return Vec::new(),
        };
        vec![statement.mark(self.network, Some(id), None)]
    }
}
