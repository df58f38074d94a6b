//! One body's networks lowered into Structured Text statements (ARCHITECTURE.md, "Bodies and
//! their origins"; the semantics are written down in `docs/graphical-semantics.md`).
//!
//! Power flow is computed once per element and scan, in data-flow order: a value is written
//! into the text where it is used when it is used once and nothing runs between where it is
//! computed and where it is used; it is stored in a hidden BOOL temporary when it is used
//! more than once (several outputs, the EN of a box whose ENO passes it on, branches holding
//! boxes) or when a box runs in between. So `a AND NOT b` driving one coil is exactly the ST
//! `c := a AND NOT b;`.

use std::collections::{HashMap, HashSet};

use project_model::{
    CoilKind, Edge, ElementId, FlowNode, Network, NetworkOutput, Operand, Parallel, VarSection,
    Variable,
};

use super::fragment::{Fragment, frag};
use super::value::{Kind, Value, prec};
use super::{Callee, Finding, Probe, ProbeKind};
use crate::diagnostic::Code;

/// The lowering of one body: the text, the hidden variables and what was found on the way.
pub(crate) struct BodyLowering<'c> {
    /// The prefix of every hidden name of this body (`__` or `__Reset__`).
    prefix: String,
    /// What a box's type name calls.
    pub(super) classify: &'c dyn Fn(&str) -> Callee,
    /// The labels of the body's networks, lower case.
    labels: HashSet<String>,
    /// The network being lowered.
    pub(super) network: usize,
    /// The nesting of the statement being written, for indentation.
    pub(super) depth: usize,
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
    /// The declared type of an ST expression over the body's names, by the checker.
    pub(super) type_of: &'c dyn Fn(&str) -> Option<String>,
    /// Each stored box result's hidden name, lower case, with the expression it stands for
    /// written over the user's names only, which is what its type is computed from.
    pub(super) results: HashMap<String, String>,
}

impl<'c> BodyLowering<'c> {
    /// A lowering of a body whose hidden names start with `prefix`.
    pub fn new(
        prefix: String,
        classify: &'c dyn Fn(&str) -> Callee,
        type_of: &'c dyn Fn(&str) -> Option<String>,
    ) -> Self {
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
            type_of,
            results: HashMap::new(),
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
            let power = self
                .chain(&network.rung, Some(Value::rail()))
                .unwrap_or_else(Value::rail);
            // Contacts or an expression whose result goes nowhere are an unfinished network:
            // no statement would read them, so nothing would check them either.
            if network.outputs.is_empty()
                && power.kind == Kind::Expr
                && !chain_runs_boxes(&network.rung)
                && let Some(owner) = power.owner
            {
                self.find(
                    owner,
                    None,
                    Code::InvalidNetwork,
                    "the result of this network drives nothing; add a coil, an assignment, a jump or a return"
                        .to_owned(),
                );
            }
            self.outputs(&network.outputs, power);
        }
    }

    pub(super) fn find(
        &mut self,
        element: ElementId,
        pin: Option<&str>,
        code: Code,
        message: String,
    ) {
        self.find_at(self.network, Some(element), pin, code, message);
    }

    pub(super) fn find_at(
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
    pub(super) fn emit(&mut self, statement: Fragment) {
        self.out.push_str(&"    ".repeat(self.depth));
        self.out.push(statement);
        self.out.push_str("\n");
    }

    pub(super) fn probe(
        &mut self,
        element: ElementId,
        pin: Option<&str>,
        kind: ProbeKind,
        path: String,
    ) {
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
    pub(super) fn declare(
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
    pub(super) fn settle(
        &mut self,
        value: Value,
        owner: ElementId,
        suffix: &str,
        what: &str,
    ) -> Value {
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
    pub(super) fn chain(&mut self, nodes: &[FlowNode], incoming: Option<Value>) -> Option<Value> {
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
    pub(super) fn user_value(
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
    pub(super) fn reserved(&mut self, element: ElementId, pin: Option<&str>, text: &str) {
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
    pub(super) fn trigger(
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

    /// The OR of branch results, recorded as the group's; the rail when a branch is a short
    /// circuit.
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
pub(super) fn is_simple(text: &str) -> bool {
    !text.is_empty()
        && !text.starts_with(['-', '+'])
        && text
            .chars()
            .all(|c| c.is_alphanumeric() || matches!(c, '_' | '.' | '#' | '%' | '[' | ']' | '^'))
}

/// A variable's path (`a`, `fb.q`, `arr[1].x`), whose value can be read online by its path.
pub(super) fn is_path(text: &str) -> bool {
    text.starts_with(|c: char| c.is_alphabetic() || c == '_')
        && !text.contains('#')
        && !matches!(text.to_ascii_uppercase().as_str(), "TRUE" | "FALSE")
        && is_simple(text)
}
