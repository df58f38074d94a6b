//! Boxes in a network: functions, operators, function block instances and programs, with
//! EN/ENO, negated and edge pins, and their outputs' assignments right after the call.

use project_model::{BlockCall, BlockInput, Edge};

use super::fragment::{Fragment, frag};
use super::network::{BodyLowering, chain_runs_boxes};
use super::operator::Operator;
use super::value::{Kind, Value, prec};
use super::{Callee, ProbeKind};
use crate::diagnostic::Code;

impl BodyLowering<'_> {
    /// A box: its inputs, the call (inside `IF EN` when it has EN), its outputs' assignments
    /// right after the call, and the value it passes on (ENO, else its first output).
    pub(super) fn block(&mut self, block: &BlockCall, incoming: Option<Value>) -> Option<Value> {
        let callee = (self.classify)(&block.type_name);
        let has_en = block.has_en_eno();
        // The incoming power drives the first input (EN when there is one) unless a chain of
        // its own drives it.
        let mut power = None;
        if let Some(incoming) = incoming {
            match block.inputs.first() {
                Some(first) if first.source.is_empty() => power = Some(incoming),
                _ if incoming.is_rail() => {}
                Some(first) => self.find(
                    block.id,
                    Some(&first.pin),
                    Code::InvalidNetwork,
                    format!(
                        "the box '{}' gets the power flow, but its first input is driven by its own chain",
                        block.type_name
                    ),
                ),
                None => self.find(
                    block.id,
                    None,
                    Code::InvalidNetwork,
                    format!(
                        "the box '{}' gets the power flow, but has no input to take it",
                        block.type_name
                    ),
                ),
            }
        }
        self.reserved(block.id, None, &block.instance);
        // Inputs fed by boxes run first, so the power held for the first input is stored
        // when a box runs before it is used.
        let mut arguments: Vec<Option<Value>> = vec![None; block.inputs.len()];
        for pass in [true, false] {
            for (index, input) in block.inputs.iter().enumerate() {
                if input.source.is_empty() || chain_runs_boxes(&input.source) != pass {
                    continue;
                }
                if pass && let Some(held) = power.take() {
                    power = Some(self.settle(held, block.id, "_in", "power flow into"));
                }
                arguments[index] = self.chain(&input.source, None);
            }
        }
        if let (Some(first), Some(power)) = (arguments.first_mut(), power)
            && first.is_none()
        {
            *first = Some(power);
        }
        let mut arguments: Vec<(Option<Value>, &BlockInput)> = arguments
            .into_iter()
            .zip(&block.inputs)
            .map(|(value, input)| {
                (
                    value.map(|value| self.pin_input(block, input, value)),
                    input,
                )
            })
            .collect();
        let enable = if has_en {
            let (value, _) = arguments.remove(0);
            Some(value.unwrap_or_else(Value::rail))
        } else {
            None
        };
        match callee {
            Callee::Block | Callee::Program => self.instance_call(block, enable, arguments),
            Callee::Function { operator } => self.function_call(block, enable, arguments, operator),
            Callee::Unknown => {
                self.find(
                    block.id,
                    None,
                    Code::UnknownName,
                    format!(
                        "'{}' is not a function, operator, function block or program",
                        block.type_name
                    ),
                );
                None
            }
        }
    }

    /// A value driving an input pin, negated or through an edge trigger as the pin says.
    fn pin_input(&mut self, block: &BlockCall, input: &BlockInput, value: Value) -> Value {
        let mut value = value;
        if input.edge != Edge::None {
            value = self.trigger(block.id, Some(&input.pin), input.edge, value);
        }
        if input.negated {
            value = value.not();
        }
        value.frag = value
            .frag
            .mark(self.network, Some(block.id), Some(&input.pin));
        value
    }

    /// The value of output `index` of a called instance, negated as the pin says.
    fn instance_output(&mut self, block: &BlockCall, instance: &str, index: usize) -> Value {
        let output = &block.outputs[index];
        let path = format!("{instance}.{}", output.pin);
        self.probe(block.id, Some(&output.pin), ProbeKind::Value, path.clone());
        let value = Value::stable(
            Fragment::plain(path).mark(self.network, Some(block.id), Some(&output.pin)),
            true,
            Some(block.id),
        );
        if output.negated { value.not() } else { value }
    }

    /// Runs `body` as the box's statements: directly, or inside `IF enable THEN` when the box
    /// has EN; gives the ENO (the enable, stored when it is read again) or `None` without EN.
    fn enabled(
        &mut self,
        block: &BlockCall,
        enable: Option<Value>,
        body: impl FnOnce(&mut Self),
    ) -> Option<Value> {
        let Some(enable) = enable else {
            body(self);
            return None;
        };
        if enable.is_rail() {
            body(self);
            return Some(enable);
        }
        let enable = self.settle(enable, block.id, "_EN", "EN input of");
        let open =
            frag!("IF ", enable.frag.clone(), " THEN").mark(self.network, Some(block.id), None);
        self.emit(open);
        self.depth += 1;
        body(self);
        self.depth -= 1;
        self.emit(Fragment::plain("END_IF;").mark(self.network, Some(block.id), None));
        Some(enable)
    }

    /// The ENO output's assignment, outside the box's `IF`, so it is FALSE when skipped.
    fn eno_assignment(&mut self, block: &BlockCall, eno: &Value) {
        for output in &block.outputs {
            if output.pin.eq_ignore_ascii_case(project_model::ENO_PIN)
                && !output.assign.trim().is_empty()
            {
                let value = if output.negated {
                    eno.not()
                } else {
                    eno.clone()
                };
                let target = self.user_value(
                    block.id,
                    Some(&output.pin),
                    &output.assign,
                    "the assigned variable",
                );
                let statement = frag!(target.frag, " := ", value.frag, ";").mark(
                    self.network,
                    Some(block.id),
                    Some(&output.pin),
                );
                self.emit(statement);
            }
        }
    }

    /// A function block instance or program: `inst(IN := …);` then each assigned output.
    fn instance_call(
        &mut self,
        block: &BlockCall,
        enable: Option<Value>,
        arguments: Vec<(Option<Value>, &BlockInput)>,
    ) -> Option<Value> {
        let instance = match block.instance.trim() {
            // A program is called by its own name.
            "" if (self.classify)(&block.type_name) == Callee::Program => {
                block.type_name.trim().to_owned()
            }
            "" => {
                self.find(
                    block.id,
                    None,
                    Code::InvalidNetwork,
                    format!(
                        "the function block box '{}' has no instance",
                        block.type_name
                    ),
                );
                return None;
            }
            instance => instance.to_owned(),
        };
        let mut call = frag!(
            Fragment::plain(instance.as_str()).mark_user(self.network, block.id, None),
            "("
        );
        let mut first = true;
        for (value, input) in arguments {
            let Some(value) = value else { continue };
            // An instance keeps its inputs, so each connected pin's value is read there.
            let path = format!("{instance}.{}", input.pin);
            self.probe(block.id, Some(&input.pin), ProbeKind::Value, path);
            if !first {
                call.push_str(", ");
            }
            first = false;
            call.push(frag!(format!("{} := ", input.pin), value.frag).mark(
                self.network,
                Some(block.id),
                Some(&input.pin),
            ));
        }
        call.push_str(");");
        let call = call.mark(self.network, Some(block.id), None);
        let eno = self.enabled(block, enable, |this| {
            this.emit(call);
            for (index, output) in block.outputs.iter().enumerate() {
                if output.pin.eq_ignore_ascii_case(project_model::ENO_PIN)
                    || output.assign.trim().is_empty()
                {
                    continue;
                }
                let value = this.instance_output(block, &instance, index);
                let target = this.user_value(
                    block.id,
                    Some(&output.pin),
                    &output.assign,
                    "the assigned variable",
                );
                let statement = frag!(target.frag, " := ", value.frag, ";").mark(
                    this.network,
                    Some(block.id),
                    Some(&output.pin),
                );
                this.emit(statement);
            }
        });
        if let Some(eno) = eno {
            self.eno_assignment(block, &eno);
            return Some(eno);
        }
        let index = block.chain_output()?;
        Some(self.instance_output(block, &instance, index))
    }

    /// A function or operator: inline where its value is used, or assigned to its output's
    /// variable (then read from there), inside `IF EN` when it has EN.
    fn function_call(
        &mut self,
        block: &BlockCall,
        enable: Option<Value>,
        arguments: Vec<(Option<Value>, &BlockInput)>,
        operator: Option<Operator>,
    ) -> Option<Value> {
        let mut values = Vec::new();
        for (value, input) in &arguments {
            match value {
                Some(value) => values.push((value.clone(), input.pin.as_str())),
                None => self.find(
                    block.id,
                    Some(&input.pin),
                    Code::InvalidNetwork,
                    format!(
                        "the input {} of '{}' is not connected",
                        input.pin, block.type_name
                    ),
                ),
            }
        }
        let result_index = block
            .outputs
            .iter()
            .position(|output| !output.pin.eq_ignore_ascii_case(project_model::ENO_PIN));
        let mut expression = match operator.filter(|op| op.fits(values.len())) {
            Some(op) => op.apply(values.into_iter().map(|(value, _)| value).collect()),
            None => {
                let mut call = frag!(block.type_name.trim(), "(");
                for (index, (value, pin)) in values.into_iter().enumerate() {
                    if index > 0 {
                        call.push_str(", ");
                    }
                    call.push(frag!(format!("{pin} := "), value.frag));
                }
                for (index, output) in block.outputs.iter().enumerate() {
                    if Some(index) == result_index
                        || output.pin.eq_ignore_ascii_case(project_model::ENO_PIN)
                        || output.assign.trim().is_empty()
                    {
                        continue;
                    }
                    let target = self.user_value(
                        block.id,
                        Some(&output.pin),
                        &output.assign,
                        "the assigned variable",
                    );
                    if !call.text.ends_with('(') {
                        call.push_str(", ");
                    }
                    call.push(frag!(format!("{} => ", output.pin), target.frag).mark(
                        self.network,
                        Some(block.id),
                        Some(&output.pin),
                    ));
                }
                call.push_str(")");
                Value {
                    frag: call,
                    prec: prec::PRIMARY,
                    kind: Kind::Expr,
                    boolean: true,
                    owner: Some(block.id),
                }
            }
        };
        if let Some(index) = result_index
            && block.outputs[index].negated
        {
            expression = expression.not();
        }
        expression.owner = Some(block.id);
        expression.frag = expression.frag.mark(self.network, Some(block.id), None);
        let assign = result_index
            .map(|index| &block.outputs[index])
            .filter(|output| !output.assign.trim().is_empty());
        // A result no variable of the user's holds is stored in a hidden one, so its pin
        // shows a live value; it costs the one store and load of the result.
        let hidden = match (assign, result_index) {
            (None, Some(index)) => self
                .result_variable(block, index, &expression)
                .map(|(name, boolean)| (name, block.outputs[index].pin.trim().to_owned(), boolean)),
            _ => None,
        };
        if enable.is_none() && assign.is_none() && hidden.is_none() {
            return Some(expression);
        }
        let mut assigned = None;
        let eno = self.enabled(block, enable, |this| {
            let statement = match (assign, hidden) {
                (None, Some((name, pin, boolean))) => {
                    assigned = Some(this.result_value(block.id, &pin, &name, boolean));
                    frag!(
                        Fragment::plain(name.as_str()).mark(
                            this.network,
                            Some(block.id),
                            Some(&pin)
                        ),
                        " := ",
                        expression.frag,
                        ";"
                    )
                }
                (Some(output), _) => {
                    let target = this.user_value(
                        block.id,
                        Some(&output.pin),
                        &output.assign,
                        "the assigned variable",
                    );
                    // The variable is the user's: a later coil may write it, so it is stored
                    // like any expression when it is read more than once.
                    assigned = Some(Value {
                        kind: Kind::Expr,
                        boolean: true,
                        ..Value::stable(target.frag.clone(), true, Some(block.id))
                    });
                    frag!(target.frag, " := ", expression.frag, ";")
                }
                (None, None) => frag!(expression.frag, ";"),
            };
            this.emit(statement.mark(this.network, Some(block.id), None));
        });
        match eno {
            Some(eno) => {
                self.eno_assignment(block, &eno);
                Some(eno)
            }
            None => assigned,
        }
    }
}
