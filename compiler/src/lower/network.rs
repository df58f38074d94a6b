//! One body's networks lowered into Structured Text statements (ARCHITECTURE.md, "Bodies and
//! their origins"; the semantics are written down in `docs/graphical-semantics.md`).
//!
//! Power flow is computed once per element and scan, in data-flow order: a value is written
//! into the text where it is used when it is used once and nothing runs between where it is
//! computed and where it is used; it is stored in a hidden BOOL temporary when it is used
//! more than once (several outputs, the EN of a box whose ENO passes it on, branches holding
//! boxes) or when a box runs in between. So `a AND NOT b` driving one coil is exactly the ST
//! `c := a AND NOT b;`.

use std::collections::HashSet;

use project_model::{
    BlockCall, BlockInput, CoilKind, Edge, ElementId, FlowNode, Network, NetworkOutput, Operand,
    Parallel, VarSection, Variable,
};

use super::fragment::{Fragment, frag};
use super::value::{Kind, Value, binary, prec};
use super::{Callee, Finding, Probe, ProbeKind};
use crate::diagnostic::Code;

/// The lowering of one body: the text, the hidden variables and what was found on the way.
pub(crate) struct BodyLowering<'c> {
    /// The prefix of every hidden name of this body (`__` or `__Reset__`).
    prefix: String,
    /// What a box's type name calls.
    classify: &'c dyn Fn(&str) -> Callee,
    /// The labels of the body's networks, lower case.
    labels: HashSet<String>,
    /// The network being lowered.
    network: usize,
    /// The nesting of the statement being written, for indentation.
    depth: usize,
    /// The generated statements.
    pub out: Fragment,
    /// The hidden variables, declared in the POU.
    pub hidden: Vec<Variable>,
    /// Each hidden name with the words a message uses for it.
    pub descriptions: Vec<(String, String)>,
    /// What the network holds that cannot be compiled.
    pub findings: Vec<Finding>,
    /// Where each element's live value is read.
    pub probes: Vec<Probe>,
    /// The hidden names taken, lower case.
    taken: HashSet<String>,
}

impl<'c> BodyLowering<'c> {
    /// A lowering of a body whose hidden names start with `prefix`.
    pub fn new(prefix: String, classify: &'c dyn Fn(&str) -> Callee) -> Self {
        Self {
            prefix,
            classify,
            labels: HashSet::new(),
            network: 0,
            depth: 0,
            out: Fragment::default(),
            hidden: Vec::new(),
            descriptions: Vec::new(),
            findings: Vec::new(),
            probes: Vec::new(),
            taken: HashSet::new(),
        }
    }

    /// Lowers every network of a body, top to bottom.
    pub fn body(&mut self, networks: &[Network]) {
        for (index, network) in networks.iter().enumerate() {
            let label = network.label.trim();
            if label.is_empty() {
                continue;
            }
            if !project_model::is_valid_identifier(label) {
                self.find_at(
                    index,
                    None,
                    None,
                    Code::InvalidNetwork,
                    format!("the label '{label}' is not an identifier (letters, digits and '_')"),
                );
            } else if label.contains("__") {
                self.find_at(
                    index,
                    None,
                    None,
                    Code::ReservedName,
                    format!(
                        "the label '{label}' contains '__', which IEC 61131-3 does not allow in names and Rivet keeps for the names it generates"
                    ),
                );
            } else if !self.labels.insert(label.to_lowercase()) {
                self.find_at(
                    index,
                    None,
                    None,
                    Code::InvalidNetwork,
                    format!("the label '{label}' is given to two networks"),
                );
            }
        }
        for (index, network) in networks.iter().enumerate() {
            self.network = index;
            let label = network.label.trim();
            if project_model::is_valid_identifier(label) {
                let glue = frag!(label, ":").mark(index, None, None);
                self.emit(glue);
            }
            let power = self.chain(&network.rung, Some(Value::rail()));
            self.outputs(&network.outputs, power.unwrap_or_else(Value::rail));
        }
    }

    fn find(&mut self, element: ElementId, pin: Option<&str>, code: Code, message: String) {
        self.find_at(self.network, Some(element), pin, code, message);
    }

    fn find_at(
        &mut self,
        network: usize,
        element: Option<ElementId>,
        pin: Option<&str>,
        code: Code,
        message: String,
    ) {
        self.findings.push(Finding {
            network,
            element,
            pin: pin.map(str::to_owned),
            code,
            message,
        });
    }

    /// Writes one statement on a line of its own.
    fn emit(&mut self, statement: Fragment) {
        self.out.push_str(&"    ".repeat(self.depth));
        self.out.push(statement);
        self.out.push_str("\n");
    }

    fn probe(&mut self, element: ElementId, pin: Option<&str>, kind: ProbeKind, path: String) {
        self.probes.push(Probe {
            network: self.network,
            element,
            pin: pin.map(str::to_owned),
            kind,
            path,
        });
    }

    /// Declares a hidden variable named after `element` and `suffix`, described in messages
    /// as `description`, and returns its name.
    fn declare(
        &mut self,
        element: ElementId,
        suffix: &str,
        ty: &str,
        description: String,
    ) -> String {
        let base = format!("{}e{}{suffix}", self.prefix, element.0);
        let mut name = base.clone();
        let mut again = 1;
        while !self.taken.insert(name.to_lowercase()) {
            again += 1;
            name = format!("{base}_{again}");
        }
        self.hidden.push(Variable {
            name: name.clone(),
            section: VarSection::Var,
            ty: ty.to_owned(),
            ..Variable::default()
        });
        self.descriptions.push((name.clone(), description));
        name
    }

    /// Stores a BOOL expression in a hidden temporary so it can be read again, and records
    /// the temporary as the live value of the element that computed it.
    fn settle(&mut self, value: Value, owner: ElementId, suffix: &str, what: &str) -> Value {
        if value.kind != Kind::Expr || !value.boolean {
            return value;
        }
        let name = self.declare(
            owner,
            suffix,
            "BOOL",
            format!("the {what} element {}", owner.0),
        );
        let statement =
            frag!(&name, " := ", value.frag.clone(), ";").mark(self.network, Some(owner), None);
        self.emit(statement);
        // The power leaving the element, and the enable of a box, are what the studio shows;
        // the power into a group or a branch's result it derives from its neighbours.
        match suffix {
            "" => self.probe(owner, None, ProbeKind::Power, name.clone()),
            "_EN" => self.probe(owner, Some("EN"), ProbeKind::Power, name.clone()),
            _ => {}
        }
        Value::stable(Fragment::plain(name), true, Some(owner))
    }

    /// The chain's value: `incoming` (the rail, the power, or nothing for an input's own
    /// chain) passed through each element.
    fn chain(&mut self, nodes: &[FlowNode], incoming: Option<Value>) -> Option<Value> {
        let mut current = incoming;
        for node in nodes {
            current = match node {
                FlowNode::Operand(operand) => Some(self.operand(operand, current)),
                FlowNode::Parallel(parallel) => self.parallel(parallel, current),
                FlowNode::Block(block) => self.block(block, current),
            };
        }
        current
    }

    /// A contact: the incoming power ANDed with the operand's value (negated, or through an
    /// edge trigger); at the start of an input's chain, the operand's value alone.
    fn operand(&mut self, operand: &Operand, incoming: Option<Value>) -> Value {
        let read = self.user_value(operand.id, None, &operand.text, "the contact or input");
        let boolean = incoming.is_some() || operand.edge != Edge::None || operand.negated;
        let mut value = Value {
            boolean,
            owner: Some(operand.id),
            ..read
        };
        if operand.edge != Edge::None {
            value = self.trigger(operand.id, None, operand.edge, value);
        }
        if operand.negated {
            value = value.not();
        }
        value.frag = value.frag.mark(self.network, Some(operand.id), None);
        match incoming {
            // The AND belongs to the contact that does it, so a finding about it (a contact
            // that is not a BOOL) is shown there.
            Some(power) if !power.is_rail() => {
                let mut value = power.and(value);
                value.frag = value.frag.mark(self.network, Some(operand.id), None);
                value.owner = Some(operand.id);
                value
            }
            Some(_) | None => value,
        }
    }

    /// What the user typed into an element, as an operand of any operator.
    fn user_value(
        &mut self,
        element: ElementId,
        pin: Option<&str>,
        text: &str,
        what: &str,
    ) -> Value {
        let text = text.trim();
        if text.is_empty() {
            self.find(
                element,
                pin,
                Code::InvalidNetwork,
                format!("{what} is empty"),
            );
            return Value::stable(
                Fragment::plain("FALSE").mark(self.network, Some(element), pin),
                true,
                Some(element),
            );
        }
        self.reserved(element, pin, text);
        let simple = is_simple(text);
        if is_path(text) {
            self.probe(element, pin, ProbeKind::Value, text.to_owned());
        }
        let inner = Fragment::plain(text).mark_user(self.network, element, pin);
        let frag = if simple {
            inner
        } else {
            frag!("(", inner, ")")
        };
        Value {
            frag,
            prec: prec::PRIMARY,
            kind: Kind::Expr,
            boolean: false,
            owner: Some(element),
        }
    }

    /// Refuses a generated name (with `__`) in what the user typed.
    fn reserved(&mut self, element: ElementId, pin: Option<&str>, text: &str) {
        if text.contains("__") {
            self.find(
                element,
                pin,
                Code::ReservedName,
                format!(
                    "'{text}' contains '__', which IEC 61131-3 does not allow in names and Rivet keeps for the names it generates"
                ),
            );
        }
    }

    /// Runs a hidden R_TRIG or F_TRIG on `clock` every scan and gives its output.
    fn trigger(
        &mut self,
        element: ElementId,
        pin: Option<&str>,
        edge: Edge,
        clock: Value,
    ) -> Value {
        let (ty, words) = match edge {
            Edge::Falling => ("F_TRIG", "falling edge detection"),
            _ => ("R_TRIG", "rising edge detection"),
        };
        let suffix = match pin {
            Some(pin) => format!("_{pin}_trig"),
            None => "_trig".to_owned(),
        };
        let name = self.declare(
            element,
            &suffix,
            ty,
            format!("the {words} of element {}", element.0),
        );
        let statement =
            frag!(&name, "(CLK := ", clock.frag, ");").mark(self.network, Some(element), pin);
        self.emit(statement);
        let output = format!("{name}.Q");
        self.probe(element, pin, ProbeKind::Edge, output.clone());
        Value::stable(Fragment::plain(output), true, Some(element))
    }

    /// Branches fed by the same power, ORed.
    fn parallel(&mut self, parallel: &Parallel, incoming: Option<Value>) -> Option<Value> {
        if parallel.branches.is_empty() {
            return incoming;
        }
        let runs_boxes = parallel
            .branches
            .iter()
            .any(|branch| chain_runs_boxes(&branch.rung));
        let mut results: Vec<Value> = Vec::new();
        match incoming {
            // Contacts only: `in AND (b1 OR b2)`, what a user writes, computing `in` once.
            Some(power) if !runs_boxes => {
                for branch in &parallel.branches {
                    results.push(
                        self.chain(&branch.rung, Some(Value::rail()))
                            .unwrap_or_else(Value::rail),
                    );
                }
                let ored = self.or_all(parallel.id, results);
                let mut value = power.and(ored);
                value.owner = Some(parallel.id);
                Some(value)
            }
            Some(power) => {
                let power = self.settle(power, parallel.id, "_in", "power flow into");
                for branch in &parallel.branches {
                    if chain_runs_boxes(&branch.rung) {
                        results = results
                            .into_iter()
                            .enumerate()
                            .map(|(at, value)| {
                                self.settle(
                                    value,
                                    parallel.id,
                                    &format!("_b{at}"),
                                    "power flow of a branch of",
                                )
                            })
                            .collect();
                    }
                    results.push(
                        self.chain(&branch.rung, Some(power.clone()))
                            .unwrap_or_else(|| power.clone()),
                    );
                }
                Some(self.or_all(parallel.id, results))
            }
            None => {
                for branch in &parallel.branches {
                    if let Some(value) = self.chain(&branch.rung, None) {
                        results.push(value);
                    }
                }
                if results.is_empty() {
                    return None;
                }
                Some(self.or_all(parallel.id, results))
            }
        }
    }

    fn or_all(&mut self, id: ElementId, values: Vec<Value>) -> Value {
        let mut values = values.into_iter();
        let Some(first) = values.next() else {
            return Value::rail();
        };
        let mut ored = values.fold(first, Value::or);
        if !ored.is_rail() {
            ored.frag = ored.frag.mark(self.network, Some(id), None);
            ored.owner = Some(id);
        }
        ored
    }

    /// A box: its inputs, the call (inside `IF EN` when it has EN), its outputs' assignments
    /// right after the call, and the value it passes on (ENO, else its first output).
    fn block(&mut self, block: &BlockCall, incoming: Option<Value>) -> Option<Value> {
        let callee = (self.classify)(&block.type_name);
        let has_en = block.has_en_eno();
        // The incoming power drives the first input (EN when there is one) unless a chain of
        // its own drives it.
        let mut power = None;
        if let Some(incoming) = incoming {
            match block.inputs.first() {
                Some(first) if first.source.is_empty() => power = Some(incoming),
                _ if incoming.is_rail() => {}
                _ => self.find(
                    block.id,
                    block.inputs.first().map(|input| input.pin.as_str()),
                    Code::InvalidNetwork,
                    format!(
                        "the box '{}' gets the power flow, but its first input is driven by its own chain",
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
        if enable.is_none() && assign.is_none() {
            return Some(expression);
        }
        let mut assigned = None;
        let eno = self.enabled(block, enable, |this| {
            let statement = match assign {
                Some(output) => {
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
                None => frag!(expression.frag, ";"),
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

    /// What the power at the end of a rung drives; stored first when several outputs read it.
    fn outputs(&mut self, outputs: &[NetworkOutput], power: Value) {
        let power = if outputs.len() > 1 {
            let owner = power
                .owner
                .or_else(|| outputs.first().map(NetworkOutput::id));
            match owner {
                Some(owner) => self.settle(power, owner, "", "power flow after"),
                None => power,
            }
        } else {
            power
        };
        for output in outputs {
            match output {
                NetworkOutput::Coil(coil) => {
                    let target =
                        self.user_value(coil.id, None, &coil.variable, "the coil's variable");
                    let statement = match coil.kind {
                        CoilKind::Normal => frag!(target.frag, " := ", power.frag.clone(), ";"),
                        CoilKind::Negated => frag!(target.frag, " := ", power.not().frag, ";"),
                        CoilKind::Set | CoilKind::Reset => {
                            let constant = if coil.kind == CoilKind::Set {
                                "TRUE"
                            } else {
                                "FALSE"
                            };
                            if power.is_rail() {
                                frag!(target.frag, format!(" := {constant};"))
                            } else {
                                frag!(
                                    "IF ",
                                    power.frag.clone(),
                                    " THEN ",
                                    target.frag,
                                    format!(" := {constant}; END_IF;")
                                )
                            }
                        }
                        CoilKind::Rising | CoilKind::Falling => {
                            let edge = if coil.kind == CoilKind::Rising {
                                Edge::Rising
                            } else {
                                Edge::Falling
                            };
                            let pulse = self.trigger(coil.id, None, edge, power.clone());
                            frag!(target.frag, " := ", pulse.frag, ";")
                        }
                    };
                    self.emit(statement.mark(self.network, Some(coil.id), None));
                }
                NetworkOutput::Jump { id, label } => {
                    let label = label.trim();
                    if !self.labels.contains(&label.to_lowercase()) {
                        let message = if label.is_empty() {
                            "the jump names no label".to_owned()
                        } else {
                            format!(
                                "the jump goes to '{label}', but no network of this body has that label"
                            )
                        };
                        self.find(*id, None, Code::InvalidNetwork, message);
                        continue;
                    }
                    let jump = Fragment::plain(format!("JMP {label};"));
                    self.conditional(*id, &power, jump);
                }
                NetworkOutput::Return { id } => {
                    self.conditional(*id, &power, Fragment::plain("RETURN;"));
                }
                NetworkOutput::Branch { id, rung, outputs } => {
                    let mut end = self
                        .chain(rung, Some(power.clone()))
                        .unwrap_or_else(|| power.clone());
                    if end.owner.is_none() {
                        end.owner = Some(*id);
                    }
                    self.outputs(outputs, end);
                }
            }
        }
    }

    /// `IF power THEN statement END_IF;`, or the statement alone when the rail drives it.
    fn conditional(&mut self, id: ElementId, power: &Value, statement: Fragment) {
        let whole = if power.is_rail() {
            statement
        } else {
            frag!("IF ", power.frag.clone(), " THEN ", statement, " END_IF;")
        };
        self.emit(whole.mark(self.network, Some(id), None));
    }
}

/// Whether a chain holds a box, whose call may change what the network reads.
pub(crate) fn chain_runs_boxes(nodes: &[FlowNode]) -> bool {
    nodes.iter().any(|node| match node {
        FlowNode::Operand(_) => false,
        FlowNode::Parallel(parallel) => parallel
            .branches
            .iter()
            .any(|branch| chain_runs_boxes(&branch.rung)),
        FlowNode::Block(_) => true,
    })
}

/// A name, path or literal that needs no parentheses as an operand.
fn is_simple(text: &str) -> bool {
    !text.is_empty()
        && !text.starts_with(['-', '+'])
        && text
            .chars()
            .all(|c| c.is_alphanumeric() || matches!(c, '_' | '.' | '#' | '%' | '[' | ']' | '^'))
}

/// A variable's path (`a`, `fb.q`, `arr[1].x`), whose value can be read online by its path.
fn is_path(text: &str) -> bool {
    text.starts_with(|c: char| c.is_alphabetic() || c == '_')
        && !text.contains('#')
        && !matches!(text.to_ascii_uppercase().as_str(), "TRUE" | "FALSE")
        && is_simple(text)
}

/// An operator box written as the ST operator a user would write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Operator {
    /// A left-associative infix operator, for two or more inputs (`+`, `AND`).
    Infix(&'static str, u8, bool),
    /// A comparison of exactly two inputs (`>`).
    Comparison(&'static str, u8),
    /// `NOT`, of one input.
    Not,
    /// `MOVE`: the input itself.
    Move,
}

impl Operator {
    /// The operator box named `name`, if it is one.
    pub fn of(name: &str) -> Option<Self> {
        use prec::*;
        Some(match name.trim().to_ascii_uppercase().as_str() {
            "ADD" => Self::Infix("+", ADDITIVE, true),
            "SUB" => Self::Infix("-", ADDITIVE, false),
            "MUL" => Self::Infix("*", MULTIPLICATIVE, true),
            "DIV" => Self::Infix("/", MULTIPLICATIVE, false),
            "MOD" => Self::Infix("MOD", MULTIPLICATIVE, false),
            "AND" => Self::Infix("AND", AND, true),
            "OR" => Self::Infix("OR", OR, true),
            "XOR" => Self::Infix("XOR", XOR, true),
            "GT" => Self::Comparison(">", COMPARISON),
            "GE" => Self::Comparison(">=", COMPARISON),
            "LT" => Self::Comparison("<", COMPARISON),
            "LE" => Self::Comparison("<=", COMPARISON),
            "EQ" => Self::Comparison("=", EQUALITY),
            "NE" => Self::Comparison("<>", EQUALITY),
            "NOT" => Self::Not,
            "MOVE" => Self::Move,
            _ => return None,
        })
    }

    /// Whether the operator form takes `inputs` inputs; otherwise the box is called as a
    /// function.
    fn fits(self, inputs: usize) -> bool {
        match self {
            Self::Infix(_, _, extensible) => inputs == 2 || (extensible && inputs > 2),
            Self::Comparison(..) => inputs == 2,
            Self::Not | Self::Move => inputs == 1,
        }
    }

    /// The expression over `values` (as many as [`Operator::fits`] allows).
    fn apply(self, values: Vec<Value>) -> Value {
        let mut values = values.into_iter();
        let Some(first) = values.next() else {
            return Value::rail();
        };
        match self {
            Self::Infix(op, strength, _) | Self::Comparison(op, strength) => {
                let logical = matches!(op, "AND" | "OR" | "XOR");
                let mut value = values.fold(first, |lhs, rhs| binary(lhs, op, strength, rhs));
                // Arithmetic gives a number; a logical operator a BOOL only of BOOLs.
                value.boolean = matches!(self, Self::Comparison(..)) || logical && value.boolean;
                value
            }
            Self::Not => first.not(),
            Self::Move => first,
        }
    }
}
